//! Sixteen 16-bit lanes in a 256-bit AVX2 register: pixels' channels widened to words.

use super::{avx2, bitwise_256, lane_ops, I32x8};
use std::arch::x86_64::*;

/// Sixteen 16-bit lanes (`__m256i`), unsigned unless an operation says otherwise. Made
/// only where the CPU has AVX2 (see [`super`]).
#[derive(Clone, Copy, Debug)]
#[repr(transparent)]
pub struct U16x16(pub(super) __m256i);

impl U16x16 {
    /// Every lane `v`.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    pub unsafe fn splat(v: u16) -> Self {
        // SAFETY: the caller vouches for AVX2.
        Self(unsafe { _mm256_set1_epi16(v as i16) })
    }

    /// Every lane 0.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    pub unsafe fn zero() -> Self {
        // SAFETY: the caller vouches for AVX2.
        Self(unsafe { _mm256_setzero_si256() })
    }

    /// Lanes 0–3, 4–7, 8–11 and 12–15 each `q[0..4]`.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    pub unsafe fn splat4(q: [u16; 4]) -> Self {
        let [a, b, c, d] = q.map(|v| v as i16);
        // SAFETY: the caller vouches for AVX2.
        Self(unsafe { _mm256_setr_epi16(a, b, c, d, a, b, c, d, a, b, c, d, a, b, c, d) })
    }

    /// The same bits as eight i32 lanes.
    #[inline(always)]
    pub fn as_i32(self) -> I32x8 {
        I32x8(self.0)
    }

    /// `vpshuflw` then `vpshufhw` with the same immediate: the four words of every 64 bits
    /// permuted by `IMM`.
    #[inline(always)]
    pub fn shuffle4<const IMM: i32>(self) -> Self {
        Self(avx2!(_mm256_shufflehi_epi16::<IMM>(
            _mm256_shufflelo_epi16::<IMM>(self.0)
        )))
    }
}

bitwise_256!(U16x16);

lane_ops! {
    U16x16;
    /// Each 16-bit lane shifted left by `N` bits.
    fn shl<const N>() -> Self = _mm256_slli_epi16::<N>;
    /// Each 16-bit lane shifted right by `N` bits, zeros in.
    fn shr<const N>() -> Self = _mm256_srli_epi16::<N>;
    /// `vpblendw` with an immediate: lane `i` from `o` where bit `i % 8` of `IMM` is set.
    fn blend<const IMM>(o) -> Self = _mm256_blend_epi16::<IMM>;
    /// `vpackuswb`: the lanes of `self` then `o` per 128-bit half, as bytes saturated to
    /// 0..=255 (the inverse of [`I32x8::unpack_lo_u8`] / [`I32x8::unpack_hi_u8`]).
    fn pack_u8(o) -> I32x8 = _mm256_packus_epi16;
    /// Wrapping `self + o` per lane.
    fn add(o) -> Self = _mm256_add_epi16;
    /// Wrapping `self - o` per lane.
    fn sub(o) -> Self = _mm256_sub_epi16;
    /// `self - o` per lane, saturated at 0.
    fn sub_sat(o) -> Self = _mm256_subs_epu16;
    /// The low 16 bits of `self * o` per lane.
    fn mullo(o) -> Self = _mm256_mullo_epi16;
    /// `vpmulhrsw`: `(self·o + 2^14) >> 15` per lane, signed.
    fn mulhrs(o) -> Self = _mm256_mulhrs_epi16;
    /// Unsigned minimum per lane.
    fn min(o) -> Self = _mm256_min_epu16;
    /// Unsigned maximum per lane.
    fn max(o) -> Self = _mm256_max_epu16;
}
