//! Triangles of a draw with a fragment shader ([`crate::shader::draw`]): the chunk rows
//! of the textured walk ([`textured::Chunks`], pairs of rows in 8-pixel chunks) through
//! the shader's compiled variant. A triangle whose plan or target the engine does not
//! draw (stencil, logic op, wide or sRGB buffers …) is not drawn and is counted in
//! `program_tris_refused`: drawing it without its shader would be wrong.

use super::textured;
use super::Draw;
use crate::fragment::span::{TexLanes, LANES};
use crate::geometry::setup::SetupTriangle;
use crate::pipe::MAX_TEXTURE_UNITS;
use crate::shader::draw::ShaderRef;

/// No texels: a shader's walk has no units.
const NO_TEXELS: TexLanes = [[[0.0; 4]; LANES]; MAX_TEXTURE_UNITS];

/// Draws `t` in box `b` (cut to the region) with shader `sh`. Out of line and cold: the
/// branch to it must not change how the fixed-function walks around it are compiled.
#[cold]
#[inline(never)]
pub(super) fn triangle(t: &SetupTriangle, b: [i64; 4], sh: &ShaderRef, d: &mut Draw<'_, '_>) {
    let (plan, fb, stats) = (d.plan, &mut *d.fb, &mut *d.stats);
    let Some(mut w) = crate::shader::draw::walk(sh, plan, fb) else {
        stats.program_tris_refused += 1;
        return;
    };
    w.begin(t);
    for c in textured::Chunks::new(t, b) {
        for (r, live) in c.live.iter().enumerate() {
            let py = (c.qy + r as i64) as usize;
            w.row(t, fb, py, c.x as usize, live, &NO_TEXELS, stats);
        }
    }
    w.end(t, fb, stats);
}
