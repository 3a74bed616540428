//! sRGB colour buffers (GL_SRGB8_ALPHA8 / GL_SRGB8 attachments; docs/fbo-rules.md §5.2).
//!
//! An sRGB buffer stores bytes like an RGBA8 one ([`super::Framebuffer::srgb`]). While
//! GL_FRAMEBUFFER_SRGB is off llvmpipe views it through the linear format, so it is drawn,
//! cleared, read and blitted exactly as RGBA8. While the enable is on, its surface has the
//! sRGB format, and the values written are encoded:
//! - by a draw (and a scissored or masked glClear, which Mesa draws as a quad): the
//!   shader's `lp_build_linear_to_srgb` ([`encode`]), blending in linear space
//!   ([`crate::fragment::srgb`]);
//! - by a full glClear: the CPU's `util_format_linear_float_to_srgb_8unorm`, a piecewise
//!   linear fit of the curve in 104 buckets of the float's exponent and top mantissa bits
//!   ([`encode_clear`]).

use std::sync::OnceLock;

pub use crate::texture::srgb::{decode, encode, table};

/// Exponents the clear's encoding table covers: inputs from 2^-13 to just below 1.
const EXPONENTS: u32 = 13;
/// Top mantissa bits that pick a bucket inside an exponent.
const BUCKET_BITS: u32 = 3;
/// Buckets in the table.
const BUCKETS: usize = (EXPONENTS << BUCKET_BITS) as usize;
/// Mantissa steps of one bucket sampled by the least-squares fit (every 32nd value).
const STEP_SHIFT: u32 = 5;
/// Samples per bucket.
const SAMPLES: u32 = (1 << (23 - BUCKET_BITS)) >> STEP_SHIFT;
/// The interpolation parameter is mantissa bits 12..20 of the input.
const T_SHIFT: u32 = 12;

/// The exact curve in double precision, with Mesa's exponent constant (0.41666666).
fn curve(x: f64) -> f64 {
    if x >= 0.0031308 {
        1.055 * x.powf(0.41666666) - 0.055
    } else {
        12.92 * x
    }
}

/// The fit of each bucket: `bias << 16 | scale` with `value·2^16 ≈ (bias << 9) + scale·t`,
/// fitted by least squares to `255·curve(x) + 0.5` over the bucket's samples (the
/// construction of Mesa's `util_format_linear_to_srgb_helper_table`).
fn buckets() -> &'static [u32; BUCKETS] {
    static T: OnceLock<[u32; BUCKETS]> = OnceLock::new();
    T.get_or_init(|| {
        let t_of = |i: u32| ((i << STEP_SHIFT) >> T_SHIFT) as f64;
        let n = SAMPLES as f64;
        let (mut st, mut stt) = (0.0f64, 0.0f64);
        for i in 0..SAMPLES {
            st += t_of(i);
            stt += t_of(i) * t_of(i);
        }
        let inv_det = 1.0 / (n * stt - st * st);
        std::array::from_fn(|b| {
            let start = ((127 - EXPONENTS) << 23) + b as u32 * (SAMPLES << STEP_SHIFT);
            let (mut sv, mut stv) = (0.0f64, 0.0f64);
            for i in 0..SAMPLES {
                let x = f32::from_bits(start + (i << STEP_SHIFT)) as f64;
                let v = curve(x) * 255.0 + 0.5;
                sv += v;
                stv += t_of(i) * v;
            }
            let a = inv_det * (stt * sv - st * stv);
            let s = inv_det * (n * stv - st * sv);
            let a = (a * 65536.0 / 512.0 + 0.5) as u32;
            let s = (s * 65536.0 + 0.5) as u32;
            (a << 16) + s
        })
    })
}

/// A clear colour channel as gallium packs it into an sRGB format (glClear of the whole
/// buffer with GL_FRAMEBUFFER_SRGB on): clamp to [2^-13, 1 − ε] (NaN to the low end),
/// pick the bucket from the exponent and top mantissa bits, and interpolate with the next
/// 8 mantissa bits.
pub fn encode_clear(x: f32) -> u8 {
    let lo = f32::from_bits((127 - EXPONENTS) << 23);
    let hi = f32::from_bits(0x3F7F_FFFF);
    let x = if x > lo { x } else { lo };
    let x = if x > hi { hi } else { x };
    let u = x.to_bits();
    let tab = buckets()[((u - lo.to_bits()) >> 20) as usize];
    let (bias, scale) = ((tab >> 16) << 9, tab & 0xFFFF);
    let t = (u >> T_SHIFT) & 0xFF;
    ((bias + scale * t) >> 16) as u8
}

/// The stored colour of a full glClear of an sRGB buffer with GL_FRAMEBUFFER_SRGB on: RGB
/// encoded ([`encode_clear`]), alpha packed as unorm8.
pub fn clear_value(c: [f32; 4]) -> [u8; 4] {
    [
        encode_clear(c[0]),
        encode_clear(c[1]),
        encode_clear(c[2]),
        super::clear_float_to_ubyte(c[3]),
    ]
}

/// The stored colour of a shader output `c` (a scissored or masked glClear's quad): RGB
/// through [`encode`], alpha `round_half_even(clamp(a)·255)`.
pub fn shader_value(c: [f32; 4], fma: bool) -> [u8; 4] {
    [
        encode(c[0], fma),
        encode(c[1], fma),
        encode(c[2], fma),
        super::float_to_ubyte(c[3]),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn clear_encoding_follows_the_curve() {
        // measured on Mesa: (0.5, 0.2, 0.8) clears to 188, 124, 231
        assert_eq!(clear_value([0.5, 0.2, 0.8, 0.6]), [188, 124, 231, 153]);
        assert_eq!(encode_clear(0.0), 0);
        assert_eq!(encode_clear(f32::NAN), 0);
        assert_eq!(encode_clear(1.0), 255);
        assert_eq!(encode_clear(7.0), 255);
        // within one step of the exact curve everywhere
        for k in 0..=4096 {
            let x = k as f32 / 4096.0;
            let exact = curve(x as f64) * 255.0;
            assert!((encode_clear(x) as f64 - exact).abs() <= 1.0, "{x}");
        }
    }
}
