//! ARB_shader_objects' own names, which Mesa exports beside the GL 2.0 ones: one
//! `GLhandleARB` name space for shaders and programs (softgl's, shared with GL 2.0, as in
//! Mesa), so glDeleteObjectARB, glGetObjectParameter{i,f}vARB and glGetInfoLogARB accept
//! either kind of object. The names that only add the suffix (glCompileShaderARB,
//! glUniform4fARB …) are generated aliases in [`super::aliases_ext`]; glShaderSourceARB is
//! here because its string array is `const GLcharARB **`.
#![allow(non_snake_case)]

use super::client::write_one;
use super::families::c_fns;
use super::types::*;
use super::with_ctx;
use crate::context::shader_objects::{ObjectText, ShaderOrProgram};
use crate::context::{Context, GlError, GlResult};

/// GL_PROGRAM_OBJECT_ARB: glGetHandleARB's pname and a program's GL_OBJECT_TYPE_ARB.
const GL_PROGRAM_OBJECT_ARB: u32 = 0x8B40;
/// A shader's GL_OBJECT_TYPE_ARB.
const GL_SHADER_OBJECT_ARB: u32 = 0x8B48;
/// glGetObjectParameterivARB: the object's kind.
const GL_OBJECT_TYPE_ARB: u32 = 0x8B4E;

/// Whether `obj` is a program (GL_INVALID_VALUE when it is neither kind).
fn is_program(c: &Context, obj: GLuint) -> GlResult<bool> {
    match c.shaders.table.objects.get(&obj) {
        Some(ShaderOrProgram::Program(_)) => Ok(true),
        Some(ShaderOrProgram::Shader(_)) => Ok(false),
        None => Err(GlError::InvalidValue),
    }
}

/// glGetObjectParameter{i,f}vARB: GL_OBJECT_TYPE_ARB, or the shader or program query.
fn object_parameter(c: &Context, obj: GLuint, pname: GLenum) -> GlResult<i32> {
    let program = is_program(c, obj)?;
    if pname == GL_OBJECT_TYPE_ARB {
        return Ok(if program {
            GL_PROGRAM_OBJECT_ARB
        } else {
            GL_SHADER_OBJECT_ARB
        } as i32);
    }
    if program {
        c.get_program(obj, pname)
    } else {
        c.get_shader(obj, pname)
    }
}

/// glDeleteObjectARB: either kind (0 ignored).
fn delete_object(c: &mut Context, obj: GLuint) -> GlResult<()> {
    if obj == 0 {
        return Ok(());
    }
    if is_program(c, obj)? {
        c.delete_program(obj)
    } else {
        c.delete_shader(obj)
    }
}

/// glGetInfoLogARB: either kind's log.
///
/// # Safety
/// `log` null or writable for `max` bytes; `length` null or writable.
unsafe fn arb_info_log(obj: GLuint, max: GLsizei, length: *mut GLsizei, log: *mut GLchar) {
    with_ctx(|c| {
        let which = if is_program(c, obj)? {
            ObjectText::ProgramLog
        } else {
            ObjectText::ShaderLog
        };
        let t = c.object_text(obj, max, which)?;
        // SAFETY: forwarded caller contract.
        unsafe { super::shaders::write_text(&t, max, length, log) };
        Ok(())
    })
}

c_fns! {
    safe fn glCreateShaderObjectARB(shader_type: GLenum) -> GLuint = shaders::glCreateShader;
    safe fn glCreateProgramObjectARB() -> GLuint = shaders::glCreateProgram;
    safe fn glAttachObjectARB(program: GLuint, shader: GLuint) = shaders::glAttachShader;
    safe fn glDetachObjectARB(program: GLuint, shader: GLuint) = shaders::glDetachShader;
    safe fn glUseProgramObjectARB(program: GLuint) = shaders::glUseProgram;
    unsafe fn glGetAttachedObjectsARB(program: GLuint, max_count: GLsizei, count: *mut GLsizei, shaders: *mut GLuint) = shaders::glGetAttachedShaders;
    unsafe fn glShaderSourceARB(shader: GLuint, count: GLsizei, string: *mut *const GLchar, length: *const GLint) => super::shaders::glShaderSource(shader, count, string as *const *const GLchar, length);
    safe fn glDeleteObjectARB(obj: GLuint) => with_ctx(|c| delete_object(c, obj));
    safe fn glGetHandleARB(pname: GLenum) -> GLuint => with_ctx(|c| if pname == GL_PROGRAM_OBJECT_ARB { Ok(c.shaders.current) } else { Err(GlError::InvalidEnum) });
    unsafe fn glGetObjectParameterivARB(obj: GLuint, pname: GLenum, params: *mut GLint) => with_ctx(|c| { let v = object_parameter(c, obj, pname)?; write_one(params, v); Ok(()) });
    unsafe fn glGetObjectParameterfvARB(obj: GLuint, pname: GLenum, params: *mut GLfloat) => with_ctx(|c| { let v = object_parameter(c, obj, pname)?; write_one(params, v as GLfloat); Ok(()) });
    unsafe fn glGetInfoLogARB(obj: GLuint, max_length: GLsizei, length: *mut GLsizei, info_log: *mut GLchar) => arb_info_log(obj, max_length, length, info_log);
}
