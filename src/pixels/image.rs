//! Client images of glDrawPixels and glBitmap, decoded once (at the call, or when a display
//! list is compiled) into the values Mesa's temporary texture holds: colours as f32 RGBA
//! the way the texture format chosen for the type returns them (8-bit types exactly
//! `u/255`, 16-bit `u/65535`, packed fields `u/(2^n − 1)`, GL_UNSIGNED_INT through a
//! 16-bit texture, floats unclamped), depth as f32, stencil and colour indices as integers,
//! bitmaps as one flag per pixel. Pixel-transfer operations run later, at execution, with
//! the state then current, as Mesa's display lists replay the raw image.

use crate::context::state::PixelStore;
use crate::gl::enums::*;
use crate::gl::error::{GlError, GlResult};

/// What a decoded image holds.
#[derive(Clone, Debug, PartialEq)]
pub enum Pixels {
    /// RGBA colours.
    Color(Vec<[f32; 4]>),
    /// Colour indices (GL_COLOR_INDEX).
    Index(Vec<i64>),
    /// Depth values (GL_DEPTH_COMPONENT).
    Depth(Vec<f32>),
    /// Stencil indices (GL_STENCIL_INDEX).
    Stencil(Vec<i64>),
}

/// A decoded `w` x `h` image, row 0 first (the bottom row).
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Width.
    pub w: usize,
    /// Height.
    pub h: usize,
    /// The values.
    pub pixels: Pixels,
}

#[derive(Clone, Copy, PartialEq, Eq)]
enum Ty {
    Plain {
        size: usize,
        signed: bool,
        float: bool,
    },
    Packed {
        size: usize,
        fields: &'static [(u32, u32)],
    },
    Bitmap,
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
        _ => return None,
    })
}

/// A GL 1.2 packed type's byte size and its (shift, width) bit field per component of
/// the format, or `None` for any other type.
pub(crate) fn packed_fields(ty: u32) -> Option<(usize, &'static [(u32, u32)])> {
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
    use crate::gl::glext_enums::{
        GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, GL_UNSIGNED_INT_24_8,
    };
    let ds_type = matches!(ty, GL_UNSIGNED_INT_24_8 | GL_FLOAT_32_UNSIGNED_INT_24_8_REV);
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

/// Which RGBA channel each component of a colour format is (4 = luminance).
fn components(format: u32) -> Option<&'static [usize]> {
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
        GL_DEPTH_COMPONENT | GL_STENCIL_INDEX | GL_COLOR_INDEX => &[0],
        _ => return None,
    })
}

/// A validated glDrawPixels format and type.
#[derive(Clone, Copy)]
pub struct Layout {
    format: u32,
    comps: &'static [usize],
    ty: Ty,
}

impl Layout {
    /// Mesa's `_mesa_error_check_format_and_type` for glDrawPixels: first the type-based
    /// checks of [`check_type_fits_format`], then unknown names → GL_INVALID_ENUM.
    pub fn new(format: u32, ty: u32) -> GlResult<Layout> {
        check_type_fits_format(format, ty)?;
        let t = pixel_type(ty).ok_or(GlError::InvalidEnum)?;
        let comps = components(format).ok_or(GlError::InvalidEnum)?;
        Ok(Layout {
            format,
            comps,
            ty: t,
        })
    }

    /// The format.
    pub fn format(&self) -> u32 {
        self.format
    }

    /// (start offset, row stride, bytes per pixel) of a `w`-wide image, and the bit size
    /// of one pixel for GL_BITMAP (0 otherwise).
    fn geometry(&self, ps: &PixelStore, w: usize) -> (usize, usize, usize) {
        match self.ty {
            Ty::Bitmap => {
                let row_px = if ps.row_length > 0 {
                    ps.row_length as usize
                } else {
                    w
                };
                let align = ps.alignment.max(1) as usize;
                let stride = row_px.div_ceil(8).div_ceil(align) * align;
                (ps.skip_rows.max(0) as usize * stride, stride, 0)
            }
            Ty::Plain { size, .. } => {
                let bpp = size * self.comps.len();
                let (s, st) = crate::ffi::query::packed_layout(ps, w, bpp, size);
                (s, st, bpp)
            }
            Ty::Packed { size, .. } => {
                let (s, st) = crate::ffi::query::packed_layout(ps, w, size, size);
                (s, st, size)
            }
        }
    }

    /// Bytes from the first byte read to one past the last for `w` x `h` pixels.
    pub fn span(&self, ps: &PixelStore, w: usize, h: usize) -> usize {
        if w == 0 || h == 0 {
            return 0;
        }
        let (start, stride, bpp) = self.geometry(ps, w);
        match self.ty {
            Ty::Bitmap => {
                start + (h - 1) * stride + (ps.skip_pixels.max(0) as usize + w).div_ceil(8)
            }
            _ => start + (h - 1) * stride + w * bpp,
        }
    }

    /// Decodes the image at `data` (GL's contract: `span` readable bytes).
    ///
    /// # Safety
    /// `data` must be null or readable for [`Layout::span`] bytes.
    pub unsafe fn decode(
        &self,
        ps: &PixelStore,
        w: usize,
        h: usize,
        data: *const u8,
    ) -> Option<Image> {
        if data.is_null() {
            return None;
        }
        // SAFETY: the caller guarantees `span` readable bytes.
        let bytes = unsafe { std::slice::from_raw_parts(data, self.span(ps, w, h)) };
        let (start, stride, bpp) = self.geometry(ps, w);
        let n = w * h;
        let pixels = match self.format {
            GL_DEPTH_COMPONENT => {
                let mut v = Vec::with_capacity(n);
                self.each(bytes, ps, w, h, start, stride, bpp, |vals, _| {
                    v.push(depth_value(self.ty, vals[0]))
                });
                Pixels::Depth(v)
            }
            GL_STENCIL_INDEX | GL_COLOR_INDEX => {
                let mut v = Vec::with_capacity(n);
                self.each(bytes, ps, w, h, start, stride, bpp, |vals, raw| {
                    v.push(index_value(self.ty, vals[0], raw))
                });
                if self.format == GL_STENCIL_INDEX {
                    Pixels::Stencil(v)
                } else {
                    Pixels::Index(v)
                }
            }
            _ => {
                let mut v = Vec::with_capacity(n);
                let comps = self.comps;
                let ty = self.ty;
                self.each(bytes, ps, w, h, start, stride, bpp, |vals, _| {
                    let mut c = [0.0, 0.0, 0.0, 1.0];
                    for (k, &ch) in comps.iter().enumerate() {
                        let f = color_value(ty, vals[k], k);
                        if ch == 4 {
                            c[0] = f;
                            c[1] = f;
                            c[2] = f;
                        } else {
                            c[ch] = f;
                        }
                    }
                    v.push(c)
                });
                Pixels::Color(v)
            }
        };
        Some(Image { w, h, pixels })
    }

    /// Calls `f(raw component values, raw bits)` for every pixel, rows bottom first.
    #[allow(clippy::too_many_arguments)]
    fn each<F: FnMut(&[u64; 4], u64)>(
        &self,
        bytes: &[u8],
        ps: &PixelStore,
        w: usize,
        h: usize,
        start: usize,
        stride: usize,
        bpp: usize,
        mut f: F,
    ) {
        let swap = ps.swap_bytes;
        for y in 0..h {
            let row = start + y * stride;
            for x in 0..w {
                let mut vals = [0u64; 4];
                match self.ty {
                    Ty::Bitmap => {
                        let bit = ps.skip_pixels.max(0) as usize + x;
                        let b = bytes[row + bit / 8];
                        let on = if ps.lsb_first {
                            (b >> (bit % 8)) & 1
                        } else {
                            (b >> (7 - bit % 8)) & 1
                        };
                        vals[0] = on as u64;
                        f(&vals, on as u64);
                    }
                    Ty::Plain { size, .. } => {
                        let o = row + x * bpp;
                        for k in 0..self.comps.len() {
                            vals[k] = read_uint(&bytes[o + k * size..o + (k + 1) * size], swap);
                        }
                        f(&vals, vals[0]);
                    }
                    Ty::Packed { size, fields } => {
                        let o = row + x * bpp;
                        let raw = read_uint(&bytes[o..o + size], swap);
                        for (k, &(shift, bits)) in fields.iter().enumerate() {
                            vals[k] = (raw >> shift) & ((1 << bits) - 1);
                        }
                        f(&vals, raw);
                    }
                }
            }
        }
    }
}

fn read_uint(bytes: &[u8], swap: bool) -> u64 {
    let mut b = [0u8; 8];
    b[..bytes.len()].copy_from_slice(bytes);
    if swap && bytes.len() > 1 {
        b[..bytes.len()].reverse();
    }
    u64::from_le_bytes(b)
}

/// A signed value of `bits` bits.
fn signed(raw: u64, bits: u32) -> i64 {
    ((raw << (64 - bits)) as i64) >> (64 - bits)
}

/// The texel value of colour component `k` as Mesa's temporary texture returns it.
fn color_value(ty: Ty, raw: u64, k: usize) -> f32 {
    match ty {
        Ty::Plain { float: true, .. } => f32::from_bits(raw as u32),
        Ty::Plain {
            size: 1,
            signed: false,
            ..
        } => raw as f32 * (1.0 / 255.0),
        Ty::Plain {
            size: 2,
            signed: false,
            ..
        } => raw as f32 * (1.0 / 65535.0),
        // GL_UNSIGNED_INT goes through an RGBA16 texture.
        Ty::Plain { signed: false, .. } => (raw >> 16) as f32 * (1.0 / 65535.0),
        Ty::Plain { size: 1, .. } => (signed(raw, 8) as f32 / 127.0).max(-1.0),
        Ty::Plain { size: 2, .. } => (signed(raw, 16) as f32 / 32767.0).max(-1.0),
        Ty::Plain { .. } => ((signed(raw, 32) >> 16) as f32 / 32767.0).max(-1.0),
        // llvmpipe samples fields of up to 8 bits as bit-replicated 8-bit values.
        Ty::Packed { fields, .. } if fields[k].1 <= 8 => {
            crate::texture::upload::unorm_to_u8(raw, fields[k].1) as f32 * (1.0 / 255.0)
        }
        Ty::Packed { fields, .. } => raw as f32 * (1.0 / ((1u64 << fields[k].1) - 1) as f32),
        Ty::Bitmap => raw as f32,
    }
}

/// A depth value as the depth texture returns it (before depth scale and bias).
fn depth_value(ty: Ty, raw: u64) -> f32 {
    match ty {
        Ty::Plain { float: true, .. } => f32::from_bits(raw as u32),
        Ty::Plain {
            size: 1,
            signed: false,
            ..
        } => raw as f32 / 255.0,
        Ty::Plain {
            size: 2,
            signed: false,
            ..
        } => raw as f32 / 65535.0,
        Ty::Plain {
            size: 4,
            signed: false,
            ..
        } => (raw as f64 / 4_294_967_295.0) as f32,
        Ty::Plain { size: 1, .. } => (signed(raw, 8) as f32 / 127.0).max(0.0),
        Ty::Plain { size: 2, .. } => (signed(raw, 16) as f32 / 32767.0).max(0.0),
        Ty::Plain { .. } => (signed(raw, 32) as f64 / 2_147_483_647.0).max(0.0) as f32,
        _ => 0.0,
    }
}

/// An index value (stencil or colour index) before the index shift and offset.
fn index_value(ty: Ty, raw: u64, _bits: u64) -> i64 {
    match ty {
        Ty::Plain { float: true, .. } => f32::from_bits(raw as u32) as i64,
        Ty::Plain {
            size, signed: true, ..
        } => signed(raw, 8 * size as u32),
        _ => raw as i64,
    }
}
