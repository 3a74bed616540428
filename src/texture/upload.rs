//! Texel value conversions shared by texture storage, mipmap generation and the GL
//! unpacking in `context::pack`: reducing 8-bit and float components to a storage
//! format's precision the way Mesa's texstore does (`_mesa_unorm_to_unorm`,
//! `_mesa_float_to_unorm`, bit replication of fields of fewer than 8 bits), and the
//! base-format swizzle of a stored texel.

use super::{BaseFormat, Storage};

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
pub fn float_to_bits_u8(x: f32, bits: u32) -> u8 {
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

/// Quantises an RGBA8 value to the storage precision (glCopyTexImage, mipmaps).
#[inline]
pub fn quantise_rgba(rgba: [u8; 4], storage: &Storage) -> [u8; 4] {
    let bits = storage.bits();
    std::array::from_fn(|c| quantise_u8(rgba[c], bits[c]))
}

/// An 8-bit fragment value written into a component of `bits` bits, as llvmpipe's fragment
/// output converts its unorm8 blend type (`lp_state_fs.c`, `scale_bits`, "wrong
/// rounding"), expanded back by bit replication: 4 bits round (through float); 5 to 7 bits
/// truncate (`x >> (8 − n)`); 1 to 3 bits take `((x >> n)·(2^n − 1) + 2^(7−n)) >> (8 − n)`.
/// This is how GL_GENERATE_MIPMAP's blit stores a level (`mipmap`).
#[inline]
pub fn render_quantise_u8(x: u8, bits: u32) -> u8 {
    let delta = 8u32.saturating_sub(bits);
    let c = match bits {
        8.. => return x,
        4 => return quantise_u8(x, 4),
        5..=7 => x as u32 >> delta,
        _ => ((x as u32 >> bits) * ((1 << bits) - 1) + (1 << (delta - 1))) >> delta,
    };
    unorm_to_u8(c as u64, bits)
}

/// [`render_quantise_u8`] of each component at the storage precision (a generated mipmap
/// level).
#[inline]
pub fn render_quantise_rgba(rgba: [u8; 4], storage: &Storage) -> [u8; 4] {
    let bits = storage.bits();
    std::array::from_fn(|c| render_quantise_u8(rgba[c], bits[c]))
}

/// Reduces client RGBA to the base format's stored (swizzled) texel.
#[inline]
pub fn to_texel(base: BaseFormat, rgba: [u8; 4]) -> [u8; 4] {
    base.swizzle(rgba, 0, 255)
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
    fn render_quantise_follows_scale_bits() {
        // 5 and 6 bits truncate: 8i + 7 stores i (as the RGB565 window buffer measured)
        assert_eq!(render_quantise_u8(8 * 9 + 7, 5), unorm_to_u8(9, 5));
        assert_eq!(render_quantise_u8(4 * 9 + 3, 6), unorm_to_u8(9, 6));
        // 3 bits: ((x >> 3)·7 + 16) >> 5
        assert_eq!(render_quantise_u8(255, 3), 255);
        assert_eq!(render_quantise_u8(146, 3), unorm_to_u8(4, 3)); // (18·7 + 16) >> 5 = 4
        assert_eq!(render_quantise_u8(145, 3), unorm_to_u8(4, 3));
        assert_eq!(quantise_u8(145, 3), unorm_to_u8(4, 3));
        assert_eq!(render_quantise_u8(127, 2), unorm_to_u8(1, 2)); // (31·3 + 32) >> 6 = 1
                                                                   // 4 bits round as texstore does; 8 bits pass
        assert_eq!(render_quantise_u8(8, 4), quantise_u8(8, 4));
        assert_eq!(render_quantise_u8(77, 8), 77);
    }
}
