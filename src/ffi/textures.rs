//! Texture calls (GL 1.1–1.3): objects, images, parameters, environment, texture units and
//! glMultiTexCoord*. Each entry point reads its pointer arguments and forwards to one
//! method of the state machine ([`crate::context::texture_spec`],
//! [`crate::context::texture_copy`], [`crate::context::texture_params`]), which validates
//! all arguments before changing any state.
#![allow(non_snake_case)]

use super::enums::*;
use super::families::vector_fns;
use super::types::*;
use super::{compiling_list, non_negative, with_ctx, with_ctx_list};
use crate::context::pack::tex::{ClientFormat, Layout};
use crate::context::state::PixelStore;
use crate::context::GlError;
use crate::texture::MAX_TEXTURE_SIZE;
use libc::c_void;

/// A client image copied while a display list is being compiled (GL 1.5 §5.4: the pixels
/// are unpacked from client memory when the command is compiled), with the pixel-store
/// state that describes the copy.
struct ClientImage {
    /// The bytes the image spans, or `None` for a null pointer or an invalid description
    /// (whose error the compiled command raises when it runs).
    bytes: Option<Vec<u8>>,
    /// The unpack state at compile time.
    unpack: PixelStore,
}

impl ClientImage {
    /// Copies the `w` x `h` image at `data` under the current unpack state.
    ///
    /// # Safety
    /// `data` (if not null) must hold the image the arguments and unpack state describe.
    unsafe fn read(
        format: GLenum,
        ty: GLenum,
        w: GLsizei,
        h: GLsizei,
        data: *const c_void,
    ) -> Self {
        let unpack = super::with_ctx_raw(|c| Ok(c.state.unpack));
        let bytes = (|| {
            let (w, h) = (usize::try_from(w).ok()?, usize::try_from(h).ok()?);
            // Larger images fail validation when the command runs: nothing to copy.
            if data.is_null() || w > MAX_TEXTURE_SIZE + 2 || h > MAX_TEXTURE_SIZE + 2 {
                return None;
            }
            let span = if format == GL_COLOR_INDEX {
                crate::context::texture_ci::span(ty, &unpack, w, h)?
            } else {
                Layout::new(&unpack, w, &ClientFormat::new(format, ty).ok()?).span(w, h)
            };
            // SAFETY: the caller promises the described image is readable.
            Some(unsafe { std::slice::from_raw_parts(data as *const u8, span) }.to_vec())
        })();
        ClientImage { bytes, unpack }
    }

    /// The copy's address (null when there is none).
    fn ptr(&self) -> *const c_void {
        self.bytes
            .as_ref()
            .map_or(std::ptr::null(), |b| b.as_ptr() as *const c_void)
    }
}

/// Whether a display list is being compiled on the current context.
pub(crate) fn compiling() -> bool {
    super::with_ctx_raw(|c| Ok(c.lists.compile_mode().is_some()))
}

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
    with_ctx_list(move |c| c.bind_texture(target, texture))
}

/// glIsTexture.
#[no_mangle]
pub extern "C" fn glIsTexture(texture: GLuint) -> GLboolean {
    with_ctx(|c| Ok(c.textures.is_texture(texture) as GLboolean))
}

/// glTexImage1D.
///
/// # Safety
/// `pixels` (if not null) must hold the image described by the arguments and unpack state.
#[no_mangle]
pub unsafe extern "C" fn glTexImage1D(
    target: GLenum,
    level: GLint,
    internalformat: GLint,
    width: GLsizei,
    border: GLint,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    if compiling() {
        // SAFETY: forwarded caller contract.
        let img = unsafe { ClientImage::read(format, type_, width, 1, pixels) };
        // SAFETY: the copy holds the described image.
        return with_ctx_list(move |c| unsafe {
            let args = (internalformat, width, 1, border, format, type_);
            c.tex_image(target, level, args, img.ptr(), 1, img.unpack)
        });
    }
    // SAFETY: forwarded caller contract.
    with_ctx(|c| unsafe {
        let args = (internalformat, width, 1, border, format, type_);
        c.tex_image(target, level, args, pixels, 1, c.state.unpack)
    })
}

/// glTexImage2D.
///
/// # Safety
/// `pixels` (if not null) must hold the image described by the arguments and unpack state.
#[no_mangle]
pub unsafe extern "C" fn glTexImage2D(
    target: GLenum,
    level: GLint,
    internalformat: GLint,
    width: GLsizei,
    height: GLsizei,
    border: GLint,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    if compiling() {
        // SAFETY: forwarded caller contract.
        let img = unsafe { ClientImage::read(format, type_, width, height, pixels) };
        // SAFETY: the copy holds the described image.
        return with_ctx_list(move |c| unsafe {
            let args = (internalformat, width, height, border, format, type_);
            c.tex_image(target, level, args, img.ptr(), 2, img.unpack)
        });
    }
    // SAFETY: forwarded caller contract.
    with_ctx(|c| unsafe {
        let args = (internalformat, width, height, border, format, type_);
        c.tex_image(target, level, args, pixels, 2, c.state.unpack)
    })
}

/// glTexSubImage1D.
///
/// # Safety
/// `pixels` must hold the image described by the arguments and unpack state.
#[no_mangle]
pub unsafe extern "C" fn glTexSubImage1D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    width: GLsizei,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    if compiling() {
        // SAFETY: forwarded caller contract.
        let img = unsafe { ClientImage::read(format, type_, width, 1, pixels) };
        // SAFETY: the copy holds the described image.
        return with_ctx_list(move |c| unsafe {
            let args = (xoffset, 0, width, 1, format, type_);
            c.tex_sub_image(target, level, args, img.ptr(), 1, img.unpack)
        });
    }
    // SAFETY: forwarded caller contract.
    with_ctx(|c| unsafe {
        let args = (xoffset, 0, width, 1, format, type_);
        c.tex_sub_image(target, level, args, pixels, 1, c.state.unpack)
    })
}

/// glTexSubImage2D.
///
/// # Safety
/// `pixels` must hold the image described by the arguments and unpack state.
#[no_mangle]
pub unsafe extern "C" fn glTexSubImage2D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    width: GLsizei,
    height: GLsizei,
    format: GLenum,
    type_: GLenum,
    pixels: *const GLvoid,
) {
    if compiling() {
        // SAFETY: forwarded caller contract.
        let img = unsafe { ClientImage::read(format, type_, width, height, pixels) };
        // SAFETY: the copy holds the described image.
        return with_ctx_list(move |c| unsafe {
            let args = (xoffset, yoffset, width, height, format, type_);
            c.tex_sub_image(target, level, args, img.ptr(), 2, img.unpack)
        });
    }
    // SAFETY: forwarded caller contract.
    with_ctx(|c| unsafe {
        let args = (xoffset, yoffset, width, height, format, type_);
        c.tex_sub_image(target, level, args, pixels, 2, c.state.unpack)
    })
}

/// glCopyTexImage1D.
#[no_mangle]
pub extern "C" fn glCopyTexImage1D(
    target: GLenum,
    level: GLint,
    internalformat: GLenum,
    x: GLint,
    y: GLint,
    width: GLsizei,
    border: GLint,
) {
    with_ctx_list(move |c| {
        c.copy_tex_image(target, level, internalformat, x, y, width, 1, border, 1)
    })
}

/// glCopyTexImage2D.
#[no_mangle]
pub extern "C" fn glCopyTexImage2D(
    target: GLenum,
    level: GLint,
    internalformat: GLenum,
    x: GLint,
    y: GLint,
    width: GLsizei,
    height: GLsizei,
    border: GLint,
) {
    with_ctx_list(move |c| {
        c.copy_tex_image(
            target,
            level,
            internalformat,
            x,
            y,
            width,
            height,
            border,
            2,
        )
    })
}

/// glCopyTexSubImage1D.
#[no_mangle]
pub extern "C" fn glCopyTexSubImage1D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    x: GLint,
    y: GLint,
    width: GLsizei,
) {
    with_ctx_list(move |c| c.copy_tex_sub_image(target, level, xoffset, 0, x, y, width, 1, 1))
}

/// glCopyTexSubImage2D.
#[no_mangle]
pub extern "C" fn glCopyTexSubImage2D(
    target: GLenum,
    level: GLint,
    xoffset: GLint,
    yoffset: GLint,
    x: GLint,
    y: GLint,
    width: GLsizei,
    height: GLsizei,
) {
    with_ctx_list(move |c| {
        c.copy_tex_sub_image(target, level, xoffset, yoffset, x, y, width, height, 2)
    })
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
    // Mesa compiles the scalar forms as glTexParameterfv with (param, 0, 0, 0)
    // (`save_TexParameter*`), so in a display list GL_TEXTURE_BORDER_COLOR is accepted.
    let v = [param as f64, 0.0, 0.0, 0.0];
    if pname == GL_TEXTURE_BORDER_COLOR && compiling_list() {
        return with_ctx_list(move |c| c.tex_parameter(target, pname, &v, false));
    }
    with_ctx_list(move |c| c.tex_parameter_scalar(target, pname, v[0]))
}

/// glTexParameteri.
#[no_mangle]
pub extern "C" fn glTexParameteri(target: GLenum, pname: GLenum, param: GLint) {
    // Mesa compiles the scalar forms as glTexParameterfv with (param, 0, 0, 0)
    // (`save_TexParameter*`), so in a display list GL_TEXTURE_BORDER_COLOR is accepted.
    let v = [param as f64, 0.0, 0.0, 0.0];
    if pname == GL_TEXTURE_BORDER_COLOR && compiling_list() {
        // (as glTexParameterfv: the integer is converted, not normalised)
        return with_ctx_list(move |c| c.tex_parameter(target, pname, &v, false));
    }
    with_ctx_list(move |c| c.tex_parameter_scalar(target, pname, v[0]))
}

/// glTexParameterfv.
///
/// # Safety
/// `params` must hold the parameter's values (4 for GL_TEXTURE_BORDER_COLOR).
#[no_mangle]
pub unsafe extern "C" fn glTexParameterfv(target: GLenum, pname: GLenum, params: *const GLfloat) {
    if params.is_null() {
        return;
    }
    let n = if pname == GL_TEXTURE_BORDER_COLOR {
        4
    } else {
        1
    };
    // SAFETY: the caller promises n readable values.
    let v = unsafe { std::slice::from_raw_parts(params, n) };
    let v: Vec<f64> = v.iter().map(|&x| x as f64).collect();
    with_ctx_list(move |c| c.tex_parameter(target, pname, &v, false))
}

/// glTexParameteriv.
///
/// # Safety
/// `params` must hold the parameter's values (4 for GL_TEXTURE_BORDER_COLOR).
#[no_mangle]
pub unsafe extern "C" fn glTexParameteriv(target: GLenum, pname: GLenum, params: *const GLint) {
    if params.is_null() {
        return;
    }
    let n = if pname == GL_TEXTURE_BORDER_COLOR {
        4
    } else {
        1
    };
    // SAFETY: the caller promises n readable values.
    let v = unsafe { std::slice::from_raw_parts(params, n) };
    let v: Vec<f64> = v.iter().map(|&x| x as f64).collect();
    with_ctx_list(move |c| c.tex_parameter(target, pname, &v, true))
}

/// glGetTexParameterfv.
///
/// # Safety
/// `params` must be writable for the parameter's values.
#[no_mangle]
pub unsafe extern "C" fn glGetTexParameterfv(target: GLenum, pname: GLenum, params: *mut GLfloat) {
    with_ctx(|c| {
        let (v, _) = c.get_tex_parameter(target, pname)?;
        if !params.is_null() {
            for (i, x) in v.iter().enumerate() {
                // SAFETY: the caller promises room for the values.
                unsafe { *params.add(i) = *x as f32 };
            }
        }
        Ok(())
    })
}

/// glGetTexParameteriv.
///
/// # Safety
/// `params` must be writable for the parameter's values.
#[no_mangle]
pub unsafe extern "C" fn glGetTexParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) {
    with_ctx(|c| {
        let (v, normalized) = c.get_tex_parameter(target, pname)?;
        if !params.is_null() {
            for (i, x) in v.iter().enumerate() {
                let iv = if normalized {
                    // Mesa's FLOAT_TO_INT truncates: 0.25 → 536870911
                    (x * 2147483647.0) as i32
                } else {
                    x.round() as i32
                };
                // SAFETY: the caller promises room for the values.
                unsafe { *params.add(i) = iv };
            }
        }
        Ok(())
    })
}

/// glGetTexLevelParameterfv.
///
/// # Safety
/// `params` must be writable.
#[no_mangle]
pub unsafe extern "C" fn glGetTexLevelParameterfv(
    target: GLenum,
    level: GLint,
    pname: GLenum,
    params: *mut GLfloat,
) {
    with_ctx(|c| {
        let v = c.get_tex_level_parameter(target, level, pname)?;
        if !params.is_null() {
            // SAFETY: the caller promises a writable value.
            unsafe { *params = v as f32 };
        }
        Ok(())
    })
}

/// glGetTexLevelParameteriv.
///
/// # Safety
/// `params` must be writable.
#[no_mangle]
pub unsafe extern "C" fn glGetTexLevelParameteriv(
    target: GLenum,
    level: GLint,
    pname: GLenum,
    params: *mut GLint,
) {
    with_ctx(|c| {
        let v = c.get_tex_level_parameter(target, level, pname)?;
        if !params.is_null() {
            // SAFETY: the caller promises a writable value.
            unsafe { *params = v as i32 };
        }
        Ok(())
    })
}

/// glTexEnvf.
#[no_mangle]
pub extern "C" fn glTexEnvf(target: GLenum, pname: GLenum, param: GLfloat) {
    with_ctx_list(move |c| c.tex_env_scalar(target, pname, param as f64))
}

/// glTexEnvi.
#[no_mangle]
pub extern "C" fn glTexEnvi(target: GLenum, pname: GLenum, param: GLint) {
    with_ctx_list(move |c| c.tex_env_scalar(target, pname, param as f64))
}

/// glTexEnvfv.
///
/// # Safety
/// `params` must hold the parameter's values (4 for GL_TEXTURE_ENV_COLOR).
#[no_mangle]
pub unsafe extern "C" fn glTexEnvfv(target: GLenum, pname: GLenum, params: *const GLfloat) {
    if params.is_null() {
        return;
    }
    let n = if pname == GL_TEXTURE_ENV_COLOR { 4 } else { 1 };
    // SAFETY: the caller promises n readable values.
    let v = unsafe { std::slice::from_raw_parts(params, n) };
    let v: Vec<f64> = v.iter().map(|&x| x as f64).collect();
    with_ctx_list(move |c| c.tex_env(target, pname, &v, false))
}

/// glTexEnviv.
///
/// # Safety
/// `params` must hold the parameter's values (4 for GL_TEXTURE_ENV_COLOR).
#[no_mangle]
pub unsafe extern "C" fn glTexEnviv(target: GLenum, pname: GLenum, params: *const GLint) {
    if params.is_null() {
        return;
    }
    let n = if pname == GL_TEXTURE_ENV_COLOR { 4 } else { 1 };
    // SAFETY: the caller promises n readable values.
    let v = unsafe { std::slice::from_raw_parts(params, n) };
    let v: Vec<f64> = v.iter().map(|&x| x as f64).collect();
    with_ctx_list(move |c| c.tex_env(target, pname, &v, true))
}

/// glGetTexEnvfv.
///
/// # Safety
/// `params` must be writable for the parameter's values.
#[no_mangle]
pub unsafe extern "C" fn glGetTexEnvfv(target: GLenum, pname: GLenum, params: *mut GLfloat) {
    with_ctx(|c| {
        let (v, _) = c.get_tex_env(target, pname)?;
        if !params.is_null() {
            for (i, x) in v.iter().enumerate() {
                // SAFETY: the caller promises room for the values.
                unsafe { *params.add(i) = *x as f32 };
            }
        }
        Ok(())
    })
}

/// glGetTexEnviv.
///
/// # Safety
/// `params` must be writable for the parameter's values.
#[no_mangle]
pub unsafe extern "C" fn glGetTexEnviv(target: GLenum, pname: GLenum, params: *mut GLint) {
    with_ctx(|c| {
        let (v, normalized) = c.get_tex_env(target, pname)?;
        if !params.is_null() {
            for (i, x) in v.iter().enumerate() {
                let iv = if normalized {
                    (x * 2147483647.0).round() as i32
                } else {
                    x.round() as i32
                };
                // SAFETY: the caller promises room for the values.
                unsafe { *params.add(i) = iv };
            }
        }
        Ok(())
    })
}

/// glActiveTexture (GL_TEXTUREi, i < GL_MAX_TEXTURE_UNITS). Mesa's rule is i < the larger
/// of the combined image-unit and texture-coordinate limits; softgl has no shader image
/// units, so both are GL_MAX_TEXTURE_UNITS (8), where llvmpipe's combined limit is 192 (piglit's
/// `texunits` expects GL_INVALID_ENUM at the limit the implementation reports).
/// `state.caps` for GL_TEXTURE_1D/2D follows the unit.
#[no_mangle]
pub extern "C" fn glActiveTexture(texture: GLenum) {
    with_ctx_list(move |c| c.active_texture(texture))
}

/// glClientActiveTexture.
#[no_mangle]
pub extern "C" fn glClientActiveTexture(texture: GLenum) {
    with_ctx(|c| c.client_active_texture(texture))
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
    let read = || -> Result<(Vec<GLuint>, Vec<GLclampf>), GlError> {
        let n = non_negative(n)?;
        if textures.is_null() || priorities.is_null() {
            return Ok((Vec::new(), Vec::new()));
        }
        // SAFETY: the caller promises n readable values in each array.
        Ok(unsafe {
            (
                std::slice::from_raw_parts(textures, n).to_vec(),
                std::slice::from_raw_parts(priorities, n).to_vec(),
            )
        })
    };
    let arrays = read();
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
