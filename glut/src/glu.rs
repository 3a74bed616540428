//! GLU 1.3's commonly used part, written here: matrices (gluPerspective, gluLookAt,
//! gluOrtho2D, gluPickMatrix), gluProject/gluUnProject, gluUnProject4,
//! gluErrorString/gluGetString and gluCheckExtension (quadrics are in [`crate::quadric`],
//! images and mipmaps in [`crate::mipmap`]). Like the GLUT part it calls GL through the program's
//! GL, so it runs on softgl and on Mesa alike.

#![allow(non_snake_case)]

use crate::gl::{self, im, GLdouble, GLenum, GLint};
use std::f64::consts::PI;

// ---------------------------------------------------------------------------
// Matrices

/// Multiplies two column-major 4x4 matrices: a * b.
fn mul(a: &[f64; 16], b: &[f64; 16]) -> [f64; 16] {
    let mut r = [0.0; 16];
    for c in 0..4 {
        for row in 0..4 {
            r[c * 4 + row] = (0..4).map(|k| a[k * 4 + row] * b[c * 4 + k]).sum();
        }
    }
    r
}

/// The inverse of a column-major 4x4 matrix (cofactors), or None when singular.
fn invert(m: &[f64; 16]) -> Option<[f64; 16]> {
    let mut inv = [0.0; 16];
    let minor = |r0: usize, r1: usize, r2: usize, c0: usize, c1: usize, c2: usize| {
        let e = |r: usize, c: usize| m[c * 4 + r];
        e(r0, c0) * (e(r1, c1) * e(r2, c2) - e(r1, c2) * e(r2, c1))
            - e(r0, c1) * (e(r1, c0) * e(r2, c2) - e(r1, c2) * e(r2, c0))
            + e(r0, c2) * (e(r1, c0) * e(r2, c1) - e(r1, c1) * e(r2, c0))
    };
    let others = |i: usize| -> [usize; 3] {
        let mut o = [0; 3];
        let mut k = 0;
        for j in 0..4 {
            if j != i {
                o[k] = j;
                k += 1;
            }
        }
        o
    };
    for r in 0..4 {
        for c in 0..4 {
            let (rs, cs) = (others(r), others(c));
            let sign = if (r + c) % 2 == 0 { 1.0 } else { -1.0 };
            // inverse[c][r] (row c, column r) = cofactor(r, c) / det
            inv[r * 4 + c] = sign * minor(rs[0], rs[1], rs[2], cs[0], cs[1], cs[2]);
        }
    }
    let det: f64 = (0..4).map(|c| m[c * 4] * inv[c]).sum();
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    Some(inv.map(|v| v / det))
}

/// `gluPerspective`: multiplies the current matrix by a perspective projection.
#[no_mangle]
pub extern "C" fn gluPerspective(
    fovy: GLdouble,
    aspect: GLdouble,
    z_near: GLdouble,
    z_far: GLdouble,
) {
    let half = fovy / 2.0 * PI / 180.0;
    let dz = z_far - z_near;
    let s = half.sin();
    if dz == 0.0 || s == 0.0 || aspect == 0.0 {
        return;
    }
    let cot = half.cos() / s;
    let mut m = [0.0; 16];
    m[0] = cot / aspect;
    m[5] = cot;
    m[10] = -(z_far + z_near) / dz;
    m[11] = -1.0;
    m[14] = -2.0 * z_near * z_far / dz;
    im::mult(&m);
}

/// `gluOrtho2D`: glOrtho with near -1 and far 1.
#[no_mangle]
pub extern "C" fn gluOrtho2D(left: GLdouble, right: GLdouble, bottom: GLdouble, top: GLdouble) {
    // SAFETY: plain GL call without pointers.
    unsafe { gl::glOrtho(left, right, bottom, top, -1.0, 1.0) };
}

/// `gluLookAt`: a viewing transform from the eye towards the centre, `up` upwards.
///
/// The basis is computed in single precision and multiplied with glMultMatrixf, then the
/// eye is translated with glTranslated: SGI's libGLU (the one Mesa's users link) does
/// exactly that, and the matrices it leaves differ from a double-precision basis in the
/// last bit of a third of their entries, enough to move scattered pixels by one step.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn gluLookAt(
    eye_x: GLdouble,
    eye_y: GLdouble,
    eye_z: GLdouble,
    center_x: GLdouble,
    center_y: GLdouble,
    center_z: GLdouble,
    up_x: GLdouble,
    up_y: GLdouble,
    up_z: GLdouble,
) {
    let forward = [
        (center_x - eye_x) as f32,
        (center_y - eye_y) as f32,
        (center_z - eye_z) as f32,
    ];
    let f = normalize_f32(forward);
    let s = normalize_f32(cross_f32(f, [up_x as f32, up_y as f32, up_z as f32]));
    let u = cross_f32(s, f);
    let m = [
        s[0], u[0], -f[0], 0.0, s[1], u[1], -f[1], 0.0, s[2], u[2], -f[2], 0.0, 0.0, 0.0, 0.0, 1.0,
    ];
    im::mult_f32(&m);
    im::translate(-eye_x as f32, -eye_y as f32, -eye_z as f32);
}

/// A vector divided by its length, all in f32 (the length's square root rounded from
/// double, as C's `sqrt` of a float sum); a zero vector is returned unchanged.
fn normalize_f32(v: [f32; 3]) -> [f32; 3] {
    let l = (f64::from(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])).sqrt() as f32;
    if l == 0.0 {
        v
    } else {
        [v[0] / l, v[1] / l, v[2] / l]
    }
}

/// The cross product a × b in f32.
fn cross_f32(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `gluPickMatrix`: restricts drawing to a small region around (x, y) of the viewport.
#[no_mangle]
pub extern "C" fn gluPickMatrix(
    x: GLdouble,
    y: GLdouble,
    del_x: GLdouble,
    del_y: GLdouble,
    viewport: *const GLint,
) {
    if viewport.is_null() || del_x <= 0.0 || del_y <= 0.0 {
        return;
    }
    // SAFETY: GLU's contract: viewport points to four ints.
    let v = unsafe { std::slice::from_raw_parts(viewport, 4) };
    let (vx, vy, vw, vh) = (
        f64::from(v[0]),
        f64::from(v[1]),
        f64::from(v[2]),
        f64::from(v[3]),
    );
    im::translate(
        ((vw - 2.0 * (x - vx)) / del_x) as f32,
        ((vh - 2.0 * (y - vy)) / del_y) as f32,
        0.0,
    );
    im::scale((vw / del_x) as f32, (vh / del_y) as f32, 1.0);
}

/// Reads a 4x4 double matrix argument.
fn read16(p: *const GLdouble) -> Option<[f64; 16]> {
    if p.is_null() {
        return None;
    }
    let mut m = [0.0; 16];
    // SAFETY: GLU's contract: matrix arguments point to 16 doubles.
    m.copy_from_slice(unsafe { std::slice::from_raw_parts(p, 16) });
    Some(m)
}

/// Reads a viewport argument.
fn read4(p: *const GLint) -> Option<[f64; 4]> {
    if p.is_null() {
        return None;
    }
    // SAFETY: GLU's contract: viewport arguments point to four ints.
    let v = unsafe { std::slice::from_raw_parts(p, 4) };
    Some([v[0], v[1], v[2], v[3]].map(f64::from))
}

fn transform(m: &[f64; 16], v: [f64; 4]) -> [f64; 4] {
    let mut r = [0.0; 4];
    for (row, out) in r.iter_mut().enumerate() {
        *out = (0..4).map(|c| m[c * 4 + row] * v[c]).sum();
    }
    r
}

/// Writes three doubles through out-pointers (skipping NULL ones).
fn write3(out: [*mut GLdouble; 3], v: [f64; 3]) {
    for (p, x) in out.into_iter().zip(v) {
        if !p.is_null() {
            // SAFETY: a non-null out-pointer points to a double (GLU's contract).
            unsafe { *p = x };
        }
    }
}

/// `gluProject`: object coordinates to window coordinates; GL_FALSE when w is 0.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn gluProject(
    obj_x: GLdouble,
    obj_y: GLdouble,
    obj_z: GLdouble,
    model: *const GLdouble,
    proj: *const GLdouble,
    view: *const GLint,
    win_x: *mut GLdouble,
    win_y: *mut GLdouble,
    win_z: *mut GLdouble,
) -> GLint {
    let (Some(mv), Some(pr), Some(vp)) = (read16(model), read16(proj), read4(view)) else {
        return 0;
    };
    let c = transform(&pr, transform(&mv, [obj_x, obj_y, obj_z, 1.0]));
    if c[3] == 0.0 {
        return 0;
    }
    let n = [c[0] / c[3], c[1] / c[3], c[2] / c[3]];
    write3(
        [win_x, win_y, win_z],
        [
            vp[0] + vp[2] * (n[0] + 1.0) / 2.0,
            vp[1] + vp[3] * (n[1] + 1.0) / 2.0,
            (n[2] + 1.0) / 2.0,
        ],
    );
    1
}

/// Window coordinates (x, y, z already in [-1, 1], clip w) back through the inverse
/// of proj × model; None for bad matrices or viewport, or a point at infinity.
fn unproject(
    win: [f64; 4],
    model: *const GLdouble,
    proj: *const GLdouble,
    view: *const GLint,
) -> Option<[f64; 4]> {
    let (mv, pr, vp) = (read16(model)?, read16(proj)?, read4(view)?);
    let inv = invert(&mul(&pr, &mv))?;
    if vp[2] == 0.0 || vp[3] == 0.0 {
        return None;
    }
    let n = [
        (win[0] - vp[0]) / vp[2] * 2.0 - 1.0,
        (win[1] - vp[1]) / vp[3] * 2.0 - 1.0,
        win[2],
        win[3],
    ];
    let o = transform(&inv, n);
    (o[3] != 0.0).then_some(o)
}

/// `gluUnProject`: window coordinates back to object coordinates.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn gluUnProject(
    win_x: GLdouble,
    win_y: GLdouble,
    win_z: GLdouble,
    model: *const GLdouble,
    proj: *const GLdouble,
    view: *const GLint,
    obj_x: *mut GLdouble,
    obj_y: *mut GLdouble,
    obj_z: *mut GLdouble,
) -> GLint {
    let Some(o) = unproject([win_x, win_y, win_z * 2.0 - 1.0, 1.0], model, proj, view) else {
        return 0;
    };
    write3(
        [obj_x, obj_y, obj_z],
        [o[0] / o[3], o[1] / o[3], o[2] / o[3]],
    );
    1
}

/// `gluUnProject4`: window coordinates and clip w back to homogeneous object
/// coordinates, window z mapped from the depth range [near, far].
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn gluUnProject4(
    win_x: GLdouble,
    win_y: GLdouble,
    win_z: GLdouble,
    clip_w: GLdouble,
    model: *const GLdouble,
    proj: *const GLdouble,
    view: *const GLint,
    near: GLdouble,
    far: GLdouble,
    obj_x: *mut GLdouble,
    obj_y: *mut GLdouble,
    obj_z: *mut GLdouble,
    obj_w: *mut GLdouble,
) -> GLint {
    if near == far {
        return 0;
    }
    let z = (win_z - near) / (far - near) * 2.0 - 1.0;
    let Some(o) = unproject([win_x, win_y, z, clip_w], model, proj, view) else {
        return 0;
    };
    write3([obj_x, obj_y, obj_z], [o[0], o[1], o[2]]);
    write3(
        [obj_w, std::ptr::null_mut(), std::ptr::null_mut()],
        [o[3], 0.0, 0.0],
    );
    1
}

// ---------------------------------------------------------------------------
// Strings

/// `gluCheckExtension`: whether `name` is one of the space-separated words of
/// `list` (GL_TRUE/GL_FALSE; false for NULL or empty names).
#[no_mangle]
pub extern "C" fn gluCheckExtension(name: *const u8, list: *const u8) -> u8 {
    if name.is_null() || list.is_null() {
        return 0;
    }
    // SAFETY: GLU's contract: both are NUL-terminated strings.
    let (name, list) = unsafe {
        (
            std::ffi::CStr::from_ptr(name.cast()).to_bytes(),
            std::ffi::CStr::from_ptr(list.cast()).to_bytes(),
        )
    };
    u8::from(!name.is_empty() && list.split(|&c| c == b' ').any(|w| w == name))
}

/// `gluErrorString`: GL and GLU error names (static strings), NULL for other codes.
#[no_mangle]
pub extern "C" fn gluErrorString(code: GLenum) -> *const u8 {
    let s: &'static [u8] = match code {
        0 => b"no error\0",
        0x0500 => b"invalid enumerant\0",
        0x0501 => b"invalid value\0",
        0x0502 => b"invalid operation\0",
        0x0503 => b"stack overflow\0",
        0x0504 => b"stack underflow\0",
        0x0505 => b"out of memory\0",
        0x8031 => b"table too large\0",
        100900 => b"invalid enumerant\0",
        100901 => b"invalid value\0",
        100902 => b"out of memory\0",
        100903 => b"incompatible gl version\0",
        100904 => b"invalid operation\0",
        // The tessellator's errors, worded as SGI's GLU words them.
        100151 => b"gluTessBeginPolygon() must precede a gluTessEndPolygon()\0",
        100152 => b"gluTessBeginContour() must precede a gluTessEndContour()\0",
        100153 => b"gluTessEndPolygon() must follow a gluTessBeginPolygon()\0",
        100154 => b"gluTessEndContour() must follow a gluTessBeginContour()\0",
        100155 => b"a coordinate is too large\0",
        100156 => b"need combine callback\0",
        c @ 100251..=100287 => crate::nurbs::ERROR_STRINGS[(c - 100251) as usize].as_bytes(),
        _ => return std::ptr::null(),
    };
    s.as_ptr()
}

/// `gluGetString`: GLU_VERSION "1.3", GLU_EXTENSIONS "".
#[no_mangle]
pub extern "C" fn gluGetString(name: GLenum) -> *const u8 {
    match name {
        100800 => c"1.3".as_ptr().cast(),
        100801 => c"".as_ptr().cast(),
        _ => std::ptr::null(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse() {
        let m = [
            2.0, 0.0, 0.0, 0.0, 0.0, 4.0, 0.0, 0.0, 0.0, 0.0, 8.0, 0.0, 1.0, 2.0, 3.0, 1.0,
        ];
        let i = invert(&m).expect("invertible");
        let id = mul(&m, &i);
        for (k, v) in id.iter().enumerate() {
            let want = if k % 5 == 0 { 1.0 } else { 0.0 };
            assert!((v - want).abs() < 1e-12, "{id:?}");
        }
    }
}
