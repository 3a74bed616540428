//! Draw calls from arrays: glDrawArrays, glDrawElements, glDrawRangeElements. Each runs,
//! or is compiled into the display list being built, through [`listable_draw`]; the
//! validation and the draw are [`crate::context::draw_cmd`]'s. A draw run now is instance
//! 0 of [`instanced`] (arrays with a divisor read their first element).
#![allow(non_snake_case)]

use super::types::*;
use super::with_ctx_raw;
pub(crate) use crate::context::draw_cmd::{array_range, draw_arrays};
use crate::context::error::{GlError, GlResult};
use crate::context::instanced::instanced;
use crate::context::state::Primitive;
use crate::context::Context;

/// Runs a draw call, or compiles it while a display list is being compiled (`compile`
/// reads the arrays now); under GL_COMPILE_AND_EXECUTE it is drawn too. A draw run now
/// does not wait for the draw on the pool first: it takes that batch over, and may leave
/// its own there ([`crate::context::draw::draw`]).
pub(crate) fn listable_draw(
    exec: impl FnOnce(&mut Context) -> GlResult<()>,
    compile: impl FnOnce(&mut Context),
) {
    with_ctx_raw(|c| match c.lists.compile_mode() {
        None => {
            c.outside_begin_end()?;
            c.flush_pending_keep();
            exec(c)
        }
        Some(execute) => {
            let inside = c.lists.compiling_inside_begin();
            compile(c);
            if execute && inside {
                // Drawn now inside the list's own glBegin: Mesa raises the error and
                // draws nothing (the compiled copy is skipped when the list runs).
                return Err(GlError::InvalidOperation);
            }
            if execute {
                c.outside_begin_end()?;
                c.flush_pending();
                exec(c)
            } else {
                Ok(())
            }
        }
    })
}

/// glDrawArrays.
#[no_mangle]
pub extern "C" fn glDrawArrays(mode: GLenum, first: GLint, count: GLsizei) {
    listable_draw(
        |c| instanced(c, 1, |c| draw_arrays(c, mode, first, count)),
        |c| c.compile_draw(Primitive::from_gl(mode), array_range(first, count)),
    )
}

/// glDrawElements: the base-vertex call with base 0.
#[no_mangle]
pub extern "C" fn glDrawElements(
    mode: GLenum,
    count: GLsizei,
    type_: GLenum,
    indices: *const GLvoid,
) {
    super::vertex_input::glDrawElementsBaseVertex(mode, count, type_, indices, 0)
}

/// glDrawRangeElements (the range is a hint; indices outside it are still drawn): the
/// base-vertex call with base 0.
#[no_mangle]
pub extern "C" fn glDrawRangeElements(
    mode: GLenum,
    start: GLuint,
    end: GLuint,
    count: GLsizei,
    type_: GLenum,
    indices: *const GLvoid,
) {
    super::vertex_input::glDrawRangeElementsBaseVertex(mode, start, end, count, type_, indices, 0)
}
