//! Untextured lines and points: the covered span of each row of the primitive, gathered
//! into a [`RowSpans`] and shaded in one call of the level's walk instead of one
//! dispatch per span.
//!
//! On the AVX2 levels, a plan the AVX2 span shader covers ([`super::simd_ok`]) takes
//! that shader as triangles do: a pair of rows whose covered pixels all lie within
//! [`NARROW`] columns (most rows of a steep line, and small points) is one 4x2 block
//! ([`crate::fragment::simd::shade_pair`]), other rows are spans
//! ([`crate::fragment::simd::shade_span`]). A plan it leaves that the 8-lane fragment
//! shader covers (the alpha test, fog, stencil, the colour sum …;
//! [`super::textured::general_ok`]) goes through that shader 8 pixels of a span at a time,
//! as untextured triangles do ([`super::untextured::spans8`]). Every other plan, and
//! every plan on the levels without AVX2, takes the general span shader
//! ([`crate::fragment::span::shade_span`]) row by row. The pixels a primitive covers are
//! the caller's; each is shaded once, with what the span shaders give it.

#[cfg(target_arch = "x86_64")]
use super::variants::with_simd_variant;
use super::variants::{with_flags, Walks};
use super::Draw;
use crate::cpu::Isa;
use crate::fragment::span::{shade_span, Madd, Span};
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::setup::SetupTriangle;
use crate::stats::Stats;

/// Rows one [`RowSpans`] holds (even, so that row pairs stay pairs across batches).
pub const ROWS: usize = 64;

/// The covered spans of consecutive rows: row `y0 + i` covers pixels `lo[i]..=hi[i]`
/// (nothing when `lo[i] > hi[i]`), for `i < n`.
pub struct RowSpans {
    /// The first row.
    pub y0: i64,
    /// The number of rows held.
    pub n: usize,
    /// Each row's first covered pixel.
    pub lo: [i64; ROWS],
    /// Each row's last covered pixel.
    pub hi: [i64; ROWS],
}

impl RowSpans {
    /// No rows, the first to come being `y0`.
    #[inline(always)]
    pub fn new(y0: i64) -> Self {
        RowSpans {
            y0,
            n: 0,
            lo: [0; ROWS],
            hi: [-1; ROWS],
        }
    }
}

/// Shades the spans `span(py)` gives for the rows `y0..=y1` (an inclusive range of
/// pixels, `lo > hi` for none; inside the region and the target), `ROWS` rows per call.
#[inline(always)]
pub fn shade_rows(
    t: &SetupTriangle,
    y0: i64,
    y1: i64,
    mut span: impl FnMut(i64) -> (i64, i64),
    d: &mut Draw<'_, '_>,
) {
    let mut rs = RowSpans::new(y0);
    for py in y0..=y1 {
        let (lo, hi) = span(py);
        rs.lo[rs.n] = lo;
        rs.hi[rs.n] = hi;
        rs.n += 1;
        if rs.n == ROWS || py == y1 {
            shade(t, &rs, d);
            rs = RowSpans::new(py + 1);
        }
    }
}

/// Shades the rows of `rs` with the planes of `t` through the level's walk for the plan.
pub fn shade(t: &SetupTriangle, rs: &RowSpans, d: &mut Draw<'_, '_>) {
    // SAFETY: (all) `cpu::isa` and `cpu::avx512` only report features the CPU has, and
    // each arm runs that level's walks.
    unsafe {
        #[cfg(all(test, target_arch = "x86_64"))]
        if tests::GENERAL_ONLY.with(|g| g.get()) {
            return match crate::cpu::isa() {
                #[cfg(target_arch = "x86_64")]
                Isa::Avx2Fma | Isa::Fma => general::<super::variants::Fma>(t, rs, d),
                _ => general::<super::variants::Base>(t, rs, d),
            };
        }
        match crate::cpu::isa() {
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2Fma if super::simd_ok(d) => simd::<super::variants::Avx2Fma>(t, rs, d),
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2Fma => general::<super::variants::Avx2Fma>(t, rs, d),
            #[cfg(target_arch = "x86_64")]
            Isa::Fma => general::<super::variants::Fma>(t, rs, d),
            _ => general::<super::variants::Base>(t, rs, d),
        }
    }
}

/// `W`'s general walk for the plan.
///
/// # Safety
/// `W`'s instruction set is the CPU's ([`Walks`]).
#[inline(always)]
unsafe fn general<W: Walks>(t: &SetupTriangle, rs: &RowSpans, d: &mut Draw<'_, '_>) {
    let (plan, fb, stats) = (d.plan, &mut *d.fb, &mut *d.stats);
    // Flat shading keeps the perspective divide for the fog coordinate.
    let persp = t.persp && (!plan.flat || plan.fog.is_some());
    with_flags!((plan.depth.is_some(), plan.flat, persp), |D, F, P| {
        // SAFETY: forwarded from the caller.
        unsafe { W::spans::<D, F, P>(t, rs, plan, fb, stats) }
    })
}

/// `W`'s AVX2 span shader walk for the plan (depth function, blend, flat / smooth /
/// perspective), as [`super::rows_simd`] picks it for triangles.
///
/// # Safety
/// `W`'s instruction set is the CPU's, and [`super::simd_ok`] holds.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn simd<W: super::variants::SimdWalks>(
    t: &SetupTriangle,
    rs: &RowSpans,
    d: &mut Draw<'_, '_>,
) {
    let (plan, fb, stats) = (d.plan, &mut *d.fb, &mut *d.stats);
    with_simd_variant!((plan, t.persp), |D, F, P, B| {
        // SAFETY: forwarded from the caller.
        unsafe { W::simd_spans::<D, F, P, B>(t, rs, plan, fb, stats) }
    })
}

/// The general walk's body: on an AVX2 level whose plan [`super::textured::general_ok`]
/// accepts (the alpha test, fog, stencil, the colour sum … which the AVX2 span shader
/// leaves), each row's span 8 pixels at a time through the 8-lane fragment shader, as
/// untextured triangles ([`super::untextured::spans8`]); else each row's span through
/// the general span shader. Both give the same bytes and counts.
#[inline(always)]
pub(super) fn rows<
    M: Madd,
    const AVX2: bool,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
>(
    t: &SetupTriangle,
    rs: &RowSpans,
    plan: &FragPlan,
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    // `AVX2` is a constant: the other levels' copies do not contain the 8-wide code.
    #[cfg(target_arch = "x86_64")]
    if AVX2 && rs.n > 0 && super::textured::general_ok(plan, fb) {
        let span = |py: i64| {
            let i = (py - rs.y0) as usize;
            (rs.lo[i] <= rs.hi[i]).then_some((rs.lo[i], rs.hi[i]))
        };
        let rows = (rs.y0, rs.y0 + rs.n as i64 - 1);
        // SAFETY: `general_ok` checked AVX2; this level's copy is compiled with FMA exactly
        // when `M::FUSED`; the caller's spans lie inside the target.
        unsafe {
            super::variants::with_fused!(M, |FMA| super::untextured::spans8::<
                FMA,
                DEPTH,
                FLAT,
                PERSP,
            >(t, rows, span, plan, fb, stats))
        }
        return;
    }
    for i in 0..rs.n {
        if rs.lo[i] <= rs.hi[i] {
            let s = Span::of(rs.y0 + i as i64, rs.lo[i], rs.hi[i]);
            shade_span::<M, DEPTH, FLAT, PERSP, true>(t, plan, fb, s, stats);
        }
    }
}

/// The AVX2 walk's body: pairs of rows as 4x2 blocks where they fit, else spans.
///
/// # Safety
/// Must be called from a function compiled with AVX2 (and FMA when `FMA`), for a plan
/// [`super::simd_ok`] accepts and whose depth and blend codes are `D` and `B`; the spans
/// lie inside the target.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) unsafe fn rows_simd<
    const FMA: bool,
    const D: u8,
    const FLAT: bool,
    const PERSP: bool,
    const B: u8,
>(
    t: &SetupTriangle,
    rs: &RowSpans,
    plan: &FragPlan,
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    use crate::fragment::simd::{shade_pair, shade_span};
    use crate::geometry::setup::NARROW;
    let blocks = super::narrow_blocks();
    let mut i = 0;
    while i < rs.n {
        let py = rs.y0 + i as i64;
        let (a0, z0) = (rs.lo[i], rs.hi[i]);
        let (a1, z1) = if i + 1 < rs.n {
            (rs.lo[i + 1], rs.hi[i + 1])
        } else {
            (0, -1)
        };
        let (e0, e1) = (a0 > z0, a1 > z1);
        let lo = if e0 {
            a1
        } else if e1 {
            a0
        } else {
            a0.min(a1)
        };
        let hi = if e0 {
            z1
        } else if e1 {
            z0
        } else {
            z0.max(z1)
        };
        if blocks && !(e0 && e1) && hi - lo < NARROW {
            // Bits 0–3: row `py` from column `lo`; bits 4–7: row `py + 1`.
            let bits = |a: i64, z: i64, e: bool| -> u32 {
                if e {
                    0
                } else {
                    ((1u32 << (z - a + 1)) - 1) << (a - lo)
                }
            };
            let mask = bits(a0, z0, e0) | bits(a1, z1, e1) << NARROW;
            // SAFETY: forwarded from the caller; the pixels of `mask` are the spans'.
            unsafe {
                shade_pair::<FMA, D, FLAT, PERSP, B>(
                    t,
                    plan,
                    fb,
                    py as usize,
                    lo as usize,
                    mask,
                    stats,
                )
            }
        } else {
            for (r, (a, z, e)) in [(a0, z0, e0), (a1, z1, e1)].into_iter().enumerate() {
                if !e {
                    let s = Span::of(py + r as i64, a, z);
                    // SAFETY: forwarded from the caller.
                    unsafe { shade_span::<FMA, D, FLAT, PERSP, B>(t, plan, fb, s, stats) }
                }
            }
        }
        i += 2;
    }
}

#[cfg(all(test, target_arch = "x86_64"))]
mod tests {
    use super::*;
    use crate::framebuffer::{ColorFormat, DepthFormat, Framebuffer};
    use crate::geometry::ClipVertex;
    use std::cell::Cell;

    thread_local! {
        /// Set by a test on its own thread: every plan takes the general span shader.
        pub(super) static GENERAL_ONLY: Cell<bool> = const { Cell::new(false) };
    }

    /// Draws the segments `lines` (width, ends) and the points `points` (size, vertex)
    /// into a framebuffer prefilled with pseudo-random colour and depth, through the
    /// general span shader only when `general`; returns the colour, depth and counters.
    fn draw(
        plan: &FragPlan,
        lines: &[(f32, ClipVertex, ClipVertex)],
        points: &[(f32, ClipVertex)],
        general: bool,
    ) -> (Vec<[u8; 4]>, Vec<u32>, Stats) {
        let (w, h) = (41, 35);
        let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba, DepthFormat::Z24, false);
        let mut next = crate::test_rng::xorshift32(91);
        for (c, d) in fb.color.iter_mut().zip(fb.depth.iter_mut()) {
            *c = next().to_le_bytes();
            *d = next() & 0xFF_FFFF;
        }
        GENERAL_ONLY.with(|g| g.set(general));
        let mut stats = Stats::default();
        {
            let mut target = fb.target();
            let region = [0, 0, w as i64, h as i64];
            let mut d = Draw::new(region, plan, &[], &mut target, &mut stats);
            for (width, a, b) in lines {
                super::super::lines::raster_line(a, b, &b.vary, (*width, false), 4, &mut d);
            }
            for (size, v) in points {
                let coords = Default::default();
                super::super::lines::raster_point(v, *size, &coords, false, 4, &mut d);
            }
        }
        GENERAL_ONLY.with(|g| g.set(false));
        (fb.color.to_vec(), fb.depth.to_vec(), stats)
    }

    /// Lines and points through the AVX2 span shader (4x2 blocks and spans) give the
    /// general span shader's bytes and counts (but the blend reads').
    #[test]
    fn simd_rows_match_general_byte_for_byte() {
        assert_rounds_match_general(0x4c49_4e45, super::super::tests::plan_of_round);
    }

    /// Lines and points whose plans the AVX2 span shader leaves (the alpha test of every
    /// function, fog of every mode, the colour sum) through the 8-lane fragment shader
    /// give the general span shader's bytes and counts (but the blend reads').
    #[test]
    fn gen_rows_match_general_byte_for_byte() {
        use crate::fixed_function::fog::FogPlan;
        use crate::pipe::lighting::FogMode;
        use crate::pipe::CompareFunc;
        assert_rounds_match_general(0x4745_4e52, |round| {
            let mut plan = super::super::tests::plan_of_round(round);
            let funcs = CompareFunc::ALL;
            plan.alpha = (round % 3 != 2).then_some((funcs[round % 8], (round * 37 % 256) as u8));
            plan.fog = (round % 3 != 0).then_some(FogPlan {
                mode: [FogMode::Linear, FogMode::Exp, FogMode::Exp2][round / 3 % 3],
                scale: -1.0 / 0.8,
                bias: 0.9 / 0.8,
                exp_k: 1.3 / std::f32::consts::LN_2,
                exp2_k: 1.3 / std::f32::consts::LN_2.sqrt(),
                color: [0.2, 0.5, 0.9],
                fma: plan.fma,
            });
            plan.separate_specular = round % 5 == 1;
            // The 8-lane shader takes these plans (else both sides would be per-lane).
            let mut fb = Framebuffer::new(1, 1, ColorFormat::Rgba, DepthFormat::Z24, false);
            assert!(super::super::textured::general_ok(&plan, &fb.target()));
            plan
        });
    }

    /// Draws 40 lines and 40 points of random widths, sizes and vertices (all varyings
    /// random, the fog coordinate among them) with `plan_of(round)` for 64 rounds, through
    /// the level's walks and through the general span shader only; asserts the same
    /// colour, depth and counters (but the blend reads).
    fn assert_rounds_match_general(seed: u32, plan_of: impl Fn(usize) -> FragPlan) {
        if !crate::cpu::isa().avx2() {
            return;
        }
        let mut next = crate::test_rng::xorshift32(seed);
        let mut unit = move || next() as f32 / u32::MAX as f32;
        for round in 0..64 {
            let plan = plan_of(round);
            let persp = round % 2 == 0;
            let mut vertex = || {
                let mut p = ClipVertex {
                    win: [
                        unit() * 47.0 - 3.0,
                        unit() * 41.0 - 3.0,
                        unit(),
                        if persp { 0.2 + unit() } else { 1.0 },
                    ],
                    ..ClipVertex::default()
                };
                for i in 0..=crate::geometry::VARY_FOG {
                    p.vary[i] = unit() * 1.2 - 0.1;
                }
                p
            };
            let lines: Vec<_> = (0..40)
                .map(|k| (1.0 + (k % 4) as f32 * 1.3, vertex(), vertex()))
                .collect();
            let points: Vec<_> = (0..40).map(|k| (1.0 + (k % 7) as f32, vertex())).collect();
            let general = draw(&plan, &lines, &points, true);
            let simd = draw(&plan, &lines, &points, false);
            assert!(general.0 == simd.0, "colour differs in round {round}");
            assert!(general.1 == simd.1, "depth differs in round {round}");
            // Blend reads are counted per shader: the general one counts a chunk's lanes
            // inside the row, the AVX2 one the span's pixels (as for triangles).
            let (mut g, mut v) = (general.2, simd.2);
            (g.color_reads, v.color_reads) = (0, 0);
            assert_eq!(g, v, "counters differ in round {round}");
            assert!(general.2.fragments > 0);
        }
    }
}
