//! The portable backend: eight lanes as arrays, each operation the scalar instruction's
//! rule lane by lane (the compiler vectorises what it can at the level's features).

use super::super::ir::{Blend8, FCmp, IOp};
use super::Lanes;
use crate::fixed_function::gallivm_math as gm;
use crate::pipe::CompareFunc;

/// Portable lanes; `FUSED` selects `fmuladd`'s fused form.
pub(in super::super) struct Portable<const FUSED: bool>;

/// Eight f32.
type F = [f32; 8];
/// Eight i32.
type I = [i32; 8];

/// The lanes of `a` and `b` combined by `f`.
#[inline(always)]
fn zip<T: Copy, U: Copy>(a: [T; 8], b: [T; 8], f: impl Fn(T, T) -> U) -> [U; 8] {
    std::array::from_fn(|i| f(a[i], b[i]))
}

/// A boolean as a lane mask.
#[inline(always)]
fn m(b: bool) -> i32 {
    -(b as i32)
}

/// Packed RGBA8 lanes as the channel-major lanes of [`crate::fragment::blend`].
#[inline(always)]
fn channels(v: I) -> crate::fragment::blend::Lanes {
    std::array::from_fn(|ch| std::array::from_fn(|i| (v[i] as u32 >> (8 * ch)) as u8))
}

impl<const FUSED: bool> Lanes for Portable<FUSED> {
    const FUSED: bool = FUSED;
    type F = F;
    type I = I;
    #[inline(always)]
    unsafe fn ld_f(p: *const [u32; 8]) -> F {
        // SAFETY: the caller passes a register slot.
        unsafe { (*p).map(f32::from_bits) }
    }
    #[inline(always)]
    unsafe fn st_f(p: *mut [u32; 8], v: F) {
        // SAFETY: the caller passes a register slot.
        unsafe { *p = v.map(f32::to_bits) }
    }
    #[inline(always)]
    unsafe fn ld_i(p: *const [u32; 8]) -> I {
        // SAFETY: the caller passes a register slot.
        unsafe { (*p).map(|v| v as i32) }
    }
    #[inline(always)]
    unsafe fn st_i(p: *mut [u32; 8], v: I) {
        // SAFETY: the caller passes a register slot.
        unsafe { *p = v.map(|v| v as u32) }
    }
    #[inline(always)]
    unsafe fn splat_i(v: i32) -> I {
        [v; 8]
    }
    #[inline(always)]
    unsafe fn lane_x(x: f32) -> F {
        std::array::from_fn(|i| x + i as f32)
    }
    #[inline(always)]
    unsafe fn splat_f(y: f32) -> F {
        [y; 8]
    }
    #[inline(always)]
    fn add(a: F, b: F) -> F {
        zip(a, b, |a, b| a + b)
    }
    #[inline(always)]
    fn sub(a: F, b: F) -> F {
        zip(a, b, |a, b| a - b)
    }
    #[inline(always)]
    fn mul(a: F, b: F) -> F {
        zip(a, b, |a, b| a * b)
    }
    #[inline(always)]
    fn div(a: F, b: F) -> F {
        zip(a, b, |a, b| a / b)
    }
    #[inline(always)]
    fn min(a: F, b: F) -> F {
        zip(a, b, |a, b| if a < b { a } else { b })
    }
    #[inline(always)]
    fn max(a: F, b: F) -> F {
        zip(a, b, |a, b| if a > b { a } else { b })
    }
    #[inline(always)]
    unsafe fn mad(a: F, b: F, c: F) -> F {
        std::array::from_fn(|i| {
            if FUSED {
                a[i].mul_add(b[i], c[i])
            } else {
                a[i] * b[i] + c[i]
            }
        })
    }
    #[inline(always)]
    fn cvt(a: F) -> I {
        a.map(|v| {
            let r = v.round_ties_even();
            if (-2_147_483_648.0..2_147_483_648.0).contains(&r) {
                r as i32
            } else {
                i32::MIN
            }
        })
    }
    #[inline(always)]
    fn cvtt(a: F) -> I {
        a.map(|v| {
            if (-2_147_483_648.0..2_147_483_648.0).contains(&v) {
                v as i32
            } else {
                i32::MIN
            }
        })
    }
    #[inline(always)]
    fn floor(a: F) -> F {
        a.map(f32::floor)
    }
    #[inline(always)]
    fn sqrt(a: F) -> F {
        a.map(f32::sqrt)
    }
    #[inline(always)]
    unsafe fn exp2(a: F) -> F {
        // Loops, not closures: a closure is compiled without the kernel's features.
        let mut out = [0.0; 8];
        for i in 0..8 {
            out[i] = gm::exp2(a[i], FUSED);
        }
        out
    }
    #[inline(always)]
    unsafe fn log2(a: F) -> F {
        let mut out = [0.0; 8];
        for i in 0..8 {
            out[i] = gm::log2_safe(a[i], FUSED);
        }
        out
    }
    #[inline(always)]
    unsafe fn pow(a: F, b: F) -> F {
        let mut out = [0.0; 8];
        for i in 0..8 {
            out[i] = gm::pow(a[i], b[i], FUSED);
        }
        out
    }
    #[inline(always)]
    fn fbits(a: F) -> I {
        a.map(|v| v.to_bits() as i32)
    }
    #[inline(always)]
    fn ibits(a: I) -> F {
        a.map(|v| f32::from_bits(v as u32))
    }
    #[inline(always)]
    fn ibin(op: IOp, a: I, b: I) -> I {
        zip(a, b, |a, b| op.apply(a, b))
    }
    #[inline(always)]
    fn xor(a: I, b: I) -> I {
        zip(a, b, |a, b| a ^ b)
    }
    #[inline(always)]
    fn igt(a: I, b: I) -> I {
        zip(a, b, |a, b| m(a > b))
    }
    #[inline(always)]
    fn ieq(a: I, b: I) -> I {
        zip(a, b, |a, b| m(a == b))
    }
    #[inline(always)]
    fn itof(a: I) -> F {
        a.map(|v| v as f32)
    }
    #[inline(always)]
    fn fcmp(op: FCmp, a: F, b: F) -> I {
        zip(a, b, |a, b| {
            m(match op {
                FCmp::Lt => a < b,
                FCmp::Le => a <= b,
                FCmp::Gt => a > b,
                FCmp::Ge => a >= b,
                FCmp::Eq => a == b,
                FCmp::Ne => a != b,
            })
        })
    }
    #[inline(always)]
    unsafe fn icmp(func: CompareFunc, a: I, b: I) -> I {
        zip(a, b, |a, b| m(func.test(a, b)))
    }
    #[inline(always)]
    fn and(a: I, b: I) -> I {
        zip(a, b, |a, b| a & b)
    }
    #[inline(always)]
    fn or(a: I, b: I) -> I {
        zip(a, b, |a, b| a | b)
    }
    #[inline(always)]
    unsafe fn shr(a: I, n: u32) -> I {
        a.map(|v| (v as u32 >> n) as i32)
    }
    #[inline(always)]
    unsafe fn shl(a: I, n: u32) -> I {
        a.map(|v| ((v as u32) << n) as i32)
    }
    #[inline(always)]
    fn select(mk: I, a: I, b: I) -> I {
        std::array::from_fn(|i| if mk[i] < 0 { a[i] } else { b[i] })
    }
    #[inline(always)]
    fn any(mk: I) -> bool {
        mk.iter().any(|&v| v != 0)
    }
    #[inline(always)]
    fn count(mk: I) -> u32 {
        mk.iter().filter(|&&v| v != 0).count() as u32
    }
    #[inline(always)]
    unsafe fn depth(
        func: CompareFunc,
        write: bool,
        q: I,
        live: I,
        p: *mut u32,
        _avail: usize,
    ) -> I {
        let mut pass = [0; 8];
        for i in 0..8 {
            if live[i] == 0 {
                continue;
            }
            // SAFETY: live lanes lie inside the depth buffer (the caller's promise).
            unsafe {
                let at = p.add(i);
                if func.test(q[i] as u32, at.read_unaligned()) {
                    if write {
                        at.write_unaligned(q[i] as u32);
                    }
                    pass[i] = -1;
                }
            }
        }
        pass
    }
    #[inline(always)]
    unsafe fn load_color(p: *const u32, live: I) -> I {
        std::array::from_fn(|i| {
            if live[i] != 0 {
                // SAFETY: live lanes lie inside the colour buffer (the caller's promise).
                unsafe { p.add(i).read_unaligned() as i32 }
            } else {
                0
            }
        })
    }
    #[inline(always)]
    unsafe fn store_color(p: *mut u32, _avail: usize, live: I, v: I) {
        for i in 0..8 {
            if live[i] != 0 {
                // SAFETY: live lanes lie inside the colour buffer (the caller's promise).
                unsafe { p.add(i).write_unaligned(v[i] as u32) }
            }
        }
    }
    #[inline(always)]
    unsafe fn blend(plan: &Blend8, _over: bool, s: I, d: I) -> I {
        let c = crate::fragment::blend::blend_lanes(plan, &channels(s), &channels(d));
        std::array::from_fn(|i| u32::from_le_bytes([c[0][i], c[1][i], c[2][i], c[3][i]]) as i32)
    }
}
