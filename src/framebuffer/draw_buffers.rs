//! The colour buffers of draw buffers 1.. while a framebuffer object with several draw
//! buffers (glDrawBuffers) is bound: the context keeps them in the working copy's
//! [`Framebuffer::more_colors`] (draw buffer k at index k − 1, an empty buffer where
//! draw buffer k is GL_NONE or names no image), laid out as the working copy's own
//! colour (same size, same rows), and every [`super::Target`] made from it (one band, or the
//! bands of a threaded draw) carries the same rows of each ([`super::Target::more_colors`]), so
//! that the thread that owns a band of draw buffer 0 owns that band of every draw buffer
//! and one rasterization writes them all.
//!
//! Only 8-bit RGBA/RGB images are drawn this way (the context assembles no other kind:
//! `crate::context::fbo_bind`).

use super::Framebuffer;
use crate::memory::HugeBuf;
use std::slice::ChunksMut;

/// Draw buffers after draw buffer 0 (GL_MAX_DRAW_BUFFERS is 8).
pub const MORE_COLORS: usize = 7;

/// One band's rows of draw buffers 1.. (empty slices for those without a buffer).
pub type MoreRows<'a> = [&'a mut [[u8; 4]]; MORE_COLORS];

impl Framebuffer {
    /// glClear's colour write into draw buffers 1..: `v` in the channels `mask` keeps,
    /// over columns `x0..x1` of rows `y0..y1` (memory rows) of each.
    pub fn clear_more_colors(&mut self, [x0, y0, x1, y1]: [usize; 4], mask: [bool; 4], v: [u8; 4]) {
        let w = self.width;
        for buf in self.more_colors.iter_mut().filter(|b| b.len() >= w * y1) {
            for y in y0..y1 {
                for p in &mut buf[y * w + x0..y * w + x1] {
                    for c in 0..4 {
                        if mask[c] {
                            p[c] = v[c];
                        }
                    }
                }
            }
        }
    }

    /// Bit k − 1 set for each draw buffer k ≥ 1 that has a colour buffer here.
    pub fn more_color_mask(&self) -> u8 {
        mask_of(self.more_colors.iter().map(|c| c.len()))
    }
}

/// Bit k set for each non-zero length `lens[k]`.
fn mask_of(lens: impl Iterator<Item = usize>) -> u8 {
    lens.enumerate()
        .filter(|&(_, n)| n != 0)
        .fold(0, |m, (k, _)| m | 1 << k)
}

/// All rows of the buffers.
#[inline(always)]
pub(super) fn whole(bufs: &mut [HugeBuf<[u8; 4]>]) -> MoreRows<'_> {
    if bufs.is_empty() {
        return Default::default();
    }
    let mut it = bufs.iter_mut();
    std::array::from_fn(|_| match it.next() {
        Some(b) => &mut b[..],
        None => &mut [],
    })
}

/// The buffers cut into bands of `n` pixels, as [`Framebuffer::bands`] cuts draw
/// buffer 0.
pub(super) struct Bands<'a> {
    bufs: Vec<ChunksMut<'a, [u8; 4]>>,
}

impl<'a> Bands<'a> {
    /// The bands of `n` pixels of `bufs`.
    pub(super) fn new(bufs: &'a mut [HugeBuf<[u8; 4]>], n: usize) -> Self {
        Bands {
            bufs: bufs.iter_mut().map(|b| b.chunks_mut(n)).collect(),
        }
    }

    /// The next band's rows of every buffer.
    pub(super) fn next_band(&mut self) -> MoreRows<'a> {
        let mut it = self.bufs.iter_mut();
        std::array::from_fn(|_| match it.next() {
            Some(b) => b.next().unwrap_or_default(),
            None => &mut [],
        })
    }
}
