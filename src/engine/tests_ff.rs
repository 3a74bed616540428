//! The fixed-function lowering ([`super::ff`]) through the draw path's [`Walk`] against
//! the per-lane general shader [`shade_chunk`] (which the C scenes hold to llvmpipe's
//! bytes): random units with random environments and combiner states (the crossbar
//! included), flat shading, the colour sum, fog of every mode, the alpha test, depth on
//! Z16, Z24 and Z32F buffers, blending, colour masks and sample counting; the colour and
//! depth bytes and every counter must be the same.

use super::draw::Walk;
use super::tests::{modulate_unit, Case};
use crate::fixed_function::fog::FogPlan;
use crate::fragment::span::{shade_chunk, ChunkColors, Fused, Madd, TexLanes, Unfused, LANES};
use crate::fragment::{BlendPlan, DepthPlan, FragPlan};
use crate::framebuffer::{ColorFormat, DepthFormat, Framebuffer};
use crate::pipe::{BlendEquation, BlendFactor, FogMode, MAX_TEXTURE_UNITS};
use crate::stats::Stats;
use crate::texture::UnitPlan;

/// A random state and its units (see the module doc).
fn random_state(pick: &mut dyn FnMut(u32) -> usize) -> (FragPlan, Vec<UnitPlan<'static>>) {
    let n = 1 + pick(3);
    let mut units = Vec::new();
    for unit in 0..n {
        let mut c = crate::texture::env::tests::random_combine(pick);
        c.canonicalise(unit, unit == 0, |k| (k < n).then_some(k));
        let mut u = modulate_unit();
        u.env = c;
        u.fast = None;
        units.push(u);
    }
    let funcs = super::exec::FUNCS;
    let factors = [
        BlendFactor::One,
        BlendFactor::SrcAlpha,
        BlendFactor::OneMinusSrcAlpha,
        BlendFactor::DstColor,
        BlendFactor::OneMinusConstantAlpha,
    ];
    let fma = crate::cpu::isa().fused();
    let formats = [DepthFormat::Z24, DepthFormat::Z16, DepthFormat::Z32F];
    let blend = (pick(3) > 0).then(|| BlendPlan {
        src_rgb: factors[pick(5)],
        dst_rgb: factors[pick(5)],
        src_a: factors[pick(5)],
        dst_a: factors[pick(5)],
        eq_rgb: [BlendEquation::Add, BlendEquation::Subtract][pick(2)],
        eq_a: BlendEquation::Add,
        color: [10, 200, 30, 77],
    });
    let fog_mode = [FogMode::Linear, FogMode::Exp, FogMode::Exp2][pick(3)];
    let plan = FragPlan {
        depth: (pick(4) > 0).then(|| DepthPlan {
            func: funcs[pick(8)],
            write: pick(2) == 0,
            format: formats[pick(3)],
        }),
        flat: pick(3) == 0,
        color_mask: if pick(3) == 0 {
            [pick(2) == 0, pick(2) == 0, pick(2) == 0, pick(2) == 0]
        } else {
            [true; 4]
        },
        fma,
        alpha: (pick(2) == 0).then(|| (funcs[pick(8)], pick(256) as u8)),
        stencil: None,
        blend,
        logic: None,
        separate_specular: pick(2) == 0,
        fog: (pick(2) == 0).then_some(FogPlan {
            mode: fog_mode,
            scale: -1.0 / 7.5,
            bias: 9.0 / 7.5,
            exp_k: 0.3,
            exp2_k: 0.2,
            color: [0.25, 0.5, 0.875],
            fma,
        }),
        count_samples: pick(2) == 0,
        smooth: None,
        ms: None,
        blend_color: [0.0; 4],
        srgb: false,
        shader: None,
    };
    (plan, units)
}

/// The per-lane shader over the case's chunks (texels `tex`), with the plan's constants.
fn run_today<M: Madd, const DEPTH: bool, const FLAT: bool, const PERSP: bool>(
    c: &Case,
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    tex: &[TexLanes],
    fb: &mut Framebuffer,
) -> Stats {
    let mut stats = Stats::default();
    let mut target = fb.target();
    for (&(y, x, live), tx) in c.chunks.iter().zip(tex) {
        if !live.iter().any(|&l| l) {
            continue;
        }
        shade_chunk::<M, DEPTH, FLAT, PERSP, true>(
            &c.t,
            plan,
            units,
            ChunkColors::Textured(tx),
            &mut target,
            y,
            x,
            live,
            &mut stats,
        );
    }
    stats
}

/// [`run_today`] for the plan's depth, shading and `persp`, fused as the CPU's level.
fn today(
    c: &Case,
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    tex: &[TexLanes],
    persp: bool,
    fb: &mut Framebuffer,
) -> Stats {
    macro_rules! go {
        ($m:ty) => {
            match (plan.depth.is_some(), plan.flat, persp) {
                (false, false, false) => {
                    run_today::<$m, false, false, false>(c, plan, units, tex, fb)
                }
                (false, false, true) => {
                    run_today::<$m, false, false, true>(c, plan, units, tex, fb)
                }
                (false, true, false) => {
                    run_today::<$m, false, true, false>(c, plan, units, tex, fb)
                }
                (false, true, true) => run_today::<$m, false, true, true>(c, plan, units, tex, fb),
                (true, false, false) => {
                    run_today::<$m, true, false, false>(c, plan, units, tex, fb)
                }
                (true, false, true) => run_today::<$m, true, false, true>(c, plan, units, tex, fb),
                (true, true, false) => run_today::<$m, true, true, false>(c, plan, units, tex, fb),
                (true, true, true) => run_today::<$m, true, true, true>(c, plan, units, tex, fb),
            }
        };
    }
    if crate::cpu::isa().fused() {
        go!(Fused)
    } else {
        go!(Unfused)
    }
}

/// Random states through the engine's walk and through `shade_chunk`: the same colour
/// and depth bytes and the same counters.
#[test]
fn walk_matches_shade_chunk_on_random_states() {
    let mut next = crate::test_rng::xorshift32(0x0e4_9155);
    let mut pick = |n: u32| (next() % n) as usize;
    let mut lowered = 0;
    for round in 0..300u32 {
        let (plan, units) = random_state(&mut pick);
        let persp = round % 2 == 0;
        let mut c = Case::new(round.wrapping_mul(7919) + 1, 27, 9, round % 3 == 0);
        for (k, f) in c.t.flat.iter_mut().enumerate() {
            *f = (k as f32 * 0.37).fract();
        }
        // Texel values as samplers give them: unorm8 values, some exact 0 and 1.
        let mut bits = crate::test_rng::xorshift32(round + 99);
        let tex: Vec<TexLanes> = c
            .chunks
            .iter()
            .map(|_| {
                let mut t: TexLanes = [[[0.0; 4]; LANES]; MAX_TEXTURE_UNITS];
                for u in t.iter_mut() {
                    for l in u.iter_mut() {
                        *l = std::array::from_fn(|_| (bits() % 256) as f32 / 255.0);
                    }
                }
                t
            })
            .collect();
        let format = plan.depth.map_or(DepthFormat::Z24, |d| d.format);
        let fresh = || {
            let mut fb = Framebuffer::new(c.w, c.h, ColorFormat::Rgba, format, false);
            fb.color.copy_from_slice(&c.color);
            for (d, &v) in fb.depth.iter_mut().zip(&c.depth) {
                *d = match format {
                    DepthFormat::Z16 => v & 0xFFFF,
                    DepthFormat::Z32F => (v as f32 / 16_777_215.0).to_bits(),
                    _ => v,
                };
            }
            fb
        };
        let mut want_fb = fresh();
        let want = today(&c, &plan, &units, &tex, persp, &mut want_fb);
        let mut got_fb = fresh();
        let mut got = Stats::default();
        {
            let mut target = got_fb.target();
            let Some(mut w) = Walk::new(&plan, &units, persp, &target) else {
                panic!("{plan:?} does not lower");
            };
            w.begin(&c.t);
            for (&(y, x, live), tx) in c.chunks.iter().zip(&tex) {
                w.row(&c.t, &mut target, y, x, &live, tx, &mut got);
            }
            w.end(&c.t, &mut target, &mut got);
        }
        lowered += 1;
        let what = format!(
            "round {round}: {plan:?} {:?}",
            units.iter().map(|u| u.env).collect::<Vec<_>>()
        );
        assert!(
            got_fb.color[..] == want_fb.color[..],
            "{what}: colours differ"
        );
        assert!(
            got_fb.depth[..] == want_fb.depth[..],
            "{what}: depths differ"
        );
        assert_eq!(got, want, "{what}: counters differ");
    }
    assert_eq!(lowered, 300);
}
