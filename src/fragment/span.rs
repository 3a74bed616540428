//! The span shader: shades the covered pixels `x0..=x1` of one row, monomorphised over the
//! multiply-add flavour and the plan's booleans so the per-pixel loop has no state branches.

use super::FragPlan;
use crate::framebuffer::{float_to_ubyte, Framebuffer};
use crate::geometry::setup::{Plane, SetupTriangle};
use crate::stats::Stats;

/// How `a * b + c` rounds: llvmpipe fuses it exactly when the CPU has FMA.
pub trait Madd {
    /// `a * b + c`.
    fn madd(a: f32, b: f32, c: f32) -> f32;
}

/// One rounding (`vfmadd` inside an FMA-enabled function).
pub struct Fused;
/// Two roundings.
pub struct Unfused;

impl Madd for Fused {
    #[inline(always)]
    fn madd(a: f32, b: f32, c: f32) -> f32 {
        a.mul_add(b, c)
    }
}

impl Madd for Unfused {
    #[inline(always)]
    fn madd(a: f32, b: f32, c: f32) -> f32 {
        a * b + c
    }
}

/// Evaluates a plane at pixel (fx, fy) as llvmpipe's interpolator does.
#[inline(always)]
pub fn eval<M: Madd>(p: &Plane, fx: f32, fy: f32) -> f32 {
    M::madd(p.dady, fy, M::madd(p.dadx, fx, p.a0))
}

/// Shades pixels `x0..=x1` of row `py` (y-down) of triangle `t`.
///
/// `FULL` selects the general path (alpha test, stencil, blending, logic op, read from
/// the plan at run time); without it only the depth test and the colour write run.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn shade_span<
    M: Madd,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
    const FULL: bool,
>(
    t: &SetupTriangle,
    plan: &FragPlan,
    fb: &mut Framebuffer,
    py: usize,
    x0: usize,
    x1: usize,
    stats: &mut Stats,
) {
    let w = fb.width;
    let fy = py as f32;
    let depth_plan = plan.depth;
    let mask = plan.color_mask;
    let full_mask = mask == [true; 4];
    let flat_color = [0, 1, 2, 3].map(|i| float_to_ubyte(t.flat[i]));
    let stencil = plan.stencil.map(|s| if t.front { s.front } else { s.back });
    stats.fragments += (x1 + 1 - x0) as u64;
    for x in x0..=x1 {
        let fx = x as f32;
        let idx = py * w + x;
        let color = || -> [u8; 4] {
            if FLAT {
                flat_color
            } else {
                let oow = if PERSP {
                    1.0f32 / eval::<M>(&t.w, fx, fy)
                } else {
                    1.0
                };
                let mut c = [0u8; 4];
                for (i, out) in c.iter_mut().enumerate() {
                    let a = eval::<M>(&t.vary[i], fx, fy);
                    *out = float_to_ubyte(if PERSP { a * oow } else { a });
                }
                c
            }
        };
        let mut c = [0u8; 4];
        if FULL {
            c = color();
            if let Some((func, reference)) = plan.alpha {
                if !func.test(c[3], reference) {
                    stats.alpha_failed += 1;
                    continue;
                }
            }
            if let Some(sp) = &stencil {
                stats.stencil_reads += 1;
                let s = fb.stencil[idx];
                if !sp.test(s) {
                    fb.stencil[idx] = sp.update(sp.fail, s);
                    stats.stencil_failed += 1;
                    continue;
                }
            }
        }
        if DEPTH {
            let d = depth_plan.expect("DEPTH implies a depth plan");
            let z = eval::<M>(&t.z, fx, fy);
            let z = if z > 0.0 { z.min(1.0) } else { 0.0 };
            let q = d.format.quantize(z);
            stats.depth_reads += 1;
            let stored = fb.depth[idx];
            if !d.func.test(q, stored) {
                stats.depth_failed += 1;
                if FULL {
                    if let Some(sp) = &stencil {
                        let s = fb.stencil[idx];
                        fb.stencil[idx] = sp.update(sp.zfail, s);
                    }
                }
                continue;
            }
            if d.write {
                fb.depth[idx] = q;
            }
        }
        if FULL {
            if let Some(sp) = &stencil {
                let s = fb.stencil[idx];
                fb.stencil[idx] = sp.update(sp.zpass, s);
            }
        } else {
            c = color();
        }
        if mask == [false; 4] {
            continue;
        }
        let mut stored = fb.store_rgba8(c);
        if FULL && (plan.blend.is_some() || plan.logic.is_some()) {
            stats.color_reads += 1;
            let d = fb.color[idx];
            let v = if let Some(b) = &plan.blend {
                super::blend::blend(b, c, d)
            } else if let Some(op) = plan.logic {
                [0, 1, 2, 3].map(|i| op.apply(c[i], d[i]))
            } else {
                c
            };
            stored = fb.store_rgba8(v);
        }
        let dst = &mut fb.color[idx];
        if full_mask {
            *dst = stored;
        } else {
            for i in 0..4 {
                if mask[i] {
                    dst[i] = stored[i];
                }
            }
        }
        stats.color_writes += 1;
    }
}
