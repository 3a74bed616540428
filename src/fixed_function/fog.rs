//! Fog as llvmpipe computes it (docs/llvmpipe-rules.md §11).
//!
//! Vertex side (`ffvertex_prog.c`, `build_fog`): the fog coordinate is `|z_eye|`
//! (GL_FRAGMENT_DEPTH; Mesa's default distance mode EYE_PLANE_ABSOLUTE) or `|fog coord|`
//! (GL_FOG_COORD). `z_eye` is the eye position's z when the lighting already computed the
//! eye position, otherwise a separate DP4 with the modelview's third row, summed from the
//! highest component down. The coordinate is then interpolated perspective-correctly.
//!
//! Fragment side (`ff_fragment_shader.cpp`, `emit_fog_instructions`), all f32 and unfused:
//! - LINEAR: `f = c·s + b` with `s = -1/(end-start)` (1 when end == start), `b = end·-s`.
//! - EXP: `f = exp2(-(c·k))`, `k = f32(density·log2 e)` computed in double.
//! - EXP2: `t = c·k2`, `f = exp2(-(t·t))`, `k2 = f32(density/sqrt(ln 2))` in double.
//! - `f` is saturated (NaN → 0); rgb = `fog·(1-f) + colour·f` (two products, then the
//!   sum); alpha is kept. `exp2` is gallivm's polynomial ([`super::gallivm_math::exp2`]),
//!   whose multiply-adds fuse on FMA hosts.

use super::gallivm_math::exp2;
use super::matrix::Mat4;
use crate::pipe::{FogMode, FogState};

/// `ONE_DIV_SQRT_LN2` of `prog_statevars.c` (Mesa's digits).
#[allow(clippy::excessive_precision)]
const ONE_DIV_SQRT_LN2: f64 = 1.201122408786449815;

/// Per-draw fog constants (STATE_FOG_PARAMS_OPTIMIZED and the clamped colour).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FogPlan {
    /// GL_FOG_MODE.
    pub mode: FogMode,
    /// LINEAR scale `-1/(end-start)`.
    pub scale: f32,
    /// LINEAR bias `end/(end-start)`.
    pub bias: f32,
    /// EXP constant `density/ln 2`.
    pub exp_k: f32,
    /// EXP2 constant `density/sqrt(ln 2)`.
    pub exp2_k: f32,
    /// The fog colour (clamped rgb).
    pub color: [f32; 3],
    /// Whether gallivm's multiply-adds fuse on this host.
    pub fma: bool,
}

impl FogPlan {
    /// The constants for `fog`.
    pub fn new(fog: &FogState, fma: bool) -> FogPlan {
        let scale = if fog.end == fog.start {
            1.0
        } else {
            -1.0 / (fog.end - fog.start)
        };
        FogPlan {
            mode: fog.mode,
            scale,
            bias: fog.end * -scale,
            exp_k: (fog.density as f64 * std::f64::consts::LOG2_E) as f32,
            exp2_k: (fog.density as f64 * ONE_DIV_SQRT_LN2) as f32,
            color: [fog.color[0], fog.color[1], fog.color[2]],
            fma,
        }
    }

    /// The saturated fog factor for an interpolated fog coordinate.
    #[inline(always)]
    pub fn factor(&self, coord: f32) -> f32 {
        let f = match self.mode {
            FogMode::Linear => coord * self.scale + self.bias,
            FogMode::Exp => exp2(-(coord * self.exp_k), self.fma),
            FogMode::Exp2 => {
                let t = coord * self.exp2_k;
                exp2(-(t * t), self.fma)
            }
        };
        // fsat: lp_build_clamp_zero_one_nanzero.
        if f > 0.0 {
            f.min(1.0)
        } else {
            0.0
        }
    }

    /// [`FogPlan::factor`] of eight fog coordinates, lane by lane the same bits, when this
    /// plan's multiply-adds fuse exactly when the caller's copy does (`self.fma == FMA`);
    /// `None` otherwise (the caller then takes [`FogPlan::factor`] per lane).
    ///
    /// # Safety
    /// The CPU has AVX2, and FMA when `FMA`.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    pub unsafe fn factor8<const FMA: bool>(
        &self,
        coord: crate::simd::F32x8,
    ) -> Option<crate::simd::F32x8> {
        use super::gallivm_lanes::{exp2, s, si};
        if self.fma != FMA {
            return None;
        }
        // SAFETY: (whole body) the caller's AVX2 (+FMA) context.
        unsafe {
            // The exponent as the scalar code has it, then `-x` as the scalar negation:
            // the sign bit flipped, NaN included (no closure: it would lose the target
            // features).
            let x = match self.mode {
                FogMode::Linear => coord.mul(s(self.scale)).add(s(self.bias)),
                FogMode::Exp => coord.mul(s(self.exp_k)),
                FogMode::Exp2 => {
                    let t = coord.mul(s(self.exp2_k));
                    t.mul(t)
                }
            };
            let f = if self.mode == FogMode::Linear {
                x
            } else {
                exp2::<FMA>(x.bits().xor(si(i32::MIN)).as_f32())
            };
            // fsat as `factor`: 0 unless f > 0 (NaN fails the compare), then min(f, 1).
            let zero = crate::simd::F32x8::zero();
            Some(zero.blendv(f.min(s(1.0)), f.cmp_gt(zero)))
        }
    }

    /// Blends `color` towards the fog colour with factor `f` (alpha unchanged).
    #[inline]
    pub fn apply(&self, color: [f32; 4], f: f32) -> [f32; 4] {
        let g = 1.0 - f;
        let mut out = color;
        for i in 0..3 {
            out[i] = self.color[i] * g + color[i] * f;
        }
        out
    }
}

/// `z_eye` by the DP4 the program uses when it has no eye position: modelview row 2
/// dotted with the object position, summed from the highest component down.
pub fn eye_z_dp4(mv: &Mat4, pos: [f32; 4]) -> f32 {
    let m = &mv.0;
    ((pos[3] * m[14] + pos[2] * m[10]) + pos[1] * m[6]) + pos[0] * m[2]
}

/// The per-vertex fog coordinate. `eye_pos` is the lighting's eye position when
/// [`super::lighting::LightPlan::needs_eye_position`] (Mesa then reuses its z), else
/// `None`; `fog_attr` is the vertex's GL_FOG_COORD value.
pub fn vertex_fog_coord(
    fog: &FogState,
    mv: &Mat4,
    obj_pos: [f32; 4],
    eye_pos: Option<[f32; 4]>,
    fog_attr: f32,
) -> f32 {
    if fog.coord_from_attrib {
        return fog_attr.abs();
    }
    match eye_pos {
        Some(e) => e[2].abs(),
        None => eye_z_dp4(mv, obj_pos).abs(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_and_exp_factors() {
        let fog = FogState {
            mode: FogMode::Linear,
            start: 1.0,
            end: 5.0,
            ..FogState::default()
        };
        let p = FogPlan::new(&fog, false);
        assert_eq!(p.factor(1.0), 1.0);
        assert_eq!(p.factor(5.0), 0.0);
        assert_eq!(p.factor(3.0), 3.0 * -0.25 + 1.25);
        assert_eq!(p.factor(100.0), 0.0);
        assert_eq!(p.factor(-100.0), 1.0);
        assert_eq!(p.factor(f32::NAN), 0.0);

        let exp = FogPlan::new(&FogState::default(), true);
        assert_eq!(exp.factor(0.0), 1.0);
        assert!((exp.factor(1.0) - (-1.0f32).exp()).abs() < 1e-6);
        let exp2 = FogPlan::new(
            &FogState {
                mode: FogMode::Exp2,
                density: 0.5,
                ..FogState::default()
            },
            false,
        );
        assert!((exp2.factor(2.0) - (-1.0f32).exp()).abs() < 1e-6);

        let c = exp.apply([1.0, 0.5, 0.0, 0.3], 0.25);
        assert_eq!(c, [0.25, 0.125, 0.0, 0.3]);
    }

    /// `factor8` of `c` in a copy compiled with AVX2 and FMA.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,fma")]
    unsafe fn factor8_fma(p: &FogPlan, c: &[f32; 8]) -> Option<[f32; 8]> {
        // SAFETY: the caller checked AVX2 and FMA; `c` holds 8 f32.
        unsafe { p.factor8::<true>(crate::simd::F32x8::load(c.as_ptr())) }.map(|v| v.to_array())
    }

    /// `factor8` of `c` in a copy compiled with AVX2 only.
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2")]
    unsafe fn factor8_avx2(p: &FogPlan, c: &[f32; 8]) -> Option<[f32; 8]> {
        // SAFETY: the caller checked AVX2; `c` holds 8 f32.
        unsafe { p.factor8::<false>(crate::simd::F32x8::load(c.as_ptr())) }.map(|v| v.to_array())
    }

    #[cfg(target_arch = "x86_64")]
    #[test]
    fn factor8_is_factor_lane_by_lane() {
        if !is_x86_feature_detected!("avx2") {
            return;
        }
        let fma_cpu = is_x86_feature_detected!("fma");
        // Edge values, then a sweep across the polynomial's fractions and the clamps.
        let mut coords = vec![
            0.0,
            -0.0,
            1e-30,
            -1e-30,
            f32::MIN_POSITIVE / 4.0,
            0.5,
            1.0,
            7.99,
            -3.0,
            1e10,
            -1e10,
            f32::MAX,
            f32::NAN,
            -f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
        ];
        coords.extend((0..4000).map(|i| (i as f32 - 500.0) * 0.0371));
        while coords.len() % 8 != 0 {
            coords.push(2.0);
        }
        let mut checked = 0;
        for mode in [FogMode::Linear, FogMode::Exp, FogMode::Exp2] {
            for (density, start, end) in [(0.06, 1.0, 5.0), (1.7, -2.0, 30.0), (0.0, 3.0, 3.0)] {
                let state = FogState {
                    mode,
                    density,
                    start,
                    end,
                    ..FogState::default()
                };
                for fma in [false, true] {
                    let p = FogPlan::new(&state, fma);
                    for c in coords.chunks_exact(8) {
                        let c: &[f32; 8] = c.try_into().unwrap();
                        // SAFETY: AVX2 checked above.
                        let plain = unsafe { factor8_avx2(&p, c) };
                        assert_eq!(plain.is_some(), !fma);
                        // SAFETY: AVX2 and FMA checked.
                        let fused = fma_cpu.then(|| unsafe { factor8_fma(&p, c) });
                        if fma_cpu {
                            assert_eq!(fused.unwrap().is_some(), fma);
                        }
                        let Some(got) = plain.or(fused.flatten()) else {
                            continue;
                        };
                        for (g, x) in got.iter().zip(c) {
                            let want = p.factor(*x);
                            assert_eq!(g.to_bits(), want.to_bits(), "{mode:?} fma {fma} at {x}");
                            checked += 1;
                        }
                    }
                }
            }
        }
        assert!(checked >= 9 * coords.len());
    }

    #[test]
    fn fog_coordinate_sources() {
        let mv = crate::fixed_function::matrix::IDENTITY;
        let fog = FogState::default();
        assert_eq!(
            vertex_fog_coord(&fog, &mv, [1.0, 2.0, -3.0, 1.0], None, 9.0),
            3.0
        );
        let f2 = FogState {
            coord_from_attrib: true,
            ..fog
        };
        assert_eq!(
            vertex_fog_coord(&f2, &mv, [1.0, 2.0, -3.0, 1.0], None, -9.0),
            9.0
        );
    }
}
