//! Four `f32` lanes in a 128-bit register, with the AVX encodings of the kernels that
//! use them (so, like the 256-bit types, made only where the CPU has AVX2).

use super::{lane_ops, wide_type};
use std::arch::x86_64::*;

wide_type! {
    /// Four `f32` lanes (`__m128`). Made only where the CPU has AVX2 (see [`super`]).
    F32x4(__m128, [f32; 4]):
        splat => _mm_set1_ps, zero => _mm_setzero_ps,
        new => _mm_setr_ps(0, 1, 2, 3),
        memory(*lane) => _mm_loadu_ps, _mm_storeu_ps,
        float => _mm_fmadd_ps, _mm_movemask_ps
}

impl F32x4 {
    /// Lane `i` of `self` broadcast to every lane.
    #[inline(always)]
    pub fn broadcast<const IMM: i32>(self) -> Self {
        self.shuffle::<IMM>(self)
    }
}

lane_ops! {
    F32x4;
    /// `shufps` with an immediate: two lanes of `self` then two of `o`.
    fn shuffle<const IMM>(o) -> Self = _mm_shuffle_ps::<IMM>;
    /// `blendps` with an immediate: lane `i` from `o` where bit `i` of `IMM` is set.
    fn blend<const IMM>(o) -> Self = _mm_blend_ps::<IMM>;
    /// `!(self <= o)` per lane (unordered: true for NaN) as a mask.
    fn cmp_nle(o) -> Self = _mm_cmp_ps::<_CMP_NLE_UQ>;
    /// `!(self >= o)` per lane (unordered: true for NaN) as a mask.
    fn cmp_nge(o) -> Self = _mm_cmp_ps::<_CMP_NGE_UQ>;
    /// `self + o` per lane.
    fn add(o) -> Self = _mm_add_ps;
    /// `self * o` per lane.
    fn mul(o) -> Self = _mm_mul_ps;
    /// `self / o` per lane (exact).
    fn div(o) -> Self = _mm_div_ps;
    /// `minps`: per lane the smaller, `o` when either is NaN.
    fn min(o) -> Self = _mm_min_ps;
    /// `maxps`: per lane the larger, `o` when either is NaN.
    fn max(o) -> Self = _mm_max_ps;
}
