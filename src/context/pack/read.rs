//! glReadPixels: the framebuffer packed into client memory, as Mesa's `readpix.c` does
//! it (its fast paths without pixel transfer, its float path with it).

use super::packed_layout;
use crate::context::error::{GlError, GlResult};
use crate::context::pixel_transfer::stencil_transfer;
use crate::context::state::PixelStore;
use crate::context::Context;
use crate::framebuffer::{float_to_ubyte, DepthFormat};
use crate::gl::enums::*;
use crate::gl::glext_enums::{
    GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, GL_UNSIGNED_INT_24_8,
};
use crate::texture::shadow;

/// What one packed pixel holds.
#[derive(Clone, Copy, PartialEq)]
enum ReadKind {
    /// Colour channels as indices into RGBA (`usize::MAX` = luminance sum), count.
    Color([usize; 4], usize),
    Depth,
    Stencil,
    /// GL_DEPTH_STENCIL: GL_UNSIGNED_INT_24_8 or GL_FLOAT_32_UNSIGNED_INT_24_8_REV.
    DepthStencil,
}

/// The bytes glReadPixels writes, from the first to one past the last, for a `w` x `h`
/// image in `format`/`ty` under the pack state `ps` (0 when the arguments describe no
/// image: the call fails on them). What a pack buffer's range must hold.
pub fn read_span(ps: &PixelStore, (format, ty): (u32, u32), w: i32, h: i32) -> usize {
    let (Ok(w), Ok(h)) = (usize::try_from(w), usize::try_from(h)) else {
        return 0;
    };
    if w == 0 || h == 0 {
        return 0;
    }
    if format == GL_DEPTH_STENCIL {
        let bpp = match ty {
            GL_UNSIGNED_INT_24_8 => 4,
            GL_FLOAT_32_UNSIGNED_INT_24_8_REV => 8,
            _ => return 0,
        };
        let (start, stride) = packed_layout(ps, w, bpp, 4);
        return start + (h - 1) * stride + w * bpp;
    }
    super::draw_image::Layout::new(format, ty).map_or(0, |l| l.span(ps, w, h))
}

/// glReadPixels: reads a rectangle of the framebuffer (bottom row first) into `out`
/// with the pack parameters and the pixel-transfer state; pixels outside the framebuffer
/// are left unwritten.
///
/// # Safety
/// `out` must be null or writable for the packed image (GL's contract with the program).
#[allow(clippy::too_many_arguments)]
pub unsafe fn read_pixels(
    c: &mut Context,
    x: i32,
    y: i32,
    w: i32,
    h: i32,
    format: u32,
    ty: u32,
    out: *mut u8,
) -> GlResult<()> {
    crate::context::pixel_ops::bitmap_cache::flush(c);
    if w < 0 || h < 0 {
        return Err(GlError::InvalidValue);
    }
    // Mesa's `_mesa_error_check_format_and_type` looks at the type before the format.
    super::check_type_fits_format(format, ty)?;
    let ds_type = format == GL_DEPTH_STENCIL;
    let packed = super::packed_fields(ty).filter(|_| !ds_type);
    let kind = match format {
        GL_RGBA => ReadKind::Color([0, 1, 2, 3], 4),
        GL_RGB => ReadKind::Color([0, 1, 2, 0], 3),
        GL_BGRA => ReadKind::Color([2, 1, 0, 3], 4),
        GL_BGR => ReadKind::Color([2, 1, 0, 0], 3),
        GL_RED => ReadKind::Color([0, 0, 0, 0], 1),
        GL_GREEN => ReadKind::Color([1, 0, 0, 0], 1),
        GL_BLUE => ReadKind::Color([2, 0, 0, 0], 1),
        GL_ALPHA => ReadKind::Color([3, 0, 0, 0], 1),
        GL_LUMINANCE => ReadKind::Color([usize::MAX, 0, 0, 0], 1),
        GL_LUMINANCE_ALPHA => ReadKind::Color([usize::MAX, 3, 0, 0], 2),
        GL_DEPTH_COMPONENT => ReadKind::Depth,
        GL_STENCIL_INDEX => ReadKind::Stencil,
        GL_DEPTH_STENCIL => ReadKind::DepthStencil,
        _ => return Err(GlError::InvalidEnum),
    };
    let tsize = match (ty, packed) {
        (_, Some((size, _))) => size,
        (GL_UNSIGNED_BYTE | GL_BYTE, _) => 1,
        (GL_UNSIGNED_SHORT | GL_SHORT, _) => 2,
        (GL_UNSIGNED_INT | GL_INT | GL_FLOAT, _) => 4,
        _ if ds_type => 4,
        _ => return Err(GlError::InvalidEnum),
    };
    c.prepare_read()?;
    if matches!(kind, ReadKind::Color(..)) && !c.reads_color() {
        // glReadBuffer(GL_NONE): no colour buffer to read.
        return Err(GlError::InvalidOperation);
    }
    let Some(fb) = c.read_fb() else {
        return Ok(());
    };
    match kind {
        ReadKind::Depth if fb.depth.is_empty() => return Err(GlError::InvalidOperation),
        ReadKind::Stencil if fb.stencil.is_empty() => return Err(GlError::InvalidOperation),
        ReadKind::DepthStencil if fb.depth.is_empty() || fb.stencil.is_empty() => {
            return Err(GlError::InvalidOperation)
        }
        _ => {}
    }
    if out.is_null() {
        return Ok(());
    }
    let comps = match kind {
        ReadKind::Color(_, n) if packed.is_none() => n,
        ReadKind::DepthStencil if ty != GL_UNSIGNED_INT_24_8 => 2,
        _ => 1,
    };
    let swap = c.state.pack.swap_bytes && tsize > 1;
    // Pixel transfer sends Mesa down its CPU path (`readpix.c`, `read_rgba_pixels`):
    // unorm8 → float, scale and bias, the colour maps, then float → the packed type.
    let tr = c.pixel_modes.transfer;
    let maps = &c.pixel_maps;
    let transfer = tr.scale_bias() || tr.map_color;
    let stencil_ops = tr.index_shift != 0 || tr.index_offset != 0 || tr.map_stencil;
    let depth_scale_bias = tr.depth_scale_bias();
    let bpp = comps * tsize;
    let (start, stride) = packed_layout(&c.state.pack, w as usize, bpp, tsize);
    let base = c.read_color_base();
    let color_at = |idx: usize| base.read_rebase(fb.color_at(idx));
    // The colour as floats: a wide buffer's at its own precision, else unorm8 to float
    // as Mesa's unpack does (u · f32(1/255)).
    let float_at = |idx: usize| match fb.wide {
        Some(k) => base
            .read_rebase_wide(fb.wide_at(idx), k.one())
            .map(|v| k.to_float(v)),
        None => color_at(idx).map(|u| u as f32 * (1.0f32 / 255.0)),
    };
    let put = |p: *mut u8, v: f64, norm: bool| {
        // `v` written at `p` as a `$t`: scaled from [`$lo`, 1] to the type's range when
        // `norm`, converted as it is otherwise.
        macro_rules! write_as {
            ($t:ty, $lo:expr) => {
                (p as *mut $t).write_unaligned(if norm {
                    (v.clamp($lo, 1.0) * <$t>::MAX as f64).round() as $t
                } else {
                    v as $t
                })
            };
        }
        // SAFETY: the program promises a destination large enough for the packed image.
        unsafe {
            match ty {
                GL_UNSIGNED_BYTE => write_as!(u8, 0.0),
                GL_BYTE => write_as!(i8, -1.0),
                GL_UNSIGNED_SHORT => write_as!(u16, 0.0),
                GL_SHORT => write_as!(i16, -1.0),
                GL_UNSIGNED_INT => write_as!(u32, 0.0),
                GL_INT => write_as!(i32, -1.0),
                _ => (p as *mut f32).write_unaligned(v as f32),
            }
        }
    };
    // Row paths for the common reads (the same bytes as the loop below).
    let dest = super::read_fast::Dest {
        rect: [x as i64, y as i64, w as i64, h as i64],
        start,
        stride,
    };
    if !transfer && !swap && packed.is_none() {
        match kind {
            // SAFETY: `out` is writable for the packed image (this function's contract).
            ReadKind::Color(map, n) if ty == GL_UNSIGNED_BYTE => unsafe {
                if super::read_fast::color_u8(fb, base, map, n, dest, out) {
                    return Ok(());
                }
            },
            // SAFETY: as above.
            ReadKind::Depth if ty == GL_FLOAT && depth_scale_bias.is_none() => unsafe {
                super::read_fast::depth_f32(fb, dest, out);
                return Ok(());
            },
            _ => {}
        }
    }
    for row in 0..h as usize {
        let gy = y as i64 + row as i64;
        if gy < 0 || gy >= fb.height as i64 {
            continue;
        }
        let fy = fb.row(gy as usize);
        for col in 0..w as usize {
            let gx = x as i64 + col as i64;
            if gx < 0 || gx >= fb.width as i64 {
                continue;
            }
            let idx = fy * fb.width + gx as usize;
            // SAFETY: pointer arithmetic within the packed image the program provided.
            let p = unsafe { out.add(start + row * stride + col * bpp) };
            match kind {
                ReadKind::Color(map, _) if packed.is_some() => {
                    let (size, fields) = packed.unwrap_or_default();
                    let bits = if transfer {
                        let mut rgba = tr.apply_scale_bias(float_at(idx));
                        if tr.map_color {
                            rgba = maps.map_rgba(rgba);
                        }
                        encode_packed(fields, map, |ch, n| float_to_unorm(rgba[ch], n))
                    } else {
                        let px = color_at(idx);
                        encode_packed(fields, map, |ch, n| unorm8_to_unorm(px[ch], n))
                    };
                    let mut bytes = bits.to_ne_bytes();
                    if swap {
                        bytes[..size].reverse();
                    }
                    // SAFETY: `size` == bpp bytes of this pixel, inside the packed image.
                    unsafe { std::ptr::copy_nonoverlapping(bytes.as_ptr(), p, size) };
                }
                ReadKind::Color(map, n) if transfer => {
                    let mut rgba = tr.apply_scale_bias(float_at(idx));
                    if tr.map_color {
                        rgba = maps.map_rgba(rgba);
                    }
                    for (k, &ch) in map.iter().take(n).enumerate() {
                        let v = if ch == usize::MAX {
                            (rgba[0] + rgba[1] + rgba[2]).clamp(0.0, 1.0)
                        } else {
                            rgba[ch]
                        };
                        // SAFETY: k * tsize < bpp, inside the packed image.
                        let q = unsafe { p.add(k * tsize) };
                        match ty {
                            // SAFETY: as above.
                            GL_UNSIGNED_BYTE => unsafe { *q = float_to_ubyte(v) },
                            _ => put(q, v as f64, ty != GL_FLOAT),
                        }
                    }
                }
                // SAFETY: `p` addresses this pixel's `n * tsize` bytes of the packed image.
                ReadKind::Color(map, n) if fb.wide.is_some() => unsafe {
                    super::wide::read_wide_pixel(fb, idx, base, map, n, ty, p, tsize, put)
                },
                ReadKind::Color(map, n) => {
                    let px = color_at(idx);
                    for (k, &ch) in map.iter().take(n).enumerate() {
                        // SAFETY: k * tsize < bpp.
                        let q = unsafe { p.add(k * tsize) };
                        if ty == GL_UNSIGNED_BYTE && ch != usize::MAX {
                            // SAFETY: as above.
                            unsafe { *q = px[ch] };
                        } else {
                            // unorm8 to float as Mesa's unpack does: u * f32(1/255).
                            let f = |u: u8| u as f32 * (1.0f32 / 255.0);
                            let v = if ch == usize::MAX {
                                (f(px[0]) + f(px[1]) + f(px[2])).min(1.0) as f64
                            } else {
                                f(px[ch]) as f64
                            };
                            put(q, v, true);
                        }
                    }
                }
                ReadKind::Depth => {
                    let z = fb.depth_at(idx);
                    match (ty, fb.depth_format, depth_scale_bias) {
                        // Mesa's `read_uint_depth_pixels`: the stored bits replicated
                        (GL_UNSIGNED_INT, DepthFormat::Z24, None) => {
                            put(p, ((z << 8) | (z >> 16)) as f64, false)
                        }
                        (GL_UNSIGNED_INT, DepthFormat::Z16, None) => {
                            put(p, ((z << 16) | z) as f64, false)
                        }
                        (GL_UNSIGNED_INT, DepthFormat::Z32, None) => put(p, z as f64, false),
                        // otherwise `read_depth_pixels`: float, scale and bias, pack
                        (_, format, sb) => {
                            let mut d = shadow::readback(z, format.texel_bits());
                            if let Some((scale, bias)) = sb {
                                d = (d * scale + bias).clamp(0.0, 1.0);
                            }
                            let (v, n) = super::depth::pack_depth(d, ty);
                            // SAFETY: n == tsize bytes of this pixel, inside the image.
                            unsafe { std::ptr::copy_nonoverlapping(v.as_ptr(), p, n) };
                        }
                    }
                }
                ReadKind::Stencil if stencil_ops => {
                    // Mesa's `_mesa_apply_stencil_transfer_ops` on the 8-bit values.
                    let s = stencil_transfer(&tr, maps, fb.stencil[idx] as i64) as u8;
                    put(p, s as f64, false)
                }
                ReadKind::Stencil => put(p, fb.stencil[idx] as f64, false),
                ReadKind::DepthStencil => {
                    let mut s = fb.stencil[idx];
                    if stencil_ops {
                        s = stencil_transfer(&tr, maps, s as i64) as u8;
                    }
                    let fast = !stencil_ops && depth_scale_bias.is_none();
                    for (k, word) in depth_stencil_words(fb, idx, s, ty, fast, depth_scale_bias)
                        .iter()
                        .enumerate()
                        .take(comps)
                    {
                        let mut b = word.to_ne_bytes();
                        if swap {
                            b.reverse();
                        }
                        // SAFETY: 4·k < bpp bytes of this pixel, inside the packed image.
                        unsafe { std::ptr::copy_nonoverlapping(b.as_ptr(), p.add(4 * k), 4) };
                    }
                }
            }
            if swap && packed.is_none() && matches!(kind, ReadKind::Color(..)) {
                // GL_PACK_SWAP_BYTES: Mesa swaps every component of the packed image
                // (`_mesa_swap_bytes_2d_image`).
                // SAFETY: `p` addresses this pixel's `bpp` bytes of the packed image.
                let px = unsafe { std::slice::from_raw_parts_mut(p, bpp) };
                for comp in px.chunks_exact_mut(tsize) {
                    comp.reverse();
                }
            }
        }
    }
    Ok(())
}

/// One GL_DEPTH_STENCIL pixel of glReadPixels (stencil `s` already transferred), as
/// Mesa's `read_depth_stencil_pixels`: a Z24 buffer read as GL_UNSIGNED_INT_24_8 without
/// transfer or byte swapping is copied (`z24 << 8 | s`); otherwise the depth is read as
/// float (`_mesa_unpack_float_z_row`), scaled, biased and clamped, and packed by
/// `_mesa_pack_depth_stencil_span`: `(GLuint)(d·f32(0xffffff)) << 8 | s`, or the float
/// and then `s` in a second word.
fn depth_stencil_words(
    fb: &crate::framebuffer::Framebuffer,
    idx: usize,
    s: u8,
    ty: u32,
    fast: bool,
    scale_bias: Option<(f32, f32)>,
) -> [u32; 2] {
    let z = fb.depth_at(idx);
    let s = s as u32;
    let z24 = ty == GL_UNSIGNED_INT_24_8;
    if z24 && fast && fb.depth_format == DepthFormat::Z24 {
        return [z << 8 | s, 0];
    }
    let mut d = shadow::readback(z, fb.depth_format.texel_bits());
    if let Some((scale, bias)) = scale_bias {
        d = (d * scale + bias).clamp(0.0, 1.0);
    }
    if z24 {
        [((d * 16_777_215.0) as u32) << 8 | s, 0]
    } else {
        [d.to_bits(), s]
    }
}

/// One pixel of a GL 1.2 packed type: component `k` of the format (RGBA channel `map[k]`)
/// goes into bit field `fields[k]`, converted by `conv(channel, width)`.
fn encode_packed(fields: &[(u32, u32)], map: [usize; 4], conv: impl Fn(usize, u32) -> u32) -> u32 {
    fields
        .iter()
        .zip(map)
        .fold(0, |acc, (&(shift, n), ch)| acc | conv(ch, n) << shift)
}

/// Mesa's `_mesa_unorm_to_unorm` from 8 bits: narrower fields round
/// (`(u * max + 127) / 255`), wider ones replicate the high bits.
fn unorm8_to_unorm(u: u8, n: u32) -> u32 {
    let u = u as u32;
    match n {
        0..=7 => (u * ((1 << n) - 1) + 127) / 255,
        8 => u,
        _ => (u << (n - 8)) | (u >> (16 - n)),
    }
}

/// Float to a packed field after pixel transfer. GL_UNSIGNED_INT_8_8_8_8(_REV) are array
/// formats to Mesa and go through `_mesa_float_to_unorm` (round half to even); the other
/// packed formats through util_format's pack, `util_iround(CLAMP(v, 0, 1) * max)`.
fn float_to_unorm(v: f32, n: u32) -> u32 {
    let x = v.clamp(0.0, 1.0) * ((1u32 << n) - 1) as f32;
    if n == 8 {
        x.round_ties_even() as u32
    } else {
        (x + 0.5) as u32
    }
}
