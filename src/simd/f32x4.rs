//! Four `f32` lanes in a 128-bit register, with the AVX encodings of the kernels that
//! use them (so, like the 256-bit types, made only where the CPU has AVX2).

use super::{avx2, binary_ops};
use std::arch::x86_64::*;

/// Four `f32` lanes (`__m128`). Made only where the CPU has AVX2 (see [`super`]).
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub struct F32x4(__m128);

// Named methods rather than `std::ops` operators: a kernel reads as the sequence of
// instructions it compiles to.
#[allow(clippy::should_implement_trait)]
impl F32x4 {
    /// Every lane `v`.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    pub unsafe fn splat(v: f32) -> Self {
        // SAFETY: SSE is baseline; the caller vouches for AVX2 (this type's promise).
        Self(unsafe { _mm_set1_ps(v) })
    }

    /// Every lane 0.0.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    pub unsafe fn zero() -> Self {
        // SAFETY: SSE is baseline; the caller vouches for AVX2 (this type's promise).
        Self(unsafe { _mm_setzero_ps() })
    }

    /// Lane `i` is `a[i]`.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    pub unsafe fn new(a: [f32; 4]) -> Self {
        // SAFETY: SSE is baseline; the caller vouches for AVX2 (this type's promise).
        Self(unsafe { _mm_setr_ps(a[0], a[1], a[2], a[3]) })
    }

    /// The four values at `p` (unaligned).
    ///
    /// # Safety
    /// The CPU has AVX2 and `p..p + 4` is readable.
    #[inline(always)]
    pub unsafe fn load(p: *const f32) -> Self {
        // SAFETY: forwarded from the caller.
        Self(unsafe { _mm_loadu_ps(p) })
    }

    /// Stores the lanes at `p` (unaligned).
    ///
    /// # Safety
    /// `p..p + 4` is writable.
    #[inline(always)]
    pub unsafe fn store(self, p: *mut f32) {
        // SAFETY: forwarded from the caller.
        unsafe { _mm_storeu_ps(p, self.0) }
    }

    /// `self * b + c` with one rounding (`vfmadd`).
    ///
    /// # Safety
    /// The CPU has FMA.
    #[inline(always)]
    pub unsafe fn mul_add(self, b: Self, c: Self) -> Self {
        // SAFETY: the caller vouches for FMA.
        Self(unsafe { _mm_fmadd_ps(self.0, b.0, c.0) })
    }

    /// `shufps` with an immediate: two lanes of `self` then two of `o`.
    #[inline(always)]
    pub fn shuffle<const IMM: i32>(self, o: Self) -> Self {
        Self(avx2!(_mm_shuffle_ps::<IMM>(self.0, o.0)))
    }

    /// Lane `i` of `self` broadcast to every lane.
    #[inline(always)]
    pub fn broadcast<const IMM: i32>(self) -> Self {
        self.shuffle::<IMM>(self)
    }

    /// `blendps` with an immediate: lane `i` from `o` where bit `i` of `IMM` is set.
    #[inline(always)]
    pub fn blend<const IMM: i32>(self, o: Self) -> Self {
        Self(avx2!(_mm_blend_ps::<IMM>(self.0, o.0)))
    }

    /// `!(self <= o)` per lane (unordered: true for NaN) as a mask.
    #[inline(always)]
    pub fn cmp_nle(self, o: Self) -> Self {
        Self(avx2!(_mm_cmp_ps::<_CMP_NLE_UQ>(self.0, o.0)))
    }

    /// `!(self >= o)` per lane (unordered: true for NaN) as a mask.
    #[inline(always)]
    pub fn cmp_nge(self, o: Self) -> Self {
        Self(avx2!(_mm_cmp_ps::<_CMP_NGE_UQ>(self.0, o.0)))
    }

    /// The sign bits of the lanes, bit `i` for lane `i`.
    #[inline(always)]
    pub fn movemask(self) -> u32 {
        avx2!(_mm_movemask_ps(self.0)) as u32
    }
}

binary_ops! {
    F32x4;
    /// `self + o` per lane.
    add => _mm_add_ps,
    /// `self * o` per lane.
    mul => _mm_mul_ps,
    /// `self / o` per lane (exact).
    div => _mm_div_ps,
    /// `minps`: per lane the smaller, `o` when either is NaN.
    min => _mm_min_ps,
    /// `maxps`: per lane the larger, `o` when either is NaN.
    max => _mm_max_ps,
}
