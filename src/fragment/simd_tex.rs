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

use super::simd::{depth_test8, eval, sat, write8, write8_over};
use super::FragPlan;
use crate::framebuffer::{ColorFormat, Target};
use crate::geometry::setup::SetupTriangle;
use crate::stats::Stats;
use crate::texture::fast::{EnvOp, FastEnv};
use crate::texture::sample::INV_255;
use std::arch::x86_64::*;

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
    let w = fb.width;
    let n = 8.min(w - x);
    let count = live.iter().filter(|&&l| l).count() as u64;
    stats.fragments += count;
    // SAFETY (whole body): AVX2 (+FMA) context guaranteed by the caller; masked loads and
    // stores touch only live lanes, which lie in `x..x + n` of row `py`.
    unsafe {
        let m = |i: usize| -(live[i] as i32);
        let live_v = _mm256_setr_epi32(m(0), m(1), m(2), m(3), m(4), m(5), m(6), m(7));
        let lane = _mm256_setr_ps(0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0);
        let fx = _mm256_add_ps(_mm256_set1_ps(x as f32), lane);
        let fy = _mm256_set1_ps(py as f32);
        let idx = (py - fb.y0) * w + x;
        let mut pass = live_v;
        if DEPTH {
            let d = plan.depth.expect("DEPTH implies a depth plan");
            pass = depth_test8::<FMA>(t, &d, fb, idx, fx, fy, live_v);
            let np = _mm256_movemask_ps(_mm256_castsi256_ps(pass)).count_ones() as u64;
            stats.depth_reads += count;
            stats.depth_failed += count - np;
            if np == 0 {
                return;
            }
        }
        if !plan.color_mask[0] {
            return;
        }
        let texv = _mm256_loadu_si256(tex.as_ptr() as *const __m256i);
        let px = if env.rgb == EnvOp::Tex && env.alpha == EnvOp::Tex {
            texv
        } else {
            let oow = if PERSP && !FLAT {
                _mm256_div_ps(_mm256_set1_ps(1.0), eval::<FMA>(&t.w, fx, fy))
            } else {
                _mm256_set1_ps(1.0)
            };
            let frag = |ch: usize| {
                if FLAT {
                    _mm256_set1_ps(t.flat[ch])
                } else {
                    let a = eval::<FMA>(&t.vary[ch], fx, fy);
                    if PERSP {
                        _mm256_mul_ps(a, oow)
                    } else {
                        a
                    }
                }
            };
            let byte = _mm256_set1_epi32(255);
            let tf = |ch: usize| {
                let u = _mm256_and_si256(
                    _mm256_srlv_epi32(texv, _mm256_set1_epi32(8 * ch as i32)),
                    byte,
                );
                _mm256_mul_ps(_mm256_cvtepi32_ps(u), _mm256_set1_ps(INV_255))
            };
            let unorm =
                |c: __m256| _mm256_cvtps_epi32(_mm256_mul_ps(sat(c), _mm256_set1_ps(255.0)));
            let mut acc = _mm256_setzero_si256();
            for ch in 0..4 {
                let op = if ch == 3 { env.alpha } else { env.rgb };
                let v = match op {
                    EnvOp::Tex => _mm256_and_si256(
                        _mm256_srlv_epi32(texv, _mm256_set1_epi32(8 * ch as i32)),
                        byte,
                    ),
                    EnvOp::Frag => unorm(frag(ch)),
                    EnvOp::Modulate => unorm(_mm256_mul_ps(tf(ch), frag(ch))),
                    EnvOp::Decal => {
                        let a = tf(3);
                        unorm(_mm256_add_ps(
                            _mm256_mul_ps(tf(ch), a),
                            _mm256_mul_ps(frag(ch), _mm256_sub_ps(_mm256_set1_ps(1.0), a)),
                        ))
                    }
                };
                acc = _mm256_or_si256(acc, _mm256_sllv_epi32(v, _mm256_set1_epi32(8 * ch as i32)));
            }
            acc
        };
        if OVER {
            write8_over(fb, idx, n, pass, px, stats);
        } else {
            write8::<BLEND>(plan, fb, idx, n, pass, px, stats);
        }
    }
}
