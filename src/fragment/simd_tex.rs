//! The AVX2 per-fragment half of the texture fast path (`raster::textured`): one row of a
//! chunk (8 pixels) whose 8-bit texture values are known, through the specialised texture
//! environment ([`FastEnv`]), the depth test, blending and the colour write, in 256-bit
//! registers.
//!
//! It computes exactly what [`super::span::shade_chunk`] computes after
//! [`crate::texture::fast::env_lanes`]: the primary colour from the planes as
//! [`super::span::frag_colors`] evaluates them (fused only in the FMA variant, the exact
//! reciprocal of the 1/w plane), `t = u8 · f32(1/255)`, MODULATE `t·f`, DECAL
//! `t·a + f·(1 − a)` (separate roundings), and `unorm8` as clamp (NaN → 0), ·255 and
//! `cvtps2dq` (round half to even); depth and blending as [`super::simd`].

#![cfg(target_arch = "x86_64")]

use super::simd::{depth_test8, eval, sat, write8};
use super::FragPlan;
use crate::framebuffer::{ColorFormat, Target};
use crate::geometry::setup::{Plane, SetupTriangle};
use crate::simd::{F32x8, I32x8};
use crate::stats::Stats;
use crate::texture::fast::{EnvOp, FastEnv};
use crate::texture::sample::INV_255;

/// Whether [`tex_row`] covers this plan: no alpha test, stencil, logic op or occlusion
/// count, a full colour mask or none, and a colour format stored as RGBA8 unchanged.
pub fn plan_ok(plan: &FragPlan, fb: &Target<'_>) -> bool {
    plan.alpha.is_none()
        && plan.stencil.is_none()
        && plan.logic.is_none()
        && !plan.count_samples
        && (plan.color_mask == [true; 4] || plan.color_mask == [false; 4])
        && matches!(
            fb.format,
            ColorFormat::Rgba | ColorFormat::Bgra | ColorFormat::Argb
        )
}

/// Evaluates a plane at 8 lanes (`fragment::simd`'s evaluation, for the texture walk).
///
/// # Safety
/// Must be called from a function compiled with AVX2 (and FMA when `FMA`).
#[inline(always)]
pub unsafe fn eval8<const FMA: bool>(p: &Plane, fx: F32x8, fy: F32x8) -> F32x8 {
    // SAFETY: forwarded from the caller.
    unsafe { eval::<FMA>(p, fx, fy) }
}

/// When the primary colour is white for the environment: every channel it reads is
/// MODULATEd (or not read), and its value makes `unorm8(t·f) = t` for every texel byte.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum White {
    /// Not known to be white: the colour is evaluated.
    No,
    /// Exactly 1.0 at every pixel (flat 1.0, or a constant plane of 1.0 without the
    /// perspective divide): the environment passes the texture value through.
    Exact,
    /// Perspective, with each read colour plane bit for bit the `1/w` plane (colour 1.0
    /// at every vertex): the colour is `x·(1/x)` for the row's `x = w plane`, which is
    /// within [`WHITE_LO`, `WHITE_HI`] (checked per lane; other lanes take the general
    /// path for the row).
    PerLane,
}

/// The range of colour values `f` with `unorm8(u·f32(1/255)·f) = u` for every byte `u`
/// that [`White::PerLane`] accepts (checked by a test over every float in it).
pub const WHITE_LO: f32 = 1.0 - 1.0 / 4_194_304.0;
/// Upper end of [`WHITE_LO`]'s range.
pub const WHITE_HI: f32 = 1.0 + 1.0 / 4_194_304.0;

impl White {
    /// The white form of triangle `t`'s primary colour for `env`.
    pub fn of<const FLAT: bool, const PERSP: bool>(t: &SetupTriangle, env: FastEnv) -> White {
        let modulate_or_tex = |op: EnvOp| matches!(op, EnvOp::Tex | EnvOp::Modulate);
        if !env.reads_frag() || !modulate_or_tex(env.rgb) || !modulate_or_tex(env.alpha) {
            return White::No;
        }
        let read = |ch: usize| {
            if ch == 3 {
                env.alpha != EnvOp::Tex
            } else {
                env.rgb != EnvOp::Tex
            }
        };
        let all = |f: &dyn Fn(usize) -> bool| (0..4).all(|ch| !read(ch) || f(ch));
        if FLAT {
            if all(&|ch| t.flat[ch] == 1.0) {
                return White::Exact;
            }
        } else if !PERSP {
            let one = |p: &Plane| p.a0 == 1.0 && p.dadx == 0.0 && p.dady == 0.0;
            if all(&|ch| one(&t.vary[ch])) {
                return White::Exact;
            }
        } else {
            let same = |p: &Plane| {
                p.a0.to_bits() == t.w.a0.to_bits()
                    && p.dadx.to_bits() == t.w.dadx.to_bits()
                    && p.dady.to_bits() == t.w.dady.to_bits()
            };
            if all(&|ch| same(&t.vary[ch])) {
                return White::PerLane;
            }
        }
        White::No
    }
}

/// One row of a chunk for [`shade8`]: where (`py`, `x`, lanes `fx`, row `fy`), which
/// lanes are covered (`live`, all-ones lanes), their RGBA8 texture values `tex`, and with
/// `PERSP` the row's `w` plane values and their reciprocal `oow` (else 1.0).
#[derive(Clone, Copy)]
pub struct Row8<'a> {
    /// The triangle.
    pub t: &'a SetupTriangle,
    /// The per-fragment plan ([`plan_ok`] accepts it).
    pub plan: &'a FragPlan,
    /// The environment.
    pub env: FastEnv,
    /// Whether the primary colour is white ([`White::of`]).
    pub white: White,
    /// Pixel row.
    pub py: usize,
    /// First pixel column.
    pub x: usize,
    /// Covered lanes.
    pub live: I32x8,
    /// Texture values.
    pub tex: I32x8,
    /// Pixel x of each lane as f32.
    pub fx: F32x8,
    /// Pixel y as f32.
    pub fy: F32x8,
    /// The `1/w` plane at each lane (PERSP).
    pub w: F32x8,
    /// `1 / w` (PERSP).
    pub oow: F32x8,
}

/// Shades the `live` lanes of the 8 pixels from `x` in row `py` with texture values
/// `tex` (RGBA8 per lane) and the fast environment `env`; `OVER` (with `BLEND`) when the
/// plan's blend is [`super::simd::blend_is_over`].
///
/// # Safety
/// Must be called from a function compiled with AVX2 (and FMA when `FMA`), for a plan
/// that [`plan_ok`] accepts; live lanes lie inside the row.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub unsafe fn tex_row<
    const FMA: bool,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
    const BLEND: bool,
    const OVER: bool,
>(
    t: &SetupTriangle,
    plan: &FragPlan,
    env: FastEnv,
    fb: &mut Target<'_>,
    py: usize,
    x: usize,
    live: &[bool; 8],
    tex: &[[u8; 4]; 8],
    stats: &mut Stats,
) {
    // SAFETY: forwarded from the caller; `tex` is 32 bytes.
    unsafe {
        let m = |i: usize| -(live[i] as i32);
        let fx = F32x8::splat(x as f32).add(F32x8::new([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]));
        let fy = F32x8::splat(py as f32);
        let (w, oow) = if PERSP && !FLAT {
            let w = eval::<FMA>(&t.w, fx, fy);
            (w, F32x8::splat(1.0).div(w))
        } else {
            (F32x8::splat(1.0), F32x8::splat(1.0))
        };
        let row = Row8 {
            t,
            plan,
            env,
            white: White::No,
            py,
            x,
            live: I32x8::new([m(0), m(1), m(2), m(3), m(4), m(5), m(6), m(7)]),
            tex: I32x8::load(tex.as_ptr()),
            fx,
            fy,
            w,
            oow,
        };
        shade8::<FMA, DEPTH, FLAT, PERSP, BLEND, OVER>(&row, fb, stats)
    }
}

/// Channel `ch` of 8 RGBA8 values as 32-bit integers.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn channel(v: I32x8, ch: usize) -> I32x8 {
    // SAFETY: forwarded from the caller.
    unsafe {
        v.shr_var(I32x8::splat(8 * ch as i32))
            .and(I32x8::splat(255))
    }
}

/// `u8 · f32(1/255)` of channel `ch`.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn tex_f(v: I32x8, ch: usize) -> F32x8 {
    // SAFETY: forwarded from the caller.
    unsafe { channel(v, ch).to_f32().mul(F32x8::splat(INV_255)) }
}

/// `unorm8`: clamp (NaN → 0), ·255, round half to even.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn unorm(c: F32x8) -> I32x8 {
    // SAFETY: forwarded from the caller.
    unsafe { sat(c).mul(F32x8::splat(255.0)).to_i32() }
}

/// The primary colour's channel `ch` of a row.
///
/// # Safety
/// AVX2 context (FMA when `FMA`).
#[inline(always)]
unsafe fn frag<const FMA: bool, const FLAT: bool, const PERSP: bool>(
    r: &Row8<'_>,
    ch: usize,
) -> F32x8 {
    // SAFETY: forwarded from the caller.
    unsafe {
        if FLAT {
            F32x8::splat(r.t.flat[ch])
        } else {
            let a = eval::<FMA>(&r.t.vary[ch], r.fx, r.fy);
            if PERSP {
                a.mul(r.oow)
            } else {
                a
            }
        }
    }
}

/// [`tex_row`] on registers: shades the live lanes of `r`.
///
/// # Safety
/// As [`tex_row`]; with `PERSP` and not `FLAT`, `r.w` and `r.oow` are the row's `1/w`
/// plane values and their exact reciprocal.
#[inline(always)]
pub unsafe fn shade8<
    const FMA: bool,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
    const BLEND: bool,
    const OVER: bool,
>(
    r: &Row8<'_>,
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    let (t, plan, env) = (r.t, r.plan, r.env);
    let w = fb.width;
    let n = 8.min(w - r.x);
    // SAFETY: (whole body) AVX2 (+FMA) context guaranteed by the caller; masked loads and
    // stores touch only live lanes, which lie in `x..x + n` of row `py`.
    unsafe {
        let live_v = r.live;
        let count = live_v.movemask().count_ones() as u64;
        stats.fragments += count;
        let idx = (r.py - fb.y0) * w + r.x;
        let mut pass = live_v;
        if DEPTH {
            let d = plan.depth.expect("DEPTH implies a depth plan");
            pass = depth_test8::<FMA>(t, &d, fb.depth, idx, r.fx, r.fy, live_v);
            let np = pass.movemask().count_ones() as u64;
            stats.depth_reads += count;
            stats.depth_failed += count - np;
            if np == 0 {
                return;
            }
        }
        if !plan.color_mask[0] {
            return;
        }
        let texv = r.tex;
        let white = match r.white {
            White::No => false,
            White::Exact => true,
            White::PerLane => {
                let f = r.w.mul(r.oow);
                let ok = f
                    .cmp_ge(F32x8::splat(WHITE_LO))
                    .and(f.cmp_le(F32x8::splat(WHITE_HI)));
                let need = pass.movemask();
                ok.movemask() & need == need
            }
        };
        let px = if white || (env.rgb == EnvOp::Tex && env.alpha == EnvOp::Tex) {
            texv
        } else {
            let mut acc = I32x8::zero();
            for ch in 0..4 {
                let op = if ch == 3 { env.alpha } else { env.rgb };
                let v = match op {
                    EnvOp::Tex => channel(texv, ch),
                    EnvOp::Frag => unorm(frag::<FMA, FLAT, PERSP>(r, ch)),
                    EnvOp::Modulate => unorm(tex_f(texv, ch).mul(frag::<FMA, FLAT, PERSP>(r, ch))),
                    EnvOp::Decal => {
                        let a = tex_f(texv, 3);
                        unorm(
                            tex_f(texv, ch)
                                .mul(a)
                                .add(frag::<FMA, FLAT, PERSP>(r, ch).mul(F32x8::splat(1.0).sub(a))),
                        )
                    }
                };
                acc = acc.or(v.shl_var(I32x8::splat(8 * ch as i32)));
            }
            acc
        };
        write8::<BLEND, OVER>(plan, fb, idx, n, pass, px, stats);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fragment::span::unorm8;

    /// Every float in [`WHITE_LO`, `WHITE_HI`] as the primary colour keeps every texel
    /// byte through MODULATE (`unorm8(t·f) = t`, the product in the shader's order); 1.0
    /// is among them ([`White::Exact`]), and so is `x·(1/x)` for 1/w values.
    #[test]
    fn white_modulate_keeps_bytes() {
        let mut f = WHITE_LO;
        let mut n = 0;
        while f <= WHITE_HI {
            for u in 0..=255u8 {
                assert_eq!(unorm8(u as f32 * INV_255 * f), u, "u {u} f {f}");
            }
            f = f32::from_bits(f.to_bits() + 1);
            n += 1;
        }
        assert_eq!(n, 7);
        for i in 1..200_000 {
            let x = i as f32 * 3.7e-4;
            assert!((WHITE_LO..=WHITE_HI).contains(&(x * (1.0 / x))), "{x}");
        }
    }
}
