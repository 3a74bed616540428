//! GL_ARB_clip_control (`GL/glext.h`): glClipControl, Mesa's `_mesa_ClipControl`
//! (`main/viewport.c`). The origin and depth mode are transform state (GL_TRANSFORM_BIT);
//! the draw turns them into the viewport transform, the near clip plane, the facing and the
//! fill rule ([`crate::geometry::ClipConvention`]).
#![allow(non_snake_case)]

use super::types::*;
use super::with_ctx_list;

/// glClipControl: GL_LOWER_LEFT or GL_UPPER_LEFT origin, GL_NEGATIVE_ONE_TO_ONE or
/// GL_ZERO_TO_ONE depth. As in Mesa: GL_INVALID_OPERATION between glBegin and glEnd, a call
/// that changes nothing returns before the enums are checked, and a bad enum is
/// GL_INVALID_ENUM (origin first). Display lists record it (Mesa's `save_ClipControl`).
#[no_mangle]
pub extern "C" fn glClipControl(origin: GLenum, depth: GLenum) {
    with_ctx_list(move |c| c.clip_control(origin, depth))
}
