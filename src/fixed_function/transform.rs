//! The fixed-function vertex stage: object position to clip space with the combined
//! projection × modelview matrix, colour clamping, clip mask and window position.
//! (Lighting and texture-coordinate generation will plug in here.)

use super::matrix::Mat4;
use crate::geometry::fetch::VertexIn;
use crate::geometry::{clip_mask, ClipVertex, Viewport};

/// Per-draw constants of the vertex stage.
#[derive(Clone, Copy, Debug)]
pub struct VertexStage {
    /// Projection × modelview, multiplied as Mesa does.
    pub mvp: Mat4,
    /// The viewport transform.
    pub viewport: Viewport,
    /// Whether the host fuses multiply-adds (as llvmpipe then does).
    pub fma: bool,
}

#[inline]
fn clamp01(v: f32) -> f32 {
    if v > 0.0 {
        v.min(1.0)
    } else {
        0.0
    }
}

impl VertexStage {
    /// Runs one vertex through the stage.
    #[inline]
    pub fn run(&self, v: &VertexIn) -> ClipVertex {
        let clip = self.mvp.transform(v.pos);
        let mask = clip_mask(clip);
        ClipVertex {
            clip,
            win: self.viewport.apply_shader(clip, self.fma),
            mask,
            vary: v.color.map(clamp01),
        }
    }
}
