//! The 8-wide AVX2 sampler of the texture fast path ([`super::fast`]): one row of a chunk
//! (8 pixels) whose quads all chose the same filter and levels, sampled at once.
//!
//! Per axis it computes llvmpipe's AoS coordinates with vector ops
//! (`fx = round_half_even(s·size·256) − 128`, `i0 = fx >> 8`, `w = fx & 255`, REPEAT of a
//! power-of-two size as `& (size − 1)`, CLAMP_TO_EDGE as a clamp; NEAREST as
//! `floor(s·size)`; REPEAT of a resource that is not a power of two on the axis as
//! llvmpipe's `npot` code, [`super::wrap::aos_linear`] and [`super::wrap::aos_nearest`]
//! on the fraction of `s`), fetches the texels (LINEAR: each row's two texels as one 8-byte load
//! per pixel, [`quad_texels`]; NEAREST: `vpgatherdd`), and filters the four channels
//! of every pixel in 16-bit fields with the 8-bit lerp `(a·(256 − w) + b·w + 128) >> 8`
//! (x for both rows, then y, then the mip blend), exactly as [`super::fast::quad_u8`]
//! does one pixel at a time. The texels are split once into even and odd bytes (no
//! shuffles) and stay in 16-bit fields through all lerps, packed once at the end.
//!
//! It declines (returns `false`, and the caller samples the row with the scalar code)
//! when a lane's scaled coordinate is not below 2^30 in magnitude or is NaN (where the
//! float → int conversions of the two paths could differ), and for REPEAT of a level that
//! is not a power of two on a resource that is. Its functions inline into the rasterizer's AVX2 entry points and
//! run only when the CPU has AVX2 ([`available`]).

#[cfg(target_arch = "x86_64")]
use crate::simd::{F32x8, I32x8, I64x4, U16x16};

pub mod chunk;

use super::{Level, Wrap};

/// Whether this CPU can run the 8-wide sampler (decided once): an AVX2 [`crate::cpu::isa`],
/// which also has POPCNT, BMI1, BMI2 and LZCNT.
pub fn available() -> bool {
    crate::cpu::isa().avx2()
}

/// Whether the vector sampler handles a wrap mode on an axis: CLAMP_TO_EDGE, or REPEAT
/// (llvmpipe's power-of-two code when the resource is a power of two on the axis, `pot`,
/// and then the level must be one too; else its `npot` code, any size).
#[inline(always)]
pub fn handles(wrap: Wrap, pot: bool, size: usize) -> bool {
    match wrap {
        Wrap::ClampToEdge => true,
        Wrap::Repeat => !pot || size.is_power_of_two(),
        _ => false,
    }
}

/// How the vector sampler wraps one axis: the wrap mode and, for REPEAT, which of
/// llvmpipe's codes (chosen from the resource's level-0 size, see [`super::wrap`]).
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum AxisWrap {
    /// CLAMP_TO_EDGE.
    Clamp,
    /// REPEAT of a power-of-two resource: `& (size − 1)`.
    RepeatPot,
    /// REPEAT of a resource that is not a power of two: on the fraction of `s`.
    RepeatNpot,
}

impl AxisWrap {
    /// The form of `wrap` on an axis whose level-0 size is a power of two when `pot`, for
    /// a wrap mode [`handles`] accepts.
    #[inline(always)]
    pub fn of(wrap: Wrap, pot: bool) -> Self {
        match wrap {
            Wrap::Repeat if pot => AxisWrap::RepeatPot,
            Wrap::Repeat => AxisWrap::RepeatNpot,
            _ => AxisWrap::Clamp,
        }
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
    pub wrap: [AxisWrap; 2],
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
    s: F32x8,
    lv: &LevelV<'_>,
    ax: usize,
    wrap: AxisWrap,
    linear: bool,
    ok: &mut F32x8,
) -> (I32x8, I32x8, I32x8) {
    // SAFETY: AVX2 context (the caller's promise).
    unsafe {
        let last = I32x8::splat(lv.last[ax]);
        let zero = I32x8::zero();
        let limit = F32x8::splat(1_073_741_824.0);
        let abs_mask = I32x8::splat(0x7fff_ffff).as_f32();
        #[inline(always)]
        unsafe fn wrap_index(i: I32x8, repeat: bool, last: I32x8) -> I32x8 {
            // SAFETY: AVX2 context (the caller's promise).
            unsafe {
                if repeat {
                    i.and(last)
                } else {
                    i.max(I32x8::zero()).min(last)
                }
            }
        }
        if wrap == AxisWrap::RepeatNpot {
            // `wrap::aos_linear` / `aos_nearest` on `f = s − floor(s)`: a finite `s` gives
            // `f` in 0..=1, so `u` is below 2^30; NaN and infinities make the row decline.
            let f = s.sub(s.floor());
            if linear {
                let u = f.mul(F32x8::splat(lv.size[ax])).mul(F32x8::splat(256.0));
                *ok = (*ok).and(u.and(abs_mask).cmp_lt(limit));
                let fx = u.to_i32().sub(I32x8::splat(128));
                let w = fx.and(I32x8::splat(255));
                // `fx ≥ −128`: `i0` is −1 (→ last, the unsigned minimum) or in 0..=size.
                let i0 = fx.sra::<8>().min_u32(last);
                let i1 = i0.add(I32x8::splat(1)).blendv(zero, i0.cmpeq(last));
                return (i0, i1, w);
            }
            // `fract_safe` (the minimum returns its second operand for a NaN, as `f32::min`
            // returns the number); the product truncated, then clamped.
            let f = f.min(F32x8::splat(f32::from_bits(0x3f7f_ffff)));
            let u = f.mul(F32x8::splat(lv.size[ax]));
            *ok = (*ok).and(u.and(abs_mask).cmp_lt(limit));
            return (wrap_index(u.to_i32_trunc(), false, last), zero, zero);
        }
        let repeat = wrap == AxisWrap::RepeatPot;
        if linear {
            let u = s.mul(F32x8::splat(lv.size256[ax]));
            // NaN compares false: such lanes make the row decline.
            *ok = (*ok).and(u.and(abs_mask).cmp_lt(limit));
            let fx = u.to_i32().sub(I32x8::splat(128));
            let w = fx.and(I32x8::splat(255));
            let i0 = fx.sra::<8>();
            let i1 = i0.add(I32x8::splat(1));
            (
                wrap_index(i0, repeat, last),
                wrap_index(i1, repeat, last),
                w,
            )
        } else {
            let u = s.mul(F32x8::splat(lv.size[ax])).floor();
            *ok = (*ok).and(u.and(abs_mask).cmp_lt(limit));
            (wrap_index(u.to_i32_trunc(), repeat, last), zero, zero)
        }
    }
}

/// 8 RGBA8 pixels as two vectors of 16-bit fields: `.0` the even bytes (R, B), `.1` the
/// odd bytes (G, A), each pixel's two fields in its own 32-bit lane. The lerps work on
/// this form without any shuffle; [`pack`] puts the bytes back.
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy)]
struct Wide(U16x16, U16x16);

/// Splits 8 RGBA8 pixels into [`Wide`] fields.
///
/// # Safety
/// Must be called from a function compiled with AVX2.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn widen(v: I32x8) -> Wide {
    let v = v.as_u16();
    // SAFETY: AVX2 context (the caller's promise).
    Wide(v.and(unsafe { U16x16::splat(0xff) }), v.shr::<8>())
}

/// The bytes of [`Wide`] fields that hold values in 0..=255.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn pack(v: Wide) -> I32x8 {
    v.0.or(v.1.shl::<8>()).as_i32()
}

/// A per-pixel weight (`w` in 0..=255 per 32-bit lane) as [`lerp16`] takes it: `w · 128`
/// in both 16-bit fields of its lane. Every weight is below 256: an axis weight is
/// `fx & 255`, and a mip blend weight is `trunc(fpart · 256)` where `fpart = lod −
/// floor(lod)` of a positive LOD, which that subtraction gives exactly, so below 1. (A
/// magnified lane's `fpart` may round to 1.0, but it samples one level, whose row ignores
/// the mip weight; any lane would only get a wrong value, never leave its bounds.)
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn weight(w: I32x8) -> U16x16 {
    w.shl::<7>().or(w.shl::<23>()).as_u16()
}

/// llvmpipe's 8-bit lerp `(a·(256 − w) + b·w + 128) >> 8` on 16-bit fields holding
/// 0..=255, `w` in 0..=255 per field, given as `w7 = w · 128` ([`weight`]): it equals
/// `a + ((b − a)·w + 128) >> 8`, and `vpmulhrsw` computes `((b − a)·w7 + 2^14) >> 15`,
/// which is that rounded quotient (`(b − a)` fits 9 signed bits and `w7` below 2^15, so
/// neither overflows; `lerp16_matches_lerp8` checks every input). Three operations where
/// the shift-multiply-round form takes six. A function, not a closure: a closure in an
/// `#[inline(always)]` function without `target_feature` is compiled without AVX2 and
/// called out of line (measured: 4x the frame time of tex_trilinear_plane).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn lerp16(a: U16x16, b: U16x16, w7: U16x16) -> U16x16 {
    a.add(b.sub(a).mulhrs(w7))
}

/// [`lerp16`] of both halves of [`Wide`] pixels with weights from [`weight`].
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn lerp_wide(a: Wide, b: Wide, w: U16x16) -> Wide {
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
    wrap: [AxisWrap; 2],
    s: F32x8,
    t: F32x8,
    ok: &mut F32x8,
) -> Wide {
    // SAFETY: AVX2 context (the caller's promise); the gathers' indices are checked below.
    unsafe {
        let base = lv.texels.as_ptr() as *const i32;
        let (x0, x1, wx) = axis(s, lv, 0, wrap[0], linear, ok);
        let (y0, y1, wy) = axis(t, lv, 1, wrap[1], linear, ok);
        if (*ok).movemask() != 0xff {
            let z = U16x16::zero();
            return Wide(z, z);
        }
        // Not a closure: see `lerp16`.
        #[inline(always)]
        unsafe fn row(lv: &LevelV<'_>, y: I32x8) -> I32x8 {
            // SAFETY: AVX2 context (the caller's promise).
            unsafe {
                match lv.shift {
                    Some(k) => y.shl_var(I32x8::splat(k as i32)),
                    None => y.mullo(I32x8::splat(lv.stride)),
                }
            }
        }
        let r0 = row(lv, y0);
        // SAFETY: (all gathers) every index is wrapped or clamped into 0..w and 0..h above
        // (the lanes passed the range check), so y·w + x < w·h = texels.len(); the texels are
        // 4 bytes each, read as unaligned i32.
        #[inline(always)]
        unsafe fn gather(base: *const i32, r: I32x8, x: I32x8) -> I32x8 {
            // SAFETY: AVX2 context; the caller's indices are in bounds (see above).
            unsafe { I32x8::gather(base, r.add(x)) }
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
    r: [I32x8; 2],
    x0: I32x8,
    x1: I32x8,
) -> [I32x8; 4] {
    // SAFETY: AVX2 context and in-bounds indices (the caller's promise).
    unsafe {
        /// The pairs of texels (x, x + 1) at row offsets `r` for 8 lanes, split into the
        /// first and second texels, where `x = min(xs, last − 1)`: always inside the row.
        #[inline(always)]
        unsafe fn row_pairs(base: *const i32, r: I32x8, x: I32x8) -> (I32x8, I32x8) {
            // SAFETY: AVX2 context (the caller's promise); `ix` is 8 i32 (32 bytes), and each `pair` reads texels `x` and `x + 1` of a row, `x <= last - 1` (the caller's bound).
            unsafe {
                let mut ix = [0i32; 8];
                r.add(x).store(ix.as_mut_ptr());
                /// Texels `ix[k]` and `ix[k] + 1` as one 64-bit value (not a closure: see
                /// `lerp16`).
                #[inline(always)]
                unsafe fn pair(base: *const i32, ix: &[i32; 8], k: usize) -> i64 {
                    // SAFETY: (by the caller) `ix[k]` and `ix[k] + 1` index texels of `base`.
                    unsafe { std::ptr::read_unaligned(base.add(ix[k] as usize) as *const i64) }
                }
                // Lanes (0, 1, 4, 5) and (2, 3, 6, 7): one `shufps` per output then puts the
                // lanes in order within each 128-bit half.
                let p = I64x4::new([
                    pair(base, &ix, 0),
                    pair(base, &ix, 1),
                    pair(base, &ix, 4),
                    pair(base, &ix, 5),
                ]);
                let o = I64x4::new([
                    pair(base, &ix, 2),
                    pair(base, &ix, 3),
                    pair(base, &ix, 6),
                    pair(base, &ix, 7),
                ]);
                let (p, o) = (p.as_i32().as_f32(), o.as_i32().as_f32());
                (p.shuffle::<0x88>(o).bits(), p.shuffle::<0xDD>(o).bits())
            }
        }
        let lastv = I32x8::splat(last);
        let pmax = I32x8::splat(last - 1);
        let xa = x0.min(pmax);
        let (tl, tr) = row_pairs(base, r[0], xa);
        let (bl, br) = row_pairs(base, r[1], xa);
        let adjacent = x1.cmpeq(x0.add(I32x8::splat(1)));
        if adjacent.movemask() == 0xff {
            return [tl, tr, bl, br];
        }
        // Seams: x0 is the pair's second texel where x0 = last; x1 comes from its own pair.
        let (a_hi, b_hi) = (x0.cmpeq(lastv), x1.cmpeq(lastv));
        let xb = x1.min(pmax);
        let (tr_lo, tr_hi) = row_pairs(base, r[0], xb);
        let (br_lo, br_hi) = row_pairs(base, r[1], xb);
        [
            tl.blendv(tr, a_hi),
            tr_lo.blendv(tr_hi, b_hi),
            bl.blendv(br, a_hi),
            br_lo.blendv(br_hi, b_hi),
        ]
    }
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
    pub wrap: [AxisWrap; 2],
}

impl RowSamplerV<'_> {
    /// [`RowSampler::row_v`] with the prepared levels.
    ///
    /// # Safety
    /// As [`RowSampler::row`].
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    pub unsafe fn row_v(&self, s: F32x8, t: F32x8, wmip: I32x8) -> (I32x8, bool) {
        // SAFETY: forwarded from the caller.
        unsafe {
            let mut ok = I32x8::splat(-1).as_f32();
            let mut v = level8(&self.a, self.linear, self.wrap, s, t, &mut ok);
            if let Some(b) = &self.b {
                let vb = level8(b, self.linear, self.wrap, s, t, &mut ok);
                v = lerp_wide(v, vb, weight(wmip));
            }
            (pack(v), ok.movemask() == 0xff)
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
    /// CPU that has it ([`available`]). Elsewhere it compiles to calls that must not run;
    /// off x86-64 it is never called ([`available`] is false) and declines.
    #[inline(always)]
    pub unsafe fn row(
        &self,
        s: &[f32; 8],
        t: &[f32; 8],
        wmip: &[i32; 8],
        out: &mut [[u8; 4]; 8],
    ) -> bool {
        #[cfg(target_arch = "x86_64")]
        // SAFETY: the arrays are 8 f32 / i32 (32 bytes); unaligned loads and store.
        unsafe {
            let (vs, vt) = (F32x8::load(s.as_ptr()), F32x8::load(t.as_ptr()));
            let w = I32x8::load(wmip.as_ptr());
            let (v, ok) = self.row_v(vs, vt, w);
            if ok {
                v.store(out.as_mut_ptr());
            }
            ok
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            let _ = (s, t, wmip, out);
            false
        }
    }

    /// [`RowSampler::row`] on registers: the texels and whether they are valid (else the
    /// row must be sampled by the scalar code).
    ///
    /// # Safety
    /// As [`RowSampler::row`].
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    pub unsafe fn row_v(&self, s: F32x8, t: F32x8, wmip: I32x8) -> (I32x8, bool) {
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
                    widen(I32x8::load(a.as_ptr())),
                    widen(I32x8::load(b.as_ptr())),
                );
                let vw = weight(I32x8::load(w.as_ptr()));
                let v = pack(lerp_wide(va, vb, vw));
                v.store(out.as_mut_ptr());
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
