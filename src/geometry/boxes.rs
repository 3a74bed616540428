//! Boxes around runs of stored positions, so that the clip-mask pass ahead of the vertex
//! stage ([`super::reject`]) can give a whole run the clip planes it lies outside of
//! without transforming its positions one by one.
//!
//! A compiled display list keeps a box per [`BOX_VERTS`] of its positions
//! ([`boxes_of`], when every position of the run is finite with w = 1). A floor grid that
//! MuJoCo draws in each of its passes is mostly outside the view; its runs outside one
//! plane are then one test each instead of 64 transforms.
//!
//! # The test and its margin
//! A clip plane is a linear function of the object position (`g · (x, y, z, 1)` with `g`
//! a row combination of the combined matrix, [`ClipPlanes::new`]); its least value over a
//! box is at a corner, `g · c − Σ |g_j| e_j` for centre `c` and half-extent `e`,
//! computed in f64. A run is given a plane's bit only when that least value exceeds
//! 10⁻⁵ of the magnitudes involved ([`ClipPlanes::outside`]). The f32 transform of a
//! vertex (four rounded multiply-adds per row) errs by under 10⁻⁶ of the same
//! magnitudes, so every vertex of the run has that bit in the mask the vertex stage
//! computes. A run's bits are a subset of each vertex's own: a triangle they reject is
//! rejected by the exact masks too, and a triangle they let through is still rejected by
//! the clip test after the vertex stage; the images are the same either way.

use super::ClipMask;

/// Positions per box, counted from the first stored position.
pub const BOX_VERTS: usize = 64;

/// The bounds of one run of positions (all finite, w = 1): centre and half-extent.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PosBox {
    /// The centre.
    pub center: [f64; 3],
    /// Half the extent along each axis.
    pub extent: [f64; 3],
}

/// The box of each run of [`BOX_VERTS`] positions of `pos` (the last run may be
/// shorter); `None` for a run with a position that is not finite or whose w is not 1.
pub fn boxes_of(pos: &[[f32; 4]]) -> Vec<Option<PosBox>> {
    pos.chunks(BOX_VERTS)
        .map(|run| {
            let mut lo = [f64::INFINITY; 3];
            let mut hi = [f64::NEG_INFINITY; 3];
            for p in run {
                if p[3] != 1.0 || !p.iter().all(|c| c.is_finite()) {
                    return None;
                }
                for j in 0..3 {
                    lo[j] = lo[j].min(f64::from(p[j]));
                    hi[j] = hi[j].max(f64::from(p[j]));
                }
            }
            Some(PosBox {
                center: [0, 1, 2].map(|j| (lo[j] + hi[j]) * 0.5),
                extent: [0, 1, 2].map(|j| (hi[j] - lo[j]) * 0.5),
            })
        })
        .collect()
}

/// The boxes of a draw's source: box `k` bounds the source's vertices from
/// `k · BOX_VERTS − first` on (those of them that are in the draw).
#[derive(Clone, Copy, Debug)]
pub struct PositionBoxes<'a> {
    /// Where the source's vertex 0 lies in the boxes' numbering.
    pub first: usize,
    /// The boxes.
    pub boxes: &'a [Option<PosBox>],
}

/// The six frustum planes of one combined matrix as functions of the object position,
/// with the clip-mask bit each one sets (those of [`super::clip_mask`]).
#[derive(Clone, Copy, Debug)]
pub struct ClipPlanes {
    /// Per plane: the coefficients of x, y, z and the constant, positive outside.
    g: [[f64; 4]; 6],
    /// Per plane: its bit.
    bits: [ClipMask; 6],
    /// The matrix rows' absolute values summed over the four clip coordinates, per object
    /// coordinate (the constant last): the scale of the rounding error.
    scale: [f64; 4],
}

impl ClipPlanes {
    /// The planes of combined matrix `m` (column-major: clip = Σ_j m[4j..4j+4] · p_j);
    /// `halfz`: GL_ZERO_TO_ONE's near plane `z ≥ 0` instead of `z ≥ −w`.
    pub fn new(m: &[f32; 16], halfz: bool) -> Self {
        let row = |r: usize| [0, 1, 2, 3].map(|j| f64::from(m[4 * j + r]));
        let (x, y, z, w) = (row(0), row(1), row(2), row(3));
        let sub = |a: [f64; 4], b: [f64; 4]| [0, 1, 2, 3].map(|j| a[j] - b[j]);
        let neg_sum = |a: [f64; 4], b: [f64; 4]| [0, 1, 2, 3].map(|j| -(a[j] + b[j]));
        let near = if halfz { z.map(|c| -c) } else { neg_sum(z, w) };
        let mut scale = [0.0; 4];
        for r in [x, y, z, w] {
            for j in 0..4 {
                scale[j] += r[j].abs();
            }
        }
        ClipPlanes {
            // Bits 0, 2, 5: x, y, z above w; bits 1, 3, 4: below −w (z below 0 under halfz).
            g: [
                sub(x, w),
                neg_sum(x, w),
                sub(y, w),
                neg_sum(y, w),
                near,
                sub(z, w),
            ],
            bits: [1, 2, 4, 8, 16, 32],
            scale,
        }
    }

    /// The bits of the planes every point of `b` lies outside of, by the margin the module
    /// describes (0 when it crosses or lies inside them all).
    pub fn outside(&self, b: &PosBox) -> ClipMask {
        let (c, e) = (b.center, b.extent);
        let mut size = self.scale[3];
        for j in 0..3 {
            size += self.scale[j] * (c[j].abs() + e[j]);
        }
        let margin = 1e-5 * size;
        let mut mask = 0;
        for (g, &bit) in self.g.iter().zip(&self.bits) {
            let centre = g[0] * c[0] + g[1] * c[1] + g[2] * c[2] + g[3];
            let reach = g[0].abs() * e[0] + g[1].abs() * e[1] + g[2].abs() * e[2];
            if centre - reach > margin {
                mask |= bit;
            }
        }
        mask
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::clip_mask;
    use crate::test_rng::xorshift32;

    /// A uniform value in `lo..hi` from `next`.
    fn range(next: &mut impl FnMut() -> u32, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * (next() as f32 / u32::MAX as f32)
    }

    /// `m · p` as the vertex stage rounds it (column by column, f32).
    fn transform(m: &[f32; 16], p: [f32; 4]) -> [f32; 4] {
        let mut c = [0f32; 4];
        for (r, out) in c.iter_mut().enumerate() {
            *out = ((p[0] * m[r] + p[1] * m[4 + r]) + p[2] * m[8 + r]) + p[3] * m[12 + r];
        }
        c
    }

    #[test]
    fn a_box_gets_only_bits_every_position_in_it_has() {
        let mut rng = xorshift32(7);
        let mut boxed = 0;
        for round in 0..400 {
            let mut m = [0f32; 16];
            for v in &mut m {
                *v = range(&mut rng, -2.0, 2.0);
            }
            m[15] = range(&mut rng, 0.5, 3.0);
            let halfz = round % 2 == 0;
            let planes = ClipPlanes::new(&m, halfz);
            let centre = [0; 3].map(|_| range(&mut rng, -6.0, 6.0));
            let size = range(&mut rng, 0.001, 2.0);
            let pos: Vec<[f32; 4]> = (0..BOX_VERTS)
                .map(|_| {
                    let p = centre.map(|c| c + range(&mut rng, -size, size));
                    [p[0], p[1], p[2], 1.0]
                })
                .collect();
            let b = boxes_of(&pos)[0].expect("finite positions with w = 1");
            let bits = planes.outside(&b);
            boxed += usize::from(bits != 0);
            for &p in &pos {
                let exact = clip_mask(transform(&m, p), halfz);
                assert_eq!(
                    exact & bits,
                    bits,
                    "round {round}: {p:?} {exact:#x} {bits:#x}"
                );
            }
        }
        // The test must judge some boxes outside, or it checks nothing.
        assert!(boxed > 50, "{boxed}");
    }

    #[test]
    fn a_box_outside_the_right_plane_by_far_gets_that_bit_and_one_across_gets_none() {
        let planes = ClipPlanes::new(
            &[
                1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0,
            ],
            false,
        );
        let far = PosBox {
            center: [5.0, 0.0, 0.0],
            extent: [1.0, 0.5, 0.5],
        };
        assert_eq!(planes.outside(&far), 1);
        let across = PosBox {
            center: [1.0, 0.0, 0.0],
            extent: [0.5, 0.5, 0.5],
        };
        assert_eq!(planes.outside(&across), 0);
        let corner = PosBox {
            center: [5.0, -5.0, 5.0],
            extent: [0.1, 0.1, 0.1],
        };
        assert_eq!(planes.outside(&corner), 1 | 8 | 32);
    }

    #[test]
    fn runs_with_other_w_or_non_finite_positions_get_no_box() {
        let mut pos = vec![[0.5f32, 0.5, 0.5, 1.0]; BOX_VERTS * 3 + 5];
        pos[3][3] = 2.0;
        pos[BOX_VERTS + 1][0] = f32::NAN;
        let b = boxes_of(&pos);
        assert_eq!(b.len(), 4);
        assert!(b[0].is_none() && b[1].is_none());
        assert_eq!(
            b[2],
            Some(PosBox {
                center: [0.5; 3],
                extent: [0.0; 3]
            })
        );
        assert!(b[3].is_some());
    }
}
