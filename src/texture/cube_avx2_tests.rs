//! [`Cube8`] against the scalar quad sampler (`cube_seamless::sample_quad`), bit for bit,
//! and the chunks, states and checks [`crate::texture::cube_aos8`]'s test shares.

use super::*;
use crate::texture::{
    cube_seamless, BaseFormat, Encoding, Level, Storage, Target, TextureObject, TextureState,
};

/// A seamless cube map of `n`x`n` faces (`n` a power of two) with a full chain of
/// random levels on unit 0 of a new state, sampled with `min`/`mip` (mag LINEAR).
pub(in crate::texture) fn state(
    n: usize,
    srgb: bool,
    next: &mut impl FnMut() -> u32,
) -> TextureState {
    let mut storage = Storage::of_base(BaseFormat::Rgba);
    if srgb {
        storage.encoding = Encoding::Srgb;
    }
    let mut o = TextureObject::new(Some(Target::Cube));
    for face in 0..6 {
        let levels = o.face_levels_mut(face);
        let mut size = n;
        for level in levels.iter_mut().take(n.trailing_zeros() as usize + 1) {
            *level = Some(Level {
                width: size,
                height: size,
                internal_format: 0x1908,
                base: BaseFormat::Rgba,
                storage,
                texels: (0..size * size).map(|_| next().to_le_bytes()).collect(),
                blocks: None,
                floats: None,
            });
            size = (size / 2).max(1);
        }
    }
    let mut ts = TextureState::default();
    ts.defaults[Target::Cube.index()] = o;
    ts.units[0].enabled_cube = true;
    ts.cube_seamless = true;
    ts
}

/// A random value in [-1, 1], often on a face edge or corner (equal magnitudes).
fn unit(next: &mut impl FnMut() -> u32) -> f32 {
    (next() % 20001) as f32 / 10000.0 - 1.0
}

/// The directions of one quad: a random direction (sometimes on an edge or a corner,
/// sometimes NaN, infinite, zero or huge) and its neighbours a small step away.
pub(in crate::texture) fn quad(next: &mut impl FnMut() -> u32) -> [[f32; 3]; 4] {
    let mut v = [unit(next), unit(next), unit(next)];
    match next() % 12 {
        // an edge: two equal magnitudes
        0 => {
            v[1] = if next().is_multiple_of(2) {
                v[0]
            } else {
                -v[0]
            }
        }
        1 => v[2] = v[1].abs(),
        // a corner
        2 => v = [1.0, -1.0, 1.0].map(|c| c * v[0]),
        3 => {
            v[(next() % 3) as usize] =
                [f32::NAN, f32::INFINITY, -f32::INFINITY][(next() % 3) as usize]
        }
        4 => v = [0.0; 3],
        5 => v[(next() % 3) as usize] = 3.0e30,
        _ => {}
    }
    let step = [1.0e-4, 1.0e-3, 1.0e-2, 0.1][(next() % 4) as usize];
    let d = [
        [0.0; 3],
        [step, 0.0, 0.0],
        [0.0, step, step / 2.0],
        [step, step, 0.0],
    ];
    d.map(|d| std::array::from_fn(|c| v[c] + d[c] * unit(next)))
}

/// Sets the cube map of `ts` to LINEAR filtering with mip filter `mip`, LOD bias
/// `bias` and maximum LOD `max_lod`.
pub(in crate::texture) fn lod_state(
    ts: &mut TextureState,
    mip: MipFilter,
    bias: f32,
    max_lod: f32,
) {
    let o = &mut ts.defaults[Target::Cube.index()];
    o.params.min_filter = Filter::Linear;
    o.params.mag_filter = Filter::Linear;
    o.params.mip_filter = mip;
    o.params.lod_bias = bias;
    o.params.max_lod = max_lod;
}

/// The mip filters, LOD biases and maximum LODs under test.
pub(in crate::texture) const LODS: [(MipFilter, f32, f32); 6] = [
    (MipFilter::None, 0.0, 1000.0),
    (MipFilter::Linear, 0.0, 1000.0),
    (MipFilter::Nearest, 0.0, 1000.0),
    (MipFilter::Linear, 0.75, 2.0),
    (MipFilter::Nearest, -1.0, 1000.0),
    (MipFilter::Linear, -2.5, 1000.0),
];

/// A chunk's directions (`[s, t, r]`, two rows of 8 lanes): four quads of [`quad`]
/// (or, when `near`, of directions within 10^-3 of one), and random live lanes.
pub(in crate::texture) fn chunk(
    next: &mut impl FnMut() -> u32,
    near: bool,
) -> ([[[f32; 8]; 2]; 3], [[bool; 8]; 2]) {
    let mut c = [[[0.0f32; 8]; 2]; 3];
    let base = quad(next)[0];
    for j in 0..4 {
        for (i, v) in quad(next).into_iter().enumerate() {
            let (row, lane) = (i / 2, 2 * j + i % 2);
            let v: [f32; 3] = if near {
                std::array::from_fn(|k| base[k] + v[k] * 1.0e-3)
            } else {
                v
            };
            for k in 0..3 {
                c[k][row][lane] = v[k];
            }
        }
    }
    let live = std::array::from_fn(|_| std::array::from_fn(|_| !next().is_multiple_of(3)));
    (c, live)
}

/// Checks the live quads of chunk `c` an 8-wide sampler wrote to `out` (all but those
/// in `redo`) against `scalar` (the quad sampler at a quad's s, t, r), bit for bit,
/// counting the quads checked and redone in `counts`; `what` names the state.
pub(in crate::texture) fn check_quads(
    c: &[[[f32; 8]; 2]; 3],
    live: &[[bool; 8]; 2],
    out: &[[[f32; 4]; 8]; 2],
    redo: u32,
    scalar: impl Fn([f32; 4], [f32; 4], [f32; 4]) -> [[f32; 4]; 4],
    counts: &mut [usize; 2],
    what: &dyn Fn() -> String,
) {
    for j in 0..4 {
        let (a, b) = (2 * j, 2 * j + 1);
        if !(live[0][a] || live[0][b] || live[1][a] || live[1][b]) {
            continue;
        }
        if redo >> j & 1 != 0 {
            counts[1] += 1;
            continue;
        }
        counts[0] += 1;
        let q4 = |c: &[[f32; 8]; 2]| [c[0][a], c[0][b], c[1][a], c[1][b]];
        let [s, t, r] = [q4(&c[0]), q4(&c[1]), q4(&c[2])];
        let q = scalar(s, t, r);
        let got = [out[0][a], out[0][b], out[1][a], out[1][b]];
        for i in 0..4 {
            assert_eq!(
                got[i].map(f32::to_bits),
                q[i].map(f32::to_bits),
                "{} pixel {i} s {s:?} t {t:?} r {r:?}",
                what()
            );
        }
    }
}

#[test]
fn rows_match_the_quad_sampler() {
    if !crate::texture::fast_avx2::available() {
        return;
    }
    let mut next = crate::test_rng::xorshift32(54);
    let mut counts = [0; 2];
    for n in [1, 4, 16, 64] {
        for srgb in [false, true] {
            for (mip, bias, max_lod) in LODS {
                let mut ts = state(n, srgb, &mut next);
                lod_state(&mut ts, mip, bias, max_lod);
                let p = ts.unit_plan(0).expect("complete");
                let ExtKind::CubeSeamless(faces) = &p.ext.kind else {
                    panic!("not seamless");
                };
                let c8 = Cube8::of(&p).expect("covered");
                for _ in 0..200 {
                    let (c, live) = chunk(&mut next, false);
                    let [s, t, r] = &c;
                    let mut out = [[[-1.0f32; 4]; 8]; 2];
                    let [o0, o1] = &mut out;
                    // SAFETY: the CPU has AVX2 (checked above), and FMA when the plan
                    // fuses (`sample::has_fma`).
                    let redo = unsafe { c8.rows(s, t, r, &live, [o0, o1]) };
                    let scalar = |s, t, r| {
                        let q = cube_seamless::sample_quad(&p, faces, s, t, r);
                        for c in &q {
                            assert!(c.iter().all(|v| v.is_finite()), "a finite colour");
                        }
                        q
                    };
                    let what = || format!("n {n} srgb {srgb} {mip:?} bias {bias}");
                    check_quads(&c, &live, &out, redo, scalar, &mut counts, &what);
                }
            }
        }
    }
    let [vector, scalar] = counts;
    // the vectors took many quads (the small faces' quads mostly reach an edge, and
    // the quads with special values always go to the scalar code)
    assert!(vector > 10_000, "vector {vector} scalar {scalar}");
}
