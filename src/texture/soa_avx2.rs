//! The 8-wide AVX2 sampler of llvmpipe's float (SoA) path for 2D textures: both rows of a
//! chunk (four 2x2 quads) of a GL_TEXTURE_2D unit that is not on the 8-bit AoS path
//! (GL_CLAMP, CLAMP_TO_BORDER, MIRRORED_REPEAT wraps, a REPEAT of a non-power-of-two
//! texture beside another wrap, sRGB and signed textures), sampled a row (8 pixels) at a
//! time with exactly the arithmetic of `UnitPlan::sample_quad` (`sample::soa_filter`).
//!
//! Per quad it takes the scalar code's LOD and level selection (`UnitPlan::quad_lod`,
//! `sample::select_levels`: four quads a chunk, every lane of a quad shares them). Then,
//! for each (filter, level) the chunk's quads select, it runs one 8-lane pass over a row:
//! per axis the wrap of `wrap::soa_nearest` / `wrap::soa_linear` on floats (floor,
//! fraction, `mirror`, `fract_safe`, the clamps in the scalar order, indices clamped or
//! masked, border lanes as masks), the taps gathered (`vpgatherdd`) and made floats as
//! `sample::texel_float` does (`u·f32(1/255)`, or the plan's decode tables), the border
//! colour blended in, and the lerps `w·(b − a) + a`, fused exactly when the unit's lerps
//! are (`UnitPlan::fma`). Each lane then takes its quad's level(s) from the passes, and
//! the mip lerp between two levels where they differ. A chunk whose quads all select one
//! level (the common case) costs one pass per row, two with a LINEAR mip filter.
//!
//! It declines ([`Soa8::of`]) float textures, depth textures, anisotropy and every other
//! target. A quad with a coordinate (of any of its four pixels) that is NaN, infinite or
//! of magnitude 2^16 or more is left to the scalar code ([`Soa8::rows`]' mask), so that
//! `s·size` stays below 2^30 and the float → int conversions of both paths agree. Its
//! functions inline into the rasterizer's AVX2 entry points and run only when the CPU
//! has AVX2 ([`super::fast_avx2::available`]).

use super::sample::{select_levels, INV_255};
use super::{ExtKind, Filter, Level, UnitPlan, Wrap, MAX_TEXTURE_SIZE};
use crate::simd::{F32x8, I32x8};

/// Coordinates of this magnitude or more (and NaN) are left to the scalar code.
const BOUND: f32 = 65536.0;

/// A unit's state when the 8-wide float sampler covers it.
#[derive(Clone, Copy)]
pub struct Soa8<'a> {
    /// The unit.
    p: &'a UnitPlan<'a>,
}

/// One axis of a row's taps: texel indices (clamped or masked into the level) and which
/// lanes read the border colour instead (masks).
#[derive(Clone, Copy)]
struct Axis {
    /// The first (or only) tap's index.
    i0: I32x8,
    /// The second tap's index (LINEAR).
    i1: I32x8,
    /// The first tap is outside the level.
    b0: I32x8,
    /// The second tap is outside the level.
    b1: I32x8,
    /// The LINEAR weight.
    w: F32x8,
}

/// A pass: one image filter at one level.
type Key = (Filter, usize);

impl<'a> Soa8<'a> {
    /// The sampler of unit `p`, when it covers the unit's state.
    #[inline(always)]
    pub fn of(p: &'a UnitPlan<'a>) -> Option<Soa8<'a>> {
        if p.aos
            || p.dims != 2
            || !matches!(p.ext.kind, ExtKind::Flat)
            || p.ext.depth.is_some()
            || p.ext.floats
            || p.max_anisotropy > 1.0
        {
            return None;
        }
        // the levels after the base are smaller (a complete chain); `BOUND·size` < 2^30
        let b = p.image(p.first);
        if b.width > MAX_TEXTURE_SIZE || b.height > MAX_TEXTURE_SIZE {
            return None;
        }
        Some(Soa8 { p })
    }

    /// Samples both rows of a chunk at `s`, `t` into `out`, except the quads it returns
    /// (bit `j`: lanes `2j`, `2j + 1` of both rows), which have a live pixel and a
    /// coordinate it does not follow, for the caller to sample with the scalar code.
    /// Lanes of quads without a live pixel, and of a row without one, may receive any
    /// value.
    ///
    /// # Safety
    /// The CPU has AVX2, and FMA when the unit's lerps fuse.
    #[inline(always)]
    #[allow(clippy::needless_range_loop)]
    pub unsafe fn rows(
        &self,
        s: &[[f32; 8]; 2],
        t: &[[f32; 8]; 2],
        live: &[[bool; 8]; 2],
        out: [&mut [[f32; 4]; 8]; 2],
    ) -> u32 {
        let p = self.p;
        let qlive = live_quads(live);
        if qlive == 0 {
            return 0;
        }
        // SAFETY: (all) the caller vouches for AVX2 (and FMA when the lerps fuse); the
        // arrays are 8 lanes each.
        unsafe {
            // (no closures here or below: one the compiler leaves out of line loses the
            // caller's target features)
            let v = [
                [F32x8::load(s[0].as_ptr()), F32x8::load(t[0].as_ptr())],
                [F32x8::load(s[1].as_ptr()), F32x8::load(t[1].as_ptr())],
            ];
            let bound = F32x8::splat(BOUND);
            // lanes (of either row) with a coordinate the vectors do not follow
            let mut bad = 0u32;
            for row in 0..2 {
                for c in v[row] {
                    // |c| < 2^16: false for NaN and infinities
                    bad |= !abs(c).cmp_lt(bound).movemask() & 0xff;
                }
            }
            // each quad's level selection, from the scalar code
            let mut redo = 0u32;
            let mut keys = [(Filter::Nearest, 0usize); 8];
            let mut nkeys = 0;
            let (mut ka, mut kb, mut frac) = ([-1i32; 8], [-1i32; 8], [0.0f32; 8]);
            for j in 0..4 {
                let (a, b) = (2 * j, 2 * j + 1);
                if qlive >> j & 1 == 0 {
                    continue;
                }
                if bad >> a & 3 != 0 {
                    redo |= 1 << j;
                    continue;
                }
                let qs = [s[0][a], s[0][b], s[1][a], s[1][b]];
                let qt = [t[0][a], t[0][b], t[1][a], t[1][b]];
                let (filter, l0, l1, f) = select_levels(p, p.quad_lod(qs, qt));
                let i0 = key_index(&mut keys, &mut nkeys, (filter, l0));
                let i1 = if l1 != l0 {
                    key_index(&mut keys, &mut nkeys, (filter, l1))
                } else {
                    -1
                };
                (ka[a], ka[b], kb[a], kb[b], frac[a], frac[b]) = (i0, i0, i1, i1, f, f);
            }
            if nkeys == 0 {
                return redo;
            }
            let (ka, kb) = (I32x8::load(ka.as_ptr()), I32x8::load(kb.as_ptr()));
            let frac = F32x8::load(frac.as_ptr());
            // lanes that blend two levels
            let two = kb.cmpgt(I32x8::splat(-1));
            let one_level = two.movemask() == 0;
            for (row, out) in out.into_iter().enumerate() {
                // a row without a live pixel (a line's or a triangle's edge) is not read
                if !live[row].iter().any(|&l| l) {
                    continue;
                }
                // the other lanes' coordinates made 0, so that every tap is in range
                let ok = [abs(v[row][0]).cmp_lt(bound), abs(v[row][1]).cmp_lt(bound)];
                let (sr, tr) = (v[row][0].and(ok[0]), v[row][1].and(ok[1]));
                if nkeys == 1 && one_level {
                    // every live quad's one level (the common case): the pass as it is
                    let (filter, level) = keys[0];
                    store_pixels(self.pass(filter, p.image(level), sr, tr), out);
                    continue;
                }
                let mut a = [F32x8::zero(); 4];
                let mut b = a;
                for (i, &(filter, level)) in keys[..nkeys].iter().enumerate() {
                    let c = self.pass(filter, p.image(level), sr, tr);
                    let ki = I32x8::splat(i as i32);
                    let ma = ka.cmpeq(ki).as_f32();
                    let mb = kb.cmpeq(ki).as_f32();
                    for ch in 0..4 {
                        a[ch] = a[ch].blendv(c[ch], ma);
                        b[ch] = b[ch].blendv(c[ch], mb);
                    }
                }
                let c = if one_level {
                    a
                } else {
                    let two = two.as_f32();
                    [
                        a[0].blendv(self.lerp(frac, a[0], b[0]), two),
                        a[1].blendv(self.lerp(frac, a[1], b[1]), two),
                        a[2].blendv(self.lerp(frac, a[2], b[2]), two),
                        a[3].blendv(self.lerp(frac, a[3], b[3]), two),
                    ]
                };
                store_pixels(c, out);
            }
            redo
        }
    }

    /// One row filtered with `filter` in `img` at (finite, bounded) `s`, `t`
    /// (`sample::soa_taps`).
    ///
    /// # Safety
    /// The CPU has AVX2, and FMA when the unit's lerps fuse.
    #[inline(always)]
    unsafe fn pass(&self, filter: Filter, img: &Level, s: F32x8, t: F32x8) -> [F32x8; 4] {
        let p = self.p;
        let (w, h) = (img.width, img.height);
        // SAFETY: forwarded from the caller.
        unsafe {
            match filter {
                Filter::Nearest => {
                    let (x, bx) = nearest(s, w, p.pot[0], p.wrap_s);
                    let (y, by) = nearest(t, h, p.pot[1], p.wrap_t);
                    self.fetch(img, x, y, bx.or(by))
                }
                Filter::Linear => {
                    let x = linear(s, w, p.pot[0], p.wrap_s);
                    let y = linear(t, h, p.pot[1], p.wrap_t);
                    let n00 = self.fetch(img, x.i0, y.i0, x.b0.or(y.b0));
                    let n01 = self.fetch(img, x.i1, y.i0, x.b1.or(y.b0));
                    let n10 = self.fetch(img, x.i0, y.i1, x.b0.or(y.b1));
                    let n11 = self.fetch(img, x.i1, y.i1, x.b1.or(y.b1));
                    [
                        bilerp(p.fma, x.w, y.w, [n00[0], n01[0], n10[0], n11[0]]),
                        bilerp(p.fma, x.w, y.w, [n00[1], n01[1], n10[1], n11[1]]),
                        bilerp(p.fma, x.w, y.w, [n00[2], n01[2], n10[2], n11[2]]),
                        bilerp(p.fma, x.w, y.w, [n00[3], n01[3], n10[3], n11[3]]),
                    ]
                }
            }
        }
    }

    /// The texels at (`x`, `y`) of `img` as floats, the border colour where `border`.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    unsafe fn fetch(&self, img: &Level, x: I32x8, y: I32x8, border: I32x8) -> [F32x8; 4] {
        // SAFETY: forwarded from the caller; the gather reads indices clamped into the
        // level (unsigned: a negative one becomes the last texel).
        unsafe {
            let zero = I32x8::zero();
            let i = y.mullo(I32x8::splat(img.width as i32)).add(x);
            let last = I32x8::splat((img.texels.len() as i32).max(1) - 1);
            let i = i.blendv(zero, border).min_u32(last);
            let raw = I32x8::gather(img.texels.as_ptr() as *const i32, i);
            let v = texels8(self.p, raw);
            if border.movemask() == 0 {
                return v;
            }
            let bc = self.p.border;
            let m = border.as_f32();
            [
                v[0].blendv(F32x8::splat(bc[0]), m),
                v[1].blendv(F32x8::splat(bc[1]), m),
                v[2].blendv(F32x8::splat(bc[2]), m),
                v[3].blendv(F32x8::splat(bc[3]), m),
            ]
        }
    }

    /// `lerpf(fma, w, a, b)` per lane.
    #[inline(always)]
    fn lerp(&self, w: F32x8, a: F32x8, b: F32x8) -> F32x8 {
        lerp(self.p.fma, w, a, b)
    }
}

/// The channel registers `c` stored as the 8 pixels' RGBA (`simd::pack::pixels_of`).
///
/// # Safety
/// The CPU has AVX2.
#[inline(always)]
pub(super) unsafe fn store_pixels(c: [F32x8; 4], out: &mut [[f32; 4]; 8]) {
    // SAFETY: forwarded from the caller; `out` is 32 contiguous f32, four 8-lane stores.
    unsafe {
        let p = out.as_mut_ptr() as *mut f32;
        for (j, r) in crate::simd::pack::pixels_of(c).iter().enumerate() {
            r.store(p.add(8 * j));
        }
    }
}

/// `lerpf(fma, w, a, b)` per lane: `w·(b − a) + a`, fused when `fma`.
#[inline(always)]
pub(super) fn lerp(fma: bool, w: F32x8, a: F32x8, b: F32x8) -> F32x8 {
    if fma {
        // SAFETY: the lerps fuse only on CPUs with FMA (`sample::has_fma`).
        unsafe { w.mul_add(b.sub(a), a) }
    } else {
        w.mul(b.sub(a)).add(a)
    }
}

/// The bilinear filter of taps `n` (n00, n01, n10, n11): x for both rows, then y.
#[inline(always)]
pub(super) fn bilerp(fma: bool, wx: F32x8, wy: F32x8, n: [F32x8; 4]) -> F32x8 {
    let r0 = lerp(fma, wx, n[0], n[1]);
    let r1 = lerp(fma, wx, n[2], n[3]);
    lerp(fma, wy, r0, r1)
}

/// The quads of a chunk (bit `j`: lanes `2j`, `2j + 1` of both rows) with a live pixel.
#[inline(always)]
pub(super) fn live_quads(live: &[[bool; 8]; 2]) -> u32 {
    (0..4).fold(0u32, |m, j| {
        let l = live[0][2 * j] || live[0][2 * j + 1] || live[1][2 * j] || live[1][2 * j + 1];
        m | (u32::from(l) << j)
    })
}

/// The index of `key` in `keys[..*n]`, added when new.
#[inline(always)]
fn key_index(keys: &mut [Key; 8], n: &mut usize, key: Key) -> i32 {
    let i = keys[..*n]
        .iter()
        .position(|&k| k == key)
        .unwrap_or_else(|| {
            keys[*n] = key;
            *n += 1;
            *n - 1
        });
    i as i32
}

/// Eight packed RGBA8 texels as floats per channel, as `sample::texel_float` makes them:
/// `u·f32(1/255)`, or through the plan's decode tables ([`super::PlanExt::decode`]).
///
/// # Safety
/// The CPU has AVX2.
#[inline(always)]
pub(super) unsafe fn texels8(p: &UnitPlan<'_>, raw: I32x8) -> [F32x8; 4] {
    // SAFETY: forwarded from the caller; the table gathers read bytes 0..=255 of
    // 256-entry tables.
    unsafe {
        let byte = I32x8::splat(0xff);
        let c = [
            raw.and(byte),
            raw.shr::<8>().and(byte),
            raw.shr::<16>().and(byte),
            raw.shr::<24>(),
        ];
        if let Some(ops) = p.ext.narrow {
            return [
                narrow(c[0], ops[0]),
                narrow(c[1], ops[1]),
                narrow(c[2], ops[2]),
                narrow(c[3], ops[3]),
            ];
        }
        match p.ext.decode {
            Some(t) => {
                let table = |k: usize| t[k].as_ptr() as *const i32;
                [
                    I32x8::gather(table(0), c[0]).as_f32(),
                    I32x8::gather(table(1), c[1]).as_f32(),
                    I32x8::gather(table(2), c[2]).as_f32(),
                    I32x8::gather(table(3), c[3]).as_f32(),
                ]
            }
            None => {
                let k = F32x8::splat(INV_255);
                [
                    c[0].to_f32().mul(k),
                    c[1].to_f32().mul(k),
                    c[2].to_f32().mul(k),
                    c[3].to_f32().mul(k),
                ]
            }
        }
    }
}

/// Bytes `c` (one per lane) of a component decoded as its [`super::unit::NarrowOps`]
/// entry `(max, scale)` says: `float((c·max + 127) / 255) · scale`, the division as
/// `(x·0x8081) >> 23` (exact for x < 2^16; here x ≤ 255·127 + 127), or `c·scale` (scale
/// `f32(1/255)`) where `max` is 0.
///
/// # Safety
/// The CPU has AVX2.
#[inline(always)]
unsafe fn narrow(c: I32x8, (max, scale): (i32, f32)) -> F32x8 {
    // SAFETY: forwarded from the caller.
    unsafe {
        let c = if max == 0 {
            c
        } else {
            c.mullo(I32x8::splat(max))
                .add(I32x8::splat(127))
                .mullo(I32x8::splat(0x8081))
                .shr::<23>()
        };
        c.to_f32().mul(F32x8::splat(scale))
    }
}

/// `|v|` per lane.
#[inline(always)]
fn abs(v: F32x8) -> F32x8 {
    // SAFETY: AVX2 as `v` proves.
    let m = unsafe { I32x8::splat(0x7fff_ffff) };
    v.bits().and(m).as_f32()
}

/// `floor(u)` as an index and `u − floor(u)`.
#[inline(always)]
fn floor_fract(u: F32x8) -> (I32x8, F32x8) {
    let f = u.floor();
    (f.to_i32_trunc(), u.sub(f))
}

/// `x − floor(x)` below 1 (`wrap::fract_safe`).
///
/// # Safety
/// The CPU has AVX2.
#[inline(always)]
unsafe fn fract_safe(x: F32x8) -> F32x8 {
    // SAFETY: forwarded from the caller.
    unsafe {
        x.sub(x.floor())
            .min(F32x8::splat(f32::from_bits(0x3f7f_ffff)))
    }
}

/// `wrap::mirror`: `|2·(x/2 − round(x/2))|`, NaN → 0.
///
/// # Safety
/// The CPU has AVX2.
#[inline(always)]
unsafe fn mirror(s: F32x8) -> F32x8 {
    // SAFETY: forwarded from the caller.
    unsafe {
        let h = s.mul(F32x8::splat(0.5));
        let f = h.sub(h.round_even());
        let m = abs(f.add(f));
        m.and(m.cmp_ord(m))
    }
}

/// `i` clamped to `0..=last`.
#[inline(always)]
fn clamp(i: I32x8, last: I32x8) -> I32x8 {
    // SAFETY: AVX2 as `i` proves.
    i.max(unsafe { I32x8::zero() }).min(last)
}

impl Axis {
    /// Taps that never read the border.
    #[inline(always)]
    fn edge(i0: I32x8, i1: I32x8, w: F32x8) -> Axis {
        // SAFETY: AVX2 as `i0` proves.
        let zero = unsafe { I32x8::zero() };
        Axis {
            i0,
            i1,
            b0: zero,
            b1: zero,
            w,
        }
    }
}

impl Axis {
    /// Taps `i0` and `i0 + 1` that read the border outside `0..=last`.
    #[inline(always)]
    fn border(i0: I32x8, last: I32x8, w: F32x8) -> Axis {
        // SAFETY: AVX2 as `i0` proves.
        let i1 = i0.add(unsafe { I32x8::splat(1) });
        Axis {
            i0,
            i1,
            b0: outside(i0, last),
            b1: outside(i1, last),
            w,
        }
    }
}

/// Lanes of `i` outside `0..=last` (a mask).
#[inline(always)]
fn outside(i: I32x8, last: I32x8) -> I32x8 {
    // SAFETY: AVX2 as `i` proves.
    let zero = unsafe { I32x8::zero() };
    zero.cmpgt(i).or(i.cmpgt(last))
}

/// `wrap::soa_nearest` of (finite, bounded) `s` on an axis of `size` texels: the index
/// and the lanes reading the border.
///
/// # Safety
/// The CPU has AVX2.
#[inline(always)]
unsafe fn nearest(s: F32x8, size: usize, pot: bool, wrap: Wrap) -> (I32x8, I32x8) {
    // SAFETY: forwarded from the caller.
    unsafe {
        let sz = F32x8::splat(size as f32);
        let last = I32x8::splat(size as i32 - 1);
        let zero = I32x8::zero();
        match wrap {
            Wrap::Repeat if pot => (s.mul(sz).floor().to_i32_trunc().and(last), zero),
            Wrap::Repeat => (clamp(fract_safe(s).mul(sz).to_i32_trunc(), last), zero),
            Wrap::Clamp | Wrap::ClampToEdge => (clamp(s.mul(sz).to_i32_trunc(), last), zero),
            Wrap::ClampToBorder => {
                let i = s.mul(sz).floor();
                let inside = i.cmp_ge(F32x8::zero()).and(i.cmp_lt(sz));
                let border = inside.bits().xor(I32x8::splat(-1));
                (i.to_i32_trunc(), border)
            }
            Wrap::MirroredRepeat => (clamp(mirror(s).mul(sz).to_i32_trunc(), last), zero),
        }
    }
}

/// `wrap::soa_linear` of (finite, bounded) `s` on an axis of `size` texels.
///
/// # Safety
/// The CPU has AVX2.
#[inline(always)]
unsafe fn linear(s: F32x8, size: usize, pot: bool, wrap: Wrap) -> Axis {
    // SAFETY: forwarded from the caller.
    unsafe {
        let sz = F32x8::splat(size as f32);
        let half = F32x8::splat(0.5);
        let last = I32x8::splat(size as i32 - 1);
        let (zero, one) = (I32x8::zero(), I32x8::splat(1));
        let fzero = F32x8::zero();
        match wrap {
            Wrap::Repeat if pot => {
                let (i0, w) = floor_fract(s.mul(sz).sub(half));
                Axis::edge(i0.and(last), i0.add(one).and(last), w)
            }
            Wrap::Repeat => {
                let (i0, w) = floor_fract(s.sub(s.floor()).mul(sz).sub(half));
                let i0 = i0.blendv(last, zero.cmpgt(i0)).min(last);
                let i1 = i0.add(one).blendv(zero, i0.cmpeq(last));
                Axis::edge(i0, i1, w)
            }
            Wrap::Clamp => {
                let u = s.mul(sz);
                // clamp to [0, size] (u ≤ 0 → 0), then −0.5
                let u = u.min(sz).and(u.cmp_gt(fzero));
                let (i0, w) = floor_fract(u.sub(half));
                Axis::border(i0, last, w)
            }
            Wrap::ClampToEdge => {
                let u = s.mul(sz);
                let u = sz.blendv(u, u.cmp_lt(sz)).sub(half);
                let u = u.and(u.cmp_gt(fzero));
                let (i0, w) = floor_fract(u);
                let i0 = clamp(i0, last);
                Axis::edge(i0, i0.add(one).min(last), w)
            }
            Wrap::ClampToBorder => {
                let u = s.mul(sz).max(F32x8::splat(-0.5)).min(sz.add(half));
                let (i0, w) = floor_fract(u.sub(half));
                Axis::border(i0, last, w)
            }
            Wrap::MirroredRepeat => {
                let (i0, w) = floor_fract(mirror(s).mul(sz).sub(half));
                let i1 = i0.add(one).min(last).max(zero);
                Axis::edge(clamp(i0, last), i1, w)
            }
        }
    }
}

#[cfg(test)]
#[path = "soa_avx2_tests.rs"]
mod tests;
