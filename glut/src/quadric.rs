//! GLU quadrics: cylinders (and cones), spheres, disks and partial disks.
//!
//! Programs pair Mesa's libOSMesa with SGI's libGLU, so a quadric is right when it sends GL
//! the calls libGLU sends: the same primitives, vertex order and values. The values follow
//! libGLU's precision, which is not uniform:
//!
//! - angles are rounded to f32, then their sine and cosine are taken in f64 and rounded to
//!   f32 for the position tables;
//! - normal tables multiply that f64 sine by the f32 normal ratio in f64, then round;
//! - radii and heights of a stack or loop are computed in f64 from an f32 fraction and
//!   rounded; positions are f32 products of a radius and a table entry;
//! - texture coordinates are f32 (`1 - i/slices`), disks add 0.5 in f64 before rounding.
//!
//! A sphere without texture coordinates closes its poles with triangle fans; with them
//! every stack is a quad strip. libGLU reads a few tables past what it filled in rare
//! cases (flat normals with GLU_POINT or GLU_SILHOUETTE; a sphere with more stacks than
//! slices at its south pole); there the tables here hold the values the formula gives.

use crate::gl::{self, im, GLdouble, GLenum, GLint};
use std::f64::consts::PI;

const GLU_INVALID_VALUE: GLenum = 100901;
pub(crate) const GLU_SMOOTH: GLenum = 100000;
pub(crate) const GLU_FLAT: GLenum = 100001;
pub(crate) const GLU_NONE: GLenum = 100002;
pub(crate) const GLU_POINT: GLenum = 100010;
pub(crate) const GLU_LINE: GLenum = 100011;
pub(crate) const GLU_FILL: GLenum = 100012;
pub(crate) const GLU_SILHOUETTE: GLenum = 100013;
pub(crate) const GLU_OUTSIDE: GLenum = 100020;
pub(crate) const GLU_INSIDE: GLenum = 100021;
/// libGLU's table size: slices (and sphere stacks) are clamped to one less.
const CACHE_SIZE: GLint = 240;

/// A `GLUquadric`: how quadric surfaces are drawn.
pub struct Quadric {
    normals: GLenum,
    texture: bool,
    orientation: GLenum,
    draw_style: GLenum,
    /// The GLU_ERROR callback, called with GLU_INVALID_VALUE for bad sizes.
    error: Option<extern "C" fn(GLenum)>,
}

impl Quadric {
    fn outside(&self) -> bool {
        self.orientation == GLU_OUTSIDE
    }
    fn fail(&self) {
        if let Some(cb) = self.error {
            cb(GLU_INVALID_VALUE);
        }
    }
    /// `glTexCoord2f` when texture coordinates are generated.
    fn tex(&self, s: f32, t: f32) {
        if self.texture {
            im::t2(s, t);
        }
    }
}

/// `gluNewQuadric`.
#[no_mangle]
pub extern "C" fn gluNewQuadric() -> *mut Quadric {
    Box::into_raw(Box::new(Quadric {
        normals: GLU_SMOOTH,
        texture: false,
        orientation: GLU_OUTSIDE,
        draw_style: GLU_FILL,
        error: None,
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

/// `gluQuadricDrawStyle`: GLU_FILL, GLU_LINE, GLU_SILHOUETTE or GLU_POINT.
#[no_mangle]
pub extern "C" fn gluQuadricDrawStyle(q: *mut Quadric, style: GLenum) {
    if matches!(style, GLU_FILL | GLU_LINE | GLU_SILHOUETTE | GLU_POINT) {
        with_q(q, |q| q.draw_style = style);
    }
}

/// `gluQuadricCallback`: GLU_ERROR (100103) sets the function called on bad sizes.
#[no_mangle]
pub extern "C" fn gluQuadricCallback(q: *mut Quadric, which: GLenum, f: Option<extern "C" fn()>) {
    if which == 100103 {
        // SAFETY: GLU's error callback takes the error code; the C declaration erases it
        // to `void (*)()`, and the program passed a function of that true type.
        let f =
            f.map(|f| unsafe { std::mem::transmute::<extern "C" fn(), extern "C" fn(GLenum)>(f) });
        with_q(q, |q| q.error = f);
    }
}

/// sin and cos (f64) of an angle libGLU has rounded to f32.
fn trig(angle: f64) -> (f64, f64) {
    let a = f64::from(angle as f32);
    (a.sin(), a.cos())
}

/// A table of `n + 1` (sin, cos) pairs of the angles `angle(i)`, each scaled by `k` in f64
/// and rounded to f32; entry `n` repeats entry 0 when `closed`.
fn table(n: i32, closed: bool, k: f64, angle: impl Fn(f64) -> f64) -> Vec<(f32, f32)> {
    (0..=n)
        .map(|i| {
            let i = if closed && i == n { 0 } else { i };
            let (s, c) = trig(angle(f64::from(i)));
            ((k * s) as f32, (k * c) as f32)
        })
        .collect()
}

/// `i / n` in f32, as libGLU's `(float) i / n`.
fn frac(i: i32, n: i32) -> f32 {
    i as f32 / n as f32
}

/// `glNormal3f`.
fn normal(x: f32, y: f32, z: f32) {
    im::n3([x, y, z]);
}

/// `glVertex3f`.
fn vertex(x: f32, y: f32, z: f32) {
    im::v3([x, y, z]);
}

/// `gluCylinder`: along +z from 0 to `height`, radius from `base` to `top`.
#[no_mangle]
pub extern "C" fn gluCylinder(
    q: *mut Quadric,
    base: GLdouble,
    top: GLdouble,
    height: GLdouble,
    slices: GLint,
    stacks: GLint,
) {
    with_q(q, |q| {
        cylinder(q, base, top, height, slices.min(CACHE_SIZE - 1), stacks)
    });
}

fn cylinder(q: &Quadric, base: f64, top: f64, height: f64, slices: i32, stacks: i32) {
    if slices < 2 || stacks < 1 || base < 0.0 || top < 0.0 || height < 0.0 {
        return q.fail();
    }
    let dr = (base - top) as f32;
    let length = (f64::from(dr * dr) + height * height).sqrt() as f32;
    if length == 0.0 {
        return q.fail();
    }
    let z_normal = dr / length;
    let xy = (height / f64::from(length)) as f32;
    let k = if q.outside() {
        f64::from(xy)
    } else {
        -f64::from(xy)
    };
    let n = f64::from(slices);
    let pos = table(slices, true, 1.0, |i| 2.0 * PI * i / n);
    let smooth = table(slices, true, k, |i| 2.0 * PI * i / n);
    let flat = table(slices, true, k, |i| 2.0 * PI * (i - 0.5) / n);
    let z_at = |j: i32| (f64::from(j) * height / f64::from(stacks)) as f32;
    let r_at = |j: i32| (base - f64::from(dr * frac(j, stacks))) as f32;
    let s_at = |i: i32| 1.0 - frac(i, slices);
    let ring_normal = |i: usize, flat_table: &[(f32, f32)]| match q.normals {
        GLU_FLAT => normal(flat_table[i].0, flat_table[i].1, z_normal),
        GLU_SMOOTH => normal(smooth[i].0, smooth[i].1, z_normal),
        _ => {}
    };
    // One ring of the side at stack j.
    let ring = |j: i32| {
        let (z, r) = (z_at(j), r_at(j));
        im::begin(gl::GL_LINE_STRIP);
        for i in 0..=slices {
            ring_normal(i as usize, &flat);
            q.tex(s_at(i), frac(j, stacks));
            let (s, c) = pos[i as usize];
            vertex(r * s, r * c, z);
        }
        im::end();
    };
    // One line of slice i from the base to the top.
    let rib = |i: i32| {
        let (s, c) = pos[i as usize];
        for j in 0..=stacks {
            let (z, r) = (z_at(j), r_at(j));
            q.tex(s_at(i), frac(j, stacks));
            vertex(r * s, r * c, z);
        }
    };
    match q.draw_style {
        GLU_FILL => {
            for j in 0..stacks {
                let (lo, hi) = ((z_at(j), r_at(j)), (z_at(j + 1), r_at(j + 1)));
                im::begin(gl::GL_QUAD_STRIP);
                for i in 0..=slices {
                    ring_normal(i as usize, &flat);
                    let (s, c) = pos[i as usize];
                    let order = if q.outside() {
                        [(lo, j), (hi, j + 1)]
                    } else {
                        [(hi, j + 1), (lo, j)]
                    };
                    for ((z, r), jj) in order {
                        q.tex(s_at(i), frac(jj, stacks));
                        vertex(r * s, r * c, z);
                    }
                }
                im::end();
            }
        }
        GLU_POINT => {
            im::begin(gl::GL_POINTS);
            for i in 0..slices {
                if q.normals != GLU_NONE {
                    normal(smooth[i as usize].0, smooth[i as usize].1, z_normal);
                }
                rib(i);
            }
            im::end();
        }
        GLU_LINE | GLU_SILHOUETTE => {
            if q.draw_style == GLU_LINE {
                (1..stacks).for_each(ring);
            }
            ring(0);
            ring(stacks);
            for i in 0..slices {
                if q.normals != GLU_NONE {
                    normal(smooth[i as usize].0, smooth[i as usize].1, 0.0);
                }
                im::begin(gl::GL_LINE_STRIP);
                rib(i);
                im::end();
            }
        }
        _ => {}
    }
}

/// `gluSphere`: radius around the origin, from +z (stack 0) to -z.
#[no_mangle]
pub extern "C" fn gluSphere(q: *mut Quadric, radius: GLdouble, slices: GLint, stacks: GLint) {
    with_q(q, |q| {
        sphere(
            q,
            radius,
            slices.min(CACHE_SIZE - 1),
            stacks.min(CACHE_SIZE - 1),
        )
    });
}

fn sphere(q: &Quadric, radius: f64, slices: i32, stacks: i32) {
    if slices < 2 || stacks < 1 || radius < 0.0 {
        return q.fail();
    }
    let out = q.outside();
    let flip = if out { 1.0 } else { -1.0 };
    let (n, m) = (f64::from(slices), f64::from(stacks));
    // Around: positions and smooth normals share one table; `flat_a` is half a slice back.
    // The around tables reach index `stacks` too (see the module doc).
    let around = table(slices.max(stacks), false, 1.0, |i| 2.0 * PI * i / n);
    let around: Vec<(f32, f32)> = (0..around.len())
        .map(|i| {
            if i == slices as usize {
                around[0]
            } else {
                around[i]
            }
        })
        .collect();
    let flat_a = table(slices, true, 1.0, |i| 2.0 * PI * (i - 0.5) / n);
    // Down: positions scaled by the radius (pinched to 0 at the poles), normals by ±1.
    let mut down = table(stacks, false, radius, |j| PI * j / m);
    down[0].0 = 0.0;
    down[stacks as usize].0 = 0.0;
    let smooth_b = table(stacks, false, flip, |j| PI * j / m);
    let flat_b = table(stacks, false, flip, |j| PI * (j - 0.5) / m);
    let s_at = |i: i32| 1.0 - frac(i, slices);
    let t_at = |j: i32| 1.0 - frac(j, stacks);
    let at = |i: usize, j: usize| {
        let (s, c) = around[i];
        let (rs, z) = down[j];
        vertex(rs * s, rs * c, z)
    };
    let nrm = |a: (f32, f32), b: (f32, f32)| normal(a.0 * b.0, a.1 * b.0, b.1);
    match q.draw_style {
        GLU_FILL => {
            let (start, finish) = if q.texture {
                (0, stacks)
            } else {
                (1, stacks - 1)
            };
            if !q.texture {
                // The poles as fans: the north one around stack 1, the south one around
                // stack stacks-1; each fan runs clockwise seen from outside the sphere.
                let last = stacks as usize;
                for (north, ring, fb, sb) in [(true, 1, 1, 1), (false, last - 1, last, last - 1)] {
                    let nb = if q.normals == GLU_FLAT {
                        flat_b[fb]
                    } else {
                        smooth_b[sb]
                    };
                    if q.normals == GLU_SMOOTH {
                        let p = if north { 0 } else { last };
                        nrm(around[p], smooth_b[p]);
                    }
                    im::begin(gl::GL_TRIANGLE_FAN);
                    let pole = if north { radius } else { -radius };
                    vertex(0.0, 0.0, pole as f32);
                    let backwards = north == out;
                    for k in 0..=slices as usize {
                        let i = if backwards { slices as usize - k } else { k };
                        match q.normals {
                            GLU_SMOOTH => nrm(around[i], nb),
                            GLU_FLAT if backwards && i != slices as usize => nrm(flat_a[i + 1], nb),
                            GLU_FLAT if !backwards => nrm(flat_a[i], nb),
                            _ => {}
                        }
                        at(i, ring);
                    }
                    im::end();
                }
            }
            for j in start..finish {
                let (ju, jn) = (j as usize, j as usize + 1);
                let (n_first, n_second) = match q.normals {
                    GLU_SMOOTH if out => (smooth_b[jn], smooth_b[ju]),
                    GLU_SMOOTH => (smooth_b[ju], smooth_b[jn]),
                    _ => (flat_b[jn], flat_b[jn]),
                };
                let (first, second) = if out {
                    ((jn, j + 1), (ju, j))
                } else {
                    ((ju, j), (jn, j + 1))
                };
                im::begin(gl::GL_QUAD_STRIP);
                for i in 0..=slices {
                    let iu = i as usize;
                    if q.normals == GLU_SMOOTH {
                        nrm(around[iu], n_first);
                    }
                    q.tex(s_at(i), t_at(first.1));
                    at(iu, first.0);
                    match q.normals {
                        GLU_SMOOTH => nrm(around[iu], n_second),
                        GLU_FLAT => nrm(flat_a[iu], n_second),
                        _ => {}
                    }
                    q.tex(s_at(i), t_at(second.1));
                    at(iu, second.0);
                }
                im::end();
            }
        }
        GLU_POINT => {
            im::begin(gl::GL_POINTS);
            for j in 0..=stacks {
                for i in 0..slices {
                    if q.normals != GLU_NONE {
                        nrm(around[i as usize], smooth_b[j as usize]);
                    }
                    q.tex(s_at(i), t_at(j));
                    at(i as usize, j as usize);
                }
            }
            im::end();
        }
        GLU_LINE | GLU_SILHOUETTE => {
            // A line vertex; flat normals pair the tables given, smooth ones are radial.
            let point = |i: usize, j: usize, flat: ((f32, f32), (f32, f32))| {
                match q.normals {
                    GLU_FLAT => nrm(flat.0, flat.1),
                    GLU_SMOOTH => nrm(around[i], smooth_b[j]),
                    _ => {}
                }
                q.tex(s_at(i as i32), t_at(j as i32));
                at(i, j);
            };
            for (j, &b) in smooth_b.iter().enumerate().take(stacks as usize).skip(1) {
                im::begin(gl::GL_LINE_STRIP);
                (0..=slices as usize).for_each(|i| point(i, j, (flat_a[i], b)));
                im::end();
            }
            for (i, &a) in around.iter().enumerate().take(slices as usize) {
                im::begin(gl::GL_LINE_STRIP);
                (0..=stacks as usize).for_each(|j| point(i, j, (a, flat_b[j])));
                im::end();
            }
        }
        _ => {}
    }
}

/// `gluPartialDisk`: a ring in the z = 0 plane from `start` degrees (0 = +y, clockwise)
/// over `sweep` degrees.
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
    with_q(q, |q| {
        disk(
            q,
            inner,
            outer,
            slices.min(CACHE_SIZE - 1),
            loops,
            start,
            sweep,
        )
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

fn disk(q: &Quadric, inner: f64, outer: f64, slices: i32, loops: i32, start: f64, sweep: f64) {
    if slices < 2 || loops < 1 || outer <= 0.0 || inner < 0.0 || inner > outer {
        return q.fail();
    }
    // libGLU maps any sweep beyond ±360 to +360, and a negative sweep to a positive one
    // that ends where it began.
    let (mut start, mut sweep) = (start, if sweep.abs() > 360.0 { 360.0 } else { sweep });
    if sweep < 0.0 {
        start += sweep;
        sweep = -sweep;
    }
    let full = sweep == 360.0;
    let spokes = if full { slices } else { slices + 1 };
    let dr = (outer - inner) as f32;
    let offset = f64::from((start / 180.0 * PI) as f32);
    let per = PI * sweep / 180.0;
    let n = f64::from(slices);
    let tab = table(slices, full, 1.0, |i| offset + per * i / n);
    if q.normals != GLU_NONE {
        normal(0.0, 0.0, if q.outside() { 1.0 } else { -1.0 });
    }
    let r_at = |j: i32| (outer - f64::from(dr * frac(j, loops))) as f32;
    let half = |r: f32| (f64::from(r) / outer / 2.0) as f32;
    let put = |r: f32, i: usize| {
        let (s, c) = tab[i];
        let h = half(r);
        q.tex(
            (f64::from(h * s) + 0.5) as f32,
            (f64::from(h * c) + 0.5) as f32,
        );
        vertex(r * s, r * c, 0.0);
    };
    let circle = |j: i32| {
        im::begin(gl::GL_LINE_STRIP);
        (0..=slices as usize).for_each(|i| put(r_at(j), i));
        im::end();
    };
    let spoke = |i: usize| {
        im::begin(gl::GL_LINE_STRIP);
        (0..=loops).for_each(|j| put(r_at(j), i));
        im::end();
    };
    match q.draw_style {
        GLU_FILL => {
            let finish = if inner == 0.0 {
                im::begin(gl::GL_TRIANGLE_FAN);
                q.tex(0.5, 0.5);
                vertex(0.0, 0.0, 0.0);
                let r = r_at(loops - 1);
                for k in 0..=slices as usize {
                    put(r, if q.outside() { slices as usize - k } else { k });
                }
                im::end();
                loops - 1
            } else {
                loops
            };
            for j in 0..finish {
                let (lo, hi) = (r_at(j), r_at(j + 1));
                let (a, b) = if q.outside() { (lo, hi) } else { (hi, lo) };
                im::begin(gl::GL_QUAD_STRIP);
                for i in 0..=slices as usize {
                    put(a, i);
                    put(b, i);
                }
                im::end();
            }
        }
        GLU_POINT => {
            im::begin(gl::GL_POINTS);
            for i in 0..spokes as usize {
                (0..=loops).for_each(|j| put(r_at(j), i));
            }
            im::end();
        }
        GLU_LINE if inner == outer => {
            im::begin(gl::GL_LINE_STRIP);
            for &(s, c) in &tab {
                q.tex(
                    (f64::from(s / 2.0) + 0.5) as f32,
                    (f64::from(c / 2.0) + 0.5) as f32,
                );
                vertex(
                    (inner * f64::from(s)) as f32,
                    (inner * f64::from(c)) as f32,
                    0.0,
                );
            }
            im::end();
        }
        GLU_LINE => {
            (0..=loops).for_each(circle);
            (0..spokes as usize).for_each(spoke);
        }
        GLU_SILHOUETTE => {
            if sweep < 360.0 {
                spoke(0);
                spoke(slices as usize);
            }
            circle(0);
            if inner != outer {
                circle(loops);
            }
        }
        _ => {}
    }
}
