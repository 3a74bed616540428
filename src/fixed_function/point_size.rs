//! Point-size attenuation (GL_POINT_DISTANCE_ATTENUATION), as llvmpipe runs Mesa's
//! generated vertex program (`ffvertex_prog.c`, `build_atten_pointsize`) in f32:
//!
//! - `d = |z_eye|` (the eye z, not the Euclidean distance). `z_eye` is the eye position's
//!   z when the program already computed the eye position (lighting or eye-space texgen),
//!   else the modelview-row-2 DP4 that fog uses too ([`super::fog::eye_z_dp4`]).
//! - `f = d·(d·c + b) + a`, each MAD a multiply then an add (never fused).
//! - `size = min(max(rsq(f)·point_size, lo), hi)` with `rsq(x) = 1/sqrt(|x|)`, `lo` =
//!   max(GL_POINT_SIZE_MIN, 1) and `hi` = min(GL_POINT_SIZE_MAX, 255) (Mesa's
//!   STATE_POINT_SIZE_CLAMPED: llvmpipe's implementation limits are 1 and 255).
//!
//! The per-vertex size then reaches llvmpipe's legacy point rasterizer (docs/llvmpipe-rules.md
//! §15), which caps it at 255 and rounds it to a whole width. Mesa's gallium path never
//! reads GL_POINT_FADE_THRESHOLD_SIZE, so thin points do not fade.

use super::gallivm_math::rsq;
use crate::pipe::{PointState, MAX_POINT_SIZE};

/// llvmpipe's smallest point size (PIPE_CAPF_MIN_POINT_SIZE and its AA twin).
const MIN_IMPL_POINT_SIZE: f32 = 1.0;

/// The per-draw constants of the attenuation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointAtten {
    /// glPointSize, unclamped.
    pub size: f32,
    /// The lower clamp.
    pub lo: f32,
    /// The upper clamp.
    pub hi: f32,
    /// Constant, linear and quadratic coefficients.
    pub abc: [f32; 3],
}

impl PointAtten {
    /// The constants for `p`, or `None` when the size is not attenuated.
    pub fn new(p: &PointState) -> Option<PointAtten> {
        p.attenuated().then_some(PointAtten {
            size: p.size,
            // Mesa's `a >= b ? a : b` and `a <= b ? a : b` (a NaN parameter loses).
            lo: if p.min_size >= MIN_IMPL_POINT_SIZE {
                p.min_size
            } else {
                MIN_IMPL_POINT_SIZE
            },
            hi: if p.max_size <= MAX_POINT_SIZE {
                p.max_size
            } else {
                MAX_POINT_SIZE
            },
            abc: p.attenuation,
        })
    }

    /// The size of a vertex whose eye-space z is `z_eye`.
    #[inline]
    pub fn size(&self, z_eye: f32) -> f32 {
        let [a, b, c] = self.abc;
        let d = z_eye.abs();
        let f = d * c + b;
        let f = d * f + a;
        (rsq(f) * self.size).max(self.lo).min(self.hi)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn attenuation_follows_the_distance_and_clamps() {
        let mut p = PointState {
            size: 10.0,
            ..PointState::default()
        };
        assert_eq!(PointAtten::new(&p), None);
        p.attenuation = [0.0, 0.0, 1.0];
        let a = PointAtten::new(&p).unwrap();
        // size / sqrt(d²) = size / d
        assert_eq!(a.size(-2.0), 5.0);
        assert_eq!(a.size(4.0), 2.5);
        // below the implementation minimum and above the user maximum
        assert_eq!(a.size(-100.0), 1.0);
        p.max_size = 3.0;
        assert_eq!(PointAtten::new(&p).unwrap().size(-1.0), 3.0);
        // f = 0 gives an infinite factor, clamped to the maximum
        assert_eq!(PointAtten::new(&p).unwrap().size(0.0), 3.0);
        p.max_size = 1000.0;
        assert_eq!(PointAtten::new(&p).unwrap().hi, MAX_POINT_SIZE);
    }
}
