//! Stress scenes: triangles with vertices 1e3–1e7 pixels away crossing the viewport,
//! compared with an exact f64 rasterization (pixel centre inside the triangle, top-left
//! ties ignored: pixels within 0.01 px of an edge are not counted, which covers the
//! 1/256-pixel snapping of the vertices); thin fans of
//! thousands of triangles covering every pixel exactly once.
//!
//! The clipper is Mesa's f32 algorithm, so at huge coordinates the clipped vertices move
//! off the true edges; the measured pixel errors are printed and bounded here (see
//! docs/robustness.md for the numbers and the proposed exact fix).

mod robust_common;

use robust_common::*;
use softgl::ffi::arrays::*;
use softgl::ffi::draw::*;
use softgl::ffi::enums::*;
use softgl::ffi::fragment::*;
use softgl::ffi::matrix::*;
use softgl::ffi::state::*;

const W: i32 = 128;
const H: i32 = 128;

fn draw_tris(v: &[[f32; 2]], cols: &[[u8; 4]]) {
    glVertexPointer(2, GL_FLOAT, 0, v.as_ptr().cast());
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, cols.as_ptr().cast());
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glDrawArrays(GL_TRIANGLES, 0, v.len() as i32);
}

fn pixel_ortho() {
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, W as f64, 0.0, H as f64, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/// Signed distance-like edge test in f64: > 0 inside for a CCW triangle.
fn edge(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> f64 {
    ((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]))
        / ((b[0] - a[0]).hypot(b[1] - a[1]))
}

/// (pixels wrong, pixels checked) for random triangles with vertices at distance `r`.
fn huge_triangle_errors(r: f64, seed: u64, n: usize) -> (usize, usize, usize) {
    let c = Ctx::new(W, H);
    pixel_ortho();
    let mut rng = Rng(seed);
    let (mut wrong, mut checked, mut worst) = (0, 0, 0);
    for _ in 0..n {
        // Edge AB passes through a random point P of the viewport with both ends about r
        // away; C is r away on one side. Only AB's clipped ends decide the boundary.
        let pnt = [rng.range(8.0, 120.0), rng.range(8.0, 120.0)];
        let a = rng.range(0.0, std::f64::consts::TAU);
        let (d, nrm) = ([a.cos(), a.sin()], [-a.sin(), a.cos()]);
        let (ra, rb) = (r * rng.range(0.5, 1.5), r * rng.range(0.5, 1.5));
        let t = [
            [(pnt[0] + ra * d[0]) as f32, (pnt[1] + ra * d[1]) as f32],
            [(pnt[0] - rb * d[0]) as f32, (pnt[1] - rb * d[1]) as f32],
            [(pnt[0] + r * nrm[0]) as f32, (pnt[1] + r * nrm[1]) as f32],
        ];
        let td = t.map(|p| [p[0] as f64, p[1] as f64]);
        let area = edge(td[0], td[1], td[2]);
        if area.abs() < 1e-9 {
            continue;
        }
        let td = if area < 0.0 {
            [td[0], td[2], td[1]]
        } else {
            td
        };
        glClear(GL_COLOR_BUFFER_BIT);
        draw_tris(&t, &[[255; 4]; 3]);
        let img = c.read();
        let mut bad = 0;
        for y in 0..H as usize {
            for x in 0..W as usize {
                let p = [x as f64 + 0.5, y as f64 + 0.5];
                let d = (0..3)
                    .map(|i| edge(td[i], td[(i + 1) % 3], p))
                    .fold(f64::INFINITY, f64::min);
                if d.abs() < 0.01 {
                    continue;
                }
                checked += 1;
                if (d > 0.0) != (img[(y * W as usize + x) * 4] != 0) {
                    bad += 1;
                }
            }
        }
        wrong += bad;
        worst = worst.max(bad);
    }
    (wrong, checked, worst)
}

#[test]
fn huge_coordinates_against_exact_coverage() {
    let mut report = vec![];
    for (r, bound) in [(1e3, 0.0), (1e4, 0.0), (1e5, 0.0), (1e6, 1e-4), (1e7, 2e-3)] {
        let (wrong, checked, worst) = huge_triangle_errors(r, 42, 60);
        let frac = wrong as f64 / checked as f64;
        report.push(format!(
            "r = {r:e}: {wrong} of {checked} pixels wrong ({:.4}%), worst triangle {worst}",
            100.0 * frac
        ));
        assert!(frac <= bound, "{}", report.join("\n"));
    }
    eprintln!("{}", report.join("\n"));
}

/// A fan of `n` slivers around a point inside the viewport, reaching far outside it:
/// every pixel covered exactly once.
#[test]
fn thin_fans_cover_exactly_once() {
    let c = Ctx::new(W, H);
    pixel_ortho();
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    for (n, r, centre) in [
        (4000, 200.0, [64.3, 61.7]),
        (3000, 1e4, [1.0, 127.0]),
        (2000, 200.0, [0.0, 0.0]),
    ] {
        glClear(GL_COLOR_BUFFER_BIT);
        let mut v = vec![];
        for i in 0..n {
            let a0 = i as f64 / n as f64 * std::f64::consts::TAU;
            let a1 = (i + 1) as f64 / n as f64 * std::f64::consts::TAU;
            let p = |a: f64| {
                [
                    (centre[0] + r * a.cos()) as f32,
                    (centre[1] + r * a.sin()) as f32,
                ]
            };
            v.push([centre[0] as f32, centre[1] as f32]);
            v.push(p(a0));
            v.push(p(a1));
        }
        draw_tris(&v, &vec![[1, 0, 0, 0]; v.len()]);
        let img = c.read();
        let counts: Vec<u8> = img.chunks(4).map(|p| p[0]).collect();
        let twice = counts.iter().filter(|&&k| k > 1).count();
        let holes = counts.iter().filter(|&&k| k == 0).count();
        assert_eq!((twice, holes), (0, 0), "fan of {n} at radius {r}");
    }
    glDisable(GL_BLEND);
}

/// Two planes 1 depth unit apart in eye space at wide near/far ratios: the nearer one wins
/// wherever the 16/24-bit depth buffer can separate them, and never loses to the farther.
#[test]
fn depth_fighting_planes_resolve_in_order() {
    for bits in [16, 24] {
        for (near, far) in [(0.1, 1e3), (1e-3, 1e5), (1.0, 1e2)] {
            let c = Ctx::with_depth(W, H, bits);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_LESS);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            glMatrixMode(GL_PROJECTION);
            glLoadIdentity();
            glFrustum(-near, near, -near, near, near, far);
            glMatrixMode(GL_MODELVIEW);
            glLoadIdentity();
            let z = -(near * 4.0) as f32;
            let quad = |z: f32, s: f32| {
                let s = s * -z;
                vec![
                    [-s, -s, z],
                    [s, -s, z],
                    [s, s, z],
                    [-s, -s, z],
                    [s, s, z],
                    [-s, s, z],
                ]
            };
            // Far plane (red) first, then the near one (green) slightly in front.
            for (zz, col) in [(z * 1.001, [255u8, 0, 0, 255]), (z, [0, 255, 0, 255])] {
                let v3 = quad(zz, 2.0);
                glVertexPointer(3, GL_FLOAT, 0, v3.as_ptr().cast());
                let cols = [col; 6];
                glColorPointer(4, GL_UNSIGNED_BYTE, 0, cols.as_ptr().cast());
                glEnableClientState(GL_VERTEX_ARRAY);
                glEnableClientState(GL_COLOR_ARRAY);
                glDrawArrays(GL_TRIANGLES, 0, 6);
            }
            let img = c.read();
            let red = img.chunks(4).filter(|p| p[0] == 255).count();
            assert_eq!(
                red, 0,
                "{bits}-bit depth, near {near} far {far}: far plane won {red} pixels"
            );
        }
    }
}
