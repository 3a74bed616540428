//! The 8-wide AVX2 depth-comparison sampler: one row of a chunk (8 pixels) of a shadow
//! map, sampled at once, with exactly the arithmetic of [`super::shadow::sample_quad`].
//!
//! It serves the common shadow-map state (MuJoCo's, and most fixed-function shadow
//! mapping): a 2D depth texture of 16 or 24 bits with GL_COMPARE_R_TO_TEXTURE, one level
//! (no LOD needed: the minification and magnification filters equal and no mipmapping, so
//! every pixel magnifies the base level on its own and a row needs no quads), NEAREST or
//! LINEAR, CLAMP_TO_EDGE or REPEAT of a power-of-two size ([`Shadow8::of`]).
//!
//! Per axis it computes the float path's coordinates as `wrap::soa_nearest` and
//! `wrap::soa_linear` do (CLAMP_TO_EDGE: `min(s·size, size) − 0.5`, `max(·, 0)`, floor
//! and fraction, index clamped; REPEAT: `floor(s·size − 0.5)` masked), gathers the stored
//! values (`vpgatherdd`), converts them as `float(z)·f32(1/max)`, compares the clamped
//! reference with the texture's function (1.0 or 0.0) and filters the comparisons with the
//! lerps `w·(b − a) + a`, fused exactly when the unit's lerps are (`UnitPlan::fma`).
//!
//! With NEAREST it prefetches the texels of the next chunk of the row (the lanes'
//! coordinates extrapolated by 8 pixels from the first and last lane): a large shadow map
//! (MuJoCo's 4096² is 64 MiB, written back by the depth pass just before) misses the
//! caches at nearly every lane, and the walk reached the gather with nothing in flight.
//!
//! It declines (returns `false`, and the caller samples with the scalar code) when a live
//! lane's scaled coordinate is not below 2^30 in magnitude or is NaN, or its reference is
//! NaN, where the float → int conversions or the clamp of the two paths could differ.
//! Lanes that are not live may hold any coordinates: their indices are still clamped or
//! masked into the image, so every gather reads inside it. Its functions inline into the
//! rasterizer's AVX2 entry points and run only when the CPU has AVX2
//! ([`super::fast_avx2::available`]).

use super::shadow::{CompareFunc, DepthMode};
use super::{ExtKind, Filter, Level, UnitPlan, Wrap};
use crate::simd::{F32x8, I32x8};

/// `f32(1/max)` of 16-bit depth texels.
const SCALE_16: f32 = (1.0 / 65535.0f64) as f32;
/// `f32(1/max)` of 24-bit depth texels.
const SCALE_24: f32 = (1.0 / 16777215.0f64) as f32;

/// A unit's shadow-map state when the 8-wide sampler covers it.
#[derive(Clone, Copy)]
pub struct Shadow8<'a> {
    /// The base level.
    img: &'a Level,
    /// LINEAR (else NEAREST).
    linear: bool,
    /// The comparison.
    func: CompareFunc,
    /// GL_DEPTH_TEXTURE_MODE.
    mode: DepthMode,
    /// `f32(1/max)` of the stored bits.
    scale: f32,
    /// REPEAT (else CLAMP_TO_EDGE) on s and t.
    repeat: [bool; 2],
    /// Whether the lerps fuse.
    fma: bool,
}

impl<'a> Shadow8<'a> {
    /// The sampler of unit `p`, when it covers the unit's state.
    #[inline(always)]
    pub fn of(p: &'a UnitPlan<'a>) -> Option<Shadow8<'a>> {
        let d = p.ext.depth.as_ref()?;
        let func = d.func?;
        if p.needs_lod || p.dims != 2 || !matches!(p.ext.kind, ExtKind::Flat) {
            return None;
        }
        // 16 and 24 bits convert as `float(z)·f32(1/max)` with z exact in f32; the scales
        // are `(1.0 / max as f64) as f32` (test `scales_are_the_divisions`), constants since
        // this runs for every chunk
        let scale = match d.bits {
            16 => SCALE_16,
            24 => SCALE_24,
            _ => return None,
        };
        // Without a LOD every pixel magnifies the base level (`select_levels` with
        // `Lod::MAG`).
        let img = p.image(p.first);
        let axis = |wrap: Wrap, pot: bool, size: usize| match wrap {
            Wrap::ClampToEdge => Some(false),
            Wrap::Repeat if pot && size.is_power_of_two() => Some(true),
            _ => None,
        };
        let repeat = [
            axis(p.wrap_s, p.pot[0], img.width)?,
            axis(p.wrap_t, p.pot[1], img.height)?,
        ];
        // every index fits an i32 lane (and `y·width + x` does too)
        if img.width.checked_mul(img.height)? >= 1 << 30 {
            return None;
        }
        Some(Shadow8 {
            img,
            linear: p.mag_filter == Filter::Linear,
            func,
            mode: d.mode,
            scale,
            repeat,
            fma: p.fma,
        })
    }

    /// Samples the 8 pixels of one row at `s`, `t` with references `r` into `out` (the
    /// RGBA the depth texture mode makes of each filtered comparison); `false` (and `out`
    /// untouched) when it declines for a live lane.
    ///
    /// # Safety
    /// The CPU has AVX2, and FMA when the unit's lerps fuse.
    #[inline(always)]
    pub unsafe fn row(
        &self,
        s: &[f32; 8],
        t: &[f32; 8],
        r: &[f32; 8],
        live: &[bool; 8],
        out: &mut [[f32; 4]; 8],
    ) -> bool {
        let mask = live
            .iter()
            .enumerate()
            .fold(0u32, |m, (i, &l)| m | ((l as u32) << i));
        let (w, h) = (self.img.width, self.img.height);
        // SAFETY: (all) the caller vouches for AVX2 (and FMA when `self.fma`); the arrays
        // are 8 lanes each; gathers read indices clamped or masked into the image.
        unsafe {
            let (sz_s, sz_t) = (F32x8::splat(w as f32), F32x8::splat(h as f32));
            let us = F32x8::load(s.as_ptr()).mul(sz_s);
            let ut = F32x8::load(t.as_ptr()).mul(sz_t);
            let rv = F32x8::load(r.as_ptr());
            let (big, nbig) = (F32x8::splat(1073741824.0), F32x8::splat(-1073741824.0));
            // ordered comparisons: false for NaN
            let ok = us
                .cmp_lt(big)
                .and(us.cmp_gt(nbig))
                .and(ut.cmp_lt(big))
                .and(ut.cmp_gt(nbig))
                .and(rv.cmp_ord(rv));
            if !ok.movemask() & mask != 0 {
                return false;
            }
            // `r.clamp(0, 1)` (no NaN among the live lanes)
            let rc = rv.max(F32x8::zero()).min(F32x8::splat(1.0));
            // `pass` is a method, not a closure: a closure the compiler leaves out of
            // line loses the caller's target features
            let v = if self.linear {
                let (x0, x1, wx) = linear(us, w, self.repeat[0]);
                let (y0, y1, wy) = linear(ut, h, self.repeat[1]);
                let r0 = self.lerp(wx, self.pass(rc, x0, y0), self.pass(rc, x1, y0));
                let r1 = self.lerp(wx, self.pass(rc, x0, y1), self.pass(rc, x1, y1));
                self.lerp(wy, r0, r1)
            } else {
                // the next chunk's texels, extrapolated along the row: a large shadow map
                // misses the caches at nearly every lane, and the gather of this row
                // waited on memory without it
                let (ns, nt) = (ahead(us), ahead(ut));
                self.prefetch(
                    nearest(ns, w, self.repeat[0]),
                    nearest(nt, h, self.repeat[1]),
                );
                self.pass(
                    rc,
                    nearest(us, w, self.repeat[0]),
                    nearest(ut, h, self.repeat[1]),
                )
            };
            for (o, v) in out.iter_mut().zip(v.to_array()) {
                *o = self.mode.swizzle(v);
            }
        }
        true
    }

    /// The comparison of references `rc` with the texels at `x`, `y` (inside the image):
    /// 1.0 where it passes, else 0.0.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    unsafe fn pass(&self, rc: F32x8, x: I32x8, y: I32x8) -> F32x8 {
        // SAFETY: forwarded from the caller; `y·width + x` is inside the image.
        unsafe {
            let i = y.mullo(I32x8::splat(self.img.width as i32)).add(x);
            let z = I32x8::gather(self.img.texels.as_ptr() as *const i32, i);
            let d = z.to_f32().mul(F32x8::splat(self.scale));
            self.compare(rc, d).and(F32x8::splat(1.0))
        }
    }

    /// Prefetches the texels at `x`, `y` (inside the image): a hint, no value changes.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    unsafe fn prefetch(&self, x: I32x8, y: I32x8) {
        // SAFETY: forwarded from the caller.
        let i = unsafe { y.mullo(I32x8::splat(self.img.width as i32)).add(x) };
        let p = self.img.texels.as_ptr();
        for k in i.to_array() {
            // a prefetch never faults, and `k` is inside the image anyway
            crate::simd::prefetch(p.wrapping_add(k as usize));
        }
    }

    /// `r func d` per lane as a mask (the functions of [`CompareFunc::test`]; no lane is
    /// NaN).
    #[inline(always)]
    fn compare(&self, r: F32x8, d: F32x8) -> F32x8 {
        // SAFETY: AVX2 as `r` proves.
        let (none, all) = unsafe { (F32x8::zero(), I32x8::splat(-1)) };
        match self.func {
            CompareFunc::Never => none,
            CompareFunc::Less => r.cmp_lt(d),
            CompareFunc::Equal => r.cmp_eq(d),
            CompareFunc::Lequal => r.cmp_le(d),
            CompareFunc::Greater => r.cmp_gt(d),
            CompareFunc::Notequal => r.cmp_eq(d).bits().xor(all).as_f32(),
            CompareFunc::Gequal => r.cmp_ge(d),
            CompareFunc::Always => all.as_f32(),
        }
    }

    /// `lerpf(fma, w, a, b)` per lane.
    #[inline(always)]
    fn lerp(&self, w: F32x8, a: F32x8, b: F32x8) -> F32x8 {
        if self.fma {
            // SAFETY: `fma` is set only on CPUs with FMA (`sample::has_fma`).
            unsafe { w.mul_add(b.sub(a), a) }
        } else {
            w.mul(b.sub(a)).add(a)
        }
    }
}

/// The scaled coordinates of the next chunk's lanes (8 pixels to the right), extrapolated
/// from this row's first and last lanes; only an address to prefetch, so a lane that is not
/// live (any value) costs at most a useless prefetch.
///
/// # Safety
/// The CPU has AVX2.
#[inline(always)]
unsafe fn ahead(u: F32x8) -> F32x8 {
    let a = u.to_array();
    // SAFETY: forwarded from the caller.
    unsafe { u.add(F32x8::splat((a[7] - a[0]) * (8.0 / 7.0))) }
}

/// `wrap::soa_nearest` of the scaled coordinate `u = s·size` (|u| < 2^30 or the lane is
/// not used): CLAMP_TO_EDGE truncates and clamps, REPEAT floors and masks.
///
/// # Safety
/// The CPU has AVX2.
#[inline(always)]
unsafe fn nearest(u: F32x8, size: usize, repeat: bool) -> I32x8 {
    // SAFETY: forwarded from the caller.
    unsafe {
        let last = I32x8::splat(size as i32 - 1);
        if repeat {
            u.floor().to_i32_trunc().and(last)
        } else {
            u.to_i32_trunc().max(I32x8::zero()).min(last)
        }
    }
}

/// `wrap::soa_linear` of the scaled coordinate `u = s·size`: the two indices and the
/// weight.
///
/// # Safety
/// The CPU has AVX2.
#[inline(always)]
unsafe fn linear(u: F32x8, size: usize, repeat: bool) -> (I32x8, I32x8, F32x8) {
    // SAFETY: forwarded from the caller.
    unsafe {
        let last = I32x8::splat(size as i32 - 1);
        let one = I32x8::splat(1);
        if repeat {
            let v = u.sub(F32x8::splat(0.5));
            let f = v.floor();
            let i0 = f.to_i32_trunc();
            (i0.and(last), i0.add(one).and(last), v.sub(f))
        } else {
            // `if u < size { u } else { size }`, then `if u > 0 { u } else { 0 }`:
            // `vminps(a, b)` is `a < b ? a : b` and `vmaxps(a, b)` is `a > b ? a : b`
            let v = u.min(F32x8::splat(size as f32)).sub(F32x8::splat(0.5));
            let v = v.max(F32x8::zero());
            let f = v.floor();
            let i0 = f.to_i32_trunc().max(I32x8::zero()).min(last);
            (i0, i0.add(one).min(last), v.sub(f))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::shadow::{self, ShadowParams};
    use crate::texture::{BaseFormat, MipFilter, Storage, Target, TextureObject, TextureState};

    const FUNCS: [CompareFunc; 8] = [
        CompareFunc::Never,
        CompareFunc::Less,
        CompareFunc::Equal,
        CompareFunc::Lequal,
        CompareFunc::Greater,
        CompareFunc::Notequal,
        CompareFunc::Gequal,
        CompareFunc::Always,
    ];

    /// A 2D depth texture of `w`x`h` texels of `bits` bits on unit 0 of a new state.
    fn state(w: usize, h: usize, bits: u8, next: &mut impl FnMut() -> u32) -> TextureState {
        let mut storage = Storage::of_base(BaseFormat::Depth);
        storage.sizes[0] = bits;
        // a few values repeat, so that EQUAL and NOTEQUAL meet equal depths
        let texels = (0..w * h)
            .map(|_| shadow::texel(shadow::store((next() % 17) as f32 / 16.0, bits)))
            .collect();
        let mut o = TextureObject::new(Some(Target::Tex2D));
        o.levels[0] = Some(Level {
            width: w,
            height: h,
            internal_format: 0x1902,
            base: BaseFormat::Depth,
            storage,
            texels,
            blocks: None,
            floats: None,
        });
        let mut ts = TextureState::default();
        ts.defaults[Target::Tex2D.index()] = o;
        ts.units[0].enabled_2d = true;
        ts
    }

    /// A coordinate: mostly inside [-0.5, 1.5], some on texel centres and edges, and in
    /// lanes that are not live also NaN, infinities and huge values.
    fn coord(next: &mut impl FnMut() -> u32, size: usize, live: bool) -> f32 {
        match next() % 16 {
            0 => (next() % (4 * size as u32)) as f32 / (2 * size) as f32,
            1 if !live => f32::NAN,
            2 if !live => 3.0e9,
            3 if !live => f32::NEG_INFINITY,
            _ => (next() % 20000) as f32 / 10000.0 - 0.5,
        }
    }

    #[test]
    fn rows_match_the_quad_sampler() {
        if !crate::texture::fast_avx2::available() {
            return;
        }
        let mut next = crate::test_rng::xorshift32(53);
        for (w, h) in [(16, 8), (5, 3)] {
            for bits in [16, 24] {
                for linear in [false, true] {
                    for repeat in [false, true] {
                        for func in FUNCS {
                            let mut ts = state(w, h, bits, &mut next);
                            let o = &mut ts.defaults[Target::Tex2D.index()];
                            let f = if linear {
                                Filter::Linear
                            } else {
                                Filter::Nearest
                            };
                            o.params.min_filter = f;
                            o.params.mag_filter = f;
                            o.params.mip_filter = MipFilter::None;
                            let wrap = if repeat {
                                Wrap::Repeat
                            } else {
                                Wrap::ClampToEdge
                            };
                            o.params.wrap_s = wrap;
                            o.params.wrap_t = wrap;
                            o.params.shadow = ShadowParams {
                                compare: true,
                                func,
                                depth_mode: DepthMode::Intensity,
                            };
                            let p = ts.unit_plan(0).expect("complete");
                            let d = p.ext.depth.expect("depth");
                            let Some(sh) = Shadow8::of(&p) else {
                                // REPEAT of a size that is not a power of two
                                assert!(repeat && !w.is_power_of_two());
                                continue;
                            };
                            for _ in 0..64 {
                                let live: [bool; 8] =
                                    std::array::from_fn(|_| !next().is_multiple_of(3));
                                let s: [f32; 8] =
                                    std::array::from_fn(|i| coord(&mut next, w, live[i]));
                                let t: [f32; 8] =
                                    std::array::from_fn(|i| coord(&mut next, h, live[i]));
                                let r: [f32; 8] =
                                    std::array::from_fn(|_| (next() % 1400) as f32 / 1000.0 - 0.2);
                                let mut out = [[-1.0f32; 4]; 8];
                                // SAFETY: the CPU has AVX2 (checked above), and FMA when
                                // the plan fuses (`sample::has_fma`).
                                assert!(unsafe { sh.row(&s, &t, &r, &live, &mut out) });
                                for i in (0..8).filter(|&i| live[i]) {
                                    let q = shadow::sample_quad(
                                        &p, &d, [s[i]; 4], [t[i]; 4], [r[i]; 4],
                                    );
                                    assert_eq!(
                                        out[i].map(f32::to_bits),
                                        q[0].map(f32::to_bits),
                                        "{w}x{h} {bits} bits linear {linear} repeat {repeat} {func:?} s {} t {} r {}",
                                        s[i],
                                        t[i],
                                        r[i]
                                    );
                                }
                            }
                        }
                    }
                }
            }
        }
    }

    #[test]
    fn scales_are_the_divisions() {
        for (bits, scale) in [(16u32, SCALE_16), (24, SCALE_24)] {
            let want = (1.0 / ((1u64 << bits) - 1) as f64) as f32;
            assert_eq!(scale.to_bits(), want.to_bits(), "{bits} bits");
        }
    }

    #[test]
    fn declines_live_lanes_it_cannot_follow() {
        if !crate::texture::fast_avx2::available() {
            return;
        }
        let mut next = crate::test_rng::xorshift32(7);
        let mut ts = state(8, 8, 24, &mut next);
        let o = &mut ts.defaults[Target::Tex2D.index()];
        o.params.min_filter = Filter::Linear;
        o.params.mag_filter = Filter::Linear;
        o.params.mip_filter = MipFilter::None;
        o.params.wrap_s = Wrap::ClampToEdge;
        o.params.wrap_t = Wrap::ClampToEdge;
        o.params.shadow.compare = true;
        let p = ts.unit_plan(0).expect("complete");
        let sh = Shadow8::of(&p).expect("covered");
        let mut out = [[0.0f32; 4]; 8];
        let live = [true; 8];
        for bad in [f32::NAN, 2.0e9, -2.0e9] {
            let mut s = [0.5f32; 8];
            s[3] = bad;
            // SAFETY: the CPU has AVX2 (checked above), and FMA when the plan fuses.
            assert!(!unsafe { sh.row(&s, &[0.5; 8], &[0.5; 8], &live, &mut out) });
            let mut r = [0.5f32; 8];
            r[5] = f32::NAN;
            // SAFETY: as above.
            assert!(!unsafe { sh.row(&[0.5; 8], &[0.5; 8], &r, &live, &mut out) });
        }
    }
}
