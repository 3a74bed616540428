//! Framebuffer and renderbuffer objects (GL_ARB_framebuffer_object, `GL/glext.h`): names,
//! bindings, attachments, storage, status and the attachment queries, each forwarded to
//! [`crate::context::fbo_api`] or [`crate::context::fbo_query`]. The EXT names that
//! differ (glBindFramebufferEXT and glBindRenderbufferEXT accept names never generated)
//! are here too; the other EXT names are aliases (`aliases_ext.rs`).
#![allow(non_snake_case)]

use super::client::read_vec;
use super::families::c_fns;
use super::types::*;
use super::{non_negative, with_ctx, with_ctx_list};
use crate::context::Context;

/// glGenFramebuffers.
///
/// # Safety
/// `framebuffers` must be writable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenFramebuffers(n: GLsizei, framebuffers: *mut GLuint) {
    // SAFETY: the caller's promise, passed on.
    unsafe { gen_names(n, framebuffers, Context::gen_framebuffers) }
}

/// The body of glGenFramebuffers and glGenRenderbuffers: `n` new names from `gen`.
///
/// # Safety
/// `out` must be writable for `n` names or null.
unsafe fn gen_names(n: GLsizei, out: *mut GLuint, gen: fn(&mut Context, &mut [GLuint])) {
    with_ctx(|c| {
        let n = non_negative(n)?;
        if !out.is_null() {
            // SAFETY: the caller promises room for n names.
            gen(c, unsafe { std::slice::from_raw_parts_mut(out, n) });
        }
        Ok(())
    })
}

/// glDeleteFramebuffers: a bound object's bindings revert to the window first.
///
/// # Safety
/// `framebuffers` must be readable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteFramebuffers(n: GLsizei, framebuffers: *const GLuint) {
    with_ctx(|c| {
        let n = non_negative(n)?;
        // SAFETY: the caller promises n readable names.
        c.delete_framebuffers(&unsafe { read_vec(framebuffers, n) });
        Ok(())
    })
}

c_fns! {
    /// glBindFramebuffer (the compatibility profile, like the EXT call, takes names never
    /// generated; only a core profile refuses them, as Mesa does).
    safe fn glBindFramebuffer(target: GLenum, framebuffer: GLuint) => with_ctx(|c| c.bind_framebuffer_object(target, framebuffer, true));
    /// glBindFramebufferEXT (any name creates an object).
    safe fn glBindFramebufferEXT(target: GLenum, framebuffer: GLuint) => with_ctx(|c| c.bind_framebuffer_object(target, framebuffer, true));
    /// glIsFramebuffer: true for names of objects that have been bound.
    safe fn glIsFramebuffer(framebuffer: GLuint) -> GLboolean => with_ctx(|c| Ok(c.is_framebuffer(framebuffer) as GLboolean));
    safe fn glCheckFramebufferStatus(target: GLenum) -> GLenum => with_ctx(|c| c.check_framebuffer_status(target));
    safe fn glFramebufferTexture1D(target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint) => with_ctx(|c| c.framebuffer_texture(target, attachment, Some(textarget), Some(1), texture, level, 0));
    safe fn glFramebufferTexture2D(target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint) => with_ctx(|c| c.framebuffer_texture(target, attachment, Some(textarget), Some(2), texture, level, 0));
    safe fn glFramebufferTexture3D(target: GLenum, attachment: GLenum, textarget: GLenum, texture: GLuint, level: GLint, zoffset: GLint) => with_ctx(|c| c.framebuffer_texture(target, attachment, Some(textarget), Some(3), texture, level, zoffset));
}

/// glFramebufferTextureLayer: layer `layer` of a 3D texture.
#[no_mangle]
pub extern "C" fn glFramebufferTextureLayer(
    target: GLenum,
    attachment: GLenum,
    texture: GLuint,
    level: GLint,
    layer: GLint,
) {
    with_ctx(|c| c.framebuffer_texture(target, attachment, None, None, texture, level, layer))
}

/// glFramebufferRenderbuffer.
#[no_mangle]
pub extern "C" fn glFramebufferRenderbuffer(
    target: GLenum,
    attachment: GLenum,
    renderbuffertarget: GLenum,
    renderbuffer: GLuint,
) {
    with_ctx(|c| c.framebuffer_renderbuffer(target, attachment, renderbuffertarget, renderbuffer))
}

/// glGenRenderbuffers.
///
/// # Safety
/// `renderbuffers` must be writable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenRenderbuffers(n: GLsizei, renderbuffers: *mut GLuint) {
    // SAFETY: the caller's promise, passed on.
    unsafe { gen_names(n, renderbuffers, Context::gen_renderbuffers) }
}

/// glDeleteRenderbuffers: detached from the bound framebuffers, unbound if bound.
///
/// # Safety
/// `renderbuffers` must be readable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteRenderbuffers(n: GLsizei, renderbuffers: *const GLuint) {
    with_ctx(|c| {
        let n = non_negative(n)?;
        // SAFETY: the caller promises n readable names.
        c.delete_renderbuffers(&unsafe { read_vec(renderbuffers, n) })
    })
}

c_fns! {
    /// glBindRenderbuffer (names never generated are taken, as by glBindFramebuffer).
    safe fn glBindRenderbuffer(target: GLenum, renderbuffer: GLuint) => with_ctx(|c| c.bind_renderbuffer(target, renderbuffer, true));
    /// glBindRenderbufferEXT (any name creates an object).
    safe fn glBindRenderbufferEXT(target: GLenum, renderbuffer: GLuint) => with_ctx(|c| c.bind_renderbuffer(target, renderbuffer, true));
    /// glIsRenderbuffer: true for names of objects that have been bound.
    safe fn glIsRenderbuffer(renderbuffer: GLuint) -> GLboolean => with_ctx(|c| Ok(c.is_renderbuffer(renderbuffer) as GLboolean));
}

/// glRenderbufferStorage.
#[no_mangle]
pub extern "C" fn glRenderbufferStorage(
    target: GLenum,
    internalformat: GLenum,
    width: GLsizei,
    height: GLsizei,
) {
    with_ctx(|c| c.renderbuffer_storage(target, 0, internalformat, width, height))
}

/// glRenderbufferStorageMultisample: `samples` above GL_MAX_SAMPLES is GL_INVALID_OPERATION.
#[no_mangle]
pub extern "C" fn glRenderbufferStorageMultisample(
    target: GLenum,
    samples: GLsizei,
    internalformat: GLenum,
    width: GLsizei,
    height: GLsizei,
) {
    with_ctx(|c| c.renderbuffer_storage(target, samples, internalformat, width, height))
}

/// glGetRenderbufferParameteriv.
///
/// # Safety
/// `params` must be writable for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetRenderbufferParameteriv(
    target: GLenum,
    pname: GLenum,
    params: *mut GLint,
) {
    let v = with_ctx(|c| c.get_renderbuffer_parameter(target, pname).map(Some));
    if let (Some(v), false) = (v, params.is_null()) {
        // SAFETY: the caller promises one writable value.
        unsafe { *params = v };
    }
}

/// glGetFramebufferAttachmentParameteriv.
///
/// # Safety
/// `params` must be writable for one value.
#[no_mangle]
pub unsafe extern "C" fn glGetFramebufferAttachmentParameteriv(
    target: GLenum,
    attachment: GLenum,
    pname: GLenum,
    params: *mut GLint,
) {
    let v = with_ctx(|c| {
        c.get_framebuffer_attachment_parameter(target, attachment, pname)
            .map(Some)
    });
    if let (Some(v), false) = (v, params.is_null()) {
        // SAFETY: the caller promises one writable value.
        unsafe { *params = v };
    }
}

/// glBlitFramebuffer.
#[no_mangle]
#[allow(clippy::too_many_arguments)]
pub extern "C" fn glBlitFramebuffer(
    srcX0: GLint,
    srcY0: GLint,
    srcX1: GLint,
    srcY1: GLint,
    dstX0: GLint,
    dstY0: GLint,
    dstX1: GLint,
    dstY1: GLint,
    mask: GLbitfield,
    filter: GLenum,
) {
    // Compiled into display lists, as Mesa's OPCODE_BLIT_FRAMEBUFFER.
    with_ctx_list(move |c| {
        let src = [srcX0, srcY0, srcX1, srcY1];
        c.blit_framebuffer(src, [dstX0, dstY0, dstX1, dstY1], mask, filter)
    })
}

c_fns! {
    /// glBlitFramebufferEXT (GL_EXT_framebuffer_blit; Mesa resolves it through
    /// OSMesaGetProcAddress without exporting it).
    #[allow(clippy::too_many_arguments)]
    safe fn glBlitFramebufferEXT(srcX0: GLint, srcY0: GLint, srcX1: GLint, srcY1: GLint, dstX0: GLint, dstY0: GLint, dstX1: GLint, dstY1: GLint, mask: GLbitfield, filter: GLenum) = framebuffers::glBlitFramebuffer;
}
