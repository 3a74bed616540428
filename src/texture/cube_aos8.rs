//! The 8-wide AVX2 sampler of a GL_TEXTURE_CUBE_MAP without seamless filtering on
//! llvmpipe's 8-bit (AoS) path: both rows of a chunk (four 2x2 quads) sampled a row
//! (8 pixels) at a time with exactly the arithmetic of [`super::cube::sample_quad`].
//!
//! It covers 8-bit texels with both image filters LINEAR and either no LOD or llvmpipe's
//! per-pixel cube LOD of a mipmapped texture (scene k's spheres). The direction, face,
//! projection and per-pixel level selection are [`super::cube_avx2`]'s ([`Chunk`]); per
//! level each face is filtered on its own, as `sample_levels_in` does on the 8-bit path:
//! per axis `fx = round_half_even(c·(n·256)) − 128`, `i0 = fx >> 8`, weight `fx & 255`,
//! both taps clamped to the face's edge (cube maps force CLAMP_TO_EDGE); the four texels
//! are gathered (from one image when all 8 lanes share the face and level, else lane by
//! lane), lerped in x then y (`vpmulhrsw`, [`super::volume8`]'s 8.8 lerp), and the two
//! levels by `(frac·256) as i32`; each texel is then made a float as `u·f32(1/255)`.
//!
//! A quad with a coordinate that is NaN or infinite in any of its four pixels (its
//! neighbours' LOD reads it), or with a scaled face coordinate of magnitude 2^30 or more
//! (where the scalar code's saturating conversion and `vcvtps2dq` part), is sampled by the
//! scalar code instead. Its functions inline into the rasterizer's AVX2 entry points and
//! run only when the CPU has AVX2 ([`super::fast_avx2::available`]).

use super::cube::Faces;
use super::cube_avx2::{abs, redo, Chunk, Levels8};
use super::sample::to_float;
use super::volume8::{lerp_wide, pack, weight, widen, Wide};
use super::{ExtKind, Level, UnitPlan};
use crate::simd::{F32x8, I32x8};

/// A unit's non-seamless cube-map state when the 8-wide sampler covers it.
#[derive(Clone, Copy)]
pub struct CubeAos8<'a> {
    /// The unit.
    p: &'a UnitPlan<'a>,
    /// The six faces' levels.
    faces: &'a Faces<'a>,
    /// The LOD, level selection and level sizes.
    lv: Levels8,
}

impl<'a> CubeAos8<'a> {
    /// The sampler of unit `p`, when it covers the unit's state.
    #[inline(always)]
    pub fn of(p: &'a UnitPlan<'a>) -> Option<CubeAos8<'a>> {
        let ExtKind::Cube(faces) = &p.ext.kind else {
            return None;
        };
        if !p.aos {
            return None;
        }
        let lv = Levels8::of(p, faces)?;
        Some(CubeAos8 { p, faces, lv })
    }

    /// Samples both rows of a chunk at directions `c` (`[s, t, r]`) into `out`, except
    /// the quads it returns (bit `j`: lanes `2j`, `2j + 1` of both rows), which have a live
    /// pixel and a lane it does not follow, for the caller to sample with the scalar code
    /// (`cube::sample_quad`). Lanes of quads without a live pixel may receive any value.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    pub unsafe fn rows(
        &self,
        c: [&[[f32; 8]; 2]; 3],
        live: &[[bool; 8]; 2],
        out: [&mut [[f32; 4]; 8]; 2],
    ) -> u32 {
        let (lv, qlive) = (&self.lv, super::soa_avx2::live_quads(live));
        if qlive == 0 {
            return 0;
        }
        // SAFETY: (all) the caller vouches for AVX2; the arrays are 8 lanes each.
        unsafe {
            let first = lv.sizes[self.p.first];
            let chunk = Chunk::of(self.p, lv.derivs, lv.sel, first, c);
            let mut bad = chunk.bad;
            for (row, out) in out.into_iter().enumerate() {
                let (face, fs, ft) = chunk.dirs[row].project(lv.derivs);
                let (l0, l1, frac) = chunk.sels[row];
                let a = self.level(face, fs, ft, l0, &mut bad[row]);
                let same = l1.cmpeq(l0);
                let c = if same.movemask() != 0xff {
                    let b = self.level(face, fs, ft, l1, &mut bad[row]);
                    // `(frac·256) as i32`, 0 where the levels are the same
                    let w = frac.mul(F32x8::splat(256.0)).to_i32_trunc();
                    let w = w.and(same.xor(I32x8::splat(-1)));
                    pack(lerp_wide(a, b, weight(w)))
                } else {
                    pack(a)
                };
                for (o, v) in out.iter_mut().zip(c.to_array()) {
                    *o = to_float((v as u32).to_le_bytes());
                }
            }
            redo(qlive, bad)
        }
    }

    /// One level per lane: the bilinear RGBA8 colour of faces `face` at `(fs, ft)` on
    /// levels `lvl`, as [`Wide`] fields; the lanes with a scaled coordinate of magnitude
    /// 2^30 or more (or NaN) are added to `bad`.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    unsafe fn level(&self, face: I32x8, fs: F32x8, ft: F32x8, lvl: I32x8, bad: &mut u32) -> Wide {
        // SAFETY: forwarded from the caller; levels are in `first..=last` (`select`), so
        // the gather reads inside `sizes`.
        unsafe {
            let n = I32x8::gather(self.lv.sizes.as_ptr(), lvl);
            let scale = n.to_f32().mul(F32x8::splat(256.0));
            let max = n.sub(I32x8::splat(1));
            let (x0, x1, wx) = axis(fs, scale, max, bad);
            let (y0, y1, wy) = axis(ft, scale, max, bad);
            let (r0, r1) = (y0.mullo(n), y1.mullo(n));
            let at = [r0.add(x0), r0.add(x1), r1.add(x0), r1.add(x1)];
            let taps = self.fetch(face, lvl, &at);
            let wx = weight(wx);
            let top = lerp_wide(widen(taps[0]), widen(taps[1]), wx);
            let bottom = lerp_wide(widen(taps[2]), widen(taps[3]), wx);
            lerp_wide(top, bottom, weight(wy))
        }
    }

    /// The image of face `face`, level `level`.
    #[inline(always)]
    fn image(&self, face: i32, level: i32) -> &'a Level {
        self.faces[face as usize][level as usize]
            .as_ref()
            .expect("cube complete")
    }

    /// The texels at indices `at` (each in `0..n²` of its lane's level) of each lane's face
    /// and level.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    #[allow(clippy::needless_range_loop)]
    unsafe fn fetch(&self, face: I32x8, lvl: I32x8, at: &[I32x8; 4]) -> [I32x8; 4] {
        // SAFETY: forwarded from the caller.
        unsafe {
            let (f0, l0) = (face.first(), lvl.first());
            let uniform = face
                .cmpeq(I32x8::splat(f0))
                .and(lvl.cmpeq(I32x8::splat(l0)))
                .movemask()
                == 0xff;
            if uniform {
                let img = self.image(f0, l0);
                let n = self.lv.sizes[l0 as usize] as usize;
                if img.texels.len() >= n * n {
                    let base = img.texels.as_ptr() as *const i32;
                    // SAFETY: every index is below n² (clamped to the face, `axis`), inside
                    // the texels (checked); a texel is 4 bytes, read as an i32.
                    return [
                        I32x8::gather(base, at[0]),
                        I32x8::gather(base, at[1]),
                        I32x8::gather(base, at[2]),
                        I32x8::gather(base, at[3]),
                    ];
                }
            }
            let (fa, la) = (face.to_array(), lvl.to_array());
            let at = [
                at[0].to_array(),
                at[1].to_array(),
                at[2].to_array(),
                at[3].to_array(),
            ];
            let mut raw = [[0i32; 8]; 4];
            for i in 0..8 {
                let img = self.image(fa[i], la[i]);
                for k in 0..4 {
                    raw[k][i] = i32::from_le_bytes(img.texels[at[k][i] as usize]);
                }
            }
            [
                I32x8::load(raw[0].as_ptr()),
                I32x8::load(raw[1].as_ptr()),
                I32x8::load(raw[2].as_ptr()),
                I32x8::load(raw[3].as_ptr()),
            ]
        }
    }
}

/// The LINEAR taps along one face axis at face coordinates `c` (`wrap::aos_linear` with
/// CLAMP_TO_EDGE): `(i0, i1, weight)` with both indices clamped into `0..=max`, where
/// `scale` is the level's `n·256`; lanes whose `c·scale` is NaN or of magnitude 2^30 or
/// more are added to `bad`.
///
/// # Safety
/// The CPU has AVX2.
#[inline(always)]
unsafe fn axis(c: F32x8, scale: F32x8, max: I32x8, bad: &mut u32) -> (I32x8, I32x8, I32x8) {
    // SAFETY: forwarded from the caller.
    unsafe {
        let u = c.mul(scale);
        // NaN compares false
        *bad |= !abs(u).cmp_lt(F32x8::splat(1_073_741_824.0)).movemask() & 0xff;
        let fx = u.to_i32().sub(I32x8::splat(128));
        let i0 = fx.sra::<8>();
        let zero = I32x8::zero();
        (
            i0.max(zero).min(max),
            i0.add(I32x8::splat(1)).max(zero).min(max),
            fx.and(I32x8::splat(255)),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::cube::sample_quad;
    use crate::texture::cube_avx2::tests::{check_quads, chunk, lod_state, state, LODS};

    #[test]
    fn rows_match_cube_sample_quad() {
        let (mut next, mut counts) = (crate::test_rng::xorshift32(58), [0; 2]);
        if !crate::texture::fast_avx2::available() {
            return;
        }
        for n in [1, 4, 16, 64, 256] {
            for (mip, bias, max_lod) in LODS {
                for fma in [false, true] {
                    let mut ts = state(n, false, &mut next);
                    ts.cube_seamless = false;
                    lod_state(&mut ts, mip, bias, max_lod);
                    let mut p = ts.unit_plan(0).expect("complete");
                    p.fma = fma && crate::texture::sample::has_fma();
                    let ExtKind::Cube(faces) = &p.ext.kind else {
                        panic!("not a plain cube map");
                    };
                    let c8 = CubeAos8::of(&p).expect("covered");
                    for k in 0..300 {
                        // every other chunk: four quads around one direction (mostly one
                        // face and level in all lanes)
                        let (c, live) = chunk(&mut next, k % 2 == 0);
                        let mut out = [[[-1.0f32; 4]; 8]; 2];
                        let [o0, o1] = &mut out;
                        // SAFETY: the CPU has AVX2 (checked above).
                        let redo = unsafe { c8.rows([&c[0], &c[1], &c[2]], &live, [o0, o1]) };
                        let scalar = |s, t, r| sample_quad(&p, faces, s, t, r);
                        let what = || format!("n {n} {mip:?} bias {bias} fma {fma}");
                        check_quads(&c, &live, &out, redo, scalar, &mut counts, &what);
                    }
                }
            }
        }
        let [vector, scalar] = counts;
        // the quads with special values go to the scalar code, the others stay
        assert!(vector > 20_000, "vector {vector} scalar {scalar}");
    }
}
