//! GL_GENERATE_MIPMAP as Mesa 22.3 does it on llvmpipe.
//!
//! `st_generate_mipmap` calls `util_gen_mipmap`, which blits each level from the previous
//! one with a LINEAR filter: llvmpipe samples the source level once per destination texel
//! at its centre, `u = (x + 0.5)·src_w/dst_w` (likewise v), with CLAMP_TO_EDGE on the 8-bit
//! AoS path, and the fragment output converts the `u8/255` result back to the same byte.
//! So level n+1 texel = the 8.8 fixed-point bilinear sample of level n at that point
//! (for power-of-two sizes a chain of `v0 + ((128·(v1 − v0) + 128) >> 8)` lerps, not an
//! exact box average). Verified bit-exact against Mesa 22.3 (glGetTexImage of levels of
//! 4x4, 5x3, 8x2, 3x3, 7x7 and 1x6 random RGBA8 textures).
//! A level stored with fewer than 8 bits per component gets the value as llvmpipe's
//! fragment output converts it into that format ([`super::upload::render_quantise_u8`]:
//! 5 to 7 bits truncate, 4 round; scene `tex_small_formats_wrap`).

use super::sample::lerp8;
use super::Level;

/// `round_half_even(u·256) − 128` split into (i0, i1, w), clamped to the edge.
pub(crate) fn axis(dst: usize, x: usize, src: usize) -> (usize, usize, i32) {
    // u·256 = (x + 0.5)·src·256/dst, computed exactly in integers: (2x+1)·src·128/dst
    let num = (2 * x as u64 + 1) * src as u64 * 128;
    let q = num / dst as u64;
    let r = num % dst as u64;
    let twice = 2 * r;
    let rounded = if twice > dst as u64 || (twice == dst as u64 && q % 2 == 1) {
        q + 1
    } else {
        q
    };
    let fx = rounded as i64 - 128;
    let i0 = fx >> 8;
    let w = (fx & 255) as i32;
    let max = src as i64 - 1;
    (
        i0.clamp(0, max) as usize,
        (i0 + 1).clamp(0, max) as usize,
        w,
    )
}

/// The next smaller level of `src` (sizes halve, rounding down, minimum 1).
pub fn downsample(src: &Level) -> Level {
    let dw = (src.width / 2).max(1);
    let dh = (src.height / 2).max(1);
    let xs: Vec<_> = (0..dw).map(|x| axis(dw, x, src.width)).collect();
    let mut texels = Vec::with_capacity(dw * dh);
    for y in 0..dh {
        let (y0, y1, wy) = axis(dh, y, src.height);
        for &(x0, x1, wx) in &xs {
            let a = src.texel(x0, y0);
            let b = src.texel(x1, y0);
            let c = src.texel(x0, y1);
            let d = src.texel(x1, y1);
            let v = std::array::from_fn(|ch| {
                let r0 = lerp8(a[ch], b[ch], wx);
                let r1 = lerp8(c[ch], d[ch], wx);
                lerp8(r0, r1, wy)
            });
            // the blit writes into the level's own storage format (e.g. RGB5) as a fragment
            // output converts to it (`upload::render_quantise_u8`)
            texels.push(super::upload::render_quantise_rgba(v, &src.storage));
        }
    }
    Level::derived(src, dw, dh, texels)
}

/// Regenerates levels `base+1 ..= max_level` (and down to 1x1) from level `base`.
pub fn generate(levels: &mut [Option<Level>], base: usize, max_level: usize) {
    let mut l = base;
    while l < max_level.min(levels.len() - 1) {
        let Some(src) = levels[l].as_ref() else {
            return;
        };
        if src.width == 1 && src.height == 1 {
            return;
        }
        // sRGB levels: decoded, filtered in float and encoded (see `srgb`)
        let next = if src.storage.encoding == super::Encoding::Srgb {
            super::srgb::downsample(src, super::sample::has_fma())
        } else if src.storage.has_floats() {
            // float and 16-bit levels: filtered and stored as floats (see `float`)
            super::float::downsample(src, super::sample::has_fma())
        } else {
            downsample(src)
        };
        levels[l + 1] = Some(next);
        l += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::texture::BaseFormat;

    fn lv(w: usize, h: usize, data: &[u8]) -> Level {
        Level {
            width: w,
            height: h,
            internal_format: 0x8058,
            base: BaseFormat::Rgba,
            storage: crate::texture::Storage::of_base(BaseFormat::Rgba),
            texels: data.chunks(4).map(|c| [c[0], c[1], c[2], c[3]]).collect(),
            blocks: None,
            floats: None,
        }
    }

    #[test]
    fn matches_mesa_4x4() {
        // level 0 and the levels Mesa 22.3 generated (probe output)
        let l0 = [
            220, 4, 101, 170, 31, 173, 29, 90, 218, 229, 172, 27, 30, 95, 19, 112, 121, 108, 253,
            16, 255, 25, 175, 96, 29, 4, 172, 180, 29, 2, 43, 70, 120, 115, 58, 242, 223, 95, 174,
            183, 8, 89, 209, 238, 57, 16, 203, 72, 149, 181, 204, 137, 41, 17, 255, 6, 182, 98, 46,
            223, 60, 249, 53, 253,
        ];
        let mut levels = vec![Some(lv(4, 4, &l0)), None, None];
        generate(&mut levels, 0, 1000);
        let l1 = levels[1].as_ref().unwrap();
        let want1 = lv(
            2,
            2,
            &[
                157, 78, 140, 93, 77, 83, 102, 98, 134, 102, 173, 143, 77, 114, 128, 197,
            ],
        );
        assert_eq!(l1.texels, want1.texels);
        assert_eq!(
            levels[2].as_ref().unwrap().texels[..],
            [[112, 95, 136, 133]]
        );
    }

    #[test]
    fn matches_mesa_5x3_npot() {
        let l0 = [
            75, 148, 40, 202, 9, 124, 68, 179, 2, 94, 150, 95, 179, 234, 109, 172, 212, 45, 129,
            110, 105, 175, 224, 230, 135, 76, 156, 4, 231, 210, 54, 93, 44, 96, 201, 234, 244, 121,
            246, 134, 160, 235, 147, 38, 228, 98, 18, 213, 13, 203, 179, 119, 21, 106, 106, 58,
            104, 186, 142, 219,
        ];
        let mut levels = vec![Some(lv(5, 3, &l0)), None, None];
        generate(&mut levels, 0, 1000);
        assert_eq!(
            levels[1].as_ref().unwrap().texels[..],
            [[128, 101, 173, 61], [94, 102, 212, 209]]
        );
        assert_eq!(
            levels[2].as_ref().unwrap().texels[..],
            [[111, 102, 193, 135]]
        );
    }
}
