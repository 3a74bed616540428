//! glGet* of the GL 2.0 programmable stages: the limits a program is held to, the current
//! program, the derivative hint and GL_SHADER_COMPILER.
//!
//! The limits are what the draw really runs, not Mesa's numbers (llvmpipe answers 32
//! image units, 128 varying floats and 16384 uniform components):
//! - **image units**: a fragment shader samples the 8 texture units
//!   ([`crate::pipe::MAX_TEXTURE_UNITS`]), the fixed-function ones; vertex shaders do not
//!   sample (a lookup there is refused, `shader` module docs), so the vertex count is 0
//!   and the combined count 8. (A sampler uniform still takes any unit below Mesa's
//!   192 without an error, as Mesa does; `uniforms`.)
//! - **varying floats**: 32, the GL 2.0 minimum. A fragment shader's inputs fill the 40
//!   varyings after the colours and fog ([`crate::geometry::MAX_VARY`] minus
//!   [`crate::geometry::VARY_TEX`]); back colours (8), a clip vertex (4) and
//!   `gl_PointCoord` (4) share them, so 32 fit beside any one of them; a program that
//!   needs more draws nothing and is counted (`program_draws_refused`).
//! - **uniform components**: 512 per stage, the fragment walk's uniform room
//!   ([`crate::engine::draw::MAX_UNIFORMS`]), the built-in state uniforms included; the
//!   vertex stage keeps its uniforms in a list and answers the same number.

use super::get::{b, e, i, Value};
use super::Context;
use crate::gl::glext_enums::*;

/// The fragment stage's varying floats the query promises (GL 2.0's minimum).
pub const MAX_VARYING_FLOATS: usize = 32;

const _: () =
    assert!(MAX_VARYING_FLOATS + 8 <= crate::geometry::MAX_VARY - crate::geometry::VARY_TEX);

/// The value of a GL 2.0 shader-stage query, or `None` when `pname` is not one.
pub fn shader_get(c: &Context, pname: u32) -> Option<Value> {
    use crate::engine::draw::MAX_UNIFORMS;
    use crate::pipe::MAX_TEXTURE_UNITS;
    Some(match pname {
        GL_MAX_TEXTURE_IMAGE_UNITS
        | GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS
        | GL_MAX_TEXTURE_COORDS => i(&[MAX_TEXTURE_UNITS as i64]),
        GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS => i(&[0]),
        GL_MAX_VARYING_FLOATS => i(&[MAX_VARYING_FLOATS as i64]),
        GL_MAX_VERTEX_UNIFORM_COMPONENTS | GL_MAX_FRAGMENT_UNIFORM_COMPONENTS => {
            i(&[MAX_UNIFORMS as i64])
        }
        GL_FRAGMENT_SHADER_DERIVATIVE_HINT => e(c.state.hints.fragment_shader_derivative),
        GL_SHADER_COMPILER => b(true),
        super::generic_attrib::GL_MAX_VERTEX_ATTRIBS => {
            i(&[super::arrays::MAX_VERTEX_ATTRIBS as i64])
        }
        super::shader_objects::GL_CURRENT_PROGRAM => i(&[c.shaders.current as i64]),
        _ => return None,
    })
}
