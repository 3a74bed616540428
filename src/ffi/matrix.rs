//! Matrix calls: glMatrixMode, loads, multiplies, the builders and the stacks.
#![allow(non_snake_case)]

use super::enums::*;
use super::families::c_fns;
use super::types::*;
use super::with_ctx_list_keep;
use crate::context::error::GlError;
use crate::context::state::MatrixMode;
use crate::fixed_function::matrix::{Mat4, IDENTITY};
use crate::fixed_function::mesa_matrix::MatFlags;

/// glMatrixMode.
#[no_mangle]
pub extern "C" fn glMatrixMode(mode: GLenum) {
    with_ctx_list_keep(move |c| {
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
    with_ctx_list_keep(move |c| {
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
    with_ctx_list_keep(move |c| {
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

c_fns! {
    unsafe fn glLoadMatrixf(m: *const GLfloat) => load(read16(m), false, false);
    unsafe fn glLoadMatrixd(m: *const GLdouble) => load(read16(m), false, false);
    unsafe fn glMultMatrixf(m: *const GLfloat) => load(read16(m), false, true);
    unsafe fn glMultMatrixd(m: *const GLdouble) => load(read16(m), false, true);
    unsafe fn glLoadTransposeMatrixf(m: *const GLfloat) => load(read16(m), true, false);
    unsafe fn glLoadTransposeMatrixd(m: *const GLdouble) => load(read16(m), true, false);
    unsafe fn glMultTransposeMatrixf(m: *const GLfloat) => load(read16(m), true, true);
    unsafe fn glMultTransposeMatrixd(m: *const GLdouble) => load(read16(m), true, true);
}

/// glTranslatef.
#[no_mangle]
pub extern "C" fn glTranslatef(x: GLfloat, y: GLfloat, z: GLfloat) {
    with_ctx_list_keep(move |c| {
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
    with_ctx_list_keep(move |c| {
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
    with_ctx_list_keep(move |c| {
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

/// glFrustum and glOrtho: GL_INVALID_VALUE when `invalid` says so of the planes (left,
/// right, bottom, top, near, far), else multiplies the current matrix by `make` of the
/// planes (converted to f32) and records the kind of matrix.
fn projection(
    planes: [GLdouble; 6],
    invalid: fn([GLdouble; 6]) -> bool,
    make: fn(f32, f32, f32, f32, f32, f32) -> Mat4,
    flag: fn(&mut MatFlags) -> bool,
) {
    with_ctx_list_keep(move |c| {
        if invalid(planes) {
            return Err(GlError::InvalidValue);
        }
        let [l, r, b, t, n, f] = planes.map(|v| v as f32);
        let p = make(l, r, b, t, n, f);
        c.with_matrix_flags(|m, fl| {
            *m = m.mul(&p);
            flag(fl);
        })
    })
}

/// glFrustum's invalid planes.
fn bad_frustum([left, right, bottom, top, near, far]: [GLdouble; 6]) -> bool {
    near <= 0.0 || far <= 0.0 || near == far || left == right || top == bottom
}

/// glOrtho's invalid planes.
fn bad_ortho([left, right, bottom, top, near, far]: [GLdouble; 6]) -> bool {
    left == right || bottom == top || near == far
}

c_fns! {
    safe fn glFrustum(left: GLdouble, right: GLdouble, bottom: GLdouble, top: GLdouble, zNear: GLdouble, zFar: GLdouble) => projection([left, right, bottom, top, zNear, zFar], bad_frustum, Mat4::frustum, MatFlags::on_frustum);
    safe fn glOrtho(left: GLdouble, right: GLdouble, bottom: GLdouble, top: GLdouble, zNear: GLdouble, zFar: GLdouble) => projection([left, right, bottom, top, zNear, zFar], bad_ortho, Mat4::ortho, MatFlags::on_ortho);
}

/// glPushMatrix.
#[no_mangle]
pub extern "C" fn glPushMatrix() {
    with_ctx_list_keep(move |c| c.push_matrix())
}

/// glPopMatrix.
#[no_mangle]
pub extern "C" fn glPopMatrix() {
    with_ctx_list_keep(move |c| c.pop_matrix())
}
