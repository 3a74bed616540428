//! Lines and points, width 1 (foundation level; llvmpipe's exact wide-line, stipple and
//! point-size rules arrive with the classic-GL issue).
//!
//! Lines follow the diamond-exit rule in its common form: an x-major line covers the
//! columns whose centres lie in [x0, x1), one pixel per column, in the row whose centre is
//! within half a pixel (bottom-inclusive in GL y-up terms, which is llvmpipe's
//! parallelogram edge rule); y-major lines likewise per row. Points of size 1 cover the
//! pixel that contains them. Attributes are interpolated linearly along the major axis
//! (points: the vertex's values).

use super::shade_pixels;
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::setup::{Plane, SetupTriangle};
use crate::geometry::{ClipVertex, MAX_VARY};
use crate::stats::Stats;

/// Plane for an attribute along a line: value `a0` at (x0, y0) changing by `d` per unit of
/// the major axis.
fn line_plane(a0: f32, a1: f32, len: f32, x_major: bool, x0: f32, y0: f32) -> Plane {
    let d = if len != 0.0 { (a1 - a0) / len } else { 0.0 };
    let (dadx, dady) = if x_major { (d, 0.0) } else { (0.0, d) };
    Plane {
        a0: a0 - (dadx * (x0 - 0.5) + dady * (y0 - 0.5)),
        dadx,
        dady,
    }
}

/// Draws the segment `v0`–`v1` (window coordinates, y-down) inside `region`.
#[allow(clippy::too_many_arguments)]
pub fn raster_line(
    v0: &ClipVertex,
    v1: &ClipVertex,
    flat: &[f32; MAX_VARY],
    region: [i64; 4],
    plan: &FragPlan,
    fb: &mut Target<'_>,
    stats: &mut Stats,
    scratch: &mut Vec<(usize, usize)>,
) {
    let (x0, y0, x1, y1) = (v0.win[0], v0.win[1], v1.win[0], v1.win[1]);
    if !(x0.is_finite() && y0.is_finite() && x1.is_finite() && y1.is_finite()) {
        return;
    }
    let (dx, dy) = (x1 - x0, y1 - y0);
    let x_major = dx.abs() >= dy.abs();
    let len = if x_major { dx } else { dy };
    if len == 0.0 {
        return;
    }
    let t = SetupTriangle {
        z: line_plane(v0.win[2], v1.win[2], len, x_major, x0, y0),
        vary: std::array::from_fn(|i| line_plane(v0.vary[i], v1.vary[i], len, x_major, x0, y0)),
        flat: *flat,
        flat_u8: [0, 1, 2, 3].map(|i| crate::framebuffer::float_to_ubyte(flat[i])),
        ..Default::default()
    };
    scratch.clear();
    let h = fb.height as f32;
    // Pixels whose major-axis centre c = p + 0.5 lies in the half-open range from start to
    // end (in the direction of travel).
    let (a, b) = if x_major { (x0, x1) } else { (y0, y1) };
    let (lo, hi) = if a < b { (a, b) } else { (b, a) };
    let first = (lo - 0.5).ceil() as i64;
    let last = (hi - 0.5).ceil() as i64 - 1;
    let (first, last) = if a < b {
        (first, last)
    } else {
        ((lo - 0.5).floor() as i64 + 1, (hi - 0.5).floor() as i64)
    };
    // Only positions inside the region can produce pixels: a line far outside the
    // framebuffer (a viewport offset of 2^30, say) must not walk a billion columns.
    let (r_lo, r_hi) = if x_major {
        (region[0], region[2] - 1)
    } else {
        (region[1], region[3] - 1)
    };
    for p in first.max(r_lo)..=last.min(r_hi) {
        let c = p as f32 + 0.5;
        let f = (c - a) / (b - a);
        let (px, py) = if x_major {
            let y = y0 + f * dy;
            // Row whose centre is in [y - 0.5, y + 0.5) in GL y-up space.
            let gl_y = h - y;
            let gl_row = gl_y.ceil() as i64 - 1;
            (p, fb.height as i64 - 1 - gl_row)
        } else {
            let x = x0 + f * dx;
            (x.ceil() as i64 - 1, p)
        };
        if px >= region[0] && px < region[2] && py >= region[1] && py < region[3] {
            scratch.push((px as usize, py as usize));
        }
    }
    shade_pixels(&t, scratch, plan, fb, stats);
}

/// Draws a size-1 point at `v`.
pub fn raster_point(
    v: &ClipVertex,
    region: [i64; 4],
    plan: &FragPlan,
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    let (x, y) = (v.win[0], v.win[1]);
    if !(x.is_finite() && y.is_finite()) {
        return;
    }
    let px = x.floor() as i64;
    let gl_row = (fb.height as f32 - y).floor() as i64;
    let py = fb.height as i64 - 1 - gl_row;
    if px < region[0] || px >= region[2] || py < region[1] || py >= region[3] {
        return;
    }
    let t = SetupTriangle {
        z: Plane {
            a0: v.win[2],
            dadx: 0.0,
            dady: 0.0,
        },
        vary: std::array::from_fn(|i| Plane {
            a0: v.vary[i],
            dadx: 0.0,
            dady: 0.0,
        }),
        flat: v.vary,
        flat_u8: [0, 1, 2, 3].map(|i| crate::framebuffer::float_to_ubyte(v.vary[i])),
        ..Default::default()
    };
    shade_pixels(&t, &[(px as usize, py as usize)], plan, fb, stats);
}
