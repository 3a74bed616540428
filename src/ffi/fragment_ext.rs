//! Per-fragment calls of GL 1.4 and 2.0 (`GL/glext.h`): separate blend functions and
//! equations, separate front/back stencil state, and glDrawBuffers.
#![allow(non_snake_case)]

use super::families::c_fns;
use super::fragment::{blend_equation, blend_func, stencil_func, stencil_mask, stencil_op, Faces};
use super::types::*;
use super::with_ctx_list;
use crate::context::error::GlError;
use crate::context::legacy_state::MAX_DRAW_BUFFERS;

/// glBlendFuncSeparate (GL 1.4).
#[no_mangle]
pub extern "C" fn glBlendFuncSeparate(
    sfactorRGB: GLenum,
    dfactorRGB: GLenum,
    sfactorAlpha: GLenum,
    dfactorAlpha: GLenum,
) {
    blend_func(sfactorRGB, dfactorRGB, sfactorAlpha, dfactorAlpha)
}

/// glBlendEquationSeparate (GL 2.0).
#[no_mangle]
pub extern "C" fn glBlendEquationSeparate(modeRGB: GLenum, modeAlpha: GLenum) {
    blend_equation(modeRGB, modeAlpha)
}

fn faces_or_error(face: GLenum) -> Option<Faces> {
    match Faces::from_gl(face) {
        Ok(f) => Some(f),
        Err(e) => {
            with_ctx_list(move |_| Err::<(), _>(e));
            None
        }
    }
}

/// glStencilFuncSeparate (GL 2.0).
#[no_mangle]
pub extern "C" fn glStencilFuncSeparate(face: GLenum, func: GLenum, ref_: GLint, mask: GLuint) {
    if let Some(f) = faces_or_error(face) {
        stencil_func(f, func, ref_, mask)
    }
}

/// glStencilOpSeparate (GL 2.0).
#[no_mangle]
pub extern "C" fn glStencilOpSeparate(face: GLenum, sfail: GLenum, dpfail: GLenum, dppass: GLenum) {
    if let Some(f) = faces_or_error(face) {
        stencil_op(f, sfail, dpfail, dppass)
    }
}

/// glStencilMaskSeparate (GL 2.0).
#[no_mangle]
pub extern "C" fn glStencilMaskSeparate(face: GLenum, mask: GLuint) {
    if let Some(f) = faces_or_error(face) {
        stencil_mask(f, mask)
    }
}

// The extension names of GL_EXT_blend_func_separate, GL_EXT_blend_equation_separate,
// GL_EXT_blend_minmax and GL_EXT_blend_color.
c_fns! {
    safe fn glBlendFuncSeparateEXT(sfactorRGB: GLenum, dfactorRGB: GLenum, sfactorAlpha: GLenum, dfactorAlpha: GLenum) = fragment_ext::glBlendFuncSeparate;
    safe fn glBlendEquationSeparateEXT(modeRGB: GLenum, modeAlpha: GLenum) = fragment_ext::glBlendEquationSeparate;
    safe fn glBlendEquationEXT(mode: GLenum) = fragment::glBlendEquation;
    safe fn glBlendColorEXT(red: GLclampf, green: GLclampf, blue: GLclampf, alpha: GLclampf) = fragment::glBlendColor;
}

/// glDrawBuffers: the draw buffers of the draw framebuffer (compiled into a display list
/// with its first eight names, as Mesa's `save_DrawBuffersARB` keeps them).
///
/// # Safety
/// `bufs` must be readable for `n` names (or null).
#[no_mangle]
pub unsafe extern "C" fn glDrawBuffers(n: GLsizei, bufs: *const GLenum) {
    let list = match usize::try_from(n) {
        // SAFETY: the caller promises `n` readable names; more than the maximum is an
        // error, so at most one past it is read.
        Ok(k) => Some(unsafe { super::client::read_vec(bufs, k.min(MAX_DRAW_BUFFERS + 1)) }),
        Err(_) => None,
    };
    with_ctx_list(move |c| match &list {
        Some(l) if (n as usize) <= MAX_DRAW_BUFFERS && l.len() == n as usize => c.draw_buffers(l),
        _ => Err(GlError::InvalidValue),
    })
}
