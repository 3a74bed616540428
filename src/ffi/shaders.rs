//! GL 2.0 shader and program objects at the C boundary: glCreateShader … glDeleteProgram,
//! the object queries, attribute locations and the active-variable queries (the state and
//! rules are in [`crate::context::shader_objects`], [`crate::context::program_link`] and
//! [`crate::context::uniforms`]; the glUniform families are in [`super::shaders_uniform`],
//! the ARB_shader_objects names in [`super::shaders_arb`]).
//!
//! Drawing with a program in use is not implemented yet (draws stay fixed-function), so
//! GL_VERSION still says 1.5; these entry points exist so that programs can compile,
//! link and query shaders against softgl.
#![allow(non_snake_case)]

use super::client::write_one;
use super::families::c_fns;
use super::types::*;
use super::with_ctx;
use crate::context::shader_objects::{gl_copy, ObjectText};
use crate::context::GlError;

/// The NUL-terminated string at `p` (`None` when `p` is null).
///
/// # Safety
/// `p`, when not null, must point to a NUL-terminated string.
pub(crate) unsafe fn c_string(p: *const GLchar) -> Option<String> {
    if p.is_null() {
        return None;
    }
    // SAFETY: the caller promises a NUL-terminated string.
    let s = unsafe { std::ffi::CStr::from_ptr(p) };
    Some(String::from_utf8_lossy(s.to_bytes()).into_owned())
}

/// Writes `text` as a GL string: at most `buf_size - 1` bytes and a NUL to `out`, the
/// length written (without the NUL) to `length`.
///
/// # Safety
/// `out`, when not null, must be writable for `buf_size` bytes; `length` null or writable.
pub(crate) unsafe fn write_text(
    text: &str,
    buf_size: GLsizei,
    length: *mut GLsizei,
    out: *mut GLchar,
) {
    let (bytes, n) = gl_copy(text, buf_size);
    if !out.is_null() {
        for (i, b) in bytes.iter().enumerate() {
            // SAFETY: `bytes` has at most `buf_size` bytes, the room the caller promises.
            unsafe { out.add(i).write(*b as GLchar) };
        }
    }
    // SAFETY: forwarded caller contract.
    unsafe { write_one(length, if out.is_null() { 0 } else { n }) };
}

/// glShaderSource: the `count` strings, each `length[i]` bytes long (NUL-terminated when
/// `length` is null or `length[i]` is negative), concatenated.
///
/// # Safety
/// `strings` must hold `count` pointers to strings as `length` describes.
unsafe fn shader_source(
    shader: GLuint,
    count: GLsizei,
    strings: *const *const GLchar,
    length: *const GLint,
) {
    with_ctx(|c| {
        c.shaders.table.shader(shader)?;
        if count < 0 || strings.is_null() {
            return Err(GlError::InvalidValue);
        }
        let mut src = Vec::new();
        for i in 0..count as usize {
            // SAFETY: the caller promises `count` string pointers (and lengths).
            let (p, len) = unsafe {
                (
                    *strings.add(i),
                    if length.is_null() { -1 } else { *length.add(i) },
                )
            };
            if p.is_null() {
                return Err(GlError::InvalidOperation);
            }
            if len < 0 {
                // SAFETY: NUL-terminated, as promised for a negative length.
                src.extend_from_slice(unsafe { std::ffi::CStr::from_ptr(p) }.to_bytes());
            } else {
                // SAFETY: `len` readable bytes, as promised.
                src.extend_from_slice(unsafe {
                    std::slice::from_raw_parts(p as *const u8, len as usize)
                });
            }
        }
        c.shader_source(shader, String::from_utf8_lossy(&src).into_owned())
    })
}

/// glGetShaderInfoLog / glGetProgramInfoLog / glGetShaderSource.
///
/// # Safety
/// `out` null or writable for `buf_size` bytes; `length` null or writable.
unsafe fn object_text(
    name: GLuint,
    buf_size: GLsizei,
    length: *mut GLsizei,
    out: *mut GLchar,
    which: ObjectText,
) {
    with_ctx(|c| {
        let t = c.object_text(name, buf_size, which)?;
        // SAFETY: forwarded caller contract.
        unsafe { write_text(&t, buf_size, length, out) };
        Ok(())
    })
}

/// glGetShaderiv / glGetProgramiv (`program` picks which).
///
/// # Safety
/// `params` null or writable for one GLint.
unsafe fn object_iv(name: GLuint, pname: GLenum, params: *mut GLint, program: bool) {
    with_ctx(|c| {
        let v = if program {
            c.get_program(name, pname)?
        } else {
            c.get_shader(name, pname)?
        };
        // SAFETY: forwarded caller contract.
        unsafe { write_one(params, v) };
        Ok(())
    })
}

/// glGetAttachedShaders.
///
/// # Safety
/// `shaders` null or writable for `max_count` names; `count` null or writable.
unsafe fn attached(program: GLuint, max_count: GLsizei, count: *mut GLsizei, shaders: *mut GLuint) {
    with_ctx(|c| {
        let names = c.attached_shaders(program, max_count)?;
        let n = if shaders.is_null() { 0 } else { names.len() };
        // SAFETY: at most `max_count` names, the room promised.
        unsafe {
            super::client::write_all(shaders, &names, |v| v);
            write_one(count, n as GLsizei);
        }
        Ok(())
    })
}

/// glGetActiveUniform / glGetActiveAttrib (`uniform` picks which).
///
/// # Safety
/// The out pointers null or writable (`name` for `buf_size` bytes).
#[allow(clippy::too_many_arguments)]
unsafe fn active(
    program: GLuint,
    index: GLuint,
    buf_size: GLsizei,
    length: *mut GLsizei,
    size: *mut GLint,
    type_: *mut GLenum,
    name: *mut GLchar,
    uniform: bool,
) {
    with_ctx(|c| {
        let (n, s, t) = if uniform {
            c.active_uniform(program, index, buf_size)?
        } else {
            c.active_attrib(program, index, buf_size)?
        };
        // SAFETY: forwarded caller contract.
        unsafe {
            write_text(&n, buf_size, length, name);
            write_one(size, s);
            write_one(type_, t);
        }
        Ok(())
    })
}

/// glGetUniformLocation / glGetAttribLocation (`uniform` picks which): -1 for a null name.
///
/// # Safety
/// `name` null or a NUL-terminated string.
unsafe fn location(program: GLuint, name: *const GLchar, uniform: bool) -> GLint {
    let r = with_ctx(|c| {
        // SAFETY: forwarded caller contract (read only with a context, as GL would).
        let name = unsafe { c_string(name) };
        // A null name is looked up as a built-in one: the program's errors still come.
        let name = name.as_deref().unwrap_or("gl_");
        Ok(Some(if uniform {
            c.uniform_location(program, name)?
        } else {
            c.attrib_location(program, name)?
        }))
    });
    r.unwrap_or(-1)
}

/// glBindAttribLocation (a null name does nothing, as in Mesa).
///
/// # Safety
/// `name` null or a NUL-terminated string.
unsafe fn bind_attrib(program: GLuint, index: GLuint, name: *const GLchar) {
    with_ctx(|c| {
        // SAFETY: forwarded caller contract.
        match unsafe { c_string(name) } {
            Some(n) => c.bind_attrib_location(program, index, &n),
            None => c.shaders.table.program(program).map(|_| ()),
        }
    })
}

/// glBindFragDataLocation (a null name does nothing after the program's checks, as in
/// Mesa).
///
/// # Safety
/// `name` null or a NUL-terminated string.
unsafe fn bind_frag_data(program: GLuint, color: GLuint, name: *const GLchar) {
    with_ctx(|c| {
        // SAFETY: forwarded caller contract.
        match unsafe { c_string(name) } {
            Some(n) => c.bind_frag_data_location(program, color, &n),
            None => c.shaders.table.program(program).map(|_| ()),
        }
    })
}

/// glGetFragDataLocation: -1 for a null name (after the program's checks) or on error.
///
/// # Safety
/// `name` null or a NUL-terminated string.
unsafe fn frag_data_location(program: GLuint, name: *const GLchar) -> GLint {
    let r = with_ctx(|c| {
        // SAFETY: forwarded caller contract (read only with a context, as GL would).
        let name = unsafe { c_string(name) };
        let name = name.as_deref().unwrap_or("gl_");
        Ok(Some(c.frag_data_location(program, name)?))
    });
    r.unwrap_or(-1)
}

c_fns! {
    unsafe fn glBindFragDataLocation(program: GLuint, color: GLuint, name: *const GLchar) => bind_frag_data(program, color, name);
    unsafe fn glGetFragDataLocation(program: GLuint, name: *const GLchar) -> GLint => frag_data_location(program, name);
    unsafe fn glBindFragDataLocationEXT(program: GLuint, color: GLuint, name: *const GLchar) = shaders::glBindFragDataLocation;
    unsafe fn glGetFragDataLocationEXT(program: GLuint, name: *const GLchar) -> GLint = shaders::glGetFragDataLocation;
    safe fn glCreateShader(type_: GLenum) -> GLuint => with_ctx(|c| c.create_shader(type_));
    safe fn glCreateProgram() -> GLuint => with_ctx(|c| Ok(c.create_program()));
    unsafe fn glShaderSource(shader: GLuint, count: GLsizei, string: *const *const GLchar, length: *const GLint) => shader_source(shader, count, string, length);
    safe fn glCompileShader(shader: GLuint) => with_ctx(|c| c.compile_shader(shader));
    safe fn glDeleteShader(shader: GLuint) => with_ctx(|c| c.delete_shader(shader));
    safe fn glDeleteProgram(program: GLuint) => with_ctx(|c| c.delete_program(program));
    safe fn glIsShader(shader: GLuint) -> GLboolean => with_ctx(|c| Ok(c.is_shader(shader) as GLboolean));
    safe fn glIsProgram(program: GLuint) -> GLboolean => with_ctx(|c| Ok(c.is_program(program) as GLboolean));
    safe fn glAttachShader(program: GLuint, shader: GLuint) => with_ctx(|c| c.attach_shader(program, shader));
    safe fn glDetachShader(program: GLuint, shader: GLuint) => with_ctx(|c| c.detach_shader(program, shader));
    unsafe fn glGetAttachedShaders(program: GLuint, max_count: GLsizei, count: *mut GLsizei, shaders: *mut GLuint) => attached(program, max_count, count, shaders);
    safe fn glLinkProgram(program: GLuint) => with_ctx(|c| c.link_program(program));
    safe fn glValidateProgram(program: GLuint) => with_ctx(|c| c.validate_program(program));
    safe fn glUseProgram(program: GLuint) => super::with_ctx_keep(|c| c.use_program(program));
    unsafe fn glGetShaderiv(shader: GLuint, pname: GLenum, params: *mut GLint) => object_iv(shader, pname, params, false);
    unsafe fn glGetProgramiv(program: GLuint, pname: GLenum, params: *mut GLint) => object_iv(program, pname, params, true);
    unsafe fn glGetShaderInfoLog(shader: GLuint, buf_size: GLsizei, length: *mut GLsizei, info_log: *mut GLchar) => object_text(shader, buf_size, length, info_log, ObjectText::ShaderLog);
    unsafe fn glGetProgramInfoLog(program: GLuint, buf_size: GLsizei, length: *mut GLsizei, info_log: *mut GLchar) => object_text(program, buf_size, length, info_log, ObjectText::ProgramLog);
    unsafe fn glGetShaderSource(shader: GLuint, buf_size: GLsizei, length: *mut GLsizei, source: *mut GLchar) => object_text(shader, buf_size, length, source, ObjectText::ShaderSource);
    unsafe fn glBindAttribLocation(program: GLuint, index: GLuint, name: *const GLchar) => bind_attrib(program, index, name);
    unsafe fn glGetAttribLocation(program: GLuint, name: *const GLchar) -> GLint => location(program, name, false);
    unsafe fn glGetUniformLocation(program: GLuint, name: *const GLchar) -> GLint => location(program, name, true);
    unsafe fn glGetActiveAttrib(program: GLuint, index: GLuint, buf_size: GLsizei, length: *mut GLsizei, size: *mut GLint, type_: *mut GLenum, name: *mut GLchar) => active(program, index, buf_size, length, size, type_, name, false);
    unsafe fn glGetActiveUniform(program: GLuint, index: GLuint, buf_size: GLsizei, length: *mut GLsizei, size: *mut GLint, type_: *mut GLenum, name: *mut GLchar) => active(program, index, buf_size, length, size, type_, name, true);
}
