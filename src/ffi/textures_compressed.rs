//! glCompressedTexImage*, glCompressedTexSubImage* and glGetCompressedTexImage. GL 1.5
//! requires no compressed internal format and softgl supports none
//! (GL_NUM_COMPRESSED_TEXTURE_FORMATS is 0; the generic GL_COMPRESSED_* asked of glTexImage
//! and glCopyTexImage store the texture uncompressed, see [`generic_base`]), so every call ends in the error Mesa's checks give for a format
//! that is not compressed, and changes nothing.
#![allow(non_snake_case)]

use super::enums::*;
use super::textures::{check_level, image_target};
use super::types::*;
use super::with_ctx_list;
use crate::context::error::{GlError, GlResult};

/// GL 1.3's generic compressed internal formats and the base internal format each names.
///
/// softgl stores them uncompressed, as their base format (the GL 1.3 spec allows it: "if
/// no specific compressed format is available, internalformat is instead replaced by the
/// corresponding base internal format"), so GL_TEXTURE_INTERNAL_FORMAT answers the base
/// format and GL_TEXTURE_COMPRESSED 0. Mesa 22.3 (llvmpipe) does the same for a 1D
/// texture and for ALPHA and INTENSITY; it compresses RGB, RGBA, LUMINANCE and
/// LUMINANCE_ALPHA of the other targets (DXT1, DXT5, LATC1, LATC2): see README's
/// known differences.
pub(crate) fn generic_base(f: GLenum) -> Option<GLenum> {
    Some(match f {
        GL_COMPRESSED_ALPHA => GL_ALPHA,
        GL_COMPRESSED_LUMINANCE => GL_LUMINANCE,
        GL_COMPRESSED_LUMINANCE_ALPHA => GL_LUMINANCE_ALPHA,
        GL_COMPRESSED_INTENSITY => GL_INTENSITY,
        GL_COMPRESSED_RGB => GL_RGB,
        GL_COMPRESSED_RGBA => GL_RGBA,
        _ => return None,
    })
}

/// The generic compressed formats (glTexImage's GL_COMPRESSED_RGB ...; GL 3.0's RED/RG and
/// EXT_texture_sRGB's too), which glCompressedTexSubImage rejects with GL_INVALID_ENUM.
fn is_generic_compressed(f: GLenum) -> bool {
    generic_base(f).is_some()
        || matches!(
            f,
            0x8225 // GL_COMPRESSED_RED
            | 0x8226 // GL_COMPRESSED_RG
            | 0x8C48 // GL_COMPRESSED_SRGB
            | 0x8C49 // GL_COMPRESSED_SRGB_ALPHA
            | 0x8C4A // GL_COMPRESSED_SLUMINANCE
            | 0x8C4B // GL_COMPRESSED_SLUMINANCE_ALPHA
        )
}

/// glCompressedTexImage{1,2,3}D: the internal format is never a supported compressed
/// format, GL_INVALID_ENUM (Mesa's `compressed_texture_error_check`; a 1D target fails its
/// target check with the same error).
fn compressed_image() {
    with_ctx_list(|_| Err(GlError::InvalidEnum))
}

/// glCompressedTexSubImage{1,2,3}D, in Mesa's order: the target (no 1D compressed
/// textures; a 3D texture takes no format softgl could have), then the format.
fn compressed_sub_image(dims: u32, target: GLenum, format: GLenum) {
    with_ctx_list(move |_| {
        let target_ok = match dims {
            2 => {
                target == GL_TEXTURE_2D
                    || (GL_TEXTURE_CUBE_MAP_POSITIVE_X..GL_TEXTURE_CUBE_MAP_POSITIVE_X + 6)
                        .contains(&target)
            }
            3 if target == GL_TEXTURE_3D => return Err(GlError::InvalidOperation),
            _ => false,
        };
        if !target_ok {
            return Err(GlError::InvalidEnum);
        }
        Err(if is_generic_compressed(format) {
            GlError::InvalidEnum
        } else {
            GlError::InvalidOperation
        })
    })
}

/// glGetCompressedTexImage: the target and level are checked, then no image is compressed.
fn get_compressed(target: GLenum, level: GLint) -> GlResult<()> {
    match image_target(target)? {
        (_, false, _) => {}
        _ => return Err(GlError::InvalidEnum),
    }
    check_level(level)?;
    Err(GlError::InvalidOperation)
}

/// glCompressedTexImage1D.
#[no_mangle]
pub extern "C" fn glCompressedTexImage1D(
    _target: GLenum,
    _level: GLint,
    _internalformat: GLenum,
    _width: GLsizei,
    _border: GLint,
    _image_size: GLsizei,
    _data: *const GLvoid,
) {
    compressed_image()
}

/// glCompressedTexImage2D.
#[no_mangle]
pub extern "C" fn glCompressedTexImage2D(
    _target: GLenum,
    _level: GLint,
    _internalformat: GLenum,
    _width: GLsizei,
    _height: GLsizei,
    _border: GLint,
    _image_size: GLsizei,
    _data: *const GLvoid,
) {
    compressed_image()
}

/// glCompressedTexImage3D.
#[no_mangle]
pub extern "C" fn glCompressedTexImage3D(
    _target: GLenum,
    _level: GLint,
    _internalformat: GLenum,
    _width: GLsizei,
    _height: GLsizei,
    _depth: GLsizei,
    _border: GLint,
    _image_size: GLsizei,
    _data: *const GLvoid,
) {
    compressed_image()
}

/// glCompressedTexSubImage1D.
#[no_mangle]
pub extern "C" fn glCompressedTexSubImage1D(
    target: GLenum,
    _level: GLint,
    _xoffset: GLint,
    _width: GLsizei,
    format: GLenum,
    _image_size: GLsizei,
    _data: *const GLvoid,
) {
    compressed_sub_image(1, target, format)
}

/// glCompressedTexSubImage2D.
#[no_mangle]
pub extern "C" fn glCompressedTexSubImage2D(
    target: GLenum,
    _level: GLint,
    _xoffset: GLint,
    _yoffset: GLint,
    _width: GLsizei,
    _height: GLsizei,
    format: GLenum,
    _image_size: GLsizei,
    _data: *const GLvoid,
) {
    compressed_sub_image(2, target, format)
}

/// glCompressedTexSubImage3D.
#[no_mangle]
pub extern "C" fn glCompressedTexSubImage3D(
    target: GLenum,
    _level: GLint,
    _xoffset: GLint,
    _yoffset: GLint,
    _zoffset: GLint,
    _width: GLsizei,
    _height: GLsizei,
    _depth: GLsizei,
    format: GLenum,
    _image_size: GLsizei,
    _data: *const GLvoid,
) {
    compressed_sub_image(3, target, format)
}

/// glGetCompressedTexImage (writes nothing: no texture image is compressed).
#[no_mangle]
pub extern "C" fn glGetCompressedTexImage(target: GLenum, level: GLint, _img: *mut GLvoid) {
    super::with_ctx(|_| get_compressed(target, level))
}
