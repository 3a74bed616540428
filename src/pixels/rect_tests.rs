//! Tests of [`super::rasterize`]'s texel selection.

use super::*;
use crate::test_rng::xorshift32;

/// The texel every pixel's own plane evaluation selects (the selection before columns
/// were cached), for the span of `tri` at row `py` from `x` on.
fn per_pixel<M: Madd>(tri: &SetupTriangle, q: &Quad, py: usize, x: usize, n: usize) -> Vec<usize> {
    let (ps, pt) = (&tri.vary[VARY_TEX], &tri.vary[VARY_TEX + 1]);
    (x..x + n)
        .map(|px| {
            let (fx, fy) = (px as f32, py as f32);
            texel_at(eval::<M>(pt, fx, fy), q.h as f32, q.h) * q.w
                + texel_at(eval::<M>(ps, fx, fy), q.w as f32, q.w)
        })
        .collect()
}

#[test]
fn cached_columns_select_the_texels_of_per_pixel_evaluation() {
    let mut r = xorshift32(0x5eed_0042);
    let (mut spans, mut cached) = (0usize, 0usize);
    for case in 0..400 {
        let fma = case % 2 == 0;
        let (fb_w, fb_h) = (64 + (r() % 200) as usize, 64 + (r() % 200) as usize);
        let zoom = |r: &mut dyn FnMut() -> u32| match r() % 4 {
            0 => 1.0,
            1 => -1.0 - (r() % 8) as f32 * 0.25,
            _ => 0.25 + (r() % 16) as f32 * 0.25,
        };
        let q = Quad {
            x: (r() % (fb_w as u32 + 80)) as i32 - 40,
            y: (r() % (fb_h as u32 + 80)) as i32 - 40,
            w: 1 + (r() % 100) as usize,
            h: 1 + (r() % 100) as usize,
            zoom: [zoom(&mut r), zoom(&mut r)],
            z: (r() % 1000) as f32 / 1000.0,
            flip_t: r() & 1 == 0,
        };
        let x0 = (r() % 20) as i64;
        let y0 = (r() % 20) as i64;
        let d = Dest {
            fb_w,
            fb_h,
            region: [x0, y0, fb_w as i64 - x0, fb_h as i64 - y0],
            fma,
            y_flip: r() & 1 == 0,
        };
        rasterize(&q, &d, |tri, py, x, texels| {
            let (ps, pt) = (&tri.vary[VARY_TEX], &tri.vary[VARY_TEX + 1]);
            spans += 1;
            cached += usize::from(ps.dady == 0.0 && pt.dadx == 0.0);
            // Fused is one rounding whether an instruction or `fmaf` computes it.
            let want = if fma {
                per_pixel::<Fused>(tri, &q, py, x, texels.len())
            } else {
                per_pixel::<Unfused>(tri, &q, py, x, texels.len())
            };
            assert_eq!(
                texels,
                &want[..],
                "case {case} row {py} from {x}: {q:?} {d:?}"
            );
        });
    }
    // Both selections ran, the cached one on most spans.
    assert!(cached > spans / 2 && cached < spans, "{cached} of {spans}");
}

/// The fragment plan of round `round` of [`ready_rows_match_per_lane_byte_for_byte`]:
/// depth off or one of three functions (written or not), the alpha test of every
/// function, no blend, "over", an additive blend or a logic op, the stencil test with
/// every operation, a partial colour mask.
#[cfg(target_arch = "x86_64")]
fn ready_plan(round: usize) -> FragPlan {
    use crate::fragment::{BlendPlan, DepthPlan, StencilFacePlan, StencilPlan};
    use crate::framebuffer::DepthFormat;
    use crate::pipe::{BlendEquation, BlendFactor, CompareFunc, LogicOp, StencilOp};
    let funcs = CompareFunc::ALL;
    let ops = [
        StencilOp::Keep,
        StencilOp::Zero,
        StencilOp::Replace,
        StencilOp::Incr,
        StencilOp::Decr,
        StencilOp::Invert,
        StencilOp::IncrWrap,
        StencilOp::DecrWrap,
    ];
    let (src, dst) = if round % 8 >= 6 {
        (BlendFactor::DstColor, BlendFactor::One)
    } else {
        (BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha)
    };
    let face = StencilFacePlan {
        func: funcs[round * 3 % 8],
        masked_ref: (round * 29 % 256) as u8 & 0xF3,
        reference: (round * 29 % 256) as u8,
        mask: 0xF3,
        fail: ops[round % 8],
        zfail: ops[(round + 3) % 8],
        zpass: ops[(round + 5) % 8],
        write: 0xBF,
    };
    FragPlan {
        depth: (!round.is_multiple_of(4)).then_some(DepthPlan {
            func: [CompareFunc::Less, CompareFunc::LEqual, CompareFunc::Greater][round % 3],
            write: !round.is_multiple_of(5),
            format: DepthFormat::Z24,
        }),
        flat: false,
        color_mask: [true, round % 7 != 3, true, round % 5 != 2],
        fma: crate::cpu::isa().fused(),
        alpha: (round % 3 != 2).then_some((funcs[round % 8], (round * 37 % 256) as u8)),
        stencil: (round % 3 == 1).then_some(StencilPlan {
            front: face,
            back: face,
        }),
        blend: (round % 4 >= 2).then_some(BlendPlan {
            src_rgb: src,
            dst_rgb: dst,
            src_a: src,
            dst_a: dst,
            eq_rgb: BlendEquation::Add,
            eq_a: BlendEquation::Add,
            color: [0; 4],
        }),
        logic: (round % 4 == 1).then_some(LogicOp::Xor),
        separate_specular: false,
        fog: None,
        count_samples: false,
        smooth: None,
        ms: None,
        blend_color: [0.0; 4],
        srgb: false,
        shader: None,
        more_buffers: 0,
    }
}

/// Pixel-rectangle fragments through the 8-lane fragment shader (the path of AVX2
/// levels) give the per-lane shader's colour, depth, stencil and counters (but the blend
/// reads, which each shader counts its own way, as for triangles), for 64 plans over
/// zoomed, clipped rectangles whose pixels have random colours, some with no fragment.
#[cfg(target_arch = "x86_64")]
#[test]
fn ready_rows_match_per_lane_byte_for_byte() {
    use crate::framebuffer::{ColorFormat, DepthFormat, Framebuffer};
    if !crate::cpu::isa().avx2() {
        return;
    }
    let (w, h) = (45, 37);
    let mut covered = 0;
    for round in 0..64 {
        let plan = ready_plan(round);
        let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba, DepthFormat::Z24, true);
        assert!(crate::fragment::simd_gen::plan_ok(&plan, &fb.target()));
        let q = Quad {
            x: (round as i32 * 7) % 30 - 6,
            y: (round as i32 * 5) % 25 - 5,
            w: 9 + round % 13,
            h: 5 + round % 11,
            zoom: [
                1.0 + (round % 4) as f32 * 0.75,
                1.0 + (round % 3) as f32 * 0.5,
            ],
            z: (round % 10) as f32 / 10.0,
            flip_t: false,
        };
        let d = Dest {
            fb_w: w,
            fb_h: h,
            region: [0, 0, w as i64, h as i64],
            fma: plan.fma,
            y_flip: false,
        };
        let mut run = |simd: bool| {
            let mut next = xorshift32(0x0052_4543 + round as u32);
            for ((c, z), s) in fb
                .color
                .iter_mut()
                .zip(fb.depth.iter_mut())
                .zip(fb.stencil.iter_mut())
            {
                *c = next().to_le_bytes();
                *z = next() & 0xFF_FFFF;
                *s = next() as u8;
            }
            let mut stats = Stats::default();
            {
                let mut f = Fragments::new(&plan, fb.target(), &mut stats);
                rasterize(&q, &d, |tri, py, x, texels| {
                    for (k, chunk) in texels.chunks(LANES).enumerate() {
                        let mut c = [[0u8; LANES]; 4];
                        let mut cf = [[0f32; LANES]; 4];
                        let mut live = [false; LANES];
                        for (l, &texel) in chunk.iter().enumerate() {
                            let v = (texel as u32).wrapping_mul(0x9E37_79B9) ^ round as u32;
                            live[l] = !v.is_multiple_of(7);
                            for ch in 0..4 {
                                c[ch][l] = (v >> (8 * ch)) as u8;
                                cf[ch][l] = c[ch][l] as f32 / 255.0;
                            }
                        }
                        let x = x + k * LANES;
                        if simd {
                            // SAFETY: `isa().avx2()` (AVX2 with FMA) and `plan_ok` above.
                            unsafe { f.ready_avx2fma(tri, py, x, live, &c, &cf) };
                        } else {
                            f.shade_any(tri, py, x, live, &c, &cf);
                        }
                    }
                });
            }
            stats.color_reads = 0;
            (
                fb.color.to_vec(),
                fb.depth.to_vec(),
                fb.stencil.to_vec(),
                stats,
            )
        };
        let lanes = run(false);
        let simd = run(true);
        assert!(lanes.0 == simd.0, "colour differs in round {round}");
        assert!(lanes.1 == simd.1, "depth differs in round {round}");
        assert!(lanes.2 == simd.2, "stencil differs in round {round}");
        assert_eq!(lanes.3, simd.3, "counters differ in round {round}");
        covered += lanes.3.fragments;
    }
    assert!(covered > 64 * 100, "{covered} fragments");
}
