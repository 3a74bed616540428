//! What a draw does with the current program (glUseProgram): fixed function when there
//! is none (or it has no shaders), the engine with the program's fragment shader when it
//! has one the engine runs and no vertex shader, and nothing (counted in
//! `program_draws_refused`) otherwise: a draw that ignored the program would draw
//! something wrong without telling.

use std::sync::Arc;

use super::program_link::Linked;
use super::Context;
use crate::shader::draw::FragShader;
use crate::shader::Slot;

/// How a draw treats the current program.
#[derive(Debug)]
pub enum ProgramDraw {
    /// No program, or a program without shaders: the fixed-function stages.
    Fixed,
    /// A program the draw cannot run: nothing is drawn.
    Refused,
    /// The fragment shader and its uniform words, with the fixed-function vertex stage.
    Shader(Arc<FragShader>, Vec<u32>),
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
        match (&linked.draw, linked.vertex.is_empty()) {
            (Some(Ok(fs)), true) => match uniform_words(linked, &fs.uniforms) {
                Some(u) => ProgramDraw::Shader(Arc::clone(fs), u),
                None => ProgramDraw::Refused,
            },
            _ => ProgramDraw::Refused,
        }
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
