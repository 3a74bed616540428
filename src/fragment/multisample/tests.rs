//! Unit tests of `multisample.rs`: the 8-lane chunk shader against the lane path.

use super::*;
use crate::fixed_function::fog::FogPlan;
use crate::fragment::span::{Fused, Unfused};
use crate::fragment::{BlendPlan, DepthPlan};
use crate::framebuffer::{ColorFormat, DepthFormat, Framebuffer};
use crate::geometry::setup::Plane;
use crate::geometry::{VARY_FOG, VARY_SPEC};
use crate::pipe::{BlendEquation, BlendFactor, CompareFunc, FogMode, MAX_TEXTURE_UNITS};

const W: usize = 21;
const H: usize = 3;

/// Plane 0 of a 4-sample object holding planes 1..4, all filled from `seed`.
fn object(seed: u32) -> Framebuffer {
    let mut next = crate::test_rng::xorshift32(seed);
    let mut planes: Vec<Framebuffer> = (0..SAMPLES)
        .map(|_| {
            let mut p = Framebuffer::new(W, H, ColorFormat::Rgba, DepthFormat::Z24, false);
            for (c, d) in p.color.iter_mut().zip(p.depth.iter_mut()) {
                *c = next().to_le_bytes();
                *d = next() & 0xFF_FFFF;
            }
            p
        })
        .collect();
    let mut fb = planes.remove(0);
    fb.hold_samples(planes);
    fb
}

/// Every plane's colour and depth.
fn contents(fb: &Framebuffer) -> Vec<(Vec<[u8; 4]>, Vec<u32>)> {
    std::iter::once(fb)
        .chain(&fb.samples)
        .map(|p| (p.color.to_vec(), p.depth.to_vec()))
        .collect()
}

/// [`shade_chunk_ms8`] with no units, its `1 / w` as the walk takes it.
#[target_feature(enable = "avx2,fma")]
#[allow(clippy::too_many_arguments)]
unsafe fn fast<const FMA: bool, const PERSP: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    fb: &mut Target<'_>,
    py: usize,
    x: usize,
    cov: &[u8; SAMPLES],
    stats: &mut Stats,
) {
    let g = GenPlan::new(plan, t, &[]);
    let tex: TexLanes = [[[0.0; 4]; LANES]; MAX_TEXTURE_UNITS];
    // SAFETY: AVX2 and FMA (this function's features).
    unsafe {
        let fx = F32x8::splat(x as f32)
            .add(F32x8::new([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]))
            .add(F32x8::splat(0.5));
        let fy = F32x8::splat(py as f32 + 0.5);
        let one = F32x8::splat(1.0);
        let oow = if PERSP {
            one.div(super::super::simd::eval::<FMA>(&t.w, fx, fy))
        } else {
            one
        };
        shade_chunk_ms8::<FMA, true, false, PERSP>(
            t,
            plan,
            &g,
            &[],
            &tex,
            fb,
            (py, x),
            cov,
            oow,
            stats,
        );
    }
}

/// The lane-by-lane path of [`shade_chunk_ms`] (no AVX2) for the same chunk.
#[allow(clippy::too_many_arguments)]
fn lanes<M: Madd, const PERSP: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    fb: &mut Target<'_>,
    py: usize,
    x: usize,
    cov: &[u8; SAMPLES],
    stats: &mut Stats,
) {
    let src = ChunkColors::Shaded;
    shade_chunk_ms::<M, false, true, false, PERSP, false>(t, plan, &[], src, fb, py, x, cov, stats);
}

/// The 8-lane chunks of untextured plans with fog or the separate specular colour
/// (with the alpha test, depth functions, blending and sample masks) write every
/// sample plane and count exactly as the lane-by-lane path, fused and unfused, with
/// and without the perspective divide.
#[test]
fn colors8_chunks_match_the_lane_path() {
    let isa = crate::cpu::isa();
    if !isa.avx2() || !crate::cpu::has_fma_instructions() {
        return;
    }
    let mut next = crate::test_rng::xorshift32(0x6d73_6138);
    let mut unit = move || next() as f32 / u32::MAX as f32;
    let mut drawn = 0;
    for round in 0..400 {
        let (fma, persp) = (round % 2 == 0, round % 4 >= 2);
        let mut t = SetupTriangle {
            persp,
            ..SetupTriangle::default()
        };
        let mut plane = |lo: f32, span: f32, step: f32| Plane {
            a0: lo + unit() * span,
            dadx: (unit() - 0.5) * step,
            dady: (unit() - 0.5) * step,
        };
        t.z = plane(0.0, 1.0, 0.2);
        t.w = plane(0.5, 1.0, 0.05);
        for k in (0..4).chain(VARY_SPEC..VARY_SPEC + 3).chain([VARY_FOG]) {
            t.vary[k] = plane(-0.1, 1.2, 0.3);
        }
        let fog = (round % 3 != 0).then_some(FogPlan {
            mode: FogMode::Linear,
            scale: -1.0 / (0.2 + unit()),
            bias: 1.0 + unit(),
            exp_k: 0.0,
            exp2_k: 0.0,
            color: [unit(), unit(), unit()],
            fma,
        });
        let blend = (round % 5 >= 2).then_some(BlendPlan {
            src_rgb: BlendFactor::SrcAlpha,
            dst_rgb: BlendFactor::OneMinusSrcAlpha,
            src_a: BlendFactor::SrcAlpha,
            dst_a: BlendFactor::OneMinusSrcAlpha,
            eq_rgb: BlendEquation::Add,
            eq_a: if round % 5 == 4 {
                BlendEquation::Max
            } else {
                BlendEquation::Add
            },
            color: [0; 4],
        });
        let plan = FragPlan {
            depth: Some(DepthPlan {
                func: [CompareFunc::Less, CompareFunc::LEqual, CompareFunc::Greater][round % 3],
                write: round % 7 != 0,
                format: DepthFormat::Z24,
            }),
            flat: false,
            color_mask: [true, true, round % 6 != 1, true],
            fma,
            alpha: (round % 4 == 1).then_some((CompareFunc::Greater, 100)),
            stencil: None,
            blend,
            logic: None,
            separate_specular: fog.is_none() || round % 2 == 1,
            fog,
            count_samples: round % 3 == 1,
            smooth: None,
            ms: Some(MsPass {
                mask: [0xF, 0xF, 0x5, 0xE][round % 4],
                alpha_to_coverage: false,
            }),
            blend_color: [0.0; 4],
            srgb: false,
            shader: None,
            more_buffers: 0,
        };
        let (py, x) = (round % H, [0, 4, 8, 13][round % 4]);
        let cov: [u8; SAMPLES] = std::array::from_fn(|_| (unit() * 256.0) as u8);
        let (mut a, mut b) = (object(round as u32 + 1), object(round as u32 + 1));
        let (mut sa, mut sb) = (Stats::default(), Stats::default());
        {
            let (mut ta, mut tb) = (a.target(), b.target());
            assert!(colors8_ok(&plan, &ta, false));
            let cov_n = cov;
            // SAFETY: AVX2 and FMA were detected above.
            unsafe {
                match (fma, persp) {
                    (true, true) => fast::<true, true>(&t, &plan, &mut ta, py, x, &cov_n, &mut sa),
                    (true, false) => {
                        fast::<true, false>(&t, &plan, &mut ta, py, x, &cov_n, &mut sa)
                    }
                    (false, true) => {
                        fast::<false, true>(&t, &plan, &mut ta, py, x, &cov_n, &mut sa)
                    }
                    (false, false) => {
                        fast::<false, false>(&t, &plan, &mut ta, py, x, &cov_n, &mut sa)
                    }
                }
            }
            match (fma, persp) {
                (true, true) => lanes::<Fused, true>(&t, &plan, &mut tb, py, x, &cov_n, &mut sb),
                (true, false) => lanes::<Fused, false>(&t, &plan, &mut tb, py, x, &cov_n, &mut sb),
                (false, true) => lanes::<Unfused, true>(&t, &plan, &mut tb, py, x, &cov_n, &mut sb),
                (false, false) => {
                    lanes::<Unfused, false>(&t, &plan, &mut tb, py, x, &cov_n, &mut sb)
                }
            }
        }
        assert!(
            contents(&a) == contents(&b),
            "planes differ in round {round}"
        );
        assert_eq!(sa, sb, "counters differ in round {round}");
        drawn += sa.color_writes;
    }
    assert!(drawn > 400, "{drawn}");
}
