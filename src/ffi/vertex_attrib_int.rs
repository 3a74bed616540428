//! GL 3.0's integer vertex attributes (EXT_gpu_shader4's): glVertexAttribIPointer, the
//! glVertexAttribI* current values and the glGetVertexAttribI*v queries, with their EXT
//! names. An integer attribute's words are its integers' bits, carried in the attribute's
//! `f32` slots unchanged (no conversion anywhere on the way), and a shader's `int`/`uint`
//! inputs read them back as bits ([`crate::context::generic_attrib`]); missing
//! components are (0, 0, 0, 1) as integers.
#![allow(non_snake_case)]

use super::client::{write_all, write_one};
use super::families::c_fns;
use super::types::*;
use super::{with_ctx, with_ctx_keep, with_ctx_raw};
use crate::context::generic_attrib::AttribValue;
use crate::context::Context;

/// Sets generic attribute `index` to the integers `v` (a vertex for attribute 0 between
/// glBegin and glEnd).
fn generic_int(index: GLuint, v: [u32; 4]) {
    with_ctx_raw(|c| c.vertex_attrib(index, v.map(f32::from_bits)))
}

/// The first `N` of `v` over (0, 0, 0, 1).
fn fill<const N: usize>(v: [u32; N]) -> [u32; 4] {
    let mut out = [0, 0, 0, 1];
    out[..N].copy_from_slice(&v);
    out
}

/// The vector forms: `N` integers at `v`, each widened by `conv` (nothing when `v` is
/// null).
///
/// # Safety
/// `v` must be null or point to `N` values.
unsafe fn generic_int_v<T: Copy, const N: usize>(index: GLuint, v: *const T, conv: fn(T) -> u32) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises `N` readable values (aligned or not).
    let vals: [u32; N] = std::array::from_fn(|i| conv(unsafe { v.add(i).read_unaligned() }));
    generic_int(index, fill(vals));
}

/// glGetVertexAttribIiv / glGetVertexAttribIuiv: as glGetVertexAttribiv, except that
/// GL_CURRENT_VERTEX_ATTRIB gives the words' bits.
///
/// # Safety
/// `params` must be null or writable for the query's values (four for
/// GL_CURRENT_VERTEX_ATTRIB, else one).
unsafe fn get_attrib_int<T>(index: GLuint, pname: GLenum, params: *mut T, conv: fn(u32) -> T) {
    with_ctx(|c: &mut Context| {
        let v = c.get_vertex_attrib(index, pname)?;
        // SAFETY: the caller promises room for the values.
        unsafe {
            match v {
                AttribValue::Int(i) => write_one(params, conv(i as u32)),
                AttribValue::Floats(f) => write_all(params, &f, |x| conv(x.to_bits())),
            }
        }
        Ok(())
    })
}

c_fns! {
    safe fn glVertexAttribI1i(index: GLuint, x: GLint) => generic_int(index, fill([x as u32]));
    safe fn glVertexAttribI1ui(index: GLuint, x: GLuint) => generic_int(index, fill([x]));
    safe fn glVertexAttribI2i(index: GLuint, x: GLint, y: GLint) => generic_int(index, fill([x as u32, y as u32]));
    safe fn glVertexAttribI2ui(index: GLuint, x: GLuint, y: GLuint) => generic_int(index, fill([x, y]));
    safe fn glVertexAttribI3i(index: GLuint, x: GLint, y: GLint, z: GLint) => generic_int(index, fill([x as u32, y as u32, z as u32]));
    safe fn glVertexAttribI3ui(index: GLuint, x: GLuint, y: GLuint, z: GLuint) => generic_int(index, fill([x, y, z]));
    safe fn glVertexAttribI4i(index: GLuint, x: GLint, y: GLint, z: GLint, w: GLint) => generic_int(index, fill([x as u32, y as u32, z as u32, w as u32]));
    safe fn glVertexAttribI4ui(index: GLuint, x: GLuint, y: GLuint, z: GLuint, w: GLuint) => generic_int(index, fill([x, y, z, w]));
    unsafe fn glVertexAttribI1iv(index: GLuint, v: *const GLint) => generic_int_v::<_, 1>(index, v, |x| x as u32);
    unsafe fn glVertexAttribI1uiv(index: GLuint, v: *const GLuint) => generic_int_v::<_, 1>(index, v, |x| x);
    unsafe fn glVertexAttribI2iv(index: GLuint, v: *const GLint) => generic_int_v::<_, 2>(index, v, |x| x as u32);
    unsafe fn glVertexAttribI2uiv(index: GLuint, v: *const GLuint) => generic_int_v::<_, 2>(index, v, |x| x);
    unsafe fn glVertexAttribI3iv(index: GLuint, v: *const GLint) => generic_int_v::<_, 3>(index, v, |x| x as u32);
    unsafe fn glVertexAttribI3uiv(index: GLuint, v: *const GLuint) => generic_int_v::<_, 3>(index, v, |x| x);
    unsafe fn glVertexAttribI4iv(index: GLuint, v: *const GLint) => generic_int_v::<_, 4>(index, v, |x| x as u32);
    unsafe fn glVertexAttribI4uiv(index: GLuint, v: *const GLuint) => generic_int_v::<_, 4>(index, v, |x| x);
    unsafe fn glVertexAttribI4bv(index: GLuint, v: *const GLbyte) => generic_int_v::<_, 4>(index, v, |x| x as i32 as u32);
    unsafe fn glVertexAttribI4sv(index: GLuint, v: *const GLshort) => generic_int_v::<_, 4>(index, v, |x| x as i32 as u32);
    unsafe fn glVertexAttribI4ubv(index: GLuint, v: *const GLubyte) => generic_int_v::<_, 4>(index, v, |x| x as u32);
    unsafe fn glVertexAttribI4usv(index: GLuint, v: *const GLushort) => generic_int_v::<_, 4>(index, v, |x| x as u32);
    safe fn glVertexAttribIPointer(index: GLuint, size: GLint, type_: GLenum, stride: GLsizei, pointer: *const GLvoid) => with_ctx_keep(|c| c.vertex_attrib_ipointer(index, (size, type_, stride), pointer as usize));
    unsafe fn glGetVertexAttribIiv(index: GLuint, pname: GLenum, params: *mut GLint) => get_attrib_int(index, pname, params, |x| x as GLint);
    unsafe fn glGetVertexAttribIuiv(index: GLuint, pname: GLenum, params: *mut GLuint) => get_attrib_int(index, pname, params, |x| x);
    safe fn glVertexAttribI1iEXT(index: GLuint, x: GLint) = vertex_attrib_int::glVertexAttribI1i;
    safe fn glVertexAttribI1uiEXT(index: GLuint, x: GLuint) = vertex_attrib_int::glVertexAttribI1ui;
    safe fn glVertexAttribI2iEXT(index: GLuint, x: GLint, y: GLint) = vertex_attrib_int::glVertexAttribI2i;
    safe fn glVertexAttribI2uiEXT(index: GLuint, x: GLuint, y: GLuint) = vertex_attrib_int::glVertexAttribI2ui;
    safe fn glVertexAttribI3iEXT(index: GLuint, x: GLint, y: GLint, z: GLint) = vertex_attrib_int::glVertexAttribI3i;
    safe fn glVertexAttribI3uiEXT(index: GLuint, x: GLuint, y: GLuint, z: GLuint) = vertex_attrib_int::glVertexAttribI3ui;
    safe fn glVertexAttribI4iEXT(index: GLuint, x: GLint, y: GLint, z: GLint, w: GLint) = vertex_attrib_int::glVertexAttribI4i;
    safe fn glVertexAttribI4uiEXT(index: GLuint, x: GLuint, y: GLuint, z: GLuint, w: GLuint) = vertex_attrib_int::glVertexAttribI4ui;
    unsafe fn glVertexAttribI1ivEXT(index: GLuint, v: *const GLint) = vertex_attrib_int::glVertexAttribI1iv;
    unsafe fn glVertexAttribI1uivEXT(index: GLuint, v: *const GLuint) = vertex_attrib_int::glVertexAttribI1uiv;
    unsafe fn glVertexAttribI2ivEXT(index: GLuint, v: *const GLint) = vertex_attrib_int::glVertexAttribI2iv;
    unsafe fn glVertexAttribI2uivEXT(index: GLuint, v: *const GLuint) = vertex_attrib_int::glVertexAttribI2uiv;
    unsafe fn glVertexAttribI3ivEXT(index: GLuint, v: *const GLint) = vertex_attrib_int::glVertexAttribI3iv;
    unsafe fn glVertexAttribI3uivEXT(index: GLuint, v: *const GLuint) = vertex_attrib_int::glVertexAttribI3uiv;
    unsafe fn glVertexAttribI4ivEXT(index: GLuint, v: *const GLint) = vertex_attrib_int::glVertexAttribI4iv;
    unsafe fn glVertexAttribI4uivEXT(index: GLuint, v: *const GLuint) = vertex_attrib_int::glVertexAttribI4uiv;
    unsafe fn glVertexAttribI4bvEXT(index: GLuint, v: *const GLbyte) = vertex_attrib_int::glVertexAttribI4bv;
    unsafe fn glVertexAttribI4svEXT(index: GLuint, v: *const GLshort) = vertex_attrib_int::glVertexAttribI4sv;
    unsafe fn glVertexAttribI4ubvEXT(index: GLuint, v: *const GLubyte) = vertex_attrib_int::glVertexAttribI4ubv;
    unsafe fn glVertexAttribI4usvEXT(index: GLuint, v: *const GLushort) = vertex_attrib_int::glVertexAttribI4usv;
    safe fn glVertexAttribIPointerEXT(index: GLuint, size: GLint, type_: GLenum, stride: GLsizei, pointer: *const GLvoid) = vertex_attrib_int::glVertexAttribIPointer;
    unsafe fn glGetVertexAttribIivEXT(index: GLuint, pname: GLenum, params: *mut GLint) = vertex_attrib_int::glGetVertexAttribIiv;
    unsafe fn glGetVertexAttribIuivEXT(index: GLuint, pname: GLenum, params: *mut GLuint) = vertex_attrib_int::glGetVertexAttribIuiv;
}
