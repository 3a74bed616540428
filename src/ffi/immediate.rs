//! Immediate mode: glBegin/glEnd and the glVertex, glColor, glTexCoord and glNormal
//! families. Integer colours and normals are converted as Mesa's vbo module does
//! (`u / 255.0f` for unsigned bytes, `(2c + 1) / (2^n - 1)` for signed types).
#![allow(non_snake_case)]

use super::types::*;
use super::{with_ctx_list, with_ctx_vertex};
use crate::context::dlist::VertexOp;
use crate::context::state::Primitive;

/// glBegin.
#[no_mangle]
pub extern "C" fn glBegin(mode: GLenum) {
    match Primitive::from_gl(mode) {
        Ok(m) => with_ctx_vertex(VertexOp::Begin(m)),
        // An invalid mode is compiled as the error it raises when the list runs.
        Err(e) => with_ctx_list(move |_| Err(e)),
    }
}

/// glEnd: draws the vertices given since glBegin (or defers them to merge with the next
/// glBegin of the same mode).
#[no_mangle]
pub extern "C" fn glEnd() {
    with_ctx_vertex(VertexOp::End)
}

/// Adds a vertex inside glBegin/glEnd (outside it, GL leaves the effect undefined; we
/// ignore it, as Mesa does).
pub(crate) fn vertex(p: [f32; 4]) {
    with_ctx_vertex(VertexOp::Vertex(p))
}

/// Sets the current colour.
pub(crate) fn color(v: [f32; 4]) {
    with_ctx_vertex(VertexOp::Color(v))
}

/// Sets the current texture coordinate of unit 0.
pub(crate) fn texcoord(v: [f32; 4]) {
    with_ctx_vertex(VertexOp::TexCoord(0, v))
}

/// Sets the current normal.
pub(crate) fn normal(v: [f32; 3]) {
    with_ctx_vertex(VertexOp::Normal(v))
}

#[inline]
fn b2f(b: GLbyte) -> f32 {
    (2.0 * b as f32 + 1.0) * (1.0 / 255.0)
}
#[inline]
fn s2f(s: GLshort) -> f32 {
    (2.0 * s as f32 + 1.0) * (1.0 / 65535.0)
}
#[inline]
fn i2f(i: GLint) -> f32 {
    ((2.0 * i as f64 + 1.0) * (1.0 / 4294967294.0)) as f32
}
#[inline]
fn ub2f(u: GLubyte) -> f32 {
    u as f32 / 255.0
}
#[inline]
fn us2f(u: GLushort) -> f32 {
    u as f32 / 65535.0
}
#[inline]
fn ui2f(u: GLuint) -> f32 {
    (u as f64 / 4294967295.0) as f32
}

/// glVertex2s.
#[no_mangle]
pub extern "C" fn glVertex2s(x: GLshort, y: GLshort) {
    vertex([x as f32, y as f32, 0.0, 1.0])
}

/// glVertex2sv.
///
/// # Safety
/// `v` must point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glVertex2sv(v: *const GLshort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 2 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 2) };
    vertex([v[0] as f32, v[1] as f32, 0.0, 1.0])
}

/// glVertex2i.
#[no_mangle]
pub extern "C" fn glVertex2i(x: GLint, y: GLint) {
    vertex([x as f32, y as f32, 0.0, 1.0])
}

/// glVertex2iv.
///
/// # Safety
/// `v` must point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glVertex2iv(v: *const GLint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 2 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 2) };
    vertex([v[0] as f32, v[1] as f32, 0.0, 1.0])
}

/// glVertex2f.
#[no_mangle]
pub extern "C" fn glVertex2f(x: GLfloat, y: GLfloat) {
    vertex([x, y, 0.0, 1.0])
}

/// glVertex2fv.
///
/// # Safety
/// `v` must point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glVertex2fv(v: *const GLfloat) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 2 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 2) };
    vertex([v[0], v[1], 0.0, 1.0])
}

/// glVertex2d.
#[no_mangle]
pub extern "C" fn glVertex2d(x: GLdouble, y: GLdouble) {
    vertex([x as f32, y as f32, 0.0, 1.0])
}

/// glVertex2dv.
///
/// # Safety
/// `v` must point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glVertex2dv(v: *const GLdouble) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 2 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 2) };
    vertex([v[0] as f32, v[1] as f32, 0.0, 1.0])
}

/// glVertex3s.
#[no_mangle]
pub extern "C" fn glVertex3s(x: GLshort, y: GLshort, z: GLshort) {
    vertex([x as f32, y as f32, z as f32, 1.0])
}

/// glVertex3sv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glVertex3sv(v: *const GLshort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    vertex([v[0] as f32, v[1] as f32, v[2] as f32, 1.0])
}

/// glVertex3i.
#[no_mangle]
pub extern "C" fn glVertex3i(x: GLint, y: GLint, z: GLint) {
    vertex([x as f32, y as f32, z as f32, 1.0])
}

/// glVertex3iv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glVertex3iv(v: *const GLint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    vertex([v[0] as f32, v[1] as f32, v[2] as f32, 1.0])
}

/// glVertex3f.
#[no_mangle]
pub extern "C" fn glVertex3f(x: GLfloat, y: GLfloat, z: GLfloat) {
    vertex([x, y, z, 1.0])
}

/// glVertex3fv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glVertex3fv(v: *const GLfloat) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    vertex([v[0], v[1], v[2], 1.0])
}

/// glVertex3d.
#[no_mangle]
pub extern "C" fn glVertex3d(x: GLdouble, y: GLdouble, z: GLdouble) {
    vertex([x as f32, y as f32, z as f32, 1.0])
}

/// glVertex3dv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glVertex3dv(v: *const GLdouble) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    vertex([v[0] as f32, v[1] as f32, v[2] as f32, 1.0])
}

/// glVertex4s.
#[no_mangle]
pub extern "C" fn glVertex4s(x: GLshort, y: GLshort, z: GLshort, w: GLshort) {
    vertex([x as f32, y as f32, z as f32, w as f32])
}

/// glVertex4sv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glVertex4sv(v: *const GLshort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    vertex([v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32])
}

/// glVertex4i.
#[no_mangle]
pub extern "C" fn glVertex4i(x: GLint, y: GLint, z: GLint, w: GLint) {
    vertex([x as f32, y as f32, z as f32, w as f32])
}

/// glVertex4iv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glVertex4iv(v: *const GLint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    vertex([v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32])
}

/// glVertex4f.
#[no_mangle]
pub extern "C" fn glVertex4f(x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) {
    vertex([x, y, z, w])
}

/// glVertex4fv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glVertex4fv(v: *const GLfloat) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    vertex([v[0], v[1], v[2], v[3]])
}

/// glVertex4d.
#[no_mangle]
pub extern "C" fn glVertex4d(x: GLdouble, y: GLdouble, z: GLdouble, w: GLdouble) {
    vertex([x as f32, y as f32, z as f32, w as f32])
}

/// glVertex4dv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glVertex4dv(v: *const GLdouble) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    vertex([v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32])
}

/// glColor3b.
#[no_mangle]
pub extern "C" fn glColor3b(red: GLbyte, green: GLbyte, blue: GLbyte) {
    color([b2f(red), b2f(green), b2f(blue), 1.0])
}

/// glColor3bv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glColor3bv(v: *const GLbyte) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    color([b2f(v[0]), b2f(v[1]), b2f(v[2]), 1.0])
}

/// glColor3s.
#[no_mangle]
pub extern "C" fn glColor3s(red: GLshort, green: GLshort, blue: GLshort) {
    color([s2f(red), s2f(green), s2f(blue), 1.0])
}

/// glColor3sv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glColor3sv(v: *const GLshort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    color([s2f(v[0]), s2f(v[1]), s2f(v[2]), 1.0])
}

/// glColor3i.
#[no_mangle]
pub extern "C" fn glColor3i(red: GLint, green: GLint, blue: GLint) {
    color([i2f(red), i2f(green), i2f(blue), 1.0])
}

/// glColor3iv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glColor3iv(v: *const GLint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    color([i2f(v[0]), i2f(v[1]), i2f(v[2]), 1.0])
}

/// glColor3f.
#[no_mangle]
pub extern "C" fn glColor3f(red: GLfloat, green: GLfloat, blue: GLfloat) {
    color([red, green, blue, 1.0])
}

/// glColor3fv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glColor3fv(v: *const GLfloat) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    color([v[0], v[1], v[2], 1.0])
}

/// glColor3d.
#[no_mangle]
pub extern "C" fn glColor3d(red: GLdouble, green: GLdouble, blue: GLdouble) {
    color([red as f32, green as f32, blue as f32, 1.0])
}

/// glColor3dv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glColor3dv(v: *const GLdouble) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    color([v[0] as f32, v[1] as f32, v[2] as f32, 1.0])
}

/// glColor3ub.
#[no_mangle]
pub extern "C" fn glColor3ub(red: GLubyte, green: GLubyte, blue: GLubyte) {
    color([ub2f(red), ub2f(green), ub2f(blue), 1.0])
}

/// glColor3ubv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glColor3ubv(v: *const GLubyte) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    color([ub2f(v[0]), ub2f(v[1]), ub2f(v[2]), 1.0])
}

/// glColor3us.
#[no_mangle]
pub extern "C" fn glColor3us(red: GLushort, green: GLushort, blue: GLushort) {
    color([us2f(red), us2f(green), us2f(blue), 1.0])
}

/// glColor3usv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glColor3usv(v: *const GLushort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    color([us2f(v[0]), us2f(v[1]), us2f(v[2]), 1.0])
}

/// glColor3ui.
#[no_mangle]
pub extern "C" fn glColor3ui(red: GLuint, green: GLuint, blue: GLuint) {
    color([ui2f(red), ui2f(green), ui2f(blue), 1.0])
}

/// glColor3uiv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glColor3uiv(v: *const GLuint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    color([ui2f(v[0]), ui2f(v[1]), ui2f(v[2]), 1.0])
}

/// glColor4b.
#[no_mangle]
pub extern "C" fn glColor4b(red: GLbyte, green: GLbyte, blue: GLbyte, alpha: GLbyte) {
    color([b2f(red), b2f(green), b2f(blue), b2f(alpha)])
}

/// glColor4bv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glColor4bv(v: *const GLbyte) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    color([b2f(v[0]), b2f(v[1]), b2f(v[2]), b2f(v[3])])
}

/// glColor4s.
#[no_mangle]
pub extern "C" fn glColor4s(red: GLshort, green: GLshort, blue: GLshort, alpha: GLshort) {
    color([s2f(red), s2f(green), s2f(blue), s2f(alpha)])
}

/// glColor4sv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glColor4sv(v: *const GLshort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    color([s2f(v[0]), s2f(v[1]), s2f(v[2]), s2f(v[3])])
}

/// glColor4i.
#[no_mangle]
pub extern "C" fn glColor4i(red: GLint, green: GLint, blue: GLint, alpha: GLint) {
    color([i2f(red), i2f(green), i2f(blue), i2f(alpha)])
}

/// glColor4iv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glColor4iv(v: *const GLint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    color([i2f(v[0]), i2f(v[1]), i2f(v[2]), i2f(v[3])])
}

/// glColor4f.
#[no_mangle]
pub extern "C" fn glColor4f(red: GLfloat, green: GLfloat, blue: GLfloat, alpha: GLfloat) {
    color([red, green, blue, alpha])
}

/// glColor4fv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glColor4fv(v: *const GLfloat) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    color([v[0], v[1], v[2], v[3]])
}

/// glColor4d.
#[no_mangle]
pub extern "C" fn glColor4d(red: GLdouble, green: GLdouble, blue: GLdouble, alpha: GLdouble) {
    color([red as f32, green as f32, blue as f32, alpha as f32])
}

/// glColor4dv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glColor4dv(v: *const GLdouble) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    color([v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32])
}

/// glColor4ub.
#[no_mangle]
pub extern "C" fn glColor4ub(red: GLubyte, green: GLubyte, blue: GLubyte, alpha: GLubyte) {
    color([ub2f(red), ub2f(green), ub2f(blue), ub2f(alpha)])
}

/// glColor4ubv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glColor4ubv(v: *const GLubyte) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    color([ub2f(v[0]), ub2f(v[1]), ub2f(v[2]), ub2f(v[3])])
}

/// glColor4us.
#[no_mangle]
pub extern "C" fn glColor4us(red: GLushort, green: GLushort, blue: GLushort, alpha: GLushort) {
    color([us2f(red), us2f(green), us2f(blue), us2f(alpha)])
}

/// glColor4usv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glColor4usv(v: *const GLushort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    color([us2f(v[0]), us2f(v[1]), us2f(v[2]), us2f(v[3])])
}

/// glColor4ui.
#[no_mangle]
pub extern "C" fn glColor4ui(red: GLuint, green: GLuint, blue: GLuint, alpha: GLuint) {
    color([ui2f(red), ui2f(green), ui2f(blue), ui2f(alpha)])
}

/// glColor4uiv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glColor4uiv(v: *const GLuint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    color([ui2f(v[0]), ui2f(v[1]), ui2f(v[2]), ui2f(v[3])])
}

/// glTexCoord1s.
#[no_mangle]
pub extern "C" fn glTexCoord1s(s: GLshort) {
    texcoord([s as f32, 0.0, 0.0, 1.0])
}

/// glTexCoord1sv.
///
/// # Safety
/// `v` must point to 1 values.
#[no_mangle]
pub unsafe extern "C" fn glTexCoord1sv(v: *const GLshort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 1 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 1) };
    texcoord([v[0] as f32, 0.0, 0.0, 1.0])
}

/// glTexCoord1i.
#[no_mangle]
pub extern "C" fn glTexCoord1i(s: GLint) {
    texcoord([s as f32, 0.0, 0.0, 1.0])
}

/// glTexCoord1iv.
///
/// # Safety
/// `v` must point to 1 values.
#[no_mangle]
pub unsafe extern "C" fn glTexCoord1iv(v: *const GLint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 1 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 1) };
    texcoord([v[0] as f32, 0.0, 0.0, 1.0])
}

/// glTexCoord1f.
#[no_mangle]
pub extern "C" fn glTexCoord1f(s: GLfloat) {
    texcoord([s, 0.0, 0.0, 1.0])
}

/// glTexCoord1fv.
///
/// # Safety
/// `v` must point to 1 values.
#[no_mangle]
pub unsafe extern "C" fn glTexCoord1fv(v: *const GLfloat) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 1 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 1) };
    texcoord([v[0], 0.0, 0.0, 1.0])
}

/// glTexCoord1d.
#[no_mangle]
pub extern "C" fn glTexCoord1d(s: GLdouble) {
    texcoord([s as f32, 0.0, 0.0, 1.0])
}

/// glTexCoord1dv.
///
/// # Safety
/// `v` must point to 1 values.
#[no_mangle]
pub unsafe extern "C" fn glTexCoord1dv(v: *const GLdouble) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 1 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 1) };
    texcoord([v[0] as f32, 0.0, 0.0, 1.0])
}

/// glTexCoord2s.
#[no_mangle]
pub extern "C" fn glTexCoord2s(s: GLshort, t: GLshort) {
    texcoord([s as f32, t as f32, 0.0, 1.0])
}

/// glTexCoord2sv.
///
/// # Safety
/// `v` must point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glTexCoord2sv(v: *const GLshort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 2 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 2) };
    texcoord([v[0] as f32, v[1] as f32, 0.0, 1.0])
}

/// glTexCoord2i.
#[no_mangle]
pub extern "C" fn glTexCoord2i(s: GLint, t: GLint) {
    texcoord([s as f32, t as f32, 0.0, 1.0])
}

/// glTexCoord2iv.
///
/// # Safety
/// `v` must point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glTexCoord2iv(v: *const GLint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 2 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 2) };
    texcoord([v[0] as f32, v[1] as f32, 0.0, 1.0])
}

/// glTexCoord2f.
#[no_mangle]
pub extern "C" fn glTexCoord2f(s: GLfloat, t: GLfloat) {
    texcoord([s, t, 0.0, 1.0])
}

/// glTexCoord2fv.
///
/// # Safety
/// `v` must point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glTexCoord2fv(v: *const GLfloat) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 2 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 2) };
    texcoord([v[0], v[1], 0.0, 1.0])
}

/// glTexCoord2d.
#[no_mangle]
pub extern "C" fn glTexCoord2d(s: GLdouble, t: GLdouble) {
    texcoord([s as f32, t as f32, 0.0, 1.0])
}

/// glTexCoord2dv.
///
/// # Safety
/// `v` must point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glTexCoord2dv(v: *const GLdouble) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 2 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 2) };
    texcoord([v[0] as f32, v[1] as f32, 0.0, 1.0])
}

/// glTexCoord3s.
#[no_mangle]
pub extern "C" fn glTexCoord3s(s: GLshort, t: GLshort, r: GLshort) {
    texcoord([s as f32, t as f32, r as f32, 1.0])
}

/// glTexCoord3sv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glTexCoord3sv(v: *const GLshort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    texcoord([v[0] as f32, v[1] as f32, v[2] as f32, 1.0])
}

/// glTexCoord3i.
#[no_mangle]
pub extern "C" fn glTexCoord3i(s: GLint, t: GLint, r: GLint) {
    texcoord([s as f32, t as f32, r as f32, 1.0])
}

/// glTexCoord3iv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glTexCoord3iv(v: *const GLint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    texcoord([v[0] as f32, v[1] as f32, v[2] as f32, 1.0])
}

/// glTexCoord3f.
#[no_mangle]
pub extern "C" fn glTexCoord3f(s: GLfloat, t: GLfloat, r: GLfloat) {
    texcoord([s, t, r, 1.0])
}

/// glTexCoord3fv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glTexCoord3fv(v: *const GLfloat) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    texcoord([v[0], v[1], v[2], 1.0])
}

/// glTexCoord3d.
#[no_mangle]
pub extern "C" fn glTexCoord3d(s: GLdouble, t: GLdouble, r: GLdouble) {
    texcoord([s as f32, t as f32, r as f32, 1.0])
}

/// glTexCoord3dv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glTexCoord3dv(v: *const GLdouble) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    texcoord([v[0] as f32, v[1] as f32, v[2] as f32, 1.0])
}

/// glTexCoord4s.
#[no_mangle]
pub extern "C" fn glTexCoord4s(s: GLshort, t: GLshort, r: GLshort, q: GLshort) {
    texcoord([s as f32, t as f32, r as f32, q as f32])
}

/// glTexCoord4sv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glTexCoord4sv(v: *const GLshort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    texcoord([v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32])
}

/// glTexCoord4i.
#[no_mangle]
pub extern "C" fn glTexCoord4i(s: GLint, t: GLint, r: GLint, q: GLint) {
    texcoord([s as f32, t as f32, r as f32, q as f32])
}

/// glTexCoord4iv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glTexCoord4iv(v: *const GLint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    texcoord([v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32])
}

/// glTexCoord4f.
#[no_mangle]
pub extern "C" fn glTexCoord4f(s: GLfloat, t: GLfloat, r: GLfloat, q: GLfloat) {
    texcoord([s, t, r, q])
}

/// glTexCoord4fv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glTexCoord4fv(v: *const GLfloat) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    texcoord([v[0], v[1], v[2], v[3]])
}

/// glTexCoord4d.
#[no_mangle]
pub extern "C" fn glTexCoord4d(s: GLdouble, t: GLdouble, r: GLdouble, q: GLdouble) {
    texcoord([s as f32, t as f32, r as f32, q as f32])
}

/// glTexCoord4dv.
///
/// # Safety
/// `v` must point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glTexCoord4dv(v: *const GLdouble) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 4 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 4) };
    texcoord([v[0] as f32, v[1] as f32, v[2] as f32, v[3] as f32])
}

/// glNormal3b.
#[no_mangle]
pub extern "C" fn glNormal3b(nx: GLbyte, ny: GLbyte, nz: GLbyte) {
    normal([b2f(nx), b2f(ny), b2f(nz)])
}

/// glNormal3bv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glNormal3bv(v: *const GLbyte) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    normal([b2f(v[0]), b2f(v[1]), b2f(v[2])])
}

/// glNormal3s.
#[no_mangle]
pub extern "C" fn glNormal3s(nx: GLshort, ny: GLshort, nz: GLshort) {
    normal([s2f(nx), s2f(ny), s2f(nz)])
}

/// glNormal3sv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glNormal3sv(v: *const GLshort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    normal([s2f(v[0]), s2f(v[1]), s2f(v[2])])
}

/// glNormal3i.
#[no_mangle]
pub extern "C" fn glNormal3i(nx: GLint, ny: GLint, nz: GLint) {
    normal([i2f(nx), i2f(ny), i2f(nz)])
}

/// glNormal3iv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glNormal3iv(v: *const GLint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    normal([i2f(v[0]), i2f(v[1]), i2f(v[2])])
}

/// glNormal3f.
#[no_mangle]
pub extern "C" fn glNormal3f(nx: GLfloat, ny: GLfloat, nz: GLfloat) {
    normal([nx, ny, nz])
}

/// glNormal3fv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glNormal3fv(v: *const GLfloat) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    normal([v[0], v[1], v[2]])
}

/// glNormal3d.
#[no_mangle]
pub extern "C" fn glNormal3d(nx: GLdouble, ny: GLdouble, nz: GLdouble) {
    normal([nx as f32, ny as f32, nz as f32])
}

/// glNormal3dv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glNormal3dv(v: *const GLdouble) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe { std::slice::from_raw_parts(v, 3) };
    normal([v[0] as f32, v[1] as f32, v[2] as f32])
}

/// glRect as Mesa draws it: a GL_QUADS quad (x1,y1), (x2,y1), (x2,y2), (x1,y2) at z = 0.
/// A display list records it as one command that runs the immediate-mode path (Mesa's
/// OPCODE_RECTF), not as a vertex node.
fn rect(x1: f32, y1: f32, x2: f32, y2: f32) {
    with_ctx_list(move |c| {
        for op in [
            VertexOp::Begin(Primitive::Quads),
            VertexOp::Vertex([x1, y1, 0.0, 1.0]),
            VertexOp::Vertex([x2, y1, 0.0, 1.0]),
            VertexOp::Vertex([x2, y2, 0.0, 1.0]),
            VertexOp::Vertex([x1, y2, 0.0, 1.0]),
            VertexOp::End,
        ] {
            c.vertex_op(op)?;
        }
        Ok(())
    })
}

/// glRects.
#[no_mangle]
pub extern "C" fn glRects(x1: GLshort, y1: GLshort, x2: GLshort, y2: GLshort) {
    rect(x1 as f32, y1 as f32, x2 as f32, y2 as f32)
}

/// glRectsv.
///
/// # Safety
/// `v1` and `v2` must point to 2 values each.
#[no_mangle]
pub unsafe extern "C" fn glRectsv(v1: *const GLshort, v2: *const GLshort) {
    if v1.is_null() || v2.is_null() {
        return;
    }
    // SAFETY: the caller promises two readable values at each pointer.
    let (a, b) = unsafe {
        (
            std::slice::from_raw_parts(v1, 2),
            std::slice::from_raw_parts(v2, 2),
        )
    };
    rect(a[0] as f32, a[1] as f32, b[0] as f32, b[1] as f32)
}

/// glRecti.
#[no_mangle]
pub extern "C" fn glRecti(x1: GLint, y1: GLint, x2: GLint, y2: GLint) {
    rect(x1 as f32, y1 as f32, x2 as f32, y2 as f32)
}

/// glRectiv.
///
/// # Safety
/// `v1` and `v2` must point to 2 values each.
#[no_mangle]
pub unsafe extern "C" fn glRectiv(v1: *const GLint, v2: *const GLint) {
    if v1.is_null() || v2.is_null() {
        return;
    }
    // SAFETY: the caller promises two readable values at each pointer.
    let (a, b) = unsafe {
        (
            std::slice::from_raw_parts(v1, 2),
            std::slice::from_raw_parts(v2, 2),
        )
    };
    rect(a[0] as f32, a[1] as f32, b[0] as f32, b[1] as f32)
}

/// glRectf.
#[no_mangle]
pub extern "C" fn glRectf(x1: GLfloat, y1: GLfloat, x2: GLfloat, y2: GLfloat) {
    rect(x1, y1, x2, y2)
}

/// glRectfv.
///
/// # Safety
/// `v1` and `v2` must point to 2 values each.
#[no_mangle]
pub unsafe extern "C" fn glRectfv(v1: *const GLfloat, v2: *const GLfloat) {
    if v1.is_null() || v2.is_null() {
        return;
    }
    // SAFETY: the caller promises two readable values at each pointer.
    let (a, b) = unsafe {
        (
            std::slice::from_raw_parts(v1, 2),
            std::slice::from_raw_parts(v2, 2),
        )
    };
    rect(a[0], a[1], b[0], b[1])
}

/// glRectd.
#[no_mangle]
pub extern "C" fn glRectd(x1: GLdouble, y1: GLdouble, x2: GLdouble, y2: GLdouble) {
    rect(x1 as f32, y1 as f32, x2 as f32, y2 as f32)
}

/// glRectdv.
///
/// # Safety
/// `v1` and `v2` must point to 2 values each.
#[no_mangle]
pub unsafe extern "C" fn glRectdv(v1: *const GLdouble, v2: *const GLdouble) {
    if v1.is_null() || v2.is_null() {
        return;
    }
    // SAFETY: the caller promises two readable values at each pointer.
    let (a, b) = unsafe {
        (
            std::slice::from_raw_parts(v1, 2),
            std::slice::from_raw_parts(v2, 2),
        )
    };
    rect(a[0] as f32, a[1] as f32, b[0] as f32, b[1] as f32)
}
