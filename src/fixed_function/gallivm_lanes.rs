//! gallivm's transcendental approximations ([`super::gallivm_math`]) on eight f32 lanes
//! of AVX2 registers: every operation of the scalar functions in the same order, lane by
//! lane, so each lane's result is the scalar result bit for bit (the lighting lanes' and
//! the fog factor's tests compare them). Used by the 8-vertex lighting blocks
//! ([`super::lighting::lanes`]: `pow` for the specular and spot exponents), the 8-lane
//! fog factor ([`super::fog::FogPlan::factor8`]: `exp2`) and the engine's AVX2 kernels
//! (a shader's `exp2`, `log2` and `pow`; `crate::engine`'s shader tests compare them).
//!
//! Every function here is `#[inline(always)]` and `unsafe`: it runs inside kernels
//! compiled for AVX2 (and FMA when `FMA`), whose callers vouch for the CPU. No closures:
//! a closure is compiled without the kernel's target features, so an intrinsic inside one
//! would be an out-of-line call.

use super::gallivm_math::{EXP2_POLY, LOG2_POLY};
use crate::simd::{F32x8, I32x8};

/// Eight f32 lanes.
type V = F32x8;

/// Every lane `x`. Safety: AVX2.
#[inline(always)]
pub(crate) unsafe fn s(x: f32) -> V {
    // SAFETY: the caller vouches for AVX2.
    unsafe { F32x8::splat(x) }
}

/// Every lane `x`, as i32. Safety: AVX2.
#[inline(always)]
pub(crate) unsafe fn si(x: i32) -> I32x8 {
    // SAFETY: the caller vouches for AVX2.
    unsafe { I32x8::splat(x) }
}

/// `t` where `m` is set, else `f`.
#[inline(always)]
pub(crate) fn sel(m: V, t: V, f: V) -> V {
    f.blendv(t, m)
}

/// gallivm's `lp_build_mad` ([`crate::fixed_function::gallivm_math::mad`]).
/// Safety: AVX2, and FMA when `FMA`.
#[inline(always)]
unsafe fn mad<const FMA: bool>(a: V, b: V, c: V) -> V {
    if FMA {
        // SAFETY: the caller vouches for FMA.
        unsafe { a.mul_add(b, c) }
    } else {
        a.mul(b).add(c)
    }
}

/// [`crate::fixed_function::gallivm_math::polynomial`]. Safety: as [`mad`].
#[inline(always)]
unsafe fn polynomial<const FMA: bool>(x: V, coeffs: &[f64]) -> V {
    let x2 = x.mul(x);
    let mut even: Option<V> = None;
    let mut odd: Option<V> = None;
    for i in (0..coeffs.len()).rev() {
        // SAFETY: (this loop) forwarded.
        let c = unsafe { s(coeffs[i] as f32) };
        let chain = if i % 2 == 0 { &mut even } else { &mut odd };
        *chain = Some(match *chain {
            // SAFETY: forwarded.
            Some(e) => unsafe { mad::<FMA>(x2, e, c) },
            None => c,
        });
    }
    match (odd, even) {
        // SAFETY: forwarded.
        (Some(o), Some(e)) => unsafe { mad::<FMA>(o, x, e) },
        (None, Some(e)) => e,
        // SAFETY: forwarded.
        _ => unsafe { s(f32::NAN) },
    }
}

/// [`crate::fixed_function::gallivm_math::exp2`]. Safety: as [`mad`].
#[inline(always)]
pub(crate) unsafe fn exp2<const FMA: bool>(x: V) -> V {
    // SAFETY: (whole body) forwarded.
    unsafe {
        // The clamp leaves NaN alone; `maxps`/`minps` give the bound for equal values,
        // which is the same value.
        let clamped = x.max(s(-126.99999)).min(s(128.0));
        let x = sel(x.cmp_ord(x), clamped, x);
        let ip = x.floor();
        let fpart = x.sub(ip);
        // `cvttps2dq` gives i32::MIN for NaN, as the scalar code does.
        let ipart = ip.to_i32_trunc();
        let expipart = ipart.add(si(127)).shl::<23>().as_f32();
        let expfpart = polynomial::<FMA>(fpart, &EXP2_POLY);
        expipart.mul(expfpart)
    }
}

/// [`crate::fixed_function::gallivm_math::log2_safe`]. Safety: as [`mad`].
#[inline(always)]
pub(crate) unsafe fn log2_safe<const FMA: bool>(x: V) -> V {
    // SAFETY: (whole body) forwarded.
    unsafe {
        let i = x.bits();
        let exp = i.and(si(0x7f80_0000));
        let logexp = exp.shr::<23>().sub(si(127)).to_f32();
        let mant = i.and(si(0x007f_ffff)).or(si(0x3f80_0000)).as_f32();
        let y = mant.sub(s(1.0)).div(mant.add(s(1.0)));
        let z = y.mul(y);
        let p_z = polynomial::<FMA>(z, &LOG2_POLY);
        let mut r = mad::<FMA>(y, p_z, logexp);
        let zero = F32x8::zero();
        r = sel(x.cmp_ge(s(f32::INFINITY)), s(f32::INFINITY), r);
        r = sel(x.cmp_eq(zero), s(f32::NEG_INFINITY), r);
        sel(x.cmp_lt(zero), s(f32::NAN), r)
    }
}

/// [`crate::fixed_function::gallivm_math::pow`].
///
/// # Safety
/// The CPU has AVX2, and FMA when `FMA`.
#[inline(always)]
pub(crate) unsafe fn pow<const FMA: bool>(x: V, y: V) -> V {
    // SAFETY: forwarded.
    unsafe {
        let zero = F32x8::zero();
        let r = exp2::<FMA>(log2_safe::<FMA>(x).mul(y));
        sel(x.cmp_eq(zero), zero, r)
    }
}
