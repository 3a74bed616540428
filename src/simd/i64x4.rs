//! Four `i64` lanes in a 256-bit AVX2 register.

use super::{avx2, bitwise_256, lane_ops, wide_type, I32x8};
use std::arch::x86_64::*;

wide_type! {
    /// Four `i64` lanes (`__m256i`). Made only where the CPU has AVX2 (see [`super`]).
    I64x4(__m256i, [i64; 4]):
        splat => _mm256_set1_epi64x, zero => _mm256_setzero_si256,
        new => _mm256_set_epi64x(3, 2, 1, 0)
}

impl I64x4 {
    /// Stores the lanes at `p` (unaligned).
    ///
    /// # Safety
    /// `p..p + 4` is writable.
    #[inline(always)]
    pub unsafe fn store(self, p: *mut i64) {
        // SAFETY: AVX2 as `self` proves; the caller vouches for the address.
        unsafe { _mm256_storeu_si256(p.cast(), self.0) }
    }

    /// The same bits as eight i32 lanes.
    #[inline(always)]
    pub fn as_i32(self) -> I32x8 {
        I32x8(self.0)
    }

    /// The sign bits of the lanes, bit `i` for lane `i`.
    #[inline(always)]
    pub fn movemask(self) -> u32 {
        avx2!(_mm256_movemask_pd(_mm256_castsi256_pd(self.0))) as u32
    }
}

bitwise_256!(I64x4);

lane_ops! {
    I64x4;
    /// Shifted left by `N` bits.
    fn shl<const N>() -> Self = _mm256_slli_epi64::<N>;
    /// Wrapping `self + o` per lane.
    fn add(o) -> Self = _mm256_add_epi64;
    /// Wrapping `self - o` per lane.
    fn sub(o) -> Self = _mm256_sub_epi64;
    /// `vpmuldq`: the exact products of the lanes' low 32 bits, as signed i32 values.
    fn mul_i32(o) -> Self = _mm256_mul_epi32;
    /// `self > o` per lane (signed) as a mask.
    fn cmpgt(o) -> Self = _mm256_cmpgt_epi64;
    /// `self == o` per lane as a mask.
    fn cmpeq(o) -> Self = _mm256_cmpeq_epi64;
}
