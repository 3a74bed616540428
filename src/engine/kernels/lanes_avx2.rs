//! The AVX2 backend: eight lanes in a 256-bit register ([`crate::simd`]'s types); the
//! depth test, blending and stores are the hand-written span shader's own kernels
//! ([`crate::fragment::simd`]), so both paths share one definition of those bytes.

use super::super::ir::{Blend8, FCmp, IOp};
use super::Lanes;
use crate::fixed_function::gallivm_lanes as gl;
use crate::fragment::simd::{blend8, depth_pass, over8, store_masked};
use crate::pipe::CompareFunc;
use crate::simd::{F32x8, I32x8};

/// AVX2 lanes; `FUSED` selects `vfmadd` for `fmuladd` (the kernels are then compiled
/// with FMA).
pub(in super::super) struct Avx2<const FUSED: bool>;

impl<const FUSED: bool> Lanes for Avx2<FUSED> {
    const FUSED: bool = FUSED;
    type F = F32x8;
    type I = I32x8;
    #[inline(always)]
    unsafe fn ld_f(p: *const [u32; 8]) -> F32x8 {
        // SAFETY: AVX2 context and a register slot (the caller's promise).
        unsafe { F32x8::load(p as *const f32) }
    }
    #[inline(always)]
    unsafe fn st_f(p: *mut [u32; 8], v: F32x8) {
        // SAFETY: as `ld_f`.
        unsafe { v.store(p as *mut f32) }
    }
    #[inline(always)]
    unsafe fn ld_i(p: *const [u32; 8]) -> I32x8 {
        // SAFETY: as `ld_f`.
        unsafe { I32x8::load(p) }
    }
    #[inline(always)]
    unsafe fn st_i(p: *mut [u32; 8], v: I32x8) {
        // SAFETY: as `ld_f`.
        unsafe { v.store(p) }
    }
    #[inline(always)]
    unsafe fn splat_i(v: i32) -> I32x8 {
        // SAFETY: AVX2 context (the caller's promise).
        unsafe { I32x8::splat(v) }
    }
    #[inline(always)]
    unsafe fn lane_x(x: f32) -> F32x8 {
        // SAFETY: AVX2 context (the caller's promise). Integers below 2^24 are exact, so
        // this is `(x + i) as f32` for the pixel columns.
        unsafe { F32x8::splat(x).add(F32x8::new([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0])) }
    }
    #[inline(always)]
    unsafe fn splat_f(y: f32) -> F32x8 {
        // SAFETY: AVX2 context (the caller's promise).
        unsafe { F32x8::splat(y) }
    }
    #[inline(always)]
    fn add(a: F32x8, b: F32x8) -> F32x8 {
        a.add(b)
    }
    #[inline(always)]
    fn sub(a: F32x8, b: F32x8) -> F32x8 {
        a.sub(b)
    }
    #[inline(always)]
    fn mul(a: F32x8, b: F32x8) -> F32x8 {
        a.mul(b)
    }
    #[inline(always)]
    fn div(a: F32x8, b: F32x8) -> F32x8 {
        a.div(b)
    }
    #[inline(always)]
    fn min(a: F32x8, b: F32x8) -> F32x8 {
        a.min(b)
    }
    #[inline(always)]
    fn max(a: F32x8, b: F32x8) -> F32x8 {
        a.max(b)
    }
    #[inline(always)]
    unsafe fn mad(a: F32x8, b: F32x8, c: F32x8) -> F32x8 {
        if FUSED {
            // SAFETY: the fused kernels are compiled with FMA and chosen only with it.
            unsafe { a.mul_add(b, c) }
        } else {
            a.mul(b).add(c)
        }
    }
    #[inline(always)]
    fn cvt(a: F32x8) -> I32x8 {
        a.to_i32()
    }
    #[inline(always)]
    fn cvtt(a: F32x8) -> I32x8 {
        a.to_i32_trunc()
    }
    #[inline(always)]
    fn floor(a: F32x8) -> F32x8 {
        a.floor()
    }
    #[inline(always)]
    fn sqrt(a: F32x8) -> F32x8 {
        a.sqrt()
    }
    #[inline(always)]
    unsafe fn exp2(a: F32x8) -> F32x8 {
        // SAFETY: AVX2 context, with FMA when `FUSED` (the caller's promise).
        unsafe { gl::exp2::<FUSED>(a) }
    }
    #[inline(always)]
    unsafe fn log2(a: F32x8) -> F32x8 {
        // SAFETY: as `exp2`.
        unsafe { gl::log2_safe::<FUSED>(a) }
    }
    #[inline(always)]
    unsafe fn pow(a: F32x8, b: F32x8) -> F32x8 {
        // SAFETY: as `exp2`.
        unsafe { gl::pow::<FUSED>(a, b) }
    }
    #[inline(always)]
    fn fbits(a: F32x8) -> I32x8 {
        a.bits()
    }
    #[inline(always)]
    fn ibits(a: I32x8) -> F32x8 {
        a.as_f32()
    }
    #[inline(always)]
    fn ibin(op: IOp, a: I32x8, b: I32x8) -> I32x8 {
        match op {
            IOp::Add => a.add(b),
            IOp::Sub => a.sub(b),
            IOp::Mul => a.mullo(b),
            IOp::Min => a.min(b),
            IOp::Max => a.max(b),
            // No AVX2 instruction divides; the shifts are rare.
            _ => {
                let (x, y) = (a.to_array(), b.to_array());
                // SAFETY: this backend runs where the CPU has AVX2 (as `a` proves).
                unsafe { I32x8::new(std::array::from_fn(|i| op.apply(x[i], y[i]))) }
            }
        }
    }
    #[inline(always)]
    fn xor(a: I32x8, b: I32x8) -> I32x8 {
        a.xor(b)
    }
    #[inline(always)]
    fn igt(a: I32x8, b: I32x8) -> I32x8 {
        a.cmpgt(b)
    }
    #[inline(always)]
    fn ieq(a: I32x8, b: I32x8) -> I32x8 {
        a.cmpeq(b)
    }
    #[inline(always)]
    fn itof(a: I32x8) -> F32x8 {
        a.to_f32()
    }
    #[inline(always)]
    fn fcmp(op: FCmp, a: F32x8, b: F32x8) -> I32x8 {
        match op {
            FCmp::Lt => a.cmp_lt(b),
            FCmp::Le => a.cmp_le(b),
            FCmp::Gt => a.cmp_gt(b),
            FCmp::Ge => a.cmp_ge(b),
            FCmp::Eq => a.cmp_eq(b),
            FCmp::Ne => {
                // Not ordered-equal: the lanes where the equality mask is zero.
                let m = a.cmp_eq(b).bits();
                return m.cmpeq(m.xor(m));
            }
        }
        .bits()
    }
    #[inline(always)]
    unsafe fn icmp(func: CompareFunc, a: I32x8, b: I32x8) -> I32x8 {
        // SAFETY: AVX2 context (the caller's promise).
        unsafe { depth_pass(func, a, b) }
    }
    #[inline(always)]
    fn and(a: I32x8, b: I32x8) -> I32x8 {
        a.and(b)
    }
    #[inline(always)]
    fn or(a: I32x8, b: I32x8) -> I32x8 {
        a.or(b)
    }
    #[inline(always)]
    unsafe fn shr(a: I32x8, n: u32) -> I32x8 {
        // SAFETY: AVX2 context (the caller's promise).
        a.shr_var(unsafe { I32x8::splat(n as i32) })
    }
    #[inline(always)]
    unsafe fn shl(a: I32x8, n: u32) -> I32x8 {
        // SAFETY: AVX2 context (the caller's promise).
        a.shl_var(unsafe { I32x8::splat(n as i32) })
    }
    #[inline(always)]
    fn select(m: I32x8, a: I32x8, b: I32x8) -> I32x8 {
        b.blendv(a, m)
    }
    #[inline(always)]
    fn any(m: I32x8) -> bool {
        m.movemask() != 0
    }
    #[inline(always)]
    fn count(m: I32x8) -> u32 {
        m.movemask().count_ones()
    }
    #[inline(always)]
    unsafe fn depth(
        func: CompareFunc,
        write: bool,
        q: I32x8,
        live: I32x8,
        p: *mut u32,
        avail: usize,
    ) -> I32x8 {
        // SAFETY: AVX2 context; the masked load and store touch live lanes, which lie in
        // the buffer, and `avail` counts the values from `p` to its end.
        unsafe {
            let p = p as *mut i32;
            let old = I32x8::maskload(p, live);
            let pass = live.and(depth_pass(func, q, old));
            if write {
                store_masked(p, avail, pass, q);
            }
            pass
        }
    }
    #[inline(always)]
    unsafe fn load_color(p: *const u32, live: I32x8) -> I32x8 {
        // SAFETY: AVX2 context; the masked load touches live lanes only.
        unsafe { I32x8::maskload(p as *const i32, live) }
    }
    #[inline(always)]
    unsafe fn store_color(p: *mut u32, avail: usize, live: I32x8, v: I32x8) {
        // SAFETY: AVX2 context; live lanes lie in the buffer, `avail` to its end.
        unsafe { store_masked(p as *mut i32, avail, live, v) }
    }
    #[inline(always)]
    unsafe fn blend(plan: &Blend8, over: bool, s: I32x8, d: I32x8) -> I32x8 {
        // SAFETY: AVX2 context (the caller's promise).
        unsafe {
            if over {
                over8(s, d)
            } else {
                blend8(plan, s, d)
            }
        }
    }
}
