//! The texture fast path: one 2D unit on llvmpipe's 8-bit AoS path (REPEAT or
//! CLAMP_TO_EDGE, no anisotropy) with REPLACE, MODULATE or DECAL (in Mesa's combiner form),
//! decided once per draw ([`FastEnv::classify`], stored in [`super::UnitPlan::fast`]).
//!
//! It computes exactly what the general path computes ([`super::UnitPlan::sample_quad`]
//! followed by [`super::env::Combine::apply`] and the unorm8 conversion), but:
//! - texels stay 8-bit until the environment: four channels are filtered at once in one
//!   `u64` of 16-bit fields (`lerp8` written as `(a·(256 − w) + b·w + 128) >> 8`, which is
//!   `a + ((w·(b − a) + 128) >> 8)` with the `a·256` moved inside the floor);
//! - the environment is specialised per channel group ([`EnvOp`]), and a texture value
//!   that reaches the colour unchanged is written as its byte (`unorm8(u·f32(1/255)) = u`
//!   for every byte, checked by a test), so REPLACE never touches floats;
//! - the level of detail is only computed when the filters need it (`needs_lod`).
//!
//! `SOFTGL_TEX_PATH=general` turns the fast path off (to compare the two paths),
//! `SOFTGL_TEX_PATH=array` keeps it but without the register walk.

use super::env::{Arg, Combine, CombineFn, Operand, Source};
use super::sample::select_levels;
use super::sample::INV_255;
use super::{fast_avx2, wrap, Filter, Level, UnitPlan};
use crate::fragment::blend::Lanes;
use crate::fragment::span::{unorm8, LANES};

/// How one channel group (RGB or alpha) of the environment's result is formed; `t` is the
/// texture value, `f` the fragment's primary colour (the previous unit's result, since the
/// fast path has one unit).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EnvOp {
    /// `t` (REPLACE with the texture).
    Tex,
    /// `f` (REPLACE with the fragment colour).
    Frag,
    /// `t·f` (MODULATE).
    Modulate,
    /// `t·t_alpha + f·(1 − t_alpha)` (DECAL on RGBA; RGB only).
    Decal,
}

/// The environment of a fast-path unit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FastEnv {
    /// RGB.
    pub rgb: EnvOp,
    /// Alpha.
    pub alpha: EnvOp,
}

/// Whether the fast path may be used (`SOFTGL_TEX_PATH=general` turns it off).
pub fn enabled() -> bool {
    crate::tuning::tuning().tex_path != crate::tuning::TexPath::General
}

/// Whether the texture fast path keeps a chunk in registers (`raster::textured::vec8`);
/// `SOFTGL_TEX_PATH=array` keeps the array walk (to compare the two).
pub fn vec8_enabled() -> bool {
    crate::tuning::tuning().tex_path != crate::tuning::TexPath::Array
}

impl FastEnv {
    /// The fast form of a unit's derived combiner, when it has one. `alpha` selects the
    /// operand that reads a value's own channel (SRC_ALPHA for the alpha group).
    pub fn classify(c: &Combine) -> Option<FastEnv> {
        if c.scale_rgb != 1.0 || c.scale_a != 1.0 {
            return None;
        }
        let own = |a: Arg, alpha: bool| -> Option<bool> {
            let op_ok = if alpha {
                a.1 == Operand::SrcAlpha
            } else {
                a.1 == Operand::SrcColor
            };
            if !op_ok {
                return None;
            }
            match a.0 {
                Source::Texture => Some(true),
                Source::PrimaryColor | Source::Previous => Some(false),
                _ => None,
            }
        };
        let group = |f: CombineFn, args: &[Arg; 3], alpha: bool| -> Option<EnvOp> {
            match f {
                CombineFn::Replace => Some(if own(args[0], alpha)? {
                    EnvOp::Tex
                } else {
                    EnvOp::Frag
                }),
                CombineFn::Modulate => {
                    let (a, b) = (own(args[0], alpha)?, own(args[1], alpha)?);
                    (a != b).then_some(EnvOp::Modulate)
                }
                CombineFn::Interpolate if !alpha => {
                    let decal = own(args[0], false)?
                        && !own(args[1], false)?
                        && args[2] == (Source::Texture, Operand::SrcAlpha);
                    decal.then_some(EnvOp::Decal)
                }
                _ => None,
            }
        };
        Some(FastEnv {
            rgb: group(c.mode_rgb, &c.args_rgb, false)?,
            alpha: group(c.mode_a, &c.args_a, true)?,
        })
    }

    /// Whether the fragment's colour is read at all.
    pub fn reads_frag(&self) -> bool {
        self.rgb != EnvOp::Tex || self.alpha != EnvOp::Tex
    }
}

/// RGBA8 spread into four 16-bit fields of a `u64`.
#[inline(always)]
fn spread(v: [u8; 4]) -> u64 {
    let x = u32::from_le_bytes(v) as u64;
    let x = (x | (x << 16)) & 0x0000_ffff_0000_ffff;
    (x | (x << 8)) & 0x00ff_00ff_00ff_00ff
}

/// The inverse of [`spread`] (every field below 256).
#[inline(always)]
fn pack(x: u64) -> [u8; 4] {
    let x = (x | (x >> 8)) & 0x0000_ffff_0000_ffff;
    ((x | (x >> 16)) as u32).to_le_bytes()
}

/// llvmpipe's 8-bit lerp ([`super::sample::lerp8`]) on four spread channels, `w` in 0..=255.
/// No field can carry: `a·(256 − w) + b·w + 128 ≤ 255·256 + 128 < 2^16`.
#[inline(always)]
fn lerp4(a: u64, b: u64, w: u64) -> u64 {
    ((a * (256 - w) + b * w + 0x0080_0080_0080_0080) >> 8) & 0x00ff_00ff_00ff_00ff
}

/// One level, NEAREST or LINEAR, as spread channels (the AoS filter of `sample.rs`).
#[inline(always)]
fn filter(p: &UnitPlan<'_>, img: &Level, linear: bool, s: f32, t: f32) -> u64 {
    let (w, h) = (img.width, img.height);
    let tx = &img.texels[..w * h];
    if linear {
        let (x0, x1, wx) = wrap::aos_linear(s, w, p.pot[0], p.wrap_s);
        let (y0, y1, wy) = wrap::aos_linear(t, h, p.pot[1], p.wrap_t);
        let (r0, r1) = (y0 * w, y1 * w);
        let (wx, wy) = (wx as u64, wy as u64);
        let a = lerp4(spread(tx[r0 + x0]), spread(tx[r0 + x1]), wx);
        let b = lerp4(spread(tx[r1 + x0]), spread(tx[r1 + x1]), wx);
        lerp4(a, b, wy)
    } else {
        let x = wrap::aos_nearest(s, w, p.pot[0], p.wrap_s);
        let y = wrap::aos_nearest(t, h, p.pot[1], p.wrap_t);
        spread(tx[y * w + x])
    }
}

/// The 8-bit texture values of a 2x2 quad (TL, TR, BL, BR, y-down) with one LOD from
/// TL/TR/BL: bit for bit the bytes behind [`UnitPlan::sample_quad`] on the AoS path.
#[inline(always)]
pub fn quad_u8(p: &UnitPlan<'_>, s: [f32; 4], t: [f32; 4]) -> [[u8; 4]; 4] {
    quad_u8_levels(p, select_levels(p, p.quad_lod(s, t)), s, t)
}

/// [`quad_u8`] with the levels [`select_levels`] chose.
#[inline(always)]
#[allow(clippy::needless_range_loop)]
fn quad_u8_levels(
    p: &UnitPlan<'_>,
    (f, l0, l1, frac): (Filter, usize, usize, f32),
    s: [f32; 4],
    t: [f32; 4],
) -> [[u8; 4]; 4] {
    let linear = f == Filter::Linear;
    let a = p.image(l0);
    // Plain loops: `array::from_fn` closures are not inlined into the AVX2 callers.
    let mut out = [[0u8; 4]; 4];
    if l1 == l0 {
        for i in 0..4 {
            out[i] = pack(filter(p, a, linear, s[i], t[i]));
        }
        return out;
    }
    let b = p.image(l1);
    let w = (frac * 256.0) as u64;
    for i in 0..4 {
        let (va, vb) = (
            filter(p, a, linear, s[i], t[i]),
            filter(p, b, linear, s[i], t[i]),
        );
        out[i] = pack(lerp4(va, vb, w));
    }
    out
}

/// The 8-bit texture values of a chunk: two rows (`s[r]`, `t[r]`) of [`LANES`] pixels,
/// [`LANES`]` / 2` quads, each with its own LOD; only quads with a `live` pixel are
/// sampled (the other lanes of `out` keep their values). With `VECTOR` (the caller is
/// compiled for AVX2; a constant, so other callers contain no AVX2 code), `vector` (the
/// CPU has AVX2, [`fast_avx2::available`]) and one filter and pair of levels for every
/// live quad, each row is sampled 8 pixels at once by [`fast_avx2::RowSampler`]; the
/// scalar code ([`quad_u8`]) gives the same bytes and serves every other case.
#[inline(always)]
#[allow(clippy::needless_range_loop)]
pub fn chunk_u8<const VECTOR: bool>(
    p: &UnitPlan<'_>,
    s: &[[f32; LANES]; 2],
    t: &[[f32; LANES]; 2],
    live: &[[bool; LANES]; 2],
    vector: bool,
    out: &mut [[[u8; 4]; LANES]; 2],
) {
    const QUADS: usize = LANES / 2;
    // Without a LOD every quad magnifies the base level: choose once, and skip the
    // per-quad bookkeeping (lanes of quads without a live pixel are sampled but unused).
    if !p.needs_lod {
        let lv = select_levels(p, super::Lod::MAG);
        let wmip = [(lv.3 * 256.0) as i32; LANES];
        if VECTOR && vector && vector_rows(p, lv.0, lv.1, lv.2, &wmip, s, t, live, out) {
            return;
        }
        for j in 0..QUADS {
            let (l, r) = (2 * j, 2 * j + 1);
            if live[0][l] || live[0][r] || live[1][l] || live[1][r] {
                quad_into(p, lv, s, t, j, out);
            }
        }
        return;
    }
    let mut sel = [None; QUADS];
    let mut key = None;
    let mut uniform = true;
    for j in 0..QUADS {
        let (l, r) = (2 * j, 2 * j + 1);
        if !(live[0][l] || live[0][r] || live[1][l] || live[1][r]) {
            continue;
        }
        let lv = select_levels(
            p,
            p.quad_lod(
                [s[0][l], s[0][r], s[1][l], s[1][r]],
                [t[0][l], t[0][r], t[1][l], t[1][r]],
            ),
        );
        sel[j] = Some(lv);
        match key {
            None => key = Some((lv.0, lv.1, lv.2)),
            Some(k) => uniform &= k == (lv.0, lv.1, lv.2),
        }
    }
    if let (true, true, true, Some((f, l0, l1))) = (VECTOR, vector, uniform, key) {
        let mut wmip = [0i32; LANES];
        for (j, lv) in sel.iter().enumerate() {
            if let Some(lv) = lv {
                let w = (lv.3 * 256.0) as i32;
                wmip[2 * j] = w;
                wmip[2 * j + 1] = w;
            }
        }
        if vector_rows(p, f, l0, l1, &wmip, s, t, live, out) {
            return;
        }
    }
    for j in 0..QUADS {
        if let Some(lv) = sel[j] {
            quad_into(p, lv, s, t, j, out);
        }
    }
}

/// Samples quad `j` of a chunk (columns `2j` and `2j + 1` of both rows) from levels `lv`
/// by [`quad_u8_levels`] into `out`.
#[inline(always)]
fn quad_into(
    p: &UnitPlan<'_>,
    lv: (Filter, usize, usize, f32),
    s: &[[f32; LANES]; 2],
    t: &[[f32; LANES]; 2],
    j: usize,
    out: &mut [[[u8; 4]; LANES]; 2],
) {
    let (l, r) = (2 * j, 2 * j + 1);
    let v = quad_u8_levels(
        p,
        lv,
        [s[0][l], s[0][r], s[1][l], s[1][r]],
        [t[0][l], t[0][r], t[1][l], t[1][r]],
    );
    out[0][l] = v[0];
    out[0][r] = v[1];
    out[1][l] = v[2];
    out[1][r] = v[3];
}

/// The vector half of [`chunk_u8`]: `false` when the rows must be sampled by the scalar
/// code (a wrap mode or size it does not handle, or a coordinate out of its range).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn vector_rows(
    p: &UnitPlan<'_>,
    f: Filter,
    l0: usize,
    l1: usize,
    wmip: &[i32; LANES],
    s: &[[f32; LANES]; 2],
    t: &[[f32; LANES]; 2],
    live: &[[bool; LANES]; 2],
    out: &mut [[[u8; 4]; LANES]; 2],
) -> bool {
    let a = p.image(l0);
    let b = (l1 != l0).then(|| p.image(l1));
    let fits = |img: &Level| {
        fast_avx2::handles(p.wrap_s, p.pot[0], img.width)
            && fast_avx2::handles(p.wrap_t, p.pot[1], img.height)
    };
    if !fits(a) || !b.is_none_or(fits) {
        return false;
    }
    let rs = fast_avx2::RowSampler {
        a,
        b,
        linear: f == Filter::Linear,
        wrap: [
            fast_avx2::AxisWrap::of(p.wrap_s, p.pot[0]),
            fast_avx2::AxisWrap::of(p.wrap_t, p.pot[1]),
        ],
    };
    // A row that declines leaves `out` to the scalar code, which rewrites every live lane.
    for r in 0..2 {
        // SAFETY: `vector` is only set when `fast_avx2::available()`, and this inlines
        // into the AVX2 raster entry points.
        if live[r].iter().any(|&l| l) && !unsafe { rs.row(&s[r], &t[r], wmip, &mut out[r]) } {
            return false;
        }
    }
    true
}

/// The environment of [`LANES`] pixels: `tex` their 8-bit texture values, `frag` their
/// primary colour (read only when [`FastEnv::reads_frag`]); returns the 8-bit colours,
/// each channel exactly `unorm8` of what [`super::env::Combine::apply`] gives.
#[inline(always)]
pub fn env_lanes(e: FastEnv, tex: &[[u8; 4]; LANES], frag: &[[f32; LANES]; 4]) -> Lanes {
    let mut out = [[0u8; LANES]; 4];
    let tf = |i: usize, ch: usize| tex[i][ch] as f32 * INV_255;
    for ch in 0..4 {
        let op = if ch == 3 { e.alpha } else { e.rgb };
        for i in 0..LANES {
            out[ch][i] = match op {
                EnvOp::Tex => tex[i][ch],
                EnvOp::Frag => unorm8(frag[ch][i]),
                EnvOp::Modulate => unorm8(tf(i, ch) * frag[ch][i]),
                EnvOp::Decal => {
                    let a = tf(i, 3);
                    unorm8(tf(i, ch) * a + frag[ch][i] * (1.0 - a))
                }
            };
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::super::env::{EnvMode, TexEnv};
    use super::super::sample::lerp8;
    use super::super::{BaseFormat, LodParams, MipFilter, SamplerParams, Wrap};
    use super::*;

    #[test]
    fn byte_survives_float_round_trip() {
        for u in 0..=255u8 {
            assert_eq!(unorm8(u as f32 * INV_255), u);
        }
    }

    #[test]
    fn lerp4_is_lerp8_per_channel() {
        for a in (0..=255u8).step_by(3) {
            for b in (0..=255u8).step_by(5) {
                for w in 0..=255u64 {
                    let r = pack(lerp4(spread([a, b, 255 - a, 7]), spread([b, a, 9, 255]), w));
                    let e = [
                        lerp8(a, b, w as i32),
                        lerp8(b, a, w as i32),
                        lerp8(255 - a, 9, w as i32),
                        lerp8(7, 255, w as i32),
                    ];
                    assert_eq!(r, e, "a {a} b {b} w {w}");
                }
            }
        }
    }

    #[test]
    fn legacy_modes_classify() {
        use EnvOp::*;
        let cases = [
            (EnvMode::Replace, BaseFormat::Rgba, Some((Tex, Tex))),
            (EnvMode::Replace, BaseFormat::Rgb, Some((Tex, Frag))),
            (EnvMode::Replace, BaseFormat::Alpha, Some((Frag, Tex))),
            (
                EnvMode::Modulate,
                BaseFormat::Rgba,
                Some((Modulate, Modulate)),
            ),
            (
                EnvMode::Modulate,
                BaseFormat::Luminance,
                Some((Modulate, Frag)),
            ),
            (EnvMode::Decal, BaseFormat::Rgba, Some((Decal, Frag))),
            (EnvMode::Decal, BaseFormat::Rgb, Some((Tex, Frag))),
            (EnvMode::Blend, BaseFormat::Rgba, None),
            (EnvMode::Add, BaseFormat::Rgba, None),
        ];
        for (mode, base, want) in cases {
            let env = TexEnv {
                mode,
                ..Default::default()
            };
            let mut c = Combine::derive(&env, base);
            c.canonicalise(0, true, |_| None);
            let got = FastEnv::classify(&c).map(|e| (e.rgb, e.alpha));
            assert_eq!(got, want, "{mode:?} {base:?}");
        }
    }

    /// Random chunks through [`chunk_u8`] (8-wide when the CPU has AVX2, and the scalar
    /// code) and the register sampler (`fast_avx2::chunk`) against [`quad_u8`] per quad: the same bytes in every live lane. Coordinates
    /// range from small steps (one level for the whole chunk) to huge and NaN values (the
    /// vector sampler declines).
    fn chunks_match_quads(p: &UnitPlan<'_>, rnd: &mut dyn FnMut() -> u32) {
        let mut chunks = Vec::new();
        for n in 0..200 {
            let f = |r: u32| (r % 20000) as f32 / 4000.0 - 2.0;
            let (s0, t0) = (f(rnd()), f(rnd()));
            let scale = [0.001f32, 0.01, 0.1, 1.0][n % 4] * (rnd() % 1000) as f32 / 1000.0;
            let (a, b, c, d) = (
                scale * f(rnd()),
                scale * f(rnd()),
                scale * f(rnd()),
                scale * f(rnd()),
            );
            let mut s = [[0f32; LANES]; 2];
            let mut t = [[0f32; LANES]; 2];
            let mut live = [[false; LANES]; 2];
            for r in 0..2 {
                for i in 0..LANES {
                    s[r][i] = s0 + a * i as f32 + b * r as f32;
                    t[r][i] = t0 + c * i as f32 + d * r as f32;
                    live[r][i] = !rnd().is_multiple_of(5);
                }
            }
            if n % 50 == 7 {
                s[0][3] = [f32::NAN, 3.0e9, -1.0e12, 4.2e6][n / 50];
            }
            chunks.push((s, t, live));
            // The same levels again, shifted by a texel: the register walk reuses the
            // sampler of the chunk before.
            if n % 3 == 0 {
                let mut s2 = s;
                for v in s2.iter_mut().flatten() {
                    *v += 1.0 / 16.0;
                }
                chunks.push((s2, t, live));
            }
        }
        // The register sampler (`fast_avx2::chunk`) sees the chunks in turn, as the walk
        // does.
        #[cfg(target_arch = "x86_64")]
        let regs = super::fast_avx2::available().then(|| {
            // SAFETY: the CPU has AVX2.
            unsafe { super::fast_avx2::chunk::texels_seq(p, &chunks) }
        });
        for (n, (s, t, live)) in chunks.iter().enumerate() {
            let mut outs = Vec::new();
            for vector in [false, super::fast_avx2::available()] {
                let mut out = [[[0u8; 4]; LANES]; 2];
                chunk_u8::<true>(p, s, t, live, vector, &mut out);
                outs.push((if vector { "vector" } else { "scalar" }, out));
            }
            #[cfg(target_arch = "x86_64")]
            if let Some(regs) = &regs {
                outs.push(("registers", regs[n]));
            }
            for (path, out) in outs {
                for j in 0..LANES / 2 {
                    let (l, r) = (2 * j, 2 * j + 1);
                    if !(live[0][l] || live[0][r] || live[1][l] || live[1][r]) {
                        continue;
                    }
                    let q = quad_u8(
                        p,
                        [s[0][l], s[0][r], s[1][l], s[1][r]],
                        [t[0][l], t[0][r], t[1][l], t[1][r]],
                    );
                    let got = [out[0][l], out[0][r], out[1][l], out[1][r]];
                    for k in 0..4 {
                        let lane_live = [live[0][l], live[0][r], live[1][l], live[1][r]][k];
                        if lane_live {
                            assert_eq!(got[k], q[k], "{path} chunk {n} quad {j} px {k}");
                        }
                    }
                }
            }
        }
    }

    /// Random quads through both paths, for every AoS configuration.
    #[test]
    fn quads_match_general_sampler() {
        let mut rnd = crate::test_rng::xorshift32(0x1234_5678);
        let mk = |w: usize, h: usize, rnd: &mut dyn FnMut() -> u32| -> Option<Level> {
            let texels = (0..w * h).map(|_| rnd().to_le_bytes()).collect();
            Some(crate::texture::tests::rgba_level(w, h, texels))
        };
        for (w0, h0) in [(16usize, 8usize), (12, 5)] {
            let mut levels = Vec::new();
            let (mut w, mut h) = (w0, h0);
            loop {
                levels.push(mk(w, h, &mut rnd));
                if w == 1 && h == 1 {
                    break;
                }
                w = (w / 2).max(1);
                h = (h / 2).max(1);
            }
            let last = levels.len() - 1;
            for mip in [MipFilter::None, MipFilter::Nearest, MipFilter::Linear] {
                for (min, mag) in [
                    (Filter::Nearest, Filter::Nearest),
                    (Filter::Linear, Filter::Linear),
                    (Filter::Linear, Filter::Nearest),
                    (Filter::Nearest, Filter::Linear),
                ] {
                    for wrap in [Wrap::Repeat, Wrap::ClampToEdge] {
                        // Bias and LOD clamps: none (NEAREST mip filtering takes the LOD
                        // from rho's exponent), a bias, each clamp alone, and a min_lod
                        // beyond i32 (the float → int conversions saturate in the scalar
                        // code, not in the vector one).
                        for (bias, min_lod, max_lod) in [
                            (0.0f32, -1000.0f32, 1000.0f32),
                            (0.75, -1000.0, 1000.0),
                            (0.0, 0.6, 1000.0),
                            (-0.25, -1000.0, 1.4),
                            (0.0, 1.0e30, 2.0e30),
                        ] {
                            let sp = SamplerParams {
                                min_filter: min,
                                mag_filter: mag,
                                mip_filter: mip,
                                lod_bias: bias,
                                min_lod,
                                max_lod,
                                ..Default::default()
                            };
                            let p = UnitPlan {
                                levels: &levels,
                                first: 0,
                                last: if mip == MipFilter::None { 0 } else { last },
                                dims: 2,
                                min_filter: min,
                                mag_filter: mag,
                                mip_filter: mip,
                                wrap_s: wrap,
                                wrap_t: wrap,
                                border: [0.0; 4],
                                aos: true,
                                pot: [w0.is_power_of_two(), h0.is_power_of_two()],
                                max_anisotropy: 1.0,
                                lod: LodParams::new(&sp, 0.0, false),
                                needs_lod: !(min == mag && mip == MipFilter::None),
                                base_format: BaseFormat::Rgba,
                                env: Combine::derive(&Default::default(), BaseFormat::Rgba),
                                fast: None,
                                fma: false,
                                ext: Default::default(),
                            };
                            for _ in 0..300 {
                                let f = |r: u32| (r % 20000) as f32 / 4000.0 - 2.0;
                                let (s0, t0) = (f(rnd()), f(rnd()));
                                let scale = (rnd() % 4000) as f32 / 1000.0 / 8.0;
                                let (dx, dy) = (scale * f(rnd()), scale * f(rnd()));
                                let s = [s0, s0 + dx, s0 + dy * 0.3, s0 + dx + dy * 0.3];
                                let t = [t0, t0 + dy * 0.2, t0 + dy, t0 + dx * 0.2 + dy];
                                let fast = quad_u8(&p, s, t);
                                let general = p.sample_quad(s, t);
                                for i in 0..4 {
                                    let b = fast[i].map(|u| u as f32 * INV_255);
                                    assert_eq!(b, general[i], "{mip:?} {min:?} {mag:?} {wrap:?}");
                                }
                            }
                            chunks_match_quads(&p, &mut rnd);
                        }
                    }
                }
            }
        }
    }
}
