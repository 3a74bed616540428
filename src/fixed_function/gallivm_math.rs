//! gallivm's transcendental approximations, bit for bit: `lp_build_exp2`,
//! `lp_build_log2_safe` and `lp_build_pow` of Mesa 22.3's `gallivm/lp_bld_arit.c`.
//!
//! llvmpipe evaluates `pow` (specular exponent, spot exponent) and `exp2` (EXP/EXP2 fog)
//! with minimax polynomials, not libm:
//!
//! - `exp2(x)`: x is clamped to [-126.99999, 128], split into `floor(x)` (placed directly
//!   in the exponent bits) and `fract` (a degree-5 polynomial, `EXP_POLY_DEGREE`).
//! - `log2(x)`: the exponent bits give `floor(log2 x)`; the mantissa `m` in [1,2) gives
//!   `y = (m-1)/(m+1)` and `log2 m = y·P(y²)` with a degree-4 polynomial
//!   (`LOG_POLY_DEGREE`). The "safe" variant maps 0 to -inf, +inf to +inf, negatives to NaN.
//! - `pow(x, y) = exp2(log2_safe(x)·y)`, with `pow(±0, y) = 0` forced.
//!
//! Polynomials are evaluated as `lp_build_polynomial` does: odd and even coefficients in
//! two Horner chains in `x²`, joined by `odd·x + even`. Each step is `lp_build_mad`, i.e.
//! `llvm.fmuladd`, which LLVM fuses on CPUs with FMA; pass `fma = true` there. Plain
//! multiplies, adds and the division are IEEE f32. Coefficients are the double constants
//! of the source rounded to f32, as `lp_build_const_vec` does.
//!
//! Measured against libm (tests): exp2 within 2.5e-7 relative on [-8, 8], log2 within 4.1e-7
//! absolute on [0.001, 10], pow within 4.6e-6 relative; what matters is matching llvmpipe.

/// `lp_build_exp2_polynomial` (EXP_POLY_DEGREE 5): 2^x on [0, 1). Mesa's digits, verbatim.
#[allow(clippy::excessive_precision)]
pub(crate) const EXP2_POLY: [f64; 6] = [
    1.000000000000000000000,
    0.693153073200168932794,
    0.240153617044375388211,
    0.0558263180532956664775,
    0.00898934009049466391101,
    0.00187757667519147912699,
];

/// `lp_build_log2_polynomial` (LOG_POLY_DEGREE 4). Mesa's digits, verbatim.
#[allow(clippy::excessive_precision)]
pub(crate) const LOG2_POLY: [f64; 5] = [
    2.88539009343309178325,
    0.961791550404184197881,
    0.577440339438736392009,
    0.403343858251329912514,
    0.406718052498846252698,
];

/// `lp_build_mad`: `llvm.fmuladd`, fused when the host has FMA.
#[inline(always)]
pub fn mad(a: f32, b: f32, c: f32, fma: bool) -> f32 {
    if fma {
        a.mul_add(b, c)
    } else {
        a * b + c
    }
}

/// `lp_build_polynomial`: `coeffs[0] + x·coeffs[1] + x²·coeffs[2] + …` in gallivm's order.
#[inline(always)]
pub fn polynomial(x: f32, coeffs: &[f64], fma: bool) -> f32 {
    let x2 = x * x;
    let mut even: Option<f32> = None;
    let mut odd: Option<f32> = None;
    for i in (0..coeffs.len()).rev() {
        let c = coeffs[i] as f32;
        if i % 2 == 0 {
            even = Some(match even {
                Some(e) => mad(x2, e, c, fma),
                None => c,
            });
        } else {
            odd = Some(match odd {
                Some(o) => mad(x2, o, c, fma),
                None => c,
            });
        }
    }
    match (odd, even) {
        (Some(o), Some(e)) => mad(o, x, e, fma),
        (None, Some(e)) => e,
        _ => f32::NAN,
    }
}

/// `lp_build_exp2` for f32.
#[inline(always)]
pub fn exp2(x: f32, fma: bool) -> f32 {
    // min/max that keep NaN (GALLIVM_NAN_RETURN_NAN_FIRST_NONNAN).
    let x = if x.is_nan() {
        x
    } else {
        x.clamp(-126.99999, 128.0)
    };
    // lp_build_ifloor_fract with SSE4.1 rounding: floor, then subtract, then fptosi.
    let ip = x.floor();
    let fpart = x - ip;
    let ipart = if ip.is_nan() { i32::MIN } else { ip as i32 };
    let expipart = f32::from_bits((ipart.wrapping_add(127) as u32).wrapping_shl(23));
    let expfpart = polynomial(fpart, &EXP2_POLY, fma);
    expipart * expfpart
}

/// `lp_build_log2_approx` without edge-case handling (`lp_build_log2`).
#[inline(always)]
pub fn log2_approx(x: f32, fma: bool) -> f32 {
    let i = x.to_bits();
    let exp = i & 0x7f80_0000;
    let logexp = ((exp >> 23) as i32 - 127) as f32;
    let mant = f32::from_bits((i & 0x007f_ffff) | 1.0f32.to_bits());
    let y = (mant - 1.0) / (mant + 1.0);
    let z = y * y;
    let p_z = polynomial(z, &LOG2_POLY, fma);
    mad(y, p_z, logexp, fma)
}

/// `lp_build_log2_safe`: as [`log2_approx`], then +inf for x ≥ +inf, -inf for x == ±0 and
/// NaN for x < 0 (a NaN input is not caught, exactly as in gallivm).
#[inline(always)]
pub fn log2_safe(x: f32, fma: bool) -> f32 {
    let mut r = log2_approx(x, fma);
    if x >= f32::INFINITY {
        r = f32::INFINITY;
    }
    if x == 0.0 {
        r = f32::NEG_INFINITY;
    }
    if x < 0.0 {
        r = f32::NAN;
    }
    r
}

/// `lp_build_pow`: `exp2(log2_safe(x)·y)`, and 0 when `x == 0`.
#[inline(always)]
pub fn pow(x: f32, y: f32, fma: bool) -> f32 {
    if x == 0.0 {
        return 0.0;
    }
    exp2(log2_safe(x, fma) * y, fma)
}

/// `lp_build_sin_or_cos` (cephes' `sin_ps`/`cos_ps` as gallivm builds them): `|x|·4/π`
/// truncated and rounded up to even selects the octant; the argument is reduced in three
/// `fmuladd` steps (the "extended precision modular arithmetic"); a degree-3 polynomial in
/// `z = x²` for cos and one for sin, chosen by the octant; the sign from the octant (and
/// the input's sign for sin); the result clamped to [-1, 1]; NaN for ±inf and NaN.
#[allow(clippy::excessive_precision)]
#[inline(always)]
pub fn sin_or_cos(a: f32, cos: bool, fma: bool) -> f32 {
    let a_i = a.to_bits() as i32;
    let x_abs = f32::from_bits(a.to_bits() & 0x7fff_ffff);
    let scale_y = x_abs * 1.27323954473516f64 as f32;
    // LLVMBuildFPToSI: cvttps2dq on x86 (out of range → i32::MIN).
    let emm2_i = if (-2_147_483_648.0..2_147_483_648.0).contains(&scale_y) {
        scale_y as i32
    } else {
        i32::MIN
    };
    let emm2_add = emm2_i.wrapping_add(1);
    let emm2_and = emm2_add & !1;
    let y_2 = emm2_and as f32;
    let emm2_2 = if cos {
        emm2_and.wrapping_sub(2)
    } else {
        emm2_and
    };
    let sign_bit = if cos {
        ((!emm2_2) & 4) << 29
    } else {
        (a_i ^ (emm2_add << 29)) & i32::MIN
    };
    let poly_mask = emm2_2 & 2 == 0;
    let x_1 = mad(y_2, -0.78515625, x_abs, fma);
    let x_2 = mad(y_2, -2.4187564849853515625e-4, x_1, fma);
    let x_3 = mad(y_2, -3.77489497744594108e-8f64 as f32, x_2, fma);
    let z = x_3 * x_3;
    let y_4 = mad(
        z,
        2.443315711809948E-005f64 as f32,
        -1.388731625493765E-003f64 as f32,
        fma,
    );
    let y_6 = mad(y_4, z, 4.166664568298827E-002f64 as f32, fma);
    let y_8 = y_6 * z * z;
    let y_10 = (y_8 - z * 0.5) + 1.0;
    let y2_4 = mad(
        z,
        -1.9515295891E-4f64 as f32,
        8.3321608736E-3f64 as f32,
        fma,
    );
    let y2_6 = mad(y2_4, z, -1.6666654611E-1f64 as f32, fma);
    let y2_9 = mad(y2_6 * z, x_3, x_3, fma);
    let y = if poly_mask { y2_9 } else { y_10 };
    let y = f32::from_bits(y.to_bits() ^ sign_bit as u32);
    // lp_build_clamp: max then min, the second operand when either is NaN.
    let y = if y > -1.0 { y } else { -1.0 };
    let y = if y < 1.0 { y } else { 1.0 };
    if a.is_finite() {
        y
    } else {
        f32::NAN
    }
}

/// `lp_build_rsqrt` as llvmpipe builds it (`1/sqrt(x)`, two correctly rounded operations);
/// prog_to_nir's RSQ takes `|x|` first.
#[inline(always)]
pub fn rsq(x: f32) -> f32 {
    1.0 / x.abs().sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn exact_points() {
        for fma in [false, true] {
            // fract = 0 leaves only the constant coefficient 1.0 and the exponent bits.
            for k in -126..=127 {
                assert_eq!(exp2(k as f32, fma), (k as f32).exp2(), "2^{k}");
            }
            assert_eq!(exp2(128.0, fma), f32::INFINITY);
            assert_eq!(exp2(1000.0, fma), f32::INFINITY);
            assert_eq!(
                exp2(-127.0, fma),
                0.0,
                "clamped to -126.99999, then 2^-127 → 0"
            );
            assert_eq!(exp2(-1000.0, fma), 0.0);
            assert!(exp2(f32::NAN, fma).is_nan());
            // Powers of two have mantissa 1, so y = 0 and log2 is the exponent exactly.
            for k in -126..=127 {
                assert_eq!(log2_safe((k as f32).exp2(), fma), k as f32);
            }
            assert_eq!(log2_safe(0.0, fma), f32::NEG_INFINITY);
            assert_eq!(log2_safe(-0.0, fma), f32::NEG_INFINITY);
            assert_eq!(log2_safe(f32::INFINITY, fma), f32::INFINITY);
            assert!(log2_safe(-1.0, fma).is_nan());
            assert_eq!(pow(0.0, 5.0, fma), 0.0);
            assert_eq!(pow(0.0, 0.0, fma), 0.0, "gallivm forces pow(0, y) = 0");
            assert_eq!(pow(2.0, 3.0, fma), 8.0);
            assert_eq!(pow(0.25, 0.5, fma), 0.5);
            assert_eq!(pow(0.7, 0.0, fma), 1.0);
        }
    }

    /// Hand-traced values (exp2(0.5) and log2(1.5) by stepping through the f32 operations
    /// of lp_build_polynomial without fusing), pinned as bit patterns.
    #[test]
    fn traced_values() {
        // exp2(0.5): x2 = 0.25; odd = ((c5·x2 + c3)·x2 + c1); even = ((c4·x2 + c2)·x2 + c0)
        let c: Vec<f32> = EXP2_POLY.iter().map(|&v| v as f32).collect();
        let x2 = 0.25f32;
        let odd = (x2 * ((x2 * c[5]) + c[3])) + c[1];
        let even = (x2 * ((x2 * c[4]) + c[2])) + c[0];
        let want = odd * 0.5 + even;
        assert_eq!(exp2(0.5, false).to_bits(), want.to_bits());
        assert!(
            (want - std::f32::consts::SQRT_2).abs() < 3e-6,
            "{}",
            want - std::f32::consts::SQRT_2
        );
        // log2(1.5): y = 0.5/2.5 = 0.2, z = 0.04.
        let l: Vec<f32> = LOG2_POLY.iter().map(|&v| v as f32).collect();
        let y = 0.5f32 / 2.5f32;
        let z = y * y;
        let z2 = z * z;
        let even = (z2 * ((z2 * l[4]) + l[2])) + l[0];
        let odd = (z2 * l[3]) + l[1];
        let p = odd * z + even;
        let want = y * p + 0.0;
        assert_eq!(log2_safe(1.5, false).to_bits(), want.to_bits());
    }

    #[test]
    fn sin_cos_close_to_libm() {
        let mut worst = 0f64;
        for i in -20000..20000 {
            let x = i as f32 / 1000.0;
            for fma in [false, true] {
                let s = sin_or_cos(x, false, fma) as f64;
                let c = sin_or_cos(x, true, fma) as f64;
                worst = worst.max((s - (x as f64).sin()).abs());
                worst = worst.max((c - (x as f64).cos()).abs());
            }
        }
        assert!(worst < 3e-7, "sin/cos abs error {worst}");
        assert!(sin_or_cos(f32::INFINITY, false, true).is_nan());
        assert_eq!(sin_or_cos(0.0, true, true), 1.0);
        assert_eq!(sin_or_cos(0.0, false, true), 0.0);
    }

    #[test]
    fn close_to_libm() {
        let mut worst_exp = 0f64;
        let mut worst_log = 0f64;
        let mut worst_pow = 0f64;
        for i in 0..20000 {
            let t = i as f32 / 20000.0;
            let x = -8.0 + 16.0 * t;
            for fma in [false, true] {
                let e = exp2(x, fma) as f64;
                worst_exp = worst_exp.max((e / (x as f64).exp2() - 1.0).abs());
                let v = 0.001 + 10.0 * t;
                let l = log2_safe(v, fma) as f64;
                worst_log = worst_log.max((l - (v as f64).log2()).abs());
                let p = pow(t.max(1e-3), 37.0 * t, fma) as f64;
                let r = (t.max(1e-3) as f64).powf(37.0 * t as f64);
                if r > 1e-30 {
                    worst_pow = worst_pow.max((p / r - 1.0).abs());
                }
            }
        }
        eprintln!("exp2 {worst_exp:e} log2 {worst_log:e} pow {worst_pow:e}");
        assert!(worst_exp < 4e-7, "exp2 rel error {worst_exp}");
        assert!(worst_log < 6e-7, "log2 abs error {worst_log}");
        assert!(worst_pow < 1e-5, "pow rel error {worst_pow}");
    }
}
