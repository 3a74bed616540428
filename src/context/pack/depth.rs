//! Depth and depth-stencil texture images (GL_ARB_depth_texture,
//! GL_EXT_packed_depth_stencil, GL_ARB_depth_buffer_float): the depth bits Mesa stores
//! for an internal format, client depth values unpacked into depth texels (with
//! GL_DEPTH_SCALE/BIAS), stencil indices of packed images, and glGetTexImage's packing.
//! The texel encoding itself is [`crate::texture::shadow`]'s.

use super::tex::{ClientFormat, Layout};
use crate::context::state::PixelStore;
use crate::gl::enums::*;
use crate::gl::glext_enums::{
    GL_DEPTH24_STENCIL8, GL_DEPTH32F_STENCIL8, GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT24,
    GL_DEPTH_COMPONENT32, GL_DEPTH_COMPONENT32F, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8,
};
use crate::texture::shadow::{readback, store, texel_z, FLOAT_BITS};
use crate::texture::Level;

/// The depth-texel conversions texture specification uses with these.
pub use crate::texture::shadow::{convert, convert_scaled, depth_size, texel};

/// Depth bits Mesa stores for a depth internal format given with client type `ty` (0 for
/// a copy).
pub fn depth_bits(internal: u32, ty: u32) -> u8 {
    match internal {
        GL_DEPTH_COMPONENT32F | GL_DEPTH32F_STENCIL8 => FLOAT_BITS,
        GL_DEPTH_STENCIL | GL_DEPTH24_STENCIL8 => 24,
        GL_DEPTH_COMPONENT16 => 16,
        GL_DEPTH_COMPONENT24 => 24,
        GL_DEPTH_COMPONENT32 => 32,
        _ => match ty {
            GL_UNSIGNED_SHORT => 16,
            GL_UNSIGNED_INT => 32,
            _ => 24,
        },
    }
}

/// Whether a glTexImage internal format is a packed depth-stencil one (GL_DEPTH_STENCIL,
/// GL_DEPTH24_STENCIL8: stored as Z24 with 8 stencil bits, GL_TEXTURE_DEPTH_SIZE 24,
/// GL_TEXTURE_STENCIL_SIZE 8, measured; GL_DEPTH32F_STENCIL8: float depth, 32 and 8).
pub fn is_depth_stencil(internal: u32) -> bool {
    matches!(
        internal,
        GL_DEPTH_STENCIL | GL_DEPTH24_STENCIL8 | GL_DEPTH32F_STENCIL8
    )
}

/// An integer client depth value that some stores take without the float detour
/// (`_mesa_unpack_depth_span`'s special cases).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Exact {
    /// None applies.
    No,
    /// A GL_UNSIGNED_SHORT value (kept as is by a 16-bit store).
    U16(u32),
    /// A GL_UNSIGNED_INT value (kept as is by a 32-bit store).
    U32(u32),
    /// The 24 depth bits of a GL_UNSIGNED_INT_24_8 value (kept by a 24-bit store).
    Z24(u32),
}

/// Reads the client depth value at `b` of type `ty` as a float (signed types may be
/// negative: the store clamps) and, for the exact paths, the raw integer.
fn client_value(b: &[u8], ty: u32, swap: bool) -> (f32, Exact) {
    let mut raw = [0u8; 4];
    let n = match ty {
        GL_UNSIGNED_BYTE | GL_BYTE => 1,
        GL_UNSIGNED_SHORT | GL_SHORT => 2,
        _ => 4,
    };
    raw[..n].copy_from_slice(&b[..n]);
    if swap {
        raw[..n].reverse();
    }
    match ty {
        GL_UNSIGNED_BYTE => (raw[0] as f32 * (1.0 / 255.0), Exact::No),
        GL_BYTE => (raw[0] as i8 as f32 * (1.0 / 127.0), Exact::No),
        GL_UNSIGNED_SHORT => {
            let v = u16::from_ne_bytes([raw[0], raw[1]]);
            (v as f32 * (1.0 / 65535.0), Exact::U16(v as u32))
        }
        GL_SHORT => {
            let v = i16::from_ne_bytes([raw[0], raw[1]]);
            (v as f32 * (1.0 / 32767.0), Exact::No)
        }
        GL_UNSIGNED_INT => {
            let v = u32::from_ne_bytes(raw);
            ((v as f64 * (1.0 / 4294967295.0)) as f32, Exact::U32(v))
        }
        GL_UNSIGNED_INT_24_8 => {
            let z = u32::from_ne_bytes(raw) >> 8;
            (z as f32 * (1.0f32 / 16777215.0), Exact::Z24(z))
        }
        GL_INT => {
            let v = i32::from_ne_bytes(raw);
            ((v as f64 * (1.0 / 2147483647.0)) as f32, Exact::No)
        }
        _ => (f32::from_ne_bytes(raw), Exact::No),
    }
}

/// Unpacks a `w x h` client depth image into depth texels of `bits` bits, with
/// GL_DEPTH_SCALE and GL_DEPTH_BIAS (`scale_bias`, when not the identity) applied as
/// `_mesa_unpack_depth_span` does: `clamp(d·scale + bias, 0, 1)` in f32, and no exact
/// integer path. Without them the exact paths are GL_UNSIGNED_SHORT into 16 bits,
/// GL_UNSIGNED_INT into 32 bits and the depth bits of GL_UNSIGNED_INT_24_8 into 24 bits.
/// Otherwise a GL_UNSIGNED_INT_24_8 value is `f32(z24)·f32(1/(2²⁴−1))`, and
/// GL_UNSIGNED_INT into 24 bits takes the float path too (measured for
/// GL_DEPTH_COMPONENT24 and GL_DEPTH24_STENCIL8: 0xffffff01 → 0xfffffe, not 0xffffff).
///
/// # Safety
/// `data` (when not null) must hold the image `ps`/`cf` describe.
pub unsafe fn unpack(
    ps: &PixelStore,
    cf: &ClientFormat,
    bits: u8,
    (w, h): (usize, usize),
    data: *const u8,
    scale_bias: Option<(f32, f32)>,
) -> Vec<[u8; 4]> {
    let lay = Layout::new(ps, w, cf);
    if data.is_null() || w == 0 || h == 0 {
        return vec![texel(0); w * h];
    }
    // SAFETY: the caller guarantees the image's bytes.
    let bytes = unsafe { std::slice::from_raw_parts(data, lay.span(w, h)) };
    let mut out = Vec::with_capacity(w * h);
    for y in 0..h {
        for x in 0..w {
            let o = lay.start + y * lay.stride + x * lay.bpp;
            let (d, exact) = client_value(&bytes[o..o + lay.bpp], cf.gl_type, ps.swap_bytes);
            let (d, exact) = match scale_bias {
                Some((scale, bias)) => (d * scale + bias, Exact::No),
                None => (d, exact),
            };
            let z = match (exact, bits) {
                (Exact::U16(v), 16) => v,
                (Exact::U32(v), 32) => v,
                (Exact::Z24(v), 24) => v,
                _ => store(d, bits),
            };
            out.push(texel(z));
        }
    }
    out
}

/// The stencil indices of a `w x h` GL_DEPTH_STENCIL/GL_UNSIGNED_INT_24_8 client image
/// (the low byte of each value), each passed through `transfer` (GL_INDEX_SHIFT,
/// GL_INDEX_OFFSET and GL_PIXEL_MAP_S_TO_S, as `_mesa_unpack_stencil_span` applies them;
/// measured: an offset of 3 turns 0xff into 0x02). Zeros for other client formats
/// (GL_DEPTH_COMPONENT data leaves the stencil undefined).
///
/// # Safety
/// `data` (when not null) must hold the image `ps`/`cf` describe.
pub unsafe fn unpack_stencil(
    ps: &PixelStore,
    cf: &ClientFormat,
    (w, h): (usize, usize),
    data: *const u8,
    transfer: &dyn Fn(u32) -> u8,
) -> Vec<u8> {
    let lay = Layout::new(ps, w, cf);
    if data.is_null() || w == 0 || h == 0 || !cf.is_depth_stencil() {
        return vec![0; w * h];
    }
    // SAFETY: the caller guarantees the image's bytes.
    let bytes = unsafe { std::slice::from_raw_parts(data, lay.span(w, h)) };
    let mut out = Vec::with_capacity(w * h);
    for y in 0..h {
        for x in 0..w {
            // GL_FLOAT_32_UNSIGNED_INT_24_8_REV keeps it in the second word
            let o = lay.start + y * lay.stride + x * lay.bpp + (lay.bpp - 4);
            let mut raw = [0u8; 4];
            raw.copy_from_slice(&bytes[o..o + 4]);
            if ps.swap_bytes {
                raw.reverse();
            }
            out.push(transfer(u32::from_ne_bytes(raw) & 0xff));
        }
    }
    out
}

/// One depth value in [0, 1] packed as client type `ty` (native byte order; the bytes
/// used), with `_mesa_pack_depth_span`'s conversions: truncating `FLOAT_TO_UBYTE`,
/// `FLOAT_TO_BYTE` (`(⌊255d⌋ − 1)/2`), `FLOAT_TO_SHORT`, `FLOAT_TO_UINT` and
/// `FLOAT_TO_INT` (f64), and round-half-even for GL_UNSIGNED_SHORT.
pub fn pack_depth(d: f32, ty: u32) -> ([u8; 4], usize) {
    let four = |b: [u8; 4]| (b, 4);
    let two = |b: [u8; 2]| ([b[0], b[1], 0, 0], 2);
    match ty {
        GL_UNSIGNED_BYTE => ([(d * 255.0) as i32 as u8, 0, 0, 0], 1),
        GL_BYTE => ([(((255.0 * d) as i32 - 1) / 2) as i8 as u8, 0, 0, 0], 1),
        GL_UNSIGNED_SHORT => two(((d * 65535.0).round_ties_even() as u16).to_ne_bytes()),
        GL_SHORT => two(((((65535.0 * d) as i32 - 1) / 2) as i16).to_ne_bytes()),
        GL_UNSIGNED_INT => four(((d as f64 * 4294967295.0) as u32).to_ne_bytes()),
        GL_INT => four(((2147483647.0 * d as f64) as i32).to_ne_bytes()),
        _ => four(d.to_ne_bytes()),
    }
}

/// Packs a depth image for glGetTexImage(GL_DEPTH_COMPONENT, type) (`_mesa_pack_depth_span`).
///
/// # Safety
/// `dst` must be writable for the packed image.
pub unsafe fn pack(ps: &PixelStore, cf: &ClientFormat, img: &Level, dst: *mut u8) {
    let (w, h) = (img.width, img.height);
    let lay = Layout::new(ps, w, cf);
    if dst.is_null() || w == 0 || h == 0 {
        return;
    }
    let bits = img.storage.depth_bits();
    // `get_tex_memcpy`: a Z32_UNORM image read as GL_UNSIGNED_INT (Z16 as
    // GL_UNSIGNED_SHORT) without byte swapping is copied, not converted through float.
    let copy = !ps.swap_bytes
        && matches!(
            (bits, cf.gl_type),
            (32, GL_UNSIGNED_INT) | (16, GL_UNSIGNED_SHORT)
        );
    // SAFETY: the caller guarantees `span` writable bytes.
    let bytes = unsafe { std::slice::from_raw_parts_mut(dst, lay.span(w, h)) };
    for y in 0..h {
        for x in 0..w {
            let z = texel_z(img.texel(x, y));
            let o = lay.start + y * lay.stride + x * lay.bpp;
            if copy {
                if bits == 16 {
                    bytes[o..o + 2].copy_from_slice(&(z as u16).to_ne_bytes());
                } else {
                    bytes[o..o + 4].copy_from_slice(&z.to_ne_bytes());
                }
                continue;
            }
            let d = readback(z, bits);
            let (mut v, n) = pack_depth(d, cf.gl_type);
            if ps.swap_bytes {
                v[..n].reverse();
            }
            let n = n.min(lay.bpp);
            bytes[o..o + n].copy_from_slice(&v[..n]);
        }
    }
}

/// Packs a packed depth-stencil image for glGetTexImage(GL_DEPTH_STENCIL, type), untouched
/// by GL_DEPTH_SCALE/BIAS (`_mesa_unpack_depth_stencil_row`; measured: the uploaded values
/// come back unchanged). GL_UNSIGNED_INT_24_8: `z24 << 8 | stencil` (a float image's z24
/// is `(GLuint)(z·f32(0xffffff))`); GL_FLOAT_32_UNSIGNED_INT_24_8_REV: the float depth (a
/// Z24 image's `z24 / (2²⁴−1)` in f64), then the stencil in the low byte of a second word.
/// `stencil` holds the image's indices (missing ones read as 0).
///
/// # Safety
/// `dst` must be writable for the packed image.
pub unsafe fn pack_depth_stencil(
    ps: &PixelStore,
    cf: &ClientFormat,
    img: &Level,
    stencil: &[u8],
    dst: *mut u8,
) {
    let (w, h) = (img.width, img.height);
    let lay = Layout::new(ps, w, cf);
    if dst.is_null() || w == 0 || h == 0 {
        return;
    }
    let float = img.storage.depth_bits() == FLOAT_BITS;
    // SAFETY: the caller guarantees `span` writable bytes.
    let bytes = unsafe { std::slice::from_raw_parts_mut(dst, lay.span(w, h)) };
    for y in 0..h {
        for x in 0..w {
            let z = texel_z(img.texel(x, y));
            let s = stencil.get(y * w + x).copied().unwrap_or(0) as u32;
            let words = match (cf.gl_type, float) {
                (GL_UNSIGNED_INT_24_8, false) => [z << 8 | s, 0],
                (GL_UNSIGNED_INT_24_8, true) => {
                    [((f32::from_bits(z) * 16_777_215.0) as u32) << 8 | s, 0]
                }
                (_, true) => [z, s],
                (_, false) => [((z as f64 / 16_777_215.0) as f32).to_bits(), s],
            };
            let o = lay.start + y * lay.stride + x * lay.bpp;
            for (k, word) in words.iter().enumerate().take(lay.bpp / 4) {
                let mut v = word.to_ne_bytes();
                if ps.swap_bytes {
                    v.reverse();
                }
                bytes[o + 4 * k..o + 4 * k + 4].copy_from_slice(&v);
            }
        }
    }
}
