//! glReadPixels from wide colour buffers (16-bit unorm and float; docs/llvmpipe-rules.md
//! §23): the stored values at full precision. GL_FLOAT gets the stored value as a float,
//! GL_UNSIGNED_SHORT a 16-bit buffer's integers, other types the float converted as for
//! 8-bit buffers. GL_CLAMP_READ_COLOR is FIXED_ONLY: Mesa clamps unless every colour
//! buffer of the framebuffer is float, which an object with a float renderbuffer is and
//! the OSMesa window is not (its visual is not a float visual, whatever the buffer type).

use crate::framebuffer::{float_to_ubyte, Framebuffer};
use crate::gl::enums::*;

/// Writes pixel `idx` of wide buffer `fb`, an image of base format `base`, at `p`: `n` components of `tsize` bytes, channel
/// `map[k]` in component `k` (`usize::MAX` for luminance, R + G + B); `put` writes a value
/// of the read type (normalised when asked).
///
/// # Safety
/// `p` must be writable for `n * tsize` bytes.
#[allow(clippy::too_many_arguments)]
pub unsafe fn read_wide_pixel(
    fb: &Framebuffer,
    idx: usize,
    base: crate::texture::BaseFormat,
    map: [usize; 4],
    n: usize,
    ty: u32,
    p: *mut u8,
    tsize: usize,
    put: impl Fn(*mut u8, f64, bool),
) {
    let Some(kind) = fb.wide else { return };
    let raw = base.read_rebase_wide(fb.wide_at(idx), kind.one());
    // The window (rows y-down) is fixed-point to Mesa's read clamp; objects are not.
    let clamp = !kind.is_float() || fb.y_flip;
    let rgba = raw.map(|v| {
        let f = kind.to_float(v);
        if clamp {
            crate::context::clamp01(f as f64) as f32
        } else {
            f
        }
    });
    for (k, &ch) in map.iter().take(n).enumerate() {
        // SAFETY: k * tsize < n * tsize, inside the bytes the caller vouches for.
        let q = unsafe { p.add(k * tsize) };
        let v = if ch == usize::MAX {
            let l = rgba[0] + rgba[1] + rgba[2];
            if clamp {
                l.min(1.0)
            } else {
                l
            }
        } else {
            rgba[ch]
        };
        match ty {
            // SAFETY: `q` addresses `tsize` (4) bytes of the caller's pixel.
            GL_FLOAT => unsafe { (q as *mut f32).write_unaligned(v) },
            // SAFETY: `q` addresses `tsize` (2) bytes of the caller's pixel.
            GL_UNSIGNED_SHORT if ch != usize::MAX => unsafe {
                (q as *mut u16).write_unaligned(kind.to_u16(raw[ch]))
            },
            // SAFETY: `q` addresses `tsize` (1) byte of the caller's pixel.
            GL_UNSIGNED_BYTE => unsafe { *q = float_to_ubyte(v) },
            _ => put(q, v as f64, true),
        }
    }
}
