//! Eight `f32` lanes in a 256-bit AVX register.

use super::{lane_ops, wide_type, I32x8};
use std::arch::x86_64::*;

wide_type! {
    /// Eight `f32` lanes (`__m256`). Made only where the CPU has AVX2 (see [`super`]).
    F32x8(__m256, [f32; 8]):
        splat => _mm256_set1_ps, zero => _mm256_setzero_ps,
        new => _mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7),
        memory(*lane) => _mm256_loadu_ps, _mm256_storeu_ps,
        float => _mm256_fmadd_ps, _mm256_movemask_ps
}

lane_ops! {
    F32x8;
    /// `vblendvps`: per lane `o` where the sign bit of `mask` is set, else `self`.
    fn blendv(o, mask) -> Self = _mm256_blendv_ps;
    /// `self < o` per lane (ordered, quiet) as a mask.
    fn cmp_lt(o) -> Self = _mm256_cmp_ps::<_CMP_LT_OQ>;
    /// `self <= o` per lane (ordered, quiet) as a mask.
    fn cmp_le(o) -> Self = _mm256_cmp_ps::<_CMP_LE_OQ>;
    /// `self > o` per lane (ordered, quiet) as a mask.
    fn cmp_gt(o) -> Self = _mm256_cmp_ps::<_CMP_GT_OQ>;
    /// `self >= o` per lane (ordered, quiet) as a mask.
    fn cmp_ge(o) -> Self = _mm256_cmp_ps::<_CMP_GE_OQ>;
    /// `self == o` per lane (ordered, quiet) as a mask.
    fn cmp_eq(o) -> Self = _mm256_cmp_ps::<_CMP_EQ_OQ>;
    /// Neither lane NaN, as a mask.
    fn cmp_ord(o) -> Self = _mm256_cmp_ps::<_CMP_ORD_Q>;
    /// Rounded down to an integral value.
    fn floor() -> Self = _mm256_floor_ps;
    /// Rounded to the nearest integral value, ties to even, without raising exceptions.
    fn round_even() -> Self =
        _mm256_round_ps::<{ _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC }>;
    /// `vcvtps2dq`: to i32 in the current rounding mode (ties to even by default).
    fn to_i32() -> I32x8 = _mm256_cvtps_epi32;
    /// `vcvttps2dq`: to i32, truncated.
    fn to_i32_trunc() -> I32x8 = _mm256_cvttps_epi32;
    /// The same bits as eight i32 lanes.
    fn bits() -> I32x8 = _mm256_castps_si256;
    /// `vpermilps` with an immediate: lanes chosen within each 128-bit half.
    fn permute<const IMM>() -> Self = _mm256_permute_ps::<IMM>;
    /// `vshufps` with an immediate: two lanes of `self` then two of `o`, per 128-bit half.
    fn shuffle<const IMM>(o) -> Self = _mm256_shuffle_ps::<IMM>;
    /// `self + o` per lane.
    fn add(o) -> Self = _mm256_add_ps;
    /// `self - o` per lane.
    fn sub(o) -> Self = _mm256_sub_ps;
    /// `self * o` per lane.
    fn mul(o) -> Self = _mm256_mul_ps;
    /// `self / o` per lane (exact, `vdivps`).
    fn div(o) -> Self = _mm256_div_ps;
    /// The square root per lane (correctly rounded, `vsqrtps`).
    fn sqrt() -> Self = _mm256_sqrt_ps;
    /// `vminps`: per lane the smaller, `o` when either is NaN.
    fn min(o) -> Self = _mm256_min_ps;
    /// `vmaxps`: per lane the larger, `o` when either is NaN.
    fn max(o) -> Self = _mm256_max_ps;
    /// Bitwise and.
    fn and(o) -> Self = _mm256_and_ps;
    /// `vunpcklps`: lanes 0, 1 of each 128-bit half interleaved with those of `o`.
    fn unpack_lo(o) -> Self = _mm256_unpacklo_ps;
    /// `vunpckhps`: lanes 2, 3 of each 128-bit half interleaved with those of `o`.
    fn unpack_hi(o) -> Self = _mm256_unpackhi_ps;
    /// `vperm2f128` with an immediate: each 128-bit half one of the halves of `self`
    /// and `o` (0x20: the low halves, 0x31: the high halves).
    fn perm128<const IMM>(o) -> Self = _mm256_permute2f128_ps::<IMM>;
}
