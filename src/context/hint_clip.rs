//! glHint (stored; the rasterizer ignores hints, as llvmpipe does) and glClipControl
//! (GL_ARB_clip_control, Mesa's `_mesa_ClipControl` in `main/viewport.c`): the origin and
//! depth mode are transform state (GL_TRANSFORM_BIT); the draw turns them into the
//! viewport transform, the near clip plane, the facing and the fill rule
//! ([`crate::geometry::ClipConvention`]).

use super::{Context, GlError, GlResult};
use crate::geometry::ClipConvention;
use crate::gl::enums::*;
use crate::gl::glext_enums::*;
use crate::gl::types::*;

impl Context {
    /// glHint: `mode` must be GL_FASTEST, GL_NICEST or GL_DONT_CARE, `target` one of the
    /// eight hints (GL 2.0's GL_FRAGMENT_SHADER_DERIVATIVE_HINT among them).
    pub(crate) fn hint(&mut self, target: GLenum, mode: GLenum) -> GlResult<()> {
        if !matches!(mode, GL_FASTEST | GL_NICEST | GL_DONT_CARE) {
            return Err(GlError::InvalidEnum);
        }
        let h = &mut self.state.hints;
        let slot = match target {
            GL_PERSPECTIVE_CORRECTION_HINT => &mut h.perspective_correction,
            GL_POINT_SMOOTH_HINT => &mut h.point_smooth,
            GL_LINE_SMOOTH_HINT => &mut h.line_smooth,
            GL_POLYGON_SMOOTH_HINT => &mut h.polygon_smooth,
            GL_FOG_HINT => &mut h.fog,
            GL_GENERATE_MIPMAP_HINT => &mut h.generate_mipmap,
            GL_TEXTURE_COMPRESSION_HINT => &mut h.texture_compression,
            GL_FRAGMENT_SHADER_DERIVATIVE_HINT => &mut h.fragment_shader_derivative,
            _ => return Err(GlError::InvalidEnum),
        };
        *slot = mode;
        Ok(())
    }

    /// glClipControl: GL_LOWER_LEFT or GL_UPPER_LEFT origin, GL_NEGATIVE_ONE_TO_ONE or
    /// GL_ZERO_TO_ONE depth. As in Mesa, a call that changes nothing returns before the
    /// enums are checked, and a bad enum is GL_INVALID_ENUM (origin first).
    pub(crate) fn clip_control(&mut self, origin: GLenum, depth: GLenum) -> GlResult<()> {
        let cur = self.state.clip_control;
        let cur_origin = if cur.upper_left {
            GL_UPPER_LEFT
        } else {
            GL_LOWER_LEFT
        };
        let cur_depth = if cur.zero_to_one {
            GL_ZERO_TO_ONE
        } else {
            GL_NEGATIVE_ONE_TO_ONE
        };
        if origin == cur_origin && depth == cur_depth {
            return Ok(());
        }
        let upper_left = match origin {
            GL_LOWER_LEFT => false,
            GL_UPPER_LEFT => true,
            _ => return Err(GlError::InvalidEnum),
        };
        let zero_to_one = match depth {
            GL_NEGATIVE_ONE_TO_ONE => false,
            GL_ZERO_TO_ONE => true,
            _ => return Err(GlError::InvalidEnum),
        };
        self.state.clip_control = ClipConvention {
            upper_left,
            zero_to_one,
        };
        Ok(())
    }
}
