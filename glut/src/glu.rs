//! GLU 1.3's commonly used part, written here: matrices (gluPerspective, gluLookAt,
//! gluOrtho2D, gluPickMatrix), gluProject/gluUnProject, quadrics (sphere, cylinder,
//! disk, partial disk), gluScaleImage and gluBuild1D/2DMipmaps (box filters), and
//! gluErrorString/gluGetString. Like the GLUT part it calls GL through the program's
//! GL, so it runs on softgl and on Mesa alike.

#![allow(non_snake_case)]

use crate::gl::{self, im, GLdouble, GLenum, GLint, GLsizei};
use std::f64::consts::PI;
use std::ffi::{c_int, c_void};

const GLU_INVALID_ENUM: c_int = 100900;
const GLU_INVALID_VALUE: c_int = 100901;
const GLU_SMOOTH: GLenum = 100000;
const GLU_FLAT: GLenum = 100001;
const GLU_NONE: GLenum = 100002;
const GLU_POINT: GLenum = 100010;
const GLU_LINE: GLenum = 100011;
const GLU_FILL: GLenum = 100012;
const GLU_SILHOUETTE: GLenum = 100013;
const GLU_OUTSIDE: GLenum = 100020;
const GLU_INSIDE: GLenum = 100021;

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

fn normalize(v: [f64; 3]) -> [f64; 3] {
    let l = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    if l == 0.0 {
        v
    } else {
        [v[0] / l, v[1] / l, v[2] / l]
    }
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `gluLookAt`: a viewing transform from the eye towards the centre, `up` upwards.
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
    let f = normalize([center_x - eye_x, center_y - eye_y, center_z - eye_z]);
    let s = normalize(cross(f, [up_x, up_y, up_z]));
    let u = cross(s, f);
    let m = [
        s[0], u[0], -f[0], 0.0, s[1], u[1], -f[1], 0.0, s[2], u[2], -f[2], 0.0, 0.0, 0.0, 0.0, 1.0,
    ];
    im::mult(&m);
    im::translate(-eye_x as f32, -eye_y as f32, -eye_z as f32);
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
    let (Some(mv), Some(pr), Some(vp)) = (read16(model), read16(proj), read4(view)) else {
        return 0;
    };
    let Some(inv) = invert(&mul(&pr, &mv)) else {
        return 0;
    };
    if vp[2] == 0.0 || vp[3] == 0.0 {
        return 0;
    }
    let n = [
        (win_x - vp[0]) / vp[2] * 2.0 - 1.0,
        (win_y - vp[1]) / vp[3] * 2.0 - 1.0,
        win_z * 2.0 - 1.0,
        1.0,
    ];
    let o = transform(&inv, n);
    if o[3] == 0.0 {
        return 0;
    }
    write3(
        [obj_x, obj_y, obj_z],
        [o[0] / o[3], o[1] / o[3], o[2] / o[3]],
    );
    1
}

// ---------------------------------------------------------------------------
// Strings

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

// ---------------------------------------------------------------------------
// Quadrics

/// A `GLUquadric`: how quadric surfaces are drawn.
pub struct Quadric {
    normals: GLenum,
    texture: bool,
    orientation: GLenum,
    draw_style: GLenum,
}

/// `gluNewQuadric`.
#[no_mangle]
pub extern "C" fn gluNewQuadric() -> *mut Quadric {
    Box::into_raw(Box::new(Quadric {
        normals: GLU_SMOOTH,
        texture: false,
        orientation: GLU_OUTSIDE,
        draw_style: GLU_FILL,
    }))
}

/// `gluDeleteQuadric`.
#[no_mangle]
pub extern "C" fn gluDeleteQuadric(q: *mut Quadric) {
    if !q.is_null() {
        // SAFETY: q came from gluNewQuadric and is deleted once (GLU's contract).
        drop(unsafe { Box::from_raw(q) });
    }
}

/// Runs `f` on a quadric pointer (nothing for NULL).
fn with_q<R>(q: *mut Quadric, f: impl FnOnce(&mut Quadric) -> R) -> Option<R> {
    // SAFETY: a non-null quadric comes from gluNewQuadric and is not yet deleted.
    unsafe { q.as_mut() }.map(f)
}

/// `gluQuadricNormals`: GLU_SMOOTH, GLU_FLAT or GLU_NONE.
#[no_mangle]
pub extern "C" fn gluQuadricNormals(q: *mut Quadric, normals: GLenum) {
    if matches!(normals, GLU_SMOOTH | GLU_FLAT | GLU_NONE) {
        with_q(q, |q| q.normals = normals);
    }
}

/// `gluQuadricTexture`.
#[no_mangle]
pub extern "C" fn gluQuadricTexture(q: *mut Quadric, texture: u8) {
    with_q(q, |q| q.texture = texture != 0);
}

/// `gluQuadricOrientation`: GLU_OUTSIDE or GLU_INSIDE.
#[no_mangle]
pub extern "C" fn gluQuadricOrientation(q: *mut Quadric, orientation: GLenum) {
    if matches!(orientation, GLU_OUTSIDE | GLU_INSIDE) {
        with_q(q, |q| q.orientation = orientation);
    }
}

/// `gluQuadricDrawStyle`: GLU_FILL, GLU_LINE, GLU_SILHOUETTE (drawn as GLU_LINE) or
/// GLU_POINT.
#[no_mangle]
pub extern "C" fn gluQuadricDrawStyle(q: *mut Quadric, style: GLenum) {
    if matches!(style, GLU_FILL | GLU_LINE | GLU_SILHOUETTE | GLU_POINT) {
        with_q(q, |q| q.draw_style = style);
    }
}

/// `gluQuadricCallback`: errors are not reported through callbacks here.
#[no_mangle]
pub extern "C" fn gluQuadricCallback(
    _q: *mut Quadric,
    _which: GLenum,
    _f: Option<extern "C" fn()>,
) {
}

/// A grid vertex of a quadric: position, normal, texture coordinate.
type QVertex = ([f64; 3], [f64; 3], [f64; 2]);

/// Draws a (cols+1) x (rows+1) vertex grid in the quadric's style. Rows are strips
/// between grid rows j and j+1; `at(i, j)` gives the vertex.
fn draw_grid(q: &Quadric, cols: i32, rows: i32, at: impl Fn(i32, i32) -> QVertex) {
    let inside = q.orientation == GLU_INSIDE;
    let emit = |v: QVertex| {
        if q.normals != GLU_NONE {
            let s = if inside { -1.0 } else { 1.0 };
            im::n3([
                (v.1[0] * s) as f32,
                (v.1[1] * s) as f32,
                (v.1[2] * s) as f32,
            ]);
        }
        if q.texture {
            im::t2(v.2[0] as f32, v.2[1] as f32);
        }
        im::v3([v.0[0] as f32, v.0[1] as f32, v.0[2] as f32]);
    };
    match q.draw_style {
        GLU_FILL => {
            for j in 0..rows {
                im::begin(gl::GL_QUAD_STRIP);
                for i in 0..=cols {
                    let (a, b) = if inside { (j, j + 1) } else { (j + 1, j) };
                    emit(at(i, a));
                    emit(at(i, b));
                }
                im::end();
            }
        }
        GLU_POINT => {
            im::begin(gl::GL_POINTS);
            for j in 0..=rows {
                for i in 0..=cols {
                    emit(at(i, j));
                }
            }
            im::end();
        }
        _ => {
            for j in 0..=rows {
                im::begin(gl::GL_LINE_STRIP);
                for i in 0..=cols {
                    emit(at(i, j));
                }
                im::end();
            }
            for i in 0..=cols {
                im::begin(gl::GL_LINE_STRIP);
                for j in 0..=rows {
                    emit(at(i, j));
                }
                im::end();
            }
        }
    }
}

/// `gluCylinder`: along +z from 0 to `height`, radius from `base` to `top`; s runs
/// around (0 at +y), t along z.
#[no_mangle]
pub extern "C" fn gluCylinder(
    q: *mut Quadric,
    base: GLdouble,
    top: GLdouble,
    height: GLdouble,
    slices: GLint,
    stacks: GLint,
) {
    if slices < 2 || stacks < 1 || base < 0.0 || top < 0.0 || height < 0.0 {
        return;
    }
    let slope = (base - top) / if height == 0.0 { 1.0 } else { height };
    let nl = (1.0 + slope * slope).sqrt();
    with_q(q, |q| {
        draw_grid(q, slices, stacks, |i, j| {
            let a = 2.0 * PI * f64::from(i % slices) / f64::from(slices);
            let t = f64::from(j) / f64::from(stacks);
            let r = base + (top - base) * t;
            let (sn, cs) = a.sin_cos();
            (
                [r * sn, r * cs, height * t],
                [sn / nl, cs / nl, slope / nl],
                [f64::from(i) / f64::from(slices), t],
            )
        })
    });
}

/// `gluSphere`: radius around the origin, stacks from -z to +z; s around, t up.
#[no_mangle]
pub extern "C" fn gluSphere(q: *mut Quadric, radius: GLdouble, slices: GLint, stacks: GLint) {
    if slices < 2 || stacks < 1 || radius < 0.0 {
        return;
    }
    with_q(q, |q| {
        draw_grid(q, slices, stacks, |i, j| {
            let a = 2.0 * PI * f64::from(i % slices) / f64::from(slices);
            let rho = PI - PI * f64::from(j) / f64::from(stacks);
            let (sn, cs) = a.sin_cos();
            let n = [sn * rho.sin(), cs * rho.sin(), rho.cos()];
            (
                n.map(|c| c * radius),
                n,
                [
                    f64::from(i) / f64::from(slices),
                    f64::from(j) / f64::from(stacks),
                ],
            )
        })
    });
}

/// `gluPartialDisk`: a ring in the z = 0 plane from `start` degrees (0 = +y,
/// clockwise) over `sweep` degrees; s, t map the disk's square onto [0, 1].
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn gluPartialDisk(
    q: *mut Quadric,
    inner: GLdouble,
    outer: GLdouble,
    slices: GLint,
    loops: GLint,
    start: GLdouble,
    sweep: GLdouble,
) {
    if slices < 2 || loops < 1 || inner < 0.0 || outer <= 0.0 || outer < inner {
        return;
    }
    let sweep = sweep.clamp(-360.0, 360.0);
    let full = sweep.abs() >= 360.0;
    with_q(q, |q| {
        // Rows run outward so that the outside (+z) faces the viewer after the swap
        // draw_grid makes for GLU_OUTSIDE.
        draw_grid(q, slices, loops, |i, j| {
            let i = if full { i % slices } else { i };
            let a = (start + sweep * f64::from(i) / f64::from(slices)) * PI / 180.0;
            let r = outer - (outer - inner) * f64::from(j) / f64::from(loops);
            let (sn, cs) = a.sin_cos();
            (
                [r * sn, r * cs, 0.0],
                [0.0, 0.0, 1.0],
                [0.5 + r * sn / outer / 2.0, 0.5 + r * cs / outer / 2.0],
            )
        })
    });
}

/// `gluDisk`: a full [`gluPartialDisk`].
#[no_mangle]
pub extern "C" fn gluDisk(
    q: *mut Quadric,
    inner: GLdouble,
    outer: GLdouble,
    slices: GLint,
    loops: GLint,
) {
    gluPartialDisk(q, inner, outer, slices, loops, 0.0, 360.0);
}

// ---------------------------------------------------------------------------
// Images

/// Components per pixel of a client format, None when GLU does not know it.
fn components(format: GLenum) -> Option<usize> {
    Some(match format {
        0x1903..=0x1906 | 0x1909 | 0x1901 => 1, // RED..ALPHA, LUMINANCE, STENCIL_INDEX
        0x1902 => 1,                            // DEPTH_COMPONENT
        0x190A => 2,                            // LUMINANCE_ALPHA
        0x1907 | 0x80E0 => 3,                   // RGB, BGR
        0x1908 | 0x80E1 => 4,                   // RGBA, BGRA
        _ => return None,
    })
}

/// Bytes per component of a supported type.
fn type_size(ty: GLenum) -> Option<usize> {
    match ty {
        gl::GL_UNSIGNED_BYTE | 0x1400 => Some(1),
        0x1402 | 0x1403 => Some(2),
        0x1404 | 0x1405 | gl::GL_FLOAT => Some(4),
        _ => None,
    }
}

/// Reads one component as f64 in the type's own scale.
///
/// # Safety
/// `p` must point to a readable value of type `ty`.
unsafe fn read_comp(p: *const u8, ty: GLenum) -> f64 {
    // SAFETY: the caller guarantees p points to a value of `ty` (unaligned reads).
    unsafe {
        match ty {
            0x1400 => f64::from(p.cast::<i8>().read()),
            0x1402 => f64::from(p.cast::<u16>().read_unaligned()),
            0x1403 => f64::from(p.cast::<i16>().read_unaligned()),
            0x1404 => f64::from(p.cast::<u32>().read_unaligned()),
            0x1405 => f64::from(p.cast::<i32>().read_unaligned()),
            gl::GL_FLOAT => f64::from(p.cast::<f32>().read_unaligned()),
            _ => f64::from(p.read()),
        }
    }
}

/// Converts an f64 in the type's scale back (rounded, clamped for integer types).
fn to_bytes(v: f64, ty: GLenum) -> Vec<u8> {
    let r = v.round();
    match ty {
        0x1400 => vec![r.clamp(-128.0, 127.0) as i8 as u8],
        0x1402 => (r.clamp(0.0, 65535.0) as u16).to_ne_bytes().to_vec(),
        0x1403 => (r.clamp(-32768.0, 32767.0) as i16).to_ne_bytes().to_vec(),
        0x1404 => (r.clamp(0.0, u32::MAX as f64) as u32)
            .to_ne_bytes()
            .to_vec(),
        0x1405 => (r.clamp(i32::MIN as f64, i32::MAX as f64) as i32)
            .to_ne_bytes()
            .to_vec(),
        gl::GL_FLOAT => (v as f32).to_ne_bytes().to_vec(),
        _ => vec![r.clamp(0.0, 255.0) as u8],
    }
}

/// An image as f64 components, tightly packed, in its type's scale.
struct Img {
    w: usize,
    h: usize,
    n: usize,
    data: Vec<f64>,
}

/// Byte offset of each row under pixel-store parameters.
fn row_stride(ps: &gl::PixelStore, w: usize, n: usize, size: usize) -> usize {
    let len = if ps.row_length > 0 {
        ps.row_length as usize
    } else {
        w
    };
    let bytes = len * n * size;
    let a = ps.alignment.max(1) as usize;
    if size >= a {
        bytes
    } else {
        bytes.div_ceil(a) * a
    }
}

/// Reads a client image under the current unpack parameters.
fn read_image(data: *const c_void, w: usize, h: usize, n: usize, ty: GLenum) -> Img {
    let size = type_size(ty).unwrap_or(1);
    let ps = gl::PixelStore::unpack();
    let stride = row_stride(&ps, w, n, size);
    let skip = ps.skip_rows.max(0) as usize * stride + ps.skip_pixels.max(0) as usize * n * size;
    let mut out = Vec::with_capacity(w * h * n);
    for y in 0..h {
        for x in 0..w * n {
            // SAFETY: GLU's contract: data holds the image described by w, h, format,
            // type and the unpack parameters; the offset stays inside it.
            out.push(unsafe { read_comp(data.cast::<u8>().add(skip + y * stride + x * size), ty) });
        }
    }
    Img { w, h, n, data: out }
}

/// Writes an image under the current pack parameters.
fn write_image(img: &Img, out: *mut c_void, ty: GLenum) {
    let size = type_size(ty).unwrap_or(1);
    let ps = gl::PixelStore::pack();
    let stride = row_stride(&ps, img.w, img.n, size);
    let skip =
        ps.skip_rows.max(0) as usize * stride + ps.skip_pixels.max(0) as usize * img.n * size;
    for y in 0..img.h {
        for x in 0..img.w * img.n {
            let bytes = to_bytes(img.data[y * img.w * img.n + x], ty);
            // SAFETY: GLU's contract: out has room for the image under the pack
            // parameters; the offset stays inside it.
            unsafe {
                std::ptr::copy_nonoverlapping(
                    bytes.as_ptr(),
                    out.cast::<u8>().add(skip + y * stride + x * size),
                    bytes.len(),
                )
            };
        }
    }
}

/// Box-filter weights: for each output index, (first input index, weights).
fn box_weights(n_in: usize, n_out: usize) -> Vec<(usize, Vec<f64>)> {
    let ratio = n_in as f64 / n_out as f64;
    (0..n_out)
        .map(|o| {
            let (a, b) = (o as f64 * ratio, (o + 1) as f64 * ratio);
            let first = a.floor() as usize;
            let last = (b.ceil() as usize).min(n_in).max(first + 1);
            let ws = (first..last)
                .map(|i| {
                    let lo = a.max(i as f64);
                    let hi = b.min(i as f64 + 1.0);
                    (hi - lo).max(0.0) / (b - a)
                })
                .collect();
            (first, ws)
        })
        .collect()
}

/// Scales an image with an area-weighted box filter (separable).
fn scale_image(img: &Img, w: usize, h: usize) -> Img {
    let (wx, wy) = (box_weights(img.w, w), box_weights(img.h, h));
    let n = img.n;
    let mut data = vec![0.0; w * h * n];
    for (oy, (fy, wys)) in wy.iter().enumerate() {
        for (ox, (fx, wxs)) in wx.iter().enumerate() {
            for c in 0..n {
                let mut acc = 0.0;
                for (dy, wyv) in wys.iter().enumerate() {
                    for (dx, wxv) in wxs.iter().enumerate() {
                        acc += wyv * wxv * img.data[((fy + dy) * img.w + fx + dx) * n + c];
                    }
                }
                data[(oy * w + ox) * n + c] = acc;
            }
        }
    }
    Img { w, h, n, data }
}

/// `gluScaleImage`: scales a client image with a box filter; 0 on success or a GLU
/// error code.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn gluScaleImage(
    format: GLenum,
    w_in: GLsizei,
    h_in: GLsizei,
    type_in: GLenum,
    data_in: *const c_void,
    w_out: GLsizei,
    h_out: GLsizei,
    type_out: GLenum,
    data_out: *mut c_void,
) -> GLint {
    let (Some(n), Some(_), Some(_)) = (components(format), type_size(type_in), type_size(type_out))
    else {
        return GLU_INVALID_ENUM;
    };
    if w_in < 0 || h_in < 0 || w_out < 0 || h_out < 0 {
        return GLU_INVALID_VALUE;
    }
    if w_in == 0 || h_in == 0 || w_out == 0 || h_out == 0 || data_in.is_null() || data_out.is_null()
    {
        return 0;
    }
    let img = read_image(data_in, w_in as usize, h_in as usize, n, type_in);
    write_image(
        &scale_image(&img, w_out as usize, h_out as usize),
        data_out,
        type_out,
    );
    0
}

/// The largest power of two not above `v` (at least 1).
fn floor_pow2(v: usize) -> usize {
    if v <= 1 {
        1
    } else {
        1 << (usize::BITS - 1 - v.leading_zeros())
    }
}

/// Uploads `img` and its box-filtered halvings, level 0 first.
fn upload_mipmaps(
    target: GLenum,
    internal: GLint,
    mut img: Img,
    format: GLenum,
    ty: GLenum,
    two_d: bool,
) {
    let saved = gl::PixelStore::unpack();
    gl::PixelStore::TIGHT.set_unpack();
    let mut level = 0;
    loop {
        let bytes: Vec<u8> = img.data.iter().flat_map(|&v| to_bytes(v, ty)).collect();
        // SAFETY: bytes holds img.w x img.h pixels of `format`/`ty`, tightly packed as
        // the unpack state just set says.
        unsafe {
            if two_d {
                gl::glTexImage2D(
                    target,
                    level,
                    internal,
                    img.w as GLsizei,
                    img.h as GLsizei,
                    0,
                    format,
                    ty,
                    bytes.as_ptr().cast(),
                );
            } else {
                gl::glTexImage1D(
                    target,
                    level,
                    internal,
                    img.w as GLsizei,
                    0,
                    format,
                    ty,
                    bytes.as_ptr().cast(),
                );
            }
        }
        if img.w == 1 && img.h == 1 {
            break;
        }
        img = scale_image(&img, (img.w / 2).max(1), (img.h / 2).max(1));
        if ty != gl::GL_FLOAT {
            img.data.iter_mut().for_each(|v| *v = v.round());
        }
        level += 1;
    }
    saved.set_unpack();
}

/// Shared part of the mipmap builders: reads, resizes to powers of two within
/// GL_MAX_TEXTURE_SIZE, uploads the chain.
#[allow(clippy::too_many_arguments)]
fn build_mipmaps(
    target: GLenum,
    internal: GLint,
    w: GLsizei,
    h: GLsizei,
    format: GLenum,
    ty: GLenum,
    data: *const c_void,
    two_d: bool,
) -> GLint {
    let (Some(n), Some(_)) = (components(format), type_size(ty)) else {
        return GLU_INVALID_ENUM;
    };
    if w < 1 || h < 1 {
        return GLU_INVALID_VALUE;
    }
    if data.is_null() {
        return 0;
    }
    let max = gl::get_int(gl::GL_MAX_TEXTURE_SIZE).max(1) as usize;
    let img = read_image(data, w as usize, h as usize, n, ty);
    let (nw, nh) = (
        floor_pow2(w as usize).min(max),
        floor_pow2(h as usize).min(max),
    );
    let mut img = if (nw, nh) == (img.w, img.h) {
        img
    } else {
        scale_image(&img, nw, nh)
    };
    if ty != gl::GL_FLOAT {
        img.data.iter_mut().for_each(|v| *v = v.round());
    }
    upload_mipmaps(target, internal, img, format, ty, two_d);
    0
}

/// `gluBuild2DMipmaps`: scales the image to powers of two (down, within the GL's
/// maximum) and uploads it with every box-filtered level; 0 on success.
#[no_mangle]
pub extern "C" fn gluBuild2DMipmaps(
    target: GLenum,
    internal: GLint,
    w: GLsizei,
    h: GLsizei,
    format: GLenum,
    ty: GLenum,
    data: *const c_void,
) -> GLint {
    build_mipmaps(target, internal, w, h, format, ty, data, true)
}

/// `gluBuild1DMipmaps`: [`gluBuild2DMipmaps`] for 1D textures.
#[no_mangle]
pub extern "C" fn gluBuild1DMipmaps(
    target: GLenum,
    internal: GLint,
    w: GLsizei,
    format: GLenum,
    ty: GLenum,
    data: *const c_void,
) -> GLint {
    build_mipmaps(target, internal, w, 1, format, ty, data, false)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inverse_and_box() {
        let m = [
            2.0, 0.0, 0.0, 0.0, 0.0, 4.0, 0.0, 0.0, 0.0, 0.0, 8.0, 0.0, 1.0, 2.0, 3.0, 1.0,
        ];
        let i = invert(&m).expect("invertible");
        let id = mul(&m, &i);
        for (k, v) in id.iter().enumerate() {
            let want = if k % 5 == 0 { 1.0 } else { 0.0 };
            assert!((v - want).abs() < 1e-12, "{id:?}");
        }
        let img = Img {
            w: 4,
            h: 1,
            n: 1,
            data: vec![0.0, 2.0, 4.0, 6.0],
        };
        assert_eq!(scale_image(&img, 2, 1).data, vec![1.0, 5.0]);
        assert_eq!(scale_image(&img, 8, 1).data[..3], [0.0, 0.0, 2.0]);
        assert_eq!(floor_pow2(100), 64);
    }
}
