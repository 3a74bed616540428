//! glCompressedTexImage*, glCompressedTexSubImage* and glGetCompressedTexImage: the
//! client's blocks are copied here and the calls forwarded to
//! [`crate::context::texture_compressed`], which holds Mesa's checks.
#![allow(non_snake_case)]

use super::client::unpack_buffer_bytes;
use super::families::c_fns;
use super::types::*;
use super::with_ctx_list;
use crate::context::texture_compressed::{ImageArgs, SubArgs};

/// The client's blocks, copied when `size` is what the format needs for `w x h` (GL's
/// contract then makes `data` readable for that many bytes; with an unpack buffer bound,
/// `data` is an offset into it, [`unpack_buffer_bytes`]); `Some(None)` otherwise, when the
/// call fails its size check anyway, or for a null client pointer; `None` when the unpack
/// buffer's checks failed (the error is recorded and the call must do nothing).
///
/// # Safety
/// `data`, when not null and `size` matches, must be readable for `size` bytes.
unsafe fn copy_blocks(
    internal: GLenum,
    w: GLsizei,
    h: GLsizei,
    size: GLsizei,
    data: *const GLvoid,
) -> Option<Option<Vec<u8>>> {
    let Some(info) = crate::context::pack::tex_format::compressed_info(internal) else {
        return Some(None);
    };
    if size <= 0 || info.image_size(w, h) != size as u32 {
        return Some(None);
    }
    if let Some(copy) = unpack_buffer_bytes(data, None, size as usize)? {
        return Some(Some(copy));
    }
    if data.is_null() {
        return Some(None);
    }
    // SAFETY: the caller's contract for a matching size.
    Some(Some(
        unsafe { std::slice::from_raw_parts(data as *const u8, size as usize) }.to_vec(),
    ))
}

/// glCompressedTexImage{1,2,3}D (`dims`) with the client's blocks (read for 2D only).
///
/// # Safety
/// As [`copy_blocks`] for a 2D image.
unsafe fn image(dims: u32, target: GLenum, a: ImageArgs, data: *const GLvoid) {
    let blocks = match dims {
        // SAFETY: forwarded caller contract.
        2 => match unsafe { copy_blocks(a.internal, a.w, a.h, a.size, data) } {
            Some(b) => b,
            None => return,
        },
        _ => None,
    };
    with_ctx_list(move |c| c.compressed_tex_image(dims, target, &a, blocks.as_deref()))
}

/// glCompressedTexSubImage{1,2,3}D (`dims`) with the client's blocks (read for 2D only).
///
/// # Safety
/// As [`copy_blocks`] for a 2D image.
unsafe fn sub_image(dims: u32, target: GLenum, a: SubArgs, data: *const GLvoid) {
    let blocks = match dims {
        // SAFETY: forwarded caller contract.
        2 => match unsafe { copy_blocks(a.format, a.w, a.h, a.size, data) } {
            Some(b) => b,
            None => return,
        },
        _ => None,
    };
    with_ctx_list(move |c| c.compressed_tex_sub_image(dims, target, &a, blocks.as_deref()))
}

// The compressed image calls: `data` is read for the 2D forms (the only targets with
// compressed formats); the 1D and 3D forms fail their checks before any data is read.
c_fns! {
    unsafe fn glCompressedTexImage1D(target: GLenum, level: GLint, internalformat: GLenum, width: GLsizei, border: GLint, image_size: GLsizei, _data: *const GLvoid) => image(1, target, ImageArgs { level, internal: internalformat, w: width, h: 1, border, size: image_size }, _data);
    unsafe fn glCompressedTexImage2D(target: GLenum, level: GLint, internalformat: GLenum, width: GLsizei, height: GLsizei, border: GLint, image_size: GLsizei, data: *const GLvoid) => image(2, target, ImageArgs { level, internal: internalformat, w: width, h: height, border, size: image_size }, data);
    unsafe fn glCompressedTexImage3D(target: GLenum, level: GLint, internalformat: GLenum, width: GLsizei, height: GLsizei, _depth: GLsizei, border: GLint, image_size: GLsizei, _data: *const GLvoid) => image(3, target, ImageArgs { level, internal: internalformat, w: width, h: height, border, size: image_size }, _data);
    unsafe fn glCompressedTexSubImage1D(target: GLenum, level: GLint, xoffset: GLint, width: GLsizei, format: GLenum, image_size: GLsizei, _data: *const GLvoid) => sub_image(1, target, SubArgs { level, x: xoffset, y: 0, w: width, h: 1, format, size: image_size }, _data);
    unsafe fn glCompressedTexSubImage2D(target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, width: GLsizei, height: GLsizei, format: GLenum, image_size: GLsizei, data: *const GLvoid) => sub_image(2, target, SubArgs { level, x: xoffset, y: yoffset, w: width, h: height, format, size: image_size }, data);
    #[allow(clippy::too_many_arguments)]
    unsafe fn glCompressedTexSubImage3D(target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, _zoffset: GLint, width: GLsizei, height: GLsizei, _depth: GLsizei, format: GLenum, image_size: GLsizei, _data: *const GLvoid) => sub_image(3, target, SubArgs { level, x: xoffset, y: yoffset, w: width, h: height, format, size: image_size }, _data);
}

/// glGetCompressedTexImage.
///
/// # Safety
/// `img` must be writable for GL_TEXTURE_COMPRESSED_IMAGE_SIZE bytes of the image.
#[no_mangle]
pub unsafe extern "C" fn glGetCompressedTexImage(target: GLenum, level: GLint, img: *mut GLvoid) {
    // SAFETY: GL's contract: `img` holds GL_TEXTURE_COMPRESSED_IMAGE_SIZE bytes (or a pack
    // buffer takes them).
    super::with_ctx(|c| unsafe { c.get_compressed_tex_image_to(target, level, img) })
}
