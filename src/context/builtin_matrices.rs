//! The values of GLSL's built-in matrix uniforms (`gl_ModelViewMatrix`,
//! `gl_ProjectionMatrix`, `gl_ModelViewProjectionMatrix`, `gl_TextureMatrix[]`, each also
//! `Inverse`, `Transpose` and `InverseTranspose`, `gl_NormalMatrix` and `gl_NormalScale`) from the matrix
//! stacks, as Mesa's `fetch_state` (`prog_statevars.c`) reads them, for either stage:
//!
//! - a matrix is the stack's top; the modelview-projection is `projection × modelview`,
//!   the product the fixed-function transform uses;
//! - an inverse is `_math_matrix_analyse`'s: the routine the matrix's flags choose (a
//!   stack's flags follow the calls that built its top; the product's are both operands'
//!   with its type dirty, as `_math_matrix_mul_matrix` leaves them), identity when
//!   singular;
//! - `Transpose` transposes what it names (the inverse's transpose for
//!   `InverseTranspose`); `gl_NormalMatrix` is the upper 3×3 of the modelview inverse,
//!   transposed, column by column; `gl_NormalScale` is Mesa's
//!   `_ModelViewInvScaleEyespace` (1 for a length-preserving modelview).
//!
//! The names are `shader::vertex_draw::MATRIX_UNIFORMS`. Words are column-major, a `mat4` 16 of them, `gl_TextureMatrix*` one per texture
//! unit.

use super::Context;
use crate::fixed_function::matrix::{Mat4, MatrixStack};
use crate::fixed_function::mesa_matrix::{MatFlags, MAT_DIRTY_INVERSE, MAT_DIRTY_TYPE};

/// `m`'s words, its inverse's (under `flags`) when `inverse`, transposed when `transpose`.
fn words(m: &Mat4, flags: MatFlags, inverse: bool, transpose: bool, out: &mut Vec<f32>) {
    let mut flags = flags;
    let m = match inverse {
        true => flags.inverse(&m.0),
        false => m.0,
    };
    out.extend((0..16).map(|k| match transpose {
        true => m[(k % 4) * 4 + k / 4],
        false => m[k],
    }));
}

/// A stack's top and its flags.
fn top(s: &MatrixStack) -> (&Mat4, MatFlags) {
    (s.top(), s.top_flags())
}

impl Context {
    /// The words of built-in matrix uniform `name`, or `None` when it is not one.
    pub(crate) fn builtin_matrix_words(&self, name: &str) -> Option<Vec<f32>> {
        let mx = &self.matrices;
        let mut v = Vec::with_capacity(16);
        if name == "gl_NormalScale" {
            // Mesa's update_modelview_scale (`_ModelViewInvScaleEyespace`): 1 unless the
            // modelview changes lengths, then 1 / |row 2 of its inverse| (a squared
            // length below 1e-12 counts as 1).
            let (mv, mut flags) = top(&mx.modelview);
            let inv = flags.inverse(&mv.0);
            if flags.is_length_preserving() {
                return Some(vec![1.0]);
            }
            let f = inv[2] * inv[2] + inv[6] * inv[6] + inv[10] * inv[10];
            let f = if f < 1e-12 { 1.0 } else { f };
            return Some(vec![1.0 / f.sqrt()]);
        }
        if name == "gl_NormalMatrix" {
            let (mv, mut flags) = top(&mx.modelview);
            let inv = flags.inverse(&mv.0);
            v.extend((0..9).map(|k| inv[(k % 3) * 4 + k / 3]));
            return Some(v);
        }
        let base = name.strip_prefix("gl_")?;
        let (base, transpose) = match base.strip_suffix("Transpose") {
            Some(b) => (b, true),
            None => (base, false),
        };
        let (base, inverse) = match base.strip_suffix("Inverse") {
            Some(b) => (b, true),
            None => (base, false),
        };
        match base {
            "ModelViewMatrix" => {
                let (m, f) = top(&mx.modelview);
                words(m, f, inverse, transpose, &mut v);
            }
            "ProjectionMatrix" => {
                let (m, f) = top(&mx.projection);
                words(m, f, inverse, transpose, &mut v);
            }
            "ModelViewProjectionMatrix" => {
                let ((p, pf), (mv, mvf)) = (top(&mx.projection), top(&mx.modelview));
                let flags = MatFlags {
                    flags: pf.flags | mvf.flags | MAT_DIRTY_TYPE | MAT_DIRTY_INVERSE,
                    ty: pf.ty,
                };
                words(&p.mul(mv), flags, inverse, transpose, &mut v);
            }
            "TextureMatrix" => {
                for s in &mx.texture {
                    let (m, f) = top(s);
                    words(m, f, inverse, transpose, &mut v);
                }
            }
            _ => return None,
        }
        Some(v)
    }
}
