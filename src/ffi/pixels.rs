//! Raster position and pixel rectangles of `GL/gl.h`: glRasterPos*, glPixelZoom.
//! Arguments convert to f32 as Mesa's `rastpos.c` does; vector forms read their values
//! before anything else.
#![allow(non_snake_case)]

use super::types::*;
use super::with_ctx_list;
use crate::context::pixel_ops::raster_pos::raster_pos;

fn rp(v: [f32; 4]) {
    with_ctx_list(move |c| {
        raster_pos(c, v);
        Ok(())
    })
}

/// Reads `N` values from a vector argument (`None` for null).
///
/// # Safety
/// `p` must be null or readable for `N` values.
pub(crate) unsafe fn read<T: Copy, const N: usize>(p: *const T) -> Option<[T; N]> {
    if p.is_null() {
        return None;
    }
    // SAFETY: the caller guarantees `N` readable values.
    Some(std::array::from_fn(|i| unsafe {
        p.add(i).read_unaligned()
    }))
}

/// glRasterPos2s.
#[no_mangle]
pub extern "C" fn glRasterPos2s(x: GLshort, y: GLshort) {
    rp([x as f32, y as f32, 0.0, 1.0])
}

/// glRasterPos2sv.
///
/// # Safety
/// `v` must be null or point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glRasterPos2sv(v: *const GLshort) {
    // SAFETY: the caller promises 2 values.
    if let Some(v) = unsafe { read::<GLshort, 2>(v) } {
        let v = v.map(|a| a as f32);
        rp([v[0], v[1], 0.0, 1.0])
    }
}

/// glRasterPos2i.
#[no_mangle]
pub extern "C" fn glRasterPos2i(x: GLint, y: GLint) {
    rp([x as f32, y as f32, 0.0, 1.0])
}

/// glRasterPos2iv.
///
/// # Safety
/// `v` must be null or point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glRasterPos2iv(v: *const GLint) {
    // SAFETY: the caller promises 2 values.
    if let Some(v) = unsafe { read::<GLint, 2>(v) } {
        let v = v.map(|a| a as f32);
        rp([v[0], v[1], 0.0, 1.0])
    }
}

/// glRasterPos2f.
#[no_mangle]
pub extern "C" fn glRasterPos2f(x: GLfloat, y: GLfloat) {
    rp([x, y, 0.0, 1.0])
}

/// glRasterPos2fv.
///
/// # Safety
/// `v` must be null or point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glRasterPos2fv(v: *const GLfloat) {
    // SAFETY: the caller promises 2 values.
    if let Some(v) = unsafe { read::<GLfloat, 2>(v) } {
        rp([v[0], v[1], 0.0, 1.0])
    }
}

/// glRasterPos2d.
#[no_mangle]
pub extern "C" fn glRasterPos2d(x: GLdouble, y: GLdouble) {
    rp([x as f32, y as f32, 0.0, 1.0])
}

/// glRasterPos2dv.
///
/// # Safety
/// `v` must be null or point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glRasterPos2dv(v: *const GLdouble) {
    // SAFETY: the caller promises 2 values.
    if let Some(v) = unsafe { read::<GLdouble, 2>(v) } {
        let v = v.map(|a| a as f32);
        rp([v[0], v[1], 0.0, 1.0])
    }
}

/// glRasterPos3s.
#[no_mangle]
pub extern "C" fn glRasterPos3s(x: GLshort, y: GLshort, z: GLshort) {
    rp([x as f32, y as f32, z as f32, 1.0])
}

/// glRasterPos3sv.
///
/// # Safety
/// `v` must be null or point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glRasterPos3sv(v: *const GLshort) {
    // SAFETY: the caller promises 3 values.
    if let Some(v) = unsafe { read::<GLshort, 3>(v) } {
        let v = v.map(|a| a as f32);
        rp([v[0], v[1], v[2], 1.0])
    }
}

/// glRasterPos3i.
#[no_mangle]
pub extern "C" fn glRasterPos3i(x: GLint, y: GLint, z: GLint) {
    rp([x as f32, y as f32, z as f32, 1.0])
}

/// glRasterPos3iv.
///
/// # Safety
/// `v` must be null or point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glRasterPos3iv(v: *const GLint) {
    // SAFETY: the caller promises 3 values.
    if let Some(v) = unsafe { read::<GLint, 3>(v) } {
        let v = v.map(|a| a as f32);
        rp([v[0], v[1], v[2], 1.0])
    }
}

/// glRasterPos3f.
#[no_mangle]
pub extern "C" fn glRasterPos3f(x: GLfloat, y: GLfloat, z: GLfloat) {
    rp([x, y, z, 1.0])
}

/// glRasterPos3fv.
///
/// # Safety
/// `v` must be null or point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glRasterPos3fv(v: *const GLfloat) {
    // SAFETY: the caller promises 3 values.
    if let Some(v) = unsafe { read::<GLfloat, 3>(v) } {
        rp([v[0], v[1], v[2], 1.0])
    }
}

/// glRasterPos3d.
#[no_mangle]
pub extern "C" fn glRasterPos3d(x: GLdouble, y: GLdouble, z: GLdouble) {
    rp([x as f32, y as f32, z as f32, 1.0])
}

/// glRasterPos3dv.
///
/// # Safety
/// `v` must be null or point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glRasterPos3dv(v: *const GLdouble) {
    // SAFETY: the caller promises 3 values.
    if let Some(v) = unsafe { read::<GLdouble, 3>(v) } {
        let v = v.map(|a| a as f32);
        rp([v[0], v[1], v[2], 1.0])
    }
}

/// glRasterPos4s.
#[no_mangle]
pub extern "C" fn glRasterPos4s(x: GLshort, y: GLshort, z: GLshort, w: GLshort) {
    rp([x as f32, y as f32, z as f32, w as f32])
}

/// glRasterPos4sv.
///
/// # Safety
/// `v` must be null or point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glRasterPos4sv(v: *const GLshort) {
    // SAFETY: the caller promises 4 values.
    if let Some(v) = unsafe { read::<GLshort, 4>(v) } {
        let v = v.map(|a| a as f32);
        rp(v)
    }
}

/// glRasterPos4i.
#[no_mangle]
pub extern "C" fn glRasterPos4i(x: GLint, y: GLint, z: GLint, w: GLint) {
    rp([x as f32, y as f32, z as f32, w as f32])
}

/// glRasterPos4iv.
///
/// # Safety
/// `v` must be null or point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glRasterPos4iv(v: *const GLint) {
    // SAFETY: the caller promises 4 values.
    if let Some(v) = unsafe { read::<GLint, 4>(v) } {
        let v = v.map(|a| a as f32);
        rp(v)
    }
}

/// glRasterPos4f.
#[no_mangle]
pub extern "C" fn glRasterPos4f(x: GLfloat, y: GLfloat, z: GLfloat, w: GLfloat) {
    rp([x, y, z, w])
}

/// glRasterPos4fv.
///
/// # Safety
/// `v` must be null or point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glRasterPos4fv(v: *const GLfloat) {
    // SAFETY: the caller promises 4 values.
    if let Some(v) = unsafe { read::<GLfloat, 4>(v) } {
        rp(v)
    }
}

/// glRasterPos4d.
#[no_mangle]
pub extern "C" fn glRasterPos4d(x: GLdouble, y: GLdouble, z: GLdouble, w: GLdouble) {
    rp([x as f32, y as f32, z as f32, w as f32])
}

/// glRasterPos4dv.
///
/// # Safety
/// `v` must be null or point to 4 values.
#[no_mangle]
pub unsafe extern "C" fn glRasterPos4dv(v: *const GLdouble) {
    // SAFETY: the caller promises 4 values.
    if let Some(v) = unsafe { read::<GLdouble, 4>(v) } {
        let v = v.map(|a| a as f32);
        rp(v)
    }
}

/// glPixelZoom.
#[no_mangle]
pub extern "C" fn glPixelZoom(xfactor: GLfloat, yfactor: GLfloat) {
    with_ctx_list(move |c| {
        c.pixel_modes.zoom = [xfactor, yfactor];
        Ok(())
    })
}
