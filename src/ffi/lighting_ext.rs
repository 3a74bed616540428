//! GL 1.4 vertex attributes of the lighting and fog stages (`GL/glext.h`): the current
//! secondary colour (glSecondaryColor3*) and fog coordinate (glFogCoord*). Integer
//! colours convert as Mesa's vbo module does (`(2c + 1) / (2^n - 1)` for signed types,
//! `c / (2^n - 1)` for unsigned ones); the alpha of the secondary colour is 1.
#![allow(non_snake_case)]

use super::types::*;
use super::with_ctx_vertex;
use crate::context::dlist::VertexOp;

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
fn f2f(f: GLfloat) -> f32 {
    f
}
#[inline]
fn d2f(d: GLdouble) -> f32 {
    d as f32
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

/// Sets the current secondary colour (allowed between glBegin and glEnd).
fn secondary(v: [f32; 3]) {
    with_ctx_vertex(VertexOp::SecondaryColor(v))
}

/// Sets the current fog coordinate (allowed between glBegin and glEnd).
fn fog_coord(f: f32) {
    with_ctx_vertex(VertexOp::FogCoord(f))
}

/// glFogCoordf.
#[no_mangle]
pub extern "C" fn glFogCoordf(coord: GLfloat) {
    fog_coord(coord)
}

/// glFogCoordd.
#[no_mangle]
pub extern "C" fn glFogCoordd(coord: GLdouble) {
    fog_coord(coord as f32)
}

/// glFogCoordfv.
///
/// # Safety
/// `coord` must point to one value.
#[no_mangle]
pub unsafe extern "C" fn glFogCoordfv(coord: *const GLfloat) {
    if !coord.is_null() {
        // SAFETY: the caller promises one readable value.
        fog_coord(unsafe { coord.read_unaligned() })
    }
}

/// glFogCoorddv.
///
/// # Safety
/// `coord` must point to one value.
#[no_mangle]
pub unsafe extern "C" fn glFogCoorddv(coord: *const GLdouble) {
    if !coord.is_null() {
        // SAFETY: the caller promises one readable value.
        fog_coord(unsafe { coord.read_unaligned() } as f32)
    }
}

/// glSecondaryColor3b.
#[no_mangle]
pub extern "C" fn glSecondaryColor3b(red: GLbyte, green: GLbyte, blue: GLbyte) {
    secondary([b2f(red), b2f(green), b2f(blue)])
}

/// glSecondaryColor3bv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3bv(v: *const GLbyte) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe {
        [
            v.read_unaligned(),
            v.add(1).read_unaligned(),
            v.add(2).read_unaligned(),
        ]
    };
    secondary([b2f(v[0]), b2f(v[1]), b2f(v[2])])
}

/// glSecondaryColor3s.
#[no_mangle]
pub extern "C" fn glSecondaryColor3s(red: GLshort, green: GLshort, blue: GLshort) {
    secondary([s2f(red), s2f(green), s2f(blue)])
}

/// glSecondaryColor3sv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3sv(v: *const GLshort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe {
        [
            v.read_unaligned(),
            v.add(1).read_unaligned(),
            v.add(2).read_unaligned(),
        ]
    };
    secondary([s2f(v[0]), s2f(v[1]), s2f(v[2])])
}

/// glSecondaryColor3i.
#[no_mangle]
pub extern "C" fn glSecondaryColor3i(red: GLint, green: GLint, blue: GLint) {
    secondary([i2f(red), i2f(green), i2f(blue)])
}

/// glSecondaryColor3iv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3iv(v: *const GLint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe {
        [
            v.read_unaligned(),
            v.add(1).read_unaligned(),
            v.add(2).read_unaligned(),
        ]
    };
    secondary([i2f(v[0]), i2f(v[1]), i2f(v[2])])
}

/// glSecondaryColor3f.
#[no_mangle]
pub extern "C" fn glSecondaryColor3f(red: GLfloat, green: GLfloat, blue: GLfloat) {
    secondary([f2f(red), f2f(green), f2f(blue)])
}

/// glSecondaryColor3fv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3fv(v: *const GLfloat) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe {
        [
            v.read_unaligned(),
            v.add(1).read_unaligned(),
            v.add(2).read_unaligned(),
        ]
    };
    secondary([f2f(v[0]), f2f(v[1]), f2f(v[2])])
}

/// glSecondaryColor3d.
#[no_mangle]
pub extern "C" fn glSecondaryColor3d(red: GLdouble, green: GLdouble, blue: GLdouble) {
    secondary([d2f(red), d2f(green), d2f(blue)])
}

/// glSecondaryColor3dv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3dv(v: *const GLdouble) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe {
        [
            v.read_unaligned(),
            v.add(1).read_unaligned(),
            v.add(2).read_unaligned(),
        ]
    };
    secondary([d2f(v[0]), d2f(v[1]), d2f(v[2])])
}

/// glSecondaryColor3ub.
#[no_mangle]
pub extern "C" fn glSecondaryColor3ub(red: GLubyte, green: GLubyte, blue: GLubyte) {
    secondary([ub2f(red), ub2f(green), ub2f(blue)])
}

/// glSecondaryColor3ubv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3ubv(v: *const GLubyte) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe {
        [
            v.read_unaligned(),
            v.add(1).read_unaligned(),
            v.add(2).read_unaligned(),
        ]
    };
    secondary([ub2f(v[0]), ub2f(v[1]), ub2f(v[2])])
}

/// glSecondaryColor3us.
#[no_mangle]
pub extern "C" fn glSecondaryColor3us(red: GLushort, green: GLushort, blue: GLushort) {
    secondary([us2f(red), us2f(green), us2f(blue)])
}

/// glSecondaryColor3usv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3usv(v: *const GLushort) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe {
        [
            v.read_unaligned(),
            v.add(1).read_unaligned(),
            v.add(2).read_unaligned(),
        ]
    };
    secondary([us2f(v[0]), us2f(v[1]), us2f(v[2])])
}

/// glSecondaryColor3ui.
#[no_mangle]
pub extern "C" fn glSecondaryColor3ui(red: GLuint, green: GLuint, blue: GLuint) {
    secondary([ui2f(red), ui2f(green), ui2f(blue)])
}

/// glSecondaryColor3uiv.
///
/// # Safety
/// `v` must point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glSecondaryColor3uiv(v: *const GLuint) {
    if v.is_null() {
        return;
    }
    // SAFETY: the caller promises 3 readable values.
    let v = unsafe {
        [
            v.read_unaligned(),
            v.add(1).read_unaligned(),
            v.add(2).read_unaligned(),
        ]
    };
    secondary([ui2f(v[0]), ui2f(v[1]), ui2f(v[2])])
}
