//! GL 2.0 shader and program objects (GL 2.0 §2.15): glCreateShader, glShaderSource,
//! glCompileShader, glCreateProgram, attaching, deleting and the object queries. Linking
//! is in [`super::program_link`], uniforms in [`super::uniforms`].
//!
//! Shaders and programs share one name space, as in Mesa (a name is either), kept in a
//! [`ShaderTable`] that contexts of one share group share (checked out with the textures,
//! `super::share`). Compiling runs softgl's GLSL front end (`softgl_glsl`), whose info
//! logs are worded like Mesa's; the checked tree of each compiled shader is kept for the
//! link and for the lowering into the engine.
//!
//! Deletion follows GL 2.0 §2.15.1 and Mesa: glDeleteShader of a shader attached to a
//! program only flags it (`GL_DELETE_STATUS`) until the last program lets go, and
//! glDeleteProgram of the current program only flags it until glUseProgram moves away.
//! (Across contexts of a share group the "current" test looks at the deleting context
//! only.)
//!
//! Drawing with a program bound is not implemented yet: draws still use the fixed
//! function stages, and GL_VERSION stays 1.5 until shaders draw (issue 43).

use std::collections::HashMap;
use std::sync::Arc;

use softgl_glsl::{hir, Stage};

use super::program_link::Linked;
use super::Context;
use crate::gl::error::{GlError, GlResult};

/// GL_SHADER_TYPE's values (GL 2.0).
pub const GL_FRAGMENT_SHADER: u32 = 0x8B30;
/// The vertex shader type.
pub const GL_VERTEX_SHADER: u32 = 0x8B31;
/// glGetShaderiv / glGetProgramiv pnames (GL 2.0 table 6.27).
pub const GL_SHADER_TYPE: u32 = 0x8B4F;
/// Whether glDelete* flagged the object.
pub const GL_DELETE_STATUS: u32 = 0x8B80;
/// Whether the last compile succeeded.
pub const GL_COMPILE_STATUS: u32 = 0x8B81;
/// Whether the last link succeeded.
pub const GL_LINK_STATUS: u32 = 0x8B82;
/// Whether the last validation succeeded.
pub const GL_VALIDATE_STATUS: u32 = 0x8B83;
/// The info log's length with its NUL (0 when empty).
pub const GL_INFO_LOG_LENGTH: u32 = 0x8B84;
/// The number of attached shaders.
pub const GL_ATTACHED_SHADERS: u32 = 0x8B85;
/// The number of active uniforms.
pub const GL_ACTIVE_UNIFORMS: u32 = 0x8B86;
/// The longest active uniform name with its NUL.
pub const GL_ACTIVE_UNIFORM_MAX_LENGTH: u32 = 0x8B87;
/// The source's length with its NUL (0 without source).
pub const GL_SHADER_SOURCE_LENGTH: u32 = 0x8B88;
/// The number of active attributes.
pub const GL_ACTIVE_ATTRIBUTES: u32 = 0x8B89;
/// The longest active attribute name with its NUL.
pub const GL_ACTIVE_ATTRIBUTE_MAX_LENGTH: u32 = 0x8B8A;
/// glGetIntegerv: the program in use.
pub const GL_CURRENT_PROGRAM: u32 = 0x8B8D;

/// A shader object.
#[derive(Clone, Debug)]
pub struct ShaderObject {
    /// Its stage (GL_VERTEX_SHADER or GL_FRAGMENT_SHADER).
    pub stage: Stage,
    /// The source of the last glShaderSource (the strings concatenated).
    pub source: Option<String>,
    /// The checked tree of the last successful compile.
    pub compiled: Option<Arc<hir::Program>>,
    /// GL_COMPILE_STATUS.
    pub compile_status: bool,
    /// The info log of the last compile.
    pub log: String,
    /// GL_DELETE_STATUS: deleted while attached.
    pub delete_pending: bool,
    /// How many programs it is attached to.
    pub attached: u32,
}

/// A program object.
#[derive(Clone, Debug, Default)]
pub struct ProgramObject {
    /// The attached shaders, in attach order.
    pub shaders: Vec<u32>,
    /// glBindAttribLocation's bindings, used by the next link.
    pub bindings: HashMap<String, u32>,
    /// glBindFragDataLocation's bindings, used by the next link.
    pub frag_bindings: HashMap<String, u32>,
    /// GL_LINK_STATUS.
    pub link_status: bool,
    /// GL_VALIDATE_STATUS.
    pub validate_status: bool,
    /// The info log of the last link or validation.
    pub log: String,
    /// GL_DELETE_STATUS: deleted while current.
    pub delete_pending: bool,
    /// What the last successful link made: active attributes and uniforms with their
    /// values and the stages' checked trees.
    pub linked: Option<Linked>,
}

/// One object of the shared name space.
#[derive(Clone, Debug)]
pub enum ShaderOrProgram {
    /// A shader.
    Shader(ShaderObject),
    /// A program (boxed: with its link results it is several times a shader's size).
    Program(Box<ProgramObject>),
}

/// The shader and program objects of a share group.
#[derive(Clone, Debug, Default)]
pub struct ShaderTable {
    /// The objects by name.
    pub objects: HashMap<u32, ShaderOrProgram>,
    /// The next name to try.
    pub next_name: u32,
}

/// A context's shader state: the (shared) objects and the current program.
#[derive(Clone, Debug, Default)]
pub struct ShaderState {
    /// The objects.
    pub table: ShaderTable,
    /// glUseProgram's program (0: fixed function).
    pub current: u32,
}

impl ShaderTable {
    /// A fresh name (never 0, never in use).
    fn alloc(&mut self, obj: ShaderOrProgram) -> u32 {
        let mut n = self.next_name.max(1);
        while self.objects.contains_key(&n) {
            n = n.checked_add(1).unwrap_or(1);
        }
        self.next_name = n.wrapping_add(1);
        self.objects.insert(n, obj);
        n
    }

    /// The shader `name`: GL_INVALID_VALUE for no object, GL_INVALID_OPERATION for a
    /// program.
    pub fn shader(&self, name: u32) -> GlResult<&ShaderObject> {
        match self.objects.get(&name) {
            Some(ShaderOrProgram::Shader(s)) => Ok(s),
            Some(_) => Err(GlError::InvalidOperation),
            None => Err(GlError::InvalidValue),
        }
    }

    /// The shader `name`, writable.
    pub fn shader_mut(&mut self, name: u32) -> GlResult<&mut ShaderObject> {
        match self.objects.get_mut(&name) {
            Some(ShaderOrProgram::Shader(s)) => Ok(s),
            Some(_) => Err(GlError::InvalidOperation),
            None => Err(GlError::InvalidValue),
        }
    }

    /// The program `name`: GL_INVALID_VALUE for no object, GL_INVALID_OPERATION for a
    /// shader.
    pub fn program(&self, name: u32) -> GlResult<&ProgramObject> {
        match self.objects.get(&name) {
            Some(ShaderOrProgram::Program(p)) => Ok(p),
            Some(_) => Err(GlError::InvalidOperation),
            None => Err(GlError::InvalidValue),
        }
    }

    /// The program `name`, writable.
    pub fn program_mut(&mut self, name: u32) -> GlResult<&mut ProgramObject> {
        match self.objects.get_mut(&name) {
            Some(ShaderOrProgram::Program(p)) => Ok(p),
            Some(_) => Err(GlError::InvalidOperation),
            None => Err(GlError::InvalidValue),
        }
    }

    /// One program fewer holds shader `s`: frees it when it was deleted and is free now.
    fn release_shader(&mut self, s: u32) {
        if let Some(ShaderOrProgram::Shader(sh)) = self.objects.get_mut(&s) {
            sh.attached = sh.attached.saturating_sub(1);
            if sh.attached == 0 && sh.delete_pending {
                self.objects.remove(&s);
            }
        }
    }

    /// Frees program `p`, releasing its shaders.
    fn free_program(&mut self, p: u32) {
        if let Some(ShaderOrProgram::Program(prog)) = self.objects.remove(&p) {
            for s in prog.shaders {
                self.release_shader(s);
            }
        }
    }
}

/// A GL string length: the text's bytes plus the NUL, 0 when empty.
pub fn gl_len(s: &str) -> i32 {
    if s.is_empty() {
        0
    } else {
        (s.len() + 1).min(i32::MAX as usize) as i32
    }
}

/// Copies `text` into a GL string buffer of `buf_size` bytes as glGet*InfoLog do: at
/// most `buf_size - 1` bytes and a NUL; returns the bytes (NUL included) and the length
/// to report (without the NUL).
pub fn gl_copy(text: &str, buf_size: i32) -> (Vec<u8>, i32) {
    if buf_size <= 0 {
        return (Vec::new(), 0);
    }
    let n = text.len().min(buf_size as usize - 1);
    let mut out = text.as_bytes()[..n].to_vec();
    out.push(0);
    (out, n as i32)
}

impl Context {
    /// glCreateShader.
    pub fn create_shader(&mut self, ty: u32) -> GlResult<u32> {
        let stage = match ty {
            GL_VERTEX_SHADER => Stage::Vertex,
            GL_FRAGMENT_SHADER => Stage::Fragment,
            _ => return Err(GlError::InvalidEnum),
        };
        Ok(self
            .shaders
            .table
            .alloc(ShaderOrProgram::Shader(ShaderObject {
                stage,
                source: None,
                compiled: None,
                compile_status: false,
                log: String::new(),
                delete_pending: false,
                attached: 0,
            })))
    }

    /// glCreateProgram.
    pub fn create_program(&mut self) -> u32 {
        self.shaders
            .table
            .alloc(ShaderOrProgram::Program(Box::default()))
    }

    /// glShaderSource with the strings already read.
    pub fn shader_source(&mut self, shader: u32, source: String) -> GlResult<()> {
        self.shaders.table.shader_mut(shader)?.source = Some(source);
        Ok(())
    }

    /// glCompileShader: runs the GLSL front end on the source.
    pub fn compile_shader(&mut self, shader: u32) -> GlResult<()> {
        let s = self.shaders.table.shader_mut(shader)?;
        let src = s.source.clone().unwrap_or_default();
        let (program, log) = softgl_glsl::compile_with_log(&[&src], s.stage);
        s.compile_status = program.is_some();
        s.compiled = program.map(Arc::new);
        s.log = log.to_string();
        Ok(())
    }

    /// glDeleteShader (0 is ignored).
    pub fn delete_shader(&mut self, shader: u32) -> GlResult<()> {
        if shader == 0 {
            return Ok(());
        }
        let s = self.shaders.table.shader_mut(shader)?;
        if s.attached > 0 {
            s.delete_pending = true;
        } else {
            self.shaders.table.objects.remove(&shader);
        }
        Ok(())
    }

    /// glDeleteProgram (0 is ignored).
    pub fn delete_program(&mut self, program: u32) -> GlResult<()> {
        if program == 0 {
            return Ok(());
        }
        let p = self.shaders.table.program_mut(program)?;
        if self.shaders.current == program {
            p.delete_pending = true;
        } else {
            self.shaders.table.free_program(program);
        }
        Ok(())
    }

    /// glIsShader.
    pub fn is_shader(&self, name: u32) -> bool {
        self.shaders.table.shader(name).is_ok()
    }

    /// glIsProgram.
    pub fn is_program(&self, name: u32) -> bool {
        self.shaders.table.program(name).is_ok()
    }

    /// glAttachShader.
    pub fn attach_shader(&mut self, program: u32, shader: u32) -> GlResult<()> {
        let t = &mut self.shaders.table;
        if t.program(program)?.shaders.contains(&shader) {
            return Err(GlError::InvalidOperation);
        }
        t.shader_mut(shader)?.attached += 1;
        t.program_mut(program)?.shaders.push(shader);
        Ok(())
    }

    /// glDetachShader.
    pub fn detach_shader(&mut self, program: u32, shader: u32) -> GlResult<()> {
        let t = &mut self.shaders.table;
        t.program(program)?;
        t.shader(shader)?;
        let p = t.program_mut(program)?;
        let Some(i) = p.shaders.iter().position(|&s| s == shader) else {
            return Err(GlError::InvalidOperation);
        };
        p.shaders.remove(i);
        t.release_shader(shader);
        Ok(())
    }

    /// glGetAttachedShaders: at most `max` names.
    pub fn attached_shaders(&self, program: u32, max: i32) -> GlResult<Vec<u32>> {
        if max < 0 {
            return Err(GlError::InvalidValue);
        }
        let p = self.shaders.table.program(program)?;
        Ok(p.shaders.iter().take(max as usize).copied().collect())
    }

    /// glUseProgram.
    pub fn use_program(&mut self, program: u32) -> GlResult<()> {
        if program != 0 && !self.shaders.table.program(program)?.link_status {
            return Err(GlError::InvalidOperation);
        }
        let old = self.shaders.current;
        self.shaders.current = program;
        if old != program {
            if let Ok(p) = self.shaders.table.program(old) {
                if p.delete_pending {
                    // A draw left on the pool may still run the old program's shaders.
                    self.settle_draws();
                    self.shaders.table.free_program(old);
                }
            }
        }
        Ok(())
    }

    /// glGetShaderiv.
    pub fn get_shader(&self, shader: u32, pname: u32) -> GlResult<i32> {
        let s = self.shaders.table.shader(shader)?;
        Ok(match pname {
            GL_SHADER_TYPE => {
                (match s.stage {
                    Stage::Vertex => GL_VERTEX_SHADER,
                    _ => GL_FRAGMENT_SHADER,
                }) as i32
            }
            GL_DELETE_STATUS => s.delete_pending as i32,
            GL_COMPILE_STATUS => s.compile_status as i32,
            GL_INFO_LOG_LENGTH => gl_len(&s.log),
            GL_SHADER_SOURCE_LENGTH => s.source.as_deref().map_or(0, gl_len),
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// glGetProgramiv.
    pub fn get_program(&self, program: u32, pname: u32) -> GlResult<i32> {
        let p = self.shaders.table.program(program)?;
        let linked = p.linked.as_ref();
        let max_len =
            |names: &mut dyn Iterator<Item = usize>| names.map(|n| n as i32 + 1).max().unwrap_or(0);
        Ok(match pname {
            GL_DELETE_STATUS => p.delete_pending as i32,
            GL_LINK_STATUS => p.link_status as i32,
            GL_VALIDATE_STATUS => p.validate_status as i32,
            GL_INFO_LOG_LENGTH => gl_len(&p.log),
            GL_ATTACHED_SHADERS => p.shaders.len() as i32,
            GL_ACTIVE_ATTRIBUTES => linked.map_or(0, |l| l.attributes.len() as i32),
            GL_ACTIVE_ATTRIBUTE_MAX_LENGTH => linked.map_or(0, |l| {
                max_len(&mut l.attributes.iter().map(|a| a.name.len()))
            }),
            GL_ACTIVE_UNIFORMS => linked.map_or(0, |l| l.uniforms.len() as i32),
            GL_ACTIVE_UNIFORM_MAX_LENGTH => linked.map_or(0, |l| {
                max_len(&mut l.uniforms.iter().map(|u| u.active_name().len()))
            }),
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// glGetShaderInfoLog / glGetProgramInfoLog / glGetShaderSource: the text, checked
    /// for `buf_size` first as Mesa does.
    pub fn object_text(&self, name: u32, buf_size: i32, which: ObjectText) -> GlResult<String> {
        if buf_size < 0 {
            return Err(GlError::InvalidValue);
        }
        let t = &self.shaders.table;
        Ok(match which {
            ObjectText::ShaderLog => t.shader(name)?.log.clone(),
            ObjectText::ShaderSource => t.shader(name)?.source.clone().unwrap_or_default(),
            ObjectText::ProgramLog => t.program(name)?.log.clone(),
        })
    }

    /// glValidateProgram: valid when linked and no two samplers of different types name
    /// one texture unit (`program_draw::samplers_conflict`, the draws' check).
    pub fn validate_program(&mut self, program: u32) -> GlResult<()> {
        let p = self.shaders.table.program_mut(program)?;
        let conflict = p
            .linked
            .as_ref()
            .is_some_and(super::program_draw::samplers_conflict);
        p.validate_status = p.link_status && !conflict;
        Ok(())
    }

    /// glBindAttribLocation: takes effect at the next link. Names starting `gl_` are
    /// GL_INVALID_OPERATION, indices past GL_MAX_VERTEX_ATTRIBS GL_INVALID_VALUE.
    pub fn bind_attrib_location(&mut self, program: u32, index: u32, name: &str) -> GlResult<()> {
        let p = self.shaders.table.program_mut(program)?;
        if index as usize >= super::arrays::MAX_VERTEX_ATTRIBS {
            return Err(GlError::InvalidValue);
        }
        if name.starts_with("gl_") {
            return Err(GlError::InvalidOperation);
        }
        p.bindings.insert(name.to_string(), index);
        Ok(())
    }
}

/// Which text of an object [`Context::object_text`] reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ObjectText {
    /// A shader's info log.
    ShaderLog,
    /// A shader's source.
    ShaderSource,
    /// A program's info log.
    ProgramLog,
}
