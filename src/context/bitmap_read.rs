//! The client's glBitmap image, unpacked to one flag per pixel.

use super::pack::draw_image::Layout;
use super::state::PixelStore;
use crate::gl::enums::{GL_BITMAP, GL_COLOR_INDEX};
use crate::gl::types::*;
use crate::pixels::image::Pixels;

/// The `w x h` bitmap at `data` under `unpack`, one flag per pixel (empty for an empty or
/// negative size, or when nothing can be read).
///
/// # Safety
/// `data` must hold the bitmap the unpack state describes (for a positive size).
pub(crate) unsafe fn bitmap_bits(
    unpack: &PixelStore,
    (w, h): (GLsizei, GLsizei),
    data: *const GLubyte,
) -> Vec<bool> {
    if w <= 0 || h <= 0 {
        return Vec::new();
    }
    let l = Layout::new(GL_COLOR_INDEX, GL_BITMAP).expect("a valid layout");
    // SAFETY: forwarded caller contract.
    match unsafe { l.decode(unpack, w as usize, h as usize, data) } {
        Some(img) => match img.pixels {
            Pixels::Index(v) => v.iter().map(|&b| b != 0).collect(),
            _ => Vec::new(),
        },
        None => Vec::new(),
    }
}
