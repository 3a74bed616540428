//! The 8-lane colour write of wide buffers (`softgl::fragment::simd_wide::store8`)
//! against the per-pixel store (`softgl::fragment::wide::store`), the reference it must
//! match bit for bit, on random stores: every precision, with and without alpha,
//! one-channel images, colour masks, every blend factor and equation (fused and not),
//! logic ops, stale 8-bit mirrors, shader colours out of range, NaN and signed zeros, and
//! chunks cut short at the end of the rows.

#![cfg(target_arch = "x86_64")]

use softgl::fragment::simd_wide::{covers, store8};
use softgl::fragment::span::LANES;
use softgl::fragment::wide::WideDst;
use softgl::fragment::{BlendPlan, FragPlan};
use softgl::framebuffer::samples::PlaneRows;
use softgl::framebuffer::wide::f16_round;
use softgl::framebuffer::WideKind;
use softgl::pipe::{BlendEquation, BlendFactor, LogicOp};
use softgl::simd::{F32x8, I32x8};

/// A xorshift32 generator (the tests' fixed seeds).
fn xorshift32(mut seed: u32) -> impl FnMut() -> u32 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        seed
    }
}

/// Every factor, each "one minus" one after its positive one (ONE after ZERO): factor
/// `2i` and `2i + 1` are complements, SRC_ALPHA_SATURATE (14) has none.
const FACTORS: [BlendFactor; 15] = [
    BlendFactor::Zero,
    BlendFactor::One,
    BlendFactor::SrcColor,
    BlendFactor::OneMinusSrcColor,
    BlendFactor::DstColor,
    BlendFactor::OneMinusDstColor,
    BlendFactor::SrcAlpha,
    BlendFactor::OneMinusSrcAlpha,
    BlendFactor::DstAlpha,
    BlendFactor::OneMinusDstAlpha,
    BlendFactor::ConstantColor,
    BlendFactor::OneMinusConstantColor,
    BlendFactor::ConstantAlpha,
    BlendFactor::OneMinusConstantAlpha,
    BlendFactor::SrcAlphaSaturate,
];

const EQUATIONS: [BlendEquation; 5] = [
    BlendEquation::Add,
    BlendEquation::Subtract,
    BlendEquation::ReverseSubtract,
    BlendEquation::Min,
    BlendEquation::Max,
];

/// One store's inputs.
struct Case {
    dst: WideDst,
    plan: FragPlan,
    color: Vec<[u8; 4]>,
    wide: Vec<[f32; 4]>,
    idx: usize,
    bits: u32,
    src: [[f32; LANES]; 4],
}

/// The plan of a random store (`fma`: whether the blend lerp fuses).
fn plan(next: &mut impl FnMut() -> u32, fma: bool) -> FragPlan {
    let r = next();
    let mut pick = |n: usize| (next() as usize) % n;
    let blend = if !r.is_multiple_of(5) {
        // Pairs that fold (equal or complementary factors) half the time.
        let (src_rgb, src_a) = (pick(15), pick(15));
        // The same factor or its complement.
        let fold = |f: usize, c: usize| if f < 14 { f ^ c } else { f };
        let (dst_rgb, dst_a) = if pick(2) == 0 {
            (fold(src_rgb, pick(2)), fold(src_a, pick(2)))
        } else {
            (pick(15), pick(15))
        };
        let [src_rgb, src_a, dst_rgb, dst_a] = [src_rgb, src_a, dst_rgb, dst_a].map(|i| FACTORS[i]);
        Some(BlendPlan {
            src_rgb,
            dst_rgb,
            src_a,
            dst_a,
            eq_rgb: EQUATIONS[pick(5)],
            eq_a: EQUATIONS[pick(5)],
            color: [0; 4],
        })
    } else {
        None
    };
    let logic = if r % 7 == 3 {
        Some([LogicOp::Xor, LogicOp::And, LogicOp::Invert][pick(3)])
    } else {
        None
    };
    let color_mask = if pick(3) == 0 {
        [pick(2) == 0, pick(2) == 0, pick(2) == 0, pick(2) == 0]
    } else {
        [true; 4]
    };
    let mut unit = || pick(1 << 20) as f32 / (1 << 20) as f32;
    let blend_color = [unit(), unit() * 1.5 - 0.25, unit(), unit()];
    FragPlan {
        depth: None,
        flat: false,
        color_mask,
        fma,
        alpha: None,
        stencil: None,
        blend,
        logic,
        separate_specular: false,
        fog: None,
        count_samples: false,
        smooth: None,
        ms: None,
        blend_color,
        srgb: false,
        shader: None,
        more_buffers: 0,
    }
}

/// A random value of a float channel: mostly in [-0.25, 1.25], sometimes a special one.
fn float_value(next: &mut impl FnMut() -> u32) -> f32 {
    let v = next();
    match v % 16 {
        0 => f32::NAN,
        1 => -0.0,
        2 => 0.0,
        3 => 1.0,
        4 => 70000.0,
        5 => -3.0e-6,
        6 => f32::INFINITY,
        _ => (v >> 8) as f32 / (1u32 << 24) as f32 * 1.5 - 0.25,
    }
}

/// A random case of precision `kind`.
fn case(next: &mut impl FnMut() -> u32, kind: WideKind, fma: bool) -> Case {
    let dst = WideDst {
        kind,
        alpha: !next().is_multiple_of(4),
        single: next().is_multiple_of(4),
    };
    let plan = plan(next, fma);
    // The chunk starts at `idx` and the rows end after `n` of its pixels.
    let idx = (next() % 5) as usize;
    let n = 1 + (next() % LANES as u32) as usize;
    let len = idx + n;
    let mut wide = vec![[0f32; 4]; len];
    let mut color = vec![[0u8; 4]; len];
    for (w, c) in wide.iter_mut().zip(color.iter_mut()) {
        for v in w.iter_mut() {
            *v = match kind {
                WideKind::Unorm16 => (next() % 65536) as f32,
                WideKind::Float16 => f16_round(float_value(next)),
                WideKind::Float32 => float_value(next),
            };
        }
        *c = if next().is_multiple_of(6) {
            next().to_le_bytes()
        } else {
            kind.mirror(*w)
        };
    }
    let bits = next() & ((1 << n) - 1);
    let src = std::array::from_fn(|_| std::array::from_fn(|_| float_value(next)));
    Case {
        dst,
        plan,
        color,
        wide,
        idx,
        bits,
        src,
    }
}

/// [`store8`] in an AVX2 and FMA context.
///
/// # Safety
/// The CPU has AVX2 and FMA; as [`store8`].
#[target_feature(enable = "avx2,fma")]
unsafe fn run_fma(c: &mut Case) -> u64 {
    // SAFETY: forwarded from the caller.
    unsafe { run::<true>(c) }
}

/// [`store8`] in an AVX2 context without FMA.
///
/// # Safety
/// The CPU has AVX2; as [`store8`].
#[target_feature(enable = "avx2")]
unsafe fn run_avx2(c: &mut Case) -> u64 {
    // SAFETY: forwarded from the caller.
    unsafe { run::<false>(c) }
}

/// The 8-lane store of case `c`.
///
/// # Safety
/// AVX2 context (FMA when `FMA`); `covers` accepted the case.
#[inline(always)]
unsafe fn run<const FMA: bool>(c: &mut Case) -> u64 {
    // SAFETY: forwarded from the caller; the lanes of `bits` lie inside the rows.
    unsafe {
        let bits = I32x8::new([1, 2, 4, 8, 16, 32, 64, 128]);
        let pass = I32x8::splat(c.bits as i32).and(bits).cmpeq(bits);
        let s = c.src.map(|l| F32x8::new(l));
        store8::<FMA>(c.dst, &c.plan, &mut c.color, &mut c.wide, c.idx, pass, s)
    }
}

#[test]
fn store8_matches_the_per_pixel_store() {
    if !std::is_x86_feature_detected!("avx2") {
        return;
    }
    let fma = std::is_x86_feature_detected!("fma");
    let mut next = xorshift32(0x5749_4445);
    let mut covered = 0;
    for round in 0..60_000 {
        let kind = [WideKind::Unorm16, WideKind::Float16, WideKind::Float32][round % 3];
        let fused = fma && round % 2 == 0;
        let mut fast = case(&mut next, kind, fused);
        if !covers(fast.dst, &fast.plan, fused) {
            continue;
        }
        covered += 1;
        let (mut color, mut wide) = (fast.color.clone(), fast.wide.clone());
        let n = color.len() - fast.idx;
        let live: [bool; LANES] = std::array::from_fn(|i| fast.bits & (1 << i) != 0);
        let want = {
            let mut rows = PlaneRows {
                color: &mut color,
                wide_color: &mut wide,
                ..PlaneRows::default()
            };
            let plan = &fast.plan;
            softgl::fragment::wide::store(fast.dst, plan, &mut rows, fast.idx, n, &live, &fast.src)
        };
        // SAFETY: AVX2 checked above, FMA when `fused`; `covers` accepted the case.
        let got = unsafe {
            if fused {
                run_fma(&mut fast)
            } else {
                run_avx2(&mut fast)
            }
        };
        assert_eq!(got, want, "round {round}");
        assert_eq!(fast.color, color, "8-bit mirror, round {round}");
        // Bit for bit, but every NaN alike: which operand's NaN an operation passes on
        // (and so its sign) is not fixed by the compiler for the per-pixel store either
        // (LLVM may swap the operands of an add or multiply).
        let bits = |v: &[[f32; 4]]| -> Vec<[u32; 4]> {
            v.iter()
                .map(|p| p.map(|c| if c.is_nan() { u32::MAX } else { c.to_bits() }))
                .collect()
        };
        assert_eq!(
            bits(&fast.wide),
            bits(&wide),
            "wide plane, round {round}: {:?}",
            fast.plan.blend
        );
    }
    assert!(covered > 50_000, "{covered}");
}
