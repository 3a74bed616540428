//! Draw buffers 1.. of the framebuffer object bound for drawing (glDrawBuffers with
//! several): their images copied into the working copy's
//! [`Framebuffer::more_colors`](crate::framebuffer::Framebuffer::more_colors) when it is
//! assembled, and written back with draw buffer 0's image.
//!
//! What is drawn this way: single-sample objects whose draw buffer 0 is 8-bit RGBA (not
//! sRGB, not wide), into draw buffers that are 8-bit RGBA images too (an RGBA8
//! renderbuffer or an 8-bit RGBA texture level). Only draws through the engine write
//! them (programs, and fixed function where it is lowered): the other paths and every
//! other image kind leave draw buffers 1.. untouched. The images are copied, not lent:
//! their copies are dropped when the working copy is parked.

use super::fbo::Attachment;
use super::fbo_image::{image_mut, load, store, ImageMut};
use super::Context;
use crate::framebuffer::draw_buffers::MORE_COLORS;
use crate::framebuffer::{ColorFormat, DepthFormat, Framebuffer};
use crate::memory::HugeBuf;
use crate::texture::BaseFormat;

/// A colour-only framebuffer of `fb`'s size and rows holding `color`, for the image
/// copies of [`load`] and [`store`].
fn colour_only(fb: &Framebuffer, color: HugeBuf<[u8; 4]>) -> Framebuffer {
    let mut t = Framebuffer::new(0, 0, ColorFormat::Rgba, DepthFormat::None, false);
    t.width = fb.width;
    t.height = fb.height;
    t.y_flip = fb.y_flip;
    t.pending_rows = vec![false; fb.height];
    t.color = color;
    t
}

impl Context {
    /// The attachments of draw buffers 1.. of draw object `name` that are drawn
    /// ([`self`](self) module docs), given the working copy `fb` of its draw buffer 0 and
    /// whether the object is multisample.
    fn more_draw_images(
        &self,
        name: u32,
        fb: &Framebuffer,
        ms: bool,
    ) -> [Option<Attachment>; MORE_COLORS] {
        let mut out = [None; MORE_COLORS];
        let Some(f) = self.fbo.object(name) else {
            return out;
        };
        if ms || fb.wide.is_some() || fb.srgb || fb.format != ColorFormat::Rgba {
            return out;
        }
        for (o, d) in out.iter_mut().zip(&f.more_draw) {
            *o = d.map(|i| f.color[i]).filter(|&a| {
                let info = self.fbo.image_info(a, &self.textures);
                a != Attachment::None
                    && info
                        .is_some_and(|i| i.kind == super::fbo::ImageKind::Color(BaseFormat::Rgba))
                    && !self.fbo.is_srgb(a, &self.textures)
                    && self.fbo.wide_kind(Some(a), &self.textures).is_none()
            });
        }
        out
    }

    /// Copies the images of draw buffers 1.. of draw object `name` into working copy
    /// `fb` (nothing when it has none to draw).
    pub(super) fn load_more_colors(&mut self, name: u32, fb: &mut Framebuffer, ms: bool) {
        fb.more_colors.clear();
        let images = self.more_draw_images(name, fb, ms);
        if images.iter().all(Option::is_none) {
            return;
        }
        let n = fb.width * fb.height;
        for a in images {
            let mut color = HugeBuf::empty();
            if let Some(a) = a {
                let mut t = colour_only(fb, HugeBuf::filled(n, [0; 4]));
                if let Some((img @ ImageMut::Color(..), iw)) =
                    image_mut(&mut self.fbo, &mut self.textures, a, 0)
                {
                    load(&mut t, img, iw, false);
                    color = t.color;
                }
            }
            fb.more_colors.push(color);
        }
    }

    /// Writes the working copy's draw buffers 1.. back into their images; returns the
    /// attachments written.
    pub(super) fn store_more_colors(&mut self) -> Vec<Attachment> {
        let name = self.fbo.draw;
        let Some(f) = self.fbo.object(name) else {
            return Vec::new();
        };
        let more = f.more_draw;
        let colors = match self.fb.as_mut() {
            Some(fb) if !fb.more_colors.is_empty() => std::mem::take(&mut fb.more_colors),
            _ => return Vec::new(),
        };
        let Some(fb) = self.fb.as_ref() else {
            return Vec::new();
        };
        let mut temps: Vec<Framebuffer> = colors.into_iter().map(|c| colour_only(fb, c)).collect();
        let mut written = Vec::new();
        for (t, d) in temps.iter_mut().zip(more) {
            let Some(a) = d.and_then(|i| self.fbo.object(name).map(|f| f.color[i])) else {
                continue;
            };
            if t.color.is_empty() {
                continue;
            }
            if let Some((img, iw)) = image_mut(&mut self.fbo, &mut self.textures, a, 0) {
                store(t, img, iw, false);
                written.push(a);
            }
        }
        if let Some(fb) = self.fb.as_mut() {
            fb.more_colors = temps.into_iter().map(|t| t.color).collect();
        }
        written
    }

    /// Whether the object bound for drawing is also read from, through a colour buffer
    /// other than its draw buffer 0 (then reads need a copy of their own:
    /// [`Context::read_other_buffer`]).
    pub fn reads_other_buffer(&self) -> bool {
        self.fbo.read == self.fbo.draw
            && self
                .fbo
                .object(self.fbo.draw)
                .is_some_and(|f| f.read_buffer != f.draw_buffer)
    }

    /// A copy of the draw object with the read buffer's image as its colour and the
    /// working copy's depth and stencil (which may be on loan to it, so not in their
    /// images), after writing the drawing back.
    pub(super) fn read_other_buffer(&mut self) -> Option<Framebuffer> {
        self.fbo_sync();
        let name = self.fbo.draw;
        let f = self.fbo.object_mut(name)?;
        let saved = f.draw_buffer;
        f.draw_buffer = f.read_buffer;
        let copy = self.assemble_copy(name);
        if let Some(f) = self.fbo.object_mut(name) {
            f.draw_buffer = saved;
        }
        let mut copy = copy?;
        let fb = self.fb.as_ref()?;
        if copy.depth.len() == fb.depth.len() {
            copy.depth.copy_from_slice(&fb.depth);
        }
        if copy.stencil.len() == fb.stencil.len() {
            copy.stencil.copy_from_slice(&fb.stencil);
        }
        Some(copy)
    }
}
