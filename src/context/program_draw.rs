//! What a draw does with the current program (glUseProgram): fixed function when there
//! is none (or it has no shaders); the program's shaders on the engine when every stage
//! it has is one the engine runs (a missing stage is fixed function); and nothing
//! (counted in `program_draws_refused`) otherwise: a draw that ignored the program would
//! draw something wrong without telling.
//!
//! Before any of that, GL 2.0's validation (§2.15.4): a draw whose program has samplers
//! of different types on one texture unit is GL_INVALID_OPERATION and draws nothing
//! ([`samplers_conflict`]), as Mesa's `_mesa_sampler_uniforms_are_valid` decides it:
//! every element of every active sampler uniform counts (an array as long as the link
//! made it: up to its last element the shaders index, scene `frag_sampler_array`), and
//! the type is the texture target (`sampler2D`, `sampler2DShadow` and `isampler2D` are one
//! type; `sampler2D` and `samplerCube` two). glValidateProgram reports the same.

use std::sync::Arc;

use super::program_link::Linked;
use super::Context;
use crate::gl::error::{GlError, GlResult};
use crate::shader::draw::FragShader;
use crate::shader::vertex_draw::{is_state_uniform, VertShader};
use crate::shader::Slot;
use softgl_glsl::types::Type;

/// How a draw treats the current program.
#[derive(Debug)]
pub enum ProgramDraw {
    /// No program, or a program without shaders: the fixed-function stages.
    Fixed,
    /// A program the draw cannot run: nothing is drawn.
    Refused,
    /// The program's shaders: the fragment shader and its uniform words (`None`:
    /// fixed-function fragments), the vertex shader (`None`: the fixed-function stage).
    Shader(Option<(Arc<FragShader>, Vec<u32>)>, Option<Box<VertInput>>),
}

/// A draw's vertex shader: the shader, its user uniform words in slot order, and the
/// generic attributes' current values.
#[derive(Debug)]
pub struct VertInput {
    /// The shader.
    pub shader: Arc<VertShader>,
    /// Its user uniforms' words (built-in uniforms skipped).
    pub uniforms: Vec<u32>,
    /// glVertexAttrib's current values.
    pub generic: [[f32; 4]; 16],
}

impl Context {
    /// How a draw treats the current program (see the module doc).
    pub fn program_draw(&self) -> ProgramDraw {
        let cur = self.shaders.current;
        if cur == 0 {
            return ProgramDraw::Fixed;
        }
        let Some(linked) = self
            .shaders
            .table
            .program(cur)
            .ok()
            .and_then(|p| p.linked.as_ref())
        else {
            return ProgramDraw::Refused;
        };
        if linked.vertex.is_empty() && linked.fragment.is_empty() {
            return ProgramDraw::Fixed;
        }
        let frag = match &linked.draw {
            None => None,
            Some(Ok(fs)) => match self.program_words(linked, &fs.uniforms) {
                Some(u) => Some((Arc::clone(fs), u)),
                None => return ProgramDraw::Refused,
            },
            Some(Err(_)) => return ProgramDraw::Refused,
        };
        let vert = match &linked.vert {
            None => None,
            Some(Ok(vs)) if self.immediate.generic_inside && vs.reads_generic() => {
                return ProgramDraw::Refused
            }
            Some(Ok(vs)) => {
                // Every uniform, the built-in matrices and state included, from here in
                // slot order.
                let Some(uniforms) = self.program_words(linked, &vs.uniforms) else {
                    return ProgramDraw::Refused;
                };
                let mut generic = [[0.0, 0.0, 0.0, 1.0]; 16];
                for (g, c) in generic.iter_mut().zip(&self.generic_current) {
                    *g = *c;
                }
                Some(Box::new(VertInput {
                    shader: Arc::clone(vs),
                    uniforms,
                    generic,
                }))
            }
            Some(Err(_)) => return ProgramDraw::Refused,
        };
        ProgramDraw::Shader(frag, vert)
    }
}

impl Context {
    /// The words of the uniforms `slots` names, in slot order: built-in state uniforms
    /// from the GL state ([`Context::builtin_uniform_words`]), the rest from the
    /// program's storage ([`uniform_words`]).
    fn program_words(&self, linked: &Linked, slots: &[Slot]) -> Option<Vec<u32>> {
        let mut out = Vec::new();
        for s in slots {
            let n = s.name.as_str();
            match is_state_uniform(n) {
                true => out.extend(self.builtin_uniform_words(n, usize::from(s.count))?),
                false => out.extend(uniform_words(linked, std::slice::from_ref(s))?),
            }
        }
        Some(out)
    }
}

/// The words of the uniforms `slots` names, in slot order, from the program's storage:
/// a basic uniform or array by its name (an array the link shortened is padded with
/// zeros, elements never read), a struct by its leaves (`s.f`, `s[1].f`) in location
/// order, which must fill the slot exactly. `None` when a uniform is missing.
pub fn uniform_words(linked: &Linked, slots: &[Slot]) -> Option<Vec<u32>> {
    let mut out = Vec::new();
    for s in slots {
        let start = out.len();
        if s.name == crate::shader::lower::FRONT_FACING {
            // Not a uniform: the draw sets it per triangle.
            out.push(0);
            continue;
        }
        match linked.uniforms.iter().find(|u| u.name == s.name) {
            Some(u) => {
                out.extend(u.values.iter().take(s.count as usize));
                out.resize(start + s.count as usize, 0);
            }
            None => {
                let dot = format!("{}.", s.name);
                let idx = format!("{}[", s.name);
                for u in &linked.uniforms {
                    if u.name.starts_with(&dot) || u.name.starts_with(&idx) {
                        out.extend(&u.values);
                    }
                }
                if out.len() - start != s.count as usize {
                    return None;
                }
            }
        }
    }
    Some(out)
}

/// Whether `linked` has samplers of different targets on one texture unit.
pub fn samplers_conflict(linked: &Linked) -> bool {
    let mut units: Vec<(u32, (softgl_glsl::types::Dim, bool))> = Vec::new();
    for u in &linked.uniforms {
        let Type::Sampler(s) = &u.ty else { continue };
        for &unit in &u.values {
            let target = (s.dim, s.array);
            match units.iter().find(|(k, _)| *k == unit) {
                Some((_, t)) if *t != target => return true,
                Some(_) => {}
                None => units.push((unit, target)),
            }
        }
    }
    false
}

impl Context {
    /// GL_INVALID_OPERATION when the current program's samplers of different types name
    /// one texture unit (the draws' validation, module doc).
    pub fn check_program_samplers(&self) -> GlResult<()> {
        if self.shaders.current == 0 {
            return Ok(());
        }
        let linked = self
            .shaders
            .table
            .program(self.shaders.current)
            .ok()
            .and_then(|p| p.linked.as_ref());
        match linked.is_some_and(samplers_conflict) {
            true => Err(GlError::InvalidOperation),
            false => Ok(()),
        }
    }
}
