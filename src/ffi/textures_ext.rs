//! Texture calls beyond GL 1.5 that Mesa's OSMesa exports and GL 1.x programs use
//! (`GL/glext.h`): glGenerateMipmap (GL 3.0 / ARB_framebuffer_object) and its EXT alias,
//! and glTexImage3DEXT, which Mesa declares in glext.h only (a program may declare a
//! pointer of that name when it includes gl.h without GL_GLEXT_PROTOTYPES).
#![allow(non_snake_case)]

use super::families::c_fns;
use super::textures_3d::glTexImage3D;
use super::types::*;
use super::with_ctx;

/// glGenerateMipmap: rebuilds levels base+1..=max from the base level with the same
/// filter GL_GENERATE_MIPMAP uses (Mesa's `st_generate_mipmap` serves both).
#[no_mangle]
pub extern "C" fn glGenerateMipmap(target: GLenum) {
    with_ctx(|c| c.generate_mipmap(target))
}

/// glGenerateMipmapEXT (GL_EXT_framebuffer_object alias).
#[no_mangle]
pub extern "C" fn glGenerateMipmapEXT(target: GLenum) {
    glGenerateMipmap(target)
}

c_fns! {
    /// glTexImage3DEXT: glTexImage3D under its EXT_texture3D name, whose header declares
    /// the internal format as a `GLenum`.
    #[allow(clippy::too_many_arguments)]
    unsafe fn glTexImage3DEXT(target: GLenum, level: GLint, internalformat: GLenum, width: GLsizei, height: GLsizei, depth: GLsizei, border: GLint, format: GLenum, type_: GLenum, pixels: *const GLvoid) => glTexImage3D(target, level, internalformat as GLint, width, height, depth, border, format, type_, pixels);
}
