//! The 8-wide AVX2 sampler of the texture fast path ([`super::fast`]): one row of a chunk
//! (8 pixels) whose quads all chose the same filter and levels, sampled at once.
//!
//! Per axis it computes llvmpipe's AoS coordinates with vector ops
//! (`fx = round_half_even(s·size·256) − 128`, `i0 = fx >> 8`, `w = fx & 255`, REPEAT of a
//! power-of-two size as `& (size − 1)`, CLAMP_TO_EDGE as a clamp; NEAREST as
//! `floor(s·size)`), fetches the texels (LINEAR: each row's two texels as one 8-byte load
//! per pixel, [`quad_texels`]; NEAREST: `vpgatherdd`), and filters the four channels
//! of every pixel in 16-bit fields with the 8-bit lerp `(a·(256 − w) + b·w + 128) >> 8`
//! (x for both rows, then y, then the mip blend), exactly as [`super::fast::quad_u8`]
//! does one pixel at a time. The texels are split once into even and odd bytes (no
//! shuffles) and stay in 16-bit fields through all lerps, packed once at the end.
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

/// Whether this CPU can run the 8-wide sampler (decided once): an AVX2 [`crate::cpu::isa`],
/// which also has POPCNT, BMI1, BMI2 and LZCNT.
pub fn available() -> bool {
    crate::cpu::isa().avx2()
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

/// A level as the vector sampler reads it: its constants are computed once (per
/// triangle, or per row for [`RowSampler`]) and read from memory as broadcasts, so the
/// gathers' addresses depend on the coordinates only, not on converting the level's size.
#[derive(Clone, Copy)]
pub struct LevelV<'a> {
    /// The texels, row by row.
    texels: &'a [[u8; 4]],
    /// Width and height as f32 (exact: sizes are far below 2^24).
    size: [f32; 2],
    /// `size · 256` (LINEAR's fixed-point scale; exact).
    size256: [f32; 2],
    /// Width − 1 and height − 1.
    last: [i32; 2],
    /// The row stride in texels (the width).
    stride: i32,
    /// log2 of the width when it is a power of two: the row offset is then a shift (one
    /// cycle) instead of `vpmulld` (ten).
    shift: Option<u32>,
}

impl<'a> LevelV<'a> {
    /// The constants of `img`.
    #[inline(always)]
    pub fn of(img: &'a Level) -> Self {
        let (w, h) = (img.width, img.height);
        debug_assert!(img.texels.len() >= w * h && w * h <= i32::MAX as usize);
        LevelV {
            texels: &img.texels[..w * h],
            size: [w as f32, h as f32],
            size256: [w as f32 * 256.0, h as f32 * 256.0],
            last: [w as i32 - 1, h as i32 - 1],
            stride: w as i32,
            shift: w.is_power_of_two().then(|| w.trailing_zeros()),
        }
    }
}

/// Texel indices along axis `ax` of `lv`: `(i0, i1, weight)` for LINEAR, `(i, _, _)` for
/// NEAREST.
///
/// # Safety
/// Must be called from a function compiled with AVX2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn axis(
    s: __m256,
    lv: &LevelV<'_>,
    ax: usize,
    wrap: Wrap,
    linear: bool,
    ok: &mut __m256,
) -> (__m256i, __m256i, __m256i) {
    let last = _mm256_set1_epi32(lv.last[ax]);
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
    if linear {
        let u = _mm256_mul_ps(s, _mm256_set1_ps(lv.size256[ax]));
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
        let u = _mm256_floor_ps(_mm256_mul_ps(s, _mm256_set1_ps(lv.size[ax])));
        *ok = _mm256_and_ps(
            *ok,
            _mm256_cmp_ps(_mm256_and_ps(u, abs_mask), limit, _CMP_LT_OQ),
        );
        (wrap_index(_mm256_cvttps_epi32(u), repeat, last), zero, zero)
    }
}

/// 8 RGBA8 pixels as two vectors of 16-bit fields: `.0` the even bytes (R, B), `.1` the
/// odd bytes (G, A), each pixel's two fields in its own 32-bit lane. The lerps work on
/// this form without any shuffle; [`pack`] puts the bytes back.
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
struct Wide(__m256i, __m256i);

/// Splits 8 RGBA8 pixels into [`Wide`] fields.
///
/// # Safety
/// Must be called from a function compiled with AVX2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn widen(v: __m256i) -> Wide {
    Wide(
        _mm256_and_si256(v, _mm256_set1_epi16(0xff)),
        _mm256_srli_epi16::<8>(v),
    )
}

/// The bytes of [`Wide`] fields that hold values in 0..=255.
///
/// # Safety
/// Must be called from a function compiled with AVX2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn pack(v: Wide) -> __m256i {
    _mm256_or_si256(v.0, _mm256_slli_epi16::<8>(v.1))
}

/// A per-pixel weight (`w` in 0..=255 per 32-bit lane) as [`lerp16`] takes it: `w · 128`
/// in both 16-bit fields of its lane. Every weight is below 256: an axis weight is
/// `fx & 255`, and a mip blend weight is `trunc(fpart · 256)` where `fpart = lod −
/// floor(lod)` of a positive LOD, which that subtraction gives exactly, so below 1. (A
/// magnified lane's `fpart` may round to 1.0, but it samples one level, whose row ignores
/// the mip weight; any lane would only get a wrong value, never leave its bounds.)
///
/// # Safety
/// Must be called from a function compiled with AVX2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn weight(w: __m256i) -> __m256i {
    _mm256_or_si256(_mm256_slli_epi32::<7>(w), _mm256_slli_epi32::<23>(w))
}

/// llvmpipe's 8-bit lerp `(a·(256 − w) + b·w + 128) >> 8` on 16-bit fields holding
/// 0..=255, `w` in 0..=255 per field, given as `w7 = w · 128` ([`weight`]): it equals
/// `a + ((b − a)·w + 128) >> 8`, and `vpmulhrsw` computes `((b − a)·w7 + 2^14) >> 15`,
/// which is that rounded quotient (`(b − a)` fits 9 signed bits and `w7` below 2^15, so
/// neither overflows; `lerp16_matches_lerp8` checks every input). Three operations where
/// the shift-multiply-round form takes six. A function, not a closure: a closure in an
/// `#[inline(always)]` function without `target_feature` is compiled without AVX2 and
/// called out of line (measured: 4x the frame time of tex_trilinear_plane).
///
/// # Safety
/// Must be called from a function compiled with AVX2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn lerp16(a: __m256i, b: __m256i, w7: __m256i) -> __m256i {
    _mm256_add_epi16(a, _mm256_mulhrs_epi16(_mm256_sub_epi16(b, a), w7))
}

/// [`lerp16`] of both halves of [`Wide`] pixels with weights from [`weight`].
///
/// # Safety
/// Must be called from a function compiled with AVX2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn lerp_wide(a: Wide, b: Wide, w: __m256i) -> Wide {
    Wide(lerp16(a.0, b.0, w), lerp16(a.1, b.1, w))
}

/// One level of 8 pixels, as [`Wide`] fields.
///
/// # Safety
/// Must be called from a function compiled with AVX2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn level8(
    lv: &LevelV<'_>,
    linear: bool,
    wrap: [Wrap; 2],
    s: __m256,
    t: __m256,
    ok: &mut __m256,
) -> Wide {
    let base = lv.texels.as_ptr() as *const i32;
    let (x0, x1, wx) = axis(s, lv, 0, wrap[0], linear, ok);
    let (y0, y1, wy) = axis(t, lv, 1, wrap[1], linear, ok);
    if _mm256_movemask_ps(*ok) != 0xff {
        let z = _mm256_setzero_si256();
        return Wide(z, z);
    }
    // Not a closure: see `lerp16`.
    #[inline(always)]
    unsafe fn row(lv: &LevelV<'_>, y: __m256i) -> __m256i {
        match lv.shift {
            Some(k) => _mm256_sllv_epi32(y, _mm256_set1_epi32(k as i32)),
            None => _mm256_mullo_epi32(y, _mm256_set1_epi32(lv.stride)),
        }
    }
    let r0 = row(lv, y0);
    // SAFETY (all gathers): every index is wrapped or clamped into 0..w and 0..h above
    // (the lanes passed the range check), so y·w + x < w·h = texels.len(); the texels are
    // 4 bytes each, read as unaligned i32.
    #[inline(always)]
    unsafe fn gather(base: *const i32, r: __m256i, x: __m256i) -> __m256i {
        _mm256_i32gather_epi32::<4>(base, _mm256_add_epi32(r, x))
    }
    if !linear {
        return widen(gather(base, r0, x0));
    }
    let r1 = row(lv, y1);
    let [tl, tr, bl, br] = if lv.last[0] == 0 {
        // A one-texel-wide level has no pairs to load.
        [
            gather(base, r0, x0),
            gather(base, r0, x1),
            gather(base, r1, x0),
            gather(base, r1, x1),
        ]
    } else {
        quad_texels(base, lv.last[0], [r0, r1], x0, x1)
    };
    let wx = weight(wx);
    let top = lerp_wide(widen(tl), widen(tr), wx);
    let bottom = lerp_wide(widen(bl), widen(br), wx);
    lerp_wide(top, bottom, weight(wy))
}

/// The four texels of 8 LINEAR pixels, (row `r[0]`, x0), (`r[0]`, x1), (`r[1]`, x0),
/// (`r[1]`, x1), each as 8 lanes. Where `x1 = x0 + 1` (every lane but those on a wrap or
/// clamp seam) both texels of a row are one 8-byte load: 16 loads instead of four
/// `vpgatherdd` of 8, which on AMD Zen 4 cost about 5 ns each (measured here: a gather of 8
/// dwords 5.0–6.1 ns, four scalar 8-byte loads 0.9–1.3 ns). A chunk with a seam lane loads
/// the pairs at x1 as well and picks each texel from the pair that holds it.
///
/// # Safety
/// Must be called from a function compiled with AVX2. The level must be at least two
/// texels wide (`last ≥ 1`), and every `r + x0`, `r + x1` lane a texel index of `base`
/// with `x0`, `x1` in `0..=last`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn quad_texels(
    base: *const i32,
    last: i32,
    r: [__m256i; 2],
    x0: __m256i,
    x1: __m256i,
) -> [__m256i; 4] {
    /// The pairs of texels (x, x + 1) at row offsets `r` for 8 lanes, split into the
    /// first and second texels, where `x = min(xs, last − 1)`: always inside the row.
    #[inline(always)]
    unsafe fn row_pairs(base: *const i32, r: __m256i, x: __m256i) -> (__m256i, __m256i) {
        let mut ix = [0i32; 8];
        _mm256_storeu_si256(ix.as_mut_ptr() as *mut __m256i, _mm256_add_epi32(r, x));
        /// Texels `ix[k]` and `ix[k] + 1` as one 64-bit value (not a closure: see
        /// `lerp16`).
        #[inline(always)]
        unsafe fn pair(base: *const i32, ix: &[i32; 8], k: usize) -> i64 {
            // SAFETY (by the caller): `ix[k]` and `ix[k] + 1` index texels of `base`.
            unsafe { std::ptr::read_unaligned(base.add(ix[k] as usize) as *const i64) }
        }
        // Lanes (0, 1, 4, 5) and (2, 3, 6, 7): one `shufps` per output then puts the
        // lanes in order within each 128-bit half.
        let p = _mm256_set_epi64x(
            pair(base, &ix, 5),
            pair(base, &ix, 4),
            pair(base, &ix, 1),
            pair(base, &ix, 0),
        );
        let o = _mm256_set_epi64x(
            pair(base, &ix, 7),
            pair(base, &ix, 6),
            pair(base, &ix, 3),
            pair(base, &ix, 2),
        );
        let (p, o) = (_mm256_castsi256_ps(p), _mm256_castsi256_ps(o));
        (
            _mm256_castps_si256(_mm256_shuffle_ps::<0x88>(p, o)),
            _mm256_castps_si256(_mm256_shuffle_ps::<0xDD>(p, o)),
        )
    }
    let lastv = _mm256_set1_epi32(last);
    let pmax = _mm256_set1_epi32(last - 1);
    let xa = _mm256_min_epi32(x0, pmax);
    let (tl, tr) = row_pairs(base, r[0], xa);
    let (bl, br) = row_pairs(base, r[1], xa);
    let adjacent = _mm256_cmpeq_epi32(x1, _mm256_add_epi32(x0, _mm256_set1_epi32(1)));
    if _mm256_movemask_ps(_mm256_castsi256_ps(adjacent)) == 0xff {
        return [tl, tr, bl, br];
    }
    // Seams: x0 is the pair's second texel where x0 = last; x1 comes from its own pair.
    let (a_hi, b_hi) = (_mm256_cmpeq_epi32(x0, lastv), _mm256_cmpeq_epi32(x1, lastv));
    let xb = _mm256_min_epi32(x1, pmax);
    let (tr_lo, tr_hi) = row_pairs(base, r[0], xb);
    let (br_lo, br_hi) = row_pairs(base, r[1], xb);
    [
        _mm256_blendv_epi8(tl, tr, a_hi),
        _mm256_blendv_epi8(tr_lo, tr_hi, b_hi),
        _mm256_blendv_epi8(bl, br, a_hi),
        _mm256_blendv_epi8(br_lo, br_hi, b_hi),
    ]
}

/// [`RowSampler`] with its levels' constants prepared ([`LevelV`]); the 8-wide walk
/// keeps one per triangle (no LOD) or per level key.
#[derive(Clone, Copy)]
pub struct RowSamplerV<'a> {
    /// The finer level.
    pub a: LevelV<'a>,
    /// The coarser level of a LINEAR mip blend (`None`: no blend).
    pub b: Option<LevelV<'a>>,
    /// LINEAR (else NEAREST) within each level.
    pub linear: bool,
    /// Wrap of s and t.
    pub wrap: [Wrap; 2],
}

impl RowSamplerV<'_> {
    /// [`RowSampler::row_v`] with the prepared levels.
    ///
    /// # Safety
    /// As [`RowSampler::row`].
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    pub unsafe fn row_v(&self, s: __m256, t: __m256, wmip: __m256i) -> (__m256i, bool) {
        // SAFETY: forwarded from the caller.
        unsafe {
            let mut ok = _mm256_castsi256_ps(_mm256_set1_epi32(-1));
            let mut v = level8(&self.a, self.linear, self.wrap, s, t, &mut ok);
            if let Some(b) = &self.b {
                let vb = level8(b, self.linear, self.wrap, s, t, &mut ok);
                v = lerp_wide(v, vb, weight(wmip));
            }
            (pack(v), _mm256_movemask_ps(ok) == 0xff)
        }
    }
}

impl<'a> RowSampler<'a> {
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
        unsafe { self.prepared().row_v(s, t, wmip) }
    }

    /// The sampler with its levels' constants prepared.
    #[inline(always)]
    pub fn prepared(&self) -> RowSamplerV<'a> {
        RowSamplerV {
            a: LevelV::of(self.a),
            b: self.b.map(LevelV::of),
            linear: self.linear,
            wrap: self.wrap,
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

#[cfg(all(test, target_arch = "x86_64"))]
mod tests {
    use super::*;
    use crate::texture::sample::lerp8 as lerp8_ref;

    /// The vector lerp, through [`widen`], [`weight`], [`lerp_wide`] and [`pack`], on every
    /// `a`, `b` in 0..=255 and `w` in 0..=255 (each triple reaches some byte: `a` runs
    /// over all values, `b` over all residues through the byte offset), against the scalar
    /// lerp.
    #[test]
    fn lerp16_matches_lerp8() {
        if !available() {
            return;
        }
        #[target_feature(enable = "avx2")]
        unsafe fn run(a: [u8; 32], b: [u8; 32], w: [i32; 8]) -> [u8; 32] {
            let mut out = [0u8; 32];
            // SAFETY: AVX2 (this function's feature); the arrays are 32 bytes each.
            unsafe {
                let (va, vb) = (
                    widen(_mm256_loadu_si256(a.as_ptr() as *const __m256i)),
                    widen(_mm256_loadu_si256(b.as_ptr() as *const __m256i)),
                );
                let vw = weight(_mm256_loadu_si256(w.as_ptr() as *const __m256i));
                let v = pack(lerp_wide(va, vb, vw));
                _mm256_storeu_si256(out.as_mut_ptr() as *mut __m256i, v);
            }
            out
        }
        for w0 in 0..=255i32 {
            let w: [i32; 8] = std::array::from_fn(|i| (w0 + i as i32 * 37) % 256);
            for a0 in 0..=255u32 {
                for b0 in (0..=255u32).step_by(8) {
                    let a: [u8; 32] = std::array::from_fn(|i| (a0 + i as u32 * 11) as u8);
                    let b: [u8; 32] = std::array::from_fn(|i| (b0 + i as u32) as u8);
                    // SAFETY: `available` checked that the CPU has AVX2.
                    let out = unsafe { run(a, b, w) };
                    for i in 0..32 {
                        let want = lerp8_ref(a[i], b[i], w[i / 4]);
                        assert_eq!(out[i], want, "a {} b {} w {}", a[i], b[i], w[i / 4]);
                    }
                }
            }
        }
    }
}
