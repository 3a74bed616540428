//! The sampling half of the 8-wide texture walk (`raster::textured::vec8`): the texels
//! of a chunk (two rows of 8 pixels) from coordinates in registers, with the level of
//! detail of its four quads computed in lanes. Bit for bit what [`fast::chunk_u8`] gives
//! (same operations in the same order as [`crate::texture::lod::compute`] and
//! [`select_levels`]); a chunk whose quads choose different levels is sampled once per
//! level key and blended per lane; a LOD form not vectorised here, or a coordinate the
//! vector sampler declines goes through [`fast::chunk_u8`] itself.

#![cfg(target_arch = "x86_64")]
// Lane loops index several arrays in step.
#![allow(clippy::needless_range_loop)]

use super::super::fast;
use super::super::sample::select_levels;
use super::super::{Filter, Level, Lod, MipFilter, UnitPlan};
use super::{handles, AxisWrap, LevelV, RowSamplerV};
use crate::fragment::span::LANES;
use crate::simd::{F32x8, I32x8};

/// Integer bitmask of a lane mask.
#[inline(always)]
pub fn bits(m: I32x8) -> u32 {
    m.movemask()
}

/// Each lane's quad's top-left value (lanes [0, 0, 2, 2] of each 128-bit half).
#[inline(always)]
fn tl(v: F32x8) -> F32x8 {
    v.permute::<0xA0>()
}

/// Each lane's quad's top-right value (lanes [1, 1, 3, 3] of each 128-bit half).
#[inline(always)]
fn tr(v: F32x8) -> F32x8 {
    v.permute::<0xF5>()
}

/// What the level of detail needs, per triangle (the base level's size, the LOD
/// parameters as vectors).
#[derive(Clone, Copy)]
struct LodConsts {
    /// Base level width and height.
    w: f32,
    h: f32,
    /// Quantised bias (added when non-zero).
    bias: f32,
    /// Clamps as llvmpipe applies them.
    max_lod: Option<f32>,
    min_lod: Option<f32>,
    /// `first`, `last` levels.
    first: i32,
    last: i32,
    /// The key of a magnified quad (`first·2` when MAG and MIN filter alike, else −2).
    mag_key: i32,
    /// NEAREST mip filtering or none (else LINEAR): one level per quad, the LOD rounded
    /// (without mipmaps `last` is `first`).
    nearest: bool,
    /// With `nearest`: no bias and no clamps, so the level comes from rho's exponent
    /// ([`crate::texture::lod::from_rho`]'s fast path).
    exponent_only: bool,
}

/// The per-quad LOD of a chunk for LINEAR, NEAREST or no mip filtering
/// ([`crate::texture::lod::compute`] then [`select_levels`] per quad, with rho from
/// TL/TR/BL, in lanes: both lanes of a quad carry its values): the key of the levels the
/// quads with a live pixel (`qlive`) share — `l0·2 + 1` for a blend of `l0` and `l0 + 1`,
/// `l·2` for the single level `l`, −2 for magnification with a filter of its own — and the
/// blend weights `trunc(fpart·256)` (0 for NEAREST), as `(key of each lane, key of the
/// first live quad, weights, whether every live quad has that key)`.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn lod_key(
    c: &LodConsts,
    s: [F32x8; 2],
    t: [F32x8; 2],
    qlive: u32,
) -> (I32x8, i32, I32x8, bool) {
    // SAFETY: AVX2 context (the caller).
    unsafe {
        let (w, h) = (F32x8::splat(c.w), F32x8::splat(c.h));
        let s0 = tl(s[0]);
        let t0 = tl(t[0]);
        let a = tr(s[0]).sub(s0).mul(w);
        let b = tr(t[0]).sub(t0).mul(h);
        let cc = tl(s[1]).sub(s0).mul(w);
        let d = tl(t[1]).sub(t0).mul(h);
        let rx = a.mul(a).add(b.mul(b));
        let ry = cc.mul(cc).add(d.mul(d));
        // `rx.max(ry)` ignores a NaN operand, then non-finite → 0; both are sums of
        // squares (≥ 0 or NaN), so NaN → 0 before `maxps` is the same.
        let rx = rx.and(rx.cmp_ord(rx));
        let ry = ry.and(ry.cmp_ord(ry));
        let r = rx.max(ry);
        let r = r.and(r.cmp_lt(F32x8::splat(f32::INFINITY)));
        let rb = r.bits();
        if c.nearest && c.exponent_only {
            // `from_rho`'s fast path: level `(exponent(rho²) + 1) >> 1`, minified where
            // rho² > 1.
            let e = rb
                .shr::<23>()
                .and(I32x8::splat(0xff))
                .sub(I32x8::splat(127));
            let ipart = e.add(I32x8::splat(1)).sra::<1>();
            let pos = r.cmp_gt(F32x8::splat(1.0)).bits();
            return nearest_key(c, ipart, pos, qlive);
        }
        // fast_log2: (exponent − 1) + mantissa in [1, 2).
        let e = rb
            .shr::<23>()
            .and(I32x8::splat(0xff))
            .sub(I32x8::splat(128));
        let m = rb
            .and(I32x8::splat(0x007f_ffff))
            .or(I32x8::splat(0x3f80_0000))
            .as_f32();
        let mut lod = e.to_f32().add(m).mul(F32x8::splat(0.5));
        if c.bias != 0.0 {
            lod = lod.add(F32x8::splat(c.bias));
        }
        if let Some(mx) = c.max_lod {
            lod = lod.min(F32x8::splat(mx));
        }
        if let Some(mn) = c.min_lod {
            lod = lod.max(F32x8::splat(mn));
        }
        // The LOD is finite (rho² is, and so are the bias and the applied clamps) but a
        // huge min_lod makes it overflow the float → int conversions below, which give
        // i32::MIN where the scalar `as i32` saturates: within ±2^24 both pick the level
        // `select_levels` picks (the first or the last), with the same zero fraction.
        let big = F32x8::splat(16_777_216.0);
        lod = lod.max(F32x8::zero().sub(big)).min(big);
        let pos = lod.cmp_gt(F32x8::zero()).bits();
        if c.nearest {
            // `Lod::from_value`: `round_ties_even(lod) as i32`.
            let lr = lod.round_even();
            return nearest_key(c, lr.to_i32_trunc(), pos, qlive);
        }
        let f = lod.floor();
        let fpart = lod.sub(f);
        let l0 = f.to_i32_trunc().add(I32x8::splat(c.first));
        let first = I32x8::splat(c.first);
        let below = first.cmpgt(l0);
        let in_hi = I32x8::splat(c.last).cmpgt(l0);
        let blend_key = l0.shl::<1>().or(I32x8::splat(1));
        let k = I32x8::splat(c.last * 2).blendv(blend_key, in_hi);
        let k = k.blendv(first.shl::<1>(), below);
        let key = I32x8::splat(c.mag_key).blendv(k, pos);
        let (k0, uniform) = shared_key(key, qlive);
        let wmip = fpart.mul(F32x8::splat(256.0)).to_i32_trunc();
        (key, k0, wmip, uniform)
    }
}

/// [`lod_key`]'s result for NEAREST mip filtering from each lane's LOD integer part
/// `ipart` and minification mask `pos`: the key `2·clamp(first + ipart, first, last)`
/// where minified, else the magnification key; weights 0.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn nearest_key(
    c: &LodConsts,
    ipart: I32x8,
    pos: I32x8,
    qlive: u32,
) -> (I32x8, i32, I32x8, bool) {
    // SAFETY: AVX2 context (the caller).
    unsafe {
        // |ipart| ≤ 2^24 and first is a level index: the sum does not overflow.
        let l = ipart.add(I32x8::splat(c.first));
        let l = l.max(I32x8::splat(c.first)).min(I32x8::splat(c.last));
        let key = I32x8::splat(c.mag_key).blendv(l.shl::<1>(), pos);
        let (k0, uniform) = shared_key(key, qlive);
        (key, k0, I32x8::zero(), uniform)
    }
}

/// The key of the first quad with a live pixel (`qlive`) among the lanes' `key`s, and
/// whether every such quad has it.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn shared_key(key: I32x8, qlive: u32) -> (i32, bool) {
    // SAFETY: AVX2 context (the caller).
    unsafe {
        let lane0 = I32x8::splat(qlive.trailing_zeros() as i32);
        let kb = key.permute_var(lane0);
        let uniform = bits(key.cmpeq(kb)) & qlive == qlive;
        (kb.first(), uniform)
    }
}

/// How a triangle's chunks are sampled (decided once per triangle).
pub struct Sampling<'a> {
    /// The unit.
    u: &'a UnitPlan<'a>,
    /// Without a LOD: the one sampler and its mip weights for every chunk.
    fixed: Option<(RowSamplerV<'a>, I32x8)>,
    /// The LOD form [`lod_key`] vectorises (2D, min and max LOD not equal), every level it
    /// can choose in the vector sampler's range.
    vec_lod: bool,
    /// Its constants.
    lc: LodConsts,
    /// The level key of the last chunk sampled with a LOD and its sampler: consecutive
    /// chunks mostly share their key, and reusing the sampler under a branch (predicted)
    /// keeps the gathers' addresses off the LOD's dependency chain (building it from the
    /// key makes them wait for the LOD).
    last: Option<(i32, RowSamplerV<'a>)>,
}

impl<'a> Sampling<'a> {
    /// The sampling of unit `u`.
    ///
    /// # Safety
    /// AVX2 context.
    #[inline(always)]
    pub unsafe fn new(u: &'a UnitPlan<'a>) -> Self {
        let fits = |img: &Level| {
            handles(u.wrap_s, u.pot[0], img.width) && handles(u.wrap_t, u.pot[1], img.height)
        };
        let fixed = if u.needs_lod {
            None
        } else {
            let lv = select_levels(u, Lod::MAG);
            // SAFETY: AVX2 context.
            let w = unsafe { I32x8::splat((lv.3 * 256.0) as i32) };
            (fits(u.image(lv.1)) && fits(u.image(lv.2)))
                .then(|| (Self::sampler(u, lv.0, lv.1, lv.2), w))
        };
        // Without mipmaps the LOD only chooses between the MIN and MAG filters of the
        // first level: a NEAREST mip key whose levels end at the first.
        let last = if u.mip_filter == MipFilter::None {
            u.first
        } else {
            u.last
        };
        let vec_lod = u.needs_lod
            && !u.lod.min_max_equal
            && u.dims == 2
            && (u.first..=last).all(|l| fits(u.image(l)));
        let base = u.image(u.first);
        let lc = LodConsts {
            w: base.width as f32,
            h: base.height as f32,
            bias: u.lod.bias,
            max_lod: u.lod.apply_max.then_some(u.lod.max_lod),
            min_lod: u.lod.apply_min.then_some(u.lod.min_lod),
            first: u.first as i32,
            last: last as i32,
            mag_key: if u.mag_filter == u.min_filter {
                2 * u.first as i32
            } else {
                -2
            },
            nearest: u.mip_filter != MipFilter::Linear,
            exponent_only: u.lod.bias == 0.0 && !u.lod.apply_min && !u.lod.apply_max,
        };
        Sampling {
            u,
            fixed,
            vec_lod,
            lc,
            last: None,
        }
    }

    /// Whether the chunks' lanes must form llvmpipe's 2x2 quads (the LOD is computed per
    /// quad); without a LOD each pixel is sampled on its own ([`fast::chunk_u8`] too).
    #[inline(always)]
    pub fn quads(&self) -> bool {
        self.u.needs_lod
    }

    /// The vector sampler of levels `l0`, `l1` with filter `f`.
    #[inline(always)]
    fn sampler(u: &'a UnitPlan<'a>, f: Filter, l0: usize, l1: usize) -> RowSamplerV<'a> {
        RowSamplerV {
            a: LevelV::of(u.image(l0)),
            b: (l1 != l0).then(|| LevelV::of(u.image(l1))),
            linear: f == Filter::Linear,
            wrap: [
                AxisWrap::of(u.wrap_s, u.pot[0]),
                AxisWrap::of(u.wrap_t, u.pot[1]),
            ],
        }
    }

    /// The sampler of level key `k` (see [`lod_key`]).
    #[inline(never)]
    fn keyed(&self, k: i32) -> RowSamplerV<'a> {
        let u = self.u;
        if k == -2 {
            return Self::sampler(u, u.mag_filter, u.first, u.first);
        }
        let l0 = (k >> 1) as usize;
        let l1 = l0 + (k & 1) as usize;
        Self::sampler(u, u.min_filter, l0, l1)
    }

    /// A chunk whose live quads chose different levels: the rows through the sampler of
    /// each key in turn, each lane kept from its own key's (every lane computes what a
    /// chunk of its key alone computes); `None` when a row declines.
    ///
    /// # Safety
    /// AVX2 context on a CPU that has what [`super::available`] requires.
    #[inline(never)]
    #[target_feature(enable = "avx2,popcnt,bmi1,bmi2,lzcnt")]
    unsafe fn mixed(
        &self,
        key: I32x8,
        wm: I32x8,
        qlive: u32,
        s: [F32x8; 2],
        t: [F32x8; 2],
        lm: [u32; 2],
    ) -> Option<[I32x8; 2]> {
        // SAFETY: AVX2 (this function's feature, on a CPU that has it: the caller).
        unsafe {
            let mut texv = [I32x8::zero(); 2];
            let mut todo = qlive;
            while todo != 0 {
                let lane = I32x8::splat(todo.trailing_zeros() as i32);
                let kv = key.permute_var(lane);
                let m = key.cmpeq(kv);
                let rs = self.keyed(kv.first());
                for r in 0..2 {
                    if lm[r] & bits(m) != 0 {
                        let (v, ok) = rs.row_v(s[r], t[r], wm);
                        if !ok {
                            return None;
                        }
                        texv[r] = texv[r].blendv(v, m);
                    }
                }
                todo &= !bits(m);
            }
            Some(texv)
        }
    }

    /// The texture values of a chunk: rows of coordinates `s`, `t`, covered lanes `live`
    /// (rows without any are not sampled); the lanes of quads without a covered pixel are
    /// unspecified.
    ///
    /// # Safety
    /// AVX2 context on a CPU that has it.
    #[inline(always)]
    pub unsafe fn texels(&mut self, s: [F32x8; 2], t: [F32x8; 2], live: [I32x8; 2]) -> [I32x8; 2] {
        // SAFETY: AVX2 context (the caller).
        unsafe {
            let lm = [bits(live[0]), bits(live[1])];
            let chosen = if let Some((rs, w)) = &self.fixed {
                Some((*rs, *w))
            } else if self.vec_lod {
                let any = live[0].or(live[1]);
                let pair = any.as_f32().permute::<0xB1>().bits();
                let qlive = bits(any.or(pair));
                match lod_key(&self.lc, s, t, qlive) {
                    (_, k, wm, true) => match self.last {
                        Some((lk, rs)) if lk == k => Some((rs, wm)),
                        _ => {
                            let rs = self.keyed(k);
                            self.last = Some((k, rs));
                            Some((rs, wm))
                        }
                    },
                    (key, _, wm, false) => {
                        if let Some(v) = self.mixed(key, wm, qlive, s, t, lm) {
                            return v;
                        }
                        None
                    }
                }
            } else {
                None
            };
            if let Some((rs, wm)) = chosen {
                let mut texv = [I32x8::zero(); 2];
                let mut done = true;
                for r in 0..2 {
                    if lm[r] != 0 {
                        let (v, ok) = rs.row_v(s[r], t[r], wm);
                        texv[r] = v;
                        done &= ok;
                    }
                }
                if done {
                    return texv;
                }
            }
            fallback(self.u, s, t, lm)
        }
    }
}

/// A chunk through the array sampler [`fast::chunk_u8`] (its vector rows included).
///
/// # Safety
/// AVX2 context on a CPU that has it.
#[inline(always)]
unsafe fn fallback(u: &UnitPlan<'_>, s: [F32x8; 2], t: [F32x8; 2], lm: [u32; 2]) -> [I32x8; 2] {
    let mut sa = [[0f32; LANES]; 2];
    let mut ta = [[0f32; LANES]; 2];
    let mut live = [[false; LANES]; 2];
    let mut out = [[[0u8; 4]; LANES]; 2];
    // SAFETY: AVX2 context; the arrays are 8 f32 / 8 RGBA8 (32 bytes) each.
    unsafe {
        for r in 0..2 {
            s[r].store(sa[r].as_mut_ptr());
            t[r].store(ta[r].as_mut_ptr());
            for (i, l) in live[r].iter_mut().enumerate() {
                *l = (lm[r] >> i) & 1 == 1;
            }
        }
        fast::chunk_u8::<true>(u, &sa, &ta, &live, true, &mut out);
        [I32x8::load(out[0].as_ptr()), I32x8::load(out[1].as_ptr())]
    }
}

/// A chunk on arrays: coordinates `s`, `t` and covered lanes per row.
#[cfg(test)]
pub type ArrayChunk = ([[f32; LANES]; 2], [[f32; LANES]; 2], [[bool; LANES]; 2]);

/// [`Sampling::texels`] on arrays, every chunk of `chunks` in turn through one
/// [`Sampling`] (as the walk does, so a chunk may reuse the sampler of the chunk before),
/// for the tests against [`fast::quad_u8`].
///
/// # Safety
/// The CPU has what [`super::available`] requires (AVX2 and the bit instructions).
#[cfg(test)]
#[target_feature(enable = "avx2,popcnt,bmi1,bmi2,lzcnt")]
pub unsafe fn texels_seq(u: &UnitPlan<'_>, chunks: &[ArrayChunk]) -> Vec<[[[u8; 4]; LANES]; 2]> {
    let mut outs = Vec::with_capacity(chunks.len());
    // SAFETY: AVX2 (this function's feature); the arrays are 32 bytes each.
    unsafe {
        let mut sampling = Sampling::new(u);
        for (s, t, live) in chunks {
            let mut out = [[[0u8; 4]; LANES]; 2];
            let mut lv = [I32x8::zero(); 2];
            let mut sv = [F32x8::zero(); 2];
            let mut tv = [F32x8::zero(); 2];
            for r in 0..2 {
                let m: [i32; LANES] = std::array::from_fn(|i| -(live[r][i] as i32));
                lv[r] = I32x8::load(m.as_ptr());
                sv[r] = F32x8::load(s[r].as_ptr());
                tv[r] = F32x8::load(t[r].as_ptr());
            }
            let v = sampling.texels(sv, tv, lv);
            for r in 0..2 {
                v[r].store(out[r].as_mut_ptr());
            }
            outs.push(out);
        }
    }
    outs
}
