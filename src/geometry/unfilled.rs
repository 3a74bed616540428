//! The draw module's primitive pipeline for triangles, as llvmpipe configures it when a
//! triangle needs more than plain filling (`draw_pipe_validate.c`): the cull stage's
//! determinant, two-sided colour selection, the polygon offset stage
//! (`draw_pipe_offset.c`, applied per vertex), and the unfilled stage
//! (`draw_pipe_unfilled.c`), which turns a triangle into its flagged edges as lines or its
//! flagged vertices as points.
//!
//! Decomposition follows `draw_decompose_tmp.h` (last-vertex convention) with its edge
//! flag bits: bit 0 is the edge v0→v1, bit 1 v1→v2, bit 2 v2→v0. The unfilled stage
//! emits the lines v2→v0, v0→v1, v1→v2 (each when its bit and its first vertex's edge
//! flag are set), so a polygon's outline starts at its first vertex.

use super::ClipVertex;
use crate::pipe::FillMode;
use crate::pipe::Primitive;
use crate::texture::shadow::FLOAT_BITS;

/// Edge v0→v1.
pub const EDGE_0: u8 = 1;
/// Edge v1→v2.
pub const EDGE_1: u8 = 2;
/// Edge v2→v0.
pub const EDGE_2: u8 = 4;
/// All three edges.
pub const EDGE_ALL: u8 = 7;

/// Calls `tri(a, b, c, edges, reset)` for every triangle of `mode` in the draw module's
/// decomposition order; `edges` holds the boundary-edge bits and `reset` marks the first
/// triangle of each primitive (it restarts the line stipple).
pub fn decompose(mode: Primitive, n: usize, mut tri: impl FnMut(usize, usize, usize, u8, bool)) {
    match mode {
        Primitive::Triangles => {
            for i in (0..n / 3 * 3).step_by(3) {
                tri(i, i + 1, i + 2, EDGE_ALL, true);
            }
        }
        Primitive::TriangleStrip => {
            for i in 2..n {
                if i % 2 == 0 {
                    tri(i - 2, i - 1, i, EDGE_ALL, true);
                } else {
                    tri(i - 1, i - 2, i, EDGE_ALL, true);
                }
            }
        }
        Primitive::TriangleFan => {
            for i in 2..n {
                tri(0, i - 1, i, EDGE_ALL, true);
            }
        }
        Primitive::Quads => {
            for q in (0..n / 4 * 4).step_by(4) {
                tri(q, q + 1, q + 3, EDGE_0 | EDGE_2, true);
                tri(q + 1, q + 2, q + 3, EDGE_0 | EDGE_1, false);
            }
        }
        Primitive::QuadStrip => {
            let mut k = 0;
            while k + 3 < n {
                let (a, b, c, d) = (k, k + 1, k + 2, k + 3);
                tri(c, a, d, EDGE_0 | EDGE_2, true);
                tri(a, b, d, EDGE_0 | EDGE_1, false);
                k += 2;
            }
        }
        Primitive::Polygon => {
            for i in 2..n {
                let mut f = EDGE_0;
                if i == 2 {
                    f |= EDGE_2;
                }
                if i == n - 1 {
                    f |= EDGE_1;
                }
                tri(i - 1, i, 0, f, i == 2);
            }
        }
        Primitive::Points | Primitive::Lines | Primitive::LineLoop | Primitive::LineStrip => {}
    }
}

/// The cull stage's determinant of a triangle in window coordinates (y-down):
/// `ex·fy − ey·fx` with e = v0 − v2, f = v1 − v2. Negative means counter-clockwise in GL.
#[inline]
pub fn determinant(v: [&ClipVertex; 3]) -> f32 {
    let ex = v[0].win[0] - v[2].win[0];
    let ey = v[0].win[1] - v[2].win[1];
    let fx = v[1].win[0] - v[2].win[0];
    let fy = v[1].win[1] - v[2].win[1];
    ex * fy - ey * fx
}

/// The draw module's polygon offset (`do_offset_tri`): the offset added to each vertex's
/// window z (which is then clamped to [0, 1]). `units` is already scaled
/// (`units · mrd · 2`).
pub fn draw_offset(v: [&ClipVertex; 3], det: f32, factor: f32, units: f32) -> f32 {
    let inv_det = 1.0f32 / det;
    let (p0, p1, p2) = (v[0].win, v[1].win, v[2].win);
    let ex = p0[0] - p2[0];
    let ey = p0[1] - p2[1];
    let ez = p0[2] - p2[2];
    let fx = p1[0] - p2[0];
    let fy = p1[1] - p2[1];
    let fz = p1[2] - p2[2];
    let a = ey * fz - ez * fy;
    let b = ez * fx - ex * fz;
    let dzdx = (a * inv_det).abs();
    let dzdy = (b * inv_det).abs();
    let m = if dzdx > dzdy { dzdx } else { dzdy };
    units + m * factor
}

/// llvmpipe's own polygon offset for filled triangles (`lp_do_offset_tri`), computed on
/// the window positions of the set-up (possibly reordered) vertices; added to every
/// fragment's z.
#[inline]
pub fn setup_offset(win: [[f32; 4]; 3], factor: f32, units: f32) -> f32 {
    let [p0, p1, p2] = win;
    let (dx01, dy01, dz01) = (p0[0] - p1[0], p0[1] - p1[1], p0[2] - p1[2]);
    let (dx20, dy20, dz20) = (p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]);
    let ooa = 1.0f32 / (dx01 * dy20 - dy01 * dx20);
    let r1 = dz20 * dy01 - dy20 * dz01;
    let r2 = dx20 * dz01 - dz20 * dx01;
    let dzdx = (r1 * ooa).abs();
    let dzdy = (r2 * ooa).abs();
    // LLVM's `fcmp ugt` select: NaN picks dzdx.
    let m = if dzdx > dzdy || dzdx.is_nan() || dzdy.is_nan() {
        dzdx
    } else {
        dzdy
    };
    units + m * factor
}

/// The offset units for a float depth buffer (the draw module's and llvmpipe's
/// `floating_point_depth` case): `units · 2^(e − 23)` with `e` the exponent of the largest
/// |z| of the triangle, taken on the float's bits (0 when `e < 23`).
#[inline]
pub fn float_units(units: f32, z: [f32; 3]) -> f32 {
    let m = z[0].abs().max(z[1].abs()).max(z[2].abs());
    let e = (m.to_bits() & (0xff << 23)) as i32 - (23 << 23);
    units * f32::from_bits(e.max(0) as u32)
}

/// The offset units as the draw module and llvmpipe scale them for a depth buffer of
/// `bits` bits: `(float)(units · mrd · 2)` with `mrd = 1 / (2^bits − 1)` in double.
///
/// A float depth buffer ([`FLOAT_BITS`] as `bits`) keeps the units as given: they are
/// scaled per triangle by [`float_units`].
pub fn scaled_units(units: f32, bits: u32) -> f32 {
    if bits == 0 {
        return 0.0;
    }
    if bits == FLOAT_BITS as u32 {
        return units;
    }
    let mrd = 1.0f64 / (((1u64 << bits) - 1) as f64);
    (units as f64 * mrd * 2.0) as f32
}

/// The fill mode of a triangle with determinant `det` (`unfilled_tri`: det ≥ 0 is
/// clockwise in GL terms).
pub fn fill_mode(det: f32, front_ccw: bool, front: FillMode, back: FillMode) -> FillMode {
    let cw = det >= 0.0;
    let is_front = cw != front_ccw;
    if is_front {
        front
    } else {
        back
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The boundary edges `decompose` draws for `n` vertices of `mode`, in its order.
    fn outline(mode: Primitive, n: usize) -> Vec<(usize, usize)> {
        let mut lines = vec![];
        decompose(mode, n, |a, b, c, f, _| {
            let v = [a, b, c];
            for (bit, (s, e)) in [(EDGE_2, (2, 0)), (EDGE_0, (0, 1)), (EDGE_1, (1, 2))] {
                if f & bit != 0 {
                    lines.push((v[s], v[e]));
                }
            }
        });
        lines
    }

    #[test]
    fn polygon_edges_walk_the_outline() {
        let lines = outline(Primitive::Polygon, 5);
        assert_eq!(lines, vec![(0, 1), (1, 2), (2, 3), (3, 4), (4, 0)]);
    }

    #[test]
    fn quad_edges() {
        let lines = outline(Primitive::Quads, 4);
        assert_eq!(lines, vec![(3, 0), (0, 1), (1, 2), (2, 3)]);
    }
}
