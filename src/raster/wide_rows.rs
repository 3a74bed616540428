//! The untextured triangle walk of wide targets (16-bit and float colour buffers): each
//! row's span in chunks of 8 pixels through the 8-lane fragment shader
//! ([`crate::fragment::simd_gen::shade_row`] with no units, which stores wide targets
//! through [`crate::fragment::simd_wide`]) on the AVX2 levels, else the per-lane span
//! shader's `FULL` path. Both compute the same values: `1 / w` and every varying as the
//! span shader evaluates them, the colour sum and fog, the tests, and the store.

use super::{row_span, rows};
use crate::fragment::span::Madd;
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::setup::SetupTriangle;
use crate::stats::Stats;

/// The rows `b` of untextured triangle `t` into a wide target (see the module comment).
#[inline(always)]
pub(super) fn rows_wide<
    M: Madd,
    const AVX2: bool,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
>(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    // `AVX2` is a constant: the other levels' copies do not contain the 8-wide code.
    #[cfg(target_arch = "x86_64")]
    if AVX2 && super::textured::general_ok(plan, fb) {
        // SAFETY: `general_ok` checked AVX2; this level's copy is compiled with FMA exactly
        // when `M::FUSED`.
        unsafe {
            if M::FUSED {
                spans8::<true, DEPTH, FLAT, PERSP>(t, b, plan, fb, stats)
            } else {
                spans8::<false, DEPTH, FLAT, PERSP>(t, b, plan, fb, stats)
            }
        }
        return;
    }
    rows::<M, DEPTH, FLAT, PERSP, true>(t, b, plan, fb, stats)
}

/// The spans of `t` in `b`, 8 pixels at a time through `shade_row`.
///
/// # Safety
/// AVX2 context (FMA when `FMA`); `general_ok` accepted the plan and target.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn spans8<const FMA: bool, const DEPTH: bool, const FLAT: bool, const PERSP: bool>(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    use crate::fragment::simd_gen::{shade_row, GenPlan};
    use crate::fragment::span::{TexLanes, LANES};
    use crate::pipe::MAX_TEXTURE_UNITS;
    use crate::simd::F32x8;
    let g = GenPlan::new(plan, t, &[]);
    // Read for no unit: the shader takes texels only for the units it is given.
    let tex: TexLanes = [[[0.0; 4]; LANES]; MAX_TEXTURE_UNITS];
    // SAFETY: (whole body) the caller's AVX2 (+FMA) context; every live lane lies in the
    // span, inside the target's row.
    unsafe {
        let lanes = F32x8::new([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]);
        for py in b[1]..=b[3] {
            let Some((lo, hi)) = row_span(t, b, py) else {
                continue;
            };
            let fy = F32x8::splat(py as f32);
            let mut x = lo as usize;
            while x <= hi as usize {
                let n = LANES.min(hi as usize + 1 - x);
                let live: [bool; LANES] = std::array::from_fn(|i| i < n);
                let oow = if PERSP {
                    let fx = F32x8::splat(x as f32).add(lanes);
                    F32x8::splat(1.0).div(crate::fragment::simd_tex::eval8::<FMA>(&t.w, fx, fy))
                } else {
                    F32x8::splat(1.0)
                };
                shade_row::<FMA, DEPTH, FLAT, PERSP>(
                    t,
                    plan,
                    &g,
                    &[],
                    &tex,
                    fb,
                    py as usize,
                    x,
                    &live,
                    oow,
                    stats,
                );
                x += n;
            }
        }
    }
}
