//! Client images of glDrawPixels and glBitmap (and colour-index texture images), decoded
//! once (at the call, or when a display list is compiled) into the values Mesa's
//! temporary texture holds: colours as f32 RGBA the way the texture format chosen for the
//! type returns them (8-bit types exactly `u/255`, 16-bit `u/65535`, packed fields
//! `u/(2^n − 1)`, GL_UNSIGNED_INT through a 16-bit texture, floats unclamped), depth as
//! f32, stencil and colour indices as integers, bitmaps as one flag per pixel.
//! Pixel-transfer operations run later, at execution, with the state then current, as
//! Mesa's display lists replay the raw image.

use super::{check_type_fits_format, components, packed_layout, pixel_type, read_uint, Ty};
use crate::context::state::PixelStore;
use crate::gl::enums::*;
use crate::gl::error::{GlError, GlResult};
use crate::gl::glext_enums::GL_DEPTH_STENCIL;
use crate::pixels::image::{Image, Pixels};
use crate::texture::upload::unorm_to_u8;

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
        // (the depth-stencil types are for glReadPixels and textures only)
        if format == GL_DEPTH_STENCIL {
            return Err(GlError::InvalidEnum);
        }
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
                let (s, st) = packed_layout(ps, w, bpp, size);
                (s, st, bpp)
            }
            Ty::Packed { size, .. } => {
                let (s, st) = packed_layout(ps, w, size, size);
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
                let unorm8 = Ty::Plain {
                    size: 1,
                    signed: false,
                    float: false,
                };
                if ty == unorm8 && bpp == comps.len() {
                    // The common bytes, read a row slice at a time (the values of
                    // `color_value`).
                    const K: f32 = 1.0 / 255.0;
                    for y in 0..h {
                        let row = &bytes[start + y * stride..][..w * bpp];
                        if comps == [0, 1, 2, 3] {
                            // RGBA and RGB, the common cases, without the per-channel branch
                            // (which kept the loop from vectorising: 9% of
                            // pushattrib_pixels).
                            v.extend(row.chunks_exact(4).map(|px| {
                                [
                                    px[0] as f32 * K,
                                    px[1] as f32 * K,
                                    px[2] as f32 * K,
                                    px[3] as f32 * K,
                                ]
                            }));
                            continue;
                        }
                        if comps == [0, 1, 2] {
                            v.extend(row.chunks_exact(3).map(|px| {
                                [px[0] as f32 * K, px[1] as f32 * K, px[2] as f32 * K, 1.0]
                            }));
                            continue;
                        }
                        v.extend(row.chunks_exact(bpp).map(|px| {
                            let mut c = [0.0, 0.0, 0.0, 1.0];
                            for (&ch, &b) in comps.iter().zip(px) {
                                let f = b as f32 * K;
                                if ch == 4 {
                                    c[..3].fill(f);
                                } else {
                                    c[ch] = f;
                                }
                            }
                            c
                        }));
                    }
                    return Some(Image {
                        w,
                        h,
                        pixels: Pixels::Color(v),
                    });
                }
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
            unorm_to_u8(raw, fields[k].1) as f32 * (1.0 / 255.0)
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
