//! The 8-wide AVX2 sampler of the texture fast path ([`super::fast`]): one row of a chunk
//! (8 pixels) whose quads all chose the same filter and levels, sampled at once.
//!
//! Per axis it computes llvmpipe's AoS coordinates with vector ops
//! (`fx = round_half_even(s·size·256) − 128`, `i0 = fx >> 8`, `w = fx & 255`, REPEAT of a
//! power-of-two size as `& (size − 1)`, CLAMP_TO_EDGE as a clamp; NEAREST as
//! `floor(s·size)`), gathers the texels with `vpgatherdd`, and filters the four channels
//! of every pixel in 16-bit fields with the 8-bit lerp `(a·(256 − w) + b·w + 128) >> 8`
//! (x for both rows, then y, then the mip blend), exactly as [`super::fast::quad_u8`]
//! does one pixel at a time.
//!
//! It declines (returns `false`, and the caller samples the row with the scalar code)
//! when a lane's scaled coordinate is not below 2^30 in magnitude or is NaN (where the
//! float → int conversions of the two paths could differ), and for REPEAT of a size that
//! is not a power of two. Its functions inline into the rasterizer's AVX2 entry points and
//! run only when the CPU has AVX2 ([`available`]).

#[cfg(target_arch = "x86_64")]
use std::arch::x86_64::*;

pub mod chunk;

use super::{Level, Wrap};

/// Whether this CPU can run the 8-wide sampler (decided once).
pub fn available() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        matches!(
            crate::cpu::isa(),
            crate::cpu::Isa::Avx2Fma | crate::cpu::Isa::Avx2
        )
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}

/// Whether the vector sampler handles a wrap mode on an axis: CLAMP_TO_EDGE, or REPEAT
/// when llvmpipe picks its power-of-two code (`pot`) and the level is a power of two too.
#[inline(always)]
pub fn handles(wrap: Wrap, pot: bool, size: usize) -> bool {
    match wrap {
        Wrap::ClampToEdge => true,
        Wrap::Repeat => pot && size.is_power_of_two(),
        _ => false,
    }
}

/// What one row needs: the level(s), the filter, the wrap of each axis and whether the
/// resource's level-0 size is a power of two on each axis.
#[derive(Clone, Copy)]
pub struct RowSampler<'a> {
    /// The finer level.
    pub a: &'a Level,
    /// The coarser level of a LINEAR mip blend (`None`: no blend).
    pub b: Option<&'a Level>,
    /// LINEAR (else NEAREST) within each level.
    pub linear: bool,
    /// Wrap of s and t.
    pub wrap: [Wrap; 2],
}

/// Texel indices along one axis: `(i0, i1, weight)` for LINEAR, `(i, _, _)` for NEAREST.
///
/// # Safety
/// Must be called from a function compiled with AVX2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn axis(
    s: __m256,
    size: usize,
    wrap: Wrap,
    linear: bool,
    ok: &mut __m256,
) -> (__m256i, __m256i, __m256i) {
    let len = _mm256_set1_epi32(size as i32);
    let last = _mm256_set1_epi32(size as i32 - 1);
    let zero = _mm256_setzero_si256();
    let limit = _mm256_set1_ps(1_073_741_824.0);
    let abs_mask = _mm256_castsi256_ps(_mm256_set1_epi32(0x7fff_ffff));
    #[inline(always)]
    unsafe fn wrap_index(i: __m256i, repeat: bool, last: __m256i) -> __m256i {
        if repeat {
            _mm256_and_si256(i, last)
        } else {
            _mm256_min_epi32(_mm256_max_epi32(i, _mm256_setzero_si256()), last)
        }
    }
    let repeat = wrap == Wrap::Repeat;
    let _ = len;
    if linear {
        let u = _mm256_mul_ps(s, _mm256_set1_ps(size as f32 * 256.0));
        // NaN compares false: such lanes make the row decline.
        *ok = _mm256_and_ps(
            *ok,
            _mm256_cmp_ps(_mm256_and_ps(u, abs_mask), limit, _CMP_LT_OQ),
        );
        let fx = _mm256_sub_epi32(_mm256_cvtps_epi32(u), _mm256_set1_epi32(128));
        let w = _mm256_and_si256(fx, _mm256_set1_epi32(255));
        let i0 = _mm256_srai_epi32(fx, 8);
        let i1 = _mm256_add_epi32(i0, _mm256_set1_epi32(1));
        (
            wrap_index(i0, repeat, last),
            wrap_index(i1, repeat, last),
            w,
        )
    } else {
        let u = _mm256_floor_ps(_mm256_mul_ps(s, _mm256_set1_ps(size as f32)));
        *ok = _mm256_and_ps(
            *ok,
            _mm256_cmp_ps(_mm256_and_ps(u, abs_mask), limit, _CMP_LT_OQ),
        );
        (wrap_index(_mm256_cvttps_epi32(u), repeat, last), zero, zero)
    }
}

/// llvmpipe's 8-bit lerp of 8 RGBA8 pixels, `w` per pixel in 0..=255.
///
/// # Safety
/// Must be called from a function compiled with AVX2.
/// `(a·(256 − w) + b·w + 128) >> 8` on 16-bit lanes. A function, not a closure: a
/// closure in an `#[inline(always)]` function without `target_feature` is compiled without
/// AVX2 and called out of line (measured: 4x the frame time of tex_trilinear_plane).
///
/// # Safety
/// Must be called from a function compiled with AVX2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn half(a: __m256i, b: __m256i, w: __m256i) -> __m256i {
    let v = _mm256_add_epi16(
        _mm256_add_epi16(
            _mm256_mullo_epi16(a, _mm256_sub_epi16(_mm256_set1_epi16(256), w)),
            _mm256_mullo_epi16(b, w),
        ),
        _mm256_set1_epi16(128),
    );
    _mm256_srli_epi16(v, 8)
}

#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn lerp8(a: __m256i, b: __m256i, w: __m256i) -> __m256i {
    let zero = _mm256_setzero_si256();
    // w in both 16-bit halves, then each pixel's weight in its four channel fields
    // (the unpacks pair pixels 0,1 | 4,5 (lo) and 2,3 | 6,7 (hi) like the byte unpacks).
    let wd = _mm256_or_si256(w, _mm256_slli_epi32(w, 16));
    let (wlo, whi) = (_mm256_unpacklo_epi32(wd, wd), _mm256_unpackhi_epi32(wd, wd));
    let lo = half(
        _mm256_unpacklo_epi8(a, zero),
        _mm256_unpacklo_epi8(b, zero),
        wlo,
    );
    let hi = half(
        _mm256_unpackhi_epi8(a, zero),
        _mm256_unpackhi_epi8(b, zero),
        whi,
    );
    _mm256_packus_epi16(lo, hi)
}

/// One level of 8 pixels.
///
/// # Safety
/// Must be called from a function compiled with AVX2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn level8(
    img: &Level,
    linear: bool,
    wrap: [Wrap; 2],
    s: __m256,
    t: __m256,
    ok: &mut __m256,
) -> __m256i {
    let (w, h) = (img.width, img.height);
    debug_assert!(img.texels.len() >= w * h && w * h <= i32::MAX as usize);
    let base = img.texels.as_ptr() as *const i32;
    let stride = _mm256_set1_epi32(w as i32);
    let (x0, x1, wx) = axis(s, w, wrap[0], linear, ok);
    let (y0, y1, wy) = axis(t, h, wrap[1], linear, ok);
    if _mm256_movemask_ps(*ok) != 0xff {
        return _mm256_setzero_si256();
    }
    let r0 = _mm256_mullo_epi32(y0, stride);
    // SAFETY (all gathers): every index is wrapped or clamped into 0..w and 0..h above
    // (the lanes passed the range check), so y·w + x < w·h ≤ texels.len(); the texels are
    // 4 bytes each, read as unaligned i32.
    #[inline(always)]
    unsafe fn gather(base: *const i32, r: __m256i, x: __m256i) -> __m256i {
        _mm256_i32gather_epi32::<4>(base, _mm256_add_epi32(r, x))
    }
    if !linear {
        return gather(base, r0, x0);
    }
    let r1 = _mm256_mullo_epi32(y1, stride);
    let top = lerp8(gather(base, r0, x0), gather(base, r0, x1), wx);
    let bottom = lerp8(gather(base, r1, x0), gather(base, r1, x1), wx);
    lerp8(top, bottom, wy)
}

impl RowSampler<'_> {
    /// Samples 8 pixels at (`s`, `t`) with mip blend weights `wmip` (ignored without a
    /// second level) into `out`; `false` (and `out` untouched) when the row must be
    /// sampled by the scalar code.
    ///
    /// # Safety
    /// Must be called from a function compiled with AVX2 (the raster entry points), on a
    /// CPU that has it ([`available`]). Elsewhere it compiles to calls that must not run.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    pub unsafe fn row(
        &self,
        s: &[f32; 8],
        t: &[f32; 8],
        wmip: &[i32; 8],
        out: &mut [[u8; 4]; 8],
    ) -> bool {
        // SAFETY: the arrays are 8 f32 / i32 (32 bytes); unaligned loads and store.
        unsafe {
            let (vs, vt) = (_mm256_loadu_ps(s.as_ptr()), _mm256_loadu_ps(t.as_ptr()));
            let w = _mm256_loadu_si256(wmip.as_ptr() as *const __m256i);
            let (v, ok) = self.row_v(vs, vt, w);
            if ok {
                _mm256_storeu_si256(out.as_mut_ptr() as *mut __m256i, v);
            }
            ok
        }
    }

    /// [`RowSampler::row`] on registers: the texels and whether they are valid (else the
    /// row must be sampled by the scalar code).
    ///
    /// # Safety
    /// As [`RowSampler::row`].
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    pub unsafe fn row_v(&self, s: __m256, t: __m256, wmip: __m256i) -> (__m256i, bool) {
        // SAFETY: forwarded from the caller.
        unsafe {
            let mut ok = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
            let mut v = level8(self.a, self.linear, self.wrap, s, t, &mut ok);
            if let Some(b) = self.b {
                let vb = level8(b, self.linear, self.wrap, s, t, &mut ok);
                v = lerp8(v, vb, wmip);
            }
            (v, _mm256_movemask_ps(ok) == 0xff)
        }
    }

    /// Without AVX2 the vector sampler never runs.
    ///
    /// # Safety
    /// Never called ([`available`] is false).
    #[cfg(not(target_arch = "x86_64"))]
    pub unsafe fn row(
        &self,
        _s: &[f32; 8],
        _t: &[f32; 8],
        _wmip: &[i32; 8],
        _out: &mut [[u8; 4]; 8],
    ) -> bool {
        false
    }
}
