//! Homogeneous clipping of triangles and lines against the six view-volume planes and the
//! user clip planes.
//!
//! Sutherland–Hodgman, one plane at a time in llvmpipe's bit order (right, left, top,
//! bottom, near, far, then user planes 0..8), only for the planes some vertex is outside
//! of. User planes are given in clip space (Mesa's `_ClipUserPlane`: the eye-space plane
//! times the inverse projection); their distances here are plain C `dot4`s, while the
//! vertex stage's mask used `fmuladd` ([`super::user_clip_mask`]), as in the draw module. A new vertex is
//! interpolated in clip space from the end nearer to the plane, and its window position is
//! computed without FMA, exactly as Mesa's draw module does (`draw_pipe_clip.c`). There is
//! no guard band: every triangle that crosses a plane is cut, so window coordinates stay
//! inside the viewport and the fixed-point rasterizer never overflows.

use super::{ClipMask, ClipVertex, Viewport};

/// The view-volume planes as (a, b, c, d) with `dot(clip, plane) >= 0` inside.
const PLANES: [[f32; 4]; 6] = [
    [-1.0, 0.0, 0.0, 1.0],
    [1.0, 0.0, 0.0, 1.0],
    [0.0, -1.0, 0.0, 1.0],
    [0.0, 1.0, 0.0, 1.0],
    [0.0, 0.0, 1.0, 1.0],
    [0.0, 0.0, -1.0, 1.0],
];

/// The most vertices a triangle clipped by six planes and eight user planes can have, plus
/// room for scratch (Mesa's `MAX_CLIPPED_VERTICES` is 29).
const MAX_POLY: usize = 20;

/// The user clip planes of a draw.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct UserPlanes {
    /// The planes, indexed by plane (bit `6 + i` of a clip mask): in clip space, measured
    /// against the clip position; or, with `clip_vertex`, in eye space.
    pub planes: [[f32; 4]; 8],
    /// With a vertex shader: the first of the four varyings holding each vertex's clip
    /// vertex (`gl_ClipVertex`, or the clip position when the shader does not write it),
    /// which the user planes measure, as the draw module's `getclipdist` does with
    /// Mesa's eye-space planes. It is interpolated with the other varyings, so a vertex
    /// the clipper makes has it too.
    pub clip_vertex: Option<usize>,
}

/// The near plane under GL_ZERO_TO_ONE (the draw module's `clip_halfz` plane 4).
const NEAR_HALFZ: [f32; 4] = [0.0, 0.0, 1.0, 0.0];

/// Plane `p` of a clip mask bit: a view-volume plane or user plane `p - 6`; `halfz`
/// selects the GL_ZERO_TO_ONE near plane.
#[inline]
fn plane(p: usize, ucp: &UserPlanes, halfz: bool) -> [f32; 4] {
    if p == 4 && halfz {
        NEAR_HALFZ
    } else if p < 6 {
        PLANES[p]
    } else {
        ucp.planes[p - 6]
    }
}

/// Vertex `v`'s distance to plane `p` (`plane`, from [`plane`]): the clip position's, or
/// for a user plane the clip vertex's when there is one.
#[inline]
fn dist(v: &ClipVertex, p: usize, plane: [f32; 4], ucp: &UserPlanes) -> f32 {
    match ucp.clip_vertex {
        Some(b) if p >= 6 => dot4(
            [v.vary[b], v.vary[b + 1], v.vary[b + 2], v.vary[b + 3]],
            plane,
        ),
        _ => dot4(v.clip, plane),
    }
}

#[inline]
fn dot4(a: [f32; 4], b: [f32; 4]) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]
}

#[inline]
fn lerp(t: f32, out: f32, inn: f32) -> f32 {
    out + t * (inn - out)
}

fn interp(t: f32, out: &ClipVertex, inn: &ClipVertex, vp: &Viewport, nvary: usize) -> ClipVertex {
    let mut d = ClipVertex::default();
    for i in 0..4 {
        d.clip[i] = lerp(t, out.clip[i], inn.clip[i]);
    }
    d.win = vp.apply_clipper(d.clip);
    for i in 0..nvary {
        d.vary[i] = lerp(t, out.vary[i], inn.vary[i]);
    }
    d.psize = lerp(t, out.psize, inn.psize);
    d
}

/// The varyings GL_FLAT makes constant: the primary and secondary colours (bits 0–7 of
/// a clipper's `flat` mask).
pub const FLAT_COLORS: u64 = 0xFF;

/// Copies the constant-interpolated varyings `flat` (bit v: varying v; the colours
/// under GL_FLAT, a shader's `flat` inputs), and with two-sided lighting the back
/// colours at `back` of the copied colours, from `src` to `dst`, as the clipper's
/// `copy_flat` does: the other varyings stay interpolated.
fn copy_flat(dst: &mut ClipVertex, src: &ClipVertex, flat: u64, back: Option<usize>) {
    let mut m = flat;
    while m != 0 {
        let v = m.trailing_zeros() as usize;
        m &= m - 1;
        if let (Some(d), Some(&s)) = (dst.vary.get_mut(v), src.vary.get(v)) {
            *d = s;
        }
        if let Some(o) = back.filter(|_| v < 8) {
            if let (Some(d), Some(&s)) = (dst.vary.get_mut(o + v), src.vary.get(o + v)) {
                *d = s;
            }
        }
    }
}

/// Clips triangle `v` (whose vertices' masks OR to `mask`, and AND to zero) and calls `emit`
/// for each resulting triangle, ordered `(P[i-1], P[i], P[0])` so that P[0], which carries
/// the provoking vertex's flat attributes, comes last. `flat` ([`copy_flat`]'s mask)
/// copies `v[2]`'s constant varyings (with the back colours at `back`) into P[0] when it
/// is a new vertex. Returns the number of triangles emitted.
#[allow(clippy::too_many_arguments)]
pub fn clip_triangle(
    v: [&ClipVertex; 3],
    mask: ClipMask,
    ucp: &UserPlanes,
    vp: &Viewport,
    nvary: usize,
    flat: u64,
    back: Option<usize>,
    mut emit: impl FnMut(&ClipVertex, &ClipVertex, &ClipVertex),
) -> usize {
    let all = 7;
    let each = |a: &ClipVertex, b: &ClipVertex, c: &ClipVertex, _: u8| emit(a, b, c);
    clip_triangle_edges(v, all, mask, ucp, vp, nvary, flat, back, each)
}

/// [`clip_triangle`] that also tracks which edges are polygon boundary edges, as
/// `do_clip_tri`/`emit_poly` do for the unfilled stage: `edges` has bit 0 for v0→v1, bit
/// 1 for v1→v2 and bit 2 for v2→v0; an edge along a frustum plane is hidden, one along a
/// user clip plane is shown, and the fan's inner diagonals are hidden. `emit` gets each
/// triangle's bits in the same layout.
#[allow(clippy::too_many_arguments)]
pub fn clip_triangle_edges(
    v: [&ClipVertex; 3],
    edges: u8,
    mask: ClipMask,
    ucp: &UserPlanes,
    vp: &Viewport,
    nvary: usize,
    flat: u64,
    back: Option<usize>,
    mut emit: impl FnMut(&ClipVertex, &ClipVertex, &ClipVertex, u8),
) -> usize {
    // The edge starting at each polygon vertex is a boundary edge.
    let mut a_e = [false; MAX_POLY];
    let mut b_e = [false; MAX_POLY];
    for (k, e) in a_e.iter_mut().enumerate().take(3) {
        *e = edges & (1 << k) != 0;
    }
    let (mut in_e, mut out_e) = (&mut a_e, &mut b_e);
    let mut a: [ClipVertex; MAX_POLY] = [ClipVertex::default(); MAX_POLY];
    let mut b: [ClipVertex; MAX_POLY] = [ClipVertex::default(); MAX_POLY];
    // Whether each polygon vertex is one of the original three (index) or new (usize::MAX).
    let mut a_orig = [usize::MAX; MAX_POLY];
    let mut b_orig = [usize::MAX; MAX_POLY];
    for i in 0..3 {
        a[i] = *v[i];
        a_orig[i] = i;
    }
    let (mut inl, mut outl) = (&mut a, &mut b);
    let (mut in_o, mut out_o) = (&mut a_orig, &mut b_orig);
    let mut n = 3usize;
    let mut planes = mask;
    while planes != 0 && n >= 3 {
        let p = planes.trailing_zeros() as usize;
        planes &= planes - 1;
        let plane = plane(p, ucp, vp.halfz);
        let mut dp_prev = dist(&inl[0], p, plane, ucp);
        if !dp_prev.is_finite() {
            return 0;
        }
        if n + 1 > MAX_POLY {
            return 0;
        }
        inl[n] = inl[0];
        in_o[n] = in_o[0];
        in_e[n] = in_e[0];
        let mut cnt = 0usize;
        for i in 1..=n {
            let dp = dist(&inl[i], p, plane, ucp);
            if !dp.is_finite() {
                return 0;
            }
            let different_sign = if dp_prev >= 0.0 {
                if cnt >= MAX_POLY {
                    return 0;
                }
                outl[cnt] = inl[i - 1];
                out_o[cnt] = in_o[i - 1];
                out_e[cnt] = in_e[i - 1];
                cnt += 1;
                dp < 0.0
            } else {
                dp >= 0.0 || dp.is_nan()
            };
            if different_sign {
                if cnt >= MAX_POLY {
                    return 0;
                }
                let (prev, cur) = (&inl[i - 1], &inl[i]);
                let denom = dp - dp_prev;
                let nv = if dp < 0.0 {
                    if -dp < dp_prev {
                        interp(dp / denom, cur, prev, vp, nvary)
                    } else {
                        interp(-dp_prev / denom, prev, cur, vp, nvary)
                    }
                } else if -dp_prev < dp {
                    interp(-dp_prev / denom, prev, cur, vp, nvary)
                } else {
                    interp(dp / denom, cur, prev, vp, nvary)
                };
                outl[cnt] = nv;
                out_o[cnt] = usize::MAX;
                // Leaving: the edge along the plane shows only for user clip planes.
                out_e[cnt] = if dp < 0.0 { p >= 6 } else { in_e[i - 1] };
                cnt += 1;
            }
            dp_prev = dp;
        }
        std::mem::swap(&mut inl, &mut outl);
        std::mem::swap(&mut in_o, &mut out_o);
        std::mem::swap(&mut in_e, &mut out_e);
        n = cnt;
    }
    if n < 3 {
        return 0;
    }
    if flat != 0 && in_o[0] != 2 {
        copy_flat(&mut inl[0], v[2], flat, back);
    }
    for i in 2..n {
        // (P[i-1], P[i], P[0]): bit 0 is P[i-1]→P[i], bit 1 P[i]→P[0], bit 2 P[0]→P[i-1].
        let mut bits = 0u8;
        if in_e[i - 1] {
            bits |= 1;
        }
        if i == n - 1 && in_e[n - 1] {
            bits |= 2;
        }
        if i == 2 && in_e[0] {
            bits |= 4;
        }
        emit(&inl[i - 1], &inl[i], &inl[0], bits);
    }
    n - 2
}

/// Clips segment `v0`–`v1` against the planes in `mask` (Mesa's `do_clip_line`: the
/// largest entry parameter from each end). Returns the clipped endpoints, or `None` when
/// nothing is left. `flat` ([`copy_flat`]'s mask) copies the provoking vertex `v1`'s
/// constant varyings to a new endpoint.
pub fn clip_line(
    v0: &ClipVertex,
    v1: &ClipVertex,
    mask: ClipMask,
    ucp: &UserPlanes,
    vp: &Viewport,
    nvary: usize,
    flat: u64,
) -> Option<(ClipVertex, ClipVertex)> {
    let (mut t0, mut t1) = (0.0f32, 0.0f32);
    let mut planes = mask;
    while planes != 0 {
        let p = planes.trailing_zeros() as usize;
        planes &= planes - 1;
        let pl = plane(p, ucp, vp.halfz);
        let dp0 = dist(v0, p, pl, ucp);
        let dp1 = dist(v1, p, pl, ucp);
        if !dp0.is_finite() || !dp1.is_finite() {
            return None;
        }
        if dp1 < 0.0 {
            t1 = t1.max(dp1 / (dp1 - dp0));
        }
        if dp0 < 0.0 {
            t0 = t0.max(dp0 / (dp0 - dp1));
        }
        if t0 + t1 >= 1.0 {
            return None;
        }
    }
    let mut a = *v0;
    let mut b = *v1;
    if v0.mask != 0 {
        a = interp(t0, v0, v1, vp, nvary);
        if flat != 0 {
            copy_flat(&mut a, v1, flat, None);
        }
    }
    if v1.mask != 0 {
        b = interp(t1, v1, v0, vp, nvary);
        if flat != 0 {
            copy_flat(&mut b, v1, flat, None);
        }
    }
    Some((a, b))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::clip_mask;

    fn vert(c: [f32; 4]) -> ClipVertex {
        ClipVertex {
            clip: c,
            mask: clip_mask(c, false),
            ..Default::default()
        }
    }

    #[test]
    fn triangle_crossing_right_plane_becomes_quad() {
        let vp = Viewport::new([0, 0, 100, 100], [0.0, 1.0], 100);
        let v = [
            vert([0.0, 0.0, 0.0, 1.0]),
            vert([2.0, 0.0, 0.0, 1.0]),
            vert([0.0, 0.5, 0.0, 1.0]),
        ];
        let mask = v[0].mask | v[1].mask | v[2].mask;
        let mut tris = vec![];
        let n = clip_triangle(
            [&v[0], &v[1], &v[2]],
            mask,
            &UserPlanes::default(),
            &vp,
            0,
            0,
            None,
            |a, b, c| tris.push([a.clip, b.clip, c.clip]),
        );
        assert_eq!(n, 2);
        for t in &tris {
            for c in t {
                assert!(c[0] <= c[3], "{c:?} outside");
            }
        }
    }

    #[test]
    fn nan_discards() {
        let vp = Viewport::new([0, 0, 10, 10], [0.0, 1.0], 10);
        let v = [
            vert([f32::NAN, 0.0, 0.0, 1.0]),
            vert([2.0, 0.0, 0.0, 1.0]),
            vert([0.0, 0.5, 0.0, 1.0]),
        ];
        assert_eq!(
            clip_triangle(
                [&v[0], &v[1], &v[2]],
                1,
                &UserPlanes::default(),
                &vp,
                0,
                0,
                None,
                |_, _, _| {}
            ),
            0
        );
    }
}
