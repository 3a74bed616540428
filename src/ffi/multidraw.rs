//! GL 1.4 multi-draw calls (`GL/glext.h`): several glDrawArrays/glDrawElements in one call.
#![allow(non_snake_case)]

use super::draw::{array_range, draw_arrays, draw_elements, element_list, listable_draw};
use super::non_negative;
use super::types::*;
use crate::context::dlist::Elements;
use crate::context::error::{GlError, GlResult};
use crate::context::state::Primitive;

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
    let pairs = || -> GlResult<Vec<(GLint, GLsizei)>> {
        let n = non_negative(drawcount)?;
        if first.is_null() || count.is_null() {
            return Ok(Vec::new());
        }
        Ok((0..n)
            // SAFETY: the caller promises `drawcount` entries in each array.
            .map(|i| unsafe { (*first.add(i), *count.add(i)) })
            .collect())
    };
    let compile = |c: &mut crate::context::Context| match pairs() {
        Err(e) => c.compile_draw(Err(e), Ok(Elements::List(Vec::new()))),
        Ok(p) => {
            for (f, k) in p {
                c.compile_draw(Primitive::from_gl(mode), array_range(f, k));
            }
        }
    };
    listable_draw(
        |c| {
            let n = non_negative(drawcount)?;
            // Validate everything before drawing anything, so an error leaves no partial
            // draw: a zero-count draw checks mode, glBegin and mapped buffers.
            draw_arrays(c, mode, 0, 0)?;
            if first.is_null() || count.is_null() {
                return Ok(());
            }
            // SAFETY: the caller promises `drawcount` entries in each array.
            if (0..n).any(|i| unsafe { *count.add(i) < 0 || *first.add(i) < 0 }) {
                return Err(GlError::InvalidValue);
            }
            for i in 0..n {
                // SAFETY: the caller promises `drawcount` entries in each array.
                let (f, k) = unsafe { (*first.add(i), *count.add(i)) };
                draw_arrays(c, mode, f, k)?;
            }
            Ok(())
        },
        compile,
    )
}

/// glMultiDrawElements.
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
    let compile = |c: &mut crate::context::Context| {
        let n = match non_negative(drawcount) {
            Ok(n) => n,
            Err(e) => return c.compile_draw(Err(e), Ok(Elements::List(Vec::new()))),
        };
        if count.is_null() || indices.is_null() {
            return;
        }
        for i in 0..n {
            // SAFETY: the caller promises `drawcount` entries in each array.
            let (k, p) = unsafe { (*count.add(i), *indices.add(i)) };
            let idx = element_list(c, k, type_, p);
            c.compile_draw(Primitive::from_gl(mode), idx);
        }
    };
    listable_draw(
        |c| {
            let n = non_negative(drawcount)?;
            // As in glMultiDrawArrays: validate mode and type before any draw.
            draw_elements(c, mode, 0, type_, std::ptr::null())?;
            if count.is_null() || indices.is_null() {
                return Ok(());
            }
            // SAFETY: the caller promises `drawcount` entries.
            if (0..n).any(|i| unsafe { *count.add(i) } < 0) {
                return Err(GlError::InvalidValue);
            }
            for i in 0..n {
                // SAFETY: the caller promises `drawcount` entries in each array.
                let (k, p) = unsafe { (*count.add(i), *indices.add(i)) };
                draw_elements(c, mode, k, type_, p)?;
            }
            Ok(())
        },
        compile,
    )
}
