//! Queries: glGet{Boolean,Integer,Float,Double}v, glGetString, glGetPointerv and
//! glReadPixels.
#![allow(non_snake_case)]

use super::client::{write_all, write_one};
use super::families::c_fns;
use super::types::*;
use super::with_ctx;
use crate::context::get::{get, Value};
use crate::context::get_extra::gl_string;
use libc::c_void;

/// Writes the components of `pname`'s value, as `conv` lists them, through `out`.
///
/// # Safety
/// `out` must be null or writable for the value's components.
unsafe fn get_into<T: Copy>(pname: GLenum, out: *mut T, conv: impl Fn(&Value) -> Vec<T>) {
    // A draw left on the pool stays there unless the value is read from the framebuffer
    // it holds (programs query matrices and the viewport between draws).
    super::with_ctx_keep(|c| {
        if crate::context::get::reads_framebuffer(c, pname) {
            c.settle_draws();
        }
        let v = conv(&get(c, pname)?);
        // SAFETY: the program promises room for the value's components, as GL requires.
        unsafe { write_all(out, &v, |x| x) };
        Ok(())
    })
}

c_fns! {
    unsafe fn glGetBooleanv(pname: GLenum, params: *mut GLboolean) => get_into(pname, params, |v| v.as_bools().map(|x| x as GLboolean).collect());
    unsafe fn glGetIntegerv(pname: GLenum, params: *mut GLint) => get_into(pname, params, |v| v.as_ints().collect());
    unsafe fn glGetFloatv(pname: GLenum, params: *mut GLfloat) => get_into(pname, params, |v| v.as_doubles().map(|x| x as f32).collect());
    unsafe fn glGetDoublev(pname: GLenum, params: *mut GLdouble) => get_into(pname, params, |v| v.as_doubles().collect());
}

pub use crate::context::get_extra::EXTENSIONS;

/// glGetString: vendor, renderer, version ("2.1 …"), shading language version and the
/// extension list.
#[no_mangle]
pub extern "C" fn glGetString(name: GLenum) -> *const GLubyte {
    // Without a current context, and between glBegin and glEnd, GL calls return 0 (Mesa).
    with_ctx(|_| gl_string(name).map(Some)).map_or(std::ptr::null(), |s| s.as_ptr())
}

/// glGetPointerv: the client array pointers.
///
/// # Safety
/// `params` must be writable.
#[no_mangle]
pub unsafe extern "C" fn glGetPointerv(pname: GLenum, params: *mut *mut GLvoid) {
    with_ctx(|c| {
        let p = c.get_pointer(pname)? as *mut c_void;
        // SAFETY: the caller promises a writable value.
        unsafe { write_one(params, p) };
        Ok(())
    })
}

/// glReadPixels: reads a rectangle of the framebuffer (bottom row first) with the pack
/// parameters; pixels outside the framebuffer are left unwritten.
///
/// # Safety
/// `pixels` must be writable for the packed image.
#[no_mangle]
pub unsafe extern "C" fn glReadPixels(
    x: GLint,
    y: GLint,
    width: GLsizei,
    height: GLsizei,
    format: GLenum,
    type_: GLenum,
    pixels: *mut GLvoid,
) {
    // SAFETY: the program promises room for the packed image, as GL requires (or a pack
    // buffer takes it).
    with_ctx(|c| unsafe { c.read_pixels_to((x, y, width, height), (format, type_), pixels) })
}
