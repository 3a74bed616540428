//! Float and 16-bit texel storage: GL_ARB_texture_float (RGBA/RGB/alpha/luminance/
//! intensity at 16F and 32F) and GL_ARB_texture_rg's R16F … RG32F, R16 and RG16.
//!
//! Such images keep one `[f32; 4]` per texel in [`Level::floats`] (after the base
//! swizzle) beside the usual unorm8 `texels`, and a unit that samples one takes the
//! float (SoA) path, reading the float values: llvmpipe samples every format that does
//! not fit 8-bit unorm through its SoA sampler, converting texels to float first and
//! filtering with float lerps, and nothing clamps them before the texture environment.
//!
//! Precision, as Mesa 22.3 stores the values (measured with glGetTexImage):
//! - 32-bit float: as given;
//! - 16-bit float: rounded toward zero to binary16, with magnitudes past the largest half
//!   becoming 65504 (Mesa's texstore calls `_mesa_float_to_float16_rtz`, F16C's
//!   `vcvtps2ph` with mode 3; llvmpipe's fragment output to a half render target rounds
//!   the same way, `lp_build_float_to_half`);
//! - 16-bit unorm: `_mesa_float_to_unorm(x, 16)`, read back and sampled as
//!   `u·f32(1/65535)` (gallivm's `lp_build_unsigned_norm_to_float`).

use super::sample::lerpfx4;
use super::upload::float_to_u8;
use super::{Encoding, Level, Storage};

/// The fields of f32 `x` for a binary16 conversion: `Ok((sign, exponent, mantissa))`, or
/// `Err(half)` for an infinity or NaN (a NaN keeps its top mantissa bits and stays quiet).
#[inline]
fn half_fields(x: f32) -> Result<(u16, i32, u32), u16> {
    let b = x.to_bits();
    let sign = ((b >> 16) & 0x8000) as u16;
    let exp = ((b >> 23) & 0xff) as i32;
    let man = b & 0x7f_ffff;
    if exp == 0xff {
        let nan = if man != 0 {
            0x200 | (man >> 13) as u16
        } else {
            0
        };
        return Err(sign | 0x7c00 | nan);
    }
    Ok((sign, exp, man))
}

/// `x` as binary16, rounded toward zero: a finite value too large becomes ±65504,
/// infinities stay infinite and a NaN stays a NaN.
pub fn half_rtz(x: f32) -> u16 {
    let (sign, exp, man) = match half_fields(x) {
        Ok(f) => f,
        Err(special) => return special,
    };
    let e = exp - 112;
    if e >= 31 {
        return sign | 0x7bff;
    }
    if e <= 0 {
        // a half subnormal (or zero): the 24-bit significand scaled to units of 2^-24
        let shift = 14 - e;
        let m = if exp == 0 || shift >= 32 {
            0
        } else {
            (man | 0x80_0000) >> shift
        };
        return sign | m as u16;
    }
    sign | ((e as u16) << 10) | (man >> 13) as u16
}

/// `x` as binary16, rounded to nearest even (F16C `vcvtps2ph` mode 0): too large a
/// magnitude becomes infinite.
pub fn half_rne(x: f32) -> u16 {
    let (sign, exp, man) = match half_fields(x) {
        Ok(f) => f,
        Err(special) => return special,
    };
    // the significand with its implicit bit, and how far it shifts into half units
    let (sig, shift) = if exp - 112 >= 1 {
        (man | 0x80_0000, 13)
    } else if exp == 0 {
        return sign;
    } else {
        (man | 0x80_0000, (14 - (exp - 112)) as u32)
    };
    if shift >= 32 {
        return sign;
    }
    let half = 1u32 << (shift - 1);
    let rest = sig & ((1u32 << shift) - 1);
    let mut m = sig >> shift;
    if rest > half || (rest == half && m & 1 == 1) {
        m += 1;
    }
    let v = if shift == 13 {
        // normal: exponent field plus the rounded significand (a carry bumps the exponent)
        (((exp - 112) as u32) << 10) + (m - 0x400)
    } else {
        m
    };
    sign | v.min(0x7c00) as u16
}

/// The value of binary16 `h` (exact).
pub fn half_to_f32(h: u16) -> f32 {
    let sign = ((h as u32) & 0x8000) << 16;
    let exp = ((h >> 10) & 0x1f) as u32;
    let man = (h & 0x3ff) as u32;
    let bits = match exp {
        0 => {
            let v = man as f32 * (1.0 / 16_777_216.0);
            return if sign != 0 { -v } else { v };
        }
        0x1f => 0x7f80_0000 | (man << 13),
        _ => ((exp + 112) << 23) | (man << 13),
    };
    f32::from_bits(sign | bits)
}

/// `x` rounded to half precision and back ([`half_rtz`]).
#[inline]
pub fn round_half(x: f32) -> f32 {
    half_to_f32(half_rtz(x))
}

/// The factor of the 16-bit unorm → float conversion, `f32(1/65535)`.
const INV_65535: f32 = (1.0f64 / 65535.0) as f32;

/// A 16-bit unorm component from a float (`_mesa_float_to_unorm(x, 16)`).
#[inline]
pub fn float_to_u16(x: f32) -> u16 {
    if x > 1.0 {
        65535
    } else if x > 0.0 {
        (x * 65535.0).round_ties_even() as u16
    } else {
        0
    }
}

/// Whether `storage` keeps 16-bit float components (else 32-bit).
fn is_half(storage: &Storage) -> bool {
    storage.sizes.iter().max().is_some_and(|&m| m == 16)
}

/// A float colour as an image of `storage` stores it (see the module doc); other storages
/// return it unchanged.
pub fn quantise(storage: &Storage, v: [f32; 4]) -> [f32; 4] {
    quantise_rounding(storage, v, true)
}

/// [`quantise`], with half floats rounded toward zero (`rtz`, a blit's conversion) or to
/// nearest even (Mesa's CPU texstore, `_mesa_float_to_half`).
pub fn quantise_rounding(storage: &Storage, v: [f32; 4], rtz: bool) -> [f32; 4] {
    match storage.encoding {
        Encoding::Float if is_half(storage) && rtz => v.map(round_half),
        Encoding::Float if is_half(storage) => v.map(|x| half_to_f32(half_rne(x))),
        Encoding::Unorm16 => v.map(|x| float_to_u16(x) as f32 * INV_65535),
        _ => v,
    }
}

/// The unorm8 `texels` kept beside float values (clamped, `_mesa_float_to_unorm`).
#[inline]
pub fn to_bytes(v: [f32; 4]) -> [u8; 4] {
    v.map(float_to_u8)
}

/// The float value an image of `storage` stores for an unorm8 colour (glCopyTexImage,
/// colour-index data): `u·f32(1/255)` in the storage's precision.
pub fn from_bytes(storage: &Storage, t: [u8; 4]) -> [f32; 4] {
    quantise(storage, super::sample::to_float(t))
}

impl Level {
    /// Sets the texels of a float image from its float values (`floats`), or its float
    /// values from its texels when `floats` is `None`; an image whose storage keeps no
    /// floats is left as it is.
    pub fn set_floats(&mut self, floats: Option<Vec<[f32; 4]>>) {
        if !self.storage.has_floats() {
            return;
        }
        match floats {
            Some(f) => {
                self.texels = f.iter().map(|&v| to_bytes(v)).collect();
                self.floats = Some(f);
            }
            None => {
                let s = self.storage;
                self.floats = Some(self.texels.iter().map(|&t| from_bytes(&s, t)).collect());
            }
        }
    }

    /// Recomputes the float values of texels `start..start + n` from their bytes, after a
    /// command wrote only bytes there (glCopyTexSubImage).
    pub fn refresh_floats(&mut self, start: usize, n: usize) {
        let s = self.storage;
        if let Some(f) = &mut self.floats {
            for (v, &t) in f[start..start + n].iter_mut().zip(&self.texels[start..]) {
                *v = from_bytes(&s, t);
            }
        }
    }

    /// Writes float texels `src` (stored precision) at texel `start`, and their bytes.
    pub fn write_floats(&mut self, start: usize, src: &[[f32; 4]]) {
        if let Some(f) = &mut self.floats {
            f[start..start + src.len()].copy_from_slice(src);
            for (t, &v) in self.texels[start..].iter_mut().zip(src) {
                *t = to_bytes(v);
            }
        }
    }
}

impl super::BaseFormat {
    /// [`super::BaseFormat::read_rebase`] of a wide pixel, whose 1 is `one`: what
    /// glReadPixels takes from a float or 16-bit image of this base format.
    pub fn read_rebase_wide(self, v: [f32; 4], one: f32) -> [f32; 4] {
        use super::BaseFormat as B;
        match self {
            B::Luminance | B::Intensity | B::Red => [v[0], 0.0, 0.0, one],
            B::LuminanceAlpha => [v[0], 0.0, 0.0, v[3]],
            B::Alpha => [0.0, 0.0, 0.0, v[3]],
            B::Rgb => [v[0], v[1], v[2], one],
            B::Rg => [v[0], v[1], 0.0, one],
            B::Rgba | B::Depth => v,
        }
    }
}

/// The next smaller level of a float image, as `util_gen_mipmap`'s blit makes it on
/// llvmpipe: the float (SoA) bilinear sample of the source at each destination texel's
/// centre, `u = (x + 0.5)·src/dst − 0.5` clamped to the edge, lerps `fmuladd(w, b − a, a)`
/// (fused on FMA CPUs), written in the storage's precision.
pub fn downsample(src: &Level, fma: bool) -> Level {
    let dw = (src.width / 2).max(1);
    let dh = (src.height / 2).max(1);
    let axis = super::srgb::blit_axis;
    let t = |x: usize, y: usize| src.ftexel(y * src.width + x);
    let mut out = Vec::with_capacity(dw * dh);
    for y in 0..dh {
        let (y0, y1, wy) = axis(dh, y, src.height);
        for x in 0..dw {
            let (x0, x1, wx) = axis(dw, x, src.width);
            let r0 = lerpfx4(fma, wx, t(x0, y0), t(x1, y0));
            let r1 = lerpfx4(fma, wx, t(x0, y1), t(x1, y1));
            let v = lerpfx4(fma, wy, r0, r1);
            out.push(quantise(&src.storage, v));
        }
    }
    let mut l = Level::derived(src, dw, dh, Vec::new());
    l.set_floats(Some(out));
    l
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_rounds_toward_zero_as_mesa_stores() {
        // glGetTexImage of GL_RGBA16F images uploaded from GL_FLOAT (Mesa 22.3 probe)
        assert_eq!(round_half(0.1), 1638.0 / 16384.0);
        assert_eq!(round_half(0.3), 1228.0 / 4096.0);
        assert_eq!(round_half(0.9), 1843.0 / 2048.0);
        assert_eq!(round_half(1e-6), 16.0 / 16_777_216.0);
        assert_eq!(round_half(70000.0), 65504.0);
        assert_eq!(round_half(-2.0), -2.0);
        assert_eq!(round_half(f32::INFINITY), f32::INFINITY);
        assert!(round_half(f32::NAN).is_nan());
    }

    #[test]
    fn half_round_trip_is_exact_for_halves() {
        for h in 0..=0xffffu16 {
            let f = half_to_f32(h);
            if !f.is_nan() {
                assert_eq!(half_rtz(f), h, "{h:#x}");
            }
        }
    }

    #[test]
    fn unorm16_matches_probe() {
        let s = Storage {
            sizes: [16, 0, 0, 0, 0, 0],
            encoding: Encoding::Unorm16,
        };
        assert_eq!(quantise(&s, [0.1, 0.0, 2.0, 1.0])[0], 0.100_007_63);
    }
}
