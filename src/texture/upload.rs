//! Texture image upload and readback: client formats and types into RGBA8 texels, and back.
//!
//! Every component becomes an 8-bit unorm value the way Mesa's `_mesa_format_convert`
//! (`main/format_utils.h`) does it; verified against Mesa 22.3 with glGetTexImage:
//! - GL_FLOAT: clamp to [0, 1], `round_half_even(v·255)` (`_mesa_float_to_unorm`);
//! - GL_UNSIGNED_SHORT/INT: `(v·255 + 2^(n−1) − 1) / (2^n − 1)` (`_mesa_unorm_to_unorm`);
//! - GL_BYTE/SHORT/INT: negative → 0, else the unsigned rule with n−1 bits
//!   (`_mesa_snorm_to_unorm`, so a byte 1 becomes 2 by bit replication);
//! - packed fields of fewer than 8 bits: bit replication (`EXTEND_NORMALIZED_INT`), which is
//!   also what llvmpipe samples from a 565/4444/5551 texture; 10-bit fields round down as
//!   the 16-bit rule does.
//!
//! The client colour is first expanded to RGBA (missing colour 0, missing alpha 1, L to
//! R=G=B), then reduced to the base internal format (L and I take R), then stored after the
//! base-format swizzle (see the module root).

use super::{BaseFormat, Level, Storage};
use crate::context::pixel_transfer::{PixelMaps, PixelTransfer};
use crate::context::state::PixelStore;
use crate::context::{GlError, GlResult};
use crate::gl::enums::*;
use crate::gl::glext_enums::{
    GL_DEPTH24_STENCIL8, GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32,
    GL_DEPTH_STENCIL, GL_SLUMINANCE, GL_SLUMINANCE8, GL_SLUMINANCE8_ALPHA8, GL_SLUMINANCE_ALPHA,
    GL_SRGB, GL_SRGB8, GL_SRGB8_ALPHA8, GL_SRGB_ALPHA, GL_UNSIGNED_INT_24_8,
};
use crate::gl::glext_enums::{
    GL_DEPTH32F_STENCIL8, GL_DEPTH_COMPONENT32F, GL_FLOAT_32_UNSIGNED_INT_24_8_REV,
};

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
        _ => return None,
    })
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
    let rgb = |r: u8, g: u8, b: u8| Storage {
        sizes: [r, g, b, 0, 0, 0],
    };
    let rgba = |r: u8, g: u8, b: u8, a: u8| Storage {
        sizes: [r, g, b, a, 0, 0],
    };
    let la = |l: u8, a: u8| Storage {
        sizes: [0, 0, 0, a, l, 0],
    };
    let rgba_fmt = format == GL_RGBA || format == GL_BGRA;
    match internal as u32 {
        GL_RGB => match ty {
            GL_UNSIGNED_SHORT_5_6_5 | GL_UNSIGNED_SHORT_5_6_5_REV => rgb(5, 6, 5),
            GL_UNSIGNED_BYTE_3_3_2 | GL_UNSIGNED_BYTE_2_3_3_REV => rgb(3, 3, 2),
            GL_UNSIGNED_SHORT_5_5_5_1 if rgba_fmt => rgb(5, 5, 5),
            GL_UNSIGNED_INT_2_10_10_10_REV if format == GL_RGBA => rgb(10, 10, 10),
            _ => Storage::of_base(base),
        },
        GL_RGBA => match ty {
            GL_UNSIGNED_SHORT_4_4_4_4 | GL_UNSIGNED_SHORT_4_4_4_4_REV => rgba(4, 4, 4, 4),
            GL_UNSIGNED_SHORT_5_5_5_1 | GL_UNSIGNED_SHORT_1_5_5_5_REV => rgba(5, 5, 5, 1),
            GL_UNSIGNED_INT_10_10_10_2 | GL_UNSIGNED_INT_2_10_10_10_REV if format == GL_RGBA => {
                rgba(10, 10, 10, 2)
            }
            GL_UNSIGNED_SHORT if format == GL_RGBA => rgba(16, 16, 16, 16),
            _ => Storage::of_base(base),
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
        GL_INTENSITY12 | GL_INTENSITY16 => Storage {
            sizes: [0, 0, 0, 0, 0, 16],
        },
        _ => Storage::of_base(base),
    }
}

/// Reduces an 8-bit component to `bits` bits as Mesa's texstore packs it
/// (`_mesa_unorm_to_unorm(x, 8, bits)`, rounding) and expands it back by bit replication.
#[inline]
pub fn quantise_u8(x: u8, bits: u32) -> u8 {
    if bits >= 8 {
        return x;
    }
    let max = (1u32 << bits) - 1;
    unorm_to_u8(((x as u32 * max + 127) / 255) as u64, bits)
}

/// A float component stored with `bits` bits, as 8 bits: 8-bit channels with
/// `_mesa_float_to_unorm` (round half to even), the packed formats of fewer bits with
/// u_format's `util_iround(clamp(x)·max)`, which Mesa 22.3 computes as `(int)(f + 0.5f)`
/// (measured: 0.3 into GL_RGBA4 stores 5, not 4).
#[inline]
fn float_to_bits_u8(x: f32, bits: u32) -> u8 {
    if bits >= 8 {
        return float_to_u8(x);
    }
    let max = ((1u32 << bits) - 1) as f32;
    let x = if x > 1.0 {
        1.0
    } else if x > 0.0 {
        x
    } else {
        0.0
    };
    unorm_to_u8((x * max + 0.5) as u64, bits)
}

/// Which RGBA channel each client component is (`4` = luminance, i.e. R=G=B).
fn format_components(format: u32) -> Option<&'static [usize]> {
    Some(match format {
        GL_RGBA => &[0, 1, 2, 3],
        GL_RGB => &[0, 1, 2],
        GL_BGRA => &[2, 1, 0, 3],
        GL_BGR => &[2, 1, 0],
        GL_LUMINANCE => &[4],
        GL_LUMINANCE_ALPHA => &[4, 3],
        GL_ALPHA => &[3],
        GL_RED => &[0],
        // only for depth images (the others refuse it)
        GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL => &[0],
        GL_GREEN => &[1],
        GL_BLUE => &[2],
        _ => return None,
    })
}

/// A client pixel type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Ty {
    /// One value per component of this many bytes (signed?, float?).
    Plain {
        size: usize,
        signed: bool,
        float: bool,
    },
    /// A packed pixel: total bytes, fields as (shift, bits) in component order.
    Packed {
        size: usize,
        fields: &'static [(u32, u32)],
    },
}

fn pixel_type(ty: u32) -> Option<Ty> {
    let plain = |size, signed, float| Ty::Plain {
        size,
        signed,
        float,
    };
    let packed = |size, fields| Ty::Packed { size, fields };
    Some(match ty {
        GL_UNSIGNED_BYTE => plain(1, false, false),
        GL_BYTE => plain(1, true, false),
        GL_UNSIGNED_SHORT => plain(2, false, false),
        GL_SHORT => plain(2, true, false),
        GL_UNSIGNED_INT => plain(4, false, false),
        GL_INT => plain(4, true, false),
        GL_FLOAT => plain(4, false, true),
        GL_UNSIGNED_BYTE_3_3_2 => packed(1, &[(5, 3), (2, 3), (0, 2)]),
        GL_UNSIGNED_BYTE_2_3_3_REV => packed(1, &[(0, 3), (3, 3), (6, 2)]),
        GL_UNSIGNED_SHORT_5_6_5 => packed(2, &[(11, 5), (5, 6), (0, 5)]),
        GL_UNSIGNED_SHORT_5_6_5_REV => packed(2, &[(0, 5), (5, 6), (11, 5)]),
        GL_UNSIGNED_SHORT_4_4_4_4 => packed(2, &[(12, 4), (8, 4), (4, 4), (0, 4)]),
        GL_UNSIGNED_SHORT_4_4_4_4_REV => packed(2, &[(0, 4), (4, 4), (8, 4), (12, 4)]),
        GL_UNSIGNED_SHORT_5_5_5_1 => packed(2, &[(11, 5), (6, 5), (1, 5), (0, 1)]),
        GL_UNSIGNED_SHORT_1_5_5_5_REV => packed(2, &[(0, 5), (5, 5), (10, 5), (15, 1)]),
        GL_UNSIGNED_INT_8_8_8_8 => packed(4, &[(24, 8), (16, 8), (8, 8), (0, 8)]),
        GL_UNSIGNED_INT_8_8_8_8_REV => packed(4, &[(0, 8), (8, 8), (16, 8), (24, 8)]),
        GL_UNSIGNED_INT_10_10_10_2 => packed(4, &[(22, 10), (12, 10), (2, 10), (0, 2)]),
        GL_UNSIGNED_INT_2_10_10_10_REV => packed(4, &[(0, 10), (10, 10), (20, 10), (30, 2)]),
        // depth in the top 24 bits, stencil in the low 8 (GL_DEPTH_STENCIL only)
        GL_UNSIGNED_INT_24_8 => packed(4, &[(8, 24)]),
        // a float depth word, then a word with the stencil in its low 8 bits
        GL_FLOAT_32_UNSIGNED_INT_24_8_REV => packed(8, &[(0, 32)]),
        _ => return None,
    })
}

/// A validated client pixel layout.
#[derive(Clone, Copy, Debug)]
pub struct ClientFormat {
    comps: &'static [usize],
    ty: Ty,
    depth: bool,
    stencil: bool,
    /// The GL type token.
    pub gl_type: u32,
}

impl ClientFormat {
    /// Validates `format`/`type`: unknown → GL_INVALID_ENUM, a packed type whose component
    /// count does not match the format → GL_INVALID_OPERATION. GL_DEPTH_STENCIL takes only
    /// GL_UNSIGNED_INT_24_8 and GL_FLOAT_32_UNSIGNED_INT_24_8_REV (another type is
    /// GL_INVALID_ENUM), and those two only GL_DEPTH_STENCIL (GL_INVALID_OPERATION), as
    /// Mesa 22.3 checks them.
    pub fn new(format: u32, ty: u32) -> GlResult<ClientFormat> {
        let comps = format_components(format).ok_or(GlError::InvalidEnum)?;
        let t = pixel_type(ty).ok_or(GlError::InvalidEnum)?;
        let ds_type = matches!(ty, GL_UNSIGNED_INT_24_8 | GL_FLOAT_32_UNSIGNED_INT_24_8_REV);
        if (format == GL_DEPTH_STENCIL) != ds_type {
            return Err(if format == GL_DEPTH_STENCIL {
                GlError::InvalidEnum
            } else {
                GlError::InvalidOperation
            });
        }
        if let Ty::Packed { fields, .. } = t {
            if fields.len() != comps.len() || (fields.len() == 3 && format != GL_RGB) {
                return Err(GlError::InvalidOperation);
            }
        }
        Ok(ClientFormat {
            comps,
            ty: t,
            depth: format == GL_DEPTH_COMPONENT || format == GL_DEPTH_STENCIL,
            stencil: format == GL_DEPTH_STENCIL,
            gl_type: ty,
        })
    }

    /// GL_DEPTH_COMPONENT or GL_DEPTH_STENCIL (valid only with depth images).
    pub fn is_depth(&self) -> bool {
        self.depth
    }

    /// GL_DEPTH_STENCIL (packed depth and stencil index).
    pub fn is_depth_stencil(&self) -> bool {
        self.stencil
    }

    /// Bytes per pixel and bytes per element (for the alignment rule).
    pub fn sizes(&self) -> (usize, usize) {
        match self.ty {
            Ty::Plain { size, .. } => (size * self.comps.len(), size),
            Ty::Packed { size, .. } => (size, size),
        }
    }
}

/// Mesa's `_mesa_unorm_to_unorm` from `bits` to 8 bits.
#[inline]
pub fn unorm_to_u8(x: u64, bits: u32) -> u8 {
    if bits == 8 {
        x as u8
    } else if bits < 8 {
        // EXTEND_NORMALIZED_INT
        let max = (1u64 << bits) - 1;
        let r = x * (255 / max)
            + if 8 % bits != 0 {
                x >> (bits - 8 % bits)
            } else {
                0
            };
        r.min(255) as u8
    } else {
        let max = (1u64 << bits) - 1;
        let half = (1u64 << (bits - 1)) - 1;
        ((x * 255 + half) / max) as u8
    }
}

/// Mesa's `_mesa_float_to_unorm(x, 8)`.
#[inline]
pub fn float_to_u8(x: f32) -> u8 {
    if x > 1.0 {
        255
    } else if x > 0.0 {
        (x * 255.0).round_ties_even() as u8
    } else {
        0
    }
}

fn read_uint(bytes: &[u8], swap: bool) -> u64 {
    let mut b = [0u8; 8];
    b[..bytes.len()].copy_from_slice(bytes);
    if swap {
        b[..bytes.len()].reverse();
    }
    let v = u64::from_ne_bytes(b);
    if cfg!(target_endian = "big") {
        v >> (64 - 8 * bytes.len())
    } else {
        v
    }
}

/// One client component as read from memory.
#[derive(Clone, Copy)]
enum Component {
    /// An unsigned normalized integer of this many bits.
    Unorm(u64, u32),
    /// A signed normalized integer of this many bits.
    Snorm(i64, u32),
    /// A float.
    Float(f32),
}

/// Calls `put(channel, component)` for each component of one client pixel (channel `4`
/// = luminance).
fn for_each_component(
    cf: &ClientFormat,
    px: &[u8],
    swap: bool,
    mut put: impl FnMut(usize, Component),
) {
    match cf.ty {
        Ty::Plain {
            size,
            signed,
            float,
        } => {
            for (i, &comp) in cf.comps.iter().enumerate() {
                let raw = read_uint(&px[i * size..(i + 1) * size], swap && size > 1);
                let bits = 8 * size as u32;
                put(
                    comp,
                    if float {
                        Component::Float(f32::from_bits(raw as u32))
                    } else if signed {
                        Component::Snorm(((raw << (64 - bits)) as i64) >> (64 - bits), bits)
                    } else {
                        Component::Unorm(raw, bits)
                    },
                );
            }
        }
        Ty::Packed { size, fields } => {
            let raw = read_uint(&px[..size], swap && size > 1);
            for (&comp, &(shift, bits)) in cf.comps.iter().zip(fields) {
                put(
                    comp,
                    Component::Unorm((raw >> shift) & ((1 << bits) - 1), bits),
                );
            }
        }
    }
}

/// Writes `v` into channel `comp` of `rgba` (`4` = luminance: R, G and B).
fn put_channel<T: Copy>(rgba: &mut [T; 4], comp: usize, v: T) {
    if comp == 4 {
        rgba[..3].fill(v);
    } else {
        rgba[comp] = v;
    }
}

/// Decodes one client pixel into RGBA8 (missing colour 0, alpha 255), each component kept
/// with `bits[channel]` bits (see [`Storage::bits`]).
fn decode_pixel(cf: &ClientFormat, px: &[u8], swap: bool, bits: [u32; 4]) -> [u8; 4] {
    let mut rgba = [0u8, 0, 0, 255];
    for_each_component(cf, px, swap, |comp, c| {
        let stored = bits[if comp == 4 { 0 } else { comp }];
        let v = match c {
            // straight to the stored precision (then the quantisation keeps it)
            Component::Float(f) => float_to_bits_u8(f, stored),
            Component::Snorm(sv, bits) if sv > 0 => unorm_to_u8(sv as u64, bits - 1),
            Component::Snorm(..) => 0,
            Component::Unorm(x, bits) => unorm_to_u8(x, bits),
        };
        put_channel(&mut rgba, comp, quantise_u8(v, stored));
    });
    rgba
}

/// Decodes one client pixel into RGBA float as Mesa's `_mesa_format_convert` does
/// before pixel transfer: unorm `x·f32(1/max)`, snorm `x·f32(1/max)` (at least −1), float
/// as is; missing colour 0, missing alpha 1, luminance into R, G and B.
fn decode_pixel_f32(cf: &ClientFormat, px: &[u8], swap: bool) -> [f32; 4] {
    let mut rgba = [0.0, 0.0, 0.0, 1.0];
    for_each_component(cf, px, swap, |comp, c| {
        let v = match c {
            Component::Float(f) => f,
            Component::Snorm(sv, bits) => {
                let max = (1i64 << (bits - 1)) - 1;
                if sv <= -max {
                    -1.0
                } else {
                    sv as f32 * (1.0 / max as f32)
                }
            }
            Component::Unorm(x, bits) => x as f32 * (1.0 / ((1u64 << bits) - 1) as f32),
        };
        put_channel(&mut rgba, comp, v);
    });
    rgba
}

/// Pixel transfer of colours stored into a texture (GL 1.5 §3.8.1: glTexImage,
/// glTexSubImage and glCopyTexImage apply it; Mesa's texstore goes through RGBA float:
/// scale and bias, then the colour maps, then the stored format's `_mesa_float_to_unorm`).
#[derive(Clone, Copy, Debug)]
pub struct ColorTransfer<'a> {
    /// Scale and bias (GL_RED_SCALE …) and GL_MAP_COLOR.
    pub transfer: &'a PixelTransfer,
    /// The GL_PIXEL_MAP_*_TO_* colour maps.
    pub maps: &'a PixelMaps,
}

impl ColorTransfer<'_> {
    /// The transfer of `tr` and `maps`, or `None` when it changes nothing
    /// (Mesa's `_ImageTransferState` is 0).
    pub fn active<'a>(tr: &'a PixelTransfer, maps: &'a PixelMaps) -> Option<ColorTransfer<'a>> {
        (tr.scale_bias() || tr.map_color).then_some(ColorTransfer { transfer: tr, maps })
    }

    /// A colour after scale, bias and the maps (not clamped: the store clamps).
    pub fn apply(&self, c: [f32; 4]) -> [f32; 4] {
        let c = self.transfer.apply_scale_bias(c);
        if self.transfer.map_color {
            self.maps.map_rgba(c)
        } else {
            c
        }
    }

    /// A float colour after the transfer, stored with `storage`'s bits as the texel of
    /// `base`.
    pub fn store(&self, c: [f32; 4], base: BaseFormat, storage: &Storage) -> [u8; 4] {
        let c = self.apply(c);
        let bits = storage.bits();
        to_texel(
            base,
            std::array::from_fn(|i| float_to_bits_u8(c[i], bits[i])),
        )
    }
}

/// Quantises an RGBA8 value to the storage precision (glCopyTexImage, mipmaps).
#[inline]
pub fn quantise_rgba(rgba: [u8; 4], storage: &Storage) -> [u8; 4] {
    let bits = storage.bits();
    std::array::from_fn(|c| quantise_u8(rgba[c], bits[c]))
}

/// Reduces client RGBA to the base format's stored (swizzled) texel.
#[inline]
pub fn to_texel(base: BaseFormat, rgba: [u8; 4]) -> [u8; 4] {
    base.swizzle(rgba, 0, 255)
}

/// Where a client image's bytes are: the byte offset of pixel (x, y) of a `width`-wide image.
#[derive(Clone, Copy, Debug)]
pub struct Layout {
    /// Offset of the first pixel.
    pub start: usize,
    /// Bytes between rows.
    pub stride: usize,
    /// Bytes per pixel.
    pub bpp: usize,
}

impl Layout {
    /// The layout of a `width`-wide image under `ps` (GL 1.5 §3.6.4).
    pub fn new(ps: &PixelStore, width: usize, cf: &ClientFormat) -> Layout {
        let (bpp, elem) = cf.sizes();
        let (start, stride) = crate::ffi::query::packed_layout(ps, width, bpp, elem);
        Layout { start, stride, bpp }
    }
    /// Bytes from the first byte read to one past the last, for `w` x `h` pixels.
    pub fn span(&self, w: usize, h: usize) -> usize {
        if w == 0 || h == 0 {
            0
        } else {
            self.start + (h - 1) * self.stride + w * self.bpp
        }
    }
}

/// Unpacks a `w` x `h` client image into texels of `base`.
///
/// # Safety
/// `data` must be readable for `Layout::span(w, h)` bytes (GL's contract with the program).
pub unsafe fn unpack(
    ps: &PixelStore,
    cf: &ClientFormat,
    base: BaseFormat,
    storage: Storage,
    w: usize,
    h: usize,
    data: *const u8,
) -> Vec<[u8; 4]> {
    // SAFETY: forwarded caller contract.
    unsafe { unpack_transfer(ps, cf, (base, storage), w, h, data, None) }
}

/// [`unpack`] with the pixel transfer `tr` applied to every colour.
///
/// # Safety
/// `data` must be readable for `Layout::span(w, h)` bytes (GL's contract with the program).
pub unsafe fn unpack_transfer(
    ps: &PixelStore,
    cf: &ClientFormat,
    (base, storage): (BaseFormat, Storage),
    w: usize,
    h: usize,
    data: *const u8,
    tr: Option<ColorTransfer<'_>>,
) -> Vec<[u8; 4]> {
    let lay = Layout::new(ps, w, cf);
    let mut out = Vec::with_capacity(w * h);
    if data.is_null() || w == 0 || h == 0 {
        out.resize(w * h, to_texel(base, [0, 0, 0, 0]));
        return out;
    }
    // SAFETY: the caller guarantees `span` readable bytes.
    let bytes = unsafe { std::slice::from_raw_parts(data, lay.span(w, h)) };
    let bits = storage.bits();
    for y in 0..h {
        let row = lay.start + y * lay.stride;
        for x in 0..w {
            let px = &bytes[row + x * lay.bpp..][..lay.bpp];
            out.push(match tr {
                Some(tr) => tr.store(decode_pixel_f32(cf, px, ps.swap_bytes), base, &storage),
                None => to_texel(base, decode_pixel(cf, px, ps.swap_bytes, bits)),
            });
        }
    }
    out
}

/// The RGBA value glGetTexImage starts from (GL 1.5 table 6.1: L and I go to R, with G = B
/// = 0; A = 1 where the format has none). Mesa 22.3 reads an intensity texture back as
/// (I, 0, 0, 1), like luminance, not with A = I.
fn readback_rgba(base: BaseFormat, t: [u8; 4]) -> [u8; 4] {
    match base {
        BaseFormat::Alpha => [0, 0, 0, t[3]],
        BaseFormat::Luminance | BaseFormat::Intensity => [t[0], 0, 0, 255],
        BaseFormat::LuminanceAlpha => [t[0], 0, 0, t[3]],
        BaseFormat::Rgb => [t[0], t[1], t[2], 255],
        BaseFormat::Rgba => t,
        // depth images are read back by `shadow::pack`
        BaseFormat::Depth => [0, 0, 0, 255],
    }
}

fn encode_u8(v: u8, ty: Ty, out: &mut [u8], swap: bool) {
    let put = |out: &mut [u8], raw: u64, size: usize| {
        let b = raw.to_ne_bytes();
        let bytes = if cfg!(target_endian = "big") {
            &b[8 - size..]
        } else {
            &b[..size]
        };
        out[..size].copy_from_slice(bytes);
        if swap && size > 1 {
            out[..size].reverse();
        }
    };
    if let Ty::Plain {
        size,
        signed,
        float,
    } = ty
    {
        let raw: u64 = if float {
            (v as f32 * (1.0 / 255.0)).to_bits() as u64
        } else if signed {
            // unorm → snorm: v · (2^(n−1) − 1) / 255, rounded
            let max = (1u64 << (8 * size - 1)) - 1;
            (v as u64 * max + 127) / 255
        } else {
            let max = if size == 8 {
                u64::MAX
            } else {
                (1u64 << (8 * size)) - 1
            };
            v as u64 * (max / 255)
        };
        put(out, raw, size);
    }
}

/// Packs texels of a level into client memory (glGetTexImage).
///
/// # Safety
/// `dst` must be writable for `Layout::span(w, h)` bytes.
pub unsafe fn pack(ps: &PixelStore, cf: &ClientFormat, img: &Level, dst: *mut u8) {
    let (w, h) = (img.width, img.height);
    let lay = Layout::new(ps, w, cf);
    if dst.is_null() || w == 0 || h == 0 {
        return;
    }
    // SAFETY: the caller guarantees `span` writable bytes.
    let bytes = unsafe { std::slice::from_raw_parts_mut(dst, lay.span(w, h)) };
    for y in 0..h {
        for x in 0..w {
            let rgba = readback_rgba(img.base, img.texel(x, y));
            let o = lay.start + y * lay.stride + x * lay.bpp;
            let px = &mut bytes[o..o + lay.bpp];
            match cf.ty {
                Ty::Plain { size, .. } => {
                    for (i, &comp) in cf.comps.iter().enumerate() {
                        let v = if comp == 4 { rgba[0] } else { rgba[comp] };
                        encode_u8(v, cf.ty, &mut px[i * size..(i + 1) * size], ps.swap_bytes);
                    }
                }
                Ty::Packed { size, fields } => {
                    let mut raw = 0u64;
                    for (&comp, &(shift, bits)) in cf.comps.iter().zip(fields) {
                        let v = if comp == 4 { rgba[0] } else { rgba[comp] } as u64;
                        let max = (1u64 << bits) - 1;
                        raw |= ((v * max + 127) / 255) << shift;
                    }
                    let b = raw.to_ne_bytes();
                    let bytes = if cfg!(target_endian = "big") {
                        &b[8 - size..]
                    } else {
                        &b[..size]
                    };
                    px[..size].copy_from_slice(bytes);
                    if ps.swap_bytes && size > 1 {
                        px[..size].reverse();
                    }
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn conversions_match_mesa_probe() {
        // values measured with Mesa 22.3 (glTexImage2D GL_RGBA8 + glGetTexImage)
        assert_eq!(float_to_u8(1.5 / 255.0), 2);
        assert_eq!(float_to_u8(2.5 / 255.0), 2);
        assert_eq!(float_to_u8(5.5 / 255.0), 6);
        assert_eq!(float_to_u8(-0.5), 0);
        assert_eq!(float_to_u8(f32::NAN), 0);
        assert_eq!(unorm_to_u8(128, 16), 0);
        assert_eq!(unorm_to_u8(129, 16), 1);
        assert_eq!(unorm_to_u8(385, 16), 1);
        assert_eq!(unorm_to_u8(774, 16), 3);
        assert_eq!(unorm_to_u8(127, 15), 1); // GL_SHORT 127
        assert_eq!(unorm_to_u8(385, 15), 3);
        assert_eq!(unorm_to_u8(8400953, 32), 0);
        assert_eq!(unorm_to_u8(16801906, 32), 1);
        assert_eq!(unorm_to_u8(11561273, 31), 1); // GL_INT
        assert_eq!(unorm_to_u8(1, 7), 2); // GL_BYTE 1
        assert_eq!(unorm_to_u8(64, 7), 129);
        assert_eq!(unorm_to_u8(127, 7), 255);
        // bit replication of packed fields
        assert_eq!(unorm_to_u8(3, 5), 24);
        assert_eq!(unorm_to_u8(4, 5), 33);
        assert_eq!(unorm_to_u8(1, 6), 4);
        assert_eq!(unorm_to_u8(5, 4), 85);
        assert_eq!(unorm_to_u8(1, 1), 255);
        assert_eq!(unorm_to_u8(7, 3), 255);
        assert_eq!(unorm_to_u8(1, 3), 36);
    }

    #[test]
    fn unpack_alignment_row_length_skip() {
        let cf = ClientFormat::new(GL_RGB, GL_UNSIGNED_BYTE).unwrap();
        // 3 px wide RGB, alignment 4 → stride 12 (9 bytes + 3 padding)
        let ps = PixelStore {
            alignment: 4,
            ..Default::default()
        };
        let mut data = [0u8; 24];
        for (i, b) in data.iter_mut().enumerate() {
            *b = i as u8;
        }
        // SAFETY: the buffer holds the whole image for this size and pixel store.
        let t = unsafe {
            unpack(
                &ps,
                &cf,
                BaseFormat::Rgb,
                Storage::of_base(BaseFormat::Rgb),
                3,
                2,
                data.as_ptr(),
            )
        };
        assert_eq!(t[2], [6, 7, 8, 255]);
        assert_eq!(t[3], [12, 13, 14, 255]);
        // alignment 1: tight rows
        let ps1 = PixelStore {
            alignment: 1,
            ..Default::default()
        };
        // SAFETY: the buffer holds the whole image for this size and pixel store.
        let t = unsafe {
            unpack(
                &ps1,
                &cf,
                BaseFormat::Rgb,
                Storage::of_base(BaseFormat::Rgb),
                3,
                2,
                data.as_ptr(),
            )
        };
        assert_eq!(t[3], [9, 10, 11, 255]);
        // row length 4, skip 1 pixel and 1 row, alignment 1
        let ps2 = PixelStore {
            alignment: 1,
            row_length: 4,
            skip_pixels: 1,
            skip_rows: 1,
            ..Default::default()
        };
        let data = (0..36u8).collect::<Vec<_>>();
        // SAFETY: the buffer holds the whole image for this size and pixel store.
        let t = unsafe {
            unpack(
                &ps2,
                &cf,
                BaseFormat::Rgb,
                Storage::of_base(BaseFormat::Rgb),
                2,
                2,
                data.as_ptr(),
            )
        };
        assert_eq!(t[0], [15, 16, 17, 255]);
        assert_eq!(t[2], [27, 28, 29, 255]);
    }

    #[test]
    fn base_format_reduction_and_swizzle() {
        let cf = ClientFormat::new(GL_RGBA, GL_UNSIGNED_BYTE).unwrap();
        let ps = PixelStore {
            alignment: 1,
            ..Default::default()
        };
        let px = [10u8, 20, 30, 40];
        // SAFETY: the buffer holds the whole image for this size and pixel store.
        let get = |b| unsafe { unpack(&ps, &cf, b, Storage::of_base(b), 1, 1, px.as_ptr()) }[0];
        assert_eq!(get(BaseFormat::Luminance), [10, 10, 10, 255]);
        assert_eq!(get(BaseFormat::Alpha), [0, 0, 0, 40]);
        assert_eq!(get(BaseFormat::Intensity), [10, 10, 10, 10]);
        assert_eq!(get(BaseFormat::LuminanceAlpha), [10, 10, 10, 40]);
        assert_eq!(get(BaseFormat::Rgb), [10, 20, 30, 255]);
        let la = ClientFormat::new(GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE).unwrap();
        // SAFETY: the buffer holds the whole image for this size and pixel store.
        let t = unsafe {
            unpack(
                &ps,
                &la,
                BaseFormat::Rgba,
                Storage::of_base(BaseFormat::Rgba),
                1,
                1,
                px.as_ptr(),
            )
        }[0];
        assert_eq!(t, [10, 10, 10, 20]);
    }

    #[test]
    fn packed_and_swapped() {
        let ps = PixelStore {
            alignment: 1,
            swap_bytes: true,
            ..Default::default()
        };
        let cf = ClientFormat::new(GL_RGB, GL_UNSIGNED_SHORT_5_6_5).unwrap();
        let v: u16 = (3 << 11) | (1 << 5) | 31;
        let b = v.swap_bytes().to_ne_bytes();
        // SAFETY: the buffer holds the whole image for this size and pixel store.
        let t = unsafe {
            unpack(
                &ps,
                &cf,
                BaseFormat::Rgb,
                Storage::of_base(BaseFormat::Rgb),
                1,
                1,
                b.as_ptr(),
            )
        }[0];
        assert_eq!(t, [24, 4, 255, 255]);
        assert_eq!(
            ClientFormat::new(GL_RGBA, GL_UNSIGNED_SHORT_5_6_5).err(),
            Some(GlError::InvalidOperation)
        );
        assert_eq!(
            ClientFormat::new(GL_INTENSITY, GL_UNSIGNED_BYTE).err(),
            Some(GlError::InvalidEnum)
        );
        let bgra = ClientFormat::new(GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV).unwrap();
        let ps = PixelStore {
            alignment: 1,
            ..Default::default()
        };
        let px = 0x4411_2233u32.to_ne_bytes();
        // SAFETY: the buffer holds the whole image for this size and pixel store.
        let t = unsafe {
            unpack(
                &ps,
                &bgra,
                BaseFormat::Rgba,
                Storage::of_base(BaseFormat::Rgba),
                1,
                1,
                px.as_ptr(),
            )
        }[0];
        assert_eq!(t, [0x11, 0x22, 0x33, 0x44]);
    }

    #[test]
    fn pack_round_trip() {
        let ps = PixelStore {
            alignment: 1,
            ..Default::default()
        };
        let img = Level {
            width: 3,
            height: 1,
            internal_format: GL_RGBA,
            base: BaseFormat::Rgba,
            storage: crate::texture::Storage::of_base(BaseFormat::Rgba),
            texels: vec![[1, 2, 3, 4], [5, 6, 7, 8], [9, 10, 11, 12]],
            blocks: None,
        };
        let cf = ClientFormat::new(GL_BGRA, GL_UNSIGNED_BYTE).unwrap();
        let mut out = vec![0u8; 12];
        // SAFETY: the buffer holds the whole image for this size and pixel store.
        unsafe { pack(&ps, &cf, &img, out.as_mut_ptr()) };
        assert_eq!(&out[..4], &[3, 2, 1, 4]);
        // SAFETY: the buffer holds the whole image for this size and pixel store.
        let back = unsafe {
            unpack(
                &ps,
                &cf,
                BaseFormat::Rgba,
                Storage::of_base(BaseFormat::Rgba),
                3,
                1,
                out.as_ptr(),
            )
        };
        assert_eq!(back, img.texels);
        let f = ClientFormat::new(GL_RGBA, GL_FLOAT).unwrap();
        let mut outf = vec![0f32; 12];
        // SAFETY: the buffer holds the whole image for this size and pixel store.
        unsafe { pack(&ps, &f, &img, outf.as_mut_ptr() as *mut u8) };
        // SAFETY: the buffer holds the whole image for this size and pixel store.
        let back = unsafe {
            unpack(
                &ps,
                &f,
                BaseFormat::Rgba,
                Storage::of_base(BaseFormat::Rgba),
                3,
                1,
                outf.as_ptr() as *const u8,
            )
        };
        assert_eq!(back, img.texels);
    }

    #[test]
    fn storage_choice_matches_mesa() {
        let sz = |i: u32, f: u32, t: u32| {
            choose_storage(i as i32, base_format(i as i32).unwrap(), f, t).sizes
        };
        assert_eq!(
            sz(GL_RGB, GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV),
            [5, 6, 5, 0, 0, 0]
        );
        assert_eq!(
            sz(GL_RGBA, GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4),
            [4, 4, 4, 4, 0, 0]
        );
        assert_eq!(
            sz(GL_RGBA, GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV),
            [5, 5, 5, 1, 0, 0]
        );
        assert_eq!(
            sz(GL_RGB, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1),
            [5, 5, 5, 0, 0, 0]
        );
        assert_eq!(
            sz(GL_RGB, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4),
            [8, 8, 8, 0, 0, 0]
        );
        assert_eq!(
            sz(GL_LUMINANCE_ALPHA, GL_LUMINANCE_ALPHA, GL_UNSIGNED_SHORT),
            [0, 0, 0, 16, 16, 0]
        );
        assert_eq!(sz(GL_RGB, GL_RGB, GL_UNSIGNED_SHORT), [8, 8, 8, 0, 0, 0]);
        assert_eq!(sz(GL_RGBA, GL_RGBA, GL_FLOAT), [8, 8, 8, 8, 0, 0]);
        // numbered internal formats are never matched to the type
        assert_eq!(sz(3, GL_RGB, GL_UNSIGNED_SHORT_5_6_5), [8, 8, 8, 0, 0, 0]);
        assert_eq!(sz(GL_RGBA2, GL_RGBA, GL_UNSIGNED_BYTE), [4, 4, 4, 4, 0, 0]);
        assert_eq!(
            sz(GL_LUMINANCE4_ALPHA4, GL_RGBA, GL_UNSIGNED_BYTE),
            [0, 0, 0, 4, 4, 0]
        );
        assert_eq!(
            sz(GL_LUMINANCE4, GL_RGBA, GL_UNSIGNED_BYTE),
            [0, 0, 0, 0, 8, 0]
        );
    }

    #[test]
    fn small_formats_round_on_upload() {
        // Mesa 22.3 glGetTexImage of a 0..255 ramp stored as GL_RGBA4 / GL_RGB5
        assert_eq!(quantise_u8(8, 4), 0);
        assert_eq!(quantise_u8(9, 4), 17);
        assert_eq!(quantise_u8(4, 5), 0);
        assert_eq!(quantise_u8(5, 5), 8);
        assert_eq!(quantise_u8(200, 8), 200);
        // expanded values are kept as they are
        for bits in 1..8 {
            for q in 0..(1u64 << bits) {
                let v = unorm_to_u8(q, bits);
                assert_eq!(quantise_u8(v, bits), v);
            }
        }
        let cf = ClientFormat::new(GL_RGBA, GL_FLOAT).unwrap();
        let ps = PixelStore {
            alignment: 1,
            ..Default::default()
        };
        let st = choose_storage(GL_RGBA4 as i32, BaseFormat::Rgba, GL_RGBA, GL_FLOAT);
        // 0.0333·15 = 0.4995 → 0, 0.0334·15 = 0.501 → 1 (17); a u8 detour would give 9 → 17
        let px = [0.0333f32, 0.0334, 1.5, -1.0];
        // SAFETY: the buffer holds the whole image for this size and pixel store.
        let t = unsafe {
            unpack(
                &ps,
                &cf,
                BaseFormat::Rgba,
                st,
                1,
                1,
                px.as_ptr() as *const u8,
            )
        };
        assert_eq!(t[0], [0, 17, 255, 0]);
    }

    #[test]
    fn intensity_reads_back_like_luminance() {
        // Mesa 22.3: glGetTexImage(GL_RGBA) of GL_INTENSITY* gives (I, 0, 0, 255)
        assert_eq!(
            readback_rgba(BaseFormat::Intensity, [7, 7, 7, 7]),
            [7, 0, 0, 255]
        );
    }
}
