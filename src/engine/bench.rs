//! The prototype's measurement (an ignored test; run it alone on a quiet machine):
//! `cargo test --release --lib engine::bench -- --ignored --nocapture`.
//!
//! It shades the same chunks with today's hand-written AVX2 fast path, today's general
//! textured path and the engine (several batch sizes, and the portable level), in
//! alternating rounds, and prints the median ns per pixel of each and the time to lower
//! and compile one state. Every candidate's bytes are compared first.

use super::exec::Scratch;
use super::exec::{compile_for, ChunkIn, Program};
use super::kernels::lanes_avx2::Avx2;
use super::kernels::Lanes;
use super::lower::{lower_textured, TexturedState};
use super::tests::{modulate_unit, run_prepared, state, Case, Prepared};
use crate::cpu::Isa;
use crate::fragment::span::{shade_chunk, ChunkColors, Fused, TexLanes, LANES};
use crate::fragment::FragPlan;
use crate::framebuffer::Framebuffer;
use crate::stats::Stats;
use std::cell::RefCell;
use std::time::Instant;

/// Today's general textured path over the case, compiled for AVX2 and FMA as the
/// pipeline's walks are (texels converted beforehand, as the sampler delivers them).
///
/// # Safety
/// The CPU has AVX2 and FMA.
#[target_feature(enable = "avx2,fma")]
unsafe fn general(c: &Case, tx: &[TexLanes], plan: &FragPlan, fb: &mut Framebuffer) {
    let units = [modulate_unit()];
    let mut stats = Stats::default();
    let mut target = fb.target();
    for (&(y, x, live), tx) in c.chunks.iter().zip(tx) {
        shade_chunk::<Fused, true, false, true, true>(
            &c.t,
            plan,
            &units,
            ChunkColors::Textured(tx),
            &mut target,
            y,
            x,
            live,
            &mut stats,
        );
    }
}

/// Today's AVX2 fast-path row shader over the case.
///
/// # Safety
/// The CPU has AVX2 and FMA; the plan has no alpha test, stencil or logic op.
#[target_feature(enable = "avx2,fma")]
unsafe fn hand(c: &Case, plan: &FragPlan, fb: &mut Framebuffer) {
    let env = modulate_unit().fast.expect("fast form");
    let mut stats = Stats::default();
    let mut target = fb.target();
    for (&(y, x, live), tex) in c.chunks.iter().zip(&c.texels) {
        // SAFETY: AVX2 and FMA (this function's features); live lanes lie in the row.
        unsafe {
            crate::fragment::simd_tex::tex_row::<true, true, false, true, true, true>(
                &c.t,
                plan,
                env,
                &mut target,
                y,
                x,
                &live,
                tex,
                &mut stats,
            )
        }
    }
}

/// The same program as straight-line AVX2+FMA code, every value in registers: what a
/// JIT could at best emit for it (the JIT candidate's ceiling; no JIT was built).
///
/// # Safety
/// The CPU has AVX2 and FMA; live lanes lie in the buffers.
#[target_feature(enable = "avx2,fma")]
unsafe fn ideal(p: &Prepared, plan: &FragPlan, fb: &mut Framebuffer) {
    type V = Avx2<true>;
    let (planes, texels, chunks) = (&p.planes, &p.texels, &p.chunks);
    let blend = plan.blend.expect("blend");
    let over = crate::fragment::simd::blend_is_over(&blend);
    let (color, depth) = (fb.color.as_mut_ptr() as *mut u32, fb.depth.as_mut_ptr());
    let (clen, dlen) = (fb.color.len(), fb.depth.len());
    // SAFETY: AVX2 and FMA (this function's features); live lanes lie in the buffers.
    unsafe {
        let ip = |n: usize, ch: &ChunkIn| {
            let [a0, dx, dy] = planes[n];
            V::mad(
                V::splat_f(dy),
                V::splat_f(ch.fy),
                V::mad(V::splat_f(dx), V::lane_x(ch.fx), V::splat_f(a0)),
            )
        };
        let (zero, one, k255) = (V::splat_f(0.0), V::splat_f(1.0), V::splat_f(255.0));
        let inv = V::splat_f(crate::texture::sample::INV_255);
        for (ch, tex) in chunks.iter().zip(texels) {
            let oow = V::div(one, ip(1, ch));
            let t = V::ld_i(tex);
            let mut col = [zero; 4];
            for (k, o) in col.iter_mut().enumerate() {
                let f = V::mul(ip(2 + k, ch), oow);
                let tf = V::mul(
                    V::itof(V::and(V::shr(t, 8 * k as u32), V::splat_i(255))),
                    inv,
                );
                *o = V::mul(f, tf);
            }
            if let Some(fog) = &plan.fog {
                let coord = V::mul(ip(2 + crate::geometry::VARY_FOG, ch), oow);
                let lin = V::add(V::mul(coord, V::splat_f(fog.scale)), V::splat_f(fog.bias));
                let f = V::min(V::max(lin, zero), one);
                let g = V::sub(one, f);
                for (k, o) in col.iter_mut().take(3).enumerate() {
                    *o = V::add(V::mul(V::splat_f(fog.color[k]), g), V::mul(*o, f));
                }
            }
            let mut px = V::splat_i(0);
            for (k, o) in col.iter().enumerate() {
                let u = V::cvt(V::mul(V::min(V::max(*o, zero), one), k255));
                px = V::or(px, V::shl(u, 8 * k as u32));
            }
            let mut live =
                crate::simd::I32x8::new(std::array::from_fn(|i| -((ch.live >> i & 1) as i32)));
            if let Some((func, r)) = plan.alpha {
                let a = V::and(V::shr(px, 24), V::splat_i(255));
                live = V::and(live, V::icmp(func, a, V::splat_i(r as i32)));
            }
            let z = V::min(V::max(ip(0, ch), zero), one);
            let q = V::cvt(V::mul(z, V::splat_f(16_777_215.0)));
            let d = plan.depth.expect("depth");
            live = V::depth(d.func, d.write, q, live, depth.add(ch.idx), dlen - ch.idx);
            let dst = V::load_color(color.add(ch.idx), live);
            let out = V::blend(&blend, over, px, dst);
            V::store_color(color.add(ch.idx), clen - ch.idx, live, out);
        }
    }
}

/// The median of `v`.
fn median(v: &mut [f64]) -> f64 {
    v.sort_by(|a, b| a.total_cmp(b));
    v[v.len() / 2]
}

/// One candidate: its name and how it shades the case into a framebuffer.
type Candidate<'a> = (String, Box<dyn Fn(&mut Framebuffer) + 'a>);

/// Times `cands` over case `c` in `rounds` alternating rounds; prints ns per pixel
/// (median, and the spread between the 25th and 75th percentiles).
fn race(title: &str, c: &Case, cands: &[Candidate<'_>], rounds: usize) {
    let px = c.chunks.len() * LANES;
    let mut want: Option<Framebuffer> = None;
    for (name, f) in cands {
        let mut fb = c.framebuffer();
        f(&mut fb);
        match &want {
            None => want = Some(fb),
            Some(w) => {
                let differ =
                    |a: &[[u8; 4]], b: &[[u8; 4]]| a.iter().zip(b).filter(|(x, y)| x != y).count();
                let dd = fb
                    .depth
                    .iter()
                    .zip(w.depth.iter())
                    .filter(|(x, y)| x != y)
                    .count();
                let dc = differ(&fb.color, &w.color);
                assert!(
                    dc == 0 && dd == 0,
                    "{name}: {dc} colours and {dd} depths differ"
                );
            }
        }
    }
    let mut times = vec![Vec::new(); cands.len()];
    let mut fbs: Vec<Framebuffer> = cands.iter().map(|_| c.framebuffer()).collect();
    for _ in 0..rounds {
        for (i, (_, f)) in cands.iter().enumerate() {
            fbs[i].color.copy_from_slice(&c.color);
            fbs[i].depth.copy_from_slice(&c.depth);
            let t0 = Instant::now();
            f(&mut fbs[i]);
            times[i].push(t0.elapsed().as_nanos() as f64 / px as f64);
        }
    }
    println!("{title} ({px} px, {rounds} rounds)");
    for ((name, _), t) in cands.iter().zip(times.iter_mut()) {
        let m = median(t);
        let (q1, q3) = (t[t.len() / 4], t[t.len() * 3 / 4]);
        println!("  {name:<28} {m:6.2} ns/px  (IQR {q1:.2}-{q3:.2})");
    }
}

/// The engine candidate with `batch` chunks per kernel call (inputs prepared and the
/// register file allocated beforehand, as a draw would keep them).
fn engine<'a>(p: &'a Prepared, prog: &'a Program, batch: usize, name: &str) -> Candidate<'a> {
    let scratch = RefCell::new(Scratch::default());
    (
        format!("engine {name} batch {batch}"),
        Box::new(move |fb| run_prepared(p, prog, fb, batch, &mut scratch.borrow_mut())),
    )
}

#[test]
#[ignore = "a measurement, not a test: run alone with --ignored --nocapture"]
fn prototype_measurements() {
    let isa = crate::cpu::isa();
    assert!(
        isa == Isa::Avx2Fma,
        "the measurement compares AVX2+FMA code"
    );
    let c = Case::new(5, 256, 64, true);
    let tx: Vec<TexLanes> = c
        .texels
        .iter()
        .map(|tex| {
            let mut t: TexLanes = Default::default();
            for i in 0..LANES {
                t[0][i] = tex[i].map(|b| b as f32 * crate::texture::sample::INV_255);
            }
            t
        })
        .collect();
    let prepared = c.prepared();
    for full in [false, true] {
        let plan = state(full, true, true);
        let ir = lower_textured(&TexturedState { plan, persp: true }).expect("lowered");
        let p = compile_for(&ir, Isa::Avx2Fma);
        // The portable kernels, fused like the AVX2+FMA reference (compiled with FMA).
        let pb = compile_for(&ir, Isa::Fma);
        let mut cands: Vec<Candidate<'_>> = vec![];
        if !full {
            // SAFETY: AVX2 and FMA (asserted); the plan has no alpha test.
            cands.push((
                "today: AVX2 fast path".into(),
                Box::new(|fb| unsafe { hand(&c, &plan, fb) }),
            ));
        }
        let plan_ref = &plan;
        let prep_ref = &prepared;
        // SAFETY: AVX2 and FMA (asserted); the case's lanes lie in its buffers.
        cands.push((
            "JIT ceiling: straight-line AVX2".into(),
            Box::new(move |fb| unsafe { ideal(prep_ref, plan_ref, fb) }),
        ));
        // SAFETY: AVX2 and FMA (asserted).
        cands.push((
            "today: general path".into(),
            Box::new(|fb| unsafe { general(&c, &tx, &plan, fb) }),
        ));
        for batch in [1, 4, 8, 32] {
            cands.push(engine(&prepared, &p, batch, "avx2fma"));
        }
        cands.push(engine(&prepared, &pb, 8, "portable+fma"));
        let title = if full {
            "MODULATE + linear fog + alpha test + depth LESS + over blend"
        } else {
            "MODULATE + depth LESS + over blend"
        };
        println!(
            "state: {} IR ops, {} steps, {} slots",
            ir.ops.len(),
            p.len(),
            p.slots()
        );
        race(title, &c, &cands, 41);
    }
    // Compile time: lowering plus compiling, per state, over states that differ in blend
    // factors (as gl-1.0-blend-func cycles them) and fog/alpha.
    let mut times = Vec::new();
    let factors = [
        crate::pipe::BlendFactor::Zero,
        crate::pipe::BlendFactor::One,
        crate::pipe::BlendFactor::SrcAlpha,
        crate::pipe::BlendFactor::OneMinusSrcAlpha,
        crate::pipe::BlendFactor::DstColor,
    ];
    let mut sink = 0;
    for round in 0..2000 {
        let mut plan = state(round % 2 == 0, true, true);
        if let Some(b) = plan.blend.as_mut() {
            b.src_rgb = factors[round % 5];
            b.dst_rgb = factors[(round / 5) % 5];
        }
        let t0 = Instant::now();
        let ir = lower_textured(&TexturedState { plan, persp: true }).expect("lowered");
        let p = compile_for(&ir, Isa::Avx2Fma);
        times.push(t0.elapsed().as_nanos() as f64);
        sink += p.len();
    }
    println!(
        "lower + compile one state: median {:.2} us ({} steps summed)",
        median(&mut times) / 1000.0,
        sink
    );
}
