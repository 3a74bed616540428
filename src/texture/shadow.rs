//! Depth textures (GL_ARB_depth_texture, GL_ARB_shadow): storage, upload, readback and
//! sampling with the depth comparison, as Mesa 22.3 and llvmpipe do them.
//!
//! # Storage
//! A depth texel is the stored depth value `z` of `bits` bits as a little-endian u32 in
//! the RGBA8 slot. Mesa picks Z16 for GL_DEPTH_COMPONENT16 (or unsized with
//! GL_UNSIGNED_SHORT data), Z32_UNORM for GL_DEPTH_COMPONENT32 (or unsized with
//! GL_UNSIGNED_INT data) and Z24X8 otherwise (measured with GL_TEXTURE_DEPTH_SIZE).
//! Client depth values become `z = (GLuint)(d·(GLfloat)max)` (`_mesa_unpack_depth_span`:
//! f32 product, truncated; f64 for 32 bits), d clamped to [0, 1].
//! GL_DEPTH_COMPONENT32F and GL_DEPTH32F_STENCIL8 (GL_ARB_depth_buffer_float) are
//! Z32_FLOAT(_S8X24_UINT): the texel holds the f32's bits, the client value clamped with
//! Mesa's `CLAMP` (float data always takes that path, never a memcpy). Their "bits" are
//! [`FLOAT_BITS`], which every conversion here checks first.
//!
//! # Sampling (`lp_bld_sample_soa.c`, always the float path)
//! - A texel becomes `float(z)·f32(1/max)` (16, 24 bits) or, for 32 bits, the 23 top bits
//!   as a mantissa: `(bits(1.0) | z >> 9) − 1.0` times `f32(2²³/(2²³−1))`
//!   (`lp_build_unsigned_norm_to_float`).
//! - GL_COMPARE_R_TO_TEXTURE: the reference r is clamped to [0, 1], each texel becomes
//!   `r func d ? 1.0 : 0.0`, and those are filtered with the float lerps
//!   `fmuladd(w, v1 − v0, v0)` — compare, then filter (Mesa 22.3's
//!   `lp_build_sample_image_linear`; later versions use a masked lerp).
//! - glCopyTexImage from the depth buffer is a blit: each stored value goes through the
//!   sampler's float and back with the depth write's `round_half_even(f32(d·max))` (for 32
//!   bits the shader's Z32_UNORM conversion); 32 bits into 32 bits is copied.
//! - [`super::shadow_avx2`] computes the same values 8 pixels at a time for the common
//!   state (one level, 16/24 bits, CLAMP_TO_EDGE or power-of-two REPEAT).
//! - The result is swizzled by GL_DEPTH_TEXTURE_MODE: LUMINANCE (d,d,d,1), INTENSITY
//!   (d,d,d,d), ALPHA (0,0,0,d); the texture environment treats the texture as that base
//!   format.

use super::lod::Lod;
use super::sample::{lerpf, select_levels, soa_taps};
use super::{BaseFormat, Filter, Level, UnitPlan};

/// GL_TEXTURE_COMPARE_FUNC.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CompareFunc {
    /// GL_NEVER.
    Never,
    /// GL_LESS.
    Less,
    /// GL_EQUAL.
    Equal,
    /// GL_LEQUAL.
    Lequal,
    /// GL_GREATER.
    Greater,
    /// GL_NOTEQUAL.
    Notequal,
    /// GL_GEQUAL.
    Gequal,
    /// GL_ALWAYS.
    Always,
}

impl CompareFunc {
    /// `r func d` (gallivm compares the reference first).
    #[inline(always)]
    pub fn test(self, r: f32, d: f32) -> bool {
        match self {
            CompareFunc::Never => false,
            CompareFunc::Less => r < d,
            CompareFunc::Equal => r == d,
            CompareFunc::Lequal => r <= d,
            CompareFunc::Greater => r > d,
            CompareFunc::Notequal => r != d,
            CompareFunc::Gequal => r >= d,
            CompareFunc::Always => true,
        }
    }
}

/// GL_DEPTH_TEXTURE_MODE: how a depth value becomes RGBA.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DepthMode {
    /// GL_LUMINANCE: (d, d, d, 1).
    Luminance,
    /// GL_INTENSITY: (d, d, d, d).
    Intensity,
    /// GL_ALPHA: (0, 0, 0, d).
    Alpha,
    /// GL_RED: (d, 0, 0, 1).
    Red,
}

/// The comparison parameters of a texture object.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ShadowParams {
    /// GL_TEXTURE_COMPARE_MODE is GL_COMPARE_R_TO_TEXTURE.
    pub compare: bool,
    /// GL_TEXTURE_COMPARE_FUNC.
    pub func: CompareFunc,
    /// GL_DEPTH_TEXTURE_MODE.
    pub depth_mode: DepthMode,
}

impl Default for ShadowParams {
    fn default() -> Self {
        ShadowParams {
            compare: false,
            func: CompareFunc::Lequal,
            depth_mode: DepthMode::Luminance,
        }
    }
}

impl DepthMode {
    /// The base format the texture environment sees.
    pub fn base(self) -> BaseFormat {
        match self {
            DepthMode::Luminance => BaseFormat::Luminance,
            DepthMode::Intensity => BaseFormat::Intensity,
            DepthMode::Alpha => BaseFormat::Alpha,
            DepthMode::Red => BaseFormat::Rgb,
        }
    }

    /// Applies the mode to a depth (or comparison) value.
    #[inline(always)]
    pub fn swizzle(self, d: f32) -> [f32; 4] {
        match self {
            DepthMode::Luminance => [d, d, d, 1.0],
            DepthMode::Intensity => [d; 4],
            DepthMode::Alpha => [0.0, 0.0, 0.0, d],
            DepthMode::Red => [d, 0.0, 0.0, 1.0],
        }
    }
}

/// The "bits" of a float depth image (Z32_FLOAT): not a bit count, a tag the conversions
/// here recognise (GL_TEXTURE_DEPTH_SIZE reports 32 for it: [`depth_size`]).
pub const FLOAT_BITS: u8 = 0xFF;

/// GL_TEXTURE_DEPTH_SIZE of an image of `bits`.
pub fn depth_size(bits: u8) -> u8 {
    if bits == FLOAT_BITS {
        32
    } else {
        bits
    }
}

/// Mesa's `CLAMP(d, 0, 1)` (NaN and −0 pass through) as stored in a float image.
fn store_float(d: f32) -> u32 {
    // `f32::clamp` compares as `CLAMP` does
    d.clamp(0.0, 1.0).to_bits()
}

/// The largest stored value of `bits` bits.
#[inline(always)]
fn zmax(bits: u8) -> u64 {
    (1u64 << bits) - 1
}

/// A client depth value in [0, 1] as stored with `bits` bits.
pub fn store(d: f32, bits: u8) -> u32 {
    if bits == FLOAT_BITS {
        return store_float(d);
    }
    let d = if d > 0.0 { d.min(1.0) } else { 0.0 };
    if bits >= 32 {
        (d as f64 * zmax(32) as f64).min(u32::MAX as f64) as u32
    } else {
        (d * zmax(bits) as f32) as u32
    }
}

/// A depth-buffer value of `bits` bits as a blit copies it into a texture of `to` bits:
/// the sampler's float ([`sample_value`]), then the depth write's
/// `round_half_even(f32(d·max))` (docs/llvmpipe-rules.md §8), or for 32 bits the shader's
/// Z32_UNORM conversion ([`crate::framebuffer::z32_unorm`]). 32 bits into 32 bits is
/// copied: llvmpipe blits Z32_UNORM to Z32_UNORM as R32_UINT (`lp_blit`).
pub fn convert(z: u32, bits: u8, to: u8) -> u32 {
    if bits == 32 && to == 32 {
        return z;
    }
    let d = sample_value(z, bits).clamp(0.0, 1.0);
    if to == FLOAT_BITS {
        crate::framebuffer::DepthFormat::Z32F.quantize(d)
    } else if to >= 32 {
        crate::framebuffer::z32_unorm(d)
    } else {
        (d * zmax(to) as f32).round_ties_even() as u32
    }
}

/// A depth-buffer value of `bits` bits copied into a texture of `to` bits under
/// GL_DEPTH_SCALE/GL_DEPTH_BIAS: Mesa's CPU copy (`fallback_copy_texsubimage`) widens it
/// to 32 bits by bit replication, computes `trunc(clamp(z32·scale + bias·(2³²−1)))` in
/// f64 and keeps the top `to` bits.
///
/// With a float image on either side the copy is taken as float (`d·scale + bias`,
/// clamped; not measured).
pub fn convert_scaled(z: u32, bits: u8, to: u8, (scale, bias): (f32, f32)) -> u32 {
    if bits == FLOAT_BITS || to == FLOAT_BITS {
        return store(readback(z, bits) * scale + bias, to);
    }
    let z32 = match bits {
        16 => (z << 16) | z,
        24 => (z << 8) | (z >> 16),
        _ => z,
    };
    let max = u32::MAX as f64;
    let d = (z32 as f64 * scale as f64 + bias as f64 * max).clamp(0.0, max) as u32;
    if to >= 32 {
        d
    } else {
        d >> (32 - to)
    }
}

/// The float Mesa reads a stored value back as (`_mesa_unpack_float_z_row`).
pub fn readback(z: u32, bits: u8) -> f32 {
    match bits {
        FLOAT_BITS => f32::from_bits(z),
        16 => z as f32 * (1.0f32 / 65535.0),
        b => (z as f64 * (1.0 / zmax(b) as f64)) as f32,
    }
}

/// The float the sampler converts a stored value to.
#[inline(always)]
pub fn sample_value(z: u32, bits: u8) -> f32 {
    if bits == FLOAT_BITS {
        f32::from_bits(z)
    } else if bits >= 32 {
        let m = f32::from_bits((z >> 9) | 0x3f80_0000) - 1.0;
        m * (8388608.0f64 / 8388607.0) as f32
    } else {
        z as f32 * (1.0 / zmax(bits) as f64) as f32
    }
}

/// The stored value of a depth texel.
#[inline(always)]
pub fn texel_z(t: [u8; 4]) -> u32 {
    u32::from_le_bytes(t)
}

/// A depth texel of stored value `z`.
#[inline(always)]
pub fn texel(z: u32) -> [u8; 4] {
    z.to_le_bytes()
}

/// The depth part of a unit's sampling plan.
#[derive(Clone, Copy, Debug)]
pub struct DepthPlan {
    /// The comparison, when GL_TEXTURE_COMPARE_MODE is GL_COMPARE_R_TO_TEXTURE.
    pub func: Option<CompareFunc>,
    /// GL_DEPTH_TEXTURE_MODE.
    pub mode: DepthMode,
    /// Stored bits.
    pub bits: u8,
}

/// One level of a depth texture: the depth value or the filtered comparison.
#[inline(always)]
fn filter_level(
    p: &UnitPlan<'_>,
    d: &DepthPlan,
    img: &Level,
    filter: Filter,
    s: f32,
    t: f32,
    r: f32,
) -> f32 {
    let (w, h) = (img.width, img.height);
    let value = |x: Option<usize>, y: Option<usize>| -> f32 {
        match (x, y) {
            (Some(x), Some(y)) => sample_value(texel_z(img.texel(x, y)), d.bits),
            _ => p.border[0],
        }
    };
    let lerp = |w, a, b| lerpf(p.fma, w, a, b);
    match d.func {
        None => soa_taps(p, filter, (w, h), (s, t), value, lerp),
        Some(func) => {
            // gallivm clamps the reference only for formats that are not float
            let rc = if d.bits == FLOAT_BITS {
                r
            } else {
                r.clamp(0.0, 1.0)
            };
            let pass = |x, y| if func.test(rc, value(x, y)) { 1.0 } else { 0.0 };
            soa_taps(p, filter, (w, h), (s, t), pass, lerp)
        }
    }
}

/// Samples a 2x2 quad of a depth texture (`r` is the comparison reference).
#[inline(always)]
pub fn sample_quad(
    p: &UnitPlan<'_>,
    d: &DepthPlan,
    s: [f32; 4],
    t: [f32; 4],
    r: [f32; 4],
) -> [[f32; 4]; 4] {
    let lod: Lod = p.quad_lod(s, t);
    let (filter, l0, l1, frac) = select_levels(p, lod);
    let (img0, img1) = (p.image(l0), p.image(l1));
    each4!(|i| {
        let a = filter_level(p, d, img0, filter, s[i], t[i], r[i]);
        let v = if l1 == l0 {
            a
        } else {
            let b = filter_level(p, d, img1, filter, s[i], t[i], r[i]);
            lerpf(p.fma, frac, a, b)
        };
        d.mode.swizzle(v)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stores_truncate_as_mesa_measured() {
        // measured with glGetTexImage on Mesa 22.3: 0.3 → 0x4ccccc (Z24), 0x4ccc (Z16)
        assert_eq!(store(0.3, 24), 0x4c_cccc);
        assert_eq!(store(0.3, 16), 0x4ccc);
        assert_eq!(store(0.712_345_7, 16), 0xb65b);
        assert_eq!(store(0.712_345_7, 24), 0xb6_5c49);
        assert_eq!(store(2.0, 24), 0xff_ffff);
        // and reads back as 0x4ccccc7f through GL_UNSIGNED_INT
        assert_eq!(
            (readback(0x4c_cccc, 24) as f64 * 4294967295.0) as u32,
            0x4ccc_cc7f
        );
    }

    #[test]
    fn comparison_uses_reference_first() {
        assert!(CompareFunc::Lequal.test(0.25, 0.5));
        assert!(!CompareFunc::Greater.test(0.25, 0.5));
        assert!(CompareFunc::Always.test(f32::NAN, 0.0));
        assert_eq!(DepthMode::Alpha.swizzle(0.5), [0.0, 0.0, 0.0, 0.5]);
    }
}
