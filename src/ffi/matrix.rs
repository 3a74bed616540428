//! Matrix calls: glMatrixMode, loads, multiplies, the builders and the stacks.
#![allow(non_snake_case)]

use super::enums::*;
use super::types::*;
use super::with_ctx_list;
use crate::context::error::GlError;
use crate::context::state::MatrixMode;
use crate::fixed_function::matrix::{Mat4, IDENTITY};

/// glMatrixMode.
#[no_mangle]
pub extern "C" fn glMatrixMode(mode: GLenum) {
    with_ctx_list(move |c| {
        let m = match mode {
            GL_MODELVIEW => MatrixMode::ModelView,
            GL_PROJECTION => MatrixMode::Projection,
            GL_TEXTURE => MatrixMode::Texture,
            GL_COLOR => MatrixMode::Color,
            _ => return Err(GlError::InvalidEnum),
        };
        c.state.matrix_mode = m;
        Ok(())
    })
}

/// glLoadIdentity.
#[no_mangle]
pub extern "C" fn glLoadIdentity() {
    with_ctx_list(move |c| {
        c.with_matrix_flags(|m, f| {
            *m = IDENTITY;
            f.on_load_identity();
        })
    })
}

/// Reads 16 values through `p`, or None for NULL.
///
/// # Safety
/// `p` must be NULL or readable for 16 elements.
unsafe fn read16<T: Copy + Into<f64>>(p: *const T) -> Option<Mat4> {
    if p.is_null() {
        return None;
    }
    let mut m = [0f32; 16];
    for (i, v) in m.iter_mut().enumerate() {
        // SAFETY: the caller promises 16 readable elements.
        *v = unsafe { *p.add(i) }.into() as f32;
    }
    Some(Mat4(m))
}

fn load(m: Option<Mat4>, transpose: bool, multiply: bool) {
    with_ctx_list(move |c| {
        let Some(m) = m else { return Ok(()) };
        let m = if transpose { m.transpose() } else { m };
        c.with_matrix_flags(|cur, f| {
            if multiply {
                if m != IDENTITY {
                    *cur = cur.mul(&m);
                    f.on_mult();
                }
            } else if *cur != m {
                *cur = m;
                f.on_load();
            }
        })
    })
}

/// glLoadMatrixf.
///
/// # Safety
/// `m` must point to 16 floats.
#[no_mangle]
pub unsafe extern "C" fn glLoadMatrixf(m: *const GLfloat) {
    // SAFETY: forwarded caller contract.
    load(unsafe { read16(m) }, false, false)
}

/// glLoadMatrixd.
///
/// # Safety
/// `m` must point to 16 doubles.
#[no_mangle]
pub unsafe extern "C" fn glLoadMatrixd(m: *const GLdouble) {
    // SAFETY: forwarded caller contract.
    load(unsafe { read16(m) }, false, false)
}

/// glMultMatrixf.
///
/// # Safety
/// `m` must point to 16 floats.
#[no_mangle]
pub unsafe extern "C" fn glMultMatrixf(m: *const GLfloat) {
    // SAFETY: forwarded caller contract.
    load(unsafe { read16(m) }, false, true)
}

/// glMultMatrixd.
///
/// # Safety
/// `m` must point to 16 doubles.
#[no_mangle]
pub unsafe extern "C" fn glMultMatrixd(m: *const GLdouble) {
    // SAFETY: forwarded caller contract.
    load(unsafe { read16(m) }, false, true)
}

/// glLoadTransposeMatrixf.
///
/// # Safety
/// `m` must point to 16 floats.
#[no_mangle]
pub unsafe extern "C" fn glLoadTransposeMatrixf(m: *const GLfloat) {
    // SAFETY: forwarded caller contract.
    load(unsafe { read16(m) }, true, false)
}

/// glLoadTransposeMatrixd.
///
/// # Safety
/// `m` must point to 16 doubles.
#[no_mangle]
pub unsafe extern "C" fn glLoadTransposeMatrixd(m: *const GLdouble) {
    // SAFETY: forwarded caller contract.
    load(unsafe { read16(m) }, true, false)
}

/// glMultTransposeMatrixf.
///
/// # Safety
/// `m` must point to 16 floats.
#[no_mangle]
pub unsafe extern "C" fn glMultTransposeMatrixf(m: *const GLfloat) {
    // SAFETY: forwarded caller contract.
    load(unsafe { read16(m) }, true, true)
}

/// glMultTransposeMatrixd.
///
/// # Safety
/// `m` must point to 16 doubles.
#[no_mangle]
pub unsafe extern "C" fn glMultTransposeMatrixd(m: *const GLdouble) {
    // SAFETY: forwarded caller contract.
    load(unsafe { read16(m) }, true, true)
}

/// glTranslatef.
#[no_mangle]
pub extern "C" fn glTranslatef(x: GLfloat, y: GLfloat, z: GLfloat) {
    with_ctx_list(move |c| {
        c.with_matrix_flags(|m, f| {
            m.translate(x, y, z);
            f.on_translate();
        })
    })
}

/// glTranslated.
#[no_mangle]
pub extern "C" fn glTranslated(x: GLdouble, y: GLdouble, z: GLdouble) {
    glTranslatef(x as f32, y as f32, z as f32)
}

/// glScalef.
#[no_mangle]
pub extern "C" fn glScalef(x: GLfloat, y: GLfloat, z: GLfloat) {
    with_ctx_list(move |c| {
        c.with_matrix_flags(|m, f| {
            m.scale(x, y, z);
            f.on_scale(x, y, z);
        })
    })
}

/// glScaled.
#[no_mangle]
pub extern "C" fn glScaled(x: GLdouble, y: GLdouble, z: GLdouble) {
    glScalef(x as f32, y as f32, z as f32)
}

/// glRotatef.
#[no_mangle]
pub extern "C" fn glRotatef(angle: GLfloat, x: GLfloat, y: GLfloat, z: GLfloat) {
    with_ctx_list(move |c| {
        c.with_matrix_flags(|m, f| {
            // Mesa skips a zero angle, and a degenerate axis leaves the matrix alone.
            if angle != 0.0 && m.rotate(angle, x, y, z) {
                f.on_rotate();
            }
        })
    })
}

/// glRotated.
#[no_mangle]
pub extern "C" fn glRotated(angle: GLdouble, x: GLdouble, y: GLdouble, z: GLdouble) {
    glRotatef(angle as f32, x as f32, y as f32, z as f32)
}

/// glFrustum.
#[no_mangle]
pub extern "C" fn glFrustum(
    left: GLdouble,
    right: GLdouble,
    bottom: GLdouble,
    top: GLdouble,
    zNear: GLdouble,
    zFar: GLdouble,
) {
    with_ctx_list(move |c| {
        if zNear <= 0.0 || zFar <= 0.0 || zNear == zFar || left == right || top == bottom {
            return Err(GlError::InvalidValue);
        }
        let f = Mat4::frustum(
            left as f32,
            right as f32,
            bottom as f32,
            top as f32,
            zNear as f32,
            zFar as f32,
        );
        c.with_matrix_flags(|m, fl| {
            *m = m.mul(&f);
            fl.on_frustum();
        })
    })
}

/// glOrtho.
#[no_mangle]
pub extern "C" fn glOrtho(
    left: GLdouble,
    right: GLdouble,
    bottom: GLdouble,
    top: GLdouble,
    zNear: GLdouble,
    zFar: GLdouble,
) {
    with_ctx_list(move |c| {
        if left == right || bottom == top || zNear == zFar {
            return Err(GlError::InvalidValue);
        }
        let o = Mat4::ortho(
            left as f32,
            right as f32,
            bottom as f32,
            top as f32,
            zNear as f32,
            zFar as f32,
        );
        c.with_matrix_flags(|m, fl| {
            *m = m.mul(&o);
            fl.on_ortho();
        })
    })
}

/// glPushMatrix.
#[no_mangle]
pub extern "C" fn glPushMatrix() {
    with_ctx_list(move |c| c.push_matrix())
}

/// glPopMatrix.
#[no_mangle]
pub extern "C" fn glPopMatrix() {
    with_ctx_list(move |c| c.pop_matrix())
}
