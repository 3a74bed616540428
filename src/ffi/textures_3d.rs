//! GL_TEXTURE_3D images (GL 1.2, GL_EXT_texture3D): glTexImage3D, glTexSubImage3D,
//! glCopyTexSubImage3D. The images are specified by [`crate::context::texture_3d`]; this
//! file copies client images for display lists and forwards the calls.
#![allow(non_snake_case)]

use super::textures::compiling;
use super::types::*;
use super::{with_ctx, with_ctx_list};
use crate::context::pack::tex::{ClientFormat, Layout};
use crate::context::state::PixelStore;
use crate::context::texture_3d::slice_store;
use crate::texture::MAX_3D_TEXTURE_SIZE;
use libc::c_void;

/// Copies a 3D client image for a display list (read under the current unpack state).
///
/// # Safety
/// `data` (when not null) must hold the described image.
unsafe fn read_client_3d(
    (format, ty): (GLenum, GLenum),
    (w, h, d): (GLsizei, GLsizei, GLsizei),
    data: *const c_void,
) -> (Option<Vec<u8>>, PixelStore) {
    let unpack = super::with_ctx_raw(|c| Ok(c.state.unpack));
    let bytes = (|| {
        let cf = ClientFormat::new(format, ty).ok()?;
        let (w, h, d) = (
            usize::try_from(w).ok()?,
            usize::try_from(h).ok()?,
            usize::try_from(d).ok()?,
        );
        let lim = MAX_3D_TEXTURE_SIZE + 2;
        if data.is_null() || w > lim || h > lim || d > lim || w == 0 || h == 0 || d == 0 {
            return None;
        }
        let last = slice_store(&unpack, h, d - 1);
        let span = Layout::new(&last, w, &cf).span(w, h);
        // SAFETY: the caller promises the described image is readable.
        Some(unsafe { std::slice::from_raw_parts(data as *const u8, span) }.to_vec())
    })();
    (bytes, unpack)
}

/// The address of a display-list copy (null when there is none).
fn copy_ptr(b: &Option<Vec<u8>>) -> *const c_void {
    b.as_ref()
        .map_or(std::ptr::null(), |b| b.as_ptr() as *const c_void)
}

/// glTexImage3D.
///
/// # Safety
/// `pixels` (if not null) must hold the image described by the arguments and unpack state.
#[no_mangle]
pub unsafe extern "C" fn glTexImage3D(
    target: GLenum,
    level: GLint,
    internalFormat: GLint,
    width: GLsizei,
    height: GLsizei,
    depth: GLsizei,
    border: GLint,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    let sizes = (internalFormat, width, height, depth, border);
    if compiling() {
        // SAFETY: forwarded caller contract.
        let (bytes, unpack) =
            unsafe { read_client_3d((format, type_), (width, height, depth), pixels) };
        // SAFETY: the copy holds the described image.
        return with_ctx_list(move |c| unsafe {
            let p = copy_ptr(&bytes);
            c.tex_image_3d(target, level, sizes, (format, type_), p, unpack)
        });
    }
    // SAFETY: forwarded caller contract.
    with_ctx(|c| unsafe {
        let u = c.state.unpack;
        c.tex_image_3d(target, level, sizes, (format, type_), pixels, u)
    })
}

/// glTexSubImage3D.
///
/// # Safety
/// `pixels` must hold the image described by the arguments and unpack state.
#[no_mangle]
pub unsafe extern "C" fn glTexSubImage3D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    zoffset: GLint,
    width: GLsizei,
    height: GLsizei,
    depth: GLsizei,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    let off = [xoffset, yoffset, zoffset];
    let size = (width, height, depth);
    if compiling() {
        // SAFETY: forwarded caller contract.
        let (bytes, unpack) = unsafe { read_client_3d((format, type_), size, pixels) };
        // SAFETY: the copy holds the described image.
        return with_ctx_list(move |c| unsafe {
            let p = copy_ptr(&bytes);
            c.tex_sub_image_3d(target, level, off, size, (format, type_), p, unpack)
        });
    }
    // SAFETY: forwarded caller contract.
    with_ctx(|c| unsafe {
        let u = c.state.unpack;
        c.tex_sub_image_3d(target, level, off, size, (format, type_), pixels, u)
    })
}

/// glCopyTexSubImage3D.
#[no_mangle]
pub extern "C" fn glCopyTexSubImage3D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    zoffset: GLint,
    x: GLint,
    y: GLint,
    width: GLsizei,
    height: GLsizei,
) {
    with_ctx_list(move |c| {
        let off = [xoffset, yoffset, zoffset];
        c.copy_tex_sub_image_3d(target, level, off, (x, y), (width, height))
    })
}
