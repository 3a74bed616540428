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
        more_buffers: 0,
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

/// Round `round`'s case of `h` rows (flat varyings set) and its texels, as samplers give
/// them: unorm8 values, some exact 0 and 1.
fn round_case(round: u32, h: usize) -> (Case, Vec<TexLanes>) {
    let mut c = Case::new(round.wrapping_mul(7919) + 1, 27, h, round.is_multiple_of(3));
    for (k, f) in c.t.flat.iter_mut().enumerate() {
        *f = (k as f32 * 0.37).fract();
    }
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
    (c, tex)
}

/// The case's framebuffer before drawing, its depth in the plan's format.
fn fresh(c: &Case, plan: &FragPlan) -> Framebuffer {
    let format = plan.depth.map_or(DepthFormat::Z24, |d| d.format);
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
}

/// Draws the case's triangle `times` times through the engine (the k-th with its depth
/// and varyings moved by k steps; with `split` only the chunks `i` with `i % times == k`,
/// so that no two triangles share a pixel): one walk for them all (`one`), or one walk per
/// triangle; `None` when the plan does not lower.
#[allow(clippy::too_many_arguments)]
fn walks(
    c: &Case,
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    tex: &[TexLanes],
    persp: bool,
    times: usize,
    one: bool,
    split: bool,
) -> Option<(Framebuffer, Stats)> {
    let mut fb = fresh(c, plan);
    let mut stats = Stats::default();
    {
        let mut target = fb.target();
        let mut w = Walk::new(plan, units, persp, &target)?;
        for k in 0..times {
            if k > 0 && !one {
                w.end(&mut target, &mut stats);
                w = Walk::new(plan, units, persp, &target)?;
            }
            // Each triangle's planes its own (a row reading another's would show).
            let mut t = c.t.clone();
            t.z.a0 -= 0.01 * k as f32;
            for v in t.vary.iter_mut() {
                v.a0 += 0.05 * k as f32;
            }
            w.begin(&t, &mut target, &mut stats);
            for (i, (&(y, x, live), tx)) in c.chunks.iter().zip(tex).enumerate() {
                if !split || i % times == k {
                    w.row(&mut target, y, x, &live, tx, &mut stats);
                }
            }
        }
        w.end(&mut target, &mut stats);
    }
    Some((fb, stats))
}

/// Asserts that two drawings left the same colour and depth bytes and counters.
fn same(what: &str, got: (&Framebuffer, &Stats), want: (&Framebuffer, &Stats)) {
    assert!(
        got.0.color[..] == want.0.color[..],
        "{what}: colours differ"
    );
    assert!(got.0.depth[..] == want.0.depth[..], "{what}: depths differ");
    assert_eq!(got.1, want.1, "{what}: counters differ");
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
        let (c, tex) = round_case(round, 9);
        let mut want_fb = fresh(&c, &plan);
        let want = today(&c, &plan, &units, &tex, persp, &mut want_fb);
        let Some((got_fb, got)) = walks(&c, &plan, &units, &tex, persp, 1, true, false) else {
            panic!("{plan:?} does not lower");
        };
        lowered += 1;
        let what = format!(
            "round {round}: {plan:?} {:?}",
            units.iter().map(|u| u.env).collect::<Vec<_>>()
        );
        same(&what, (&got_fb, &got), (&want_fb, &want));
    }
    assert_eq!(lowered, 300);
}

/// One walk over several triangles (a shader draw's batches) against a walk per
/// triangle: three triangles with planes of their own, either each over the whole case,
/// so that every row of the second and third overlaps a pending row and must wait for it
/// (blending reads what the earlier one wrote), or on disjoint chunks, so that the rows
/// of all three share a batch. The same bytes and counters.
#[test]
fn one_walk_over_overlapping_triangles_matches_a_walk_each() {
    let mut next = crate::test_rng::xorshift32(0x5eed_0b47);
    let mut pick = |n: u32| (next() % n) as usize;
    let mut blended = 0;
    for round in 0..200u32 {
        let (plan, units) = random_state(&mut pick);
        let persp = round % 2 == 1;
        // Fewer chunks than a batch holds: the second triangle's first row meets the
        // first triangle's pending rows.
        let (c, tex) = round_case(round + 1000, 5);
        assert!(c.chunks.len() < super::exec::MAX_BATCH);
        let split = round % 4 < 2;
        let (Some((want_fb, want)), Some((got_fb, got))) = (
            walks(&c, &plan, &units, &tex, persp, 3, false, split),
            walks(&c, &plan, &units, &tex, persp, 3, true, split),
        ) else {
            panic!("{plan:?} does not lower");
        };
        let what = format!("round {round} (split {split}): {plan:?}");
        same(&what, (&got_fb, &got), (&want_fb, &want));
        blended += usize::from(plan.blend.is_some() && plan.color_mask != [false; 4]);
    }
    assert!(blended > 100, "{blended}");
}
