//! GL_TEXTURE_3D images (GL 1.2, GL_EXT_texture3D): glTexImage3D, glTexSubImage3D,
//! glCopyTexSubImage3D. The images are specified by [`crate::context::texture_3d`]; this
//! file copies client images for display lists and forwards the calls.
#![allow(non_snake_case)]

use super::client::image_command;
use super::types::*;
use super::with_ctx_list;
use crate::context::Context;

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
    // SAFETY: `p` is the caller's image or the display list's copy of it.
    let run = move |c: &mut Context, p, u| unsafe {
        c.tex_image_3d(target, level, sizes, (format, type_), p, u)
    };
    // SAFETY: forwarded caller contract.
    unsafe { image_command(3, (format, type_), (width, height, depth), pixels, run) }
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
    let (off, size) = ([xoffset, yoffset, zoffset], (width, height, depth));
    // SAFETY: `p` is the caller's image or the display list's copy of it.
    let run = move |c: &mut Context, p, u| unsafe {
        c.tex_sub_image_3d(target, level, off, size, (format, type_), p, u)
    };
    // SAFETY: forwarded caller contract.
    unsafe { image_command(3, (format, type_), size, pixels, run) }
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
