//! GL 1.4 multi-draw calls (`GL/glext.h`): several glDrawArrays/glDrawElements in one call
//! ([`crate::context::multi_draw`]).
#![allow(non_snake_case)]

use super::client::read_pairs;
use super::draw::listable_draw;
use super::types::*;
use crate::context::instanced::instanced;

/// glMultiDrawArrays.
///
/// # Safety
/// `first` and `count` must be readable for `drawcount` entries.
#[no_mangle]
pub unsafe extern "C" fn glMultiDrawArrays(
    mode: GLenum,
    first: *const GLint,
    count: *const GLsizei,
    drawcount: GLsizei,
) {
    // SAFETY: the caller promises `drawcount` entries in each array.
    let draws = unsafe { read_pairs(first, count, drawcount) };
    listable_draw(
        |c| instanced(c, 1, |c| c.multi_draw_arrays(mode, &draws)),
        |c| c.compile_multi_draw_arrays(mode, &draws),
    )
}

/// glMultiDrawElements: the base-vertex call without base vertices (all 0).
///
/// # Safety
/// `count` and `indices` must be readable for `drawcount` entries.
#[no_mangle]
pub unsafe extern "C" fn glMultiDrawElements(
    mode: GLenum,
    count: *const GLsizei,
    type_: GLenum,
    indices: *const *const GLvoid,
    drawcount: GLsizei,
) {
    // SAFETY: forwarded caller contract; a null base-vertex array reads as zeros.
    unsafe {
        super::vertex_input::glMultiDrawElementsBaseVertex(
            mode,
            count,
            type_,
            indices,
            drawcount,
            std::ptr::null(),
        )
    }
}
