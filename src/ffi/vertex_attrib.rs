//! GL 2.0's generic vertex attributes: the glVertexAttrib* families,
//! glVertexAttribPointer, glEnable/DisableVertexAttribArray and the glGetVertexAttrib
//! queries. The rules (attribute 0 as the vertex position) live in
//! [`crate::context::generic_attrib`]; the `4N` forms normalise as Mesa's vbo module does
//! ([`Component::norm`]), the others convert with a plain cast.
#![allow(non_snake_case)]

use super::client::{write_all, write_one};
use super::families::{c_fns, vector_fns, Component};
use super::types::*;
use super::{gl_bool, with_ctx, with_ctx_raw};
use crate::context::generic_attrib::AttribValue;
use crate::context::Context;

/// Sets generic attribute `index` (a vertex for attribute 0 between glBegin and glEnd).
fn generic(index: GLuint, v: [f32; 4]) {
    with_ctx_raw(|c| c.vertex_attrib(index, v))
}

/// The vector-only forms (glVertexAttrib4bv, glVertexAttrib4Nbv …): four values at `v`
/// converted by `conv` (nothing happens when `v` is null).
///
/// # Safety
/// `v` must be null or point to four values.
unsafe fn generic4v<T: Component>(index: GLuint, v: *const T, conv: fn(T) -> f32) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises four readable values (aligned or not).
    generic(
        index,
        std::array::from_fn(|i| conv(unsafe { v.add(i).read_unaligned() })),
    )
}

vector_fns! {
    generic cast [0.0, 0.0, 0.0, 1.0] {
        (index: GLuint; x) glVertexAttrib1s glVertexAttrib1sv GLshort, glVertexAttrib1f glVertexAttrib1fv GLfloat, glVertexAttrib1d glVertexAttrib1dv GLdouble;
        (index: GLuint; x, y) glVertexAttrib2s glVertexAttrib2sv GLshort, glVertexAttrib2f glVertexAttrib2fv GLfloat, glVertexAttrib2d glVertexAttrib2dv GLdouble;
        (index: GLuint; x, y, z) glVertexAttrib3s glVertexAttrib3sv GLshort, glVertexAttrib3f glVertexAttrib3fv GLfloat, glVertexAttrib3d glVertexAttrib3dv GLdouble;
        (index: GLuint; x, y, z, w) glVertexAttrib4s glVertexAttrib4sv GLshort, glVertexAttrib4f glVertexAttrib4fv GLfloat, glVertexAttrib4d glVertexAttrib4dv GLdouble;
    }
    generic norm [0.0, 0.0, 0.0, 1.0] {
        (index: GLuint; x, y, z, w) glVertexAttrib4Nub glVertexAttrib4Nubv GLubyte;
    }
}

/// glGetVertexAttrib{f,d,i}v: the value of `pname` written to `params`, each number
/// converted by `conv` (GL_CURRENT_VERTEX_ATTRIB's floats truncate to integers, as Mesa).
///
/// # Safety
/// `params` must be null or writable for the query's values (four for
/// GL_CURRENT_VERTEX_ATTRIB, else one).
unsafe fn get_attrib<T>(index: GLuint, pname: GLenum, params: *mut T, conv: fn(f64) -> T) {
    with_ctx(|c: &mut Context| {
        let v = c.get_vertex_attrib(index, pname)?;
        // SAFETY: the caller promises room for the values.
        unsafe {
            match v {
                AttribValue::Int(i) => write_one(params, conv(i as f64)),
                AttribValue::Floats(f) => write_all(params, &f, |x| conv(x as f64)),
            }
        }
        Ok(())
    })
}

c_fns! {
    unsafe fn glVertexAttrib4bv(index: GLuint, v: *const GLbyte) => generic4v(index, v, Component::cast);
    unsafe fn glVertexAttrib4iv(index: GLuint, v: *const GLint) => generic4v(index, v, Component::cast);
    unsafe fn glVertexAttrib4ubv(index: GLuint, v: *const GLubyte) => generic4v(index, v, Component::cast);
    unsafe fn glVertexAttrib4usv(index: GLuint, v: *const GLushort) => generic4v(index, v, Component::cast);
    unsafe fn glVertexAttrib4uiv(index: GLuint, v: *const GLuint) => generic4v(index, v, Component::cast);
    unsafe fn glVertexAttrib4Nbv(index: GLuint, v: *const GLbyte) => generic4v(index, v, Component::norm);
    unsafe fn glVertexAttrib4Nsv(index: GLuint, v: *const GLshort) => generic4v(index, v, Component::norm);
    unsafe fn glVertexAttrib4Niv(index: GLuint, v: *const GLint) => generic4v(index, v, Component::norm);
    unsafe fn glVertexAttrib4Nusv(index: GLuint, v: *const GLushort) => generic4v(index, v, Component::norm);
    unsafe fn glVertexAttrib4Nuiv(index: GLuint, v: *const GLuint) => generic4v(index, v, Component::norm);
    safe fn glVertexAttribPointer(index: GLuint, size: GLint, type_: GLenum, normalized: GLboolean, stride: GLsizei, pointer: *const GLvoid) => super::with_ctx_keep(|c| c.vertex_attrib_pointer(index, (size, type_, gl_bool(normalized), stride), pointer as usize));
    safe fn glEnableVertexAttribArray(index: GLuint) => super::with_ctx_keep(|c| c.set_vertex_attrib_array(index, true));
    safe fn glDisableVertexAttribArray(index: GLuint) => super::with_ctx_keep(|c| c.set_vertex_attrib_array(index, false));
    unsafe fn glGetVertexAttribfv(index: GLuint, pname: GLenum, params: *mut GLfloat) => get_attrib(index, pname, params, |x| x as f32);
    unsafe fn glGetVertexAttribdv(index: GLuint, pname: GLenum, params: *mut GLdouble) => get_attrib(index, pname, params, |x| x);
    unsafe fn glGetVertexAttribiv(index: GLuint, pname: GLenum, params: *mut GLint) => get_attrib(index, pname, params, |x| x as GLint);
    unsafe fn glGetVertexAttribPointerv(index: GLuint, pname: GLenum, pointer: *mut *mut GLvoid) => with_ctx(|c| { let p = c.get_vertex_attrib_pointer(index, pname)?; write_one(pointer, p as *mut GLvoid); Ok(()) });
}
