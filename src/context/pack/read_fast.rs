//! glReadPixels's row paths: 8-bit colour read as unsigned bytes and depth read as
//! GL_FLOAT, without pixel transfer or byte swapping, packed a row at a time (RGB bytes
//! through [`crate::simd::pack::rgba_to_rgb`], float depth of a Z32F buffer copied) instead
//! of [`super::read::read_pixels`]'s per-pixel dispatch. They write the same bytes: the
//! per-pixel loop is the reference they are compared with in the tests.

use crate::framebuffer::{DepthFormat, Framebuffer};
use crate::texture::{shadow, BaseFormat};

/// Where the read rectangle goes in client memory: the rectangle in GL window
/// coordinates, and the packed image's first byte and row stride.
#[derive(Clone, Copy)]
pub(super) struct Dest {
    /// Left column, bottom row, width and height read.
    pub rect: [i64; 4],
    /// Offset of the first pixel ([`super::packed_layout`]).
    pub start: usize,
    /// Bytes from one row to the next.
    pub stride: usize,
}

impl Dest {
    /// The rows of the rectangle inside `fb`: (image row, memory row, first image column,
    /// first buffer column, pixels).
    fn rows(
        self,
        fb: &Framebuffer,
    ) -> impl Iterator<Item = (usize, usize, usize, usize, usize)> + '_ {
        let [x, y, w, h] = self.rect;
        let (x0, x1) = (x.max(0), (x + w).min(fb.width as i64));
        let (y0, y1) = (y.max(0), (y + h).min(fb.height as i64));
        let n = (x1 - x0).max(0) as usize;
        (y0..y1.max(y0)).filter(move |_| n > 0).map(move |gy| {
            let fy = fb.row(gy as usize);
            ((gy - y) as usize, fy, (x0 - x) as usize, x0 as usize, n)
        })
    }

    /// The `len` bytes of image row `row` from column `col` (`bpp` bytes per pixel).
    ///
    /// # Safety
    /// `out` is writable for the packed image, and the bytes lie inside it.
    unsafe fn span<'a>(
        self,
        out: *mut u8,
        row: usize,
        col: usize,
        bpp: usize,
        len: usize,
    ) -> &'a mut [u8] {
        // SAFETY: the caller's promise (GL's contract with the program).
        unsafe {
            std::slice::from_raw_parts_mut(out.add(self.start + row * self.stride + col * bpp), len)
        }
    }
}

/// Colour read as GL_UNSIGNED_BYTE: component `k` of each pixel is channel `map[k]` of
/// the stored colour after `base`'s read rebase. `false` (nothing written) for a luminance
/// format (a sum, not a channel).
///
/// # Safety
/// `out` must be writable for the packed image.
pub(super) unsafe fn color_u8(
    fb: &Framebuffer,
    base: BaseFormat,
    map: [usize; 4],
    n: usize,
    d: Dest,
    out: *mut u8,
) -> bool {
    if map[..n].contains(&usize::MAX) || fb.wide.is_some() {
        return false;
    }
    // The rebase changes no channel read (RGB of an RGB or RGBA image, all of RGBA).
    let plain = match base {
        BaseFormat::Rgba | BaseFormat::Depth => true,
        BaseFormat::Rgb => !map[..n].contains(&3),
        _ => false,
    };
    for (row, fy, col, fx, len) in d.rows(fb) {
        // SAFETY: the row's pixels read lie inside the packed image (the caller's promise).
        let dst = unsafe { d.span(out, row, col, n, len * n) };
        let pending = fb.pending_color_row(fy);
        let src = &fb.color[fy * fb.width + fx..][..len];
        match (pending, plain, n, map) {
            (None, true, 3, [0, 1, 2, _]) => crate::simd::pack::rgba_to_rgb(src, dst),
            (None, true, 4, [0, 1, 2, 3]) => dst.copy_from_slice(src.as_flattened()),
            _ => {
                for (i, o) in dst.chunks_exact_mut(n).enumerate() {
                    let px = base.read_rebase(pending.unwrap_or(src[i]));
                    for (k, v) in o.iter_mut().enumerate() {
                        *v = px[map[k]];
                    }
                }
            }
        }
    }
    true
}

/// Depth read as GL_FLOAT without scale and bias: Mesa's `read_depth_pixels` float,
/// [`shadow::readback`] of each stored value (a Z32F buffer's bits themselves).
///
/// # Safety
/// `out` must be writable for the packed image.
pub(super) unsafe fn depth_f32(fb: &Framebuffer, d: Dest, out: *mut u8) {
    let bits = fb.depth_format.texel_bits();
    for (row, fy, col, fx, len) in d.rows(fb) {
        // SAFETY: the row's pixels read lie inside the packed image (the caller's promise).
        let dst = unsafe { d.span(out, row, col, 4, len * 4) };
        let src = &fb.depth[fy * fb.width + fx..][..len];
        match fb.pending_depth_row(fy) {
            Some(z) => {
                let v = shadow::readback(z, bits).to_ne_bytes();
                for o in dst.chunks_exact_mut(4) {
                    o.copy_from_slice(&v);
                }
            }
            None if fb.depth_format == DepthFormat::Z32F => {
                for (o, z) in dst.chunks_exact_mut(4).zip(src) {
                    o.copy_from_slice(&z.to_ne_bytes());
                }
            }
            None => {
                for (o, &z) in dst.chunks_exact_mut(4).zip(src) {
                    o.copy_from_slice(&shadow::readback(z, bits).to_ne_bytes());
                }
            }
        }
    }
}
