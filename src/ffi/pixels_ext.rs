//! glWindowPos of GL 1.4 (`GL/glext.h`) with the ARB aliases Mesa exports (it exports no MESA ones):
//! window coordinates set the raster position directly (Mesa's `window_pos3f`).
#![allow(non_snake_case)]

use super::pixels::read;
use super::types::*;
use super::with_ctx_list;
use crate::context::pixel_ops::raster_pos::window_pos;

fn wp(x: f32, y: f32, z: f32) {
    with_ctx_list(move |c| {
        window_pos(c, x, y, z);
        Ok(())
    })
}

/// glWindowPos2s.
#[no_mangle]
pub extern "C" fn glWindowPos2s(x: GLshort, y: GLshort) {
    wp(x as f32, y as f32, 0.0)
}

/// glWindowPos2sv.
///
/// # Safety
/// `v` must be null or point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2sv(v: *const GLshort) {
    // SAFETY: the caller promises 2 values.
    if let Some(v) = unsafe { read::<GLshort, 2>(v) } {
        let v = v.map(|a| a as f32);
        wp(v[0], v[1], 0.0)
    }
}

/// glWindowPos2i.
#[no_mangle]
pub extern "C" fn glWindowPos2i(x: GLint, y: GLint) {
    wp(x as f32, y as f32, 0.0)
}

/// glWindowPos2iv.
///
/// # Safety
/// `v` must be null or point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2iv(v: *const GLint) {
    // SAFETY: the caller promises 2 values.
    if let Some(v) = unsafe { read::<GLint, 2>(v) } {
        let v = v.map(|a| a as f32);
        wp(v[0], v[1], 0.0)
    }
}

/// glWindowPos2f.
#[no_mangle]
pub extern "C" fn glWindowPos2f(x: GLfloat, y: GLfloat) {
    wp(x, y, 0.0)
}

/// glWindowPos2fv.
///
/// # Safety
/// `v` must be null or point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2fv(v: *const GLfloat) {
    // SAFETY: the caller promises 2 values.
    if let Some(v) = unsafe { read::<GLfloat, 2>(v) } {
        wp(v[0], v[1], 0.0)
    }
}

/// glWindowPos2d.
#[no_mangle]
pub extern "C" fn glWindowPos2d(x: GLdouble, y: GLdouble) {
    wp(x as f32, y as f32, 0.0)
}

/// glWindowPos2dv.
///
/// # Safety
/// `v` must be null or point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2dv(v: *const GLdouble) {
    // SAFETY: the caller promises 2 values.
    if let Some(v) = unsafe { read::<GLdouble, 2>(v) } {
        let v = v.map(|a| a as f32);
        wp(v[0], v[1], 0.0)
    }
}

/// glWindowPos3s.
#[no_mangle]
pub extern "C" fn glWindowPos3s(x: GLshort, y: GLshort, z: GLshort) {
    wp(x as f32, y as f32, z as f32)
}

/// glWindowPos3sv.
///
/// # Safety
/// `v` must be null or point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3sv(v: *const GLshort) {
    // SAFETY: the caller promises 3 values.
    if let Some(v) = unsafe { read::<GLshort, 3>(v) } {
        let v = v.map(|a| a as f32);
        wp(v[0], v[1], v[2])
    }
}

/// glWindowPos3i.
#[no_mangle]
pub extern "C" fn glWindowPos3i(x: GLint, y: GLint, z: GLint) {
    wp(x as f32, y as f32, z as f32)
}

/// glWindowPos3iv.
///
/// # Safety
/// `v` must be null or point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3iv(v: *const GLint) {
    // SAFETY: the caller promises 3 values.
    if let Some(v) = unsafe { read::<GLint, 3>(v) } {
        let v = v.map(|a| a as f32);
        wp(v[0], v[1], v[2])
    }
}

/// glWindowPos3f.
#[no_mangle]
pub extern "C" fn glWindowPos3f(x: GLfloat, y: GLfloat, z: GLfloat) {
    wp(x, y, z)
}

/// glWindowPos3fv.
///
/// # Safety
/// `v` must be null or point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3fv(v: *const GLfloat) {
    // SAFETY: the caller promises 3 values.
    if let Some(v) = unsafe { read::<GLfloat, 3>(v) } {
        wp(v[0], v[1], v[2])
    }
}

/// glWindowPos3d.
#[no_mangle]
pub extern "C" fn glWindowPos3d(x: GLdouble, y: GLdouble, z: GLdouble) {
    wp(x as f32, y as f32, z as f32)
}

/// glWindowPos3dv.
///
/// # Safety
/// `v` must be null or point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3dv(v: *const GLdouble) {
    // SAFETY: the caller promises 3 values.
    if let Some(v) = unsafe { read::<GLdouble, 3>(v) } {
        let v = v.map(|a| a as f32);
        wp(v[0], v[1], v[2])
    }
}

/// glWindowPos2sARB.
#[no_mangle]
pub extern "C" fn glWindowPos2sARB(x: GLshort, y: GLshort) {
    wp(x as f32, y as f32, 0.0)
}

/// glWindowPos2svARB.
///
/// # Safety
/// `v` must be null or point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2svARB(v: *const GLshort) {
    // SAFETY: the caller promises 2 values.
    if let Some(v) = unsafe { read::<GLshort, 2>(v) } {
        let v = v.map(|a| a as f32);
        wp(v[0], v[1], 0.0)
    }
}

/// glWindowPos2iARB.
#[no_mangle]
pub extern "C" fn glWindowPos2iARB(x: GLint, y: GLint) {
    wp(x as f32, y as f32, 0.0)
}

/// glWindowPos2ivARB.
///
/// # Safety
/// `v` must be null or point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2ivARB(v: *const GLint) {
    // SAFETY: the caller promises 2 values.
    if let Some(v) = unsafe { read::<GLint, 2>(v) } {
        let v = v.map(|a| a as f32);
        wp(v[0], v[1], 0.0)
    }
}

/// glWindowPos2fARB.
#[no_mangle]
pub extern "C" fn glWindowPos2fARB(x: GLfloat, y: GLfloat) {
    wp(x, y, 0.0)
}

/// glWindowPos2fvARB.
///
/// # Safety
/// `v` must be null or point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2fvARB(v: *const GLfloat) {
    // SAFETY: the caller promises 2 values.
    if let Some(v) = unsafe { read::<GLfloat, 2>(v) } {
        wp(v[0], v[1], 0.0)
    }
}

/// glWindowPos2dARB.
#[no_mangle]
pub extern "C" fn glWindowPos2dARB(x: GLdouble, y: GLdouble) {
    wp(x as f32, y as f32, 0.0)
}

/// glWindowPos2dvARB.
///
/// # Safety
/// `v` must be null or point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos2dvARB(v: *const GLdouble) {
    // SAFETY: the caller promises 2 values.
    if let Some(v) = unsafe { read::<GLdouble, 2>(v) } {
        let v = v.map(|a| a as f32);
        wp(v[0], v[1], 0.0)
    }
}

/// glWindowPos3sARB.
#[no_mangle]
pub extern "C" fn glWindowPos3sARB(x: GLshort, y: GLshort, z: GLshort) {
    wp(x as f32, y as f32, z as f32)
}

/// glWindowPos3svARB.
///
/// # Safety
/// `v` must be null or point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3svARB(v: *const GLshort) {
    // SAFETY: the caller promises 3 values.
    if let Some(v) = unsafe { read::<GLshort, 3>(v) } {
        let v = v.map(|a| a as f32);
        wp(v[0], v[1], v[2])
    }
}

/// glWindowPos3iARB.
#[no_mangle]
pub extern "C" fn glWindowPos3iARB(x: GLint, y: GLint, z: GLint) {
    wp(x as f32, y as f32, z as f32)
}

/// glWindowPos3ivARB.
///
/// # Safety
/// `v` must be null or point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3ivARB(v: *const GLint) {
    // SAFETY: the caller promises 3 values.
    if let Some(v) = unsafe { read::<GLint, 3>(v) } {
        let v = v.map(|a| a as f32);
        wp(v[0], v[1], v[2])
    }
}

/// glWindowPos3fARB.
#[no_mangle]
pub extern "C" fn glWindowPos3fARB(x: GLfloat, y: GLfloat, z: GLfloat) {
    wp(x, y, z)
}

/// glWindowPos3fvARB.
///
/// # Safety
/// `v` must be null or point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3fvARB(v: *const GLfloat) {
    // SAFETY: the caller promises 3 values.
    if let Some(v) = unsafe { read::<GLfloat, 3>(v) } {
        wp(v[0], v[1], v[2])
    }
}

/// glWindowPos3dARB.
#[no_mangle]
pub extern "C" fn glWindowPos3dARB(x: GLdouble, y: GLdouble, z: GLdouble) {
    wp(x as f32, y as f32, z as f32)
}

/// glWindowPos3dvARB.
///
/// # Safety
/// `v` must be null or point to 3 values.
#[no_mangle]
pub unsafe extern "C" fn glWindowPos3dvARB(v: *const GLdouble) {
    // SAFETY: the caller promises 3 values.
    if let Some(v) = unsafe { read::<GLdouble, 3>(v) } {
        let v = v.map(|a| a as f32);
        wp(v[0], v[1], v[2])
    }
}
