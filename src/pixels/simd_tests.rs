//! [`super`]'s 8-lane pixel-rectangle fragments against the per-lane ones
//! ([`crate::pixels::rect::Fragments`]): the same bytes and counters over random
//! per-fragment states, quads and images.

use super::SCALAR_ONLY;
use crate::fragment::{BlendPlan, DepthPlan, FragPlan, StencilFacePlan, StencilPlan};
use crate::framebuffer::{ColorFormat, DepthFormat, Framebuffer};
use crate::pipe::{BlendEquation, BlendFactor, CompareFunc, LogicOp, StencilOp};
use crate::pixels::draw::{run, Source, Target};
use crate::pixels::rect::Quad;
use crate::stats::Stats;

/// What a draw leaves: colour, depth, stencil and counters.
type Drawn = (Vec<[u8; 4]>, Vec<u32>, Vec<u8>, Stats);

/// Draws `src` as quad `q` with `plan` into a 53x41 RGBA8 buffer with Z24 depth and
/// stencil prefilled with pseudo-random values, through the per-lane path when `scalar`.
fn draw(plan: &FragPlan, q: &Quad, src: Source<'_>, scalar: bool, y_flip: bool) -> Drawn {
    let (w, h) = (53, 41);
    let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba, DepthFormat::Z24, true);
    fb.y_flip = y_flip;
    let mut next = crate::test_rng::xorshift32(11);
    for i in 0..w * h {
        fb.color[i] = next().to_le_bytes();
        fb.depth[i] = next() & 0xFF_FFFF;
        fb.stencil[i] = next() as u8;
    }
    let mut stats = Stats::default();
    SCALAR_ONLY.with(|s| s.set(scalar));
    let t = Target {
        fb: &mut fb,
        plan,
        region: [2, 3, w as i64 - 1, h as i64 - 4],
        stencil_mask: 0xFF,
        fma: false,
        stats: &mut stats,
    };
    run(t, q, src);
    SCALAR_ONLY.with(|s| s.set(false));
    (
        fb.color.to_vec(),
        fb.depth.to_vec(),
        fb.stencil.to_vec(),
        stats,
    )
}

/// A random per-fragment state of the kinds [`super::covers`] accepts: depth (any
/// function, written or not), stencil (any function, operations and masks), the alpha
/// test, blending (any factors and equations) or a logic op, and the colour mask.
fn plan(r: &mut impl FnMut() -> u32) -> FragPlan {
    use BlendEquation as E;
    use BlendFactor as F;
    use CompareFunc as C;
    use StencilOp as S;
    let funcs = [
        C::Never,
        C::Less,
        C::Equal,
        C::LEqual,
        C::Greater,
        C::NotEqual,
        C::GEqual,
        C::Always,
    ];
    let ops = [
        S::Keep,
        S::Zero,
        S::Replace,
        S::Incr,
        S::Decr,
        S::Invert,
        S::IncrWrap,
        S::DecrWrap,
    ];
    let factors = [
        F::Zero,
        F::One,
        F::SrcColor,
        F::OneMinusSrcColor,
        F::DstColor,
        F::OneMinusDstColor,
        F::SrcAlpha,
        F::OneMinusSrcAlpha,
        F::DstAlpha,
        F::OneMinusDstAlpha,
        F::ConstantColor,
        F::OneMinusConstantColor,
        F::ConstantAlpha,
        F::OneMinusConstantAlpha,
        F::SrcAlphaSaturate,
    ];
    let eqs = [E::Add, E::Subtract, E::ReverseSubtract, E::Min, E::Max];
    let mut pick = |n: usize| r() as usize % n;
    let depth = (pick(3) != 0).then(|| DepthPlan {
        func: funcs[pick(8)],
        write: pick(2) == 0,
        format: DepthFormat::Z24,
    });
    let with_stencil = pick(3) == 0;
    let (reference, mask) = (pick(256) as u8, [0xFF, 0x0F, 0x3C][pick(3)]);
    let face = StencilFacePlan {
        func: funcs[pick(8)],
        masked_ref: reference & mask,
        reference,
        mask,
        fail: ops[pick(8)],
        zfail: ops[pick(8)],
        zpass: ops[pick(8)],
        write: [0xFF, 0xF0, 0][pick(3)],
    };
    let stencil = with_stencil.then_some(StencilPlan {
        front: face,
        back: face,
    });
    let blend = BlendPlan {
        src_rgb: factors[pick(15)],
        dst_rgb: factors[pick(15)],
        src_a: factors[pick(15)],
        dst_a: factors[pick(15)],
        eq_rgb: eqs[pick(5)],
        eq_a: eqs[pick(5)],
        color: [
            pick(256) as u8,
            pick(256) as u8,
            pick(256) as u8,
            pick(256) as u8,
        ],
    };
    let over = BlendPlan {
        src_rgb: F::SrcAlpha,
        dst_rgb: F::OneMinusSrcAlpha,
        src_a: F::SrcAlpha,
        dst_a: F::OneMinusSrcAlpha,
        eq_rgb: E::Add,
        eq_a: E::Add,
        color: [0; 4],
    };
    let (blend, logic) = match pick(4) {
        0 => (Some(blend), None),
        1 => (Some(over), None),
        2 => (None, Some(LogicOp::ALL[pick(LogicOp::ALL.len())])),
        _ => (None, None),
    };
    let alpha = (pick(4) == 0).then(|| (funcs[pick(8)], pick(256) as u8));
    let color_mask = if pick(3) == 0 {
        [pick(2) == 0, pick(2) == 0, pick(2) == 0, pick(2) == 0]
    } else {
        [true; 4]
    };
    FragPlan {
        depth,
        flat: false,
        color_mask,
        fma: false,
        alpha,
        stencil,
        blend,
        logic,
        separate_specular: false,
        fog: None,
        count_samples: pick(2) == 0,
        smooth: None,
        ms: None,
        blend_color: [0.0; 4],
        srgb: false,
        shader: None,
    }
}

#[test]
fn lanes_match_the_per_lane_fragments() {
    if !crate::cpu::isa().avx2() {
        return;
    }
    let mut r = crate::test_rng::xorshift32(0x7069_7865);
    let mut drawn = 0u64;
    for case in 0..300 {
        let plan = plan(&mut r);
        let zoom = |r: &mut dyn FnMut() -> u32| match r() % 4 {
            0 => 1.0,
            1 => -1.0 - (r() % 6) as f32 * 0.25,
            _ => 0.5 + (r() % 10) as f32 * 0.25,
        };
        let q = Quad {
            x: (r() % 90) as i32 - 20,
            y: (r() % 80) as i32 - 20,
            w: 1 + (r() % 40) as usize,
            h: 1 + (r() % 30) as usize,
            zoom: [zoom(&mut r), zoom(&mut r)],
            z: (r() % 1000) as f32 / 1000.0,
            flip_t: r() & 1 == 0,
        };
        let n = q.w * q.h;
        // Colours in and around [0, 1] (the conversion clamps), a NaN now and then.
        let mut unit = || match r() % 50 {
            0 => f32::NAN,
            _ => (r() % 1400) as f32 / 1000.0 - 0.2,
        };
        let colors: Vec<[f32; 4]> = (0..n).map(|_| [unit(), unit(), unit(), unit()]).collect();
        let bits: Vec<bool> = (0..n).map(|_| r() % 3 != 0).collect();
        let flip = case % 2 == 0;
        let (a, b) = if case % 3 == 0 {
            let c = colors[0];
            (
                draw(&plan, &q, Source::Mask(&bits, c), true, flip),
                draw(&plan, &q, Source::Mask(&bits, c), false, flip),
            )
        } else {
            (
                draw(&plan, &q, Source::Color(&colors), true, flip),
                draw(&plan, &q, Source::Color(&colors), false, flip),
            )
        };
        assert!(a == b, "case {case}: {plan:?} {q:?}");
        drawn += a.3.fragments;
    }
    // The quads reached the buffer.
    assert!(drawn > 20_000, "{drawn} fragments");
}
