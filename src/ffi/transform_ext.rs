//! GL_ARB_clip_control (`GL/glext.h`): glClipControl, Mesa's `_mesa_ClipControl`
//! (`main/viewport.c`). The origin and depth mode are transform state (GL_TRANSFORM_BIT);
//! the draw turns them into the viewport transform, the near clip plane, the facing and the
//! fill rule ([`crate::geometry::ClipConvention`]).
#![allow(non_snake_case)]

use super::glext_enums::*;
use super::types::*;
use super::with_ctx_list;
use crate::context::error::GlError;
use crate::geometry::ClipConvention;

/// glClipControl: GL_LOWER_LEFT or GL_UPPER_LEFT origin, GL_NEGATIVE_ONE_TO_ONE or
/// GL_ZERO_TO_ONE depth. As in Mesa: GL_INVALID_OPERATION between glBegin and glEnd, a call
/// that changes nothing returns before the enums are checked, and a bad enum is
/// GL_INVALID_ENUM (origin first). Display lists record it (Mesa's `save_ClipControl`).
#[no_mangle]
pub extern "C" fn glClipControl(origin: GLenum, depth: GLenum) {
    with_ctx_list(move |c| {
        let cur = c.state.clip_control;
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
        c.state.clip_control = ClipConvention {
            upper_left,
            zero_to_one,
        };
        Ok(())
    })
}
