//! Lines and points exactly as llvmpipe rasterizes them (docs/llvmpipe-rules.md §15).
//!
//! A line segment is a parallelogram with four exact integer edge functions (the triangle
//! fill rule): x-major segments are `util_iround(width)` pixels tall, y-major ones as wide,
//! and the ends are moved by up to half a pixel along the major axis so that the end
//! pixels follow the diamond-exit rule (`lp_setup_line.c`, `try_setup_line`, the
//! non-rectangular branch used when GL_LINE_SMOOTH is off). Positions snap with
//! `util_iround` (half away from zero), not the triangles' round-half-even. Attributes
//! vary along the major axis only, with the plane computed in f32 in Mesa's order.
//!
//! Points use the legacy GL rule (`lp_setup_point.c`, `legacy_points`): an integer-sized
//! square of pixels around the snapped centre, all attributes constant.

use super::Draw;
use crate::fragment::span::Span;
use crate::geometry::setup::{Edge, Plane, SetupTriangle};
use crate::geometry::{ClipVertex, MAX_VARY};

/// Sub-pixel units per pixel.
const ONE: i64 = 256;

/// Mesa's `util_iround` on x86-64: `(int)(f + 0.5f)` for f >= 0, `(int)(f - 0.5f)` else
/// (the addition rounds in f32 first).
#[inline]
pub fn util_iround(f: f32) -> i64 {
    if f >= 0.0 {
        (f + 0.5) as i64
    } else {
        (f - 0.5) as i64
    }
}

/// `util_iround(256 * a)`.
#[inline]
fn subpixel_snap(a: f32) -> i64 {
    util_iround(256.0 * a)
}

/// `f - floor(f)`.
#[inline]
fn fracf(f: f32) -> f32 {
    f - f.floor()
}

/// The largest window coordinate a point may have, and the box a line's coverage is cut
/// to (f32 clipping of extreme lines leaves ends far outside the viewport; llvmpipe's
/// int conversion would overflow there). Cutting keeps the 64-bit edge functions exact;
/// the visible pixels are those of the uncut line up to rounding far off screen.
const MAX_COORD: f32 = (1u64 << 21) as f32;

/// Cuts segment `a`–`b` to the square |x|, |y| <= MAX_COORD (Liang–Barsky in f64);
/// `None` when nothing is left.
fn cut_to_box(a: [f32; 2], b: [f32; 2]) -> Option<([f32; 2], [f32; 2])> {
    let (mut t0, mut t1) = (0f64, 1f64);
    let m = MAX_COORD as f64;
    for k in 0..2 {
        let (p, d) = (a[k] as f64, b[k] as f64 - a[k] as f64);
        for (q, r) in [(-d, p + m), (d, m - p)] {
            if q == 0.0 {
                if r < 0.0 {
                    return None;
                }
            } else {
                let t = r / q;
                if q < 0.0 {
                    t0 = t0.max(t);
                } else {
                    t1 = t1.min(t);
                }
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    let at = |t: f64| -> [f32; 2] {
        std::array::from_fn(|k| (a[k] as f64 + t * (b[k] as f64 - a[k] as f64)) as f32)
    };
    Some((at(t0), at(t1)))
}

/// The ends of the parallelogram along the major axis after the diamond-exit adjustment,
/// and the four corners in 1/256 pixel, for segment `v1`–`v2` (window coordinates, y-down).
fn corners(v1: [f32; 2], v2: [f32; 2], width: f32) -> ([i64; 4], [i64; 4]) {
    let (mut v1, mut v2) = (v1, v2);
    let dx = v1[0] - v2[0];
    let dy = v1[1] - v2[1];
    let sign = |x: f32| x >= 0.0;
    let mut x_offset = 0f32;
    let mut y_offset = 0f32;
    let mut x_offset_end = 0f32;
    let mut y_offset_end = 0f32;
    let x1diff = v1[0] - v1[0].floor() - 0.5;
    let y1diff = v1[1] - v1[1].floor() - 0.5;
    let mut x2diff = v2[0] - v2[0].floor() - 0.5;
    let mut y2diff = v2[1] - v2[1].floor() - 0.5;
    let fixed_width = util_iround(width) * ONE;
    let half = fixed_width / 2;
    if dx.abs() >= dy.abs() {
        let dydx = dy / dx;
        if y2diff == -0.5 && dy < 0.0 {
            y2diff = 0.5;
        }
        let draw_start = if x1diff.abs() + y1diff.abs() < 0.5 {
            true
        } else if sign(x1diff) == sign(-dx) {
            false
        } else if sign(-y1diff) != sign(dy) {
            true
        } else {
            let yi = fracf(v1[1]) + x1diff * dydx;
            yi < 1.0 && yi > 0.0
        };
        let draw_end = if x2diff.abs() + y2diff.abs() < 0.5 || sign(x2diff) != sign(-dx) {
            false
        } else if sign(-y2diff) == sign(dy) {
            true
        } else {
            let yi = fracf(v2[1]) + x2diff * dydx;
            yi < 1.0 && yi > 0.0
        };
        if dx < 0.0 {
            std::mem::swap(&mut v1, &mut v2);
            if (x1diff <= 0.0) != draw_start {
                x_offset_end = -x1diff - 0.5;
                y_offset_end = x_offset_end * dydx;
            }
            if (x2diff > 0.0) != draw_end {
                x_offset = -x2diff - 0.5;
                y_offset = x_offset * dydx;
            }
        } else {
            if (x1diff > 0.0) != draw_start {
                x_offset = -x1diff + 0.5;
                y_offset = x_offset * dydx;
            }
            if (x2diff <= 0.0) != draw_end {
                x_offset_end = -x2diff + 0.5;
                y_offset_end = x_offset_end * dydx;
            }
        }
        let xa = subpixel_snap(v1[0] + x_offset - 0.5);
        let xb = subpixel_snap(v2[0] + x_offset_end - 0.5);
        let ya = subpixel_snap(v1[1] + y_offset - 0.5);
        let yb = subpixel_snap(v2[1] + y_offset_end - 0.5);
        (
            [xa, xb, xb, xa],
            [ya - half, yb - half, yb + half, ya + half],
        )
    } else {
        let dxdy = dx / dy;
        if x2diff == -0.5 && dx < 0.0 {
            x2diff = 0.5;
        }
        let draw_start = if x1diff.abs() + y1diff.abs() < 0.5 {
            true
        } else if sign(-y1diff) == sign(dy) {
            false
        } else if sign(x1diff) != sign(-dx) {
            true
        } else {
            let xi = fracf(v1[0]) + y1diff * dxdy;
            xi < 1.0 && xi > 0.0
        };
        let draw_end = if x2diff.abs() + y2diff.abs() < 0.5 || sign(-y2diff) != sign(dy) {
            false
        } else if sign(x2diff) == sign(-dx) {
            true
        } else {
            let xi = fracf(v2[0]) + y2diff * dxdy;
            (0.0..1.0).contains(&xi)
        };
        // OSMesa's window buffer uses the bottom-edge rule.
        if dy > 0.0 {
            std::mem::swap(&mut v1, &mut v2);
            if (y1diff >= 0.0) != draw_start {
                y_offset_end = -y1diff + 0.5;
                x_offset_end = y_offset_end * dxdy;
            }
            if (y2diff < 0.0) != draw_end {
                y_offset = -y2diff + 0.5;
                x_offset = y_offset * dxdy;
            }
        } else {
            if (y1diff < 0.0) != draw_start {
                y_offset = -y1diff - 0.5;
                x_offset = y_offset * dxdy;
            }
            if (y2diff >= 0.0) != draw_end {
                y_offset_end = -y2diff - 0.5;
                x_offset_end = y_offset_end * dxdy;
            }
        }
        let xa = subpixel_snap(v1[0] + x_offset - 0.5);
        let xb = subpixel_snap(v2[0] + x_offset_end - 0.5);
        let ya = subpixel_snap(v1[1] + y_offset - 0.5);
        let yb = subpixel_snap(v2[1] + y_offset_end - 0.5);
        (
            [xa - half, xb - half, xb + half, xa + half],
            [ya, yb, yb, ya],
        )
    }
}

/// Line attribute plane (`linear_coef` of `lp_setup_line.c`): `dx`, `dy` are the adjusted
/// deltas (one of them zero), `ooa` the reciprocal squared length, (x1, y1) the first
/// vertex.
#[inline]
fn line_plane(a1: f32, a2: f32, dx: f32, dy: f32, ooa: f32, x1: f32, y1: f32) -> Plane {
    let da21 = a1 - a2;
    let dadx = da21 * dx * ooa;
    let dady = da21 * dy * ooa;
    Plane {
        a0: a1 - (dadx * (x1 - 0.5) + dady * (y1 - 0.5)),
        dadx,
        dady,
    }
}

/// Draws segment `v1`–`v2` (window coordinates, y-down) of integer-rounded `width` inside
/// the region; `flat` is the provoking vertex's varyings (used under GL_FLAT); `top_left`
/// is llvmpipe's `bottom_edge_rule = 0` (objects, toggled by GL_UPPER_LEFT): horizontal
/// edges with `dcdy > 0` instead of `< 0` get the +1, and the box has no `adj`.
pub fn raster_line(
    v1: &ClipVertex,
    v2: &ClipVertex,
    flat: &[f32; MAX_VARY],
    (width, top_left): (f32, bool),
    nvary: usize,
    d: &mut Draw<'_, '_>,
) {
    let (p1, p2) = ([v1.win[0], v1.win[1]], [v2.win[0], v2.win[1]]);
    if !p1.iter().chain(p2.iter()).all(|c| c.is_finite()) {
        return;
    }
    let dx = p1[0] - p2[0];
    let dy = p1[1] - p2[1];
    let area = dx * dx + dy * dy;
    if area == 0.0 {
        return;
    }
    let inside = p1.iter().chain(p2.iter()).all(|c| c.abs() < MAX_COORD);
    let (xs, ys) = if inside {
        corners(p1, p2, width.max(1.0))
    } else {
        match cut_to_box(p1, p2) {
            Some((q1, q2)) if q1 != q2 => corners(q1, q2, width.max(1.0)),
            _ => return,
        }
    };
    let minx = *xs.iter().min().unwrap_or(&0);
    let maxx = *xs.iter().max().unwrap_or(&0);
    let miny = *ys.iter().min().unwrap_or(&0);
    let maxy = *ys.iter().max().unwrap_or(&0);
    // llvmpipe's bounding box, with the bottom-edge rule's +1 in y (`adj`).
    let adj = if top_left { 0 } else { 1 };
    let b = d.clip([
        (minx + ONE - 1) >> 8,
        (miny + ONE - 1 + adj) >> 8,
        ((maxx + ONE - 1) >> 8) - 1,
        ((maxy + ONE - 1 + adj) >> 8) - 1,
    ]);
    if b[0] > b[2] || b[1] > b[3] {
        return;
    }
    let edges: [Edge; 4] = std::array::from_fn(|i| {
        let j = (i + 1) % 4;
        let a = ys[i] - ys[j];
        let bb = xs[i] - xs[j];
        let mut c = a * xs[i] - bb * ys[i];
        if a < 0 || (a == 0 && if top_left { bb > 0 } else { bb < 0 }) {
            c += 1;
        }
        Edge { a, b: bb, c }
    });

    // Planes: x-major lines vary along x only, y-major along y only.
    let ooa = 1.0f32 / area;
    let (pdx, pdy) = if dx.abs() >= dy.abs() {
        let dydx = dy / dx;
        (dx * (1.0 + dydx * dydx), 0.0)
    } else {
        let dxdy = dx / dy;
        (0.0, dy * (1.0 + dxdy * dxdy))
    };
    let (x1, y1) = (p1[0], p1[1]);
    let plane = |a1: f32, a2: f32| line_plane(a1, a2, pdx, pdy, ooa, x1, y1);
    let (w1, w2) = (v1.win[3], v2.win[3]);
    let persp = !(w1 == 1.0 && w2 == 1.0);
    let mut t = SetupTriangle {
        z: plane(v1.win[2], v2.win[2]),
        w: plane(w1, w2),
        persp,
        flat: *flat,
        flat_u8: [0, 1, 2, 3].map(|i| crate::framebuffer::float_to_ubyte(flat[i])),
        ..Default::default()
    };
    for i in 0..nvary {
        t.vary[i] = if persp {
            plane(v1.vary[i] * w1, v2.vary[i] * w2)
        } else {
            plane(v1.vary[i], v2.vary[i])
        };
    }
    let plan = d.plan;
    if let Some(sh) = &plan.shader {
        t.front = d.prim_front;
        super::shaded::covered(&t, b, &super::prim_tex::EdgeCover(&edges), sh, d);
        return;
    }
    if !d.units.is_empty() {
        super::prim_tex::shade_covered(&t, b, &super::prim_tex::EdgeCover(&edges), d);
        return;
    }
    let span = |py: i64| {
        let (mut lo, mut hi) = (b[0], b[2]);
        for e in &edges {
            match e.span(py) {
                Some((l, h)) => {
                    lo = lo.max(l);
                    hi = hi.min(h);
                }
                None => hi = lo - 1,
            }
        }
        (lo, hi)
    };
    super::prim_spans::shade_rows(&t, b[1], b[3], span, d);
}

/// Draws a point of `size` (glPointSize, already clamped) at `v`; `top_left` as
/// [`raster_line`]'s (`y0 = snap(y) − adj`, adj = `bottom_edge_rule`); `coords` are
/// replaced across the square as a sprite's (a shader's `gl_PointCoord`).
pub fn raster_point(
    v: &ClipVertex,
    size: f32,
    coords: &super::sprite::Sprite,
    top_left: bool,
    nvary: usize,
    d: &mut Draw<'_, '_>,
) {
    let (x, y) = (v.win[0], v.win[1]);
    if !(x.is_finite() && y.is_finite() && x.abs() < MAX_COORD && y.abs() < MAX_COORD) {
        return;
    }
    let size = size.min(255.0);
    let x0 = subpixel_snap(x);
    let y0 = subpixel_snap(y) - if top_left { 0 } else { 1 };
    let width = (((subpixel_snap(size) + ONE / 2 - 1) & !(ONE - 1)).max(ONE)) >> 8;
    let (bx, by) = if width == 1 {
        (x0 >> 8, y0 >> 8)
    } else if width & 1 == 1 {
        ((x0 >> 8) - (width - 1) / 2, (y0 >> 8) - (width - 1) / 2)
    } else {
        (
            ((x0 + ONE / 2) >> 8) - width / 2,
            ((y0 + ONE / 2) >> 8) - width / 2,
        )
    };
    let b = d.clip([bx, by, bx + width - 1, by + width - 1]);
    if b[0] > b[2] || b[1] > b[3] {
        return;
    }
    let mut t = point_planes(v, nvary);
    super::sprite::replace_coords(&mut t, v, width << 8, coords);
    let plan = d.plan;
    if let Some(sh) = &plan.shader {
        t.front = d.prim_front;
        super::shaded::covered(&t, b, &super::prim_tex::BoxCover, sh, d);
        return;
    }
    if !d.units.is_empty() {
        super::prim_tex::shade_covered(&t, b, &super::prim_tex::BoxCover, d);
        return;
    }
    super::prim_spans::shade_rows(&t, b[1], b[3], |_| (b[0], b[2]), d);
}

/// The planes of a point: depth, w and the first `nvary` varyings constant at vertex
/// `v`'s values (perspective-divided varyings kept times w, as the walks expect), flat
/// values from `v`.
pub(super) fn point_planes(v: &ClipVertex, nvary: usize) -> SetupTriangle {
    let w0 = v.win[3];
    let persp = w0 != 1.0;
    let constant = |a: f32| Plane {
        a0: a,
        dadx: 0.0,
        dady: 0.0,
    };
    let mut t = SetupTriangle {
        z: constant(v.win[2]),
        w: constant(w0),
        persp,
        ..Default::default()
    };
    t.set_flat(MAX_VARY, |i| v.vary[i]);
    for i in 0..nvary {
        t.vary[i] = constant(if persp { v.vary[i] * w0 } else { v.vary[i] });
    }
    t
}

/// The line stipple stage of Mesa's draw module (`draw_pipe_stipple.c`): cuts a segment
/// into its "on" pieces, keeping the pattern position across the segments of a strip.
#[derive(Clone, Copy, Debug)]
pub struct LineStipple {
    /// The pattern, bit 0 first.
    pub pattern: u16,
    /// The repeat factor (1..=256).
    pub factor: u32,
    /// The pattern position (a float, as Mesa keeps it).
    pub counter: f32,
    /// `line_rectangular` (GL_LINE_SMOOTH): the length is Euclidean, not max(|dx|, |dy|).
    pub rectangular: bool,
}

impl LineStipple {
    /// Calls `emit(t0, t1)` with the parameter range of every "on" piece of the segment
    /// from `p0` to `p1` (window x, y), then advances the counter by the segment's length
    /// (max of |dx| and |dy|, or Euclidean for smooth lines) rounded up.
    pub fn split(&mut self, p0: [f32; 2], p1: [f32; 2], mut emit: impl FnMut(f32, f32)) {
        let dx = (p0[0] - p1[0]).abs();
        let dy = (p0[1] - p1[1]).abs();
        let length = if self.rectangular {
            let (ex, ey) = (p1[0] - p0[0], p1[1] - p0[1]);
            (ex * ex + ey * ey).sqrt()
        } else {
            dx.max(dy)
        };
        let n = if length.is_finite() {
            length.ceil() as i64
        } else {
            0
        };
        let mut start = 0f32;
        let mut state = false;
        let base = self.counter as i64;
        for i in 0..n {
            let b = ((base + i) / self.factor as i64) & 15;
            let on = self.pattern & (1 << b) != 0;
            if on != state {
                if state {
                    emit(start / length, i as f32 / length);
                } else {
                    start = i as f32;
                }
                state = on;
            }
        }
        if state && start < length {
            emit(start / length, 1.0);
        }
        // Mesa's counter is an integer advanced by the whole pixels iterated.
        self.counter += n as f32;
    }
}

/// A vertex between `a` and `b` at parameter `t`, every field interpolated linearly in
/// window space (the stipple stage's `screen_interp`).
pub fn screen_interp(t: f32, a: &ClipVertex, b: &ClipVertex, nvary: usize) -> ClipVertex {
    let mut v = *a;
    for i in 0..4 {
        v.win[i] = a.win[i] + t * (b.win[i] - a.win[i]);
    }
    for i in 0..nvary {
        v.vary[i] = a.vary[i] + t * (b.vary[i] - a.vary[i]);
    }
    v
}

/// Shades span `s` with the planes of `t` (through [`super::prim_spans`], as the rows of
/// a line).
pub fn shade_span_dispatch(t: &SetupTriangle, d: &mut Draw<'_, '_>, s: Span) {
    let mut rs = super::prim_spans::RowSpans::new(s.y as i64);
    rs.n = 1;
    rs.lo[0] = s.x0 as i64;
    rs.hi[0] = s.x1 as i64;
    super::prim_spans::shade(t, &rs, d);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn iround_is_half_away_from_zero() {
        assert_eq!(util_iround(0.5), 1);
        assert_eq!(util_iround(-0.5), -1);
        assert_eq!(util_iround(1.49), 1);
        assert_eq!(util_iround(-2.5), -3);
    }

    #[test]
    fn stipple_splits_pattern() {
        let mut s = LineStipple {
            pattern: 0x00ff,
            factor: 1,
            counter: 0.0,
            rectangular: false,
        };
        let mut pieces = vec![];
        s.split([0.0, 0.0], [32.0, 0.0], |a, b| pieces.push((a, b)));
        assert_eq!(pieces, vec![(0.0, 0.25), (0.5, 0.75)]);
        assert_eq!(s.counter, 32.0);
    }
}
