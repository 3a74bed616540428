//! The colour write of an sRGB buffer while GL_FRAMEBUFFER_SRGB is on (the plan's
//! [`FragPlan::srgb`]), as llvmpipe's `generate_unswizzled_blend` does for sRGB formats:
//! the shader colour is clamped to [0, 1]; with blending the destination is decoded
//! (`lp_build_srgb_to_linear`, alpha `u·f32(1/255)`), blended in f32 with the constant
//! colour clamped too, and the result encoded (`lp_build_float_to_srgb_packed`: RGB by
//! `lp_build_linear_to_srgb`, alpha `round_half_even(clamp(a)·255)`). The rasterizer
//! takes the FULL path for these draws, which keep the colours as floats.
// Lane loops index several arrays in step; iterators would hide that.
#![allow(clippy::needless_range_loop)]

use super::span::LANES;
use super::wide::{equation_f, factor_f, per_channel};
use super::{BlendPlan, FragPlan};
use crate::framebuffer::srgb;
use crate::pipe::BlendEquation;

/// Clamps to [0, 1], NaN to 0 (`lp_build_clamp_zero_one_nanzero`).
#[inline(always)]
fn clamp01(v: f32) -> f32 {
    let v = if v > 0.0 { v } else { 0.0 };
    if v < 1.0 {
        v
    } else {
        1.0
    }
}

/// Writes the live lanes of the chunk `dst` (its pixels inside the row) of an sRGB
/// target, whose format has alpha if `alpha`, with the shader colours `cf` (`[channel][lane]`): blending in linear space,
/// encoding and the colour mask. The logic op is ignored, as llvmpipe's float blend type
/// ignores it. Returns the number of pixels written.
#[inline(never)]
pub fn store(
    plan: &FragPlan,
    alpha: bool,
    dst: &mut [[u8; 4]],
    live: &[bool; LANES],
    cf: &[[f32; LANES]; 4],
) -> u64 {
    let mask = plan.color_mask;
    let table = srgb::table(plan.fma);
    let kc = plan.blend_color.map(clamp01);
    let mut written = 0;
    for (i, px) in dst.iter_mut().enumerate() {
        if !live[i] {
            continue;
        }
        let src = [cf[0][i], cf[1][i], cf[2][i], cf[3][i]].map(clamp01);
        let d8 = *px;
        let mut v = match &plan.blend {
            Some(b) => {
                let d = [
                    table[d8[0] as usize],
                    table[d8[1] as usize],
                    table[d8[2] as usize],
                    d8[3] as f32 * crate::texture::sample::INV_255,
                ];
                srgb::shader_value(blend(b, kc, src, d), plan.fma)
            }
            None => srgb::shader_value(src, plan.fma),
        };
        if !alpha {
            v[3] = 255;
        }
        for c in 0..4 {
            if !mask[c] {
                v[c] = d8[c];
            }
        }
        *px = v;
        written += 1;
    }
    written
}

/// Blends `s` over the decoded destination `d` in f32 (`lp_build_blend`): as the float
/// buffers blend ([`super::wide`]), except that when each of the RGB and alpha source
/// factors equals its destination factor llvmpipe factors the product out:
/// `(s op d)·f` for ADD, SUBTRACT and REVERSE_SUBTRACT.
#[inline]
fn blend(p: &BlendPlan, kc: [f32; 4], s: [f32; 4], d: [f32; 4]) -> [f32; 4] {
    let f = |f, ch| factor_f(f, s, d, kc, ch);
    let same = p.src_rgb == p.dst_rgb && p.src_a == p.dst_a;
    per_channel(p, f, |ch, eq, sf, df| {
        if same {
            match eq {
                BlendEquation::Add => return (s[ch] + d[ch]) * sf,
                BlendEquation::Subtract => return (s[ch] - d[ch]) * sf,
                BlendEquation::ReverseSubtract => return (d[ch] - s[ch]) * sf,
                _ => {}
            }
        }
        equation_f(eq, s[ch], sf, d[ch], df)
    })
}
