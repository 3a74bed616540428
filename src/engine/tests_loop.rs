//! Loops in the executor ([`Op::LoopBegin`] … [`Op::LoopEnd`] with mutable variables):
//! per-lane trip counts against the same arithmetic done lane by lane, values defined
//! before a loop that stay alive through it, and the loop limiter, at every level.

use super::exec::{compile_for, Scratch, LOOP_LIMIT};
use super::ir::{Builder, FCmp, Ir, Op, Ty};
use super::tests::{colour_io, levels, row_chunks};

/// Runs `ir` (which stores f32 bits to draw buffer 0) over 3 chunks whose pixels have
/// x = 0..24, batches of `batch` chunks, and returns the stored floats.
fn run(ir: &Ir, isa: crate::cpu::Isa, batch: usize) -> Vec<f32> {
    let prog = compile_for(ir, isa);
    let mut color = vec![[0u8; 4]; 24];
    let chunks = row_chunks(3);
    let mut io = colour_io(&[], &mut color, &[]);
    prog.run(&mut Scratch::default(), &mut io, &chunks, batch);
    color.iter().map(|c| f32::from_le_bytes(*c)).collect()
}

/// `s = Σ (c² + k)` for `c` from 0 while `c < x` (each lane runs x times; `k = x / 2` is
/// defined before the loop and read only at the start of its body, so its slot would be
/// free for the body's later values but for the loop).
fn sum_of_squares() -> Ir {
    let mut b = Builder::new();
    let x = b.push(Op::FragX);
    let half = b.f32(0.5);
    let k = b.push(Op::Mul(x, half));
    let (zero, one) = (b.f32(0.0), b.f32(1.0));
    b.push(Op::VarStore(0, zero));
    b.push(Op::VarStore(1, zero));
    b.push(Op::LoopBegin(0));
    let c = b.push(Op::VarLoad(0, Ty::F32));
    let s = b.push(Op::VarLoad(1, Ty::F32));
    let run = b.push(Op::FCmp(FCmp::Lt, c, x));
    let sk = b.push(Op::Add(s, k));
    let cc = b.push(Op::Mul(c, c));
    let s1 = b.push(Op::Add(sk, cc));
    let c1 = b.push(Op::Add(c, one));
    let s2 = b.push(Op::Select(run, s1, s));
    let c2 = b.push(Op::Select(run, c1, c));
    b.push(Op::VarStore(0, c2));
    b.push(Op::VarStore(1, s2));
    let again = b.push(Op::FCmp(FCmp::Lt, c2, x));
    b.push(Op::LoopEnd(0, again));
    let s = b.push(Op::VarLoad(1, Ty::F32));
    let bits = b.push(Op::Bits(s));
    b.push(Op::StoreColor(0, bits));
    b.finish().unwrap()
}

#[test]
fn each_lane_runs_its_own_trip_count() {
    let ir = sum_of_squares();
    for isa in levels() {
        for batch in [1, 2, 3] {
            let got = run(&ir, isa, batch);
            for (i, &g) in got.iter().enumerate() {
                let x = i as f32;
                let mut s = 0.0f32;
                let mut c = 0.0f32;
                while c < x {
                    s = (s + x * 0.5) + c * c;
                    c += 1.0;
                }
                assert_eq!(g.to_bits(), s.to_bits(), "{isa:?} batch {batch} lane {i}");
            }
        }
    }
}

/// A loop whose mask never clears stops at the limiter: the body runs `LOOP_LIMIT`
/// times (llvmpipe decrements, then goes on while the count stays above zero).
#[test]
fn a_loop_that_never_ends_stops_at_the_limiter() {
    let mut b = Builder::new();
    let (zero, one) = (b.f32(0.0), b.f32(1.0));
    b.push(Op::VarStore(0, zero));
    b.push(Op::LoopBegin(0));
    let c = b.push(Op::VarLoad(0, Ty::F32));
    let c1 = b.push(Op::Add(c, one));
    b.push(Op::VarStore(0, c1));
    let x = b.push(Op::FragX);
    let always = b.push(Op::FCmp(FCmp::Ge, x, zero));
    b.push(Op::LoopEnd(0, always));
    let c = b.push(Op::VarLoad(0, Ty::F32));
    let bits = b.push(Op::Bits(c));
    b.push(Op::StoreColor(0, bits));
    let ir = b.finish().unwrap();
    for isa in levels() {
        let got = run(&ir, isa, 3);
        assert!(
            got.iter().all(|&g| g == LOOP_LIMIT as f32),
            "{isa:?}: {got:?}"
        );
    }
}
