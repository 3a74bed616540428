//! The fixed-function vertex stage: object position to clip space with the combined
//! projection × modelview matrix, colour clamping, texture coordinates through the texture
//! matrices, clip mask and window position. (Lighting and texture-coordinate generation
//! plug in here.)

use super::matrix::{Mat4, IDENTITY};
use crate::context::state::MAX_TEXTURE_UNITS;
use crate::geometry::fetch::VertexIn;
use crate::geometry::{clip_mask, ClipVertex, Viewport, VARY_TEX};

/// Per-draw constants of the vertex stage.
#[derive(Clone, Copy, Debug)]
pub struct VertexStage {
    /// Projection × modelview, multiplied as Mesa does.
    pub mvp: Mat4,
    /// The viewport transform.
    pub viewport: Viewport,
    /// Whether the host fuses multiply-adds (as llvmpipe then does).
    pub fma: bool,
    /// The enabled texture units, in order: (unit, texture matrix unless identity).
    pub tex_units: [(usize, Option<Mat4>); MAX_TEXTURE_UNITS],
    /// How many entries of `tex_units` are used.
    pub n_tex: usize,
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
    /// A stage without texturing.
    pub fn new(mvp: Mat4, viewport: Viewport, fma: bool) -> Self {
        VertexStage {
            mvp,
            viewport,
            fma,
            tex_units: [(0, None); MAX_TEXTURE_UNITS],
            n_tex: 0,
        }
    }

    /// Adds texture unit `unit` with texture matrix `m` (skipped when it is the identity,
    /// as Mesa's fixed-function vertex program does).
    pub fn add_texture_unit(&mut self, unit: usize, m: &Mat4) {
        if self.n_tex < MAX_TEXTURE_UNITS {
            self.tex_units[self.n_tex] = (unit, (*m != IDENTITY).then_some(*m));
            self.n_tex += 1;
        }
    }

    /// The number of varying floats this stage writes.
    pub fn nvary(&self) -> usize {
        if self.n_tex == 0 {
            4
        } else {
            VARY_TEX + 4 * self.n_tex
        }
    }

    /// Runs one vertex through the stage.
    #[inline]
    pub fn run(&self, v: &VertexIn) -> ClipVertex {
        let clip = self.mvp.transform(v.pos);
        let mask = clip_mask(clip);
        let mut out = ClipVertex {
            clip,
            win: self.viewport.apply_shader(clip, self.fma),
            mask,
            ..Default::default()
        };
        let c = v.color.map(clamp01);
        out.vary[..4].copy_from_slice(&c);
        for (k, (unit, m)) in self.tex_units[..self.n_tex].iter().enumerate() {
            let tc = v.texcoord[*unit];
            let tc = match m {
                Some(m) => m.transform(tc),
                None => tc,
            };
            out.vary[VARY_TEX + 4 * k..VARY_TEX + 4 * k + 4].copy_from_slice(&tc);
        }
        out
    }
}
