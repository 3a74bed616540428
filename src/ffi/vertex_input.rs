//! GL 3.0–3.3's vertex input calls that a GL 2.1 compatibility context offers as
//! extensions: vertex array objects (ARB_vertex_array_object), base-vertex draws
//! (ARB_draw_elements_base_vertex), instanced draws and attribute divisors
//! (ARB_draw_instanced, ARB_instanced_arrays) and primitive restart (GL 3.1,
//! NV_primitive_restart's index call). The rules live in [`crate::context::arrays`],
//! [`crate::context::draw_cmd`] and [`crate::context::instanced`].
#![allow(non_snake_case)]

use super::client::{read_pairs, read_vec, write_all};
use super::draw::listable_draw;
use super::families::c_fns;
use super::types::*;
use super::{non_negative, with_ctx, with_ctx_keep, with_ctx_raw};
use crate::context::draw_cmd::{draw_arrays, draw_elements_base, element_list};
use crate::context::error::{GlError, GlResult};
use crate::context::instanced::instanced;
use crate::context::multi_draw::{with_base, RangeDraw};
use crate::context::state::Primitive;
use crate::context::Context;

/// glGenVertexArrays.
///
/// # Safety
/// `arrays` must be writable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenVertexArrays(n: GLsizei, arrays: *mut GLuint) {
    with_ctx_keep(|c| {
        let n = if arrays.is_null() {
            0
        } else {
            non_negative(n)?
        };
        // SAFETY: the caller promises room for n names.
        unsafe { write_all(arrays, &c.arrays.gen_vertex_arrays(n), |x| x) };
        Ok(())
    })
}

/// glDeleteVertexArrays (0 and unused names are ignored; a bound object is unbound).
///
/// # Safety
/// `arrays` must be readable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteVertexArrays(n: GLsizei, arrays: *const GLuint) {
    with_ctx(|c| {
        // SAFETY: the caller promises n readable names.
        c.arrays
            .delete_vertex_arrays(&unsafe { read_vec(arrays, non_negative(n)?) });
        Ok(())
    })
}

/// glBindVertexArray.
#[no_mangle]
pub extern "C" fn glBindVertexArray(array: GLuint) {
    with_ctx_keep(|c| c.arrays.bind_vertex_array(array))
}

/// glIsVertexArray: true for an object that has been bound and not deleted.
#[no_mangle]
pub extern "C" fn glIsVertexArray(array: GLuint) -> GLboolean {
    with_ctx(|c| Ok(c.arrays.is_vertex_array(array) as GLboolean))
}

/// glVertexAttribDivisor.
#[no_mangle]
pub extern "C" fn glVertexAttribDivisor(index: GLuint, divisor: GLuint) {
    with_ctx_keep(|c| c.vertex_attrib_divisor(index, divisor))
}

/// glPrimitiveRestartIndex.
#[no_mangle]
pub extern "C" fn glPrimitiveRestartIndex(index: GLuint) {
    with_ctx_keep(|c| {
        c.arrays.restart_index = index;
        Ok(())
    })
}

/// glDrawElementsBaseVertex.
#[no_mangle]
pub extern "C" fn glDrawElementsBaseVertex(
    mode: GLenum,
    count: GLsizei,
    type_: GLenum,
    indices: *const GLvoid,
    basevertex: GLint,
) {
    listable_draw(
        |c| {
            instanced(c, 1, |c| {
                draw_elements_base(c, mode, count, type_, indices, basevertex)
            })
        },
        |c| {
            let idx = element_list(c, count, type_, indices).map(|e| with_base(e, basevertex));
            c.compile_draw(Primitive::from_gl(mode), idx)
        },
    )
}

/// glDrawRangeElementsBaseVertex (the range is a hint, as for glDrawRangeElements).
#[no_mangle]
pub extern "C" fn glDrawRangeElementsBaseVertex(
    mode: GLenum,
    start: GLuint,
    end: GLuint,
    count: GLsizei,
    type_: GLenum,
    indices: *const GLvoid,
    basevertex: GLint,
) {
    let d = RangeDraw {
        start,
        end,
        count,
        type_,
        indices,
        base: basevertex,
    };
    listable_draw(
        |c| instanced(c, 1, |c| c.draw_range_elements(mode, &d)),
        |c| c.compile_draw_range_elements(mode, &d),
    )
}

/// glMultiDrawElementsBaseVertex.
///
/// # Safety
/// `count`, `indices` and `basevertex` must be readable for `drawcount` entries.
#[no_mangle]
pub unsafe extern "C" fn glMultiDrawElementsBaseVertex(
    mode: GLenum,
    count: *const GLsizei,
    type_: GLenum,
    indices: *const *const GLvoid,
    drawcount: GLsizei,
    basevertex: *const GLint,
) {
    // SAFETY: the caller promises `drawcount` entries in each array.
    let draws = unsafe { read_pairs(count, indices, drawcount) };
    let n = draws.as_ref().map_or(0, Vec::len);
    // SAFETY: as above.
    let bases = unsafe { read_vec(basevertex, n) };
    listable_draw(
        |c| instanced(c, 1, |c| c.multi_draw_elements(mode, type_, &draws, &bases)),
        |c| c.compile_multi_draw_elements(mode, type_, &draws, &bases),
    )
}

/// An instanced draw call of `count` vertices or indices: GL_INVALID_OPERATION while a
/// display list is compiled (Mesa compiles no instanced draw and runs none then);
/// GL_INVALID_VALUE for a negative instance count or count; `check` (the draw's own
/// validation, drawing nothing); GL_OUT_OF_MEMORY, drawing nothing, for more than
/// [`MAX_INSTANCES`] instances or [`MAX_INSTANCED_VERTICES`] vertices in all (each
/// instance is a draw of its own, so a hostile count would otherwise run for hours); then
/// `draw` once per instance ([`instanced`]).
fn instanced_call(
    (count, instances): (GLsizei, GLsizei),
    check: impl FnOnce(&mut Context) -> GlResult<()>,
    draw: impl FnMut(&mut Context) -> GlResult<()>,
) {
    with_ctx_raw(|c| {
        if c.lists.compile_mode().is_some() {
            return Err(GlError::InvalidOperation);
        }
        c.outside_begin_end()?;
        c.flush_pending_keep();
        let n = non_negative(instances)?;
        let per = non_negative(count)?;
        check(c)?;
        if n == 0 || per == 0 {
            return Ok(());
        }
        if n > MAX_INSTANCES || (n as u64) * (per as u64) > MAX_INSTANCED_VERTICES {
            return Err(GlError::OutOfMemory);
        }
        instanced(c, n as u32, draw)
    })
}

/// The most instances one instanced draw runs (see [`instanced_call`]).
const MAX_INSTANCES: usize = 1 << 24;

/// The most vertices (instances times the count) one instanced draw runs.
const MAX_INSTANCED_VERTICES: u64 = 1 << 31;

/// glDrawArraysInstanced.
#[no_mangle]
pub extern "C" fn glDrawArraysInstanced(
    mode: GLenum,
    first: GLint,
    count: GLsizei,
    instancecount: GLsizei,
) {
    instanced_call(
        (count, instancecount),
        |c| draw_arrays(c, mode, first, 0),
        |c| draw_arrays(c, mode, first, count),
    )
}

/// glDrawElementsInstancedBaseVertex.
#[no_mangle]
pub extern "C" fn glDrawElementsInstancedBaseVertex(
    mode: GLenum,
    count: GLsizei,
    type_: GLenum,
    indices: *const GLvoid,
    instancecount: GLsizei,
    basevertex: GLint,
) {
    instanced_call(
        (count, instancecount),
        |c| draw_elements_base(c, mode, 0, type_, std::ptr::null(), 0),
        |c| draw_elements_base(c, mode, count, type_, indices, basevertex),
    )
}

/// glDrawElementsInstanced.
#[no_mangle]
pub extern "C" fn glDrawElementsInstanced(
    mode: GLenum,
    count: GLsizei,
    type_: GLenum,
    indices: *const GLvoid,
    instancecount: GLsizei,
) {
    glDrawElementsInstancedBaseVertex(mode, count, type_, indices, instancecount, 0)
}

c_fns! {
    safe fn glDrawArraysInstancedARB(mode: GLenum, first: GLint, count: GLsizei, primcount: GLsizei) = vertex_input::glDrawArraysInstanced;
    safe fn glDrawArraysInstancedEXT(mode: GLenum, start: GLint, count: GLsizei, primcount: GLsizei) = vertex_input::glDrawArraysInstanced;
    safe fn glDrawElementsInstancedARB(mode: GLenum, count: GLsizei, type_: GLenum, indices: *const GLvoid, primcount: GLsizei) = vertex_input::glDrawElementsInstanced;
    safe fn glDrawElementsInstancedEXT(mode: GLenum, count: GLsizei, type_: GLenum, indices: *const GLvoid, primcount: GLsizei) = vertex_input::glDrawElementsInstanced;
    safe fn glVertexAttribDivisorARB(index: GLuint, divisor: GLuint) = vertex_input::glVertexAttribDivisor;
    safe fn glPrimitiveRestartIndexNV(index: GLuint) = vertex_input::glPrimitiveRestartIndex;
}
