//! Texture calls (GL 1.1–1.3): objects, images, parameters, environment, texture units and
//! glMultiTexCoord*. Each entry point reads its pointer arguments and forwards to one
//! method of the state machine ([`crate::context::texture_spec`],
//! [`crate::context::texture_copy`], [`crate::context::texture_params`]), which validates
//! all arguments before changing any state.
#![allow(non_snake_case)]

use super::client::{image_command, read_f64, read_vec, write_all};
use super::enums::*;
use super::families::{c_fns, vector_fns};
use super::types::*;
use super::{compiling_list, non_negative, with_ctx, with_ctx_list, with_ctx_list_keep};
use crate::context::texture_get::{ints_rounded, ints_truncated};
use crate::context::{Context, GlResult};

/// glGenTextures.
///
/// # Safety
/// `textures` must be writable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenTextures(n: GLsizei, textures: *mut GLuint) {
    with_ctx(|c| {
        let n = non_negative(n)?;
        if !textures.is_null() {
            // SAFETY: the caller promises room for n names.
            c.gen_textures(unsafe { std::slice::from_raw_parts_mut(textures, n) });
        }
        Ok(())
    })
}

/// glDeleteTextures (bindings of deleted names revert to 0).
///
/// # Safety
/// `textures` must be readable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteTextures(n: GLsizei, textures: *const GLuint) {
    with_ctx(|c| {
        let n = non_negative(n)?;
        if textures.is_null() {
            return Ok(());
        }
        // SAFETY: the caller promises n readable names.
        c.delete_textures(unsafe { std::slice::from_raw_parts(textures, n) });
        Ok(())
    })
}

/// glBindTexture (a name first bound to another target: GL_INVALID_OPERATION).
#[no_mangle]
pub extern "C" fn glBindTexture(target: GLenum, texture: GLuint) {
    with_ctx_list_keep(move |c| c.bind_texture(target, texture))
}

/// glIsTexture.
#[no_mangle]
pub extern "C" fn glIsTexture(texture: GLuint) -> GLboolean {
    with_ctx(|c| Ok(c.textures.is_texture(texture) as GLboolean))
}

// The image calls: the image is read now, or copied into the display list being
// compiled (GL 1.5 §5.4), by [`image_command`].
c_fns! {
    /// glTexImage1D (`pixels`, if not null, holds the image the arguments and unpack state describe).
    unsafe fn glTexImage1D(target: GLenum, level: GLint, internalformat: GLint, width: GLsizei, border: GLint, format: GLenum, type_: GLenum, pixels: *const GLvoid) => image_command(1, (format, type_), (width, 1, 1), pixels, move |c: &mut Context, p, u| c.tex_image(target, level, (internalformat, width, 1, border, format, type_), p, 1, u));
    /// glTexImage2D (`pixels`, if not null, holds the image the arguments and unpack state describe).
    unsafe fn glTexImage2D(target: GLenum, level: GLint, internalformat: GLint, width: GLsizei, height: GLsizei, border: GLint, format: GLenum, type_: GLenum, pixels: *const GLvoid) => image_command(2, (format, type_), (width, height, 1), pixels, move |c: &mut Context, p, u| c.tex_image(target, level, (internalformat, width, height, border, format, type_), p, 2, u));
    /// glTexSubImage1D (`pixels` holds the image the arguments and unpack state describe).
    unsafe fn glTexSubImage1D(target: GLenum, level: GLint, xoffset: GLint, width: GLsizei, format: GLenum, type_: GLenum, pixels: *const GLvoid) => image_command(1, (format, type_), (width, 1, 1), pixels, move |c: &mut Context, p, u| c.tex_sub_image(target, level, (xoffset, 0, width, 1, format, type_), p, 1, u));
    /// glTexSubImage2D (`pixels` holds the image the arguments and unpack state describe).
    unsafe fn glTexSubImage2D(target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, width: GLsizei, height: GLsizei, format: GLenum, type_: GLenum, pixels: *const GLvoid) => image_command(2, (format, type_), (width, height, 1), pixels, move |c: &mut Context, p, u| c.tex_sub_image(target, level, (xoffset, yoffset, width, height, format, type_), p, 2, u));
}

// The copies from the read buffer (`copy_tex_image` / `copy_tex_sub_image` with the
// image's dimensions last).
c_fns! {
    safe fn glCopyTexImage1D(target: GLenum, level: GLint, internalformat: GLenum, x: GLint, y: GLint, width: GLsizei, border: GLint) => with_ctx_list(move |c| c.copy_tex_image(target, level, internalformat, x, y, width, 1, border, 1));
    safe fn glCopyTexImage2D(target: GLenum, level: GLint, internalformat: GLenum, x: GLint, y: GLint, width: GLsizei, height: GLsizei, border: GLint) => with_ctx_list(move |c| c.copy_tex_image(target, level, internalformat, x, y, width, height, border, 2));
    safe fn glCopyTexSubImage1D(target: GLenum, level: GLint, xoffset: GLint, x: GLint, y: GLint, width: GLsizei) => with_ctx_list(move |c| c.copy_tex_sub_image(target, level, xoffset, 0, x, y, width, 1, 1));
    safe fn glCopyTexSubImage2D(target: GLenum, level: GLint, xoffset: GLint, yoffset: GLint, x: GLint, y: GLint, width: GLsizei, height: GLsizei) => with_ctx_list(move |c| c.copy_tex_sub_image(target, level, xoffset, yoffset, x, y, width, height, 2));
}

/// glGetTexImage.
///
/// # Safety
/// `pixels` must be writable for the packed image of the level.
#[no_mangle]
pub unsafe extern "C" fn glGetTexImage(
    target: GLenum,
    level: GLint,
    format: GLenum,
    type_: GLenum,
    pixels: *mut GLvoid,
) {
    // SAFETY: forwarded caller contract.
    with_ctx(|c| unsafe { c.get_tex_image(target, level, (format, type_), pixels) })
}

/// glTexParameterf.
#[no_mangle]
pub extern "C" fn glTexParameterf(target: GLenum, pname: GLenum, param: GLfloat) {
    tex_parameter_one(target, pname, param as f64)
}

/// glTexParameteri.
#[no_mangle]
pub extern "C" fn glTexParameteri(target: GLenum, pname: GLenum, param: GLint) {
    tex_parameter_one(target, pname, param as f64)
}

/// The scalar glTexParameter forms, with the value as `f64`. Mesa compiles them as
/// glTexParameterfv with (param, 0, 0, 0) (`save_TexParameter*`), so in a display list
/// GL_TEXTURE_BORDER_COLOR is accepted (an integer converted, as glTexParameterfv, not
/// normalised).
fn tex_parameter_one(target: GLenum, pname: GLenum, param: f64) {
    let v = [param, 0.0, 0.0, 0.0];
    if pname == GL_TEXTURE_BORDER_COLOR && compiling_list() {
        return with_ctx_list(move |c| c.tex_parameter(target, pname, &v, false));
    }
    with_ctx_list(move |c| c.tex_parameter_scalar(target, pname, v[0]))
}

/// The parameter vector calls: as many values as `pname` takes (4 for `color`, the
/// colour parameter, otherwise 1), converted to `f64`, for `set` (nothing for NULL).
///
/// # Safety
/// `params` must be NULL or readable for the values `pname` takes.
unsafe fn set_params<T: Copy + Into<f64>>(
    params: *const T,
    (pname, color): (GLenum, GLenum),
    set: impl Fn(&mut Context, &[f64]) -> GlResult<()> + Send + Sync + 'static,
) {
    let n = if pname == color { 4 } else { 1 };
    // SAFETY: the caller promises n readable values.
    if let Some(v) = unsafe { read_f64(params, n) } {
        with_ctx_list(move |c| set(c, &v))
    }
}

/// The parameter queries: the values `get` answers, each converted by `conv`, written
/// through `params`.
///
/// # Safety
/// `params` must be NULL or writable for the values.
unsafe fn get_params<S: Copy, T>(
    params: *mut T,
    get: impl FnOnce(&mut Context) -> GlResult<Vec<S>>,
    conv: impl Fn(S) -> T,
) {
    with_ctx(|c| {
        let v = get(c)?;
        // SAFETY: the caller promises room for the values.
        unsafe { write_all(params, &v, conv) };
        Ok(())
    })
}

c_fns! {
    /// glTexParameterfv (4 values for GL_TEXTURE_BORDER_COLOR).
    unsafe fn glTexParameterfv(target: GLenum, pname: GLenum, params: *const GLfloat) => set_params(params, (pname, GL_TEXTURE_BORDER_COLOR), move |c, v| c.tex_parameter(target, pname, v, false));
    /// glTexParameteriv (4 values for GL_TEXTURE_BORDER_COLOR).
    unsafe fn glTexParameteriv(target: GLenum, pname: GLenum, params: *const GLint) => set_params(params, (pname, GL_TEXTURE_BORDER_COLOR), move |c, v| c.tex_parameter(target, pname, v, true));
    unsafe fn glGetTexParameterfv(target: GLenum, pname: GLenum, params: *mut GLfloat) => get_params(params, |c| Ok(c.get_tex_parameter(target, pname)?.0), |x| x as f32);
    /// glGetTexParameteriv (normalized values truncated, as Mesa's FLOAT_TO_INT).
    unsafe fn glGetTexParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) => get_params(params, |c| Ok(ints_truncated(c.get_tex_parameter(target, pname)?)), |x| x);
    unsafe fn glGetTexLevelParameterfv(target: GLenum, level: GLint, pname: GLenum, params: *mut GLfloat) => get_params(params, |c| Ok(vec![c.get_tex_level_parameter(target, level, pname)?]), |x| x as f32);
    unsafe fn glGetTexLevelParameteriv(target: GLenum, level: GLint, pname: GLenum, params: *mut GLint) => get_params(params, |c| Ok(vec![c.get_tex_level_parameter(target, level, pname)?]), |x| x as i32);
}

/// glTexEnvf.
#[no_mangle]
pub extern "C" fn glTexEnvf(target: GLenum, pname: GLenum, param: GLfloat) {
    with_ctx_list_keep(move |c| c.tex_env_scalar(target, pname, param as f64))
}

/// glTexEnvi.
#[no_mangle]
pub extern "C" fn glTexEnvi(target: GLenum, pname: GLenum, param: GLint) {
    with_ctx_list_keep(move |c| c.tex_env_scalar(target, pname, param as f64))
}

c_fns! {
    /// glTexEnvfv (4 values for GL_TEXTURE_ENV_COLOR).
    unsafe fn glTexEnvfv(target: GLenum, pname: GLenum, params: *const GLfloat) => set_params(params, (pname, GL_TEXTURE_ENV_COLOR), move |c, v| c.tex_env(target, pname, v, false));
    /// glTexEnviv (4 values for GL_TEXTURE_ENV_COLOR).
    unsafe fn glTexEnviv(target: GLenum, pname: GLenum, params: *const GLint) => set_params(params, (pname, GL_TEXTURE_ENV_COLOR), move |c, v| c.tex_env(target, pname, v, true));
    unsafe fn glGetTexEnvfv(target: GLenum, pname: GLenum, params: *mut GLfloat) => get_params(params, |c| Ok(c.get_tex_env(target, pname)?.0), |x| x as f32);
    /// glGetTexEnviv (normalized values rounded).
    unsafe fn glGetTexEnviv(target: GLenum, pname: GLenum, params: *mut GLint) => get_params(params, |c| Ok(ints_rounded(c.get_tex_env(target, pname)?)), |x| x);
}

/// glActiveTexture (GL_TEXTUREi, i < GL_MAX_TEXTURE_UNITS). Mesa's rule is i < the larger
/// of the combined image-unit and texture-coordinate limits; softgl has no shader image
/// units, so both are GL_MAX_TEXTURE_UNITS (8), where llvmpipe's combined limit is 192 (piglit's
/// `texunits` expects GL_INVALID_ENUM at the limit the implementation reports).
/// `state.caps` for GL_TEXTURE_1D/2D follows the unit.
#[no_mangle]
pub extern "C" fn glActiveTexture(texture: GLenum) {
    with_ctx_list_keep(move |c| c.active_texture(texture))
}

/// glClientActiveTexture.
#[no_mangle]
pub extern "C" fn glClientActiveTexture(texture: GLenum) {
    super::with_ctx_keep(|c| c.client_active_texture(texture))
}

/// glPrioritizeTextures (priorities are stored; residency is always true).
///
/// # Safety
/// `textures` and `priorities` must be readable for `n` values.
#[no_mangle]
pub unsafe extern "C" fn glPrioritizeTextures(
    n: GLsizei,
    textures: *const GLuint,
    priorities: *const GLclampf,
) {
    // SAFETY: the caller promises n readable values in each array.
    let arrays =
        non_negative(n).map(|n| unsafe { (read_vec(textures, n), read_vec(priorities, n)) });
    with_ctx_list(move |c| {
        let (names, prios) = arrays.as_ref().map_err(|e| *e)?;
        c.prioritize_textures(names, prios);
        Ok(())
    })
}

/// glAreTexturesResident: GL_TRUE for valid names (software textures are always resident);
/// GL_INVALID_VALUE for 0 or an unknown name.
///
/// # Safety
/// `textures` must be readable for `n` names; `residences` writable for `n` values.
#[no_mangle]
pub unsafe extern "C" fn glAreTexturesResident(
    n: GLsizei,
    textures: *const GLuint,
    residences: *mut GLboolean,
) -> GLboolean {
    with_ctx(|c| {
        let n = non_negative(n)?;
        if textures.is_null() {
            return Ok(GL_TRUE as GLboolean);
        }
        // SAFETY: the caller promises n readable names.
        c.are_textures_resident(unsafe { std::slice::from_raw_parts(textures, n) })?;
        let _ = residences;
        Ok(GL_TRUE as GLboolean)
    })
}

/// Sets the current texture coordinate of unit `target - GL_TEXTURE0`.
fn multi_texcoord(target: GLenum, v: [f32; 4]) {
    // As Mesa (immediate mode and display lists alike): the unit is the target's low three
    // bits, with no error for a target outside GL_TEXTURE0..7.
    let u = (target & 7) as u8;
    super::with_ctx_vertex(crate::context::dlist::VertexOp::TexCoord(u, v))
}

vector_fns! {
    multi_texcoord cast [0.0, 0.0, 0.0, 1.0] {
        (target: GLenum; s) glMultiTexCoord1s glMultiTexCoord1sv GLshort, glMultiTexCoord1i glMultiTexCoord1iv GLint, glMultiTexCoord1f glMultiTexCoord1fv GLfloat, glMultiTexCoord1d glMultiTexCoord1dv GLdouble;
        (target: GLenum; s, t) glMultiTexCoord2s glMultiTexCoord2sv GLshort, glMultiTexCoord2i glMultiTexCoord2iv GLint, glMultiTexCoord2f glMultiTexCoord2fv GLfloat, glMultiTexCoord2d glMultiTexCoord2dv GLdouble;
        (target: GLenum; s, t, r) glMultiTexCoord3s glMultiTexCoord3sv GLshort, glMultiTexCoord3i glMultiTexCoord3iv GLint, glMultiTexCoord3f glMultiTexCoord3fv GLfloat, glMultiTexCoord3d glMultiTexCoord3dv GLdouble;
        (target: GLenum; s, t, r, q) glMultiTexCoord4s glMultiTexCoord4sv GLshort, glMultiTexCoord4i glMultiTexCoord4iv GLint, glMultiTexCoord4f glMultiTexCoord4fv GLfloat, glMultiTexCoord4d glMultiTexCoord4dv GLdouble;
    }
}
