//! sRGB textures (GL_EXT_texture_sRGB, GL 2.1): GL_SRGB(8), GL_SRGB(8)_ALPHA(8),
//! GL_SLUMINANCE(8), GL_SLUMINANCE(8)_ALPHA(8).
//!
//! # Storage and readback
//! The bytes are stored as given (8 bits a channel, like GL_RGB8 …; float data is stored
//! linearly, `round_half_even(v·255)`, measured) and glGetTexImage returns them undecoded
//! (Mesa's `_mesa_get_srgb_format_linear`; measured also for GL_FLOAT). The image's
//! storage says so ([`super::Encoding::Srgb`], set from the internal format by the state).
//!
//! # Sampling (`lp_bld_format_srgb.c`, `lp_build_srgb_to_linear`)
//! sRGB formats never take llvmpipe's 8-bit AoS path (`util_format_fits_8unorm` is false
//! for them), so they are filtered on the float SoA path, after each texel's R, G and B
//! are decoded (alpha stays `u·f32(1/255)`): for the byte value x as f32,
//! `x ≤ 15 ? x·f32(1/(12.6·255)) : poly(x)` with `x2 = x·x`,
//! `poly = fmuladd(fmuladd(x2, c3, c1), x, fmuladd(x2, c2, c0))` (`lp_build_polynomial`'s
//! even/odd split), `c0 = 0.0023f`, `c1 = 0.0030f/255`, `c2 = 0.6935f/255²`,
//! `c3 = 0.3012f/255³` (f32 arithmetic). The fmuladds fuse exactly on FMA CPUs, so the
//! table differs between the levels: the fused one equals docs/fbo-rules.md §5.1's measured
//! table in all 256 entries.
//!
//! # Mipmap generation (`st_generate_mipmap` → `util_gen_mipmap`)
//! Each level is a LINEAR blit of the previous one between sRGB views: the sampler decodes
//! and filters on the float path (`fmuladd(w, b − a, a)`), and the render target encodes
//! with `lp_build_linear_to_srgb` ([`encode`]): clamp to [0, 1]; `x ≤ 0.0031308f` →
//! `x·(12.92f·255f)`, else `a·x^0.375 + fmuladd(b, x^0.5, c)` with
//! `a = f32(0.675f·1.0622·255f)`, `b = f32(0.325f·1.0622·255f)`, `c = −0.062f·255f`,
//! `x^0.5 = x·rsqrt(x)`, `x^0.375 = rsqrt(rsqrt(x·x^0.5))`, where rsqrt is the CPU's
//! approximate `rsqrtps` (used here too, so the result matches llvmpipe on the same CPU);
//! then `round_half_even`. Alpha is `round_half_even(clamp(a)·255)`.

use std::sync::OnceLock;

/// llvmpipe's multiply-add: fused or with two roundings.
#[inline(always)]
fn madd(a: f32, b: f32, c: f32, fma: bool) -> f32 {
    if fma {
        a.mul_add(b, c)
    } else {
        a * b + c
    }
}

/// `lp_build_srgb_to_linear` of one 8-bit value.
pub fn decode(u: u8, fma: bool) -> f32 {
    let x = u as f32;
    if x <= 15.0 {
        return x * (1.0f32 / (12.6f32 * 255.0f32));
    }
    let c0 = 0.0023f32;
    let c1 = 0.0030f32 / 255.0f32;
    let c2 = 0.6935f32 / (255.0f32 * 255.0f32);
    let c3 = 0.3012f32 / (255.0f32 * 255.0f32 * 255.0f32);
    let x2 = x * x;
    let odd = madd(x2, c3, c1, fma);
    let even = madd(x2, c2, c0, fma);
    madd(odd, x, even, fma)
}

/// The decode of every byte value, unfused (`[0]`) and fused (`[1]`).
fn tables() -> &'static [[f32; 256]; 2] {
    static T: OnceLock<[[f32; 256]; 2]> = OnceLock::new();
    T.get_or_init(|| [false, true].map(|f| std::array::from_fn(|u| decode(u as u8, f))))
}

/// The decode table sampling uses on this instruction-set level.
pub fn table(fma: bool) -> &'static [f32; 256] {
    &tables()[fma as usize]
}

/// An sRGB texel as the float SoA path sees it: R, G, B decoded, alpha linear.
#[inline(always)]
pub fn to_float(t: [u8; 4], table: &[f32; 256]) -> [f32; 4] {
    [
        table[t[0] as usize],
        table[t[1] as usize],
        table[t[2] as usize],
        t[3] as f32 * super::sample::INV_255,
    ]
}

/// The CPU's approximate reciprocal square root (`rsqrtps`), as llvmpipe's
/// `lp_build_fast_rsqrt` uses it; an exact `1/sqrt` elsewhere.
#[inline]
fn fast_rsqrt(x: f32) -> f32 {
    crate::simd::rsqrt_approx(x)
}

/// `lp_build_linear_to_srgb` of one channel, as an 8-bit value.
pub fn encode(v: f32, fma: bool) -> u8 {
    let x = v.clamp(0.0, 1.0);
    let y = if x <= 0.0031308f32 {
        x * (12.92f32 * 255.0f32)
    } else {
        let a = (0.675f32 as f64 * 1.0622 * 255.0f32 as f64) as f32;
        let b = (0.325f32 as f64 * 1.0622 * 255.0f32 as f64) as f32;
        let c = -0.0620f32 * 255.0f32;
        let x05 = x * fast_rsqrt(x);
        let x0375 = fast_rsqrt(fast_rsqrt(x05 * x));
        a * x0375 + madd(b, x05, c, fma)
    };
    y.round_ties_even().clamp(0.0, 255.0) as u8
}

/// One axis of the mipmap blit's bilinear tap (llvmpipe's blitter samples destination texel
/// `i` of `d` at the centre of its footprint in a source of `s`): the two source texels,
/// clamped to the edge, and the weight of the second.
#[inline]
pub(super) fn blit_axis(d: usize, i: usize, s: usize) -> (usize, usize, f32) {
    let u = (2 * i + 1) as f32 * s as f32 / (2 * d) as f32 - 0.5;
    let f = u.floor();
    let i0 = f as i64;
    let max = s as i64 - 1;
    (
        i0.clamp(0, max) as usize,
        (i0 + 1).clamp(0, max) as usize,
        u - f,
    )
}

/// The float-path bilinear sample of `src` at the centre of destination texel (`x`, `y`)
/// of a `dw x dh` level, then encoded: one texel of the next mipmap level.
fn blit_texel(
    src: &super::Level,
    (dw, dh): (usize, usize),
    (x, y): (usize, usize),
    fma: bool,
) -> [u8; 4] {
    let table = table(fma);
    let axis = blit_axis;
    let (x0, x1, wx) = axis(dw, x, src.width);
    let (y0, y1, wy) = axis(dh, y, src.height);
    let t = |x, y| to_float(src.texel(x, y), table);
    let lerp = |w: f32, a: [f32; 4], b: [f32; 4]| {
        std::array::from_fn::<f32, 4, _>(|c| madd(w, b[c] - a[c], a[c], fma))
    };
    let v = lerp(
        wy,
        lerp(wx, t(x0, y0), t(x1, y0)),
        lerp(wx, t(x0, y1), t(x1, y1)),
    );
    let a = (v[3].clamp(0.0, 1.0) * 255.0).round_ties_even() as u8;
    [encode(v[0], fma), encode(v[1], fma), encode(v[2], fma), a]
}

/// The next smaller level of an sRGB `src` (sizes halve, rounding down, minimum 1).
pub fn downsample(src: &super::Level, fma: bool) -> super::Level {
    let dw = (src.width / 2).max(1);
    let dh = (src.height / 2).max(1);
    let mut texels = Vec::with_capacity(dw * dh);
    for y in 0..dh {
        for x in 0..dw {
            let t = blit_texel(src, (dw, dh), (x, y), fma);
            texels.push(super::upload::to_texel(src.base, t));
        }
    }
    super::Level::derived(src, dw, dh, texels)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fused_decode_matches_measured_table() {
        // docs/fbo-rules.md §5.1 (llvmpipe on an FMA host), a few entries
        let want: [(u8, u32); 6] = [
            (1, 0x39a3_2d56),
            (15, 0x3b98_fa81),
            (16, 0x3bad_702a),
            (128, 0x3e5d_d65c),
            (200, 0x3f13_9a9a),
            (255, 0x3f80_0000),
        ];
        for (u, bits) in want {
            assert_eq!(decode(u, true).to_bits(), bits, "{u}");
        }
    }

    #[test]
    fn encode_inverts_decode() {
        // lp_bld_format_srgb.c requires every byte to survive decode and encode
        for u in 0..=255u8 {
            for fma in [false, true] {
                assert_eq!(encode(decode(u, fma), fma), u, "{u} {fma}");
            }
        }
    }
}
