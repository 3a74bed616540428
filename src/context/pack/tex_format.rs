//! The texture formats of glTexImage internal formats: the base format, and the storage
//! Mesa 22.3 (llvmpipe) picks for an internal format with a client format and type.

use crate::gl::enums::*;
use crate::gl::glext_enums::*;
use crate::gl::glext_enums::{
    GL_DEPTH24_STENCIL8, GL_DEPTH32F_STENCIL8, GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24,
    GL_DEPTH_COMPONENT32, GL_DEPTH_COMPONENT32F, GL_DEPTH_STENCIL, GL_SLUMINANCE, GL_SLUMINANCE8,
    GL_SLUMINANCE8_ALPHA8, GL_SLUMINANCE_ALPHA, GL_SRGB, GL_SRGB8, GL_SRGB8_ALPHA8, GL_SRGB_ALPHA,
};
use crate::texture::compressed::{Format, Info};
use crate::texture::{BaseFormat, Encoding, Storage};

/// The base internal format of a glTexImage internalformat, or `None` (GL_INVALID_VALUE).
pub fn base_format(internal: i32) -> Option<BaseFormat> {
    use BaseFormat as B;
    Some(match internal as u32 {
        1 | GL_LUMINANCE | GL_LUMINANCE4 | GL_LUMINANCE8 | GL_LUMINANCE12 | GL_LUMINANCE16 => {
            B::Luminance
        }
        2
        | GL_LUMINANCE_ALPHA
        | GL_LUMINANCE4_ALPHA4
        | GL_LUMINANCE6_ALPHA2
        | GL_LUMINANCE8_ALPHA8
        | GL_LUMINANCE12_ALPHA4
        | GL_LUMINANCE12_ALPHA12
        | GL_LUMINANCE16_ALPHA16 => B::LuminanceAlpha,
        3 | GL_RGB | GL_R3_G3_B2 | GL_RGB4 | GL_RGB5 | GL_RGB8 | GL_RGB10 | GL_RGB12 | GL_RGB16 => {
            B::Rgb
        }
        4 | GL_RGBA | GL_RGBA2 | GL_RGBA4 | GL_RGB5_A1 | GL_RGBA8 | GL_RGB10_A2 | GL_RGBA12
        | GL_RGBA16 => B::Rgba,
        GL_ALPHA | GL_ALPHA4 | GL_ALPHA8 | GL_ALPHA12 | GL_ALPHA16 => B::Alpha,
        GL_INTENSITY | GL_INTENSITY4 | GL_INTENSITY8 | GL_INTENSITY12 | GL_INTENSITY16 => {
            B::Intensity
        }
        GL_DEPTH_COMPONENT | GL_DEPTH_COMPONENT16 | GL_DEPTH_COMPONENT24 | GL_DEPTH_COMPONENT32 => {
            B::Depth
        }
        // packed depth-stencil images are depth images that also keep stencil indices
        // (see `shadow`)
        GL_DEPTH_STENCIL | GL_DEPTH24_STENCIL8 => B::Depth,
        // GL_ARB_depth_buffer_float: float depth images (see `shadow`)
        GL_DEPTH_COMPONENT32F | GL_DEPTH32F_STENCIL8 => B::Depth,
        // sRGB: stored like their linear counterparts, decoded when sampled (`srgb`)
        GL_SRGB | GL_SRGB8 => B::Rgb,
        GL_SRGB_ALPHA | GL_SRGB8_ALPHA8 => B::Rgba,
        GL_SLUMINANCE | GL_SLUMINANCE8 => B::Luminance,
        GL_SLUMINANCE_ALPHA | GL_SLUMINANCE8_ALPHA8 => B::LuminanceAlpha,
        _ => return float_base_format(internal as u32),
    })
}

/// The base format of GL_ARB_texture_rg's and GL_ARB_texture_float's internal formats.
fn float_base_format(internal: u32) -> Option<BaseFormat> {
    use BaseFormat as B;
    Some(match internal {
        GL_RED | GL_R8 | GL_R16 | GL_R16F | GL_R32F => B::Red,
        GL_RG | GL_RG8 | GL_RG16 | GL_RG16F | GL_RG32F => B::Rg,
        GL_RGBA32F | GL_RGBA16F => B::Rgba,
        GL_RGB32F | GL_RGB16F => B::Rgb,
        GL_ALPHA32F_ARB | GL_ALPHA16F_ARB => B::Alpha,
        GL_INTENSITY32F_ARB | GL_INTENSITY16F_ARB => B::Intensity,
        GL_LUMINANCE32F_ARB | GL_LUMINANCE16F_ARB => B::Luminance,
        GL_LUMINANCE_ALPHA32F_ARB | GL_LUMINANCE_ALPHA16F_ARB => B::LuminanceAlpha,
        _ => return None,
    })
}

/// The storage of a float or 16-bit unorm internal format (GL_ARB_texture_float,
/// GL_ARB_texture_rg): every component of the base format at 16 or 32 bits (measured:
/// Mesa 22.3 reports 16 for every 16F format and 32 for every 32F one).
fn float_storage(internal: u32, base: BaseFormat) -> Option<Storage> {
    let (bits, encoding) = match internal {
        GL_R16 | GL_RG16 => (16, Encoding::Unorm16),
        // R16G16B16(A16)_UNORM and the 16-bit legacy formats (12-bit ones get 16 bits in
        // Mesa too): kept and rendered at 16 bits
        GL_RGBA16
        | GL_RGB16
        | GL_RGBA12
        | GL_RGB12
        | GL_ALPHA16
        | GL_ALPHA12
        | GL_LUMINANCE16
        | GL_LUMINANCE12
        | GL_LUMINANCE16_ALPHA16
        | GL_LUMINANCE12_ALPHA12
        | GL_INTENSITY16
        | GL_INTENSITY12 => (16, Encoding::Unorm16),
        GL_R16F
        | GL_RG16F
        | GL_RGBA16F
        | GL_RGB16F
        | GL_ALPHA16F_ARB
        | GL_INTENSITY16F_ARB
        | GL_LUMINANCE16F_ARB
        | GL_LUMINANCE_ALPHA16F_ARB => (16, Encoding::Float),
        GL_R32F
        | GL_RG32F
        | GL_RGBA32F
        | GL_RGB32F
        | GL_ALPHA32F_ARB
        | GL_INTENSITY32F_ARB
        | GL_LUMINANCE32F_ARB
        | GL_LUMINANCE_ALPHA32F_ARB => (32, Encoding::Float),
        _ => return None,
    };
    let sizes = Storage::of_base(base)
        .sizes
        .map(|s| if s == 0 { 0 } else { bits });
    Some(Storage { sizes, encoding })
}

/// The storage format Mesa 22.3 (llvmpipe) picks for a glTexImage, as component sizes.
///
/// Measured with glGetTexLevelParameter over every internal format × client format/type:
/// - unsized GL_RGB/GL_RGBA/GL_LUMINANCE/... (not 1–4) take the format matching the
///   client type when there is one (`st_ChooseTextureFormat` → `st_choose_matching_format`
///   for unsigned types): RGB + 5_6_5(_REV) → R5G6B5, RGB + 3_3_2/2_3_3_REV → R3G3B2,
///   RGB + RGBA/BGRA 5_5_5_1 → RGB5, RGB + 2_10_10_10_REV → RGB10, RGBA + 4_4_4_4(_REV) →
///   RGBA4, RGBA + 5_5_5_1/1_5_5_5_REV → RGB5_A1, RGBA + 10_10_10_2(_REV) → RGB10_A2,
///   RGBA/L/A/LA + GL_UNSIGNED_SHORT → 16 bits; everything else 8 bits;
/// - sized formats: R3_G3_B2 3/3/2, RGB4 4, RGB5 5, RGB10 10, RGB12/16 16, RGBA2/RGBA4 4,
///   RGB5_A1 5/1, RGB10_A2 10/2, RGBA12/16 16, *12/*16 16, LUMINANCE4_ALPHA4 4/4 (other
///   4-bit and 6/2 formats are stored with 8 bits).
///
/// `format`/`ty` are 0 when there is no client image (glCopyTexImage).
pub fn choose_storage(internal: i32, base: BaseFormat, format: u32, ty: u32) -> Storage {
    if let Some(s) = float_storage(internal as u32, base) {
        return s;
    }
    let encoding = if is_srgb(internal as u32) {
        Encoding::Srgb
    } else {
        Encoding::Unorm
    };
    Storage {
        sizes: choose_sizes(internal, base, format, ty),
        encoding,
    }
}

/// The component sizes of [`choose_storage`].
fn choose_sizes(internal: i32, base: BaseFormat, format: u32, ty: u32) -> [u8; 6] {
    let rgb = |r: u8, g: u8, b: u8| [r, g, b, 0, 0, 0];
    let rgba = |r: u8, g: u8, b: u8, a: u8| [r, g, b, a, 0, 0];
    let la = |l: u8, a: u8| [0, 0, 0, a, l, 0];
    let rgba_fmt = format == GL_RGBA || format == GL_BGRA;
    match internal as u32 {
        GL_RGB => match ty {
            GL_UNSIGNED_SHORT_5_6_5 | GL_UNSIGNED_SHORT_5_6_5_REV => rgb(5, 6, 5),
            GL_UNSIGNED_BYTE_3_3_2 | GL_UNSIGNED_BYTE_2_3_3_REV => rgb(3, 3, 2),
            GL_UNSIGNED_SHORT_5_5_5_1 if rgba_fmt => rgb(5, 5, 5),
            GL_UNSIGNED_INT_2_10_10_10_REV if format == GL_RGBA => rgb(10, 10, 10),
            _ => Storage::of_base(base).sizes,
        },
        GL_RGBA => match ty {
            GL_UNSIGNED_SHORT_4_4_4_4 | GL_UNSIGNED_SHORT_4_4_4_4_REV => rgba(4, 4, 4, 4),
            GL_UNSIGNED_SHORT_5_5_5_1 | GL_UNSIGNED_SHORT_1_5_5_5_REV => rgba(5, 5, 5, 1),
            GL_UNSIGNED_INT_10_10_10_2 | GL_UNSIGNED_INT_2_10_10_10_REV if format == GL_RGBA => {
                rgba(10, 10, 10, 2)
            }
            GL_UNSIGNED_SHORT if format == GL_RGBA => rgba(16, 16, 16, 16),
            _ => Storage::of_base(base).sizes,
        },
        GL_LUMINANCE if ty == GL_UNSIGNED_SHORT && format == GL_LUMINANCE => la(16, 0),
        GL_ALPHA if ty == GL_UNSIGNED_SHORT && format == GL_ALPHA => la(0, 16),
        GL_LUMINANCE_ALPHA if ty == GL_UNSIGNED_SHORT && format == GL_LUMINANCE_ALPHA => la(16, 16),
        GL_R3_G3_B2 => rgb(3, 3, 2),
        GL_RGB4 => rgb(4, 4, 4),
        GL_RGB5 => rgb(5, 5, 5),
        GL_RGB10 => rgb(10, 10, 10),
        GL_RGB12 | GL_RGB16 => rgb(16, 16, 16),
        GL_RGBA2 | GL_RGBA4 => rgba(4, 4, 4, 4),
        GL_RGB5_A1 => rgba(5, 5, 5, 1),
        GL_RGB10_A2 => rgba(10, 10, 10, 2),
        GL_RGBA12 | GL_RGBA16 => rgba(16, 16, 16, 16),
        GL_ALPHA12 | GL_ALPHA16 => la(0, 16),
        GL_LUMINANCE12 | GL_LUMINANCE16 => la(16, 0),
        GL_LUMINANCE4_ALPHA4 => la(4, 4),
        GL_LUMINANCE12_ALPHA4 | GL_LUMINANCE12_ALPHA12 | GL_LUMINANCE16_ALPHA16 => la(16, 16),
        GL_INTENSITY12 | GL_INTENSITY16 => [0, 0, 0, 0, 0, 16],
        _ => Storage::of_base(base).sizes,
    }
}

/// Whether a glTexImage internal format is an (uncompressed) sRGB one.
pub fn is_srgb(internal: u32) -> bool {
    matches!(
        internal,
        GL_SRGB
            | GL_SRGB8
            | GL_SRGB_ALPHA
            | GL_SRGB8_ALPHA8
            | GL_SLUMINANCE
            | GL_SLUMINANCE8
            | GL_SLUMINANCE_ALPHA
            | GL_SLUMINANCE8_ALPHA8
    )
}

/// The compressed internal formats, in the order of [`compressed_info`]'s table.
pub const FORMATS: [u32; 16] = [
    GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
    GL_COMPRESSED_RGBA_S3TC_DXT1_EXT,
    GL_COMPRESSED_RGBA_S3TC_DXT3_EXT,
    GL_COMPRESSED_RGBA_S3TC_DXT5_EXT,
    GL_COMPRESSED_SRGB_S3TC_DXT1_EXT,
    GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT,
    GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT,
    GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT,
    GL_COMPRESSED_RED_RGTC1,
    GL_COMPRESSED_SIGNED_RED_RGTC1,
    GL_COMPRESSED_RG_RGTC2,
    GL_COMPRESSED_SIGNED_RG_RGTC2,
    GL_COMPRESSED_LUMINANCE_LATC1_EXT,
    GL_COMPRESSED_SIGNED_LUMINANCE_LATC1_EXT,
    GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT,
    GL_COMPRESSED_SIGNED_LUMINANCE_ALPHA_LATC2_EXT,
];

/// GL_COMPRESSED_TEXTURE_FORMATS: Mesa lists S3TC's DXT1 RGB, DXT3 and DXT5 (never RGBA
/// DXT1, RGTC, LATC or sRGB; its FXT1 and ETC2 entries are formats softgl lacks).
pub const LISTED: [u32; 3] = [
    GL_COMPRESSED_RGB_S3TC_DXT1_EXT,
    GL_COMPRESSED_RGBA_S3TC_DXT3_EXT,
    GL_COMPRESSED_RGBA_S3TC_DXT5_EXT,
];

/// The compressed format behind an internal format enum, if softgl supports it.
pub fn compressed_info(internal: u32) -> Option<Info> {
    let i = FORMATS.iter().position(|&f| f == internal)?;
    let s3tc = [
        Format::Dxt1Rgb,
        Format::Dxt1Rgba,
        Format::Dxt3,
        Format::Dxt5,
    ];
    Some(if i < 8 {
        Info {
            format: s3tc[i % 4],
            srgb: i >= 4,
            signed: false,
            luminance: false,
        }
    } else {
        let k = i - 8;
        Info {
            format: if k % 4 < 2 { Format::One } else { Format::Two },
            srgb: false,
            signed: k % 2 == 1,
            luminance: k >= 4,
        }
    })
}
