//! The colour write of wide buffers (16-bit unorm, half and single float; docs/
//! llvmpipe-rules.md §23): the shader's float colour is converted to the buffer's
//! precision and blended there, as llvmpipe's `generate_unswizzled_blend` does for
//! R16G16B16A16_UNORM (16-bit fixed point, `mul(a, b) = (t + (t >> 16) + 2^15) >> 16`)
//! and the float formats (f32 arithmetic, no clamping, half floats rounded at the store).
// Lane loops index several arrays in step; iterators would hide that.
#![allow(clippy::needless_range_loop)]

use super::span::LANES;
use super::{BlendPlan, FragPlan};
use crate::framebuffer::samples::PlaneRows;
use crate::framebuffer::wide::unorm16;
use crate::framebuffer::WideKind;
use crate::pipe::{BlendEquation, BlendFactor};

/// How a wide plane stores: its precision, whether it has alpha, and whether it is an
/// image of one channel (blended with llvmpipe's single-channel rules).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct WideDst {
    /// The precision.
    pub kind: WideKind,
    /// The buffer has alpha.
    pub alpha: bool,
    /// [`crate::framebuffer::Framebuffer::wide_single`].
    pub single: bool,
}

/// Writes the live lanes of the chunk at `row` (`n` pixels inside the row) of the rows
/// `fb` of a wide plane stored as `dst` says with the shader colours
/// `cf` (`[channel][lane]`): conversion, blending or logic op, colour mask, and the 8-bit
/// mirror. Returns the number of pixels written.
#[inline(never)]
#[allow(clippy::too_many_arguments)]
pub fn store(
    dst: WideDst,
    plan: &FragPlan,
    fb: &mut PlaneRows<'_>,
    row: usize,
    n: usize,
    live: &[bool; LANES],
    cf: &[[f32; LANES]; 4],
) -> u64 {
    let WideDst {
        kind: k,
        alpha,
        single,
    } = dst;
    let mask = plan.color_mask;
    let mut written = 0;
    for i in 0..n {
        if !live[i] {
            continue;
        }
        let j = row + i;
        let src = [cf[0][i], cf[1][i], cf[2][i], cf[3][i]];
        let d = fb.wide_at(k, j);
        let mut v = match (&plan.blend, plan.logic) {
            (Some(b), _) if k.is_float() => {
                blend_float(k, b, plan.blend_color, src, d, single, plan.fma)
            }
            (Some(b), _) => blend(k, b, plan.blend_color, src, d),
            (None, Some(op)) if k == WideKind::Unorm16 => {
                // Bitwise operations act on each byte of the 16-bit values alike.
                let s = src.map(unorm16);
                std::array::from_fn(|c| {
                    let (sb, db) = (s[c].to_le_bytes(), (d[c] as u16).to_le_bytes());
                    let lo = op.apply(sb[0], db[0]);
                    let hi = op.apply(sb[1], db[1]);
                    u16::from_le_bytes([lo, hi]) as f32
                })
            }
            // Float buffers ignore the logic op.
            _ => src.map(|c| k.from_shader(c)),
        };
        if !alpha {
            v[3] = k.one();
        }
        for c in 0..4 {
            if !mask[c] {
                v[c] = d[c];
            }
        }
        fb.wide_color[j] = v;
        fb.color[j] = k.mirror(v);
        written += 1;
    }
    written
}

/// Blends shader colour `s` (float) over stored colour `d` at precision `k` with the
/// constant colour `kf`; returns the stored result.
#[inline]
fn blend(k: WideKind, p: &BlendPlan, kf: [f32; 4], s: [f32; 4], d: [f32; 4]) -> [f32; 4] {
    match k {
        WideKind::Unorm16 => {
            let s = s.map(|c| unorm16(c) as u32);
            let d = d.map(|c| c as u32);
            let kc = kf.map(|c| unorm16(c) as u32);
            let f = |f, ch| factor16(f, s, d, kc, ch);
            per_channel(p, f, |ch, eq, sf, df| {
                equation16(eq, s[ch], sf, d[ch], df) as f32
            })
        }
        _ => {
            let kc = kf;
            let f = |f, ch| factor_f(f, s, d, kc, ch);
            per_channel(p, f, |ch, eq, sf, df| {
                k.from_shader(equation_f(eq, s[ch], sf, d[ch], df))
            })
        }
    }
}

/// Blends float shader colour `s` over stored float colour `d` as llvmpipe's
/// `lp_build_blend` does when it may fold the factors: that is when the colour and alpha
/// factors pair up as `src_rgb == dst_rgb && src_a == dst_a`, or always for an image of
/// one channel (`single`; `lp_build_blend_aos` sets `rgb_alpha_same` for
/// `nr_channels == 1`). Then equal factors give `(s ∘ d)·f`, and complementary ones
/// (f and 1 − f, or ONE and ZERO) a lerp: ADD is `fmuladd(f, s − d, d)` with `f` the
/// positive factor (fused on FMA hosts, `fma`), SUBTRACT `(s + d)·f − d` or
/// `s − (s + d)·f'`, REVERSE_SUBTRACT the mirror. Otherwise as [`blend`].
#[inline]
fn blend_float(
    k: WideKind,
    p: &BlendPlan,
    kf: [f32; 4],
    s: [f32; 4],
    d: [f32; 4],
    single: bool,
    fma: bool,
) -> [f32; 4] {
    let same = single || (p.src_rgb == p.dst_rgb && p.src_a == p.dst_a);
    if !same {
        return blend(k, p, kf, s, d);
    }
    let f = |f, ch| factor_f(f, s, d, kf, ch);
    std::array::from_fn(|ch| {
        let (eq, sfe, dfe) = if ch < 3 {
            (p.eq_rgb, p.src_rgb, p.dst_rgb)
        } else {
            (p.eq_a, p.src_a, p.dst_a)
        };
        let (sc, dc) = (s[ch], d[ch]);
        let (sf, df) = (f(sfe, ch), f(dfe, ch));
        let lerp = |w: f32, a: f32, b: f32| {
            if fma {
                w.mul_add(b - a, a)
            } else {
                w * (b - a) + a
            }
        };
        let v = match (complement(sfe) == Some(dfe), eq) {
            (true, BlendEquation::Add) if positive(sfe) => lerp(sf, dc, sc),
            (true, BlendEquation::Add) => lerp(df, sc, dc),
            (true, BlendEquation::Subtract) if positive(sfe) => (sc + dc) * sf - dc,
            (true, BlendEquation::Subtract) => sc - (sc + dc) * df,
            (true, BlendEquation::ReverseSubtract) if positive(sfe) => dc - (sc + dc) * sf,
            (true, BlendEquation::ReverseSubtract) => (sc + dc) * df - sc,
            (false, BlendEquation::Add) if sfe == dfe => (sc + dc) * sf,
            (false, BlendEquation::Subtract) if sfe == dfe => (sc - dc) * sf,
            (false, BlendEquation::ReverseSubtract) if sfe == dfe => (dc - sc) * sf,
            _ => equation_f(eq, sc, sf, dc, df),
        };
        k.from_shader(v)
    })
}

/// The factor gallium numbers `f ^ 0x10` (1 − f; ONE and ZERO pair up too).
pub(super) fn complement(f: BlendFactor) -> Option<BlendFactor> {
    use BlendFactor as F;
    Some(match f {
        F::Zero => F::One,
        F::One => F::Zero,
        F::SrcColor => F::OneMinusSrcColor,
        F::OneMinusSrcColor => F::SrcColor,
        F::DstColor => F::OneMinusDstColor,
        F::OneMinusDstColor => F::DstColor,
        F::SrcAlpha => F::OneMinusSrcAlpha,
        F::OneMinusSrcAlpha => F::SrcAlpha,
        F::DstAlpha => F::OneMinusDstAlpha,
        F::OneMinusDstAlpha => F::DstAlpha,
        F::ConstantColor => F::OneMinusConstantColor,
        F::OneMinusConstantColor => F::ConstantColor,
        F::ConstantAlpha => F::OneMinusConstantAlpha,
        F::OneMinusConstantAlpha => F::ConstantAlpha,
        F::SrcAlphaSaturate => return None,
    })
}

/// Whether gallium numbers `f` below its complement (ONE, and the factors that are not
/// "one minus"): the lerp then weighs by the source factor.
pub(super) fn positive(f: BlendFactor) -> bool {
    use BlendFactor as F;
    matches!(
        f,
        F::One
            | F::SrcColor
            | F::DstColor
            | F::SrcAlpha
            | F::DstAlpha
            | F::ConstantColor
            | F::ConstantAlpha
            | F::SrcAlphaSaturate
    )
}

/// Blends each channel: `factor(f, ch)` gives a factor's value in channel `ch`, and
/// `apply(ch, equation, src_factor, dst_factor)` the blended channel (RGB take the plan's
/// colour equation and factors, alpha its alpha ones).
#[inline(always)]
pub(super) fn per_channel<T: Copy>(
    p: &BlendPlan,
    factor: impl Fn(BlendFactor, usize) -> T,
    apply: impl Fn(usize, BlendEquation, T, T) -> f32,
) -> [f32; 4] {
    std::array::from_fn(|ch| {
        let (eq, sf, df) = if ch < 3 {
            (p.eq_rgb, factor(p.src_rgb, ch), factor(p.dst_rgb, ch))
        } else {
            (p.eq_a, factor(p.src_a, ch), factor(p.dst_a, ch))
        };
        apply(ch, eq, sf, df)
    })
}

/// llvmpipe's unorm16 multiply (`lp_build_mul_norm` in 32-bit lanes; exact for 0 and
/// 65535).
#[inline(always)]
pub fn mul16(a: u32, b: u32) -> u32 {
    let t = a * b;
    (t + (t >> 16) + 0x8000) >> 16
}

/// The blend factor table of every precision: factor `$f` of channel `$ch` from the
/// source `$s`, destination `$d` and constant `$k` colours (arrays or references to
/// arrays of four channels), with the precision's `$zero` and `$one`, its subtraction
/// `$sub` (ONE_MINUS_x is `$sub(one, x)`) and its `$min` (SRC_ALPHA_SATURATE). The scalar
/// stores here and the 8-lane ones of `super::simd_wide` expand it.
macro_rules! blend_factor {
    ($f:expr, $s:expr, $d:expr, $k:expr, $ch:expr;
     $zero:expr, $one:expr, $sub:expr, $min:expr) => {{
        let (s, d, k, ch, one) = ($s, $d, $k, $ch, $one);
        match $f {
            BlendFactor::Zero => $zero,
            BlendFactor::One => one,
            BlendFactor::SrcColor => s[ch],
            BlendFactor::OneMinusSrcColor => $sub(one, s[ch]),
            BlendFactor::DstColor => d[ch],
            BlendFactor::OneMinusDstColor => $sub(one, d[ch]),
            BlendFactor::SrcAlpha => s[3],
            BlendFactor::OneMinusSrcAlpha => $sub(one, s[3]),
            BlendFactor::DstAlpha => d[3],
            BlendFactor::OneMinusDstAlpha => $sub(one, d[3]),
            BlendFactor::ConstantColor => k[ch],
            BlendFactor::OneMinusConstantColor => $sub(one, k[ch]),
            BlendFactor::ConstantAlpha => k[3],
            BlendFactor::OneMinusConstantAlpha => $sub(one, k[3]),
            BlendFactor::SrcAlphaSaturate if ch == 3 => one,
            BlendFactor::SrcAlphaSaturate => $min(s[3], $sub(one, d[3])),
        }
    }};
}
pub(super) use blend_factor;

/// A blend factor in 16-bit fixed point (ONE is 65535, ONE_MINUS_x is `65535 − x`).
#[inline(always)]
fn factor16(f: BlendFactor, s: [u32; 4], d: [u32; 4], k: [u32; 4], ch: usize) -> u32 {
    use std::ops::Sub;
    blend_factor!(f, s, d, k, ch; 0, 65535, u32::sub, u32::min)
}

/// A blend equation in 16-bit fixed point: saturating add and subtract.
#[inline(always)]
fn equation16(eq: BlendEquation, s: u32, sf: u32, d: u32, df: u32) -> u32 {
    match eq {
        BlendEquation::Add => (mul16(s, sf) + mul16(d, df)).min(65535),
        BlendEquation::Subtract => mul16(s, sf).saturating_sub(mul16(d, df)),
        BlendEquation::ReverseSubtract => mul16(d, df).saturating_sub(mul16(s, sf)),
        BlendEquation::Min => s.min(d),
        BlendEquation::Max => s.max(d),
    }
}

/// A blend factor in f32 (ONE_MINUS_x is `1 − x`).
#[inline(always)]
pub(super) fn factor_f(f: BlendFactor, s: [f32; 4], d: [f32; 4], k: [f32; 4], ch: usize) -> f32 {
    use std::ops::Sub;
    blend_factor!(f, s, d, k, ch; 0.0, 1.0, f32::sub, f32::min)
}

/// A blend equation in f32: each product rounded, then the sum (no clamping).
#[inline(always)]
pub(super) fn equation_f(eq: BlendEquation, s: f32, sf: f32, d: f32, df: f32) -> f32 {
    match eq {
        BlendEquation::Add => s * sf + d * df,
        BlendEquation::Subtract => s * sf - d * df,
        BlendEquation::ReverseSubtract => d * df - s * sf,
        BlendEquation::Min => s.min(d),
        BlendEquation::Max => s.max(d),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mul16_ends() {
        for a in [0u32, 1, 255, 32768, 65534, 65535] {
            assert_eq!(mul16(a, 65535), a);
            assert_eq!(mul16(a, 0), 0);
        }
    }
}
