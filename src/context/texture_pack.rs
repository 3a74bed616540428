//! glGetTexImage: a level of the bound texture packed under the pack state into client
//! memory, or with a buffer bound to GL_PIXEL_PACK_BUFFER into its store at the offset the
//! pointer gives ([`super::pixel_buffer`]).

use super::client_image::image_span;
use super::texture_spec::{check_level, depth_match, image_target};
use super::{Context, GlError, GlResult};
use crate::context::pack::depth as shadow;
use crate::context::pack::tex::{self as upload, ClientFormat, Layout};
use crate::gl::types::*;
use crate::texture::{BaseFormat, Target};
use std::ffi::c_void;

impl Context {
    /// glGetTexImage: packs a level of the bound texture into `pixels` under the pack state.
    ///
    /// # Safety
    /// Without a pack buffer, `pixels` must be null or writable for the packed image of the
    /// level.
    pub(crate) unsafe fn get_tex_image(
        &mut self,
        target: GLenum,
        level: GLint,
        (format, type_): (GLenum, GLenum),
        pixels: *mut c_void,
    ) -> GlResult<()> {
        if self.state.pack.buffer == 0 {
            // SAFETY: forwarded caller contract.
            return unsafe { self.pack_tex_image(target, level, (format, type_), pixels) };
        }
        let span = self.tex_image_span(target, level, (format, type_));
        let Some(mut staged) = self.pack_stage(pixels, Some(type_), span)? else {
            return Ok(());
        };
        let out = staged.ptr() as *mut c_void;
        // SAFETY: the staged range holds the `span` bytes of the packed level (or is null).
        unsafe { self.pack_tex_image(target, level, (format, type_), out)? };
        self.pack_commit(staged);
        Ok(())
    }

    /// The bytes glGetTexImage writes for the level under the pack state: 0 when the
    /// arguments name no image (the call then fails on them or writes nothing).
    fn tex_image_span(&self, target: GLenum, level: GLint, ft: (GLenum, GLenum)) -> usize {
        let (Ok((t, false, face)), Ok(level)) = (image_target(target), check_level(level)) else {
            return 0;
        };
        let obj = self.tex_object(t, false);
        let Some(Some(img)) = obj.face_levels(face).get(level) else {
            return 0;
        };
        let (dims, d) = match t {
            Target::Tex1D => (1, 1),
            Target::Tex3D => (3, obj.depths[level]),
            _ => (2, 1),
        };
        let size = (img.width as GLsizei, img.height as GLsizei, d as GLsizei);
        image_span(dims, ft, &self.state.pack, size).unwrap_or(0)
    }

    /// Packs the level into `pixels` (the client's memory or a staged pack-buffer range).
    ///
    /// # Safety
    /// `pixels` must be null or writable for the packed image of the level.
    unsafe fn pack_tex_image(
        &mut self,
        target: GLenum,
        level: GLint,
        (format, type_): (GLenum, GLenum),
        pixels: *mut c_void,
    ) -> GlResult<()> {
        let (t, face) = match image_target(target)? {
            (t, false, face) => (t, face),
            _ => return Err(GlError::InvalidEnum),
        };
        let level = check_level(level)?;
        let cf = ClientFormat::new(format, type_)?;
        let ps = self.state.pack;
        // The image may be attached to the framebuffer object being drawn.
        let name = self.textures.units[self.state.active_texture].bound[t.index()];
        self.fbo_sync_texture(name);
        let obj = self.tex_object(t, false);
        let Some(Some(img)) = obj.face_levels(face).get(level) else {
            return Ok(());
        };
        depth_match(img.base, &cf)?;
        if cf.is_depth_stencil() {
            if !shadow::is_depth_stencil(img.internal_format) {
                return Err(GlError::InvalidOperation);
            }
            let stencil = obj.stencil.get(&(face, level)).map_or(&[][..], |s| s);
            // SAFETY: the caller promises room for the packed image.
            unsafe { shadow::pack_depth_stencil(&ps, &cf, img, stencil, pixels as *mut u8) };
            return Ok(());
        }
        if img.base == BaseFormat::Depth {
            // SAFETY: the caller promises room for the packed image.
            unsafe { shadow::pack(&ps, &cf, img, pixels as *mut u8) };
            return Ok(());
        }
        if t == Target::Tex3D {
            // SAFETY: the caller promises room for the packed image.
            unsafe { super::texture_3d::pack_3d(&ps, &cf, img, obj.depths[level], pixels) };
            return Ok(());
        }
        let _ = Layout::new(&ps, img.width, &cf);
        // SAFETY: the caller promises room for the packed image.
        unsafe { upload::pack(&ps, &cf, img, pixels as *mut u8) };
        Ok(())
    }
}
