//! The shader operations ([`Op::Un`], [`Op::Pow`], the integer and bit operations, `Eq`
//! and `Ne` comparisons) against their scalar rules at every level, and the hoisting of
//! per-run values into the prologue.

use super::exec::{compile_for, ChunkIn, Io, Scratch};
use super::ir::{Builder, FCmp, IOp, Op, Un, UNS};
use super::tests::{colour_io, eval_f32, levels, row_chunks};
use crate::fixed_function::gallivm_math as gm;

/// Specials and random values of several magnitudes.
fn values() -> Vec<f32> {
    let mut v = vec![
        0.0,
        -0.0,
        0.5,
        -0.5,
        1.0,
        -1.5,
        2.5,
        3.0e9,
        -3.0e9,
        1e-40,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
        f32::MAX,
    ];
    let mut bits = crate::test_rng::xorshift32(7);
    v.extend((0..80).map(|k| (bits() as i32) as f32 / [1e9, 1e7, 1e5, 1e3][k % 4]));
    v
}

/// The scalar rule of a unary function at a level that fuses or not.
fn unary(u: Un, x: f32, fused: bool) -> f32 {
    match u {
        Un::Floor => x.floor(),
        Un::Ceil => x.ceil(),
        Un::Sqrt => x.sqrt(),
        Un::Abs => x.abs(),
        Un::Neg => -x,
        Un::Exp2 => gm::exp2(x, fused),
        Un::Log2 => gm::log2_safe(x, fused),
        Un::Sin => gm::sin_or_cos(x, false, fused),
        Un::Cos => gm::sin_or_cos(x, true, fused),
    }
}

#[test]
fn shader_ops_follow_the_scalar_rules() {
    let vals = values();
    let same = |got: u32, want: f32| {
        got == want.to_bits() || (want.is_nan() && f32::from_bits(got).is_nan())
    };
    for isa in levels() {
        for w in vals.windows(2) {
            // The values arrive through a plane, `0·x + a0`, which turns −0 into +0.
            let (x, y) = (w[0] + 0.0, w[1] + 0.0);
            for u in UNS {
                let got = eval_f32(isa, [x, y, 0.0], |b, v| b.push(Op::Un(u, v[0])));
                let want = unary(u, x, isa.fused());
                assert!(same(got, want), "{isa:?} {u:?} {x}: {got:x} {want}");
            }
            let got = eval_f32(isa, [x, y, 0.0], |b, v| b.push(Op::Pow(v[0], v[1])));
            assert!(same(got, gm::pow(x, y, isa.fused())), "{isa:?} pow {x} {y}");
            let (i, j) = (x.to_bits() as i32, y.to_bits() as i32);
            let ints = |b: &mut Builder, v: [super::ir::Val; 3]| {
                (b.push(Op::Bits(v[0])), b.push(Op::Bits(v[1])))
            };
            for (op, want) in [
                (IOp::Add, i.wrapping_add(j)),
                (IOp::Sub, i.wrapping_sub(j)),
                (IOp::Mul, i.wrapping_mul(j)),
                (IOp::Min, i.min(j)),
                (IOp::Max, i.max(j)),
                (
                    IOp::Div,
                    if j == 0 {
                        0
                    } else {
                        (i as i64 / j as i64) as i32
                    },
                ),
                (
                    IOp::UDiv,
                    if j == 0 {
                        -1
                    } else {
                        (i as u32 / j as u32) as i32
                    },
                ),
                (
                    IOp::URem,
                    if j == 0 {
                        -1
                    } else {
                        (i as u32 % j as u32) as i32
                    },
                ),
                (IOp::Shl, ((i as i64) << (j & 31)) as i32),
                (IOp::Shr, ((i as i64) >> (j & 31)) as i32),
                (IOp::UShr, ((i as u32 as u64) >> (j & 31)) as i32),
            ] {
                let got = eval_f32(isa, [x, y, 0.0], |b, v| {
                    let (a, c) = ints(b, v);
                    b.push(Op::IBin(op, a, c))
                });
                assert_eq!(got as i32, want, "{isa:?} {op:?} {i} {j}");
            }
            let got = eval_f32(isa, [x, y, 0.0], |b, v| {
                let (a, c) = ints(b, v);
                b.push(Op::Xor(a, c))
            });
            assert_eq!(got as i32, i ^ j);
            for c in [FCmp::Lt, FCmp::Le, FCmp::Gt, FCmp::Ge, FCmp::Eq, FCmp::Ne] {
                let (fw, iw) = match c {
                    FCmp::Lt => (x < y, i < j),
                    FCmp::Le => (x <= y, i <= j),
                    FCmp::Gt => (x > y, i > j),
                    FCmp::Ge => (x >= y, i >= j),
                    FCmp::Eq => (x == y, i == j),
                    FCmp::Ne => (x != y, i != j),
                };
                let pick = |b: &mut Builder, m| {
                    let (one, two) = (b.i32(1), b.i32(2));
                    b.push(Op::Select(m, one, two))
                };
                let got = eval_f32(isa, [x, y, 0.0], |b, v| {
                    let m = b.push(Op::FCmp(c, v[0], v[1]));
                    pick(b, m)
                });
                assert_eq!(got, if fw { 1 } else { 2 }, "{isa:?} {c:?} {x} {y}");
                let got = eval_f32(isa, [x, y, 0.0], |b, v| {
                    let (a, d) = ints(b, v);
                    let m = b.push(Op::SCmp(c, a, d));
                    pick(b, m)
                });
                assert_eq!(got, if iw { 1 } else { 2 }, "{isa:?} s{c:?} {i} {j}");
            }
            let got = eval_f32(isa, [x, y, 0.0], |b, v| b.push(Op::FtoI(v[0])));
            let trunc = if (-2_147_483_648.0..2_147_483_648.0).contains(&x) {
                x as i32
            } else {
                i32::MIN
            };
            assert_eq!(got as i32, trunc, "{isa:?} ftoi {x}");
            let got = eval_f32(isa, [x, y, 0.0], |b, v| {
                let a = b.push(Op::Bits(v[0]));
                let f = b.push(Op::ItoF(a));
                let g = b.push(Op::FromBits(a));
                b.push(Op::Add(f, g))
            });
            assert!(same(got, i as f32 + x), "{isa:?} itof {i}");
        }
    }
}

/// Uniforms and what is computed from them run in the prologue, and give the values of
/// the same arithmetic per lane.
#[test]
fn uniform_arithmetic_is_hoisted() {
    for isa in levels() {
        let mut b = Builder::new();
        let u = b.push(Op::Uniform(0));
        let e = b.push(Op::Un(Un::Exp2, u));
        let k = b.f32(3.0);
        let m = b.push(Op::Mul(e, k));
        let x = b.push(Op::FragX);
        let r = b.push(Op::Add(m, x));
        let bits = b.push(Op::Bits(r));
        b.push(Op::StoreColor(0, bits));
        let prog = compile_for(&b.finish().unwrap(), isa);
        assert_eq!(prog.prologue_len(), 4, "uniform, exp2, constant, multiply");
        let mut color = vec![[0u8; 4]; 24];
        let chunks = row_chunks(3);
        let mut io = colour_io(&[], &mut color, &[0.7]);
        prog.run(&mut Scratch::default(), &mut io, &chunks, 2);
        for (i, c) in color.iter().enumerate() {
            let want = gm::exp2(0.7, isa.fused()) * 3.0 + i as f32;
            assert_eq!(u32::from_le_bytes(*c), want.to_bits(), "{isa:?} lane {i}");
        }
    }
}

/// Values nothing with an effect uses cost no step, and constants of the same bits share
/// one: the lowering reads all of `gl_TexCoord[]` (32 planes, each with its perspective
/// divide) for one `.st`, and makes a constant per use.
#[test]
fn dead_values_are_dropped_and_constants_shared() {
    for isa in levels() {
        let mut b = Builder::new();
        let w = b.push(Op::Interp(0));
        let one = b.f32(1.0);
        let rw = b.push(Op::Div(one, w));
        let mut planes = Vec::new();
        for p in 2..34 {
            let a = b.push(Op::Interp(p));
            planes.push(b.push(Op::Mul(a, rw)));
        }
        let one_again = b.f32(1.0);
        let s = b.push(Op::Add(planes[0], one_again));
        let _dead = b.push(Op::Un(Un::Sqrt, planes[5]));
        let bits = b.push(Op::Bits(s));
        b.push(Op::StoreColor(0, bits));
        let prog = compile_for(&b.finish().unwrap(), isa);
        // prologue: the constant 1.0 once; body: w, 1/w, plane 2, the divide, the add,
        // the bits and the store
        assert_eq!(prog.prologue_len(), 1, "{isa:?}");
        assert_eq!(prog.len(), 8, "{isa:?}");
        let mut color = vec![[0u8; 4]; 8];
        let mut planes_in = vec![[0.0f32; 3]; 34];
        planes_in[0] = [2.0, 0.0, 0.0];
        planes_in[2] = [3.0, 1.0, 0.0];
        let mut io = colour_io(&planes_in, &mut color, &[]);
        let chunk = ChunkIn {
            idx: 0,
            fx: 0.0,
            fy: 0.0,
            live: 0xFF,
            planes: 0,
        };
        prog.run(&mut Scratch::default(), &mut io, &[chunk], 1);
        for (i, c) in color.iter().enumerate() {
            let want = (3.0 + i as f32) * (1.0f32 / 2.0) + 1.0;
            assert_eq!(u32::from_le_bytes(*c), want.to_bits(), "{isa:?} lane {i}");
        }
    }
}

/// Runs `f`'s value (bits stored as the colour) over `pairs` chunk pairs of 8 lanes (rows
/// `2p` and `2p + 1` from x = 8p) in batches of `batch`, with `sampler`; returns each
/// chunk's lanes.
fn run_pairs(
    isa: crate::cpu::Isa,
    pairs: usize,
    batch: usize,
    live: &dyn Fn(usize) -> u8,
    sampler: Option<&dyn super::exec::TexSampler>,
    f: impl Fn(&mut Builder, [super::ir::Val; 3]) -> super::ir::Val,
) -> Vec<[u32; 8]> {
    let mut b = Builder::new();
    let v = [0u16, 1, 2].map(|n| b.push(Op::Interp(n)));
    let r = f(&mut b, v);
    let r = b.push(Op::Bits(r));
    b.push(Op::StoreColor(0, r));
    let prog = compile_for(&b.finish().expect("typed"), isa);
    assert!(prog.quads());
    // v0 = -3y, v1 = 0.25x, v2 = y
    let planes = [[0.0, 0.0, -3.0], [0.0, 0.25, 0.0], [0.0, 0.0, 1.0]];
    let chunks: Vec<ChunkIn> = (0..2 * pairs)
        .map(|k| ChunkIn {
            idx: 8 * k,
            fx: (8 * (k / 2)) as f32,
            fy: k as f32,
            live: live(k),
            planes: 0,
        })
        .collect();
    let mut color = vec![[0u8; 4]; 16 * pairs];
    let mut io = Io {
        planes: &planes,
        inputs: &[],
        color: &mut color,
        more_colors: Default::default(),
        depth: &mut [],
        uniforms: &[],
        live_out: &mut [],
        sampler,
        stencil: &mut [],
        front: true,
        outputs: &mut [],
    };
    prog.run(&mut Scratch::default(), &mut io, &chunks, batch);
    color
        .chunks(8)
        .map(|c| std::array::from_fn(|i| u32::from_le_bytes(c[i])))
        .collect()
}

#[test]
fn derivatives_are_quad_differences() {
    // value(x, y) = (x - 3y)·(0.25x + y) + x·y: non-linear, exact.
    let value = |x: f32, y: f32| (x - 3.0 * y) * (0.25 * x + y) + x * y;
    let f = |b: &mut Builder, v: [super::ir::Val; 3]| {
        let x = b.push(Op::FragX);
        let p = b.add(x, v[0]);
        let q = b.add(v[1], v[2]);
        let m = b.mul(p, q);
        let xy = b.mul(x, v[2]);
        b.add(m, xy)
    };
    for isa in levels() {
        for batch in [2, 3, 8] {
            let dx = run_pairs(isa, 3, batch, &|_| 0xFF, None, |b, v| {
                let w = f(b, v);
                b.push(Op::Ddx(w))
            });
            let dy = run_pairs(isa, 3, batch, &|k| [0xFF, 0][k % 2], None, |b, v| {
                let w = f(b, v);
                b.push(Op::Ddy(w))
            });
            for k in 0..6 {
                let (x0, y) = ((8 * (k / 2)) as f32, k as f32);
                for i in 0..8 {
                    let x = x0 + i as f32;
                    let l = x0 + (i & !1) as f32;
                    let want = value(l + 1.0, y) - value(l, y);
                    assert_eq!(dx[k][i], want.to_bits(), "{isa:?} ddx chunk {k} lane {i}");
                    if k % 2 == 0 {
                        // The second row is not live: the pair's first chunk only.
                        let want = value(x, y + 1.0) - value(x, y);
                        assert_eq!(dy[k][i], want.to_bits(), "{isa:?} ddy chunk {k} lane {i}");
                    } else {
                        assert_eq!(dy[k][i], 0, "a chunk without live lanes is not written");
                    }
                }
            }
        }
    }
}

/// A sampler that returns its coordinates and whether the lane is live plus the
/// level-of-detail argument, and counts its calls.
struct Echo(std::cell::Cell<usize>);

impl super::exec::TexSampler for Echo {
    fn sample(&self, lookup: usize, c: &super::exec::QuadCoords, out: &mut [[[f32; 4]; 8]; 2]) {
        self.0.set(self.0.get() + 1);
        for (r, row) in out.iter_mut().enumerate() {
            for (i, o) in row.iter_mut().enumerate() {
                let live = if c.live[r][i] { 1.0 } else { 0.0 };
                *o = [
                    c.s[r][i],
                    c.t[r][i],
                    c.r[r][i] + lookup as f32,
                    live + c.l[r][i],
                ];
            }
        }
    }
}

#[test]
fn sample_hands_pairs_to_the_sampler_and_texel_reads_its_result() {
    for isa in levels() {
        for ch in 0..4u16 {
            let echo = Echo(std::cell::Cell::new(0));
            let live = |k: usize| [0b1010_1111, 0b0000_0110][k % 2];
            let got = run_pairs(isa, 2, 4, &live, Some(&echo), |b, v| {
                let s = b.push(Op::Mul(v[0], v[0]));
                b.push(Op::Sample {
                    lookup: 2,
                    s,
                    t: v[1],
                    r: v[2],
                    l: v[1],
                });
                b.push(Op::Texel(4 * 2 + ch))
            });
            assert_eq!(echo.0.get(), 2, "one call per pair");
            for (k, lanes) in got.iter().enumerate() {
                let y = k as f32;
                for (i, &bits) in lanes.iter().enumerate() {
                    if live(k) >> i & 1 == 0 {
                        continue;
                    }
                    let x = (8 * (k / 2) + i) as f32;
                    let v0 = -3.0 * y;
                    let want = [v0 * v0, 0.25 * x, y + 2.0, 1.0 + 0.25 * x][usize::from(ch)];
                    assert_eq!(f32::from_bits(bits), want, "{isa:?} chunk {k} lane {i}");
                }
            }
        }
    }
}
