//! Texture coordinate generation and user clip planes (`GL/gl.h`): glTexGen*,
//! glGetTexGen*, glClipPlane and glGetClipPlane. Values convert to f32 as Mesa's
//! `texgen.c` and `clip.c` do (glTexGeni/f/d set a plane to `(param, 0, 0, 0)`).
#![allow(non_snake_case)]

use super::client::write_all;
use super::enums::*;
use super::families::c_fns;
use super::lighting::read4;
use super::types::*;
use super::with_ctx;
use super::with_ctx_list_keep;
use crate::context::texgen_state::{plane_times_inverse, ClipPlanes};

/// How many values a glTexGen pname takes.
fn texgen_count(pname: GLenum) -> usize {
    if pname == GL_TEXTURE_GEN_MODE {
        1
    } else {
        4
    }
}

fn texgen(coord: GLenum, pname: GLenum, p: [f32; 4]) {
    with_ctx_list_keep(move |c| {
        let unit = c.state.active_texture;
        c.texgen.set(unit, coord, pname, p, &c.matrices.modelview)
    })
}

/// Reads a texgen value of the active unit and writes it converted by `conv`.
///
/// # Safety
/// `params` must be null or writable for the values `pname` returns.
unsafe fn get_texgen<T>(coord: GLenum, pname: GLenum, params: *mut T, conv: impl Fn(f64) -> T) {
    let r = with_ctx(|c| c.texgen.get(c.state.active_texture, coord, pname).map(Some));
    if let Some((v, n)) = r {
        if params.is_null() {
            return;
        }
        for (i, x) in v.into_iter().take(n).enumerate() {
            // SAFETY: the caller promises room for the values.
            unsafe { params.add(i).write_unaligned(conv(x)) };
        }
    }
}

// glTexGen: glTexGeni/f/d set `(param, 0, 0, 0)`, the vector forms read as many values as
// `pname` takes. glGetTexGeniv truncates planes to integers, as Mesa's `(GLint)` casts do.
c_fns! {
    safe fn glTexGenf(coord: GLenum, pname: GLenum, param: GLfloat) => texgen(coord, pname, [param, 0.0, 0.0, 0.0]);
    safe fn glTexGeni(coord: GLenum, pname: GLenum, param: GLint) => texgen(coord, pname, [param as f32, 0.0, 0.0, 0.0]);
    safe fn glTexGend(coord: GLenum, pname: GLenum, param: GLdouble) => texgen(coord, pname, [param as f32, 0.0, 0.0, 0.0]);
    unsafe fn glTexGenfv(coord: GLenum, pname: GLenum, params: *const GLfloat) => if let Some(p) = read4(params, texgen_count(pname)) { texgen(coord, pname, p) };
    unsafe fn glTexGeniv(coord: GLenum, pname: GLenum, params: *const GLint) => if let Some(p) = read4(params, texgen_count(pname)) { texgen(coord, pname, p.map(|v| v as f32)) };
    unsafe fn glTexGendv(coord: GLenum, pname: GLenum, params: *const GLdouble) => if let Some(p) = read4(params, texgen_count(pname)) { texgen(coord, pname, p.map(|v| v as f32)) };
    unsafe fn glGetTexGenfv(coord: GLenum, pname: GLenum, params: *mut GLfloat) => get_texgen(coord, pname, params, |v| v as f32);
    unsafe fn glGetTexGeniv(coord: GLenum, pname: GLenum, params: *mut GLint) => get_texgen(coord, pname, params, |v| v as i32);
    unsafe fn glGetTexGendv(coord: GLenum, pname: GLenum, params: *mut GLdouble) => get_texgen(coord, pname, params, |v| v);
}

/// glClipPlane: the equation is converted to f32 and moved to eye space.
///
/// # Safety
/// `equation` must be null or point to four values.
#[no_mangle]
pub unsafe extern "C" fn glClipPlane(plane: GLenum, equation: *const GLdouble) {
    // SAFETY: the caller promises four values.
    let Some(eq) = (unsafe { read4(equation, 4) }) else {
        return;
    };
    with_ctx_list_keep(move |c| {
        let i = ClipPlanes::index(plane)?;
        c.clip_planes.eye[i] = plane_times_inverse(&c.matrices.modelview, eq.map(|v| v as f32));
        Ok(())
    })
}

/// glGetClipPlane.
///
/// # Safety
/// `equation` must be null or writable for four values.
#[no_mangle]
pub unsafe extern "C" fn glGetClipPlane(plane: GLenum, equation: *mut GLdouble) {
    let r = with_ctx(|c| Ok(Some(c.clip_planes.eye[ClipPlanes::index(plane)?])));
    if let Some(p) = r {
        // SAFETY: the caller promises room for four values.
        unsafe { write_all(equation, &p, |x| x as f64) };
    }
}
