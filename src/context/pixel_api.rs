//! The pixel-rectangle commands' validation (GL 1.5 §3.6, §4.3.3): glDrawPixels,
//! glCopyPixels, glBitmap, glPixelZoom and the glPixelMap queries, in Mesa's error order
//! (size, format/type, missing buffer). The C boundary decodes client images with the
//! unpack state when the call is made; the drawing is `crate::pixels::draw`'s.

use super::pixel_transfer::{is_index_map, map_index};
use super::{Context, GlError, GlResult};
use crate::context::pack::draw_image::Layout;
use crate::context::pixel_ops::{bitmap, copy_pixels, draw_pixels};
use crate::framebuffer::DepthFormat;
use crate::gl::enums::*;
use crate::gl::glext_enums::GL_DEPTH_STENCIL;
use crate::gl::types::*;
use crate::pixels::draw::CopyKind;
use crate::pixels::image::Image;

impl Context {
    /// glDrawPixels of a `width` x `height` image of `layout`, decoded by the caller
    /// (`None` for a null or undecodable image).
    pub(crate) fn draw_pixel_rect(
        &mut self,
        (width, height): (GLsizei, GLsizei),
        layout: GlResult<Layout>,
        img: Option<&Image>,
    ) -> GlResult<()> {
        if width < 0 || height < 0 {
            return Err(GlError::InvalidValue);
        }
        let l = layout?;
        self.check_draw_framebuffer()?;
        let fb = self.fb.as_ref();
        match l.format() {
            GL_STENCIL_INDEX if fb.is_none_or(|f| f.stencil.is_empty()) => {
                return Err(GlError::InvalidOperation)
            }
            GL_DEPTH_COMPONENT if fb.is_none_or(|f| f.depth_format == DepthFormat::None) => {
                return Err(GlError::InvalidOperation)
            }
            _ => {}
        }
        match img {
            // Into a multisample object: every sample plane gets the pixels (llvmpipe's
            // pixel-aligned quad covers every sample of the pixels it covers).
            Some(img) if self.feedback.mode == super::feedback::RenderMode::Render => {
                self.for_each_sample(|c, _| draw_pixels(c, img))
            }
            Some(img) => draw_pixels(self, img),
            // Mesa cannot map a null image into its texture: GL_OUT_OF_MEMORY.
            None if self.raster_pos.valid && width > 0 && height > 0 => {
                return Err(GlError::OutOfMemory)
            }
            None => {}
        }
        Ok(())
    }

    /// glCopyPixels of the `width` x `height` rectangle at (`x`, `y`) of the read buffer.
    pub(crate) fn copy_pixel_rect(
        &mut self,
        (x, y): (GLint, GLint),
        (width, height): (GLsizei, GLsizei),
        type_: GLenum,
    ) -> GlResult<()> {
        if width < 0 || height < 0 {
            return Err(GlError::InvalidValue);
        }
        let kind = match type_ {
            GL_COLOR => CopyKind::Color,
            GL_DEPTH => CopyKind::Depth,
            GL_STENCIL => CopyKind::Stencil,
            GL_DEPTH_STENCIL => CopyKind::DepthStencil,
            _ => return Err(GlError::InvalidEnum),
        };
        self.check_draw_framebuffer()?;
        self.check_read_framebuffer()?;
        // Mesa refuses to copy from a multisample object (`_mesa_CopyPixels`).
        if self.read_samples() > 0 {
            return Err(GlError::InvalidOperation);
        }
        let fb = self.fb.as_ref();
        let missing = match kind {
            CopyKind::Color => !self.reads_color(),
            CopyKind::Depth => fb.is_none_or(|f| f.depth_format == DepthFormat::None),
            CopyKind::Stencil => fb.is_none_or(|f| f.stencil.is_empty()),
            CopyKind::DepthStencil => {
                fb.is_none_or(|f| f.stencil.is_empty() || f.depth_format == DepthFormat::None)
            }
        };
        if missing {
            return Err(GlError::InvalidOperation);
        }
        copy_pixels(self, x, y, width as usize, height as usize, kind);
        Ok(())
    }

    /// glBitmap of a `width` x `height` bitmap decoded by the caller (`bits` empty for a
    /// null or empty bitmap: only the raster position moves).
    pub(crate) fn draw_bitmap(
        &mut self,
        (width, height): (GLsizei, GLsizei),
        orig: [GLfloat; 2],
        mv: [GLfloat; 2],
        bits: &[bool],
    ) -> GlResult<()> {
        if width < 0 || height < 0 {
            return Err(GlError::InvalidValue);
        }
        let (w, h) = if bits.is_empty() {
            (0, 0)
        } else {
            (width as usize, height as usize)
        };
        bitmap(self, w, h, orig, mv, bits);
        Ok(())
    }

    /// glPixelZoom.
    pub(crate) fn pixel_zoom(&mut self, x: GLfloat, y: GLfloat) {
        self.pixel_modes.zoom = [x, y];
    }

    /// glPixelMap with a size outside 1..=256: GL_INVALID_ENUM for an unknown map first,
    /// else GL_INVALID_VALUE.
    pub(crate) fn pixel_map_size_error(&self, map: GLenum) -> GlResult<()> {
        map_index(map)?;
        Err(GlError::InvalidValue)
    }

    /// glGetPixelMap: the values of `map`, and whether it is an index map.
    pub(crate) fn pixel_map_values(&self, map: GLenum) -> GlResult<(&[f32], bool)> {
        let i = map_index(map)?;
        Ok((&self.pixel_maps.maps[i], is_index_map(i)))
    }
}
