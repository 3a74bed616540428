//! Triangle setup of eight triangles at a time: the snapping, culling, edge functions and
//! plane equations of [`super::setup`], computed lane by lane over a queue of triangles.
//!
//! Per triangle, setup is a chain of data-dependent branches (degenerate? culled? does
//! the box hold a pixel centre?) and short arithmetic; a draw of 200k one-pixel triangles
//! spent 40% of its single-threaded frame there. Here the decisions become lane masks and
//! the arithmetic runs in AVX2 vectors over eight queued triangles; the scalar part that
//! remains per triangle only copies a drawn triangle's values out. Every value is the
//! scalar setup's, bit for bit: the same i64 and f32 operations in the same order (Rust
//! never fuses a multiply and an add), and the test below compares the two on random
//! triangles. A lane whose coordinates are too large for the 32-bit lanes (beyond 2^21
//! pixels, which the clipper keeps unclipped triangles far inside) is set up by the scalar
//! code instead.

use super::setup::{setup_triangle_shaded, CullMode, Edge, Plane, SetupResult, SetupTriangle};
use super::ClipVertex;

/// Triangles set up together.
pub const LANES: usize = 8;
/// Varyings per vertex the queue holds (the two colours); draws with texture coordinates
/// set triangles up one by one. Only colour-only draws (small_tris_200k) were measured to
/// gain; with textures the set-up triangles are few and the fragments many.
pub const QUEUE_VARY: usize = 8;

/// Window coordinates below this (in magnitude) snap to values that fit the lanes' i32.
#[cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]
const FAST_LIMIT: f32 = (1u32 << 21) as f32;
/// Snapped sub-pixel units per pixel.
#[cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]
const ONE: i32 = 1 << super::setup::SUBPIXEL_BITS;

/// A lane's outcome.
#[derive(Clone, Copy, PartialEq, Eq, Debug, Default)]
enum Class {
    Draw,
    Degenerate,
    Culled,
    #[default]
    Empty,
    /// Set up by the scalar code (coordinates beyond [`FAST_LIMIT`] or not finite).
    Scalar,
}

/// Up to [`LANES`] triangles waiting for setup, their vertices' window positions and
/// varyings stored lane by lane, and the lanes' results.
pub struct SetupQueue {
    /// Triangles queued.
    n: usize,
    /// Varyings per vertex (at most [`QUEUE_VARY`]).
    nvary: usize,
    /// Varyings copied per vertex: `nvary`, and at least the colour that flat shading's
    /// 8-bit colour reads.
    ncopy: usize,
    /// `win[k][c][l]`: window coordinate `c` (x, y, z, 1/w) of vertex `k` of lane `l`.
    win: [[[f32; LANES]; 4]; 3],
    /// `vary[k][i][l]`: varying `i` of vertex `k` of lane `l`.
    vary: [[[f32; LANES]; QUEUE_VARY]; 3],
    out: Lanes,
}

/// The lanes' results (only a [`Class::Draw`] lane's values are read).
struct Lanes {
    class: [Class; LANES],
    front: [bool; LANES],
    /// Edge `i`'s a, b and c.
    edge: [[[i64; LANES]; 3]; 3],
    bbox: [[i64; LANES]; 4],
    /// z and 1/w planes: a0, dadx, dady.
    z: [[f32; LANES]; 3],
    w: [[f32; LANES]; 3],
    persp: [bool; LANES],
    /// Varying planes: a0, dadx, dady.
    vary: [[[f32; LANES]; 3]; QUEUE_VARY],
}

impl SetupQueue {
    /// An empty queue for a draw with `nvary` varyings (at most [`QUEUE_VARY`]).
    pub fn new(nvary: usize) -> Box<Self> {
        Box::new(Self::empty(nvary))
    }

    /// Empties the queue, as [`Self::new`] makes it, for another draw with `nvary`
    /// varyings.
    pub fn reset(&mut self, nvary: usize) {
        *self = Self::empty(nvary);
    }

    /// The empty queue of [`Self::new`].
    fn empty(nvary: usize) -> Self {
        assert!(nvary <= QUEUE_VARY);
        SetupQueue {
            n: 0,
            nvary,
            ncopy: nvary.max(4),
            win: [[[0.0; LANES]; 4]; 3],
            vary: [[[0.0; LANES]; QUEUE_VARY]; 3],
            out: Lanes {
                class: [Class::Empty; LANES],
                front: [false; LANES],
                edge: [[[0; LANES]; 3]; 3],
                bbox: [[0; LANES]; 4],
                z: [[0.0; LANES]; 3],
                w: [[0.0; LANES]; 3],
                persp: [false; LANES],
                vary: [[[0.0; LANES]; 3]; QUEUE_VARY],
            },
        }
    }

    /// Queues triangle `v` (v[2] the provoking vertex); returns whether the queue is full
    /// and must be flushed before the next push.
    #[inline(always)]
    pub fn push(&mut self, v: [&ClipVertex; 3]) -> bool {
        let l = self.n;
        for (k, p) in v.iter().enumerate() {
            for c in 0..4 {
                self.win[k][c][l] = p.win[c];
            }
            for i in 0..self.ncopy {
                self.vary[k][i][l] = p.vary[i];
            }
        }
        self.n += 1;
        self.n == LANES
    }

    /// Sets up the queued triangles in queue order and empties the queue: `out(result,
    /// fill, win)` for each (`win` its vertices' window positions, in queue order), `fill`
    /// holding the set-up triangle when the result is
    /// [`SetupResult::Draw`] (exactly what [`setup_triangle_shaded`] would have made of
    /// it with `cull` and `flat`, and no two-sided colours). `fill` is written as
    /// `setup_triangle_shaded` writes it.
    ///
    /// # Safety
    /// On x86-64 the CPU must have AVX2 and the bit instructions of `cpu::isa`'s AVX2
    /// variants.
    pub unsafe fn flush(
        &mut self,
        cull: CullMode,
        flat: bool,
        fill: &mut SetupTriangle,
        mut out: impl FnMut(SetupResult, &mut SetupTriangle, [[f32; 4]; 3]),
    ) {
        if self.n == 0 {
            return;
        }
        // SAFETY: forwarded from the caller.
        unsafe { self.compute(cull) };
        let nvary = self.nvary;
        for l in 0..self.n {
            let r = match self.out.class[l] {
                Class::Draw => {
                    let o = &self.out;
                    for (i, e) in fill.edges.iter_mut().enumerate() {
                        *e = Edge {
                            a: o.edge[i][0][l],
                            b: o.edge[i][1][l],
                            c: o.edge[i][2][l],
                        };
                    }
                    // Written out: `[0, 1, 2, 3].map(..)` stayed an out-of-line call whose
                    // result came back through the stack, a store-forwarding stall that
                    // cost more than the rest of the copy.
                    fill.bbox = [o.bbox[0][l], o.bbox[1][l], o.bbox[2][l], o.bbox[3][l]];
                    fill.front = o.front[l];
                    let plane = |p: &[[f32; LANES]; 3]| Plane {
                        a0: p[0][l],
                        dadx: p[1][l],
                        dady: p[2][l],
                    };
                    fill.z = plane(&o.z);
                    fill.w = plane(&o.w);
                    fill.persp = o.persp[l];
                    for i in 0..nvary {
                        fill.vary[i] = plane(&o.vary[i]);
                    }
                    if flat {
                        // `ncopy` >= 4: the colour is queued even with fewer varyings.
                        fill.set_flat(nvary, |i| self.vary[2][i][l]);
                    }
                    SetupResult::Draw
                }
                Class::Degenerate => SetupResult::Degenerate,
                Class::Culled => SetupResult::Culled,
                Class::Empty => SetupResult::Empty,
                Class::Scalar => {
                    let v: [ClipVertex; 3] = std::array::from_fn(|k| {
                        let mut p = ClipVertex {
                            win: [
                                self.win[k][0][l],
                                self.win[k][1][l],
                                self.win[k][2][l],
                                self.win[k][3][l],
                            ],
                            ..ClipVertex::default()
                        };
                        for i in 0..self.ncopy {
                            p.vary[i] = self.vary[k][i][l];
                        }
                        p
                    });
                    setup_triangle_shaded([&v[0], &v[1], &v[2]], nvary, cull, None, flat, fill)
                }
            };
            let win = std::array::from_fn(|k| std::array::from_fn(|c| self.win[k][c][l]));
            out(r, fill, win);
        }
        self.n = 0;
    }

    /// The lanes' results into `self.out` (lanes past `n` compute garbage, unread).
    ///
    /// # Safety
    /// As [`Self::flush`].
    #[cfg(target_arch = "x86_64")]
    #[target_feature(enable = "avx2,popcnt,bmi1,bmi2,lzcnt")]
    unsafe fn compute(&mut self, cull: CullMode) {
        // SAFETY: forwarded from the caller.
        unsafe { lanes_avx2(&self.win, &self.vary, self.nvary, cull, &mut self.out) };
    }

    /// Off x86-64 (where no draw queues triangles: [`SetupQueue`] needs the AVX2 setup)
    /// every lane goes to the scalar setup.
    ///
    /// # Safety
    /// None; `unsafe` as the x86-64 version.
    #[cfg(not(target_arch = "x86_64"))]
    unsafe fn compute(&mut self, _cull: CullMode) {
        self.out.class = [Class::Scalar; LANES];
    }
}

/// The lanes' class from their bit masks (bit `l` for lane `l`).
#[cfg_attr(not(target_arch = "x86_64"), allow(dead_code))]
#[inline(always)]
fn classes(fast: u32, degenerate: u32, culled: u32, empty: u32) -> [Class; LANES] {
    std::array::from_fn(|l| {
        let bit = |m: u32| m >> l & 1 != 0;
        if !bit(fast) {
            Class::Scalar
        } else if bit(degenerate) {
            Class::Degenerate
        } else if bit(culled) {
            Class::Culled
        } else if bit(empty) {
            Class::Empty
        } else {
            Class::Draw
        }
    })
}

/// The setup of every lane (see [`SetupQueue::flush`]) in AVX2 vectors: eight f32 or i32 lanes, or two halves of four i64 lanes for
/// the products (`vpmuldq` of sign-extended i32 values is the exact i64 product).
///
/// # Safety
/// The CPU must have AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn lanes_avx2(
    win: &[[[f32; LANES]; 4]; 3],
    vary: &[[[f32; LANES]; QUEUE_VARY]; 3],
    nvary: usize,
    cull: CullMode,
    o: &mut Lanes,
) {
    use crate::simd::{F32x8, I32x8, I64x4};
    // SAFETY: AVX2 is present (the caller's promise); every load and store is of a
    // `[f32; 8]`, `[i64; 8]` or `[i64; 4]`-sized part of the arrays named, unaligned.
    unsafe {
        let ld = |a: &[f32; LANES]| F32x8::load(a.as_ptr());
        let st = |a: &mut [f32; LANES], v: F32x8| v.store(a.as_mut_ptr());
        // The two halves of eight i32 lanes, sign-extended to i64.
        let wide = |v: I32x8| (v.widen_lo(), v.widen_hi());
        let st64 = |a: &mut [i64; LANES], (lo, hi): (I64x4, I64x4)| {
            lo.store(a.as_mut_ptr());
            hi.store(a.as_mut_ptr().add(4));
        };
        // Lane masks as bits: eight f32/i32 lanes, four i64 lanes.
        let bits32 = |m: I32x8| m.movemask();
        let bits64 = |(lo, hi): (I64x4, I64x4)| lo.movemask() | hi.movemask() << 4;
        // A bit mask back as eight i32 lanes of all ones or zero.
        let lanes_of = |m: u32| {
            let b = I32x8::new([1, 2, 4, 8, 16, 32, 64, 128]);
            I32x8::splat(m as i32).and(b).cmpeq(b)
        };

        let x = [0, 1, 2].map(|k| ld(&win[k][0]));
        let y = [0, 1, 2].map(|k| ld(&win[k][1]));
        // Lanes whose six coordinates are below FAST_LIMIT in magnitude (NaN is not).
        let abs = I32x8::splat(0x7FFF_FFFF).as_f32();
        let lim = F32x8::splat(FAST_LIMIT);
        let mut fastv = I32x8::splat(-1).as_f32();
        for v in x.iter().chain(&y) {
            fastv = fastv.and((*v).and(abs).cmp_lt(lim));
        }
        let fast = fastv.movemask();
        // `snap`: round half to even of (v - 0.5) * 256 (0 in the other lanes), as i32.
        let snap = |v: F32x8| {
            let t = v.sub(F32x8::splat(0.5)).mul(F32x8::splat(256.0));
            let t = t.and(fastv);
            t.round_even().to_i32_trunc()
        };
        let sx = x.map(snap);
        let sy = y.map(snap);
        // |snapped| < 2^30: the differences fit i32 and their products i64.
        let mul64 = |a: (I64x4, I64x4), b: (I64x4, I64x4)| (a.0.mul_i32(b.0), a.1.mul_i32(b.1));
        let sub64 = |a: (I64x4, I64x4), b: (I64x4, I64x4)| (a.0.sub(b.0), a.1.sub(b.1));
        let area = sub64(
            mul64(wide(sx[0].sub(sx[1])), wide(sy[2].sub(sy[0]))),
            mul64(wide(sx[2].sub(sx[0])), wide(sy[0].sub(sy[1]))),
        );
        let z64 = I64x4::zero();
        let degenerate = bits64((area.0.cmpeq(z64), area.1.cmpeq(z64)));
        let ccw = bits64((area.0.cmpgt(z64), area.1.cmpgt(z64)));
        let front = if cull.front_ccw { ccw } else { !ccw & 0xFF };
        let culled =
            (if cull.front { front } else { 0 }) | (if cull.back { !front & 0xFF } else { 0 });
        // Clockwise lanes swap vertices 0 and 1 (setup_rest).
        let ccwv = lanes_of(ccw);
        let ccwf = ccwv.as_f32();
        let pick = |v: [F32x8; 3]| [v[1].blendv(v[0], ccwf), v[0].blendv(v[1], ccwf), v[2]];
        let pick_i = |v: [I32x8; 3]| [v[1].blendv(v[0], ccwv), v[0].blendv(v[1], ccwv), v[2]];
        let xs = pick_i(sx);
        let ys = pick_i(sy);
        let mut edge = [[(z64, z64); 3]; 3];
        for i in 0..3 {
            let j = (i + 1) % 3;
            let a = ys[i].sub(ys[j]);
            let b = xs[i].sub(xs[j]);
            let (aw, bw) = (wide(a), wide(b));
            let c = sub64(mul64(aw, wide(xs[i])), mul64(bw, wide(ys[i])));
            // Left edges (a < 0) and bottom edges (a == 0, b < 0) take +1; by the top-left
            // rule, top edges (a == 0, b > 0) instead.
            let zero = I32x8::zero();
            let horizontal_in = if cull.top_left {
                b.cmpgt(zero)
            } else {
                zero.cmpgt(b)
            };
            let left = zero.cmpgt(a).or(a.cmpeq(zero).and(horizontal_in));
            let c = sub64(c, wide(left));
            edge[i] = [aw, bw, c];
            st64(&mut o.edge[i][0], aw);
            st64(&mut o.edge[i][1], bw);
            st64(&mut o.edge[i][2], c);
        }
        let (min3, max3) = (
            |v: [I32x8; 3]| v[0].min(v[1]).min(v[2]),
            |v: [I32x8; 3]| v[0].max(v[1]).max(v[2]),
        );
        let up = I32x8::splat(ONE - 1);
        let bx0 = min3(xs).add(up).sra::<8>();
        let by0 = min3(ys).add(up).sra::<8>();
        let bx1 = max3(xs).sra::<8>();
        let by1 = max3(ys).sra::<8>();
        for (k, b) in [bx0, by0, bx1, by1].into_iter().enumerate() {
            st64(&mut o.bbox[k], wide(b));
        }
        let no_box = bits32(bx0.cmpgt(bx1).or(by0.cmpgt(by1)));
        // `tiny_box_covered`: a box of at most 2x2 centres must hold one inside all edges.
        let (wx, wy) = (bx1.sub(bx0), by1.sub(by0));
        let one = I32x8::splat(1);
        let big = bits32(wx.cmpgt(one).or(wy.cmpgt(one)));
        let neg = |v: I32x8| I32x8::zero().sub(v);
        let (mx, my) = (wide(neg(wx)), wide(neg(wy)));
        let (bx0w, by0w) = (wide(bx0), wide(by0));
        let mut inside = [(I64x4::splat(-1), I64x4::splat(-1)); 4];
        for e in &edge {
            let [a, b, c] = *e;
            let half = |h: usize| {
                let sel = |v: (I64x4, I64x4)| if h == 0 { v.0 } else { v.1 };
                let (a, b, c) = (sel(a), sel(b), sel(c));
                let v00 = c
                    .sub(a.mul_i32(sel(bx0w)).shl::<8>())
                    .add(b.mul_i32(sel(by0w)).shl::<8>());
                let v10 = v00.sub(a.shl::<8>().and(sel(mx)));
                let dy = b.shl::<8>().and(sel(my));
                [v00, v10, v00.add(dy), v10.add(dy)].map(|v| v.cmpgt(I64x4::zero()))
            };
            let (lo, hi) = (half(0), half(1));
            for k in 0..4 {
                inside[k] = (inside[k].0.and(lo[k]), inside[k].1.and(hi[k]));
            }
        }
        let covered = big | inside.iter().fold(0, |m, v| m | bits64(*v));
        o.class = classes(fast, degenerate, culled, no_box | !covered & 0xFF);
        o.front = std::array::from_fn(|l| front >> l & 1 != 0);

        // Plane equations in f32, Mesa's order (as `setup_rest`), from the unsnapped
        // positions; no fused multiply-add.
        let fx = pick(x);
        let fy = pick(y);
        let half = F32x8::splat(0.5);
        let x0c = fx[0].sub(half);
        let y0c = fy[0].sub(half);
        let dx01 = fx[0].sub(fx[1]);
        let dy01 = fy[0].sub(fy[1]);
        let dx20 = fx[2].sub(fx[0]);
        let dy20 = fy[2].sub(fy[0]);
        let ooa = F32x8::splat(1.0).div(dx01.mul(dy20).sub(dy01.mul(dx20)));
        let dx20o = dx20.mul(ooa);
        let dy20o = dy20.mul(ooa);
        let dx01o = dx01.mul(ooa);
        let dy01o = dy01.mul(ooa);
        let plane = |a: [F32x8; 3], out: &mut [[f32; LANES]; 3]| {
            let da01 = a[0].sub(a[1]);
            let da20 = a[2].sub(a[0]);
            let dadx = da01.mul(dy20o).sub(da20.mul(dy01o));
            let dady = da20.mul(dx01o).sub(da01.mul(dx20o));
            let a0 = a[0].sub(dadx.mul(x0c).add(dady.mul(y0c)));
            st(&mut out[0], a0);
            st(&mut out[1], dadx);
            st(&mut out[2], dady);
        };
        plane(pick([0, 1, 2].map(|k| ld(&win[k][2]))), &mut o.z);
        let w = pick([0, 1, 2].map(|k| ld(&win[k][3])));
        let onev = F32x8::splat(1.0);
        let unit = w[0]
            .cmp_eq(onev)
            .and(w[1].cmp_eq(onev))
            .and(w[2].cmp_eq(onev));
        let unit = unit.movemask();
        o.persp = std::array::from_fn(|l| unit >> l & 1 == 0);
        plane(w, &mut o.w);
        for (i, out) in o.vary.iter_mut().enumerate().take(nvary) {
            // Pre-multiplied by 1/w; when the triangle is not perspective every w is
            // exactly 1.0 and the product is the value itself, as setup's plain path.
            let a = pick([0, 1, 2].map(|k| ld(&vary[k][i])));
            plane([0, 1, 2].map(|k| a[k].mul(w[k])), out);
        }
    }
}

#[cfg(all(test, target_arch = "x86_64"))]
mod tests {
    use super::*;

    /// Bit patterns of a set-up triangle, for exact comparison (NaN included).
    fn bits(t: &SetupTriangle, nvary: usize, flat: bool) -> Vec<u64> {
        let mut v: Vec<u64> = vec![];
        for e in &t.edges {
            v.extend([e.a as u64, e.b as u64, e.c as u64]);
        }
        v.extend(t.bbox.map(|b| b as u64));
        v.extend([t.front as u64, t.persp as u64]);
        let mut planes = vec![t.z, t.w];
        planes.extend_from_slice(&t.vary[..nvary]);
        for p in planes {
            v.extend([p.a0, p.dadx, p.dady].map(|f| f.to_bits() as u64));
        }
        if flat {
            v.extend(t.flat[..nvary].iter().map(|f| f.to_bits() as u64));
            v.extend(t.flat_u8.map(|b| b as u64));
        }
        v
    }

    #[test]
    fn eight_lanes_match_scalar_setup_bit_for_bit() {
        if !crate::cpu::isa().avx2() {
            return;
        }
        let mut next = crate::test_rng::xorshift32(0x5EED_0008);
        let mut unit = move || next() as f32 / u32::MAX as f32;
        const ODD: [f32; 6] = [f32::NAN, f32::INFINITY, -1e7, 3e6, 1.0, 0.5];
        let mut seen = [0usize; 4];
        for round in 0..6000 {
            let nvary = [0, 4, 5, 8][round % 4];
            let flat = round % 3 == 0;
            let cull = CullMode {
                front: round % 5 == 1,
                back: round % 5 == 2,
                front_ccw: round % 2 == 0,
                top_left: round % 7 >= 3,
            };
            // Small triangles around a few centres (many empty or tiny), larger ones, and
            // now and then an odd coordinate or a shared w of 1.
            let scale = [1.5, 6.0, 300.0][round % 3];
            let tris: Vec<[ClipVertex; 3]> = (0..LANES)
                .map(|_| {
                    let (cx, cy) = (unit() * 500.0, unit() * 500.0);
                    let one_w = unit() < 0.3;
                    std::array::from_fn(|_| {
                        let mut p = ClipVertex {
                            win: [
                                cx + unit() * scale,
                                cy + unit() * scale,
                                unit(),
                                if one_w { 1.0 } else { 0.1 + unit() },
                            ],
                            ..ClipVertex::default()
                        };
                        if unit() < 0.02 {
                            p.win[(unit() * 2.0) as usize] = ODD[(unit() * 6.0) as usize % 6];
                        }
                        for i in 0..nvary {
                            p.vary[i] = unit() * 2.0 - 0.5;
                        }
                        p
                    })
                })
                .collect();
            let mut q = SetupQueue::new(nvary);
            for t in &tris {
                q.push([&t[0], &t[1], &t[2]]);
            }
            let mut got = vec![];
            let mut fill = SetupTriangle::default();
            // SAFETY: the CPU has AVX2 (checked above).
            unsafe {
                q.flush(cull, flat, &mut fill, |r, t, win| {
                    let win = win.map(|p| p.map(f32::to_bits));
                    got.push((r, bits(t, nvary, flat), win))
                })
            };
            assert_eq!(got.len(), LANES);
            for (t, (r, b, win)) in tris.iter().zip(&got) {
                // Each triangle's window positions come back with it, in queue order.
                assert_eq!(*win, t.map(|v| v.win.map(f32::to_bits)));
                let mut want = SetupTriangle::default();
                let rw = setup_triangle_shaded(
                    [&t[0], &t[1], &t[2]],
                    nvary,
                    cull,
                    None,
                    flat,
                    &mut want,
                );
                assert_eq!(*r, rw, "{:?}", t.map(|v| v.win));
                if rw == SetupResult::Draw {
                    assert_eq!(*b, bits(&want, nvary, flat), "{:?}", t.map(|v| v.win));
                }
                seen[rw as usize] += 1;
            }
        }
        // Every outcome occurs many times.
        assert!(seen.iter().all(|&n| n > 200), "{seen:?}");
    }
}
