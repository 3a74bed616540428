//! Block-compressed textures: S3TC (DXT1/3/5 and their sRGB forms), RGTC and LATC, the
//! formats glCompressedTexImage2D takes on Mesa 22.3's llvmpipe.
//!
//! # Storage
//! An image keeps the blocks as given ([`super::Level::blocks`], returned by
//! glGetCompressedTexImage) and its texels decoded once at upload into the usual RGBA8
//! storage (after the base swizzle), so sampling never looks at blocks. The decoded values
//! are the ones llvmpipe's sampler computes (`lp_bld_format_s3tc.c`, which
//! decodes 4 texels at a time on both of its paths; its texel cache is compiled out,
//! `LP_USE_TEXTURE_CACHE 0`), not those of Mesa's CPU decoder (`texcompress_s3tc_tmp.h`,
//! exact thirds and halves), which differ:
//!
//! - **565 → 888**: bit replication (`r5 << 3 | r5 >> 2`, `g6 << 2 | g6 >> 4`).
//! - **4-colour mode** (DXT1 when `color0 > color1` as 16-bit numbers; DXT3/DXT5 always):
//!   per 8-bit channel with `d = c1 − c0`, `c2 = c0 + ⌊85·d / 256⌋` and
//!   `c3 = c0 + ⌊85·d / 128⌋` (the 16-bit products of `lp_build_lerp23`, shifted by 8 and
//!   by 7), not `(2·c0 + c1) / 3`.
//! - **3-colour mode** (DXT1, `color0 ≤ color1`): `c2 = (c0 + c1 + 1) >> 1` (`pavgb`,
//!   rounding up; the scalar variant rounding down is used only for single-texel fetches,
//!   which fragment shading never makes) and `c3` black, with alpha 0 for the RGBA forms
//!   and 255 for the RGB forms.
//! - **DXT3 alpha**: the 4-bit value `a` becomes `a << 4 | a`.
//! - **DXT5 alpha and RGTC/LATC channels** (`lp_build_lerpdxta`): with codes 2..7 and
//!   `w = (W·(code − 1)) >> 6`, `W = 255·64/7 = 2331` when `a0 > a1` (8-value mode) else
//!   `255·64/5 = 3264`, the value is `a0 + ⌊(a1 − a0)·w / 256⌋`; in 6-value mode codes 6
//!   and 7 give 0 and 255 (signed: −127 and 127). The signed formats compare and
//!   interpolate the bytes as `i8` (−128 is kept; sampling clamps it to −1.0).
//! - **RGTC/LATC layout**: RGTC1 → (r, 0, 0, 1), RGTC2 → (r, g, 0, 1), LATC1 →
//!   (l, l, l, 1), LATC2 → (l, l, l, a), where 1 is 255, or 127 for the signed forms.
//!
//! Signed texels are stored as their `i8` bytes; sampling converts them on the float path
//! as `max(i8 · f32(1/127), −1)` (R8G8B8A8_SNORM, [`snorm_table`]). The sRGB forms are
//! decoded to bytes, then linearised like the other sRGB textures ([`super::srgb`]).

use super::{BaseFormat, Encoding};
use std::sync::OnceLock;

/// A compressed internal format softgl supports.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// DXT1 without alpha (GL_COMPRESSED_RGB_S3TC_DXT1_EXT, GL_COMPRESSED_SRGB_S3TC_DXT1_EXT).
    Dxt1Rgb,
    /// DXT1 with 1-bit alpha.
    Dxt1Rgba,
    /// DXT3: explicit 4-bit alpha.
    Dxt3,
    /// DXT5: interpolated alpha.
    Dxt5,
    /// RGTC1 / LATC1: one interpolated channel.
    One,
    /// RGTC2 / LATC2: two interpolated channels.
    Two,
}

/// Everything the API needs to know about a compressed internal format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Info {
    /// Block layout.
    pub format: Format,
    /// sRGB colour (sampled through [`super::srgb`]).
    pub srgb: bool,
    /// Signed channels (RGTC/LATC `SIGNED_*`).
    pub signed: bool,
    /// Luminance layout (LATC) rather than red/green (RGTC).
    pub luminance: bool,
}

impl Info {
    /// How the decoded bytes are read when sampled.
    pub fn encoding(&self) -> Encoding {
        if self.srgb {
            Encoding::SrgbBlocks
        } else if self.signed {
            Encoding::Snorm
        } else {
            Encoding::Unorm
        }
    }

    /// Bytes per 4x4 block.
    pub fn block_bytes(&self) -> usize {
        match self.format {
            Format::Dxt1Rgb | Format::Dxt1Rgba | Format::One => 8,
            _ => 16,
        }
    }

    /// The base internal format the image has (RGTC's RED and RG act as RGB in the
    /// texture environment, Mesa's `calculate_derived_texenv`).
    pub fn base(&self) -> BaseFormat {
        match (self.format, self.luminance) {
            (Format::Dxt1Rgb, _) | (Format::One | Format::Two, false) => BaseFormat::Rgb,
            (Format::One, true) => BaseFormat::Luminance,
            (Format::Two, true) => BaseFormat::LuminanceAlpha,
            _ => BaseFormat::Rgba,
        }
    }

    /// Bytes of a `w x h` image: whole blocks (Mesa's `_mesa_format_image_size`, in
    /// wrapping 32-bit arithmetic as there, so negative sizes give what Mesa compares).
    pub fn image_size(&self, w: i32, h: i32) -> u32 {
        let blocks = |n: i32| (n as u32).wrapping_add(3) / 4;
        blocks(w)
            .wrapping_mul(blocks(h))
            .wrapping_mul(self.block_bytes() as u32)
    }
}

/// A 565 colour expanded to 8 bits a channel by bit replication.
fn expand565(c: u16) -> [u8; 3] {
    let (r, g, b) = ((c >> 11) as u8, ((c >> 5) & 63) as u8, (c & 31) as u8);
    [r << 3 | r >> 2, g << 2 | g >> 4, b << 3 | b >> 2]
}

/// The four colours (RGBA) of a DXT colour block; `four` forces the 4-colour mode
/// (DXT3/5), `alpha` marks DXT1's RGBA form (transparent black in 3-colour mode).
fn palette(block: &[u8], four: bool, alpha: bool) -> [[u8; 4]; 4] {
    let c0 = u16::from_le_bytes([block[0], block[1]]);
    let c1 = u16::from_le_bytes([block[2], block[3]]);
    let (e0, e1) = (expand565(c0), expand565(c1));
    let mut p = [[0u8, 0, 0, 255]; 4];
    for ch in 0..3 {
        let (a, b) = (e0[ch] as i32, e1[ch] as i32);
        p[0][ch] = a as u8;
        p[1][ch] = b as u8;
        if four || c0 > c1 {
            // 16-bit products shifted right: floor division for negative deltas too
            let m = 85 * (b - a);
            p[2][ch] = (a + (m >> 8)) as u8;
            p[3][ch] = (a + (m >> 7)) as u8;
        } else {
            p[2][ch] = ((a + b + 1) >> 1) as u8;
            p[3][ch] = 0;
        }
    }
    if !four && c0 <= c1 && alpha {
        p[3][3] = 0;
    }
    p
}

/// The 16 values of an interpolated 8-byte channel block (DXT5 alpha, RGTC, LATC), as
/// bytes (`i8` bytes when `signed`).
fn channel(block: &[u8], signed: bool) -> [u8; 16] {
    let v = |b: u8| if signed { b as i8 as i32 } else { b as i32 };
    let (a0, a1) = (v(block[0]), v(block[1]));
    let bits = u64::from_le_bytes(block[..8].try_into().expect("8 bytes")) >> 16;
    let eight = a0 > a1;
    std::array::from_fn(|k| {
        let code = ((bits >> (3 * k)) & 7) as i32;
        let out = match code {
            0 => a0,
            1 => a1,
            6 if !eight => {
                if signed {
                    -127
                } else {
                    0
                }
            }
            7 if !eight => {
                if signed {
                    127
                } else {
                    255
                }
            }
            _ => {
                let w = (if eight { 2331 } else { 3264 } * (code - 1)) >> 6;
                a0 + (((a1 - a0) * w) >> 8)
            }
        };
        out as u8
    })
}

/// Decodes one block into its 16 texels (row-major, row 0 first) as stored: after the
/// base swizzle, signed channels as `i8` bytes.
pub fn decode_block(info: &Info, block: &[u8]) -> [[u8; 4]; 16] {
    match info.format {
        Format::Dxt1Rgb | Format::Dxt1Rgba => {
            let p = palette(block, false, info.format == Format::Dxt1Rgba);
            let idx = u32::from_le_bytes(block[4..8].try_into().expect("block"));
            std::array::from_fn(|k| p[((idx >> (2 * k)) & 3) as usize])
        }
        Format::Dxt3 | Format::Dxt5 => {
            let p = palette(&block[8..], true, false);
            let idx = u32::from_le_bytes(block[12..16].try_into().expect("block"));
            let alpha: [u8; 16] = if info.format == Format::Dxt3 {
                let bits = u64::from_le_bytes(block[..8].try_into().expect("block"));
                std::array::from_fn(|k| {
                    let a = ((bits >> (4 * k)) & 15) as u8;
                    a << 4 | a
                })
            } else {
                channel(block, false)
            };
            std::array::from_fn(|k| {
                let c = p[((idx >> (2 * k)) & 3) as usize];
                [c[0], c[1], c[2], alpha[k]]
            })
        }
        Format::One | Format::Two => {
            let one = if info.signed { 0x7f } else { 0xff };
            let r = channel(block, info.signed);
            let g = if info.format == Format::Two {
                channel(&block[8..], info.signed)
            } else {
                [0; 16]
            };
            std::array::from_fn(|k| match (info.luminance, info.format) {
                (false, Format::One) => [r[k], 0, 0, one],
                (false, _) => [r[k], g[k], 0, one],
                (true, Format::One) => [r[k], r[k], r[k], one],
                (true, _) => [r[k], r[k], r[k], g[k]],
            })
        }
    }
}

/// Decodes a `w x h` image of whole blocks (`data` must hold [`Info::image_size`] bytes).
pub fn decode(info: &Info, w: usize, h: usize, data: &[u8]) -> Vec<[u8; 4]> {
    let mut out = vec![[0u8; 4]; w * h];
    write_rect(info, (w, h), (0, 0, w, h), data, &mut out);
    out
}

/// Decodes the blocks of a `rw x rh` rectangle at (`x`, `y`) (block-aligned) into the
/// texels of a `w x h` image.
pub fn write_rect(
    info: &Info,
    (w, _h): (usize, usize),
    (x, y, rw, rh): (usize, usize, usize, usize),
    data: &[u8],
    texels: &mut [[u8; 4]],
) {
    let bb = info.block_bytes();
    let bw = rw.div_ceil(4);
    for by in 0..rh.div_ceil(4) {
        for bx in 0..bw {
            let off = (by * bw + bx) * bb;
            let t = decode_block(info, &data[off..off + bb]);
            for j in 0..4 {
                for i in 0..4 {
                    let (tx, ty) = (bx * 4 + i, by * 4 + j);
                    if tx < rw && ty < rh {
                        texels[(y + ty) * w + x + tx] = t[j * 4 + i];
                    }
                }
            }
        }
    }
}

/// Copies the blocks of a `rw x rh` rectangle at (`x`, `y`) (block-aligned) into the
/// blocks of a `w x h` image.
pub fn replace_blocks(
    info: &Info,
    w: usize,
    (x, y, rw, rh): (usize, usize, usize, usize),
    data: &[u8],
    blocks: &mut [u8],
) {
    let bb = info.block_bytes();
    let (iw, bw) = (w.div_ceil(4), rw.div_ceil(4));
    for by in 0..rh.div_ceil(4) {
        let src = by * bw * bb;
        let dst = ((y / 4 + by) * iw + x / 4) * bb;
        blocks[dst..dst + bw * bb].copy_from_slice(&data[src..src + bw * bb]);
    }
}

/// The float value of each signed byte as llvmpipe's SNORM8 unpack gives it:
/// `max(i8 · f32(1/127), −1)`.
pub fn snorm_table() -> &'static [f32; 256] {
    static T: OnceLock<[f32; 256]> = OnceLock::new();
    T.get_or_init(|| {
        let scale = (1.0f64 / 127.0) as f32;
        std::array::from_fn(|u| (u as u8 as i8 as f32 * scale).max(-1.0))
    })
}

/// The linear unorm8 value of each byte, `u · f32(1/255)` (alpha of sRGB textures).
pub fn unorm_table() -> &'static [f32; 256] {
    static T: OnceLock<[f32; 256]> = OnceLock::new();
    T.get_or_init(|| std::array::from_fn(|u| u as f32 * super::sample::INV_255))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dxt1_modes() {
        let i = Info {
            format: Format::Dxt1Rgba,
            srgb: false,
            signed: false,
            luminance: false,
        };
        // color0 = white > color1 = black: thirds, index 2 and 3
        let t = decode_block(&i, &[0xff, 0xff, 0, 0, 0b1110_0100, 0, 0, 0]);
        assert_eq!(t[0], [255, 255, 255, 255]);
        assert_eq!(t[1], [0, 0, 0, 255]);
        assert_eq!(t[2], [170, 170, 170, 255]); // 255 + floor(-21675/256)
        assert_eq!(t[3], [85, 85, 85, 255]); // 255 + floor(-21675/128)
                                             // swapped: 3-colour mode, average rounds up, index 3 transparent
        let t = decode_block(&i, &[0, 0, 0xff, 0xff, 0b1110_0100, 0, 0, 0]);
        assert_eq!(t[2], [128, 128, 128, 255]);
        assert_eq!(t[3], [0, 0, 0, 0]);
    }

    #[test]
    fn rgtc_signed_modes() {
        let i = Info {
            format: Format::One,
            srgb: false,
            signed: true,
            luminance: false,
        };
        // a0 = -128 <= a1 = 127: codes 6 and 7 are -127 and 127
        let codes: u64 = 6 | 7 << 3 | 1 << 6;
        let mut b = [0x80u8, 0x7f, 0, 0, 0, 0, 0, 0];
        b[2..8].copy_from_slice(&codes.to_le_bytes()[..6]);
        let t = decode_block(&i, &b);
        assert_eq!(t[0], [0x81, 0, 0, 0x7f]);
        assert_eq!(t[1], [0x7f, 0, 0, 0x7f]);
        assert_eq!(t[2], [0x7f, 0, 0, 0x7f]);
        assert_eq!(t[3], [0x80, 0, 0, 0x7f]);
        assert_eq!(snorm_table()[0x80], -1.0);
    }
}
