//! Instanced draws (GL 3.1 / ARB_draw_instanced, ARB_instanced_arrays): a draw call run
//! once per instance. Each run supplies its instance to a vertex shader as `gl_InstanceID`
//! ([`Context::draw_instance`]), and each generic attribute array with a
//! divisor `d` reads element `instance / d` for every vertex of the instance: the array is
//! disabled for the runs and its element made the attribute's current value, which is
//! what a disabled array reads. Every array draw goes through here, so that a plain
//! glDrawArrays with a divisor set draws instance 0 as GL says.
//!
//! Attribute 0 (the position, aliased with GL_VERTEX_ARRAY in the compatibility
//! profile) keeps its array: a divisor on it is not applied.
//!
//! The runs are whole draws: per-draw costs are paid per instance. That is fine for tens
//! or hundreds of instances; a draw of 100,000 is slow.

use super::arrays::MAX_VERTEX_ATTRIBS;
use super::{Context, GlResult};
use crate::geometry::fetch::VertexFetcher;
use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};

/// Runs `draw` for instances `0..count` (see the module doc); the arrays, the current
/// attributes and the instance are restored afterwards, even if a draw panics. An error
/// from the first run ends the loop (the later runs would repeat it).
pub(crate) fn instanced(
    c: &mut Context,
    count: u32,
    mut draw: impl FnMut(&mut Context) -> GlResult<()>,
) -> GlResult<()> {
    let v = &c.arrays.vao;
    let per: Vec<(usize, u32)> = (1..MAX_VERTEX_ATTRIBS)
        .filter(|&k| v.generic[k].enabled && v.divisor[k] != 0)
        .map(|k| (k, v.divisor[k]))
        .collect();
    if per.is_empty() && count == 1 {
        return draw(c);
    }
    // Each attribute's elements for the instances, read while its array is enabled.
    let values: Vec<Vec<[f32; 4]>> = {
        let fetch = VertexFetcher::new(&c.arrays.inputs(), &c.state.current);
        per.iter()
            .map(|&(k, d)| {
                (0..count.div_ceil(d))
                    // SAFETY: an enabled client-memory array is the program's promise
                    // for the elements its instances read; buffers are bounds-checked.
                    .map(|e| unsafe { fetch.generic(k, e) }.unwrap_or([0.0, 0.0, 0.0, 1.0]))
                    .collect()
            })
            .collect()
    };
    let current = c.generic_current;
    for &(k, _) in &per {
        c.arrays.vao.generic[k].enabled = false;
    }
    let r = catch_unwind(AssertUnwindSafe(|| {
        for i in 0..count {
            c.draw_instance = i;
            for (&(k, d), vals) in per.iter().zip(&values) {
                c.generic_current[k] = vals[(i / d) as usize];
            }
            draw(c)?;
        }
        Ok(())
    }));
    for &(k, _) in &per {
        c.arrays.vao.generic[k].enabled = true;
    }
    c.generic_current = current;
    c.draw_instance = 0;
    r.unwrap_or_else(|p| resume_unwind(p))
}
