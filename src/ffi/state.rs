//! GL state calls: capabilities, clears, viewport, depth, faces, hints, pixel store,
//! glFlush/glFinish and glGetError.
#![allow(non_snake_case)]

use super::enums::*;
use super::families::c_fns;
use super::types::*;
use super::{gl_bool, with_ctx, with_ctx_list, with_ctx_list_keep};
use crate::context::clamp01;
use crate::context::error::{GlError, GlResult};
use crate::context::state::{CompareFunc, Face, PixelStore, ShadeModel};
use crate::context::Context;

/// glGetError: the first error since the last call, or GL_NO_ERROR.
#[no_mangle]
pub extern "C" fn glGetError() -> GLenum {
    // Between glBegin and glEnd it returns 0 and records GL_INVALID_OPERATION, as Mesa.
    // A draw left on the pool stays there: every error is recorded before its call
    // returns (PyOpenGL checks glGetError after every call it makes).
    super::with_ctx_keep(|c| Ok(c.take_error().map_or(GL_NO_ERROR, GlError::to_gl)))
}

/// glEnable.
#[no_mangle]
pub extern "C" fn glEnable(cap: GLenum) {
    with_ctx_list_keep(move |c| c.enable(cap, true))
}

/// glDisable.
#[no_mangle]
pub extern "C" fn glDisable(cap: GLenum) {
    with_ctx_list_keep(move |c| c.enable(cap, false))
}

/// glIsEnabled (also answers the client array states).
#[no_mangle]
pub extern "C" fn glIsEnabled(cap: GLenum) -> GLboolean {
    // State alone: a draw left on the pool stays there.
    super::with_ctx_keep(|c| Ok(c.is_enabled(cap)? as GLboolean))
}

/// Stores `value` (or raises its error when the command runs) in the state `field`
/// selects, as a listable command.
fn set_state<T: Clone + Send + Sync + 'static>(
    value: GlResult<T>,
    field: fn(&mut Context) -> &mut T,
) {
    with_ctx_list_keep(move |c| {
        *field(c) = value.clone()?;
        Ok(())
    })
}

/// glShadeModel's mode.
fn shade_model(mode: GLenum) -> GlResult<ShadeModel> {
    match mode {
        GL_FLAT => Ok(ShadeModel::Flat),
        GL_SMOOTH => Ok(ShadeModel::Smooth),
        _ => Err(GlError::InvalidEnum),
    }
}

/// glFrontFace's mode: true for counter-clockwise.
fn front_ccw(mode: GLenum) -> GlResult<bool> {
    match mode {
        GL_CCW => Ok(true),
        GL_CW => Ok(false),
        _ => Err(GlError::InvalidEnum),
    }
}

// The depth clear value is clamped to [0, 1]; the clear colour is kept as given (Mesa
// clamps it where it is used: fixed-point buffers and GL_COLOR_CLEAR_VALUE).
c_fns! {
    safe fn glClearColor(red: GLclampf, green: GLclampf, blue: GLclampf, alpha: GLclampf) => set_state(Ok([red, green, blue, alpha]), |c| &mut c.state.clear_color);
    safe fn glClearDepth(depth: GLclampd) => set_state(Ok(clamp01(depth)), |c| &mut c.state.clear_depth);
    safe fn glClearStencil(s: GLint) => set_state(Ok(s), |c| &mut c.state.clear_stencil);
    safe fn glClear(mask: GLbitfield) => with_ctx_list(move |c| c.clear(mask));
    safe fn glViewport(x: GLint, y: GLint, width: GLsizei, height: GLsizei) => with_ctx_list_keep(move |c| c.viewport(x, y, width, height));
    safe fn glScissor(x: GLint, y: GLint, width: GLsizei, height: GLsizei) => with_ctx_list_keep(move |c| c.scissor(x, y, width, height));
    safe fn glDepthRange(near_val: GLclampd, far_val: GLclampd) => with_ctx_list_keep(move |c| c.depth_range(near_val, far_val));
    safe fn glDepthFunc(func: GLenum) => set_state(CompareFunc::from_gl(func), |c| &mut c.state.depth_func);
    safe fn glDepthMask(flag: GLboolean) => set_state(Ok(gl_bool(flag)), |c| &mut c.state.depth_mask);
    safe fn glColorMask(red: GLboolean, green: GLboolean, blue: GLboolean, alpha: GLboolean) => set_state(Ok([red, green, blue, alpha].map(gl_bool)), |c| &mut c.state.color_mask);
    safe fn glShadeModel(mode: GLenum) => set_state(shade_model(mode), |c| &mut c.state.shade_model);
    safe fn glCullFace(mode: GLenum) => set_state(Face::from_gl(mode), |c| &mut c.state.cull_face);
    safe fn glFrontFace(mode: GLenum) => set_state(front_ccw(mode), |c| &mut c.state.front_ccw);
}

/// glHint (stored; the rasterizer ignores hints, as llvmpipe does).
#[no_mangle]
pub extern "C" fn glHint(target: GLenum, mode: GLenum) {
    with_ctx_list_keep(move |c| c.hint(target, mode))
}

/// glFlush: makes the rendering visible in the OSMesa buffer.
#[no_mangle]
pub extern "C" fn glFlush() {
    with_ctx(|c| {
        c.flush();
        Ok(())
    })
}

/// glFinish: as glFlush (rendering is synchronous).
#[no_mangle]
pub extern "C" fn glFinish() {
    glFlush()
}

fn pixel_store(pname: GLenum, value: f64) {
    with_ctx(|c| {
        let (store, which): (&mut PixelStore, GLenum) = match pname {
            GL_PACK_SWAP_BYTES | GL_PACK_LSB_FIRST | GL_PACK_ROW_LENGTH | GL_PACK_SKIP_ROWS
            | GL_PACK_SKIP_PIXELS | GL_PACK_ALIGNMENT | GL_PACK_IMAGE_HEIGHT
            | GL_PACK_SKIP_IMAGES => (&mut c.state.pack, pname),
            GL_UNPACK_SWAP_BYTES
            | GL_UNPACK_LSB_FIRST
            | GL_UNPACK_ROW_LENGTH
            | GL_UNPACK_SKIP_ROWS
            | GL_UNPACK_SKIP_PIXELS
            | GL_UNPACK_ALIGNMENT
            | GL_UNPACK_IMAGE_HEIGHT
            | GL_UNPACK_SKIP_IMAGES => (&mut c.state.unpack, pname),
            _ => return Err(GlError::InvalidEnum),
        };
        let iv = value.round() as i64;
        let int = || -> Result<i32, GlError> {
            if iv < 0 || iv > i32::MAX as i64 {
                Err(GlError::InvalidValue)
            } else {
                Ok(iv as i32)
            }
        };
        match which {
            GL_PACK_SWAP_BYTES | GL_UNPACK_SWAP_BYTES => store.swap_bytes = value != 0.0,
            GL_PACK_LSB_FIRST | GL_UNPACK_LSB_FIRST => store.lsb_first = value != 0.0,
            GL_PACK_ROW_LENGTH | GL_UNPACK_ROW_LENGTH => store.row_length = int()?,
            GL_PACK_SKIP_ROWS | GL_UNPACK_SKIP_ROWS => store.skip_rows = int()?,
            GL_PACK_SKIP_PIXELS | GL_UNPACK_SKIP_PIXELS => store.skip_pixels = int()?,
            GL_PACK_IMAGE_HEIGHT | GL_UNPACK_IMAGE_HEIGHT => store.image_height = int()?,
            GL_PACK_SKIP_IMAGES | GL_UNPACK_SKIP_IMAGES => store.skip_images = int()?,
            _ => {
                let a = int()?;
                if !matches!(a, 1 | 2 | 4 | 8) {
                    return Err(GlError::InvalidValue);
                }
                store.alignment = a;
            }
        }
        Ok(())
    })
}

/// glPixelStorei.
#[no_mangle]
pub extern "C" fn glPixelStorei(pname: GLenum, param: GLint) {
    pixel_store(pname, param as f64);
}

/// glPixelStoref.
#[no_mangle]
pub extern "C" fn glPixelStoref(pname: GLenum, param: GLfloat) {
    pixel_store(pname, param as f64);
}
