//! Level of detail, one per 2x2 quad, as llvmpipe computes it (`lp_build_lod_selector`,
//! `lp_build_rho`, `lp_build_fast_log2`; docs/llvmpipe-rules.md §9.3).
//!
//! - Derivatives: `ddx = TR − TL`, `ddy = BL − TL` (y-down quad).
//! - 2D: `rho² = max((W·dsdx)² + (H·dtdx)², (W·dsdy)² + (H·dtdy)²)` (f32, no fusing).
//!   1D: `rho = max(|dsdx|, |dsdy|)·W` (not squared: llvmpipe only squares for dims > 1).
//! - Fast path (no bias, no min/max LOD clamp, mip filter NONE or NEAREST):
//!   `ipart = (exponent(rho²) + 1) >> 1` (1D: `exponent(rho·√2)`), minified iff rho > 1.
//! - General path: `lod = 0.5·fast_log2(rho²)` with the piecewise-linear
//!   `fast_log2(x) = exponent + (mantissa − 1)`, plus the quantised bias, then
//!   `min(max_lod)`, `max(min_lod)` where they apply; minified iff lod > 0; NEAREST takes
//!   `round_half_even(lod)`, LINEAR `floor(lod)` and `lod − floor(lod)`.
//! - GL's MIN_LOD = MAX_LOD (after Mesa's `max(min_lod, 0)` and swap) forces lod = min_lod.

use super::{MipFilter, SamplerParams, MAX_LOD_BIAS};

/// The per-quad LOD result that sampling needs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lod {
    /// Minification (lod > 0, or rho > 1 on the fast path).
    pub positive: bool,
    /// Integer part relative to the base level (rounded for NEAREST, floor for LINEAR).
    pub ipart: i32,
    /// Fraction for LINEAR mip filtering (0 otherwise).
    pub fpart: f32,
}

impl Lod {
    /// Magnification at the base level.
    pub const MAG: Lod = Lod {
        positive: false,
        ipart: 0,
        fpart: 0.0,
    };

    /// A LOD from a float value, as the general path turns it into level parts.
    #[inline(always)]
    pub fn from_value(lod: f32, mip: MipFilter) -> Lod {
        let positive = lod > 0.0;
        match mip {
            MipFilter::Linear => {
                let f = lod.floor();
                Lod {
                    positive,
                    ipart: f as i32,
                    fpart: lod - f,
                }
            }
            _ => Lod {
                positive,
                ipart: lod.round_ties_even() as i32,
                fpart: 0.0,
            },
        }
    }
}

/// The sampler's LOD adjustments, converted as Mesa's state tracker and llvmpipe's static
/// sampler state do.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LodParams {
    /// Texture bias plus unit bias, each clamped to ±16 and quantised to 1/256 on its
    /// own (the sum is neither clamped nor re-quantised).
    pub bias: f32,
    /// gallium min_lod (`max(GL min_lod, 0)`, swapped with max_lod if greater).
    pub min_lod: f32,
    /// gallium max_lod.
    pub max_lod: f32,
    /// llvmpipe applies min_lod (min_lod > 0).
    pub apply_min: bool,
    /// llvmpipe applies max_lod (max_lod < 15).
    pub apply_max: bool,
    /// min_lod == max_lod: the LOD is the constant min_lod.
    pub min_max_equal: bool,
}

/// `util_quantize_lod_bias`: clamp to ±16, round to 1/256.
pub fn quantize_bias(b: f32) -> f32 {
    let b = if b.is_nan() {
        0.0
    } else {
        b.clamp(-MAX_LOD_BIAS, MAX_LOD_BIAS)
    };
    (b * 256.0).round() / 256.0
}

impl LodParams {
    /// From the texture's parameters and the unit's bias. `one_d` is unused by the
    /// parameters themselves but kept for symmetry with the sampler key.
    ///
    /// Mesa quantises each bias when it is set (`glTexParameter` stores
    /// `util_quantize_lod_bias(b)` in the texture's sampler state, `glTexEnv` of
    /// GL_TEXTURE_FILTER_CONTROL in `texUnit->LodBiasQuantized`); `st_convert_sampler`
    /// then adds the two (`sampler->lod_bias += tex_unit_lod_bias`) and llvmpipe copies
    /// the sum into its jit sampler unchanged, so |bias| can reach 32.
    pub fn new(p: &SamplerParams, unit_bias: f32, _one_d: bool) -> LodParams {
        let bias = quantize_bias(p.lod_bias) + quantize_bias(unit_bias);
        let mut min_lod = p.min_lod.max(0.0);
        let mut max_lod = p.max_lod;
        if max_lod < min_lod {
            std::mem::swap(&mut min_lod, &mut max_lod);
        }
        let lod_used = p.mip_filter != MipFilter::None || p.min_filter != p.mag_filter;
        let min_max_equal = lod_used && min_lod == max_lod;
        LodParams {
            bias,
            min_lod,
            max_lod,
            apply_min: lod_used && !min_max_equal && min_lod > 0.0,
            apply_max: lod_used && !min_max_equal && max_lod < 15.0,
            min_max_equal,
        }
    }
}

impl LodParams {
    /// The general path's LOD `v` after the sampler's adjustments, in
    /// `lp_build_lod_selector`'s order: the bias, then `max_lod`, then `min_lod` (a NaN
    /// gives way to each clamp, as `minps(lod, max)` and `maxps(lod, min)` do).
    #[inline(always)]
    pub fn adjust(&self, v: f32) -> f32 {
        let mut v = v;
        if self.bias != 0.0 {
            v += self.bias;
        }
        if self.apply_max {
            v = v.min(self.max_lod);
        }
        if self.apply_min {
            v = v.max(self.min_lod);
        }
        v
    }
}

/// `lp_build_fast_log2`: exponent plus the linear mantissa fraction.
#[inline(always)]
pub fn fast_log2(x: f32) -> f32 {
    let bits = x.to_bits();
    let e = ((bits >> 23) & 0xff) as i32 - 127;
    let m = f32::from_bits((bits & 0x007f_ffff) | 0x3f80_0000);
    (e - 1) as f32 + m
}

/// The unbiased float exponent (`lp_build_extract_exponent`).
#[inline(always)]
fn exponent(x: f32) -> i32 {
    ((x.to_bits() >> 23) & 0xff) as i32 - 127
}

/// rho (1D) or rho² (2D) of a quad, NaN/Inf → 0.
#[inline(always)]
pub fn rho(dims: u8, w: f32, h: f32, s: [f32; 4], t: [f32; 4]) -> f32 {
    let dsdx = s[1] - s[0];
    let dsdy = s[2] - s[0];
    let r = if dims == 1 {
        dsdx.abs().max(dsdy.abs()) * w
    } else {
        let dtdx = t[1] - t[0];
        let dtdy = t[2] - t[0];
        let (a, b) = (dsdx * w, dtdx * h);
        let (c, d) = (dsdy * w, dtdy * h);
        let rx = a * a + b * b;
        let ry = c * c + d * d;
        rx.max(ry)
    };
    if r.is_finite() {
        r
    } else {
        0.0
    }
}

/// The LOD of a quad (`s`, `t` in TL, TR, BL, BR order); `w`, `h` the base level size.
#[inline(always)]
pub fn compute(
    p: &LodParams,
    mip: MipFilter,
    dims: u8,
    w: f32,
    h: f32,
    s: [f32; 4],
    t: [f32; 4],
) -> Lod {
    if p.min_max_equal {
        return Lod::from_value(p.min_lod, mip);
    }
    from_rho(p, mip, dims > 1, rho(dims, w, h, s, t))
}

/// The LOD from a quad's rho (`squared`: rho², as llvmpipe keeps it for dims > 1), for
/// callers that compute rho themselves (3D textures, cube maps).
#[inline(always)]
pub fn from_rho(p: &LodParams, mip: MipFilter, squared: bool, r: f32) -> Lod {
    if p.min_max_equal {
        return Lod::from_value(p.min_lod, mip);
    }
    let r = if r.is_finite() { r } else { 0.0 };
    let fast = p.bias == 0.0 && !p.apply_min && !p.apply_max;
    if fast && mip != MipFilter::Linear {
        let ipart = if squared {
            (exponent(r) + 1) >> 1
        } else {
            exponent(r * std::f32::consts::SQRT_2)
        };
        return Lod {
            positive: r > 1.0,
            ipart,
            fpart: 0.0,
        };
    }
    let r2 = if squared { r } else { r * r };
    Lod::from_value(p.adjust(fast_log2(r2) * 0.5), mip)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn quad_lod(rho: f32, mip: MipFilter) -> Lod {
        let p = LodParams::new(
            &SamplerParams {
                mip_filter: mip,
                ..Default::default()
            },
            0.0,
            false,
        );
        // a 1-texel texture with ds/dx = rho: rho² = rho·rho
        compute(&p, mip, 2, 1.0, 1.0, [0.0, rho, 0.0, rho], [0.0; 4])
    }

    #[test]
    fn nearest_mip_thresholds() {
        assert_eq!(quad_lod(1.41, MipFilter::Nearest).ipart, 0);
        assert_eq!(quad_lod(1.42, MipFilter::Nearest).ipart, 1);
        assert_eq!(quad_lod(2.80, MipFilter::Nearest).ipart, 1);
        assert_eq!(quad_lod(2.84, MipFilter::Nearest).ipart, 2);
        assert_eq!(quad_lod(5.0, MipFilter::Nearest).ipart, 2);
        assert_eq!(quad_lod(6.0, MipFilter::Nearest).ipart, 3);
        assert!(!quad_lod(1.0, MipFilter::Nearest).positive);
        assert!(quad_lod(1.0001, MipFilter::Nearest).positive);
    }

    #[test]
    fn piecewise_linear_log2() {
        // rho = 1.2: rho² = 1.44 → fast_log2 = 0.44 → lod 0.22 (a true log2 gives 0.263)
        let l = quad_lod(1.2, MipFilter::Linear);
        assert_eq!(l.ipart, 0);
        assert!((l.fpart - 0.22).abs() < 1e-6, "{}", l.fpart);
        // the AoS blend weight: trunc(0.22·256) = 56 (a true log2 gives 67)
        assert_eq!((l.fpart * 256.0) as i32, 56);
        assert_eq!(fast_log2(8.0), 3.0);
        assert_eq!(fast_log2(1.5), 0.5);
    }

    #[test]
    fn bias_is_quantised_and_clamped() {
        assert_eq!(quantize_bias(0.3), 77.0 / 256.0);
        assert_eq!(quantize_bias(100.0), 16.0);
        assert_eq!(quantize_bias(-100.0), -16.0);
    }

    #[test]
    fn texture_and_unit_bias_quantised_separately() {
        let sp = SamplerParams {
            mip_filter: MipFilter::Linear,
            lod_bias: -0.9,
            ..Default::default()
        };
        // −0.9 → −230/256, 0.6 → 154/256: −76/256 (the sum −0.3 would give −77/256)
        assert_eq!(LodParams::new(&sp, 0.6, false).bias, -76.0 / 256.0);
        // each is clamped to ±16 on its own, the sum is not
        let sp = SamplerParams {
            lod_bias: 100.0,
            ..sp
        };
        assert_eq!(LodParams::new(&sp, 20.0, false).bias, 32.0);
    }

    #[test]
    fn min_max_lod_clamps() {
        let sp = SamplerParams {
            mip_filter: MipFilter::Linear,
            min_lod: 1.5,
            max_lod: 2.25,
            ..Default::default()
        };
        let p = LodParams::new(&sp, 0.0, false);
        assert!(p.apply_min && p.apply_max);
        let at_width = |w: f32| {
            compute(
                &p,
                MipFilter::Linear,
                2,
                w,
                1.0,
                [0.0, 1.0, 0.0, 0.0],
                [0.0; 4],
            )
        };
        let l = at_width(1.0);
        assert_eq!((l.ipart, l.fpart, l.positive), (1, 0.5, true));
        let l = at_width(64.0);
        assert_eq!((l.ipart, l.fpart), (2, 0.25));
        // default −1000/1000: no clamp applies
        let d = LodParams::new(&SamplerParams::default(), 0.0, false);
        assert!(!d.apply_min && !d.apply_max && !d.min_max_equal);
    }

    #[test]
    fn one_d_fast_path_rounds_log2() {
        let p = LodParams::new(&SamplerParams::default(), 0.0, true);
        let l = |r: f32| {
            compute(
                &p,
                MipFilter::Nearest,
                1,
                1.0,
                1.0,
                [0.0, r, 0.0, 0.0],
                [0.0; 4],
            )
        };
        assert_eq!(l(1.41).ipart, 0);
        assert_eq!(l(1.42).ipart, 1);
        assert_eq!(l(2.82).ipart, 1);
        assert_eq!(l(2.84).ipart, 2);
    }
}
