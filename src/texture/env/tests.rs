//! Unit tests of the texture environment ([`super::Combine`]).

use super::super::BaseFormat as B;
use super::*;

fn run(mode: EnvMode, base: B, f: [f32; 4], t: [f32; 4]) -> [f32; 4] {
    let env = TexEnv {
        mode,
        color: [0.25, 0.5, 0.75, 0.125],
        ..Default::default()
    };
    let t = base.swizzle(t, 0.0, 1.0);
    Combine::derive(&env, base).apply(f, t, f, &[])
}

/// A random texture environment derived for a random base format: every legacy mode, every
/// combiner function, source (the crossbar's `TextureN` included), operand and scale; the
/// generator of the combiner tests here, in `vec8` and in the engine's lowering test.
pub(crate) fn random_combine(pick: &mut dyn FnMut(u32) -> usize) -> Combine {
    use CombineFn as F;
    let fns = [
        F::Replace,
        F::Modulate,
        F::Add,
        F::AddSigned,
        F::Interpolate,
        F::Subtract,
        F::Dot3Rgb,
        F::Dot3Rgba,
    ];
    let ops = [
        Operand::SrcColor,
        Operand::OneMinusSrcColor,
        Operand::SrcAlpha,
        Operand::OneMinusSrcAlpha,
    ];
    let modes = [
        EnvMode::Replace,
        EnvMode::Modulate,
        EnvMode::Decal,
        EnvMode::Blend,
        EnvMode::Add,
        EnvMode::Combine,
    ];
    let bases = [
        B::Alpha,
        B::Luminance,
        B::LuminanceAlpha,
        B::Intensity,
        B::Rgb,
        B::Rgba,
    ];
    let src = |pick: &mut dyn FnMut(u32) -> usize| match pick(6) {
        0 => Source::Texture,
        1 => Source::TextureN(pick(3) as u8),
        2 => Source::Constant,
        3 => Source::PrimaryColor,
        _ => Source::Previous,
    };
    let scales = [1.0, 2.0, 4.0];
    let env = TexEnv {
        mode: modes[pick(6)],
        combine_rgb: fns[pick(8)],
        combine_alpha: fns[pick(6)],
        source_rgb: [src(pick), src(pick), src(pick)],
        source_alpha: [src(pick), src(pick), src(pick)],
        operand_rgb: [ops[pick(4)], ops[pick(4)], ops[pick(4)]],
        operand_alpha: [ops[2 + pick(2)], ops[2 + pick(2)], ops[2 + pick(2)]],
        rgb_scale: scales[pick(3)],
        alpha_scale: scales[pick(3)],
        color: [0.25, 0.5, 0.75, 0.125],
    };
    Combine::derive(&env, bases[pick(6)])
}

const F: [f32; 4] = [0.2, 0.4, 0.6, 0.8];
const T: [f32; 4] = [0.9, 0.5, 0.1, 0.3];

#[test]
fn gl_table_replace_modulate() {
    assert_eq!(run(EnvMode::Replace, B::Alpha, F, T), [0.2, 0.4, 0.6, 0.3]);
    assert_eq!(
        run(EnvMode::Replace, B::Luminance, F, T),
        [0.9, 0.9, 0.9, 0.8]
    );
    assert_eq!(run(EnvMode::Replace, B::Intensity, F, T), [0.9; 4]);
    assert_eq!(run(EnvMode::Replace, B::Rgb, F, T), [0.9, 0.5, 0.1, 0.8]);
    assert_eq!(
        run(EnvMode::Modulate, B::Rgba, F, T),
        [0.9 * 0.2, 0.5 * 0.4, 0.1 * 0.6, 0.3 * 0.8]
    );
    assert_eq!(
        run(EnvMode::Modulate, B::Luminance, F, T),
        [0.9 * 0.2, 0.9 * 0.4, 0.9 * 0.6, 0.8]
    );
    assert_eq!(
        run(EnvMode::Modulate, B::Alpha, F, T),
        [0.2, 0.4, 0.6, 0.3 * 0.8]
    );
}

#[test]
fn decal_blend_add() {
    // DECAL RGBA: Ct·At + Cf·(1 − At)
    let d = run(EnvMode::Decal, B::Rgba, F, T);
    assert_eq!(d[0], 0.9f32 * 0.3 + 0.2 * (1.0 - 0.3));
    assert_eq!(d[3], 0.8);
    assert_eq!(run(EnvMode::Decal, B::Luminance, F, T), F);
    assert_eq!(run(EnvMode::Decal, B::Rgb, F, T), [0.9, 0.5, 0.1, 0.8]);
    // BLEND RGB: Cc·Ct + Cf·(1 − Ct); A = Af
    let b = run(EnvMode::Blend, B::Rgb, F, T);
    assert_eq!(b[0], 0.25f32 * 0.9 + 0.2 * (1.0 - 0.9));
    assert_eq!(b[3], 0.8);
    // BLEND INTENSITY alpha: Ac·It + Af·(1 − It)
    let bi = run(EnvMode::Blend, B::Intensity, F, T);
    assert_eq!(bi[3], 0.125f32 * 0.9 + 0.8 * (1.0 - 0.9));
    assert_eq!(
        run(EnvMode::Blend, B::Alpha, F, T),
        [0.2, 0.4, 0.6, 0.3 * 0.8]
    );
    // ADD saturates; INTENSITY adds alpha
    let a = run(EnvMode::Add, B::Rgba, F, T);
    assert_eq!(a, [1.0, 0.5f32 + 0.4, 0.1f32 + 0.6, 0.3f32 * 0.8]);
    assert_eq!(run(EnvMode::Add, B::Intensity, F, T)[3], 1.0);
    assert_eq!(run(EnvMode::Add, B::Luminance, F, T)[3], 0.8);
}

#[test]
fn combine_functions_and_scale() {
    let mut env = TexEnv {
        mode: EnvMode::Combine,
        combine_rgb: CombineFn::Subtract,
        combine_alpha: CombineFn::AddSigned,
        rgb_scale: 2.0,
        ..Default::default()
    };
    let c = Combine::derive(&env, B::Rgba).apply(F, T, F, &[]);
    assert_eq!(c[0], sat((0.9f32 - 0.2) * 2.0));
    assert_eq!(c[2], 0.0);
    assert_eq!(c[3], sat((0.3f32 + -0.5) + 0.8));
    env.combine_rgb = CombineFn::Dot3Rgba;
    env.rgb_scale = 1.0;
    let c = Combine::derive(&env, B::Rgba).apply(F, T, F, &[]);
    let t0 = [0.9f32, 0.5, 0.1].map(|v| v * 2.0 - 1.0);
    let t1 = [0.2f32, 0.4, 0.6].map(|v| v * 2.0 - 1.0);
    let d = sat(t0[0] * t1[0] + t0[1] * t1[1] + t0[2] * t1[2]);
    assert_eq!(c, [d; 4]);
    // crossbar source
    env.combine_rgb = CombineFn::Replace;
    env.source_rgb[0] = Source::TextureN(1);
    let c = Combine::derive(&env, B::Rgba).apply(F, T, F, &[[0.0; 4], [0.7; 4]]);
    assert_eq!(c[0], 0.7);
}

fn add_signed_alpha(op0: Operand, op1: Operand, a: f32, rgb_scale: f32) -> f32 {
    let env = TexEnv {
        mode: EnvMode::Combine,
        combine_rgb: CombineFn::Replace,
        combine_alpha: CombineFn::AddSigned,
        source_alpha: [Source::PrimaryColor; 3],
        operand_alpha: [op0, op1, Operand::SrcAlpha],
        rgb_scale,
        ..Default::default()
    };
    let f = [0.2, 0.4, 0.6, a];
    Combine::derive(&env, B::Rgba).apply(f, T, f, &[])[3]
}

#[test]
fn add_signed_reassociated_like_nir() {
    use Operand::*;
    // llvmpipe (c_tests/repro/combine_add_signed.c): (a, 1 − a) gives 127 for odd k
    // in 65..127, (1 − a, a) gives 128 everywhere.
    for k in 0..=255u32 {
        let a = k as f32 / 255.0;
        let q = |v: f32| (v * 255.0).round_ties_even() as u32;
        let row0 = q(add_signed_alpha(SrcAlpha, OneMinusSrcAlpha, a, 1.0));
        let row1 = q(add_signed_alpha(OneMinusSrcAlpha, SrcAlpha, a, 1.0));
        let expect0 = if (65..=127).contains(&k) && k % 2 == 1 {
            127
        } else {
            128
        };
        assert_eq!((k, row0, row1), (k, expect0, 128));
    }
    // (a + −0.5) + (1 − a) against the plain (a + (1 − a)) + −0.5
    let a = 65.0f32 / 255.0;
    assert_eq!(
        add_signed_alpha(SrcAlpha, OneMinusSrcAlpha, a, 1.0),
        (a + -0.5) + (1.0 - a)
    );
}

#[test]
fn add_signed_shared_with_alpha_is_not_reassociated() {
    let pr = (Source::PrimaryColor, Operand::SrcAlpha);
    let tx = (Source::Texture, Operand::OneMinusSrcAlpha);
    let mut c = Combine::derive(
        &TexEnv {
            mode: EnvMode::Combine,
            combine_rgb: CombineFn::AddSigned,
            combine_alpha: CombineFn::AddSigned,
            ..Default::default()
        },
        B::Rgba,
    );
    c.args_rgb = [pr, tx, pr];
    c.args_a = [tx, pr, pr];
    c.one_vec4 = false;
    // no scale: both sides saturate the one merged value → reassociated
    assert_eq!(c.add_signed_reassociates(), (true, true));
    // RGB ×2, alpha saturated: two users → left as (arg0 + arg1) − 0.5
    c.scale_rgb = 2.0;
    assert_eq!(c.add_signed_reassociates(), (false, false));
    // alpha ADD of the same two scalars shares the inner sum
    c.scale_rgb = 1.0;
    c.mode_a = CombineFn::Add;
    assert_eq!(c.add_signed_reassociates(), (false, false));
    // RGB colour operands: per-channel sums, always reassociated
    c.args_rgb[1].1 = Operand::OneMinusSrcColor;
    assert_eq!(c.add_signed_reassociates(), (true, true));
}

#[test]
fn interpolate_one_minus_arg2_folds() {
    let env = TexEnv {
        mode: EnvMode::Combine,
        combine_rgb: CombineFn::Interpolate,
        combine_alpha: CombineFn::Interpolate,
        source_rgb: [Source::Texture, Source::PrimaryColor, Source::Texture],
        operand_rgb: [
            Operand::SrcColor,
            Operand::SrcColor,
            Operand::OneMinusSrcAlpha,
        ],
        ..Default::default()
    };
    let c = Combine::derive(&env, B::Rgba).apply(F, T, F, &[]);
    // 1 − (1 − x) is x itself
    assert_eq!(c[0], 0.9f32 * (1.0 - 0.3) + 0.2 * 0.3);
}

/// Which derived combiners' alpha can read a texel: none of a texture without alpha
/// under the legacy modes, MODULATE and BLEND of an RGBA texture, a GL_COMBINE alpha
/// argument of GL_TEXTURE or GL_TEXTUREn, and DOT3_RGBA through its RGB arguments (its
/// alpha is the dot product) whatever its alpha arguments say.
#[test]
fn alpha_reads_texels_follows_the_alpha_arguments() {
    let legacy = |mode, base| {
        let env = TexEnv {
            mode,
            ..TexEnv::default()
        };
        Combine::derive(&env, base).alpha_reads_texels()
    };
    for mode in [
        EnvMode::Replace,
        EnvMode::Modulate,
        EnvMode::Decal,
        EnvMode::Blend,
        EnvMode::Add,
    ] {
        assert!(!legacy(mode, B::Rgb), "{mode:?} on RGB");
        assert!(!legacy(mode, B::Luminance), "{mode:?} on LUMINANCE");
        // DECAL keeps the fragment's alpha on every format
        assert_eq!(
            legacy(mode, B::Rgba),
            mode != EnvMode::Decal,
            "{mode:?} on RGBA"
        );
    }
    let combine = |rgb, a, src_rgb: [Source; 3], src_a: [Source; 3]| {
        let env = TexEnv {
            mode: EnvMode::Combine,
            combine_rgb: rgb,
            combine_alpha: a,
            source_rgb: src_rgb,
            source_alpha: src_a,
            ..TexEnv::default()
        };
        Combine::derive(&env, B::Rgba).alpha_reads_texels()
    };
    use Source::*;
    let (c, p, t) = (Constant, PrimaryColor, Texture);
    assert!(!combine(
        CombineFn::Modulate,
        CombineFn::Add,
        [t, t, t],
        [p, c, t]
    ));
    assert!(combine(
        CombineFn::Modulate,
        CombineFn::Interpolate,
        [p; 3],
        [p, c, t]
    ));
    assert!(combine(
        CombineFn::Replace,
        CombineFn::Replace,
        [p; 3],
        [TextureN(1), p, p]
    ));
    assert!(combine(
        CombineFn::Dot3Rgba,
        CombineFn::Replace,
        [p, t, p],
        [p; 3]
    ));
    assert!(!combine(
        CombineFn::Dot3Rgba,
        CombineFn::Replace,
        [p, c, t],
        [t; 3]
    ));
    assert!(!combine(
        CombineFn::Dot3Rgb,
        CombineFn::Add,
        [t; 3],
        [c, p, t]
    ));
}
