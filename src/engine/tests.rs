//! Differential tests: lowered programs run on random inputs give the bytes of today's
//! fragment functions for the same state ([`shade_chunk`] on its textured path, which the
//! C scenes hold to llvmpipe's bytes, and the AVX2 texture fast path's [`tex_row`]), at
//! every instruction-set level this CPU has.

use super::exec::{compile_for, isa_allowed, ChunkIn, Io, Scratch};
use super::ir::{Builder, FCmp, Op, Ty};
use super::lower::{lower_textured, planes_of, TexturedState};
use crate::cpu::Isa;
use crate::fixed_function::fog::FogPlan;
use crate::fragment::span::{shade_chunk, ChunkColors, Fused, Madd, TexLanes, Unfused, LANES};
use crate::fragment::{BlendPlan, DepthPlan, FragPlan};
use crate::framebuffer::{ColorFormat, DepthFormat, Framebuffer};
use crate::geometry::setup::{Plane, SetupTriangle};
use crate::pipe::{BlendEquation, BlendFactor, CompareFunc, FogMode};
use crate::stats::Stats;
use crate::texture::env::{Combine, TexEnv};
use crate::texture::lod::LodParams;
use crate::texture::{BaseFormat, Filter, MipFilter, SamplerParams, UnitPlan, Wrap};

/// A random test or benchmark case: a triangle's planes, a framebuffer's initial
/// contents, the chunks to shade and their texels.
pub(super) struct Case {
    /// The triangle (only its planes matter).
    pub t: SetupTriangle,
    /// Framebuffer size.
    pub w: usize,
    /// Framebuffer rows.
    pub h: usize,
    /// Initial colours.
    pub color: Vec<[u8; 4]>,
    /// Initial depths.
    pub depth: Vec<u32>,
    /// Chunks as (row, first column, live lanes).
    pub chunks: Vec<(usize, usize, [bool; LANES])>,
    /// RGBA8 texels of each chunk.
    pub texels: Vec<[[u8; 4]; LANES]>,
}

/// A plane with `a0` in `base ± spread` and small slopes.
fn plane(next: &mut impl FnMut() -> f32, base: f32, spread: f32, slope: f32) -> Plane {
    Plane {
        a0: base + (next() * 2.0 - 1.0) * spread,
        dadx: (next() * 2.0 - 1.0) * slope,
        dady: (next() * 2.0 - 1.0) * slope,
    }
}

impl Case {
    /// A case of `w`×`h` pixels, every chunk of every row; `full` makes every lane inside
    /// the row live, else lanes are live at random.
    pub fn new(seed: u32, w: usize, h: usize, full: bool) -> Case {
        let mut bits = crate::test_rng::xorshift32(seed);
        let mut next = || (bits() >> 8) as f32 / 16_777_216.0;
        let mut t = SetupTriangle {
            z: plane(&mut next, 0.5, 0.45, 0.02),
            w: plane(&mut next, 1.0, 0.5, 0.002),
            ..Default::default()
        };
        for k in 0..t.vary.len() {
            t.vary[k] = plane(&mut next, 0.5, 0.7, 0.03);
        }
        // Alpha mostly above the alpha test's reference, so that most lanes reach blending.
        t.vary[3] = plane(&mut next, 0.8, 0.3, 0.01);
        t.vary[crate::geometry::VARY_FOG] = plane(&mut next, 5.0, 6.0, 0.2);
        let mut rnd = crate::test_rng::xorshift32(seed ^ 0x9e37_79b9);
        let color = (0..w * h).map(|_| rnd().to_le_bytes()).collect();
        let depth = (0..w * h).map(|_| rnd() & 0xFF_FFFF).collect();
        let mut chunks = vec![];
        let mut texels = vec![];
        for y in 0..h {
            for x in (0..w).step_by(LANES) {
                let m = if full { 0xFF } else { rnd() };
                let live = std::array::from_fn(|i| x + i < w && (m >> i) & 1 == 1);
                chunks.push((y, x, live));
                texels.push(std::array::from_fn(|_| rnd().to_le_bytes()));
            }
        }
        Case {
            t,
            w,
            h,
            color,
            depth,
            chunks,
            texels,
        }
    }

    /// A framebuffer holding the initial contents.
    pub fn framebuffer(&self) -> Framebuffer {
        let mut fb = Framebuffer::new(self.w, self.h, ColorFormat::Rgba, DepthFormat::Z24, false);
        fb.color.copy_from_slice(&self.color);
        fb.depth.copy_from_slice(&self.depth);
        fb
    }

    /// The chunks as the engine takes them.
    pub fn chunk_ins(&self) -> Vec<ChunkIn> {
        self.chunks
            .iter()
            .map(|&(y, x, live)| ChunkIn {
                idx: y * self.w + x,
                fx: x as f32,
                fy: y as f32,
                live: live
                    .iter()
                    .enumerate()
                    .fold(0, |m, (i, &l)| m | (l as u8) << i),
                planes: 0,
            })
            .collect()
    }

    /// The texels packed, one 8-lane value per chunk.
    pub fn packed_texels(&self) -> Vec<[u32; 8]> {
        self.texels
            .iter()
            .map(|c| c.map(u32::from_le_bytes))
            .collect()
    }
}

/// The unit plan of a MODULATE RGBA texture (its levels are never read: the texels
/// come sampled).
pub(super) fn modulate_unit() -> UnitPlan<'static> {
    let sp = SamplerParams::default();
    let env = Combine::derive(&TexEnv::default(), BaseFormat::Rgba);
    UnitPlan {
        levels: &[],
        first: 0,
        last: 0,
        dims: 2,
        min_filter: Filter::Nearest,
        mag_filter: Filter::Nearest,
        mip_filter: MipFilter::None,
        wrap_s: Wrap::Repeat,
        wrap_t: Wrap::Repeat,
        border: [0.0; 4],
        aos: true,
        pot: [true, true],
        max_anisotropy: 1.0,
        lod: LodParams::new(&sp, 0.0, false),
        needs_lod: false,
        base_format: BaseFormat::Rgba,
        fast: crate::texture::fast::FastEnv::classify(&env),
        env,
        fma: false,
        ext: Default::default(),
    }
}

/// The prototype's state: MODULATE, then (with `full`) linear fog and the alpha test
/// GREATER 0x40, depth LESS with writes, blending SRC_ALPHA / ONE_MINUS_SRC_ALPHA.
pub(super) fn state(full: bool, fma: bool, over: bool) -> FragPlan {
    let (src, dst) = if over {
        (BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha)
    } else {
        (BlendFactor::DstColor, BlendFactor::OneMinusConstantAlpha)
    };
    FragPlan {
        depth: Some(DepthPlan {
            func: CompareFunc::Less,
            write: true,
            format: DepthFormat::Z24,
        }),
        flat: false,
        color_mask: [true; 4],
        fma,
        alpha: full.then_some((CompareFunc::Greater, 0x40)),
        stencil: None,
        blend: Some(BlendPlan {
            src_rgb: src,
            dst_rgb: dst,
            src_a: src,
            dst_a: dst,
            eq_rgb: BlendEquation::Add,
            eq_a: BlendEquation::Add,
            color: [10, 200, 30, 77],
        }),
        logic: None,
        separate_specular: false,
        fog: full.then_some(FogPlan {
            mode: FogMode::Linear,
            scale: -1.0 / 7.5,
            bias: 9.0 / 7.5,
            exp_k: 0.0,
            exp2_k: 0.0,
            color: [0.25, 0.5, 0.875],
            fma,
        }),
        count_samples: false,
        smooth: None,
        ms: None,
        blend_color: [0.0; 4],
        srgb: false,
        shader: None,
        more_buffers: 0,
    }
}

/// Today's textured general path over the case's chunks: colour and depth after.
pub(super) fn run_today<M: Madd, const PERSP: bool>(
    c: &Case,
    plan: &FragPlan,
    fb: &mut Framebuffer,
) -> Stats {
    let units = [modulate_unit()];
    let mut stats = Stats::default();
    let mut target = fb.target();
    for (&(y, x, live), tex) in c.chunks.iter().zip(&c.texels) {
        let mut tx: TexLanes = Default::default();
        for i in 0..LANES {
            tx[0][i] = tex[i].map(|b| b as f32 * crate::texture::sample::INV_255);
        }
        shade_chunk::<M, true, false, PERSP, true>(
            &c.t,
            plan,
            &units,
            ChunkColors::Textured(&tx),
            &mut target,
            y,
            x,
            live,
            &mut stats,
        );
    }
    stats
}

/// A case's engine inputs: planes, packed texels and chunks.
pub(super) struct Prepared {
    /// The triangle's planes.
    pub planes: Vec<[f32; 3]>,
    /// Packed texels, one 8-lane value per chunk.
    pub texels: Vec<[u32; 8]>,
    /// The chunks.
    pub chunks: Vec<ChunkIn>,
}

impl Case {
    /// The engine's inputs for this case.
    pub fn prepared(&self) -> Prepared {
        Prepared {
            planes: planes_of(&self.t).to_vec(),
            texels: self.packed_texels(),
            chunks: self.chunk_ins(),
        }
    }
}

/// Runs `prog` over prepared inputs into `fb`, `batch` chunks per kernel call.
pub(super) fn run_prepared(
    p: &Prepared,
    prog: &super::exec::Program,
    fb: &mut Framebuffer,
    batch: usize,
    scratch: &mut Scratch,
) {
    let inputs: [&[[u32; 8]]; 1] = [&p.texels];
    let mut io = Io {
        planes: &p.planes,
        inputs: &inputs,
        color: &mut fb.color,
        more_colors: Default::default(),
        depth: &mut fb.depth,
        uniforms: &[],
        live_out: &mut [],
        sampler: None,
        stencil: &mut [],
        front: true,
        outputs: &mut [],
    };
    prog.run(scratch, &mut io, &p.chunks, batch);
}

/// The engine over the case's chunks, `batch` chunks per kernel call.
pub(super) fn run_engine(
    c: &Case,
    prog: &super::exec::Program,
    fb: &mut Framebuffer,
    batch: usize,
) {
    run_prepared(&c.prepared(), prog, fb, batch, &mut Scratch::default());
}

/// The levels this CPU can run, each with whether it fuses.
pub(super) fn levels() -> Vec<Isa> {
    [Isa::Base, Isa::Fma, Isa::Avx2Fma]
        .into_iter()
        .filter(|&i| isa_allowed(i, crate::cpu::isa()))
        .collect()
}

/// Checks the engine against today's path for one state at every level.
fn check(full: bool, over: bool, persp: bool, seed: u32) {
    for isa in levels() {
        let plan = state(full, isa.fused(), over);
        let ir = lower_textured(&TexturedState { plan, persp }).expect("lowered");
        let prog = compile_for(&ir, isa);
        let mut drawn = 0;
        for (k, batch) in [1usize, 3, 8].into_iter().enumerate() {
            let c = Case::new(seed + k as u32, 37, 6, k == 2);
            let mut want = c.framebuffer();
            match (isa.fused(), persp) {
                (true, true) => run_today::<Fused, true>(&c, &plan, &mut want),
                (true, false) => run_today::<Fused, false>(&c, &plan, &mut want),
                (false, true) => run_today::<Unfused, true>(&c, &plan, &mut want),
                (false, false) => run_today::<Unfused, false>(&c, &plan, &mut want),
            };
            let mut got = c.framebuffer();
            run_engine(&c, &prog, &mut got, batch);
            let what = format!("{isa:?} full {full} over {over} persp {persp} batch {batch}");
            assert_eq!(got.depth.to_vec(), want.depth.to_vec(), "depth, {what}");
            assert_eq!(got.color.to_vec(), want.color.to_vec(), "colour, {what}");
            drawn += got
                .color
                .iter()
                .zip(&c.color)
                .filter(|(a, b)| a != b)
                .count();
        }
        assert!(
            drawn > 100,
            "{drawn} pixels drawn, {isa:?} full {full} over {over}"
        );
    }
}

#[test]
fn modulate_depth_over_matches_today() {
    check(false, true, true, 11);
    check(false, true, false, 21);
}

#[test]
fn fog_alpha_test_blend_matches_today() {
    check(true, true, true, 31);
    check(true, false, true, 41);
    check(true, false, false, 51);
}

/// The fast path's AVX2 row shader gives the same bytes as the engine for its states.
#[cfg(target_arch = "x86_64")]
#[test]
fn matches_the_avx2_fast_path() {
    use crate::fragment::simd_tex::tex_row;
    let isa = crate::cpu::isa();
    if !isa.avx2() {
        return;
    }
    let plan = state(false, isa.fused(), true);
    let env = modulate_unit().fast.expect("MODULATE has a fast form");
    let prog = compile_for(
        &lower_textured(&TexturedState { plan, persp: true }).expect("lowered"),
        isa,
    );
    let c = Case::new(7, 37, 6, false);
    let mut want = c.framebuffer();
    {
        let mut target = want.target();
        let mut stats = Stats::default();
        for (&(y, x, live), tex) in c.chunks.iter().zip(&c.texels) {
            // SAFETY: AVX2 (and FMA when fused) detected; the plan is one `plan_ok`
            // accepts (no alpha test, stencil or logic op); live lanes lie in the row.
            unsafe {
                // The row of the fused or unfused variant.
                macro_rules! row {
                    ($f:literal) => {
                        tex_row::<$f, true, false, true, true, true>(
                            &c.t,
                            &plan,
                            env,
                            &mut target,
                            y,
                            x,
                            &live,
                            tex,
                            &mut stats,
                        )
                    };
                }
                if isa.fused() {
                    row!(true)
                } else {
                    row!(false)
                }
            }
        }
    }
    let mut got = c.framebuffer();
    run_engine(&c, &prog, &mut got, 4);
    assert_eq!(got.depth.to_vec(), want.depth.to_vec());
    assert_eq!(got.color.to_vec(), want.color.to_vec());
}

/// Runs `f`'s result (an f32 value of a program over planes 0..3 with zero slopes, so
/// that each evaluates to its `a0` at every lane) at level `isa`, returning its bits.
pub(super) fn eval_f32(
    isa: Isa,
    a0: [f32; 3],
    f: impl Fn(&mut Builder, [super::ir::Val; 3]) -> super::ir::Val,
) -> u32 {
    let mut b = Builder::new();
    let v = [0u16, 1, 2].map(|n| b.push(Op::Interp(n)));
    let r = f(&mut b, v);
    let r = if b.ty(r) == Some(Ty::F32) {
        b.push(Op::Bits(r))
    } else {
        r
    };
    b.push(Op::StoreColor(0, r));
    let prog = compile_for(&b.finish().expect("typed"), isa);
    let planes = a0.map(|a| [a, 0.0, 0.0]);
    let mut color = [[0u8; 4]; 8];
    let chunk = ChunkIn {
        idx: 0,
        fx: 0.0,
        fy: 0.0,
        live: 0xFF,
        planes: 0,
    };
    let mut io = colour_io(&planes, &mut color, &[]);
    prog.run(&mut Scratch::default(), &mut io, &[chunk], 1);
    let lanes = color.map(u32::from_le_bytes);
    assert!(lanes.iter().all(|&l| l == lanes[0]), "{lanes:x?}");
    lanes[0]
}

/// The ALU operations against their scalar rules (`minps`/`maxps` NaN order, `cvtps2dq`
/// rounding and overflow, fused or not) on random values and specials, at every level.
#[test]
fn alu_ops_follow_the_scalar_rules() {
    let specials = [
        f32::NAN,
        0.0,
        1.0,
        -1.0,
        0.5,
        2.5,
        3.5,
        -2.5,
        1e10,
        -1e10,
        f32::INFINITY,
    ];
    let mut bits = crate::test_rng::xorshift32(99);
    let mut vals: Vec<f32> = specials.to_vec();
    vals.extend((0..60).map(|_| (bits() as i32) as f32 / 1e7));
    let sat = |v: f32| if v > 0.0 { v.min(1.0) } else { 0.0 };
    let cvt = |v: f32| {
        let r = v.round_ties_even();
        if (-2_147_483_648.0..2_147_483_648.0).contains(&r) {
            r as i32 as u32
        } else {
            0x8000_0000
        }
    };
    for isa in levels() {
        for w in vals.windows(3) {
            let (x, y, z) = (w[0], w[1], w[2]);
            let same = |got: u32, want: f32| {
                got == want.to_bits() || (want.is_nan() && f32::from_bits(got).is_nan())
            };
            let mad = if isa.fused() {
                x.mul_add(y, z)
            } else {
                x * y + z
            };
            let got = eval_f32(isa, [x, y, z], |b, v| b.push(Op::Mad(v[0], v[1], v[2])));
            assert!(same(got, mad), "{isa:?} mad {x} {y} {z}");
            let got = eval_f32(isa, [x, y, z], |b, v| b.push(Op::Min(v[0], v[1])));
            assert!(same(got, if x < y { x } else { y }), "{isa:?} min {x} {y}");
            let got = eval_f32(isa, [x, y, z], |b, v| b.push(Op::Max(v[0], v[1])));
            assert!(same(got, if x > y { x } else { y }), "{isa:?} max {x} {y}");
            let got = eval_f32(isa, [x, y, z], |b, v| b.push(Op::Sat(v[0])));
            assert!(same(got, sat(x)), "{isa:?} sat {x}");
            let got = eval_f32(isa, [x, y, z], |b, v| b.push(Op::Div(v[0], v[1])));
            assert!(same(got, x / y), "{isa:?} div {x} {y}");
            let got = eval_f32(isa, [x, y, z], |b, v| b.push(Op::CvtRne(v[0])));
            assert_eq!(got, cvt(x), "{isa:?} cvt {x}");
            let got = eval_f32(isa, [x, y, z], |b, v| {
                let lt = b.push(Op::FCmp(FCmp::Lt, v[0], v[1]));
                let (one, two) = (b.i32(1), b.i32(2));
                b.push(Op::Select(lt, one, two))
            });
            assert_eq!(got, if x < y { 1 } else { 2 }, "{isa:?} select {x} < {y}");
        }
    }
}

/// A type error is reported at the operation that makes it.
#[test]
fn builder_checks_types() {
    let mut b = Builder::new();
    let f = b.f32(1.0);
    let i = b.i32(1);
    b.add(f, f);
    b.add(f, i);
    let e = b.finish().unwrap_err();
    assert_eq!(e.at, 3);
}

/// An [`Io`] for programs that only read planes and uniforms and write draw buffer 0.
pub(super) fn colour_io<'a>(
    planes: &'a [[f32; 3]],
    color: &'a mut [[u8; 4]],
    uniforms: &'a [f32],
) -> Io<'a> {
    Io {
        planes,
        inputs: &[],
        color,
        more_colors: Default::default(),
        depth: &mut [],
        uniforms,
        live_out: &mut [],
        sampler: None,
        stencil: &mut [],
        front: true,
        outputs: &mut [],
    }
}

/// `n` chunks of 8 live pixels in a row: chunk `k` covers x = 8k..8k+8 at y = 0.
pub(super) fn row_chunks(n: usize) -> Vec<ChunkIn> {
    (0..n)
        .map(|k| ChunkIn {
            idx: 8 * k,
            fx: 8.0 * k as f32,
            fy: 0.0,
            live: 0xFF,
            planes: 0,
        })
        .collect()
}
