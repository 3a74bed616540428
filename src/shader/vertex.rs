//! Lowering a checked vertex shader into the engine's IR: the expression, statement and
//! built-in lowering of [`super::lower`] (one SSA value per component, masks for control
//! flow, llvmpipe's arithmetic), with a vertex stage's interface.
//!
//! - Inputs are attribute streams: each attribute the shader reads (`gl_Vertex`,
//!   `gl_Color`, `gl_Normal`, `gl_MultiTexCoordN`, a user `attribute`/`in`) gets one
//!   [`Op::InputF`] stream per component ([`LoweredVertex::attributes`]), 8 vertices a
//!   chunk, which [`super::vertex_draw`] fills from the draw's vertices.
//! - Uniforms are [`Op::Uniform`] slots as in a fragment shader (hoisted per run); the
//!   built-in matrices (`gl_ModelViewProjectionMatrix` …) are uniforms by name, which a
//!   draw supplies from its matrix stacks.
//! - Outputs are [`Op::Output`] values: every output the shader wrote (`gl_Position`,
//!   `gl_FrontColor`, `gl_TexCoord[]`, user varyings …), one per component, in
//!   [`LoweredVertex::outputs`] order; an output never written is absent (undefined in
//!   GL; a draw reads it as 0).
//! - `ftransform()` is `gl_ModelViewProjectionMatrix * gl_Vertex` as Mesa's
//!   `ast_function.cpp` emits it, a matrix-vector product lowered as every other: column
//!   by column, `((C0·x + C1·y) + C2·z) + C3·w`, never fused (`lower_ffma32`), which is
//!   the fixed-function transform's order ([`crate::fixed_function::matrix::Mat4::transform`]),
//!   so a program using it is position invariant to fixed function.

use super::lower::{no, slot_of, Lower, Options, Slot, Unsupported, R};
use crate::engine::ir::{Ir, Op, Val};
use softgl_glsl::builtins::variables::Kind as BKind;
use softgl_glsl::hir::{self, Storage};
use softgl_glsl::types::Scalar;

/// A lowered vertex shader.
#[derive(Clone, Debug)]
pub struct LoweredVertex {
    /// The program, its outputs written by [`Op::Output`].
    pub ir: Ir,
    /// The uniforms read, in the order of their slots.
    pub uniforms: Vec<Slot>,
    /// The attributes read: `first` is the first [`Op::InputF`] stream.
    pub attributes: Vec<Slot>,
    /// The outputs written: `first` is the first [`Op::Output`] index.
    pub outputs: Vec<Slot>,
}

/// Lowers a vertex shader.
pub fn lower_vertex(p: &hir::Program) -> Result<LoweredVertex, Unsupported> {
    let mut l = Lower::new(p, Options::default(), true);
    l.run_main()?;
    let mut outputs: Vec<Slot> = Vec::new();
    let mut next = 0u16;
    for (id, var) in p.vars.iter().enumerate() {
        if !matches!(var.storage, Storage::Out | Storage::Builtin(BKind::Output)) {
            continue;
        }
        let Some(vals) = l.env.get(&id).cloned() else {
            continue;
        };
        for (k, v) in vals.iter().enumerate() {
            l.b.push(Op::Output(next + k as u16, *v));
        }
        outputs.push(Slot {
            name: var.name.clone(),
            first: next,
            count: vals.len() as u16,
            scalars: Vec::new(),
            linear: false,
        });
        next += vals.len() as u16;
    }
    let ir =
        l.b.finish()
            .map_err(|e| Unsupported(format!("IR type error {e:?}")))?;
    Ok(LoweredVertex {
        ir,
        uniforms: l.uniforms,
        attributes: l.varyings,
        outputs,
    })
}

impl Lower<'_> {
    /// The components of attribute `name` (streams added on its first read).
    /// An `int`/`uint` attribute's components are the bits of its words (integer arrays and
    /// values, `crate::ffi::vertex_attrib_int`).
    pub(super) fn attribute(&mut self, name: &str, sc: &[Scalar]) -> R<Vec<Val>> {
        if sc.contains(&Scalar::Bool) {
            return no(format!("boolean attribute {name}"));
        }
        let first = slot_of(&mut self.varyings, name, sc);
        Ok((0..sc.len())
            .map(|k| {
                let v = self.op(Op::InputF(first + k as u16));
                match sc[k] {
                    Scalar::Float => v,
                    _ => self.op(Op::Bits(v)),
                }
            })
            .collect())
    }

    /// `ftransform()`: `gl_ModelViewProjectionMatrix * gl_Vertex` (see the module doc).
    pub(super) fn ftransform(&mut self) -> R<Vec<Val>> {
        if !self.vertex {
            return no("ftransform outside a vertex shader");
        }
        let sc = [Scalar::Float; 16];
        let first = self.uniform_slot("gl_ModelViewProjectionMatrix", &sc);
        let m: Vec<Val> = (0..16).map(|k| self.op(Op::Uniform(first + k))).collect();
        let v = self.attribute("gl_Vertex", &sc[..4])?;
        Ok(self.mat_vec(&m, 4, &v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check(src: &str) -> hir::Program {
        softgl_glsl::compile(&[src], softgl_glsl::Stage::Vertex).expect("compiles")
    }

    #[test]
    fn lowers_attributes_uniforms_and_outputs() {
        let p = check(
            "uniform mat4 m; attribute vec3 a; varying vec2 v;
             void main() { gl_Position = m * vec4(a, 1.0); v = a.xy; gl_FrontColor = gl_Color; }",
        );
        let l = lower_vertex(&p).unwrap();
        let names: Vec<_> = l.attributes.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(names, ["a", "gl_Color"]);
        assert_eq!(l.uniforms[0].name, "m");
        let outs: Vec<_> = l
            .outputs
            .iter()
            .map(|s| (s.name.as_str(), s.count))
            .collect();
        assert!(outs.contains(&("gl_Position", 4)) && outs.contains(&("v", 2)));
        assert!(outs.contains(&("gl_FrontColor", 4)));
    }

    #[test]
    fn writes_to_gl_tex_coord_elements_lower() {
        // `gl_TexCoord[]` is unsized in the declaration: 8 vec4 elements as an output.
        let p = check("void main() { gl_Position = gl_Vertex; gl_TexCoord[1] = gl_Color; }");
        let l = lower_vertex(&p).unwrap();
        let t = l.outputs.iter().find(|s| s.name == "gl_TexCoord").unwrap();
        assert_eq!(t.count, 32);
    }

    #[test]
    fn ftransform_reads_the_mvp_and_gl_vertex() {
        let p = check("void main() { gl_Position = ftransform(); }");
        let l = lower_vertex(&p).unwrap();
        assert_eq!(l.uniforms[0].name, "gl_ModelViewProjectionMatrix");
        assert_eq!(l.attributes[0].name, "gl_Vertex");
    }
}
