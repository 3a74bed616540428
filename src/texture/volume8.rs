//! The 8-wide AVX2 sampler of GL_TEXTURE_3D on llvmpipe's 8-bit (AoS) path: both rows of
//! a chunk sampled a row (8 pixels) at a time with exactly the arithmetic of
//! [`super::volume`]'s quad sampler.
//!
//! It covers the state without a LOD (MIN_FILTER = MAG_FILTER, no mip filter: one level,
//! the base) with each axis CLAMP_TO_EDGE, or REPEAT of a power-of-two size: per axis,
//! LINEAR's `fx = round_half_even(c·size·256) − 128`, `i0 = fx >> 8`, weight `fx & 255`
//! and NEAREST's `floor(c·size)`, wrapped or clamped; the 8 (or 1) texels of each lane
//! gathered at `(z·h + y)·w + x`, and the 8.8 lerps in x on the four rows, in y on both
//! slices, then in z (`vpmulhrsw`, equal to `a + ((b − a)·w + 128) >> 8`), each texel made
//! a float as `u·f32(1/255)`. A lane whose scaled coordinate is NaN or of magnitude 2^30
//! or more (where the scalar code's saturating conversion and `vcvtps2dq` part) sends its
//! quad to the quad sampler. Its functions inline into the rasterizer's AVX2 entry points
//! and run only when the CPU has AVX2 ([`super::fast_avx2::available`]).

use super::sample::to_float;
use super::{ExtKind, Filter, Level, UnitPlan, Wrap};
use crate::fragment::span::LANES;
use crate::simd::{F32x8, I32x8, U16x16};

/// A unit's 3D state when the 8-wide sampler covers it.
#[derive(Clone, Copy)]
pub struct Vol8<'a> {
    /// The base level (every slice after the other).
    img: &'a Level,
    /// Width, height and depth.
    size: [i32; 3],
    /// REPEAT (power of two) on each axis, else CLAMP_TO_EDGE.
    repeat: [bool; 3],
    /// LINEAR, else NEAREST.
    linear: bool,
}

impl<'a> Vol8<'a> {
    /// The sampler of unit `p`, when it covers the unit's state.
    #[inline(always)]
    pub fn of(p: &'a UnitPlan<'a>) -> Option<Vol8<'a>> {
        let ExtKind::Volume(v) = &p.ext.kind else {
            return None;
        };
        if !p.aos || p.needs_lod {
            return None;
        }
        let img = p.image(p.first);
        let size = [img.width, img.height, v.depths[p.first]];
        let wraps = [p.wrap_s, p.wrap_t, v.wrap_r];
        let pots = [p.pot[0], p.pot[1], v.pot_r];
        let mut repeat = [false; 3];
        for k in 0..3 {
            repeat[k] = match wraps[k] {
                Wrap::ClampToEdge => false,
                // llvmpipe's power-of-two code (chosen from level 0) on a power-of-two level
                Wrap::Repeat if pots[k] && size[k].is_power_of_two() => true,
                _ => return None,
            };
        }
        let n = size[0].checked_mul(size[1])?.checked_mul(size[2])?;
        if n == 0 || n > i32::MAX as usize || img.texels.len() < n {
            return None;
        }
        Some(Vol8 {
            img,
            size: size.map(|n| n as i32),
            repeat,
            linear: p.mag_filter == Filter::Linear,
        })
    }

    /// Samples both rows at (`s`, `t`, `r`) into `out`, skipping rows without a `live`
    /// lane. Returns the quads (bit j: lanes 2j and 2j+1 of both rows) the caller samples
    /// with the quad sampler instead; their lanes here may hold any value, as may lanes
    /// that are not live (a row without a live lane is not sampled).
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    pub unsafe fn rows(
        &self,
        s: &[[f32; LANES]; 2],
        t: &[[f32; LANES]; 2],
        r: &[[f32; LANES]; 2],
        live: &[[bool; LANES]; 2],
        out: [&mut [[f32; 4]; LANES]; 2],
    ) -> u32 {
        let mut redo = 0;
        for (row, out) in out.into_iter().enumerate() {
            if !live[row].iter().any(|&l| l) {
                continue;
            }
            // SAFETY: AVX2 (the caller's promise).
            let (v, bad) = unsafe { self.row(&s[row], &t[row], &r[row]) };
            for (o, v) in out.iter_mut().zip(v.to_array()) {
                *o = to_float((v as u32).to_le_bytes());
            }
            for j in 0..LANES / 2 {
                redo |= u32::from(bad >> (2 * j) & 3 != 0) << j;
            }
        }
        redo
    }

    /// One row: the 8 texels as RGBA8 lanes, and the lanes (bits) the quad sampler must
    /// take.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    unsafe fn row(&self, s: &[f32; LANES], t: &[f32; LANES], r: &[f32; LANES]) -> (I32x8, u32) {
        // SAFETY: AVX2 (the caller's promise); the gathers read texel indices (below).
        unsafe {
            let mut ok = I32x8::splat(-1).as_f32();
            let (size, rep, lin) = (self.size, self.repeat, self.linear);
            let (x0, x1, wx) = axis(F32x8::load(s.as_ptr()), size[0], rep[0], lin, &mut ok);
            let (y0, y1, wy) = axis(F32x8::load(t.as_ptr()), size[1], rep[1], lin, &mut ok);
            let (z0, z1, wz) = axis(F32x8::load(r.as_ptr()), size[2], rep[2], lin, &mut ok);
            let bad = !ok.movemask() & 0xff;
            // Every index lane is wrapped or clamped into 0..size on its axis (`axis`,
            // whatever the coordinate), so (z·h + y)·w + x < w·h·d ≤ texels.len() (`of`).
            let base = self.img.texels.as_ptr() as *const i32;
            let (wv, hv) = (I32x8::splat(size[0]), I32x8::splat(size[1]));
            let z0h = z0.mullo(hv);
            let r00 = z0h.add(y0).mullo(wv);
            if !lin {
                // SAFETY: in bounds (above); the texels are 4 bytes each, read as i32.
                return (I32x8::gather(base, r00.add(x0)), bad);
            }
            let z1h = z1.mullo(hv);
            let (r01, r10, r11) = (
                z0h.add(y1).mullo(wv),
                z1h.add(y0).mullo(wv),
                z1h.add(y1).mullo(wv),
            );
            let (wx, wy) = (weight(wx), weight(wy));
            let s0 = lerp_wide(line(base, r00, x0, x1, wx), line(base, r01, x0, x1, wx), wy);
            let s1 = lerp_wide(line(base, r10, x0, x1, wx), line(base, r11, x0, x1, wx), wy);
            (pack(lerp_wide(s0, s1, weight(wz))), bad)
        }
    }
}

/// One row of LINEAR texels lerped in x: the texels at `at + x0` and `at + x1`.
///
/// # Safety
/// Must be called from a function compiled with AVX2; every `at + x0`, `at + x1` lane is
/// an index of a texel of `base`.
#[inline(always)]
unsafe fn line(base: *const i32, at: I32x8, x0: I32x8, x1: I32x8, wx: U16x16) -> Wide {
    // SAFETY: forwarded from the caller; the texels are 4 bytes each, read as i32.
    unsafe {
        let a = widen(I32x8::gather(base, at.add(x0)));
        let b = widen(I32x8::gather(base, at.add(x1)));
        lerp_wide(a, b, wx)
    }
}

/// Texel indices along an axis of size `n` at coordinates `c`: `(i0, i1, weight)` for
/// LINEAR, `(i, _, _)` for NEAREST, wrapped (`repeat`, `n` a power of two) or clamped
/// into `0..n`; lanes whose scaled coordinate is NaN or of magnitude 2^30 or more are
/// cleared in `ok`.
///
/// # Safety
/// Must be called from a function compiled with AVX2.
#[inline(always)]
unsafe fn axis(
    c: F32x8,
    n: i32,
    repeat: bool,
    linear: bool,
    ok: &mut F32x8,
) -> (I32x8, I32x8, I32x8) {
    // SAFETY: AVX2 context (the caller's promise).
    unsafe {
        let last = I32x8::splat(n - 1);
        // Not a closure: one that is not inlined loses the caller's target features.
        #[inline(always)]
        unsafe fn wrap(i: I32x8, repeat: bool, last: I32x8) -> I32x8 {
            // SAFETY: AVX2 context (the caller's promise).
            unsafe {
                if repeat {
                    i.and(last)
                } else {
                    i.max(I32x8::zero()).min(last)
                }
            }
        }
        let scale = if linear { n as f32 * 256.0 } else { n as f32 };
        let mut u = c.mul(F32x8::splat(scale));
        if !linear {
            u = u.floor();
        }
        let abs = u.and(I32x8::splat(0x7fff_ffff).as_f32());
        // NaN compares false
        *ok = ok.and(abs.cmp_lt(F32x8::splat(1_073_741_824.0)));
        if !linear {
            return (
                wrap(u.to_i32_trunc(), repeat, last),
                I32x8::zero(),
                I32x8::zero(),
            );
        }
        let fx = u.to_i32().sub(I32x8::splat(128));
        let i0 = fx.sra::<8>();
        (
            wrap(i0, repeat, last),
            wrap(i0.add(I32x8::splat(1)), repeat, last),
            fx.and(I32x8::splat(255)),
        )
    }
}

/// 8 RGBA8 pixels as 16-bit fields: the even bytes (R, B), then the odd ones (G, A).
pub(super) type Wide = (U16x16, U16x16);

/// Splits 8 RGBA8 pixels into [`Wide`] fields.
#[inline(always)]
pub(super) fn widen(v: I32x8) -> Wide {
    let v = v.as_u16();
    (v.shl::<8>().shr::<8>(), v.shr::<8>())
}

/// The bytes of [`Wide`] fields that hold values in 0..=255.
#[inline(always)]
pub(super) fn pack(v: Wide) -> I32x8 {
    v.0.or(v.1.shl::<8>()).as_i32()
}

/// A weight in 0..=255 per 32-bit lane as `w · 128` in both of its 16-bit fields.
#[inline(always)]
pub(super) fn weight(w: I32x8) -> U16x16 {
    w.shl::<7>().or(w.shl::<23>()).as_u16()
}

/// llvmpipe's 8-bit lerp of both halves: `a + ((b − a)·w7 + 2^14) >> 15` (`vpmulhrsw`),
/// which is `a + ((b − a)·w + 128) >> 8` for fields in 0..=255.
#[inline(always)]
pub(super) fn lerp_wide(a: Wide, b: Wide, w7: U16x16) -> Wide {
    (
        a.0.add(b.0.sub(a.0).mulhrs(w7)),
        a.1.add(b.1.sub(a.1).mulhrs(w7)),
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::{volume, MipFilter, Target, TextureObject, TextureState};

    /// A `w`x`h`x`d` RGBA8 volume of random texels on unit 0 of a new state.
    fn state(size: [usize; 3], next: &mut impl FnMut() -> u32) -> TextureState {
        let [w, h, d] = size;
        let mut o = TextureObject::new(Some(Target::Tex3D));
        let texels = (0..w * h * d).map(|_| next().to_le_bytes()).collect();
        o.levels[0] = Some(crate::texture::tests::rgba_level(w, h, texels));
        o.depths[0] = d;
        o.params.mip_filter = MipFilter::None;
        let mut ts = TextureState::default();
        ts.defaults[Target::Tex3D.index()] = o;
        ts.units[0].enabled_3d = true;
        ts
    }

    /// A coordinate: mostly in -2..2, sometimes on a texel edge, NaN, infinite or huge.
    fn coord(next: &mut impl FnMut() -> u32, n: usize) -> f32 {
        match next() % 16 {
            0 => [f32::NAN, f32::INFINITY, -f32::INFINITY, 3.0e9][(next() % 4) as usize],
            1 => (next() % (4 * n as u32)) as f32 / (2 * n) as f32 - 1.0,
            _ => (next() % 40001) as f32 / 10000.0 - 2.0,
        }
    }

    #[test]
    fn rows_match_the_quad_sampler() {
        if !crate::texture::fast_avx2::available() {
            return;
        }
        let mut next = crate::test_rng::xorshift32(56);
        let (mut vector, mut scalar) = (0, 0);
        for size in [[32, 32, 32], [4, 8, 2], [1, 16, 4], [8, 1, 1], [2, 2, 64]] {
            for filter in [Filter::Linear, Filter::Nearest] {
                for wraps in [
                    [Wrap::Repeat; 3],
                    [Wrap::ClampToEdge; 3],
                    [Wrap::Repeat, Wrap::ClampToEdge, Wrap::Repeat],
                ] {
                    let mut ts = state(size, &mut next);
                    let o = &mut ts.defaults[Target::Tex3D.index()];
                    o.params.min_filter = filter;
                    o.params.mag_filter = filter;
                    [o.params.wrap_s, o.params.wrap_t, o.params.wrap_r] = wraps;
                    let p = ts.unit_plan(0).expect("complete");
                    let ExtKind::Volume(v) = &p.ext.kind else {
                        panic!("not 3D");
                    };
                    let v8 = Vol8::of(&p).expect("covered");
                    for _ in 0..300 {
                        let mut c = [[[0.0f32; 8]; 2]; 3];
                        for row in c.iter_mut() {
                            for (k, v) in row.iter_mut().flatten().enumerate() {
                                *v = coord(&mut next, size[k % 3]);
                            }
                        }
                        let live: [[bool; 8]; 2] = std::array::from_fn(|_| {
                            std::array::from_fn(|_| !next().is_multiple_of(3))
                        });
                        let mut out = [[[-1.0f32; 4]; 8]; 2];
                        let [o0, o1] = &mut out;
                        // SAFETY: the CPU has AVX2 (checked above).
                        let redo = unsafe { v8.rows(&c[0], &c[1], &c[2], &live, [o0, o1]) };
                        for j in 0..4 {
                            let (a, b) = (2 * j, 2 * j + 1);
                            if !(live[0][a] || live[0][b] || live[1][a] || live[1][b]) {
                                continue;
                            }
                            if redo >> j & 1 != 0 {
                                scalar += 1;
                                continue;
                            }
                            vector += 1;
                            let q4 = |c: &[[f32; 8]; 2]| [c[0][a], c[0][b], c[1][a], c[1][b]];
                            let [s, t, r] = [q4(&c[0]), q4(&c[1]), q4(&c[2])];
                            let q = volume::sample_quad(&p, v, s, t, r);
                            let got = [out[0][a], out[0][b], out[1][a], out[1][b]];
                            let lv = [live[0][a], live[0][b], live[1][a], live[1][b]];
                            for i in (0..4).filter(|&i| lv[i]) {
                                assert_eq!(
                                    got[i].map(f32::to_bits),
                                    q[i].map(f32::to_bits),
                                    "{size:?} {filter:?} {wraps:?} pixel {i} s {s:?} t {t:?} r {r:?}",
                                );
                            }
                        }
                    }
                }
            }
        }
        assert!(
            vector > 5_000 && scalar > 100,
            "vector {vector} scalar {scalar}"
        );
    }
}
