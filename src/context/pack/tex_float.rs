//! Unpacking into and packing from float and 16-bit texture images (GL_ARB_texture_float,
//! GL_ARB_texture_rg's R16 … RG32F; see `texture::float`), and GL_HALF_FLOAT
//! (GL_ARB_half_float_pixel) client data.
//!
//! - Upload: each client pixel becomes RGBA float as for the other formats
//!   (`tex::decode_pixel_f32`: unorm `x·f32(1/max)`, floats as given, half floats exact),
//!   goes through the pixel transfer, and is stored in the image's precision
//!   (`texture::float::quantise`) after the base swizzle.
//! - Readback (glGetTexImage): the value rebased as Mesa reads an image back
//!   (luminance and intensity to (L, 0, 0, 1), alpha to (0, 0, 0, A), missing colour 0 and
//!   alpha 1), then Mesa's `_mesa_format_convert` into the client type: floats as they
//!   are, half floats rounded to nearest even (`_mesa_float_to_half`), unsigned types
//!   `_mesa_float_to_unorm` (clamped, `round_half_even(x·max)` in f32), signed ones
//!   `_mesa_float_to_snorm`.

use super::tex::{decode_pixel_f32, ClientFormat, ColorTransfer, Layout};
use super::{write_uint, Ty};
use crate::context::state::PixelStore;
use crate::gl::enums::{GL_FLOAT, GL_UNSIGNED_BYTE};
use crate::texture::float::{half_rne, half_to_f32, quantise_rounding};
use crate::texture::{BaseFormat, Storage};

/// The pixel type of GL_HALF_FLOAT: one 2-byte float per component.
pub(crate) const HALF: Ty = Ty::Plain {
    size: 2,
    signed: false,
    float: true,
};

/// The value of a client float component of `size` bytes (4: f32, 2: binary16).
#[inline]
pub(crate) fn float_of(raw: u64, size: usize) -> f32 {
    if size == 2 {
        half_to_f32(raw as u16)
    } else {
        f32::from_bits(raw as u32)
    }
}

/// The client bits of float `v` as a component of `size` bytes.
#[inline]
pub(crate) fn float_bits(v: f32, size: usize) -> u64 {
    if size == 2 {
        half_rne(v) as u64
    } else {
        v.to_bits() as u64
    }
}

/// Mesa's `_mesa_float_to_unorm(x, bits)`: f32 arithmetic, the product rounded to even
/// as a 64-bit integer (and cut to the type).
fn float_to_unorm(x: f32, bits: u32) -> u64 {
    let max = if bits == 64 {
        u64::MAX
    } else {
        (1u64 << bits) - 1
    };
    if x < 0.0 || x.is_nan() {
        0
    } else if x > 1.0 {
        max
    } else {
        ((x * max as f32).round_ties_even() as i64 as u64) & max
    }
}

/// Mesa's `_mesa_float_to_snorm(x, bits)`, as the type's bit pattern.
fn float_to_snorm(x: f32, bits: u32) -> u64 {
    let max = (1i64 << (bits - 1)) - 1;
    let v = if x.is_nan() {
        0
    } else if x < -1.0 {
        -max
    } else if x > 1.0 {
        max
    } else {
        (x * max as f32).round_ties_even() as i64
    };
    (v as u64) & ((1u64 << (bits - 1) << 1).wrapping_sub(1))
}

/// The RGBA value glGetTexImage starts from for a texel of `base` (see the module doc).
fn readback(base: BaseFormat, t: [f32; 4]) -> [f32; 4] {
    match base {
        BaseFormat::Alpha => [0.0, 0.0, 0.0, t[3]],
        BaseFormat::Luminance | BaseFormat::Intensity => [t[0], 0.0, 0.0, 1.0],
        BaseFormat::LuminanceAlpha => [t[0], 0.0, 0.0, t[3]],
        BaseFormat::Rgb => [t[0], t[1], t[2], 1.0],
        BaseFormat::Red => [t[0], 0.0, 0.0, 1.0],
        BaseFormat::Rg => [t[0], t[1], 0.0, 1.0],
        BaseFormat::Rgba | BaseFormat::Depth => t,
    }
}

/// Packs the float texel `t` of an image of `base` as one client pixel `px`.
pub(super) fn pack_pixel(
    cf: &ClientFormat,
    base: BaseFormat,
    t: [f32; 4],
    px: &mut [u8],
    swap: bool,
) {
    let rgba = readback(base, t);
    let comp = |c: usize| if c == 4 { rgba[0] } else { rgba[c] };
    match cf.ty {
        Ty::Plain {
            size,
            signed,
            float,
        } => {
            for (i, &c) in cf.comps.iter().enumerate() {
                let v = comp(c);
                let raw = if float {
                    float_bits(v, size)
                } else if signed {
                    float_to_snorm(v, 8 * size as u32)
                } else {
                    float_to_unorm(v, 8 * size as u32)
                };
                write_uint(&mut px[i * size..(i + 1) * size], raw, size, swap);
            }
        }
        Ty::Packed { size, fields } => {
            let mut raw = 0u64;
            for (&c, &(shift, bits)) in cf.comps.iter().zip(fields) {
                raw |= float_to_unorm(comp(c), bits) << shift;
            }
            write_uint(px, raw, size, swap);
        }
        // refused by `ClientFormat::new`
        Ty::Bitmap => {}
    }
}

/// Unpacks a `w` x `h` client image into the float values of an image of `base` stored as
/// `storage`, with the pixel transfer `tr`.
///
/// # Safety
/// `data` must be null or readable for `Layout::span(w, h)` bytes.
pub unsafe fn unpack(
    ps: &PixelStore,
    cf: &ClientFormat,
    (base, storage): (BaseFormat, Storage),
    (w, h): (usize, usize),
    data: *const u8,
    tr: Option<ColorTransfer<'_>>,
) -> Vec<[f32; 4]> {
    let lay = Layout::new(ps, w, cf);
    // Mesa uploads GL_RGBA/GL_BGRA float and unsigned-byte data by a blit (whose half
    // conversion truncates) and the rest on the CPU (`_mesa_float_to_half`, to nearest
    // even): measured on every 16F format with RGBA, RG, RED, RGB and LUMINANCE data of
    // GL_FLOAT, GL_UNSIGNED_SHORT and GL_UNSIGNED_BYTE
    let blit = cf.comps.len() == 4
        && cf.comps[3] == 3
        && matches!(cf.gl_type, GL_FLOAT | GL_UNSIGNED_BYTE);
    let store = |c: [f32; 4]| quantise_rounding(&storage, base.swizzle(c, 0.0, 1.0), blit);
    if data.is_null() || w == 0 || h == 0 {
        return vec![store([0.0; 4]); w * h];
    }
    // SAFETY: the caller guarantees `span` readable bytes.
    let bytes = unsafe { std::slice::from_raw_parts(data, lay.span(w, h)) };
    let mut out = Vec::with_capacity(w * h);
    for y in 0..h {
        let row = lay.start + y * lay.stride;
        for x in 0..w {
            let px = &bytes[row + x * lay.bpp..][..lay.bpp];
            let c = decode_pixel_f32(cf, px, ps.swap_bytes);
            out.push(store(tr.map_or(c, |t| t.apply(c))));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::float::half_rtz;

    #[test]
    fn half_rne_rounds_to_nearest_even() {
        assert_eq!(half_rne(0.3), 0x34cd);
        assert_eq!(half_rtz(0.3), 0x34cc);
        assert_eq!(half_rne(1.0), 0x3c00);
        assert_eq!(half_rne(65519.0), 0x7bff);
        assert_eq!(half_rne(65520.0), 0x7c00);
        assert_eq!(half_rne(1e-6), 17);
        assert_eq!(half_rne(-2.0), 0xc000);
        for h in 0..0x7c00u16 {
            assert_eq!(half_rne(half_to_f32(h)), h, "{h:#x}");
        }
    }

    #[test]
    fn unorm_and_snorm_as_mesa() {
        assert_eq!(float_to_unorm(0.1, 8), 26);
        assert_eq!(float_to_unorm(2.5, 16), 65535);
        assert_eq!(float_to_unorm(-0.75, 16), 0);
        assert_eq!(float_to_snorm(-0.75, 8), (-95i64 as u64) & 0xff);
        assert_eq!(float_to_snorm(3.0, 16), 32767);
    }
}
