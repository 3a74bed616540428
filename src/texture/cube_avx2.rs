//! The 8-wide AVX2 seamless cube-map sampler: both rows of a chunk (four 2x2 quads) of a
//! GL_TEXTURE_CUBE_MAP with GL_TEXTURE_CUBE_MAP_SEAMLESS and LINEAR filtering, sampled a
//! row (8 pixels) at a time with exactly the arithmetic of
//! [`super::cube_seamless::sample_quad`].
//!
//! It serves the state of MuJoCo's skybox and of most seamless cube maps: 8-bit texels
//! (unorm, or through the plan's decode tables), both image filters LINEAR, and either no
//! LOD or llvmpipe's per-pixel cube LOD of a mipmapped texture ([`Cube8::of`]). Per lane it
//! computes, as the scalar code does:
//! - the major axis, face and mirrored minor coordinates ([`super::cube::project`]);
//! - the LOD of each pixel from its quad's row and column differences
//!   ([`super::cube`]'s `pixel_lod`, then `lod::from_rho` and `select_levels`);
//! - per level, `u = max(s, 0)·n − 0.5`, floor and fraction, the four texels read with
//!   `u·f32(1/255)` (or the decode tables), and the lerps `w·(b − a) + a`, fused exactly when
//!   the unit's lerps are (`UnitPlan::fma`); between two levels one more lerp.
//!
//! A quad with a tap off its face (the seamless edge and corner rules), or with a NaN or
//! infinite coordinate in any of its four pixels (helper pixels included, as they take
//! part in the quad's corner rule), is sampled by the scalar code instead: a few quads
//! along the face edges. Its functions inline into the rasterizer's AVX2 entry points and
//! run only when the CPU has AVX2 ([`super::fast_avx2::available`]).

use super::cube::Faces;
use super::lod::Lod;
use super::sample::select_levels;
use super::{ExtKind, Filter, MipFilter, UnitPlan, MAX_LEVELS};
use crate::simd::{F32x8, I32x8};

/// A unit's seamless cube-map state when the 8-wide sampler covers it.
#[derive(Clone, Copy)]
pub struct Cube8<'a> {
    /// The unit.
    p: &'a UnitPlan<'a>,
    /// The six faces' levels.
    faces: &'a Faces<'a>,
    /// The LOD is computed per pixel (else `sel` holds the one selection).
    derivs: bool,
    /// The level selection of every pixel when there are no derivatives.
    sel: (usize, usize, f32),
    /// The face size of each level.
    sizes: [i32; MAX_LEVELS],
}

/// A direction's major axis, face and mirrored minor coordinates, per lane.
#[derive(Clone, Copy)]
pub(super) struct Dir {
    /// The major axis is z (mask).
    z: F32x8,
    /// The major axis is x (mask).
    x: F32x8,
    /// The major coordinate.
    ma: F32x8,
    /// Its sign bit.
    ms: I32x8,
    /// The minor coordinates, mirrored.
    sc: F32x8,
    /// See `sc`.
    tc: F32x8,
}

/// One level selection per lane: `(level0, level1, fraction)`.
pub(super) type Sel8 = (I32x8, I32x8, F32x8);

impl<'a> Cube8<'a> {
    /// The sampler of unit `p`, when it covers the unit's state.
    #[inline(always)]
    pub fn of(p: &'a UnitPlan<'a>) -> Option<Cube8<'a>> {
        let ExtKind::CubeSeamless(faces) = &p.ext.kind else {
            return None;
        };
        if p.ext.floats || p.ext.depth.is_some() {
            return None;
        }
        let Levels8 { derivs, sel, sizes } = Levels8::of(p, faces)?;
        Some(Cube8 {
            p,
            faces,
            derivs,
            sel,
            sizes,
        })
    }

    /// Samples both rows of a chunk at directions `s`, `t`, `r` into `out`, except the
    /// quads it returns (bit `j`: lanes `2j`, `2j + 1` of both rows), which have a live
    /// pixel and a lane it does not follow, for the caller to sample with the scalar code
    /// (`cube_seamless::sample_quad`). Lanes of quads without a live pixel may receive any
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
        r: &[[f32; 8]; 2],
        live: &[[bool; 8]; 2],
        out: [&mut [[f32; 4]; 8]; 2],
    ) -> u32 {
        let qlive = super::soa_avx2::live_quads(live);
        if qlive == 0 {
            return 0;
        }
        // SAFETY: (all) the caller vouches for AVX2 (and FMA when the lerps fuse); the
        // arrays are 8 lanes each.
        unsafe {
            let size = self.sizes[self.p.first];
            let Chunk {
                dirs,
                sels,
                mut bad,
            } = Chunk::of(self.p, self.derivs, self.sel, size, [s, t, r]);
            for row in 0..2 {
                let (face, fs, ft) = dirs[row].project(self.derivs);
                let (l0, l1, frac) = sels[row];
                let a = self.level(face, fs, ft, l0, &mut bad[row]);
                let same = l1.cmpeq(l0);
                let c = if same.movemask() != 0xff {
                    let b = self.level(face, fs, ft, l1, &mut bad[row]);
                    let same = same.as_f32();
                    // the lerp between the levels where they differ
                    [
                        self.lerp(frac, a[0], b[0]).blendv(a[0], same),
                        self.lerp(frac, a[1], b[1]).blendv(a[1], same),
                        self.lerp(frac, a[2], b[2]).blendv(a[2], same),
                        self.lerp(frac, a[3], b[3]).blendv(a[3], same),
                    ]
                } else {
                    a
                };
                super::soa_avx2::store_pixels(c, out[row]);
            }
            redo(qlive, bad)
        }
    }

    /// One level per lane: the bilinear colour (R, G, B, A) of faces `face` at `(fs, ft)`
    /// on levels `lvl`; the lanes with a tap off the face are added to `bad`.
    ///
    /// # Safety
    /// The CPU has AVX2, and FMA when the unit's lerps fuse.
    #[inline(always)]
    unsafe fn level(
        &self,
        face: I32x8,
        fs: F32x8,
        ft: F32x8,
        lvl: I32x8,
        bad: &mut u32,
    ) -> [F32x8; 4] {
        // SAFETY: forwarded from the caller; levels are in `first..=last` (`select`), so
        // the gather reads inside `sizes`.
        unsafe {
            let n = I32x8::gather(self.sizes.as_ptr(), lvl);
            let (size, max) = (n.to_f32(), n.sub(I32x8::splat(1)));
            let zero = I32x8::zero();
            let ((x0, wx), (y0, wy)) = (split(fs, size), split(ft, size));
            // off the face: x0 < 0 or x0 + 1 > max (a huge u converts to i32::MIN)
            let last0 = max.sub(I32x8::splat(1));
            let off = zero
                .cmpgt(x0)
                .or(x0.cmpgt(last0))
                .or(zero.cmpgt(y0))
                .or(y0.cmpgt(last0));
            *bad |= off.as_f32().movemask();
            // indices kept inside the level for every lane
            let one = I32x8::splat(1);
            let (x1, y1) = (
                x0.add(one).max(zero).min(max),
                y0.add(one).max(zero).min(max),
            );
            let (x0, y0) = (x0.max(zero).min(max), y0.max(zero).min(max));
            let (r0, r1) = (y0.mullo(n), y1.mullo(n));
            let at = [
                r0.add(x0).to_array(),
                r0.add(x1).to_array(),
                r1.add(x0).to_array(),
                r1.add(x1).to_array(),
            ];
            let (fa, la) = (face.to_array(), lvl.to_array());
            let mut raw = [[0u32; 8]; 4];
            for i in 0..8 {
                let img = self.faces[fa[i] as usize][la[i] as usize]
                    .as_ref()
                    .expect("cube complete");
                for (k, at) in at.iter().enumerate() {
                    raw[k][i] = u32::from_le_bytes(img.texels[at[i] as usize]);
                }
            }
            let n = [
                self.texels(&raw[0]),
                self.texels(&raw[1]),
                self.texels(&raw[2]),
                self.texels(&raw[3]),
            ];
            [
                self.bilerp(wx, wy, &n, 0),
                self.bilerp(wx, wy, &n, 1),
                self.bilerp(wx, wy, &n, 2),
                self.bilerp(wx, wy, &n, 3),
            ]
        }
    }

    /// Eight packed texels as floats per channel (`texel_float`, through
    /// [`super::soa_avx2::texels8`]).
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    unsafe fn texels(&self, raw: &[u32; 8]) -> [F32x8; 4] {
        // SAFETY: forwarded from the caller; 8 lanes.
        unsafe { super::soa_avx2::texels8(self.p, I32x8::load(raw.as_ptr())) }
    }

    /// Channel `c` of the bilinear filter of taps `n` (n00, n01, n10, n11).
    #[inline(always)]
    fn bilerp(&self, wx: F32x8, wy: F32x8, n: &[[F32x8; 4]; 4], c: usize) -> F32x8 {
        let n = [n[0][c], n[1][c], n[2][c], n[3][c]];
        super::soa_avx2::bilerp(self.p.fma, wx, wy, n)
    }

    /// `lerpf(fma, w, a, b)` per lane.
    #[inline(always)]
    fn lerp(&self, w: F32x8, a: F32x8, b: F32x8) -> F32x8 {
        super::soa_avx2::lerp(self.p.fma, w, a, b)
    }
}

/// The level state the 8-wide cube samplers share: both image filters LINEAR, and either
/// no LOD or llvmpipe's per-pixel cube LOD of a mipmapped texture.
#[derive(Clone, Copy)]
pub(super) struct Levels8 {
    /// The LOD is computed per pixel (else `sel` holds the one selection).
    pub(super) derivs: bool,
    /// The level selection of every pixel when there are no derivatives.
    pub(super) sel: (usize, usize, f32),
    /// The face size of each level.
    pub(super) sizes: [i32; MAX_LEVELS],
}

impl Levels8 {
    /// The level state of unit `p` with faces `faces`, when the 8-wide samplers cover it.
    #[inline(always)]
    #[allow(clippy::needless_range_loop)]
    pub(super) fn of(p: &UnitPlan<'_>, faces: &Faces<'_>) -> Option<Levels8> {
        if p.min_filter != Filter::Linear || p.mag_filter != Filter::Linear {
            return None;
        }
        let derivs = p.needs_lod && !p.lod.min_max_equal;
        // without a mip filter llvmpipe takes the quad's top-left LOD (not covered)
        if derivs && p.mip_filter == MipFilter::None {
            return None;
        }
        let mut sizes = [1i32; MAX_LEVELS];
        for l in p.first..=p.last {
            let n = faces[0].get(l)?.as_ref()?.width;
            // every index `y·n + x` fits an i32 lane
            if n.checked_mul(n)? >= 1 << 30 {
                return None;
            }
            sizes[l] = n as i32;
        }
        let sel = if derivs {
            (p.first, p.first, 0.0)
        } else {
            let lod = if p.needs_lod {
                super::lod::from_rho(&p.lod, p.mip_filter, true, 0.0)
            } else {
                Lod::MAG
            };
            let (_, l0, l1, f) = select_levels(p, lod);
            (l0, l1, f)
        };
        Some(Levels8 { derivs, sel, sizes })
    }
}

/// What both rows of a chunk share before their texels are read: the directions, each
/// lane's level selection, and per row the lanes (bits) whose coordinates are not all
/// finite (their quads go to the scalar code).
pub(super) struct Chunk {
    /// Per row: the direction of each lane.
    pub(super) dirs: [Dir; 2],
    /// Per row: the level selection of each lane.
    pub(super) sels: [Sel8; 2],
    /// Per row: the lanes with a NaN or infinite coordinate.
    pub(super) bad: [u32; 2],
}

impl Chunk {
    /// The directions at `[s, t, r]` of unit `p` and their levels: per pixel from the
    /// quads' row and column differences in texels of a face of `size` when `derivs`,
    /// else `sel` for every lane.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    pub(super) unsafe fn of(
        p: &UnitPlan<'_>,
        derivs: bool,
        sel: (usize, usize, f32),
        size: i32,
        [s, t, r]: [&[[f32; 8]; 2]; 3],
    ) -> Chunk {
        let mut bad = [0u32; 2];
        // SAFETY: forwarded from the caller; the arrays are 8 lanes each.
        unsafe {
            // (no closures here or below: one the compiler leaves out of line loses the
            // caller's target features)
            let v = [
                [
                    F32x8::load(s[0].as_ptr()),
                    F32x8::load(t[0].as_ptr()),
                    F32x8::load(r[0].as_ptr()),
                ],
                [
                    F32x8::load(s[1].as_ptr()),
                    F32x8::load(t[1].as_ptr()),
                    F32x8::load(r[1].as_ptr()),
                ],
            ];
            let inf = F32x8::splat(f32::INFINITY);
            for row in 0..2 {
                for c in v[row] {
                    // |c| < inf: false for NaN and infinities
                    bad[row] |= !abs(c).cmp_lt(inf).movemask() & 0xff;
                }
            }
            let dirs = [Dir::of(v[0]), Dir::of(v[1])];
            let sels = if derivs {
                // ddy: bottom minus top of the pixel's column, the same for both rows
                let ddy = [
                    v[1][0].sub(v[0][0]),
                    v[1][1].sub(v[0][1]),
                    v[1][2].sub(v[0][2]),
                ];
                let size = F32x8::splat(size as f32);
                // ddx: right minus left of the pixel's row in its quad
                let ddx0 = [quad_dx(v[0][0]), quad_dx(v[0][1]), quad_dx(v[0][2])];
                let ddx1 = [quad_dx(v[1][0]), quad_dx(v[1][1]), quad_dx(v[1][2])];
                [
                    select(p, dirs[0].rho(size, ddx0, ddy)),
                    select(p, dirs[1].rho(size, ddx1, ddy)),
                ]
            } else {
                let (l0, l1, f) = sel;
                let sel = (
                    I32x8::splat(l0 as i32),
                    I32x8::splat(l1 as i32),
                    F32x8::splat(f),
                );
                [sel, sel]
            };
            Chunk { dirs, sels, bad }
        }
    }
}

/// The quads (bit `j`: lanes `2j`, `2j + 1` of both rows) with a live pixel (`qlive`)
/// and a lane in `bad` (per row).
#[inline(always)]
pub(super) fn redo(qlive: u32, bad: [u32; 2]) -> u32 {
    let lanes = bad[0] | bad[1];
    (0..4).fold(0, |m, j| {
        let redo = qlive >> j & 1 != 0 && lanes >> (2 * j) & 3 != 0;
        m | (u32::from(redo) << j)
    })
}

/// The level selection of each lane of unit `p` from its rho² (`lod::from_rho` with
/// `select_levels`; the image filters are both LINEAR).
///
/// # Safety
/// The CPU has AVX2.
#[inline(always)]
pub(super) unsafe fn select(p: &UnitPlan<'_>, rho: F32x8) -> Sel8 {
    let lp = &p.lod;
    // SAFETY: forwarded from the caller.
    unsafe {
        let zero = F32x8::zero();
        let bits = rho.bits();
        let e = bits
            .shr::<23>()
            .and(I32x8::splat(0xff))
            .sub(I32x8::splat(127));
        let fast = lp.bias == 0.0 && !lp.apply_min && !lp.apply_max;
        let (positive, ipart, fpart) = if fast && p.mip_filter != MipFilter::Linear {
            let ipart = e.add(I32x8::splat(1)).sra::<1>();
            (rho.cmp_gt(F32x8::splat(1.0)), ipart, zero)
        } else {
            // `fast_log2(rho²)·0.5`
            let m = bits
                .and(I32x8::splat(0x007f_ffff))
                .or(I32x8::splat(0x3f80_0000))
                .as_f32();
            let mut lod = e
                .sub(I32x8::splat(1))
                .to_f32()
                .add(m)
                .mul(F32x8::splat(0.5));
            if lp.bias != 0.0 {
                lod = lod.add(F32x8::splat(lp.bias));
            }
            if lp.apply_max {
                lod = lod.min(F32x8::splat(lp.max_lod));
            }
            if lp.apply_min {
                lod = lod.max(F32x8::splat(lp.min_lod));
            }
            let positive = lod.cmp_gt(zero);
            if p.mip_filter == MipFilter::Linear {
                let f = lod.floor();
                (positive, f.to_i32_trunc(), lod.sub(f))
            } else {
                (positive, lod.round_even().to_i32_trunc(), zero)
            }
        };
        let (first, last) = (I32x8::splat(p.first as i32), I32x8::splat(p.last as i32));
        let minified = positive.bits();
        match p.mip_filter {
            MipFilter::None => (first, first, zero),
            MipFilter::Nearest => {
                let l = ipart.add(first).max(first).min(last);
                let l = first.blendv(l, minified);
                (l, l, zero)
            }
            MipFilter::Linear => {
                let l0 = ipart.add(first);
                // below the base: the base alone; at or past the last: the last alone
                let below = first.cmpgt(l0);
                let past = l0.cmpgt(last.sub(I32x8::splat(1)));
                let one = below.or(past).xor(I32x8::splat(-1)).and(minified);
                let l = first.blendv(last, past.and(minified));
                let l0 = l.blendv(l0, one);
                let l1 = l.blendv(l0.add(I32x8::splat(1)), one);
                (l0, l1, zero.blendv(fpart, one.as_f32()))
            }
        }
    }
}

/// `max(c, 0)·n − 0.5` (NaN → 0) per lane, floored to an index (`i32::MIN` when too
/// large) and the fraction.
///
/// # Safety
/// The CPU has AVX2.
#[inline(always)]
unsafe fn split(c: F32x8, size: F32x8) -> (I32x8, F32x8) {
    // SAFETY: forwarded from the caller.
    unsafe {
        let u = c.max(F32x8::zero()).mul(size).sub(F32x8::splat(0.5));
        let f = u.floor();
        (f.to_i32_trunc(), u.sub(f))
    }
}

/// Right minus left of each lane's pair (the row difference in a 2x2 quad).
#[inline(always)]
pub(super) fn quad_dx(v: F32x8) -> F32x8 {
    v.permute::<0xF5>().sub(v.permute::<0xA0>())
}

/// `|v|` per lane.
#[inline(always)]
pub(super) fn abs(v: F32x8) -> F32x8 {
    // SAFETY: AVX2 as `v` proves.
    let m = unsafe { I32x8::splat(0x7fff_ffff) };
    v.bits().and(m).as_f32()
}

/// `v` with its sign bits flipped by `m`.
#[inline(always)]
fn flip(v: F32x8, m: I32x8) -> F32x8 {
    v.bits().xor(m).as_f32()
}

impl Dir {
    /// The major axis of directions `v` (finite lanes; others are sampled by the scalar
    /// code): z when `|r| ≥ max(|s|, |t|)`, else x when `|s| > |t|`, else y.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    pub(super) unsafe fn of(v: [F32x8; 3]) -> Dir {
        let [s, t, r] = v;
        // SAFETY: forwarded from the caller.
        unsafe {
            let (a_s, a_t, a_r) = (abs(s), abs(t), abs(r));
            let z = a_r.cmp_ge(a_s.max(a_t));
            let x = a_s.cmp_gt(a_t).blendv(F32x8::zero(), z);
            let ma = t.blendv(s, x).blendv(r, z);
            let ms = ma.bits().and(I32x8::splat(i32::MIN));
            let (sc, tc) = Dir::mirror(z, x, ms, v);
            Dir {
                z,
                x,
                ma,
                ms,
                sc,
                tc,
            }
        }
    }

    /// The mirrored minor coordinates of `v` (a direction, or a difference of two) on
    /// this direction's axis and sign: x: `(−sgn·r, −t)`, y: `(s, sgn·r)`, z: `(sgn·s, −t)`.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    unsafe fn mirror(z: F32x8, x: F32x8, ms: I32x8, v: [F32x8; 3]) -> (F32x8, F32x8) {
        let [s, t, r] = v;
        // SAFETY: forwarded from the caller.
        let neg = unsafe { I32x8::splat(i32::MIN) };
        let sc = s.blendv(flip(r, ms.xor(neg)), x).blendv(flip(s, ms), z);
        let tc = flip(r, ms).blendv(flip(t, neg), x.bits().or(z.bits()).as_f32());
        (sc, tc)
    }

    /// The face and face coordinates (`cube::project`); `lod` selects the `need_derivs`
    /// projection.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    pub(super) unsafe fn project(&self, lod: bool) -> (I32x8, F32x8, F32x8) {
        // SAFETY: forwarded from the caller.
        unsafe {
            let half = F32x8::splat(0.5);
            let k = if lod {
                abs(half.mul(F32x8::splat(1.0).div(self.ma)))
            } else {
                let a = abs(self.ma);
                half.div(a).and(a.cmp_gt(F32x8::zero()))
            };
            // axis 0 (x), 1 (y), 2 (z), twice, plus the sign bit
            let axis = I32x8::splat(2)
                .blendv(I32x8::zero(), self.x.bits())
                .blendv(I32x8::splat(4), self.z.bits());
            let face = axis.add(self.ms.shr::<31>());
            (face, self.sc.mul(k).add(half), self.tc.mul(k).add(half))
        }
    }

    /// The squared length, in texels of a face of `size`, of the face derivative of
    /// direction difference `d` (`cube`'s `Deriv::sq`).
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    unsafe fn sq(&self, ima: F32x8, imahalf: F32x8, size: F32x8, d: [F32x8; 3]) -> F32x8 {
        // SAFETY: forwarded from the caller.
        let (dsc, dtc) = unsafe { Dir::mirror(self.z, self.x, self.ms, d) };
        let dma = d[1].blendv(d[0], self.x).blendv(d[2], self.z);
        let m = dma.mul(ima);
        let a = dsc.sub(m.mul(self.sc)).mul(imahalf);
        let b = dtc.sub(m.mul(self.tc)).mul(imahalf);
        let (a, b) = (size.mul(a), size.mul(b));
        a.mul(a).add(b.mul(b))
    }

    /// rho² of each pixel (`cube::pixel_lod`): the larger of the squared face derivatives
    /// of `ddx` and `ddy` in texels of a face of `size`, as `f32::max` takes it (a NaN
    /// gives the other), and 0 where that is not finite.
    ///
    /// # Safety
    /// The CPU has AVX2.
    #[inline(always)]
    pub(super) unsafe fn rho(&self, size: F32x8, ddx: [F32x8; 3], ddy: [F32x8; 3]) -> F32x8 {
        // SAFETY: forwarded from the caller.
        unsafe {
            let ima = F32x8::splat(1.0).div(self.ma);
            let imahalf = F32x8::splat(0.5).mul(ima);
            let (rx, ry) = (
                self.sq(ima, imahalf, size, ddx),
                self.sq(ima, imahalf, size, ddy),
            );
            // `vmaxps(rx, ry)` gives ry when either is NaN; a NaN ry gives rx
            let ry_nan = ry.cmp_ord(ry).bits().xor(I32x8::splat(-1)).as_f32();
            let m = rx.max(ry).blendv(rx, ry_nan);
            m.and(abs(m).cmp_lt(F32x8::splat(f32::INFINITY)))
        }
    }
}

#[cfg(test)]
#[path = "cube_avx2_tests.rs"]
pub(super) mod tests;
