//! Texture calls beyond GL 1.5 that Mesa's OSMesa exports and GL 1.x programs use
//! (`GL/glext.h`): glGenerateMipmap (GL 3.0 / ARB_framebuffer_object) and its EXT alias,
//! and glTexImage3DEXT, which Mesa declares in glext.h only (a program may declare a
//! pointer of that name when it includes gl.h without GL_GLEXT_PROTOTYPES).
#![allow(non_snake_case)]

use super::textures::{bind_target, object_mut, regenerate};
use super::textures_3d::glTexImage3D;
use super::types::*;
use super::with_ctx;
use crate::context::error::GlError;

/// glGenerateMipmap: rebuilds levels base+1..=max from the base level with the same
/// filter GL_GENERATE_MIPMAP uses (Mesa's `st_generate_mipmap` serves both).
#[no_mangle]
pub extern "C" fn glGenerateMipmap(target: GLenum) {
    with_ctx(|c| {
        let t = bind_target(target)?;
        let obj = object_mut(c, t, false);
        let p = obj.params;
        let base = usize::try_from(p.base_level).map_err(|_| GlError::InvalidOperation)?;
        if obj.levels.get(base).is_none_or(|l| l.is_none()) {
            return Err(GlError::InvalidOperation);
        }
        // Mesa: no mipmaps of a packed depth-stencil image
        let internal = obj.levels[base].as_ref().map_or(0, |l| l.internal_format);
        if crate::context::pack::depth::is_depth_stencil(internal) {
            return Err(GlError::InvalidOperation);
        }
        regenerate(obj, base);
        Ok(())
    })
}

/// glGenerateMipmapEXT (GL_EXT_framebuffer_object alias).
#[no_mangle]
pub extern "C" fn glGenerateMipmapEXT(target: GLenum) {
    glGenerateMipmap(target)
}

/// glTexImage3DEXT: glTexImage3D under its EXT_texture3D name, whose header declares the
/// internal format as a `GLenum`.
///
/// # Safety
/// As [`glTexImage3D`](super::textures_3d::glTexImage3D).
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub unsafe extern "C" fn glTexImage3DEXT(
    target: GLenum,
    level: GLint,
    internalformat: GLenum,
    width: GLsizei,
    height: GLsizei,
    depth: GLsizei,
    border: GLint,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    // SAFETY: the caller upholds glTexImage3D's contract; the arguments pass through.
    unsafe {
        glTexImage3D(
            target,
            level,
            internalformat as GLint,
            width,
            height,
            depth,
            border,
            format,
            type_,
            pixels,
        )
    }
}
