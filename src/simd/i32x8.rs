//! Eight `i32` lanes in a 256-bit AVX2 register.

use super::{avx2, bitwise_256, lane_ops, wide_type, F32x8, I64x4, U16x16};
use std::arch::x86_64::*;

wide_type! {
    /// Eight `i32` lanes (`__m256i`); the unsigned operations say so in their names. Made
    /// only where the CPU has AVX2 (see [`super`]).
    I32x8(__m256i, [i32; 8]):
        splat => _mm256_set1_epi32, zero => _mm256_setzero_si256,
        new => _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7)
}

impl I32x8 {
    /// The 32 bytes at `p` (unaligned).
    ///
    /// # Safety
    /// The CPU has AVX2 and the 32 bytes at `p` are readable.
    #[inline(always)]
    pub unsafe fn load<T>(p: *const T) -> Self {
        // SAFETY: forwarded from the caller.
        Self(unsafe { _mm256_loadu_si256(p.cast()) })
    }

    /// Stores the lanes at `p` (unaligned).
    ///
    /// # Safety
    /// The 32 bytes at `p` are writable.
    #[inline(always)]
    pub unsafe fn store<T>(self, p: *mut T) {
        // SAFETY: AVX2 as `self` proves; the caller vouches for the address.
        unsafe { _mm256_storeu_si256(p.cast(), self.0) }
    }

    /// `vpmaskmovd` load: lane `i` from `p + i` where the sign bit of lane `i` of `mask`
    /// is set, else 0; other lanes' memory is not touched.
    ///
    /// # Safety
    /// The masked lanes' addresses are readable (AVX2 as `mask` proves).
    #[inline(always)]
    pub unsafe fn maskload(p: *const i32, mask: Self) -> Self {
        // SAFETY: forwarded from the caller.
        Self(unsafe { _mm256_maskload_epi32(p, mask.0) })
    }

    /// `vpmaskmovd` store of the lanes whose sign bit in `mask` is set.
    ///
    /// # Safety
    /// The masked lanes' addresses are writable.
    #[inline(always)]
    pub unsafe fn maskstore(self, p: *mut i32, mask: Self) {
        // SAFETY: forwarded from the caller; AVX2 as `self` proves.
        unsafe { _mm256_maskstore_epi32(p, mask.0, self.0) }
    }

    /// [`Self::maskload`] of lanes 0–3 from `lo` and lanes 4–7 from `hi` (two 128-bit
    /// `vpmaskmovd`).
    ///
    /// # Safety
    /// The masked lanes' addresses are readable.
    #[inline(always)]
    pub unsafe fn maskload_halves(lo: *const i32, hi: *const i32, mask: Self) -> Self {
        // SAFETY: forwarded from the caller; AVX2 as `mask` proves.
        unsafe {
            let l = _mm_maskload_epi32(lo, _mm256_castsi256_si128(mask.0));
            let h = _mm_maskload_epi32(hi, _mm256_extracti128_si256::<1>(mask.0));
            Self(_mm256_set_m128i(h, l))
        }
    }

    /// [`Self::maskstore`] of lanes 0–3 at `lo` and lanes 4–7 at `hi`.
    ///
    /// # Safety
    /// The masked lanes' addresses are writable.
    #[inline(always)]
    pub unsafe fn maskstore_halves(self, lo: *mut i32, hi: *mut i32, mask: Self) {
        // SAFETY: forwarded from the caller; AVX2 as `self` proves.
        unsafe {
            _mm_maskstore_epi32(
                lo,
                _mm256_castsi256_si128(mask.0),
                _mm256_castsi256_si128(self.0),
            );
            _mm_maskstore_epi32(
                hi,
                _mm256_extracti128_si256::<1>(mask.0),
                _mm256_extracti128_si256::<1>(self.0),
            );
        }
    }

    /// `vpgatherdd`: lane `i` is the i32 at `base + idx[i]` (in elements).
    ///
    /// # Safety
    /// Every lane's address is readable.
    #[inline(always)]
    pub unsafe fn gather(base: *const i32, idx: Self) -> Self {
        // SAFETY: forwarded from the caller; AVX2 as `idx` proves.
        Self(unsafe { _mm256_i32gather_epi32::<4>(base, idx.0) })
    }

    /// The lanes as an array.
    #[inline(always)]
    pub fn to_array(self) -> [i32; 8] {
        let mut a = [0; 8];
        // SAFETY: AVX2 as `self` proves; `a` is 32 writable bytes.
        unsafe { self.store(a.as_mut_ptr()) };
        a
    }

    /// Lane 0.
    #[inline(always)]
    pub fn first(self) -> i32 {
        avx2!(_mm256_cvtsi256_si32(self.0))
    }

    /// The same bits as sixteen u16 lanes.
    #[inline(always)]
    pub fn as_u16(self) -> U16x16 {
        U16x16(self.0)
    }

    /// The same bits as four i64 lanes.
    #[inline(always)]
    pub fn as_i64(self) -> I64x4 {
        I64x4(self.0)
    }

    /// The sign bits of the lanes, bit `i` for lane `i`.
    #[inline(always)]
    pub fn movemask(self) -> u32 {
        self.as_f32().movemask()
    }

    /// Lanes 0–3 sign-extended to i64.
    #[inline(always)]
    pub fn widen_lo(self) -> I64x4 {
        I64x4(avx2!(_mm256_cvtepi32_epi64(_mm256_castsi256_si128(self.0))))
    }

    /// Lanes 4–7 sign-extended to i64.
    #[inline(always)]
    pub fn widen_hi(self) -> I64x4 {
        I64x4(avx2!(_mm256_cvtepi32_epi64(_mm256_extracti128_si256::<1>(
            self.0
        ))))
    }

    /// The eight bytes `b` zero-extended, lane `i` from `b[i]` (`vpmovzxbd`).
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    pub unsafe fn from_u8(b: [u8; 8]) -> Self {
        // SAFETY: forwarded from the caller; the 8-byte load reads `b` only.
        unsafe {
            let v = _mm_loadl_epi64(b.as_ptr().cast());
            Self(_mm256_cvtepu8_epi32(v))
        }
    }

    /// The low byte of each lane, lane `i` at byte `i` (the inverse of [`Self::from_u8`]
    /// for lanes of 0..=255).
    #[inline(always)]
    pub fn to_u8(self) -> [u8; 8] {
        avx2!({
            // Bytes 0, 4, 8, 12 of each half to its low four bytes, then the halves'
            // low dwords side by side.
            let pick = _mm256_setr_epi8(
                0, 4, 8, 12, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, 4, 8, 12, -1, -1,
                -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
            );
            let s = _mm256_shuffle_epi8(self.0, pick);
            let v = _mm_unpacklo_epi32(_mm256_castsi256_si128(s), _mm256_extracti128_si256::<1>(s));
            (_mm_cvtsi128_si64(v) as u64).to_le_bytes()
        })
    }
}

bitwise_256!(I32x8);

lane_ops! {
    I32x8;
    /// Shifted left by `N` bits.
    fn shl<const N>() -> Self = _mm256_slli_epi32::<N>;
    /// Shifted right by `N` bits, zeros in.
    fn shr<const N>() -> Self = _mm256_srli_epi32::<N>;
    /// Shifted right by `N` bits, the sign in.
    fn sra<const N>() -> Self = _mm256_srai_epi32::<N>;
    /// Each lane shifted left by the same lane of `n` (0 from 32 on).
    fn shl_var(n) -> Self = _mm256_sllv_epi32;
    /// Each lane shifted right by the same lane of `n`, zeros in (0 from 32 on).
    fn shr_var(n) -> Self = _mm256_srlv_epi32;
    /// `vpblendvb`: per byte `o` where the byte's sign bit in `mask` is set, else `self`
    /// (per lane, for masks of all ones or zero).
    fn blendv(o, mask) -> Self = _mm256_blendv_epi8;
    /// `vpermd`: lane `i` is lane `idx[i] & 7` of `self`.
    fn permute_var(idx) -> Self = _mm256_permutevar8x32_epi32;
    /// Converted to f32 (rounded to nearest).
    fn to_f32() -> F32x8 = _mm256_cvtepi32_ps;
    /// The same bits as eight f32 lanes.
    fn as_f32() -> F32x8 = _mm256_castsi256_ps;
    /// `vpunpcklbw`: the low 8 bytes of each 128-bit half interleaved with those of `o`
    /// (with `o` zero: those bytes zero-extended to u16).
    fn unpack_lo_u8(o) -> U16x16 = _mm256_unpacklo_epi8;
    /// `vpunpckhbw`: as [`Self::unpack_lo_u8`] for the high 8 bytes of each half.
    fn unpack_hi_u8(o) -> U16x16 = _mm256_unpackhi_epi8;
    /// Wrapping `self + o` per lane.
    fn add(o) -> Self = _mm256_add_epi32;
    /// Wrapping `self - o` per lane.
    fn sub(o) -> Self = _mm256_sub_epi32;
    /// The low 32 bits of `self * o` per lane.
    fn mullo(o) -> Self = _mm256_mullo_epi32;
    /// Bitwise exclusive or.
    fn xor(o) -> Self = _mm256_xor_si256;
    /// `self > o` per lane (signed) as a mask.
    fn cmpgt(o) -> Self = _mm256_cmpgt_epi32;
    /// `self == o` per lane as a mask.
    fn cmpeq(o) -> Self = _mm256_cmpeq_epi32;
    /// `vpackusdw`: per 128-bit half, the four lanes of `self` then those of `o` as u16
    /// (saturated to 0..=65535), sixteen u16 in the bits of the result.
    fn pack_u16(o) -> Self = _mm256_packus_epi32;
    /// `vpermq` with an immediate: 64-bit lane `i` is lane `(IMM >> 2i) & 3`.
    fn permute_q<const IMM>() -> Self = _mm256_permute4x64_epi64::<IMM>;
    /// Signed minimum per lane.
    fn min(o) -> Self = _mm256_min_epi32;
    /// Signed maximum per lane.
    fn max(o) -> Self = _mm256_max_epi32;
    /// Unsigned minimum per lane.
    fn min_u32(o) -> Self = _mm256_min_epu32;
    /// Unsigned maximum per lane.
    fn max_u32(o) -> Self = _mm256_max_epu32;
}
