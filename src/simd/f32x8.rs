//! Eight `f32` lanes in a 256-bit AVX register.

use super::{avx2, binary_ops, wide_type, I32x8};
use std::arch::x86_64::*;

wide_type! {
    /// Eight `f32` lanes (`__m256`). Made only where the CPU has AVX2 (see [`super`]).
    F32x8(__m256, f32): splat => _mm256_set1_ps, zero => _mm256_setzero_ps
}

// Named methods rather than `std::ops` operators: a kernel reads as the sequence of
// instructions it compiles to.
#[allow(clippy::should_implement_trait)]
impl F32x8 {
    /// Lane `i` is `a[i]`.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    pub unsafe fn new(a: [f32; 8]) -> Self {
        // SAFETY: the caller vouches for AVX2.
        Self(unsafe { _mm256_setr_ps(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7]) })
    }

    /// The eight values at `p` (unaligned).
    ///
    /// # Safety
    /// The CPU has AVX2 and `p..p + 8` is readable.
    #[inline(always)]
    pub unsafe fn load(p: *const f32) -> Self {
        // SAFETY: forwarded from the caller.
        Self(unsafe { _mm256_loadu_ps(p) })
    }

    /// Stores the lanes at `p` (unaligned).
    ///
    /// # Safety
    /// `p..p + 8` is writable.
    #[inline(always)]
    pub unsafe fn store(self, p: *mut f32) {
        // SAFETY: AVX2 as `self` proves; the caller vouches for the address.
        unsafe { _mm256_storeu_ps(p, self.0) }
    }

    /// The lanes as an array.
    #[inline(always)]
    pub fn to_array(self) -> [f32; 8] {
        let mut a = [0.0; 8];
        // SAFETY: AVX2 as `self` proves; `a` is 32 writable bytes.
        unsafe { self.store(a.as_mut_ptr()) };
        a
    }

    /// `self * b + c` with one rounding (`vfmadd`).
    ///
    /// # Safety
    /// The CPU has FMA.
    #[inline(always)]
    pub unsafe fn mul_add(self, b: Self, c: Self) -> Self {
        // SAFETY: AVX2 as `self` proves; the caller vouches for FMA.
        Self(unsafe { _mm256_fmadd_ps(self.0, b.0, c.0) })
    }

    /// `vblendvps`: per lane `o` where the sign bit of `mask` is set, else `self`.
    #[inline(always)]
    pub fn blendv(self, o: Self, mask: Self) -> Self {
        Self(avx2!(_mm256_blendv_ps(self.0, o.0, mask.0)))
    }

    /// `self < o` per lane (ordered, quiet) as a mask.
    #[inline(always)]
    pub fn cmp_lt(self, o: Self) -> Self {
        Self(avx2!(_mm256_cmp_ps::<_CMP_LT_OQ>(self.0, o.0)))
    }

    /// `self <= o` per lane (ordered, quiet) as a mask.
    #[inline(always)]
    pub fn cmp_le(self, o: Self) -> Self {
        Self(avx2!(_mm256_cmp_ps::<_CMP_LE_OQ>(self.0, o.0)))
    }

    /// `self > o` per lane (ordered, quiet) as a mask.
    #[inline(always)]
    pub fn cmp_gt(self, o: Self) -> Self {
        Self(avx2!(_mm256_cmp_ps::<_CMP_GT_OQ>(self.0, o.0)))
    }

    /// `self >= o` per lane (ordered, quiet) as a mask.
    #[inline(always)]
    pub fn cmp_ge(self, o: Self) -> Self {
        Self(avx2!(_mm256_cmp_ps::<_CMP_GE_OQ>(self.0, o.0)))
    }

    /// `self == o` per lane (ordered, quiet) as a mask.
    #[inline(always)]
    pub fn cmp_eq(self, o: Self) -> Self {
        Self(avx2!(_mm256_cmp_ps::<_CMP_EQ_OQ>(self.0, o.0)))
    }

    /// Neither lane NaN, as a mask.
    #[inline(always)]
    pub fn cmp_ord(self, o: Self) -> Self {
        Self(avx2!(_mm256_cmp_ps::<_CMP_ORD_Q>(self.0, o.0)))
    }

    /// Rounded down to an integral value.
    #[inline(always)]
    pub fn floor(self) -> Self {
        Self(avx2!(_mm256_floor_ps(self.0)))
    }

    /// Rounded to the nearest integral value, ties to even, without raising exceptions.
    #[inline(always)]
    pub fn round_even(self) -> Self {
        Self(avx2!(_mm256_round_ps::<
            { _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC },
        >(self.0)))
    }

    /// `vcvtps2dq`: to i32 in the current rounding mode (ties to even by default).
    #[inline(always)]
    pub fn to_i32(self) -> I32x8 {
        I32x8(avx2!(_mm256_cvtps_epi32(self.0)))
    }

    /// `vcvttps2dq`: to i32, truncated.
    #[inline(always)]
    pub fn to_i32_trunc(self) -> I32x8 {
        I32x8(avx2!(_mm256_cvttps_epi32(self.0)))
    }

    /// The same bits as eight i32 lanes.
    #[inline(always)]
    pub fn bits(self) -> I32x8 {
        I32x8(avx2!(_mm256_castps_si256(self.0)))
    }

    /// The sign bits of the lanes, bit `i` for lane `i`.
    #[inline(always)]
    pub fn movemask(self) -> u32 {
        avx2!(_mm256_movemask_ps(self.0)) as u32
    }

    /// `vpermilps` with an immediate: lanes chosen within each 128-bit half.
    #[inline(always)]
    pub fn permute<const IMM: i32>(self) -> Self {
        Self(avx2!(_mm256_permute_ps::<IMM>(self.0)))
    }

    /// `vshufps` with an immediate: two lanes of `self` then two of `o`, per 128-bit half.
    #[inline(always)]
    pub fn shuffle<const IMM: i32>(self, o: Self) -> Self {
        Self(avx2!(_mm256_shuffle_ps::<IMM>(self.0, o.0)))
    }
}

binary_ops! {
    F32x8;
    /// `self + o` per lane.
    add => _mm256_add_ps,
    /// `self - o` per lane.
    sub => _mm256_sub_ps,
    /// `self * o` per lane.
    mul => _mm256_mul_ps,
    /// `self / o` per lane (exact, `vdivps`).
    div => _mm256_div_ps,
    /// `vminps`: per lane the smaller, `o` when either is NaN.
    min => _mm256_min_ps,
    /// `vmaxps`: per lane the larger, `o` when either is NaN.
    max => _mm256_max_ps,
    /// Bitwise and.
    and => _mm256_and_ps,
}
