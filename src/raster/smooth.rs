//! Antialiased (GL_LINE_SMOOTH, GL_POINT_SMOOTH) lines and points as llvmpipe draws them:
//! through the draw module's "aaline" and "aapoint" stages (Mesa 22.3,
//! `draw_pipe_aaline.c`, `draw_pipe_aapoint.c`, `nir_draw_helpers.c`).
//!
//! Both stages turn the primitive into two ordinary triangles (set up and filled with the
//! triangle rules) that carry one extra vec4 varying, and both rewrite the fragment
//! shader so that it multiplies the final alpha by a coverage computed from that varying
//! (interpolated like every generic input: perspective-correct, `fmuladd` planes).
//!
//! aaline (after clipping and line stipple): the segment p→q (window coordinates,
//! y-down) becomes a rectangle lengthened by 0.5 pixel at both ends and `hw` pixels to
//! each side, with `hw = 1` for widths ≤ 1 and `width/2 + 0.5` otherwise. The direction
//! comes from `atan2f`, `cosf`, `sinf` of (dx, dy) in f32 (C, no FMA). The varying is
//! `(±hw, hw, ±hl, hl)` with `hl = length/2 + 0.5` (or `length` for segments shorter than
//! one pixel), and the coverage is `sat(y − |x|) · sat(w − |z|)`. Triangles:
//! (v2, v1, v0), (v3, v1, v2).
//!
//! aapoint: a square of half-side `r` around the point (`r = 1` for sizes ≤ 2, else
//! `size/2`), triangles (v0, v1, v2), (v0, v2, v3) from the top-left corner clockwise, with
//! the varying `(±1, ±1, k, 1)`, `k = (1 − 2/r) + 1/r²`. The fragment shader computes
//! `d = x² + y²`, kills the fragment when `1 < d`, and multiplies alpha by
//! `(k ≥ d) ? (1/(1 − k))·(1 − d) : 1` — the selection is inverted with respect to the
//! comment in Mesa's source, so inside the inner circle alpha is scaled *up* (and then
//! saturates), and the ring between `k` and 1 keeps the full alpha: llvmpipe's smooth
//! points are round, nearly hard-edged discs.

use super::{raster_triangle, Draw};
use crate::fragment::span::{one_over_w, vary_at, Madd, LANES};
use crate::fragment::FragPlan;
use crate::geometry::setup::{setup_triangle, CullMode, SetupResult, SetupTriangle};
use crate::geometry::{ClipVertex, MAX_VARY};

/// The coverage the fragment stage multiplies into alpha, with the varying slot that
/// carries the stage's vec4.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Smooth {
    /// aaline: `sat(y − |x|) · sat(w − |z|)`.
    Line(usize),
    /// aapoint: kill outside the unit disc, scale alpha inside the inner circle.
    Point(usize),
}

/// No culling: the stages bind a rasterizer state without culling, offset or two-side.
const NOCULL: CullMode = CullMode {
    front: false,
    back: false,
    front_ccw: true,
    top_left: false,
};

/// Where the stage's vec4 goes among `nvary` varyings: after them, or over the back
/// colours (which lines and points never use) when there is no room.
fn slot(nvary: usize) -> usize {
    if nvary + 4 <= MAX_VARY {
        nvary
    } else {
        nvary - 8
    }
}

/// The coverage of [`LANES`] pixels of row `fy`, clearing the `live` lanes the aapoint
/// shader kills.
#[inline(always)]
pub fn coverage<M: Madd, const PERSP: bool>(
    t: &SetupTriangle,
    s: Smooth,
    fx: &[f32; LANES],
    fy: f32,
    live: &mut [bool; LANES],
) -> [f32; LANES] {
    let oow = one_over_w::<M, PERSP>(t, fx, fy);
    let base = match s {
        Smooth::Line(k) | Smooth::Point(k) => k,
    };
    // gallivm's saturate: min(max(v, 0), 1) with NaN giving 0.
    let sat = |v: f32| if v > 0.0 { v.min(1.0) } else { 0.0 };
    let mut cov = [1f32; LANES];
    for i in 0..LANES {
        let e = |k: usize| vary_at::<M, PERSP>(t, base + k, fx[i], fy, oow[i]);
        let (x, y, z, w) = (e(0), e(1), e(2), e(3));
        cov[i] = match s {
            Smooth::Line(_) => sat(y - x.abs()) * sat(w - z.abs()),
            Smooth::Point(_) => {
                let d = x * x + y * y;
                if w < d {
                    live[i] = false;
                }
                if z >= d {
                    (1.0f32 / (w - z)) * (w - d)
                } else {
                    w
                }
            }
        };
    }
    cov
}

/// Sets up and fills the two triangles of quad `v` with the coverage `smooth` (the
/// stage's replacement fragment shader), whose four varyings follow the draw's.
fn fill(v: &[ClipVertex; 4], smooth: Smooth, d: &mut Draw<'_, '_>) {
    // The rows a shader draw has pending go first (primitive order).
    if let Some(p) = d.shaded.take() {
        p.end(d.units, d.fb, d.stats);
    }
    let plan = FragPlan {
        smooth: Some(smooth),
        ..*d.plan
    };
    let d = &mut Draw::new(d.region, &plan, d.units, d.fb, d.stats);
    let (tris, nvary) = match smooth {
        Smooth::Line(k) => ([[2, 1, 0], [3, 1, 2]], k + 4),
        Smooth::Point(k) => ([[0, 1, 2], [0, 2, 3]], k + 4),
    };
    let mut t = SetupTriangle::default();
    for [a, b, c] in tris {
        d.stats.triangles += 1;
        match setup_triangle([&v[a], &v[b], &v[c]], nvary, NOCULL, None, &mut t) {
            SetupResult::Draw => {
                if raster_triangle(&t, d) {
                    d.stats.tris_rasterized += 1;
                } else {
                    d.stats.tris_offscreen += 1;
                }
            }
            _ => d.stats.tris_degenerate += 1,
        }
    }
}

/// Draws the antialiased segment `p`–`q` (clipped, window coordinates) of `width`
/// (already clamped to [1, 255]); under flat shading the colours are `flat`'s.
pub fn line(
    p: &ClipVertex,
    q: &ClipVertex,
    flat: Option<&[f32; MAX_VARY]>,
    width: f32,
    nvary: usize,
    d: &mut Draw<'_, '_>,
) {
    let half_width = if width <= 1.0 { 1.0 } else { 0.5 * width + 0.5 };
    let dx = q.win[0] - p.win[0];
    let dy = q.win[1] - p.win[1];
    let a = dy.atan2(dx);
    let (c_a, s_a) = (a.cos(), a.sin());
    let half_length = 0.5 * (dx * dx + dy * dy).sqrt();
    let half_length = if half_length < 0.5 {
        2.0 * half_length
    } else {
        half_length + 0.5
    };
    let (t_w, t_l) = (half_width, 0.5f32);
    let k = slot(nvary);
    let mut v = [*p, *p, *q, *q];
    if let Some(f) = flat {
        for x in &mut v {
            x.vary[..8].copy_from_slice(&f[..8]);
        }
    }
    // (along, across) signs of the four corners.
    for (i, (l, w)) in [(-t_l, t_w), (-t_l, -t_w), (t_l, t_w), (t_l, -t_w)]
        .into_iter()
        .enumerate()
    {
        v[i].win[0] += l * c_a - w * s_a;
        v[i].win[1] += l * s_a + w * c_a;
        let (x, z) = (
            if i % 2 == 0 { -half_width } else { half_width },
            if i < 2 { -half_length } else { half_length },
        );
        v[i].vary[k..k + 4].copy_from_slice(&[x, half_width, z, half_length]);
    }
    fill(&v, Smooth::Line(k), d);
}

/// Draws the antialiased point `v` (inside the clip volume) of `size` (glPointSize).
pub fn point(v: &ClipVertex, size: f32, nvary: usize, d: &mut Draw<'_, '_>) {
    let radius = if size <= 2.0 { 1.0f32 } else { 0.5 * size };
    let k = 1.0f32 / radius;
    let k = 1.0f32 - 2.0 * k + k * k;
    let s = slot(nvary);
    let mut q = [*v; 4];
    for (i, (sx, sy)) in [(-1.0f32, -1.0f32), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)]
        .into_iter()
        .enumerate()
    {
        q[i].win[0] = if sx < 0.0 {
            v.win[0] - radius
        } else {
            v.win[0] + radius
        };
        q[i].win[1] = if sy < 0.0 {
            v.win[1] - radius
        } else {
            v.win[1] + radius
        };
        q[i].vary[s..s + 4].copy_from_slice(&[sx, sy, k, 1.0]);
    }
    fill(&q, Smooth::Point(s), d);
}
