//! Pixel buffer objects (GL 2.1, ARB_pixel_buffer_object). With a buffer bound to
//! GL_PIXEL_UNPACK_BUFFER, the pointer of a command that reads an image (glTexImage*,
//! glTexSubImage*, glCompressedTex*, glDrawPixels, glBitmap, glPolygonStipple) is an offset
//! into the buffer's store; with one bound to GL_PIXEL_PACK_BUFFER, so is the pointer of a
//! command that writes one (glReadPixels, glGetTexImage, glGetCompressedTexImage,
//! glGetPolygonStipple). The bindings live in the pack and unpack pixel stores
//! ([`super::state::PixelStore::buffer`]), as in Mesa.
//!
//! The commands themselves only ever see plain memory: an unpacking command gets a copy of
//! the bytes it reads ([`Context::unpack_source`]), a packing one writes into a staging copy
//! of the range it may write ([`Context::pack_stage`]), which [`Context::pack_commit`] puts
//! back (bytes the command leaves unwritten, such as pixels outside the framebuffer or row
//! padding, keep their values). The copy costs one pass over the image, small beside the
//! conversion every such command does anyway.
//!
//! The checks are Mesa's (`_mesa_validate_pbo_access` and its callers), each
//! GL_INVALID_OPERATION, made before the command runs so that a failed one changes
//! nothing:
//! 1. the offset is a multiple of the size of one datum of the type (not for GL_BITMAP or
//!    compressed images);
//! 2. the buffer's store is not empty;
//! 3. the image (unless it is empty) ends inside the store;
//! 4. the buffer is not mapped.
//!
//! Because they run before the command, a call with bad arguments *and* a bad buffer range
//! reports GL_INVALID_OPERATION where Mesa reports the argument's error; a call whose
//! arguments do not describe an image (so no extent can be computed) skips them and fails
//! on its arguments, as in Mesa.

use super::pack::read::{read_pixels, read_span};
use super::state::PixelStore;
use super::{Context, GlError, GlResult};
use crate::gl::enums::*;
use crate::gl::glext_enums::*;
use crate::gl::types::GLenum;

/// The bytes one datum of `ty` takes in client memory (Mesa's `_mesa_sizeof_packed_type`):
/// the alignment a buffer offset must have. 1 for GL_BITMAP and for types without a size.
fn datum_size(ty: GLenum) -> usize {
    match ty {
        GL_UNSIGNED_SHORT | GL_SHORT | GL_HALF_FLOAT => 2,
        GL_UNSIGNED_SHORT_5_6_5
        | GL_UNSIGNED_SHORT_5_6_5_REV
        | GL_UNSIGNED_SHORT_4_4_4_4
        | GL_UNSIGNED_SHORT_4_4_4_4_REV
        | GL_UNSIGNED_SHORT_5_5_5_1
        | GL_UNSIGNED_SHORT_1_5_5_5_REV => 2,
        GL_UNSIGNED_INT | GL_INT | GL_FLOAT => 4,
        GL_UNSIGNED_INT_8_8_8_8
        | GL_UNSIGNED_INT_8_8_8_8_REV
        | GL_UNSIGNED_INT_10_10_10_2
        | GL_UNSIGNED_INT_2_10_10_10_REV
        | GL_UNSIGNED_INT_24_8 => 4,
        GL_FLOAT_32_UNSIGNED_INT_24_8_REV => 8,
        _ => 1,
    }
}

/// A packing command's output staged for the pack buffer: the bytes of the buffer's range,
/// written by the command through [`Staged::ptr`] and put back by [`Context::pack_commit`].
#[derive(Debug)]
pub(crate) struct Staged {
    /// The buffer object's name.
    buffer: u32,
    /// Where the range starts in its store.
    offset: usize,
    /// The range's bytes.
    bytes: Vec<u8>,
}

impl Staged {
    /// Where the command writes (null for an empty range: nothing is written).
    pub(crate) fn ptr(&mut self) -> *mut u8 {
        if self.bytes.is_empty() {
            std::ptr::null_mut()
        } else {
            self.bytes.as_mut_ptr()
        }
    }
}

impl Context {
    /// The range `[offset, offset + span)` of the buffer `ps` binds, after the checks of
    /// the module doc (`ty` is the image's type, `None` for a compressed one).
    fn pixel_buffer_range(
        &self,
        ps: &PixelStore,
        ptr: usize,
        ty: Option<GLenum>,
        span: usize,
    ) -> GlResult<&[u8]> {
        let b = self
            .arrays
            .buffers
            .get(&ps.buffer)
            .and_then(|b| b.as_ref())
            .ok_or(GlError::InvalidOperation)?;
        if ty.is_some_and(|t| t != GL_BITMAP && !ptr.is_multiple_of(datum_size(t))) {
            return Err(GlError::InvalidOperation);
        }
        let len = b.data.len();
        let end = ptr.checked_add(span).ok_or(GlError::InvalidOperation)?;
        if len == 0 || (span != 0 && end > len) {
            return Err(GlError::InvalidOperation);
        }
        if b.mapped.is_some() {
            return Err(GlError::InvalidOperation);
        }
        Ok(if span == 0 { &[] } else { &b.data[ptr..end] })
    }

    /// Where an unpacking command reads its image of `span` bytes and type `ty` (`None`
    /// when compressed): `None` without an unpack buffer (the pointer is the client's),
    /// else a copy of the bytes at offset `ptr` in the buffer (see the module doc).
    pub(crate) fn unpack_source(
        &self,
        ptr: *const libc::c_void,
        ty: Option<GLenum>,
        span: usize,
    ) -> GlResult<Option<Vec<u8>>> {
        let ps = self.state.unpack;
        if ps.buffer == 0 {
            return Ok(None);
        }
        Ok(Some(
            self.pixel_buffer_range(&ps, ptr as usize, ty, span)?
                .to_vec(),
        ))
    }

    /// Where a packing command writes its image of `span` bytes and type `ty`: `None`
    /// without a pack buffer (the pointer is the client's), else the staged range at
    /// offset `ptr` of the buffer, to be written and then given to [`Self::pack_commit`].
    pub(crate) fn pack_stage(
        &self,
        ptr: *mut libc::c_void,
        ty: Option<GLenum>,
        span: usize,
    ) -> GlResult<Option<Staged>> {
        let ps = self.state.pack;
        if ps.buffer == 0 {
            return Ok(None);
        }
        let bytes = self
            .pixel_buffer_range(&ps, ptr as usize, ty, span)?
            .to_vec();
        Ok(Some(Staged {
            buffer: ps.buffer,
            offset: ptr as usize,
            bytes,
        }))
    }

    /// Puts a staged range back into its buffer (which the command cannot have resized).
    pub(crate) fn pack_commit(&mut self, s: Staged) {
        if let Some(Some(b)) = self.arrays.buffers.get_mut(&s.buffer) {
            if let Some(dst) = b.data.get_mut(s.offset..s.offset + s.bytes.len()) {
                dst.copy_from_slice(&s.bytes);
            }
        }
    }
}

impl Context {
    /// Runs a packing command's output step `write` on the memory `dst` names: the
    /// client's, or with a pack buffer bound the staged `span` bytes at offset `dst` (after
    /// the checks; put back when `write` succeeds). `ty` as for [`Self::pack_stage`].
    ///
    /// # Safety
    /// Without a pack buffer, `dst` must be null or writable for what `write` writes.
    unsafe fn pack_with(
        &mut self,
        dst: *mut libc::c_void,
        ty: Option<GLenum>,
        span: usize,
        write: impl FnOnce(&mut Context, *mut u8) -> GlResult<()>,
    ) -> GlResult<()> {
        let Some(mut staged) = self.pack_stage(dst, ty, span)? else {
            return write(self, dst as *mut u8);
        };
        write(self, staged.ptr())?;
        self.pack_commit(staged);
        Ok(())
    }

    /// glReadPixels into client memory or the pack buffer (see the module doc).
    ///
    /// # Safety
    /// Without a pack buffer, `pixels` must be null or writable for the packed image.
    pub(crate) unsafe fn read_pixels_to(
        &mut self,
        (x, y, w, h): (i32, i32, i32, i32),
        (format, ty): (GLenum, GLenum),
        pixels: *mut libc::c_void,
    ) -> GlResult<()> {
        // Arguments that describe no image give an empty range; read_pixels fails on them.
        let span = match self.state.pack.buffer {
            0 => 0,
            _ => read_span(&self.state.pack, (format, ty), w, h),
        };
        // SAFETY: forwarded caller contract, or the staged range of `span` bytes.
        unsafe {
            self.pack_with(pixels, Some(ty), span, |c, out| {
                read_pixels(c, x, y, w, h, format, ty, out)
            })
        }
    }

    /// glGetPolygonStipple into client memory or the pack buffer (128 bytes; a null
    /// client pointer is ignored).
    ///
    /// # Safety
    /// Without a pack buffer, `mask` must be null or writable for 128 bytes.
    pub(crate) unsafe fn get_polygon_stipple_to(&mut self, mask: *mut u8) -> GlResult<()> {
        let rows = self.polygon_stipple_rows();
        // SAFETY: forwarded caller contract, or the staged range of 128 bytes.
        unsafe {
            self.pack_with(mask.cast(), None, 128, |_, out| {
                write_to(rows.as_flattened(), out);
                Ok(())
            })
        }
    }

    /// glGetCompressedTexImage into client memory or the pack buffer (a null client
    /// pointer is ignored).
    ///
    /// # Safety
    /// Without a pack buffer, `img` must be null or writable for the image's size.
    pub(crate) unsafe fn get_compressed_tex_image_to(
        &mut self,
        target: GLenum,
        level: i32,
        img: *mut libc::c_void,
    ) -> GlResult<()> {
        let blocks = self.compressed_blocks(target, level)?.to_vec();
        // SAFETY: forwarded caller contract, or the staged range of the blocks' size.
        unsafe {
            self.pack_with(img, None, blocks.len(), |_, out| {
                write_to(&blocks, out);
                Ok(())
            })
        }
    }
}

/// Copies `bytes` to `dst` (nothing when `dst` is null).
///
/// # Safety
/// `dst`, when not null, must be writable for `bytes.len()` bytes.
unsafe fn write_to(bytes: &[u8], dst: *mut u8) {
    if !dst.is_null() {
        // SAFETY: the caller's contract.
        unsafe { std::ptr::copy_nonoverlapping(bytes.as_ptr(), dst, bytes.len()) };
    }
}
