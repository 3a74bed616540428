//! The untextured triangle walk, onto every target the AVX2 span shader
//! (`super::rows_simd`) leaves: 8-bit targets with stencil, the alpha test, fog, the
//! colour sum, a partial colour mask or sample counting, and wide targets (16-bit and
//! float colour buffers) and sRGB writes. On the AVX2 levels, where
//! [`crate::fragment::simd_gen::plan_ok`] covers the plan, each row's span goes in chunks
//! of 8 pixels from its first pixel through the 8-lane fragment shader
//! ([`crate::fragment::simd_gen::shade_row`] with no units, which stores wide targets
//! through [`crate::fragment::simd_wide`]); else each span goes through the per-lane
//! span shader ([`shade_span`], `FULL` unless the plan needs none of the per-fragment
//! pipeline). Both compute the same values: `1 / w` and every varying as the span shader
//! evaluates them, the colour sum and fog, the tests, and the store. No texture
//! coordinate is used, so the spans need no 2x2 quads (the textured walks' row pairs).

use super::row_span;
use crate::fragment::span::{float_store, shade_span, Madd, Span};
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::setup::SetupTriangle;
use crate::stats::Stats;

/// The rows `b` of untextured triangle `t` (see the module comment).
#[inline(always)]
pub(super) fn rows_untextured<
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
            super::variants::with_fused!(M, |FMA| spans8::<FMA, DEPTH, FLAT, PERSP>(
                t,
                (b[1], b[3]),
                |py| row_span(t, b, py),
                plan,
                fb,
                stats
            ))
        }
        return;
    }
    // Wide targets and sRGB writes store through the whole pipeline.
    if plan.needs_full_path() || float_store(plan, fb) {
        rows::<M, DEPTH, FLAT, PERSP, true>(t, b, plan, fb, stats)
    } else {
        rows::<M, DEPTH, FLAT, PERSP, false>(t, b, plan, fb, stats)
    }
}

/// Each row's span through the per-lane span shader.
#[inline(always)]
fn rows<M: Madd, const DEPTH: bool, const FLAT: bool, const PERSP: bool, const FULL: bool>(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    for py in b[1]..=b[3] {
        if let Some((lo, hi)) = row_span(t, b, py) {
            shade_span::<M, DEPTH, FLAT, PERSP, FULL>(t, plan, fb, Span::of(py, lo, hi), stats);
        }
    }
}

/// The spans `span(py)` of the rows `rows.0..=rows.1` (an inclusive range of pixels, or
/// `None`) with the planes of `t`, 8 pixels at a time through `shade_row`: a triangle's
/// rows, or a line's or point's (`super::prim_spans`).
///
/// # Safety
/// AVX2 context (FMA when `FMA`); `general_ok` accepted the plan and target; the spans lie
/// inside the target.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) unsafe fn spans8<
    const FMA: bool,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
>(
    t: &SetupTriangle,
    rows: (i64, i64),
    mut span: impl FnMut(i64) -> Option<(i64, i64)>,
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
        for py in rows.0..=rows.1 {
            let Some((lo, hi)) = span(py) else {
                continue;
            };
            // The span two rows down starts near this one's (as in `super::rows_simd`).
            super::prefetch_row(fb, py + 2, lo, hi, DEPTH, 1);
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

#[cfg(all(test, target_arch = "x86_64"))]
mod tests {
    use crate::fixed_function::fog::FogPlan;
    use crate::fragment::{FragPlan, StencilFacePlan, StencilPlan};
    use crate::framebuffer::{ColorFormat, DepthFormat, Framebuffer};
    use crate::geometry::setup::SetupTriangle;
    use crate::geometry::{VARY_FOG, VARY_SPEC};
    use crate::pipe::{CompareFunc, FogMode, StencilOp};
    use crate::raster::tests::{setup_of, vertex};
    use crate::raster::variants::{with_flags, Avx2Fma, Fma, Walks};
    use crate::stats::Stats;

    /// Draws `tris` with `plan` through level `W`'s untextured walk into an RGBA8 target
    /// with depth and stencil prefilled with pseudo-random values; returns the colour,
    /// depth, stencil and counters.
    fn draw<W: Walks>(
        plan: &FragPlan,
        tris: &[SetupTriangle],
    ) -> (Vec<[u8; 4]>, Vec<u32>, Vec<u8>, Stats) {
        let (w, h) = (45, 31);
        let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba, DepthFormat::Z24, true);
        let mut next = crate::test_rng::xorshift32(5);
        for i in 0..w * h {
            fb.color[i] = next().to_le_bytes();
            fb.depth[i] = next() & 0xFF_FFFF;
            fb.stencil[i] = next() as u8;
        }
        let mut stats = Stats::default();
        {
            let mut target = fb.target();
            for t in tris {
                let b = [
                    t.bbox[0].max(0),
                    t.bbox[1].max(0),
                    t.bbox[2].min(w as i64 - 1),
                    t.bbox[3].min(h as i64 - 1),
                ];
                if b[0] > b[2] || b[1] > b[3] {
                    continue;
                }
                let persp = t.persp && (!plan.flat || plan.fog.is_some());
                let depth = plan.depth.is_some();
                with_flags!((depth, plan.flat, persp), |D, F, P| {
                    // SAFETY: the test runs `W` only on a CPU with AVX2 (the caller checks).
                    unsafe { W::untextured::<D, F, P>(t, b, plan, &mut target, &mut stats) }
                });
            }
        }
        let (c, d, s) = (fb.color.to_vec(), fb.depth.to_vec(), fb.stencil.to_vec());
        (c, d, s, stats)
    }

    /// The states the AVX2 span shader leaves (the alpha test, stencil, fog, the colour
    /// sum, a partial colour mask, over the depth and blend plans of `plan_of_round`):
    /// the 8-lane span walk gives the per-lane span shader's bytes and counts.
    #[test]
    fn spans8_match_the_span_shader() {
        if !crate::cpu::isa().avx2() {
            return;
        }
        let mut next = crate::test_rng::xorshift32(0x5350_414e);
        let mut unit = move || next() as f32 / u32::MAX as f32;
        let mut fragments = 0;
        for round in 0..48 {
            let mut plan = super::super::tests::plan_of_round(round);
            plan.fma = true;
            if round % 3 == 0 {
                let func = [CompareFunc::Greater, CompareFunc::LEqual][round % 2];
                plan.alpha = Some((func, 100));
            }
            if round % 4 != 3 {
                let face = StencilFacePlan {
                    func: [CompareFunc::Less, CompareFunc::NotEqual][round % 2],
                    masked_ref: 0x60 & 0xF0,
                    reference: 0x60,
                    mask: 0xF0,
                    fail: StencilOp::Incr,
                    zfail: StencilOp::Invert,
                    zpass: StencilOp::DecrWrap,
                    write: [0xFF, 0x3C][round % 2],
                };
                plan.stencil = Some(StencilPlan {
                    front: face,
                    back: face,
                });
            }
            if round % 5 < 2 {
                plan.fog = Some(FogPlan {
                    mode: [FogMode::Linear, FogMode::Exp, FogMode::Exp2][round % 3],
                    scale: -0.8,
                    bias: 0.9,
                    exp_k: 1.7,
                    exp2_k: 1.3,
                    color: [0.2, 0.7, 0.4],
                    fma: true,
                });
            }
            plan.separate_specular = round % 7 < 3;
            if round % 6 == 1 {
                plan.color_mask = [true, false, true, false];
            }
            let persp = round % 2 == 0;
            let mut tris = vec![];
            while tris.len() < 60 {
                let (cx, cy) = (unit() * 49.0 - 4.0, unit() * 35.0 - 4.0);
                let s = 2.0 + unit() * 20.0;
                let v = std::array::from_fn(|_| {
                    let mut p = vertex(&mut unit, [cx, cy, s, s], persp);
                    for i in VARY_SPEC..VARY_SPEC + 4 {
                        p.vary[i] = unit() * 1.2 - 0.1;
                    }
                    p.vary[VARY_FOG] = unit() * 1.5;
                    p
                });
                tris.extend(setup_of(v, 9, plan.flat));
            }
            let lanes = draw::<Fma>(&plan, &tris);
            let spans8 = draw::<Avx2Fma>(&plan, &tris);
            assert!(lanes.0 == spans8.0, "colour differs in round {round}");
            assert!(lanes.1 == spans8.1, "depth differs in round {round}");
            assert!(lanes.2 == spans8.2, "stencil differs in round {round}");
            // Blend reads are counted per shader (a chunk's lanes inside the row on 8
            // lanes, the pixels read by the span shader).
            let (mut a, mut b) = (lanes.3, spans8.3);
            (a.color_reads, b.color_reads) = (0, 0);
            assert_eq!(a, b, "counters differ in round {round}");
            fragments += lanes.3.fragments;
        }
        assert!(fragments > 10_000, "{fragments}");
    }
}
