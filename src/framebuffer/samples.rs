//! The other sample planes of a 4x multisample object while a one-pass multisample
//! triangle draw runs (`crate::raster::multisample`): the context moves planes 1..4 into
//! plane 0's [`Framebuffer::samples`] for the draw, and every [`Target`] made from plane 0
//! (one band, or the bands of a threaded draw) carries the same rows of those planes
//! ([`Target::samples`]), so that the thread that owns a band of plane 0 owns that band
//! of every plane and one rasterization writes all four.

use super::{Framebuffer, Target};
use std::slice::ChunksMut;

/// Sample planes of a multisample object besides plane 0.
pub const MORE_SAMPLES: usize = 3;

/// One sample plane's rows of a band (indices relative to the band's first row, as the
/// [`Target`]'s own slices); empty slices for a buffer the plane does not have.
#[derive(Default)]
pub struct PlaneRows<'a> {
    /// Colour rows.
    pub color: &'a mut [[u8; 4]],
    /// Depth rows (empty without a depth buffer).
    pub depth: &'a mut [u32],
    /// Stencil rows (empty without a stencil buffer).
    pub stencil: &'a mut [u8],
    /// Wide colour rows (empty for 8-bit buffers).
    pub wide_color: &'a mut [[f32; 4]],
}

impl PlaneRows<'_> {
    /// Stored wide colour of pixel `j` of a wide plane of precision `k`, as
    /// [`Framebuffer::wide_at`] reads it.
    #[inline]
    pub fn wide_at(&self, k: super::WideKind, j: usize) -> [f32; 4] {
        let (w, c8) = (self.wide_color[j], self.color[j]);
        if k.mirror(w) == c8 {
            w
        } else {
            k.from_u8(c8)
        }
    }
}

impl Framebuffer {
    /// Holds `planes` (the object's planes 1..4) in [`Framebuffer::samples`] for a one-pass
    /// multisample draw, with their recorded clears written: bands of plane 0 carry the
    /// other planes' rows as they are in memory.
    pub fn hold_samples(&mut self, mut planes: Vec<Framebuffer>) {
        for p in &mut planes {
            p.resolve();
            p.uniform_color = None;
        }
        self.samples = planes;
    }

    /// Gives back the planes [`Framebuffer::hold_samples`] took.
    pub fn release_samples(&mut self) -> Vec<Framebuffer> {
        std::mem::take(&mut self.samples)
    }
}

/// All rows of the held planes (empty rows past the planes there are).
#[inline(always)]
pub(super) fn whole(planes: &mut [Framebuffer]) -> [PlaneRows<'_>; MORE_SAMPLES] {
    if planes.is_empty() {
        return Default::default();
    }
    let mut it = planes.iter_mut();
    std::array::from_fn(|_| match it.next() {
        Some(p) => PlaneRows {
            color: &mut p.color,
            depth: &mut p.depth,
            stencil: &mut p.stencil,
            wide_color: &mut p.wide_color,
        },
        None => PlaneRows::default(),
    })
}

/// The held planes cut into bands of `n` pixels, as [`Framebuffer::bands`] cuts plane 0.
pub(super) struct Bands<'a> {
    planes: Vec<PlaneChunks<'a>>,
}

/// One plane's buffers cut into bands.
struct PlaneChunks<'a> {
    color: ChunksMut<'a, [u8; 4]>,
    depth: ChunksMut<'a, u32>,
    stencil: ChunksMut<'a, u8>,
    wide_color: ChunksMut<'a, [f32; 4]>,
}

impl<'a> Bands<'a> {
    /// The bands of `n` pixels of `planes`.
    pub(super) fn new(planes: &'a mut [Framebuffer], n: usize) -> Self {
        let planes = planes
            .iter_mut()
            .map(|p| PlaneChunks {
                color: p.color.chunks_mut(n),
                depth: p.depth.chunks_mut(n),
                stencil: p.stencil.chunks_mut(n),
                wide_color: p.wide_color.chunks_mut(n),
            })
            .collect();
        Bands { planes }
    }

    /// The next band's rows of every plane.
    pub(super) fn next_band(&mut self) -> [PlaneRows<'a>; MORE_SAMPLES] {
        let mut it = self.planes.iter_mut();
        std::array::from_fn(|_| match it.next() {
            Some(p) => PlaneRows {
                color: p.color.next().unwrap_or_default(),
                depth: p.depth.next().unwrap_or_default(),
                stencil: p.stencil.next().unwrap_or_default(),
                wide_color: p.wide_color.next().unwrap_or_default(),
            },
            None => PlaneRows::default(),
        })
    }
}

impl Target<'_> {
    /// Sample plane `s`'s rows of this band: the target's own for 0, else those of
    /// [`Target::samples`] (`s` < 4).
    #[inline(always)]
    pub fn plane(&mut self, s: usize) -> PlaneRows<'_> {
        if s == 0 {
            return PlaneRows {
                color: &mut *self.color,
                depth: &mut *self.depth,
                stencil: &mut *self.stencil,
                wide_color: &mut *self.wide_color,
            };
        }
        let p = &mut self.samples[s - 1];
        PlaneRows {
            color: &mut *p.color,
            depth: &mut *p.depth,
            stencil: &mut *p.stencil,
            wide_color: &mut *p.wide_color,
        }
    }
}
