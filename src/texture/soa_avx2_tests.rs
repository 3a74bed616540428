//! [`Soa8`] against the scalar quad sampler (`UnitPlan::sample_quad`), bit for bit.

use super::*;
use crate::texture::upload::{quantise_rgba, to_texel};
use crate::texture::{
    BaseFormat, Encoding, MipFilter, Storage, Target, TextureObject, TextureState,
};

/// The formats under test: internal format, base, component sizes (R, G, B, A, L, I) and
/// encoding.
#[rustfmt::skip]
const FORMATS: [(u32, BaseFormat, [u8; 6], Encoding); 11] = [
    (0x8040, BaseFormat::Luminance, [0, 0, 0, 0, 8, 0], Encoding::Unorm), // LUMINANCE8
    (0x803C, BaseFormat::Alpha, [0, 0, 0, 8, 0, 0], Encoding::Unorm), // ALPHA8
    (0x804B, BaseFormat::Intensity, [0, 0, 0, 0, 0, 8], Encoding::Unorm), // INTENSITY8
    (0x8045, BaseFormat::LuminanceAlpha, [0, 0, 0, 8, 8, 0], Encoding::Unorm), // LA8
    (0x8051, BaseFormat::Rgb, [8, 8, 8, 0, 0, 0], Encoding::Unorm), // RGB8
    (0x8058, BaseFormat::Rgba, [8, 8, 8, 8, 0, 0], Encoding::Unorm), // RGBA8
    (0x8050, BaseFormat::Rgb, [5, 5, 5, 0, 0, 0], Encoding::Unorm), // RGB5
    (0x2A10, BaseFormat::Rgb, [3, 3, 2, 0, 0, 0], Encoding::Unorm), // R3_G3_B2
    (0x8056, BaseFormat::Rgba, [4, 4, 4, 4, 0, 0], Encoding::Unorm), // RGBA4
    (0x8057, BaseFormat::Rgba, [5, 5, 5, 1, 0, 0], Encoding::Unorm), // RGB5_A1
    (0x8C43, BaseFormat::Rgba, [8, 8, 8, 8, 0, 0], Encoding::Srgb), // SRGB8_ALPHA8
];

/// Base level sizes: powers of two and not.
const SIZES: [[usize; 2]; 8] = [
    [1, 1],
    [4, 4],
    [16, 8],
    [64, 64],
    [5, 3],
    [7, 13],
    [12, 20],
    [33, 2],
];

const WRAPS: [Wrap; 5] = [
    Wrap::Repeat,
    Wrap::Clamp,
    Wrap::ClampToEdge,
    Wrap::ClampToBorder,
    Wrap::MirroredRepeat,
];

/// A 2D texture of format `f` with a full chain of random levels from `w`x`h`, on unit
/// 0 of a new state.
fn state(f: usize, [w, h]: [usize; 2], next: &mut impl FnMut() -> u32) -> TextureState {
    let (internal, base, sizes, encoding) = FORMATS[f];
    let storage = Storage { sizes, encoding };
    let mut o = TextureObject::new(Some(Target::Tex2D));
    let (mut w, mut h) = (w, h);
    for level in o.levels.iter_mut() {
        let texels = (0..w * h)
            .map(|_| to_texel(base, quantise_rgba(next().to_le_bytes(), &storage)))
            .collect();
        let mut l = crate::texture::tests::rgba_level(w, h, texels);
        (l.internal_format, l.base, l.storage) = (internal, base, storage);
        *level = Some(l);
        if w == 1 && h == 1 {
            break;
        }
        (w, h) = ((w / 2).max(1), (h / 2).max(1));
    }
    let mut ts = TextureState::default();
    ts.defaults[Target::Tex2D.index()] = o;
    ts.units[0].enabled_2d = true;
    ts
}

/// A random value in [-1, 1].
fn unit(next: &mut impl FnMut() -> u32) -> f32 {
    (next() % 20001) as f32 / 10000.0 - 1.0
}

/// A quad's coordinates on an axis of `size` texels: a random point (sometimes on a
/// texel centre or edge, or far outside) and its neighbours a random footprint away;
/// sometimes one pixel's value is NaN, infinite, huge or a negative zero.
fn quad(next: &mut impl FnMut() -> u32, size: usize) -> [f32; 4] {
    let n = size as f32;
    let c = match next() % 8 {
        0 => (next() % (8 * size as u32)) as f32 / (2.0 * n) - 2.0,
        1 => unit(next) * 1000.0,
        _ => unit(next) * 3.0,
    };
    let step = (2.0f32).powi((next() % 12) as i32 - 4) / n;
    let d = [0.0, step * unit(next), step * unit(next), step * unit(next)];
    let mut q = d.map(|d| c + d);
    if next().is_multiple_of(10) {
        q[(next() % 4) as usize] = [
            f32::NAN,
            f32::INFINITY,
            -f32::INFINITY,
            3.0e30,
            -70000.0,
            65535.5,
            -0.0,
        ][(next() % 7) as usize];
    }
    q
}

/// Whether the vectors follow a coordinate (`BOUND`).
fn follows(c: f32) -> bool {
    c.abs() < BOUND
}

#[test]
#[allow(clippy::needless_range_loop)]
fn rows_match_the_quad_sampler() {
    if !crate::texture::fast_avx2::available() {
        return;
    }
    let has_fma = std::is_x86_feature_detected!("fma");
    let mut next = crate::test_rng::xorshift32(55);
    let (mut vector, mut scalar, mut plans) = (0, 0, 0);
    let filters = [Filter::Nearest, Filter::Linear];
    let mips = [MipFilter::None, MipFilter::Nearest, MipFilter::Linear];
    // (texture bias, unit bias, min LOD, max LOD)
    let lods = [
        (0.0, 0.0, -1000.0, 1000.0),
        (0.75, 0.0, -1000.0, 1000.0),
        (-1.5, 0.5, -1000.0, 1000.0),
        (0.0, 0.0, 1.25, 2.5),
        (0.3, 0.0, 0.5, 0.5),
        (0.0, -0.25, -1000.0, 0.0),
    ];
    for ws in WRAPS {
        for wt in WRAPS {
            for min in filters {
                for mag in filters {
                    for mip in mips {
                        let f = (next() % FORMATS.len() as u32) as usize;
                        let size = SIZES[(next() % SIZES.len() as u32) as usize];
                        let mut ts = state(f, size, &mut next);
                        let (bias, ubias, min_lod, max_lod) =
                            lods[(next() % lods.len() as u32) as usize];
                        let o = &mut ts.defaults[Target::Tex2D.index()];
                        o.params.wrap_s = ws;
                        o.params.wrap_t = wt;
                        o.params.min_filter = min;
                        o.params.mag_filter = mag;
                        o.params.mip_filter = mip;
                        o.params.lod_bias = bias;
                        o.params.min_lod = min_lod;
                        o.params.max_lod = max_lod;
                        o.params.border_color = [0; 4].map(|_| (next() % 256) as f32 / 255.0);
                        if next().is_multiple_of(4) {
                            o.params.base_level = 1;
                        }
                        ts.units[0].lod_bias = ubias;
                        let Some(plan) = ts.unit_plan(0) else {
                            continue;
                        };
                        for fma in [false, true] {
                            if fma && !has_fma {
                                continue;
                            }
                            let mut p = plan.clone();
                            p.fma = fma;
                            let Some(s8) = Soa8::of(&p) else {
                                assert!(p.aos, "{ws:?} {wt:?} {f}");
                                continue;
                            };
                            plans += 1;
                            let b = p.image(p.first);
                            for _ in 0..12 {
                                let (mut s, mut t) = ([[0.0f32; 8]; 2], [[0.0f32; 8]; 2]);
                                for j in 0..4 {
                                    let qs = quad(&mut next, b.width);
                                    let qt = quad(&mut next, b.height);
                                    for i in 0..4 {
                                        let (row, lane) = (i / 2, 2 * j + i % 2);
                                        (s[row][lane], t[row][lane]) = (qs[i], qt[i]);
                                    }
                                }
                                // one chunk in four has a row without a live pixel
                                let dead = next() % 8;
                                let live: [[bool; 8]; 2] = std::array::from_fn(|r| {
                                    std::array::from_fn(|_| {
                                        dead != r as u32 && !next().is_multiple_of(3)
                                    })
                                });
                                let mut out = [[[-1.0f32; 4]; 8]; 2];
                                let [o0, o1] = &mut out;
                                // SAFETY: the CPU has AVX2 (checked above), and FMA when
                                // the plan fuses (checked above).
                                let redo = unsafe { s8.rows(&s, &t, &live, [o0, o1]) };
                                for j in 0..4 {
                                    let (a, c) = (2 * j, 2 * j + 1);
                                    let q4 =
                                        |v: &[[f32; 8]; 2]| [v[0][a], v[0][c], v[1][a], v[1][c]];
                                    let (qs, qt) = (q4(&s), q4(&t));
                                    if !(live[0][a] || live[0][c] || live[1][a] || live[1][c]) {
                                        assert_eq!(redo >> j & 1, 0, "a dead quad redone");
                                        continue;
                                    }
                                    let ok = qs.iter().chain(&qt).all(|&c| follows(c));
                                    assert_eq!(redo >> j & 1 == 0, ok, "s {qs:?} t {qt:?}");
                                    if !ok {
                                        scalar += 1;
                                        continue;
                                    }
                                    vector += 1;
                                    let want = p.sample_quad(qs, qt);
                                    let got = [out[0][a], out[0][c], out[1][a], out[1][c]];
                                    for i in 0..4 {
                                        // a row without a live pixel is not sampled
                                        if !live[i / 2].iter().any(|&l| l) {
                                            assert_eq!(got[i], [-1.0; 4], "a dead row written");
                                            continue;
                                        }
                                        assert_eq!(
                                            got[i].map(f32::to_bits),
                                            want[i].map(f32::to_bits),
                                            "format {f} size {size:?} {ws:?}/{wt:?} \
                                             min {min:?} mag {mag:?} {mip:?} fma {fma} \
                                             lod {:?} pixel {i} s {qs:?} t {qt:?}: \
                                             {:?} vs {:?}",
                                            p.lod,
                                            got[i],
                                            want[i]
                                        );
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
    }
    assert!(plans > 300, "plans {plans}");
    // (a quad has a special value in about one case of six)
    assert!(vector > 4 * scalar, "vector {vector} scalar {scalar}");
}

#[test]
fn texels_decode_every_byte_as_the_scalar_code() {
    if !crate::texture::fast_avx2::available() {
        return;
    }
    let mut next = crate::test_rng::xorshift32(58);
    let mut narrow = 0;
    for f in 0..FORMATS.len() {
        for wrap in [Wrap::ClampToBorder, Wrap::Repeat] {
            let mut ts = state(f, [4, 4], &mut next);
            let o = &mut ts.defaults[Target::Tex2D.index()];
            o.params.wrap_s = wrap;
            let p = ts.unit_plan(0).expect("complete");
            narrow += usize::from(p.ext.narrow.is_some());
            // every byte in every component, 8 lanes at a time, the components apart
            for b in (0..256u32).step_by(8) {
                let raw: [u32; 8] = std::array::from_fn(|i| {
                    let u = b + i as u32;
                    u | (255 - u) << 8 | (u ^ 0x5a) << 16 | ((u * 7) & 255) << 24
                });
                // SAFETY: the CPU has AVX2 (checked above); 8 lanes.
                let got = unsafe { texels8(&p, I32x8::load(raw.as_ptr())) };
                let got = got.map(|c| c.to_array());
                for (i, r) in raw.iter().enumerate() {
                    let want = crate::texture::sample::texel_float(&p, r.to_le_bytes());
                    for c in 0..4 {
                        assert_eq!(
                            got[c][i].to_bits(),
                            want[c].to_bits(),
                            "format {f} {wrap:?} texel {r:#010x} component {c}"
                        );
                    }
                }
            }
        }
    }
    // RGB5, R3_G3_B2, RGBA4 and RGB5_A1 off the 8-bit path
    assert_eq!(narrow, 4);
}
