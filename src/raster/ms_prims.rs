//! Lines and points into a 4x multisample object with GL_MULTISAMPLE on, as llvmpipe draws
//! them (docs/fbo-rules.md §3.2; `lp_setup_line.c` with `rectangular_lines`,
//! `lp_setup_point.c` with `multisample`).
//!
//! - A line is the rectangle from end point to end point, `±w/2` across: with
//!   `t = util_iround(256·(−dy, dx)·(w/2)/|d|)`, `d = v1 − v2`, its corners are
//!   `snap(v1) − t`, `snap(v2) − t`, `snap(v2) + t`, `snap(v1) + t`, snapped with
//!   `util_iround(256·v)` (no half-pixel offset). Its attribute planes are those of the
//!   single-sample line setup but along the line itself (`dadx = Δa·dx/|d|²`,
//!   `dady = Δa·dy/|d|²`) and keep the half-pixel origin (`setup->pixel_offset`), while the
//!   multisample shader evaluates them at the pixel centre as for triangles: every
//!   attribute, depth included, is taken half a pixel further along x and y than the
//!   fragment. llvmpipe's box rounds the low corner up (`(min + 255) >> 8`), which only
//!   matters through the tiles it bins into: a line whose box is empty on an axis, or
//!   outside the framebuffer, is dropped, and pixels in 64-pixel tiles left of or below
//!   the box's tile are not drawn.
//! - A point is the square of side `max(1, util_iround(256·size))/256` around
//!   `util_iround(256·v)`, sample points on its left and bottom edges inside; its
//!   attributes are constant.
//!
//! Both are four integer edges with the triangles' tie rule, tested at the sample points,
//! drawn as the two triangles on either side of a diagonal by the triangle walk
//! ([`super::raster_samples`]): the diagonal's two opposite edges give each sample on it
//! to exactly one of them, so the union is the rectangle's coverage and every sample is
//! written once (a pixel with samples on both sides is shaded twice, alike).

use super::lines::util_iround;
use super::Draw;
use crate::geometry::setup::{Edge, Plane, SetupTriangle, SAMPLE_POS};
use crate::geometry::{ClipVertex, MAX_VARY};

/// Sub-pixel units per pixel.
const ONE: i64 = 256;

/// llvmpipe's tile size in pixels (the unit its binner skips).
const TILE: i64 = 64;

/// Coordinates beyond this are not drawn (clipping keeps real geometry inside the
/// viewport; this only keeps the integer arithmetic exact for garbage).
const MAX_COORD: f32 = (1u64 << 21) as f32;

/// `util_iround(256·a)`.
#[inline]
fn snap(a: f32) -> i64 {
    util_iround(256.0 * a)
}

/// Draws segment `v1`–`v2` (window coordinates of the object, y up) of `width` (clamped
/// by the state tracker); `flat` holds the provoking vertex's varyings (GL_FLAT).
pub fn line(
    v1: &ClipVertex,
    v2: &ClipVertex,
    flat: &[f32; MAX_VARY],
    width: f32,
    nvary: usize,
    d: &mut Draw<'_, '_>,
) {
    let (p1, p2) = ([v1.win[0], v1.win[1]], [v2.win[0], v2.win[1]]);
    if !p1.iter().chain(p2.iter()).all(|c| c.abs() < MAX_COORD) {
        return;
    }
    let dx = p1[0] - p2[0];
    let dy = p1[1] - p2[1];
    let area = dx * dx + dy * dy;
    if area == 0.0 {
        return;
    }
    let scale = (width * 0.5) / area.sqrt();
    let tx = snap(-dy * scale);
    let ty = snap(dx * scale);
    let (x1, y1, x2, y2) = (snap(p1[0]), snap(p1[1]), snap(p2[0]), snap(p2[1]));
    let xs = [x1 - tx, x2 - tx, x2 + tx, x1 + tx];
    let ys = [y1 - ty, y2 - ty, y2 + ty, y1 + ty];
    let Some(allowed) = line_tiles(&xs, &ys, d.region) else {
        return;
    };
    let ooa = 1.0f32 / area;
    let plane = |a1: f32, a2: f32| {
        let da21 = a1 - a2;
        let dadx = da21 * dx * ooa;
        let dady = da21 * dy * ooa;
        Plane {
            a0: a1 - (dadx * (p1[0] - 0.5) + dady * (p1[1] - 0.5)),
            dadx,
            dady,
        }
    };
    let (w1, w2) = (v1.win[3], v2.win[3]);
    let persp = !(w1 == 1.0 && w2 == 1.0);
    let mut t = SetupTriangle {
        z: plane(v1.win[2], v2.win[2]),
        w: plane(w1, w2),
        persp,
        ..Default::default()
    };
    t.set_flat(MAX_VARY, |i| flat[i]);
    for i in 0..nvary {
        t.vary[i] = if persp {
            plane(v1.vary[i] * w1, v2.vary[i] * w2)
        } else {
            plane(v1.vary[i], v2.vary[i])
        };
    }
    quad(&mut t, xs, ys, allowed, d);
}

/// The pixels llvmpipe's binner visits for a line with corners `xs`, `ys`: the tiles of
/// its box (rounded up at the low end, `lp_setup_line.c`), cut to `region`; `None` when
/// the line is dropped.
fn line_tiles(xs: &[i64; 4], ys: &[i64; 4], region: [i64; 4]) -> Option<[i64; 4]> {
    let lo = |v: &[i64; 4]| (v.iter().min().copied().unwrap_or(0) + ONE - 1) >> 8;
    let hi = |v: &[i64; 4]| ((v.iter().max().copied().unwrap_or(0) + ONE - 1) >> 8) - 1;
    let b = [lo(xs), lo(ys), hi(xs), hi(ys)];
    // `u_rect_test_intersection` with the draw region (exclusive high end here); an
    // empty box fails it too.
    let r = [region[0], region[1], region[2] - 1, region[3] - 1];
    if b[0] > b[2] || b[1] > b[3] || b[2] < r[0] || r[2] < b[0] || b[3] < r[1] || r[3] < b[1] {
        return None;
    }
    let b = [b[0].max(0), b[1].max(0), b[2], b[3]];
    // `lp_setup_bin_triangle`: a box that crosses no 64-pixel boundary is drawn in the
    // tile of its low corner; otherwise in the tiles of the box cut to the region.
    let cross = (b[0] ^ b[2]) | (b[1] ^ b[3]);
    let t = if cross < TILE {
        [b[0] / TILE, b[1] / TILE, b[0] / TILE, b[1] / TILE]
    } else {
        let c = [
            b[0].max(r[0]),
            b[1].max(r[1]),
            b[2].min(r[2]),
            b[3].min(r[3]),
        ];
        [c[0] / TILE, c[1] / TILE, c[2] / TILE, c[3] / TILE]
    };
    Some([
        (t[0] * TILE).max(r[0]),
        (t[1] * TILE).max(r[1]),
        (t[2] * TILE + TILE - 1).min(r[2]),
        (t[3] * TILE + TILE - 1).min(r[3]),
    ])
}

/// Draws point `v` of `size` (clamped, or the vertex's own under attenuation).
pub fn point(
    v: &ClipVertex,
    size: f32,
    coords: &super::sprite::Sprite,
    nvary: usize,
    d: &mut Draw<'_, '_>,
) {
    let (x, y) = (v.win[0], v.win[1]);
    if !(x.abs() < MAX_COORD && y.abs() < MAX_COORD) {
        return;
    }
    let size = size.min(crate::pipe::MAX_POINT_SIZE);
    let fw = snap(size).max(ONE);
    let (x0, y0) = (snap(x) - fw / 2, snap(y) - fw / 2);
    let (x1, y1) = (x0 + fw, y0 + fw);
    let b = [
        x0 >> 8,
        y0 >> 8,
        ((x1 + ONE - 1) >> 8) - 1,
        ((y1 + ONE - 1) >> 8) - 1,
    ];
    let r = d.region;
    let b = [
        b[0].max(r[0]),
        b[1].max(r[1]),
        b[2].min(r[2] - 1),
        b[3].min(r[3] - 1),
    ];
    if b[0] > b[2] || b[1] > b[3] {
        return;
    }
    // The square cut to the box's pixels (`lp_setup_point.c` clamps its planes so).
    let (l, rt) = (x0.max(b[0] << 8), x1.min((b[2] + 1) << 8));
    let (bt, tp) = (y0.max(b[1] << 8), y1.min((b[3] + 1) << 8));
    let mut t = super::lines::point_planes(v, nvary);
    super::sprite::replace_coords(&mut t, v, fw, coords);
    // Clockwise in y-up terms, as a line's rectangle: left and bottom edges inclusive.
    quad(&mut t, [l, rt, rt, l], [tp, tp, bt, bt], b, d);
}

/// The edge from corner (xi, yi) to (xj, yj) with the triangles' tie rule for an object
/// (llvmpipe's `bottom_edge_rule = 0`): left edges and edges with `dcdy > 0` get the +1.
fn edge(xi: i64, yi: i64, xj: i64, yj: i64) -> Edge {
    let a = yi - yj;
    let b = xi - xj;
    let mut c = a * xi - b * yi;
    if a < 0 || (a == 0 && b > 0) {
        c += 1;
    }
    Edge { a, b, c }
}

/// Draws the parallelogram with corners (`xs[i]`, `ys[i]`) in 1/256 pixel (clockwise in
/// y-up terms) and the planes of `t` at the sample points, inside `allowed` (inclusive
/// pixel box), as two triangles split along the diagonal from corner 0 to corner 2.
fn quad(
    t: &mut SetupTriangle,
    xs: [i64; 4],
    ys: [i64; 4],
    allowed: [i64; 4],
    d: &mut Draw<'_, '_>,
) {
    let e = |i: usize, j: usize| edge(xs[i], ys[i], xs[j], ys[j]);
    for tri in [[0, 1, 2], [0, 2, 3]] {
        t.edges = [e(tri[0], tri[1]), e(tri[1], tri[2]), e(tri[2], tri[0])];
        // The pixels whose sample points may lie inside.
        let (sx, sy) = (tri.map(|i| xs[i]), tri.map(|i| ys[i]));
        let [lo, hi] = [SAMPLE_POS[2][0], SAMPLE_POS[1][0]];
        let bbox = [
            (sx.iter().min().copied().unwrap_or(0) - hi + ONE - 1).div_euclid(ONE),
            (sy.iter().min().copied().unwrap_or(0) - SAMPLE_POS[3][1] + ONE - 1).div_euclid(ONE),
            (sx.iter().max().copied().unwrap_or(0) - lo).div_euclid(ONE),
            (sy.iter().max().copied().unwrap_or(0) - SAMPLE_POS[0][1]).div_euclid(ONE),
        ];
        let b = d.clip([
            bbox[0].max(allowed[0]),
            bbox[1].max(allowed[1]),
            bbox[2].min(allowed[2]),
            bbox[3].min(allowed[3]),
        ]);
        if b[0] <= b[2] && b[1] <= b[3] {
            t.bbox = b;
            super::raster_samples(t, b, d);
        }
    }
}
