//! Property tests of the rasterizer's invariants (proptest, fixed seeds: every run checks
//! the same cases, and a failure shrinks to a small one and prints it):
//!
//! (a) a triangulated rectangle covers every pixel inside it exactly once and nothing
//!     outside, under random translation, rotation, scale (sub-pixel to 1e6 pixels) and
//!     perspective (additive blending counts the covering triangles);
//! (b) interpolated colours stay within the vertex colours;
//! (c) degenerate triangles draw nothing;
//! (d) a mesh translated by whole pixels gives the same image shifted;
//! (e) depth along each row of a slanted plane is monotonic;
//! (f) triangles with vertices behind the eye cover exactly the projection of their
//!     in-front part (f64 ray casting reference);
//! (g) NaN/Inf in vertices, colours, matrices, viewport or depth range never crash and
//!     never draw where a finite scene would not.
//!
//! The reference for (a) and (f) casts the ray of each pixel centre (and of four points
//! 0.75 px around it) through the f64 clip-space image of each triangle: a pixel whose five
//! samples are all inside must be covered once, one whose samples are all outside must not
//! be covered, and no pixel may ever be covered twice.

mod robust_common;

use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestRng, TestRunner};
use robust_common::*;
use softgl::ffi::arrays::*;
use softgl::ffi::draw::*;
use softgl::ffi::enums::*;
use softgl::ffi::fragment::*;
use softgl::ffi::matrix::*;
use softgl::ffi::state::*;

const W: i32 = 64;
const H: i32 = 64;

/// A deterministic runner with `cases` cases and no persistence files.
fn runner(cases: u32, seed: u8) -> TestRunner {
    let config = Config {
        cases,
        failure_persistence: None,
        max_shrink_iters: 2000,
        ..Config::default()
    };
    TestRunner::new_with_rng(
        config,
        TestRng::from_seed(RngAlgorithm::ChaCha, &[seed; 32]),
    )
}

/// Column-major 4x4 product a*b.
fn mul(a: &[f64; 16], b: &[f64; 16]) -> [f64; 16] {
    let mut r = [0.0; 16];
    for c in 0..4 {
        for row in 0..4 {
            r[c * 4 + row] = (0..4).map(|k| a[k * 4 + row] * b[c * 4 + k]).sum();
        }
    }
    r
}

fn apply(m: &[f64; 16], p: [f64; 3]) -> [f64; 4] {
    let mut o = [0.0; 4];
    for (row, o) in o.iter_mut().enumerate() {
        *o = m[row] * p[0] + m[4 + row] * p[1] + m[8 + row] * p[2] + m[12 + row];
    }
    o
}

/// A scene transform: projection and modelview as the f32 matrices GL receives.
#[derive(Clone, Debug)]
struct Xform {
    proj: [f32; 16],
    mv: [f32; 16],
}

impl Xform {
    fn load(&self) {
        glMatrixMode(GL_PROJECTION);
        // SAFETY: 16 floats.
        unsafe { glLoadMatrixf(self.proj.as_ptr()) };
        glMatrixMode(GL_MODELVIEW);
        // SAFETY: 16 floats.
        unsafe { glLoadMatrixf(self.mv.as_ptr()) };
    }
    /// P*MV in f64 (of the f32 entries).
    fn m(&self) -> [f64; 16] {
        mul(&self.proj.map(|v| v as f64), &self.mv.map(|v| v as f64))
    }
}

/// An affine transform in pixel units: ortho(0,W,0,H) projection, modelview =
/// translate(tx,ty) * rotate(angle) * scale(s).
fn affine() -> impl Strategy<Value = Xform> {
    (
        -3.0f64..3.0,
        prop_oneof![0.05f64..2.0, 2.0f64..100.0, 100.0f64..1e6],
        0.0f64..W as f64,
        0.0f64..H as f64,
    )
        .prop_map(|(angle, s, tx, ty)| {
            let (c, sn) = (angle.cos(), angle.sin());
            let mv = [
                c * s,
                sn * s,
                0.0,
                0.0,
                -sn * s,
                c * s,
                0.0,
                0.0,
                0.0,
                0.0,
                1.0,
                0.0,
                tx,
                ty,
                0.0,
                1.0,
            ];
            let proj = [
                2.0 / W as f64,
                0.0,
                0.0,
                0.0,
                0.0,
                2.0 / H as f64,
                0.0,
                0.0,
                0.0,
                0.0,
                -1.0,
                0.0,
                -1.0,
                -1.0,
                0.0,
                1.0,
            ];
            Xform {
                proj: proj.map(|v| v as f32),
                mv: mv.map(|v| v as f32),
            }
        })
}

/// A perspective transform: glFrustum(-r,r,-r,r,n,f) and a modelview rotating the unit
/// scene about two axes and pushing it to distance `d` (it may cross the eye plane).
fn perspective() -> impl Strategy<Value = Xform> {
    (
        0.2f64..1.5,
        prop_oneof![Just(0.01f64), Just(0.5), 0.05f64..1.0],
        prop_oneof![Just(10.0f64), Just(1e4), 2.0f64..100.0],
        -3.0f64..3.0,
        -3.0f64..3.0,
        -2.0f64..6.0,
        0.2f64..50.0,
    )
        .prop_map(|(r, n, f, a, b, d, s)| {
            let f = n * f;
            let proj = [
                n / r,
                0.0,
                0.0,
                0.0,
                0.0,
                n / r,
                0.0,
                0.0,
                0.0,
                0.0,
                -(f + n) / (f - n),
                -1.0,
                0.0,
                0.0,
                -2.0 * f * n / (f - n),
                0.0,
            ];
            let (ca, sa, cb, sb) = (a.cos(), a.sin(), b.cos(), b.sin());
            // Ry(b) * Rx(a) * scale(s), then translate z by -d.
            let rx = [
                1.0, 0.0, 0.0, 0.0, 0.0, ca, sa, 0.0, 0.0, -sa, ca, 0.0, 0.0, 0.0, 0.0, 1.0,
            ];
            let ry = [
                cb, 0.0, -sb, 0.0, 0.0, 1.0, 0.0, 0.0, sb, 0.0, cb, 0.0, 0.0, 0.0, 0.0, 1.0,
            ];
            let sc = [
                s, 0.0, 0.0, 0.0, 0.0, s, 0.0, 0.0, 0.0, 0.0, s, 0.0, 0.0, 0.0, 0.0, 1.0,
            ];
            let mut mv = mul(&ry, &mul(&rx, &sc));
            mv[14] -= d;
            Xform {
                proj: proj.map(|v| v as f32),
                mv: mv.map(|v| v as f32),
            }
        })
}

/// [`perspective`] without the views where the z = 0 plane passes within 0.05 units of
/// the eye: there the mesh is seen edge-on, every triangle projects to (nearly) the same
/// line, and f32 rounding folds the projected mesh, so no tiling property can hold.
fn perspective_not_edge_on() -> impl Strategy<Value = Xform> {
    perspective().prop_filter("edge-on", |x| {
        let n = [x.mv[8] as f64, x.mv[9] as f64, x.mv[10] as f64];
        let t = [x.mv[12] as f64, x.mv[13] as f64, x.mv[14] as f64];
        let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        (n[0] * t[0] + n[1] * t[1] + n[2] * t[2]).abs() / len > 0.05
    })
}

/// A jittered grid triangulation of the rectangle [-1,1]^2 (object space, z = 0): boundary
/// points stay on the boundary, interior points move by up to 0.35 of a cell
/// (cases where a triangle folds over are rejected).
fn mesh() -> impl Strategy<Value = Vec<[[f32; 3]; 3]>> {
    (1usize..7, 1usize..7)
        .prop_flat_map(|(nx, ny)| {
            (
                Just((nx, ny)),
                proptest::collection::vec((-0.35f64..0.35, -0.35f64..0.35), (nx + 1) * (ny + 1)),
                proptest::collection::vec(any::<bool>(), nx * ny),
            )
        })
        .prop_map(|((nx, ny), jit, diag)| {
            let p = |i: usize, j: usize| -> [f32; 3] {
                let (mut x, mut y) = (i as f64, j as f64);
                let (jx, jy) = jit[j * (nx + 1) + i];
                if i > 0 && i < nx {
                    x += jx;
                }
                if j > 0 && j < ny {
                    y += jy;
                }
                [
                    (-1.0 + 2.0 * x / nx as f64) as f32,
                    (-1.0 + 2.0 * y / ny as f64) as f32,
                    0.0,
                ]
            };
            let mut tris = vec![];
            for j in 0..ny {
                for i in 0..nx {
                    let (a, b, c, d) = (p(i, j), p(i + 1, j), p(i + 1, j + 1), p(i, j + 1));
                    if diag[j * nx + i] {
                        tris.push([a, b, c]);
                        tris.push([a, c, d]);
                    } else {
                        tris.push([a, b, d]);
                        tris.push([b, c, d]);
                    }
                }
            }
            tris
        })
        // Jitter can fold a quad; a grid triangulation whose triangles all keep their
        // orientation is a valid tiling of the rectangle.
        .prop_filter("folded mesh", |tris| {
            tris.iter().all(|[a, b, c]| {
                let area = (b[0] - a[0]) as f64 * (c[1] - a[1]) as f64
                    - (c[0] - a[0]) as f64 * (b[1] - a[1]) as f64;
                area > 1e-4
            })
        })
}

/// Draws `tris` with per-vertex colours `cols` (RGBA8) through client arrays.
fn draw(tris: &[[[f32; 3]; 3]], cols: &[[u8; 4]]) {
    let v: Vec<f32> = tris.iter().flatten().flatten().copied().collect();
    // The arrays hold 3 vertices per triangle and outlive the draw call below.
    glVertexPointer(3, GL_FLOAT, 0, v.as_ptr().cast());
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, cols.as_ptr().cast());
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glDrawArrays(GL_TRIANGLES, 0, 3 * tris.len() as i32);
    glDisableClientState(GL_COLOR_ARRAY);
}

/// Whether the ray of window point (sx, sy) hits triangle `t` (object space) inside the
/// view volume, solved in f64 in clip space.
fn hits(m: &[f64; 16], t: &[[f32; 3]; 3], sx: f64, sy: f64) -> bool {
    let c = t.map(|p| apply(m, p.map(|v| v as f64)));
    let x = 2.0 * sx / W as f64 - 1.0;
    let y = 2.0 * sy / H as f64 - 1.0;
    // f(p) = (p.x - x p.w, p.y - y p.w) is linear: f(A) + s f(B-A) + t f(C-A) = 0.
    let f = |p: [f64; 4]| [p[0] - x * p[3], p[1] - y * p[3]];
    let fa = f(c[0]);
    let e1 = f([0, 1, 2, 3].map(|i| c[1][i] - c[0][i]));
    let e2 = f([0, 1, 2, 3].map(|i| c[2][i] - c[0][i]));
    let det = e1[0] * e2[1] - e1[1] * e2[0];
    if det == 0.0 || !det.is_finite() {
        return false;
    }
    let s = (-fa[0] * e2[1] + fa[1] * e2[0]) / det;
    let u = (-e1[0] * fa[1] + e1[1] * fa[0]) / det;
    if !(s >= 0.0 && u >= 0.0 && s + u <= 1.0) {
        return false;
    }
    let p: [f64; 4] =
        [0, 1, 2, 3].map(|i| c[0][i] + s * (c[1][i] - c[0][i]) + u * (c[2][i] - c[0][i]));
    p[3] > 0.0 && p[2] >= -p[3] && p[2] <= p[3]
}

/// Compares the red channel counts of the framebuffer against the ray-cast reference:
/// `Err` describes the first pixel that breaks a rule.
fn check_coverage(
    counts: &[u8],
    m: &[f64; 16],
    tris: &[[[f32; 3]; 3]],
) -> Result<(usize, usize), String> {
    let (mut interior, mut covered) = (0, 0);
    for py in 0..H as usize {
        for px in 0..W as usize {
            let n = counts[py * W as usize + px];
            if n > 1 {
                return Err(format!("pixel ({px},{py}) covered {n} times"));
            }
            covered += n as usize;
            let (cx, cy) = (px as f64 + 0.5, py as f64 + 0.5);
            let samples = [
                (cx, cy),
                (cx - 0.75, cy - 0.75),
                (cx + 0.75, cy - 0.75),
                (cx - 0.75, cy + 0.75),
                (cx + 0.75, cy + 0.75),
            ];
            let inside = samples
                .iter()
                .filter(|&&(x, y)| tris.iter().any(|t| hits(m, t, x, y)))
                .count();
            if inside == 5 {
                interior += 1;
                if n != 1 {
                    return Err(format!("interior pixel ({px},{py}) not covered"));
                }
            } else if inside == 0 && n != 0 {
                return Err(format!("exterior pixel ({px},{py}) covered"));
            }
        }
    }
    Ok((interior, covered))
}

/// Clears, sets additive blending and draws `tris` with colour 1/255 per triangle; returns
/// the per-pixel red counts (bottom row first).
fn coverage_counts(c: &Ctx, x: &Xform, tris: &[[[f32; 3]; 3]]) -> Vec<u8> {
    glClearColor(0.0, 0.0, 0.0, 0.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    x.load();
    let cols = vec![[1u8, 0, 0, 0]; tris.len() * 3];
    draw(tris, &cols);
    glDisable(GL_BLEND);
    c.read().chunks(4).map(|p| p[0]).collect()
}

fn fail(s: String) -> TestCaseError {
    TestCaseError::fail(s)
}

#[test]
fn a_mesh_covers_each_pixel_once_affine() {
    let c = Ctx::new(W, H);
    let stats = std::cell::Cell::new((0usize, 0usize));
    runner(500, 1)
        .run(&(affine(), mesh()), |(x, tris)| {
            let counts = coverage_counts(&c, &x, &tris);
            let (i, n) = check_coverage(&counts, &x.m(), &tris).map_err(fail)?;
            let (a, b) = stats.get();
            stats.set((a + i, b + n));
            Ok(())
        })
        .unwrap();
    let stats = stats.get();
    assert!(
        stats.0 > 50_000,
        "too few interior pixels checked: {stats:?}"
    );
}

#[test]
fn a_mesh_covers_each_pixel_once_perspective() {
    let c = Ctx::new(W, H);
    let interior = std::cell::Cell::new(0usize);
    runner(500, 2)
        .run(&(perspective_not_edge_on(), mesh()), |(x, tris)| {
            let counts = coverage_counts(&c, &x, &tris);
            let i = check_coverage(&counts, &x.m(), &tris).map_err(fail)?.0;
            interior.set(interior.get() + i);
            Ok(())
        })
        .unwrap();
    let interior = interior.get();
    assert!(
        interior > 20_000,
        "too few interior pixels checked: {interior}"
    );
}

/// (f): single triangles whose vertices lie on both sides of the eye (w < 0 and w > 0).
#[test]
fn f_clipping_behind_the_eye_matches_reference() {
    let c = Ctx::new(W, H);
    let pt = || (-3.0f32..3.0, -3.0f32..3.0, -8.0f32..3.0).prop_map(|(x, y, z)| [x, y, z]);
    let tri = (pt(), pt(), pt()).prop_map(|(a, b, c)| vec![[a, b, c]]);
    let crossing = std::cell::Cell::new(0usize);
    runner(1000, 6)
        .run(&(perspective(), tri), |(x, tris)| {
            let m = x.m();
            let ws: Vec<f64> = tris[0]
                .iter()
                .map(|p| apply(&m, p.map(|v| v as f64))[3])
                .collect();
            if ws.iter().any(|&w| w < 0.0) && ws.iter().any(|&w| w > 0.0) {
                crossing.set(crossing.get() + 1);
            }
            let counts = coverage_counts(&c, &x, &tris);
            check_coverage(&counts, &m, &tris).map_err(fail)?;
            Ok(())
        })
        .unwrap();
    let crossing = crossing.get();
    assert!(
        crossing > 50,
        "too few triangles cross the eye plane: {crossing}"
    );
}

/// (b): every channel of every pixel lies within the vertex colours' range (8-bit).
#[test]
fn b_colours_stay_within_vertex_range() {
    let c = Ctx::new(W, H);
    let pt = || (-1.5f32..1.5, -1.5f32..1.5, -1.0f32..1.0).prop_map(|(x, y, z)| [x, y, z]);
    let col = || any::<[u8; 4]>();
    let case = (
        prop_oneof![
            perspective(),
            affine().prop_map(|mut x| {
                // Unit scene: scale the pixel-space transform down to [-1,1]-ish sizes.
                x.mv[0] *= 30.0 / x.mv[0].hypot(x.mv[1]).max(1e-3);
                x
            })
        ],
        (pt(), pt(), pt()),
        (col(), col(), col()),
        any::<bool>(),
    );
    runner(600, 3)
        .run(&case, |(x, (a, b, p), (ca, cb, cc), persp_hint)| {
            // Pass 1: which pixels the triangle covers (white on black).
            glClearColor(0.0, 0.0, 0.0, 0.0);
            glClear(GL_COLOR_BUFFER_BIT);
            x.load();
            draw(&[[a, b, p]], &[[255; 4]; 3]);
            let mask: Vec<bool> = c.read().chunks(4).map(|p| p[3] != 0).collect();
            glClear(GL_COLOR_BUFFER_BIT);
            glHint(
                GL_PERSPECTIVE_CORRECTION_HINT,
                if persp_hint { GL_NICEST } else { GL_FASTEST },
            );
            x.load();
            draw(&[[a, b, p]], &[ca, cb, cc]);
            let img = c.read();
            for (i, px) in img.chunks(4).enumerate() {
                let (ppx, ppy) = (i % W as usize, i / W as usize);
                if !mask[i] {
                    continue;
                }
                for ch in 0..4 {
                    let lo = ca[ch].min(cb[ch]).min(cc[ch]);
                    let hi = ca[ch].max(cb[ch]).max(cc[ch]);
                    if px[ch] < lo || px[ch] > hi {
                        return Err(fail(format!(
                            "pixel ({ppx},{ppy}) channel {ch} = {} outside [{lo},{hi}]",
                            px[ch]
                        )));
                    }
                }
            }
            Ok(())
        })
        .unwrap();
}

/// (c): repeated vertices under any transform, and exactly collinear points, draw nothing.
#[test]
fn c_degenerate_triangles_draw_nothing() {
    let c = Ctx::new(W, H);
    let pt = || (-2.0f32..2.0, -2.0f32..2.0, -1.0f32..1.0).prop_map(|(x, y, z)| [x, y, z]);
    let case = (
        prop_oneof![perspective(), affine()],
        pt(),
        pt(),
        0usize..4,
        (1i32..63, 1i32..63, -8i32..8, -8i32..8, -6i32..6),
    );
    runner(800, 4)
        .run(&case, |(x, a, b, kind, (ox, oy, dx, dy, k))| {
            glClearColor(0.0, 0.0, 0.0, 0.0);
            glClear(GL_COLOR_BUFFER_BIT);
            let tri = match kind {
                0 => [a, a, b],
                1 => [a, b, a],
                2 => [a, a, a],
                _ => {
                    // Integer points on one line, pixel units, identity-like transform.
                    glMatrixMode(GL_PROJECTION);
                    glLoadIdentity();
                    glOrtho(0.0, W as f64, 0.0, H as f64, -1.0, 1.0);
                    glMatrixMode(GL_MODELVIEW);
                    glLoadIdentity();
                    // Inside the viewport: clipping would move the vertices off the line.
                    let p = |t: i32| {
                        [
                            (ox + t * dx).clamp(1, 63) as f32,
                            (oy + t * dy).clamp(1, 63) as f32,
                            0.0,
                        ]
                    };
                    let k = if [0, k, 2 * k + 1].iter().all(|&t| {
                        (1..=63).contains(&(ox + t * dx)) && (1..=63).contains(&(oy + t * dy))
                    }) {
                        k
                    } else {
                        0
                    };
                    let tri = [p(0), p(k), p(2 * k + 1)];
                    let f0 = softgl::ffi::current_stats().unwrap().fragments;
                    draw(&[tri], &[[255; 4]; 3]);
                    return check_blank(&c, &tri, f0);
                }
            };
            x.load();
            let f0 = softgl::ffi::current_stats().unwrap().fragments;
            draw(&[tri], &[[255; 4]; 3]);
            check_blank(&c, &tri, f0)
        })
        .unwrap();
}

fn check_blank(c: &Ctx, tri: &[[f32; 3]; 3], frags_before: u64) -> Result<(), TestCaseError> {
    // Fragments, not just pixels: a degenerate triangle's colour planes are NaN, so a
    // wrongly drawn one could be black on black.
    let frags = softgl::ffi::current_stats().unwrap().fragments - frags_before;
    if frags != 0 {
        return Err(fail(format!("degenerate {tri:?} made {frags} fragments")));
    }
    match c.read().iter().position(|&v| v != 0) {
        Some(i) => Err(fail(format!("degenerate {tri:?} drew pixel {}", i / 4))),
        None => Ok(()),
    }
}

/// (d): whole-pixel translations shift the image exactly (coordinates are multiples of
/// 1/256 so that every transform step is exact in f32).
#[test]
fn d_whole_pixel_translation_shifts_the_image() {
    let c = Ctx::new(W, H);
    // Inside [21, 43] and shifted by at most 20: never clipped (clipping computes new
    // vertices, which need not shift exactly).
    let q = || (21 * 256i32..43 * 256).prop_map(|v| v as f32 / 256.0);
    let tri = || ((q(), q()), (q(), q()), (q(), q()), any::<[u8; 3]>());
    let case = (
        proptest::collection::vec(tri(), 1..12),
        (-20i32..20, -20i32..20),
    );
    type Tri = ((f32, f32), (f32, f32), (f32, f32), [u8; 3]);
    let render = |tris: &[Tri], dx: i32, dy: i32| {
        glClearColor(0.0, 0.0, 0.0, 0.0);
        glClear(GL_COLOR_BUFFER_BIT);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(0.0, W as f64, 0.0, H as f64, -1.0, 1.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        let t: Vec<[[f32; 3]; 3]> = tris
            .iter()
            .map(|(a, b, p, _)| [*a, *b, *p].map(|(x, y)| [x + dx as f32, y + dy as f32, 0.0]))
            .collect();
        let cols: Vec<[u8; 4]> = tris
            .iter()
            .flat_map(|(.., k)| [[k[0], k[1], k[2], 255]; 3])
            .collect();
        draw(&t, &cols);
        c.read()
    };
    runner(400, 5)
        .run(&case, |(tris, (dx, dy))| {
            let a = render(&tris, 0, 0);
            let b = render(&tris, dx, dy);
            for y in 0..H {
                for x in 0..W {
                    let (sx, sy) = (x + dx, y + dy);
                    if sx < 0 || sy < 0 || sx >= W || sy >= H {
                        continue;
                    }
                    let i = ((y * W + x) * 4) as usize;
                    let j = ((sy * W + sx) * 4) as usize;
                    if a[i..i + 4] != b[j..j + 4] {
                        return Err(fail(format!(
                            "pixel ({x},{y}) {:?} moved to ({sx},{sy}) {:?}",
                            &a[i..i + 4],
                            &b[j..j + 4]
                        )));
                    }
                }
            }
            Ok(())
        })
        .unwrap();
}

/// (e): window depth of a slanted plane is monotonic along every row and column, for
/// 16- and 24-bit depth buffers and wide near/far ratios.
#[test]
fn e_depth_is_monotonic_on_a_slanted_plane() {
    for depth_bits in [16, 24] {
        let c = Ctx::with_depth(W, H, depth_bits);
        runner(200, 7 + depth_bits as u8)
            .run(&perspective(), |x| {
                glClearDepth(1.0);
                glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_ALWAYS);
                x.load();
                // One big plane (two triangles of the unit square scaled up).
                let s = 4.0f32;
                let (a, b, p, d) = ([-s, -s, 0.0], [s, -s, 0.0], [s, s, 0.0], [-s, s, 0.0]);
                draw(&[[a, b, p], [a, p, d]], &[[255; 4]; 6]);
                glDisable(GL_DEPTH_TEST);
                let img = c.read();
                let z = c.read_depth();
                let covered = |i: usize| img[i * 4] != 0;
                let w = W as usize;
                // Rows: the depth of consecutive covered pixels changes in one direction.
                for line in 0..H as usize {
                    for (step, idx) in [
                        (1usize, (0..w).map(|k| line * w + k).collect::<Vec<_>>()),
                        (w, (0..H as usize).map(|k| k * w + line).collect()),
                    ] {
                        let _ = step;
                        let vals: Vec<f32> =
                            idx.iter().filter(|&&i| covered(i)).map(|&i| z[i]).collect();
                        let up = vals.windows(2).any(|p| p[1] > p[0]);
                        let down = vals.windows(2).any(|p| p[1] < p[0]);
                        if up && down {
                            return Err(fail(format!(
                                "{depth_bits}-bit depth not monotonic along line {line}: {vals:?}"
                            )));
                        }
                    }
                }
                Ok(())
            })
            .unwrap();
    }
}

/// (g): non-finite values anywhere: no panic, no GL error but the ones the calls name, and
/// no pixel drawn outside what the scene without the poisoned triangle draws.
#[test]
fn g_non_finite_inputs_draw_nothing_unexpected() {
    install_panic_counter();
    let c = Ctx::new(W, H);
    let bad = prop_oneof![
        Just(f32::NAN),
        Just(f32::INFINITY),
        Just(f32::NEG_INFINITY),
        Just(f32::MAX),
        Just(-f32::MAX),
        Just(1e38f32),
    ];
    let case = (
        perspective_not_edge_on(),
        mesh(),
        0usize..5,
        bad,
        any::<prop::sample::Index>(),
    );
    let p0 = panics();
    runner(600, 8)
        .run(&case, |(x, tris, place, v, ix)| {
            // Reference: the mesh without the triangle that gets poisoned.
            let k = ix.index(tris.len());
            let mut rest = tris.clone();
            rest.remove(k);
            let reference = coverage_counts(&c, &x, &rest);
            let mut poisoned = tris.clone();
            let mut x2 = x.clone();
            match place {
                0 => poisoned[k][ix.index(3)][ix.index(2)] = v,
                1 => x2.mv[ix.index(16)] = v,
                2 => x2.proj[ix.index(16)] = v,
                _ => {}
            }
            let counts = {
                glClearColor(0.0, 0.0, 0.0, 0.0);
                glClear(GL_COLOR_BUFFER_BIT);
                glEnable(GL_BLEND);
                glBlendFunc(GL_ONE, GL_ONE);
                x2.load();
                match place {
                    3 => glDepthRange(v as f64, 0.5),
                    4 => glViewport(0, 0, i32::MAX, i32::MAX),
                    _ => {}
                }
                let cols = vec![[1u8, 0, 0, 0]; tris.len() * 3];
                draw(&poisoned, &cols);
                glDisable(GL_BLEND);
                glDepthRange(0.0, 1.0);
                glViewport(0, 0, W, H);
                c.read().chunks(4).map(|p| p[0]).collect::<Vec<u8>>()
            };
            let e = take_error();
            if e != GL_NO_ERROR {
                return Err(fail(format!("GL error {e:#x}")));
            }
            let finite = v.is_finite();
            let full = || coverage_counts(&c, &x, &tris);
            let expect: Option<Vec<u8>> = match place {
                // A non-finite vertex drops its triangle: exactly the rest is drawn.
                0 if !finite => Some(reference.clone()),
                // A non-finite matrix entry reaches a whole row of P*MV, so a coordinate
                // of every vertex (0 * NaN is NaN): nothing is drawn.
                1 | 2 if !finite => Some(vec![0; counts.len()]),
                // The depth range does not change coverage (depth test off).
                3 => Some(full()),
                _ => None,
            };
            if let Some(expect) = expect {
                if let Some(i) = (0..counts.len()).find(|&i| counts[i] != expect[i]) {
                    return Err(fail(format!(
                        "pixel {i}: {} instead of {} (value {v})",
                        counts[i], expect[i]
                    )));
                }
            }
            for (i, (&n, &r)) in counts.iter().zip(&reference).enumerate() {
                // A huge but finite vertex legitimately moves its triangle over the others:
                // one extra layer at most. Everything else stays a single layer.
                let limit = if place == 0 { r + 1 } else { 1 };
                if n > limit {
                    return Err(fail(format!("pixel {i} covered {n} times (value {v})")));
                }
            }
            Ok(())
        })
        .unwrap();
    assert_eq!(panics(), p0, "non-finite input panicked");
    // Non-finite colours through the immediate-mode and float array paths.
    for v in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        glClear(GL_COLOR_BUFFER_BIT);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        softgl::ffi::immediate::glBegin(GL_TRIANGLES);
        softgl::ffi::immediate::glColor4f(v, 0.5, v, 1.0);
        softgl::ffi::immediate::glVertex2f(-1.0, -1.0);
        softgl::ffi::immediate::glVertex2f(1.0, -1.0);
        softgl::ffi::immediate::glVertex2f(v, 1.0);
        softgl::ffi::immediate::glVertex2f(-1.0, -1.0);
        softgl::ffi::immediate::glVertex2f(1.0, -1.0);
        softgl::ffi::immediate::glVertex2f(-1.0, 1.0);
        softgl::ffi::immediate::glEnd();
        assert_eq!(take_error(), GL_NO_ERROR);
        let img = c.read();
        // Only the finite triangle (lower-left half) is drawn.
        for (i, p) in img.chunks(4).enumerate() {
            let (x, y) = ((i % W as usize) as f64 + 0.5, (i / W as usize) as f64 + 0.5);
            if x + y > W as f64 + 1.0 {
                assert_eq!(p, [0, 0, 0, 0], "pixel ({x},{y}) drawn with colour {v}");
            }
        }
    }
    assert_eq!(panics(), p0);
}
