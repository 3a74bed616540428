//! 8-bit fixed-point blending exactly as llvmpipe does it for unorm8 colour buffers
//! (docs/llvmpipe-rules.md §13): factors are 8-bit, `mul(a, b) = (t + (t >> 8) + 128) >> 8` with
//! `t = a·b`, ADD saturates at 255, SUBTRACT clamps at 0, MIN/MAX ignore the factors.
// Lane loops index several arrays in step; iterators would hide that.
#![allow(clippy::needless_range_loop)]

use super::BlendPlan;
use crate::pipe::{BlendEquation, BlendFactor};

/// llvmpipe's unorm8 multiply (exact for 0 and 255).
#[inline(always)]
pub fn mul8(a: u8, b: u8) -> u8 {
    let t = a as u32 * b as u32;
    ((t + (t >> 8) + 128) >> 8) as u8
}

#[inline(always)]
fn factor(f: BlendFactor, s: [u8; 4], d: [u8; 4], k: [u8; 4], ch: usize) -> u8 {
    match f {
        BlendFactor::Zero => 0,
        BlendFactor::One => 255,
        BlendFactor::SrcColor => s[ch],
        BlendFactor::OneMinusSrcColor => 255 - s[ch],
        BlendFactor::DstColor => d[ch],
        BlendFactor::OneMinusDstColor => 255 - d[ch],
        BlendFactor::SrcAlpha => s[3],
        BlendFactor::OneMinusSrcAlpha => 255 - s[3],
        BlendFactor::DstAlpha => d[3],
        BlendFactor::OneMinusDstAlpha => 255 - d[3],
        BlendFactor::ConstantColor => k[ch],
        BlendFactor::OneMinusConstantColor => 255 - k[ch],
        BlendFactor::ConstantAlpha => k[3],
        BlendFactor::OneMinusConstantAlpha => 255 - k[3],
        BlendFactor::SrcAlphaSaturate => {
            if ch == 3 {
                255
            } else {
                s[3].min(255 - d[3])
            }
        }
    }
}

#[inline(always)]
fn equation(eq: BlendEquation, s: u8, sf: u8, d: u8, df: u8) -> u8 {
    match eq {
        BlendEquation::Add => mul8(s, sf).saturating_add(mul8(d, df)),
        BlendEquation::Subtract => mul8(s, sf).saturating_sub(mul8(d, df)),
        BlendEquation::ReverseSubtract => mul8(d, df).saturating_sub(mul8(s, sf)),
        BlendEquation::Min => s.min(d),
        BlendEquation::Max => s.max(d),
    }
}

/// Blends source `s` over destination `d`.
#[inline(always)]
pub fn blend(p: &BlendPlan, s: [u8; 4], d: [u8; 4]) -> [u8; 4] {
    let k = p.color;
    let mut out = [0u8; 4];
    for ch in 0..3 {
        out[ch] = equation(
            p.eq_rgb,
            s[ch],
            factor(p.src_rgb, s, d, k, ch),
            d[ch],
            factor(p.dst_rgb, s, d, k, ch),
        );
    }
    out[3] = equation(
        p.eq_a,
        s[3],
        factor(p.src_a, s, d, k, 3),
        d[3],
        factor(p.dst_a, s, d, k, 3),
    );
    out
}

/// [`LANES`](super::span::LANES) pixels' channels, channel-major (`[channel][lane]`).
pub type Lanes = [[u8; super::span::LANES]; 4];

#[inline(always)]
fn factor_lanes(
    f: BlendFactor,
    s: &Lanes,
    d: &Lanes,
    k: [u8; 4],
    ch: usize,
) -> [u8; super::span::LANES] {
    let inv = |v: [u8; super::span::LANES]| v.map(|x| 255 - x);
    match f {
        BlendFactor::Zero => [0; super::span::LANES],
        BlendFactor::One => [255; super::span::LANES],
        BlendFactor::SrcColor => s[ch],
        BlendFactor::OneMinusSrcColor => inv(s[ch]),
        BlendFactor::DstColor => d[ch],
        BlendFactor::OneMinusDstColor => inv(d[ch]),
        BlendFactor::SrcAlpha => s[3],
        BlendFactor::OneMinusSrcAlpha => inv(s[3]),
        BlendFactor::DstAlpha => d[3],
        BlendFactor::OneMinusDstAlpha => inv(d[3]),
        BlendFactor::ConstantColor => [k[ch]; super::span::LANES],
        BlendFactor::OneMinusConstantColor => [255 - k[ch]; super::span::LANES],
        BlendFactor::ConstantAlpha => [k[3]; super::span::LANES],
        BlendFactor::OneMinusConstantAlpha => [255 - k[3]; super::span::LANES],
        BlendFactor::SrcAlphaSaturate => {
            if ch == 3 {
                [255; super::span::LANES]
            } else {
                let mut o = [0; super::span::LANES];
                for i in 0..super::span::LANES {
                    o[i] = s[3][i].min(255 - d[3][i]);
                }
                o
            }
        }
    }
}

#[inline(always)]
fn equation_lanes(
    eq: BlendEquation,
    s: &[u8; super::span::LANES],
    sf: &[u8; super::span::LANES],
    d: &[u8; super::span::LANES],
    df: &[u8; super::span::LANES],
) -> [u8; super::span::LANES] {
    let mut o = [0u8; super::span::LANES];
    match eq {
        BlendEquation::Add => {
            for i in 0..super::span::LANES {
                o[i] = (mul8(s[i], sf[i]) as u16 + mul8(d[i], df[i]) as u16).min(255) as u8;
            }
        }
        BlendEquation::Subtract => {
            for i in 0..super::span::LANES {
                o[i] = mul8(s[i], sf[i]).saturating_sub(mul8(d[i], df[i]));
            }
        }
        BlendEquation::ReverseSubtract => {
            for i in 0..super::span::LANES {
                o[i] = mul8(d[i], df[i]).saturating_sub(mul8(s[i], sf[i]));
            }
        }
        BlendEquation::Min => {
            for i in 0..super::span::LANES {
                o[i] = s[i].min(d[i]);
            }
        }
        BlendEquation::Max => {
            for i in 0..super::span::LANES {
                o[i] = s[i].max(d[i]);
            }
        }
    }
    o
}

/// [`blend`] for a chunk of pixels, with every state branch outside the lane loops.
#[inline(always)]
pub fn blend_lanes(p: &BlendPlan, s: &Lanes, d: &Lanes) -> Lanes {
    let k = p.color;
    let mut out = [[0u8; super::span::LANES]; 4];
    for ch in 0..3 {
        let sf = factor_lanes(p.src_rgb, s, d, k, ch);
        let df = factor_lanes(p.dst_rgb, s, d, k, ch);
        out[ch] = equation_lanes(p.eq_rgb, &s[ch], &sf, &d[ch], &df);
    }
    let sf = factor_lanes(p.src_a, s, d, k, 3);
    let df = factor_lanes(p.dst_a, s, d, k, 3);
    out[3] = equation_lanes(p.eq_a, &s[3], &sf, &d[3], &df);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn mul8_matches_llvmpipe_examples() {
        // 152·229 gives 136 in llvmpipe (exact rounding would give 137).
        assert_eq!(mul8(152, 229), 136);
        for a in 0..=255u8 {
            assert_eq!(mul8(a, 255), a);
            assert_eq!(mul8(a, 0), 0);
        }
    }

    #[test]
    fn over_operator() {
        let p = BlendPlan {
            src_rgb: BlendFactor::SrcAlpha,
            dst_rgb: BlendFactor::OneMinusSrcAlpha,
            src_a: BlendFactor::SrcAlpha,
            dst_a: BlendFactor::OneMinusSrcAlpha,
            eq_rgb: BlendEquation::Add,
            eq_a: BlendEquation::Add,
            color: [0; 4],
        };
        let out = blend(&p, [255, 0, 0, 128], [0, 0, 255, 255]);
        assert_eq!(
            out,
            [
                mul8(255, 128),
                0,
                mul8(255, 127),
                mul8(128, 128).saturating_add(mul8(255, 127))
            ]
        );
    }
}
