//! Pixel packing and unpacking: every conversion between client memory in a GL format
//! and type (under GL_PACK_* / GL_UNPACK_* and the pixel-transfer state) and the values
//! the pipeline works with.
//!
//! - [`read`]: glReadPixels (framebuffer → client memory);
//! - [`draw_image`]: the client images of glDrawPixels, glBitmap and colour-index
//!   textures, decoded once into [`crate::pixels::image::Image`];
//! - [`tex`] and [`tex_format`]: glTexImage/glTexSubImage unpacking into texels,
//!   glGetTexImage packing, and the storage Mesa picks for an internal format;
//!   [`tex_float`] the same for float and 16-bit images;
//! - [`depth`]: depth and depth-stencil texture images.
//!
//! The layout rules (GL 1.5 §3.6.4 / §4.3.2) and the table of pixel types are shared here.

pub mod depth;
pub mod draw_image;
pub mod read;
mod read_fast;
pub mod tex;
pub mod tex_float;
pub mod tex_format;
pub mod wide;

use super::state::PixelStore;
use crate::gl::enums::*;
use crate::gl::error::{GlError, GlResult};
use crate::gl::glext_enums::{
    GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, GL_UNSIGNED_INT_24_8,
};

/// Byte layout of a client image (GL 1.5 §3.6.4 / §4.3.2 with the pack or unpack
/// parameters): (offset of the first pixel, bytes between rows).
pub fn packed_layout(
    ps: &PixelStore,
    width: usize,
    bytes_per_pixel: usize,
    type_size: usize,
) -> (usize, usize) {
    let row_px = if ps.row_length > 0 {
        ps.row_length as usize
    } else {
        width
    };
    let align = ps.alignment as usize;
    let raw = row_px * bytes_per_pixel;
    let stride = if type_size >= align {
        raw
    } else {
        raw.div_ceil(align) * align
    };
    let start = ps.skip_rows as usize * stride + ps.skip_pixels as usize * bytes_per_pixel;
    (start, stride)
}

/// A client pixel type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Ty {
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
    /// GL_BITMAP: one bit a pixel.
    Bitmap,
}

/// The pixel type of a GL type token, or `None` for an unknown one.
pub(crate) fn pixel_type(ty: u32) -> Option<Ty> {
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
        GL_BITMAP => Ty::Bitmap,
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

/// Whether `ty` is one of the two GL_DEPTH_STENCIL types.
fn is_depth_stencil_type(ty: u32) -> bool {
    matches!(ty, GL_UNSIGNED_INT_24_8 | GL_FLOAT_32_UNSIGNED_INT_24_8_REV)
}

/// Which RGBA channel each component of a client format is (`4` = luminance, i.e.
/// R=G=B); depth, stencil and colour-index formats have one component.
pub(crate) fn components(format: u32) -> Option<&'static [usize]> {
    Some(match format {
        GL_RGBA => &[0, 1, 2, 3],
        GL_RGB => &[0, 1, 2],
        GL_BGRA => &[2, 1, 0, 3],
        GL_BGR => &[2, 1, 0],
        GL_LUMINANCE => &[4],
        GL_LUMINANCE_ALPHA => &[4, 3],
        GL_ALPHA => &[3],
        GL_RED => &[0],
        GL_GREEN => &[1],
        GL_BLUE => &[2],
        GL_DEPTH_COMPONENT | GL_DEPTH_STENCIL | GL_STENCIL_INDEX | GL_COLOR_INDEX => &[0],
        _ => return None,
    })
}

/// A GL 1.2 packed colour type's byte size and its (shift, width) bit field per component
/// of the format, or `None` for any other type.
pub(crate) fn packed_fields(ty: u32) -> Option<(usize, &'static [(u32, u32)])> {
    if is_depth_stencil_type(ty) {
        return None;
    }
    match pixel_type(ty)? {
        Ty::Packed { size, fields } => Some((size, fields)),
        _ => None,
    }
}

/// The checks Mesa's `_mesa_error_check_format_and_type` makes from the type before it
/// looks at the format (glDrawPixels and glReadPixels alike): GL_DEPTH_STENCIL with a type
/// other than 24_8 / FLOAT_32_24_8_REV and GL_BITMAP with a non-index format are
/// GL_INVALID_ENUM; a packed type whose field count does not fit the format (3 fields:
/// GL_RGB; 4: GL_RGBA or GL_BGRA), and a depth-stencil type with another format, are
/// GL_INVALID_OPERATION, even when the format is one softgl (or GL) does not know.
pub(crate) fn check_type_fits_format(format: u32, ty: u32) -> GlResult<()> {
    let ds_type = is_depth_stencil_type(ty);
    if format == GL_DEPTH_STENCIL && !ds_type {
        return Err(GlError::InvalidEnum);
    }
    if ds_type && format != GL_DEPTH_STENCIL {
        return Err(GlError::InvalidOperation);
    }
    if ty == GL_BITMAP && !matches!(format, GL_COLOR_INDEX | GL_STENCIL_INDEX) {
        return Err(GlError::InvalidEnum);
    }
    if let Some((_, fields)) = packed_fields(ty) {
        let fits = match fields.len() {
            3 => format == GL_RGB,
            _ => matches!(format, GL_RGBA | GL_BGRA),
        };
        if !fits {
            return Err(GlError::InvalidOperation);
        }
    }
    Ok(())
}

/// An unsigned integer of `bytes.len()` bytes in native order, byte-swapped first when
/// `swap` (GL_PACK/UNPACK_SWAP_BYTES) and it has more than one byte.
pub(crate) fn read_uint(bytes: &[u8], swap: bool) -> u64 {
    let mut b = [0u8; 8];
    b[..bytes.len()].copy_from_slice(bytes);
    if swap && bytes.len() > 1 {
        b[..bytes.len()].reverse();
    }
    let v = u64::from_ne_bytes(b);
    if cfg!(target_endian = "big") {
        v >> (64 - 8 * bytes.len())
    } else {
        v
    }
}

/// Writes the low `size` bytes of `raw` into `out` in native order, byte-swapped when
/// `swap` and `size` > 1 (the inverse of [`read_uint`]).
pub(crate) fn write_uint(out: &mut [u8], raw: u64, size: usize, swap: bool) {
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
}
