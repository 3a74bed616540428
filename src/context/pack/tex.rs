//! Texture image unpacking and packing (glTexImage, glTexSubImage, glGetTexImage): client
//! formats and types into RGBA8 texels, and back.
//!
//! Every component becomes an 8-bit unorm value the way Mesa's `_mesa_format_convert`
//! (`main/format_utils.h`) does it; verified against Mesa 22.3 with glGetTexImage:
//! - GL_FLOAT: clamp to [0,1], `round_half_even(v·255)` (`_mesa_float_to_unorm`);
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

use super::{components, packed_layout, pixel_type, read_uint, write_uint, Ty};
use crate::context::pixel_transfer::{PixelMaps, PixelTransfer};
use crate::context::state::PixelStore;
use crate::gl::enums::*;
use crate::gl::error::{GlError, GlResult};
use crate::gl::glext_enums::{
    GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, GL_HALF_FLOAT, GL_RG, GL_UNSIGNED_INT_24_8,
};
use crate::texture::upload::{float_to_bits_u8, quantise_u8, unorm_to_u8};
use crate::texture::{BaseFormat, Level, Storage};

pub use super::tex_format::{base_format, choose_storage};
/// The storage conversions glTexImage and glCopyTexImage use with these.
pub use crate::texture::upload::{quantise_rgba, to_texel};

/// A validated client pixel layout.
#[derive(Clone, Copy, Debug)]
pub struct ClientFormat {
    pub(super) comps: &'static [usize],
    pub(super) ty: Ty,
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
        // GL_RG (GL_ARB_texture_rg) and GL_HALF_FLOAT (GL_ARB_half_float_pixel) are
        // texture image formats only here
        let comps = components(format)
            .or_else(|| (format == GL_RG).then_some(&[0usize, 1][..]))
            .filter(|_| !matches!(format, GL_STENCIL_INDEX | GL_COLOR_INDEX))
            .ok_or(GlError::InvalidEnum)?;
        let t = pixel_type(ty)
            .or_else(|| (ty == GL_HALF_FLOAT).then_some(super::tex_float::HALF))
            .filter(|t| *t != Ty::Bitmap)
            .ok_or(GlError::InvalidEnum)?;
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
            // refused by `new`
            Ty::Bitmap => (0, 1),
        }
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
                        Component::Float(super::tex_float::float_of(raw, size))
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
        // refused by `ClientFormat::new`
        Ty::Bitmap => {}
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
pub(super) fn decode_pixel_f32(cf: &ClientFormat, px: &[u8], swap: bool) -> [f32; 4] {
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
        let (start, stride) = packed_layout(ps, width, bpp, elem);
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
        BaseFormat::Red => [t[0], 0, 0, 255],
        BaseFormat::Rg => [t[0], t[1], 0, 255],
        // depth images are read back by `depth::pack`
        BaseFormat::Depth => [0, 0, 0, 255],
    }
}

fn encode_u8(v: u8, ty: Ty, out: &mut [u8], swap: bool) {
    if let Ty::Plain {
        size,
        signed,
        float,
    } = ty
    {
        let raw: u64 = if float {
            super::tex_float::float_bits(v as f32 * (1.0 / 255.0), size)
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
        write_uint(out, raw, size, swap);
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
            let o = lay.start + y * lay.stride + x * lay.bpp;
            let px = &mut bytes[o..o + lay.bpp];
            if let Some(f) = &img.floats {
                super::tex_float::pack_pixel(cf, img.base, f[y * w + x], px, ps.swap_bytes);
                continue;
            }
            let rgba = readback_rgba(img.base, img.texel(x, y));
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
                    write_uint(px, raw, size, ps.swap_bytes);
                }
                // refused by `ClientFormat::new`
                Ty::Bitmap => {}
            }
        }
    }
}

#[cfg(test)]
#[path = "tex_tests.rs"]
mod tests;
