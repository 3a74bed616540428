//! The 8-wide chunk walk of the texture fast path: everything of a chunk (two rows of 8
//! pixels) stays in AVX2 registers from the planes to the store — lane masks from the
//! row spans, `1 / w`, the projected coordinates, the level of detail of its four quads,
//! the gathers and the environment. It computes exactly what the array walk of
//! [`super::rows_tex_fast`] computes (same operations in the same order), and hands a
//! chunk it cannot sample in registers (a LOD form it does not vectorise, a coordinate
//! the vector sampler declines) to
//! [`crate::texture::fast::chunk_u8`], the array sampler, which gives the same bytes.

use super::super::prefetch_row;
use super::super::row_pairs::RowPairs;
use crate::fragment::simd_tex::{eval8, shade8, Row8, White};
use crate::fragment::span::LANES;
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::setup::{Plane, SetupTriangle};
use crate::geometry::VARY_TEX;
use crate::simd::{F32x8, I32x8};
use crate::stats::Stats;
use crate::texture::fast::FastEnv;
use crate::texture::fast_avx2::chunk::{bits, Sampling};
use crate::texture::UnitPlan;

/// The most 64-byte lines per row the walk asks for ahead (64 pixels, a 1024² sprite's
/// row and then some); longer rows are sequential, which the hardware prefetcher follows.
const PREFETCH_LINES: usize = 4;

/// Whether `p` is the constant plane 1.0 (its value is exactly 1.0 at every pixel).
fn is_one(p: &Plane) -> bool {
    p.a0 == 1.0 && p.dadx == 0.0 && p.dady == 0.0
}

/// The lane bounds of a row span as `(a − 1, z + 1)` (no span: no lane is inside).
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn bounds(s: Option<(i64, i64)>) -> (I32x8, I32x8) {
    // SAFETY: AVX2 context (the caller's promise).
    unsafe {
        match s {
            Some((a, z)) => (I32x8::splat(a as i32 - 1), I32x8::splat(z as i32 + 1)),
            None => (I32x8::splat(i32::MAX), I32x8::splat(i32::MIN)),
        }
    }
}

/// Lanes `xi` with `a <= xi <= z`, from [`bounds`].
#[inline(always)]
fn inside(xi: I32x8, (am1, zp1): (I32x8, I32x8)) -> I32x8 {
    xi.cmpgt(am1).and(zp1.cmpgt(xi))
}

/// `1 / q` in every lane, bit for bit what `vdivps` gives, without the division when every
/// lane is within one ulp of 1.0 (an ordinary texture coordinate's `q`, 1 per vertex,
/// comes out of the perspective divide as `(q/w)·w`, which rounds to one of these): the
/// correctly rounded reciprocals of `1 − 2⁻²³`, `1 − 2⁻²⁴`, `1`, `1 + 2⁻²³` are
/// `1 + 2⁻²³`, `1 + 2⁻²³`, `1`, `1 − 2⁻²³`. The division sat on each chunk's critical
/// path between the `1/w` division and the gathers' addresses.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn recip(q: F32x8) -> F32x8 {
    const ULP: f32 = f32::EPSILON; // 2^-23
                                   // SAFETY: AVX2 context (the caller's promise).
    let (one, lo, hi) = unsafe {
        (
            F32x8::splat(1.0),
            F32x8::splat(1.0 - ULP),
            F32x8::splat(1.0 + ULP),
        )
    };
    let near = q.cmp_ge(lo).and(q.cmp_le(hi));
    if near.movemask() != 0xff {
        return one.div(q);
    }
    let below = one.blendv(hi, q.cmp_lt(one));
    below.blendv(lo, q.cmp_gt(one))
}

/// Shades the rows `b` of `t` through the 8-wide walk (see the module comment). The
/// caller has checked that [`crate::fragment::simd_tex::plan_ok`] accepts the plan.
///
/// # Safety
/// Must be called from a function compiled with AVX2 (and FMA when `FMA`), on a CPU that
/// has them.
#[inline(always)]
pub(in crate::raster) unsafe fn rows<
    const FMA: bool,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
>(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    u: &UnitPlan<'_>,
    env: FastEnv,
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    let white = White::of::<FLAT, PERSP>(t, env);
    let q_one = !PERSP && is_one(&t.vary[VARY_TEX + 3]);
    let over = plan
        .blend
        .as_ref()
        .is_some_and(crate::fragment::simd::blend_is_over);
    let blend = plan.blend.is_some();
    // SAFETY: (whole loop) AVX2 (+FMA) context from the caller; `shade8` gets lanes
    // inside their row (the spans lie in `b`, which lies in the target).
    unsafe {
        let mut sampling = Sampling::new(u);
        // Chunks start at even pixels only for the LOD's 2x2 quads; without a LOD every
        // pixel is sampled on its own, and starting at the span (a 16-px sprite row that
        // begins at an odd x fits 2 chunks instead of 3) gives the same bytes.
        let align = if sampling.quads() { !1 } else { !0 };
        let lane_i = I32x8::new([0, 1, 2, 3, 4, 5, 6, 7]);
        let lane_f = F32x8::new([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]);
        let one = F32x8::splat(1.0);
        let vary = &t.vary[VARY_TEX..];
        for pair in RowPairs::new(std::array::from_ref(&t.edges), b, align) {
            let (qy, lo, hi) = (pair.qy, pair.lo, pair.hi);
            let spans = [pair.spans[0][0], pair.spans[1][0]];
            // The chunk rows two rows down: a sprite's rows lie a framebuffer row apart, and
            // without this the walk's first load of each chunk row waited on the cache
            // (sprites_10k at 1024², one thread: 52 → 39 ms).
            for py in qy + 2..qy + 4 {
                prefetch_row(fb, py, lo, hi, DEPTH, PREFETCH_LINES);
            }
            let bnd = [bounds(spans[0]), bounds(spans[1])];
            let fy = [F32x8::splat(qy as f32), F32x8::splat((qy + 1) as f32)];
            let mut x = lo & align;
            while x <= hi {
                let xi = I32x8::splat(x as i32).add(lane_i);
                let live = [inside(xi, bnd[0]), inside(xi, bnd[1])];
                let lm = [bits(live[0]), bits(live[1])];
                if lm[0] | lm[1] == 0 {
                    x += LANES as i64;
                    continue;
                }
                // Integers below 2^24 are exact in f32: this is `(x + i) as f32`.
                let fx = F32x8::splat(x as f32).add(lane_f);
                let mut xw = [one; 2];
                let mut oow = [one; 2];
                let mut s = [one; 2];
                let mut tt = [one; 2];
                for r in 0..2 {
                    let mut sr = eval8::<FMA>(&vary[0], fx, fy[r]);
                    let mut tv = eval8::<FMA>(&vary[1], fx, fy[r]);
                    if PERSP {
                        xw[r] = eval8::<FMA>(&t.w, fx, fy[r]);
                        oow[r] = one.div(xw[r]);
                        sr = sr.mul(oow[r]);
                        tv = tv.mul(oow[r]);
                    }
                    if !q_one {
                        let q = eval8::<FMA>(&vary[3], fx, fy[r]);
                        let q = if PERSP { q.mul(oow[r]) } else { q };
                        let rq = recip(q);
                        sr = sr.mul(rq);
                        tv = tv.mul(rq);
                    }
                    s[r] = sr;
                    tt[r] = tv;
                }
                let texv = sampling.texels(s, tt, live);
                for r in 0..2 {
                    if lm[r] == 0 {
                        continue;
                    }
                    let row = Row8 {
                        t,
                        plan,
                        env,
                        white,
                        py: (qy + r as i64) as usize,
                        x: x as usize,
                        live: live[r],
                        tex: texv[r],
                        fx,
                        fy: fy[r],
                        w: xw[r],
                        oow: oow[r],
                    };
                    match (blend, over) {
                        (false, _) => {
                            shade8::<FMA, DEPTH, FLAT, PERSP, false, false>(&row, fb, stats)
                        }
                        (true, false) => {
                            shade8::<FMA, DEPTH, FLAT, PERSP, true, false>(&row, fb, stats)
                        }
                        (true, true) => {
                            shade8::<FMA, DEPTH, FLAT, PERSP, true, true>(&row, fb, stats)
                        }
                    }
                }
                x += LANES as i64;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`recip`] on 8 lanes, on a CPU with AVX2.
    #[target_feature(enable = "avx2")]
    unsafe fn recip8(q: [f32; 8]) -> [f32; 8] {
        let mut out = [0f32; 8];
        // SAFETY: AVX2 (this function's feature); the arrays are 8 f32.
        unsafe {
            recip(F32x8::load(q.as_ptr())).store(out.as_mut_ptr());
        }
        out
    }

    /// Every lane is `1.0 / q` bit for bit: the lanes near 1.0 (taken without a division
    /// when all eight are), far from it, and mixes of both, plus zeros, infinities and NaN.
    #[test]
    fn recip_is_the_division() {
        if !crate::cpu::isa().avx2() {
            return;
        }
        let one = 1.0f32.to_bits();
        let mut values: Vec<f32> = (one - 600..one + 600).map(f32::from_bits).collect();
        values.extend([
            0.0,
            -0.0,
            f32::INFINITY,
            -1.0,
            2.0,
            0.5,
            3.0,
            f32::NAN,
            1e-40,
        ]);
        let check = |q: [f32; 8]| {
            // SAFETY: AVX2 was detected above.
            let got = unsafe { recip8(q) };
            for i in 0..8 {
                let want = 1.0 / q[i];
                assert!(
                    got[i].to_bits() == want.to_bits() || (got[i].is_nan() && want.is_nan()),
                    "1/{:e}: {:e} instead of {:e}",
                    q[i],
                    got[i],
                    want
                );
            }
        };
        for w in values.windows(8) {
            check(w.try_into().unwrap());
            for &k in &[1usize, 5] {
                let mut q: [f32; 8] = w.try_into().unwrap();
                q.rotate_left(k);
                q[k] = 1.0;
                check(q);
            }
        }
        for q in [
            1.0 - f32::EPSILON,
            1.0 - f32::EPSILON / 2.0,
            1.0,
            1.0 + f32::EPSILON,
        ] {
            check([q; 8]);
            check([q, 1.0, q, 1.0 + f32::EPSILON, q, q, 1.0 - f32::EPSILON, q]);
        }
    }
}
