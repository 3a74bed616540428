//! The row walk of a one-pass 4x multisample triangle draw ([`crate::fragment::MsPass`]):
//! each pixel's coverage by the four sample points, then the shader of
//! [`crate::fragment::multisample`] once per chunk of pixels where any sample is covered.
//!
//! The triangle comes from [`crate::geometry::setup::setup_triangle_samples`]: its edges
//! are those of test point (0, 0) and its box the union of the samples' boxes. Sample s's
//! edges ([`Edge::at_sample`]) are exactly those a per-sample set-up makes, and each row's
//! covered pixels come from them through the same [`crate::geometry::setup::row_span`]
//! as a single-sample walk, so the coverage of every sample is what the rasterizer of a
//! pass of that sample finds. Rows go in pairs ([`super::row_pairs`], the walk the
//! single-sample quad walks take) and chunks start at even columns, so that a
//! 2x2 quad (aligned to even coordinates) is sampled whole, with its level of detail
//! from its own texture coordinates (evaluated on the planes for every pixel, covered or
//! not): a quad gets the same texels as in a pass that covers any of its pixels.

use super::row_pairs::RowPairs;
use super::textured::Chunk;
use super::{sample_chunk, Draw};
#[cfg(target_arch = "x86_64")]
use crate::fragment::multisample::{colors8_ok, shade_chunk_ms8};
use crate::fragment::multisample::{shade_chunk_ms, SAMPLES};
#[cfg(target_arch = "x86_64")]
use crate::fragment::simd_gen::GenPlan;
use crate::fragment::span::{ChunkColors, Madd, TexLanes, LANES};
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::setup::{Edge, SetupTriangle};
use crate::pipe::MAX_TEXTURE_UNITS;
use crate::stats::Stats;
use crate::texture::UnitPlan;
use crate::tuning::MsPrefetch;

/// Pixels ahead in the same rows that [`MsPrefetch::Ahead`] asks for.
const AHEAD: i64 = 64;

use super::variants::{with_flags, Walks};

/// Rasterizes `t` (set up for every sample) in box `b` with the walks of level `W`.
///
/// # Safety
/// `W`'s instruction set is the CPU's ([`Walks`]).
#[inline(always)]
pub(super) unsafe fn triangle<W: Walks>(t: &SetupTriangle, b: [i64; 4], d: &mut Draw<'_, '_>) {
    let (plan, units, fb, stats) = (d.plan, d.units, &mut *d.fb, &mut *d.stats);
    let depth = plan.depth.is_some();
    // As the single-sample walks: flat colours need no divide unless something else
    // interpolated does (fog, texture coordinates).
    let persp =
        t.persp && (!units.is_empty() || !plan.flat || plan.fog.is_some() || plan.smooth.is_some());
    with_flags!((depth, plan.flat, persp), |D, F, P| {
        // SAFETY: forwarded from the caller.
        unsafe { W::multisample::<D, F, P>(t, b, plan, units, fb, stats) }
    })
}

/// The walk of [`triangle`]'s variant (8-bit or wide target).
#[inline(always)]
pub(crate) fn rows<
    M: Madd,
    const AVX2: bool,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
>(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    if crate::fragment::span::float_store(plan, fb) {
        rows_wide::<M, DEPTH, FLAT, PERSP>(t, b, plan, units, fb, stats)
    } else {
        rows_as::<M, AVX2, DEPTH, FLAT, PERSP, false>(t, b, plan, units, fb, stats)
    }
}

/// [`rows`] into a wide target, out of line as the single-sample wide shader.
#[inline(never)]
fn rows_wide<M: Madd, const DEPTH: bool, const FLAT: bool, const PERSP: bool>(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    rows_as::<M, false, DEPTH, FLAT, PERSP, true>(t, b, plan, units, fb, stats)
}

/// [`rows`]' body.
#[inline(always)]
fn rows_as<
    M: Madd,
    const AVX2: bool,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
    const WIDE: bool,
>(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    let edges = sample_edges(t);
    // Texel values of the current chunk (lanes of quads not sampled keep stale values,
    // never used), as in the textured walk.
    let mut texels: [TexLanes; 2] = [[[[0.0; 4]; LANES]; MAX_TEXTURE_UNITS]; 2];
    let prefetch = crate::tuning::tuning().ms_prefetch;
    #[cfg(target_arch = "x86_64")]
    let (fast, g) = (
        AVX2 && !WIDE && colors8_ok(plan, fb, !units.is_empty()),
        GenPlan::new(plan, t, units),
    );
    for pair in RowPairs::new(&edges, b, !1) {
        let (qy, spans) = (pair.qy, pair.spans);
        let (lo, hi) = (pair.lo, pair.hi);
        let mut x = lo & !1;
        while x <= hi {
            // Each plane's line holding the chunk's last pixel, in the next pair of rows
            // (or further along these): eight planes' rows are more streams than the
            // hardware prefetcher follows, and the walk's loads of the planes waited on
            // the cache.
            match prefetch {
                MsPrefetch::Off => {}
                MsPrefetch::Below => prefetch_planes(fb, qy + 2, x + LANES as i64 - 1, DEPTH),
                MsPrefetch::Ahead => prefetch_planes(fb, qy, x + AHEAD + LANES as i64 - 1, DEPTH),
            }
            let (chunk, cov, any) = chunk_at(&spans, qy, x);
            #[cfg(target_arch = "x86_64")]
            if fast {
                // SAFETY: `AVX2` walks are compiled with AVX2, and with FMA exactly when
                // `M` fuses; `g` is this triangle's; the covered lanes lie in the rows.
                unsafe {
                    if M::FUSED {
                        fast_chunk::<M, true, DEPTH, FLAT, PERSP>(
                            t,
                            plan,
                            &g,
                            units,
                            fb,
                            &chunk,
                            &cov,
                            &mut texels,
                            stats,
                        );
                    } else {
                        fast_chunk::<M, false, DEPTH, FLAT, PERSP>(
                            t,
                            plan,
                            &g,
                            units,
                            fb,
                            &chunk,
                            &cov,
                            &mut texels,
                            stats,
                        );
                    }
                }
                x += LANES as i64;
                continue;
            }
            if !units.is_empty() {
                sample_chunk::<M, PERSP, true>(t, units, &chunk, &mut texels);
            }
            for r in 0..2 {
                if any[r] == 0 {
                    continue;
                }
                let colors = if units.is_empty() {
                    ChunkColors::Shaded
                } else {
                    ChunkColors::Textured(&texels[r])
                };
                let (y, xu) = ((qy + r as i64) as usize, x as usize);
                shade_chunk_ms::<M, AVX2, DEPTH, FLAT, PERSP, WIDE>(
                    t, plan, units, colors, fb, y, xu, &cov[r], stats,
                );
            }
            x += LANES as i64;
        }
    }
}

/// The chunk of 8 pixels from `x` in rows `qy` and `qy + 1` whose samples' covered
/// pixels are `spans`, its coordinates at the pixel centres (where the walk evaluates
/// attributes and texture coordinates); with each row's coverage (bit i of `cov[r][s]`:
/// sample s of pixel x + i of row r is covered) and its union over the samples.
#[inline(always)]
#[allow(clippy::type_complexity)]
fn chunk_at(
    spans: &[[Option<(i64, i64)>; SAMPLES]; 2],
    qy: i64,
    x: i64,
) -> (Chunk, [[u8; SAMPLES]; 2], [u8; 2]) {
    let mut cov = [[0u8; SAMPLES]; 2];
    let mut any = [0u8; 2];
    for r in 0..2 {
        for s in 0..SAMPLES {
            if let Some((a, z)) = spans[r][s] {
                cov[r][s] = lane_bits(a - x, z - x);
                any[r] |= cov[r][s];
            }
        }
    }
    let live: [[bool; LANES]; 2] =
        std::array::from_fn(|r| std::array::from_fn(|i| any[r] & (1 << i) != 0));
    let xf = x as f32;
    let chunk = Chunk {
        qy,
        x,
        fx: std::array::from_fn(|i| (xf + i as f32) + 0.5),
        fy: [qy as f32 + 0.5, (qy + 1) as f32 + 0.5],
        live,
    };
    (chunk, cov, any)
}

/// Each sample's edges of `t` (set up for every sample).
#[inline(always)]
pub(super) fn sample_edges(t: &SetupTriangle) -> [[Edge; 3]; SAMPLES] {
    std::array::from_fn(|s| t.edges.map(|e| e.at_sample(s)))
}

/// The chunks of a triangle set up for every sample ([`sample_edges`]) in a box, as the
/// walk of [`rows`] visits them ([`chunk_at`]: the pixel centres, and the coverage per
/// sample), for a fragment shader's walk (`super::shaded`). An iterator rather than a
/// closure walker, as [`super::textured::Chunks`].
pub(super) struct MsChunks<'e> {
    pairs: RowPairs<'e, SAMPLES>,
    spans: [[Option<(i64, i64)>; SAMPLES]; 2],
    qy: i64,
    x: i64,
    hi: i64,
}

impl<'e> MsChunks<'e> {
    /// The chunks covered by `edges` in `b`.
    #[inline(always)]
    pub fn new(edges: &'e [[Edge; 3]; SAMPLES], b: [i64; 4]) -> Self {
        MsChunks {
            pairs: RowPairs::new(edges, b, !1),
            spans: [[None; SAMPLES]; 2],
            qy: 0,
            x: 0,
            hi: -1,
        }
    }
}

impl Iterator for MsChunks<'_> {
    type Item = (Chunk, [[u8; SAMPLES]; 2]);

    #[inline(always)]
    fn next(&mut self) -> Option<Self::Item> {
        if self.x > self.hi {
            let p = self.pairs.next()?;
            (self.spans, self.qy, self.x, self.hi) = (p.spans, p.qy, p.lo & !1, p.hi);
        }
        let x = self.x;
        self.x += LANES as i64;
        let (chunk, cov, _) = chunk_at(&self.spans, self.qy, x);
        Some((chunk, cov))
    }
}

/// The lanes `i` (0..[`LANES`]) with `lo <= i <= hi`, as bits.
#[inline(always)]
fn lane_bits(lo: i64, hi: i64) -> u8 {
    let (lo, hi) = (lo.max(0), hi.min(LANES as i64 - 1));
    if lo > hi {
        return 0;
    }
    // Bits lo..=hi of a byte (hi < 8, so the shift stays below 9).
    (((1u32 << (hi + 1)) - (1u32 << lo)) & 0xFF) as u8
}

/// The chunk `c` (sample coverage `cov` per row) of a plan [`colors8_ok`] accepts:
/// every unit's coordinates and texels on 8 lanes as the single-sample general walk
/// takes them ([`super::textured::coords_and_sample`]), then each row through
/// [`shade_chunk_ms8`].
///
/// # Safety
/// AVX2 context (FMA exactly when `FMA`); `g` made from this plan, triangle and units;
/// the covered lanes lie inside the target.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
#[allow(clippy::too_many_arguments)]
unsafe fn fast_chunk<
    M: Madd,
    const FMA: bool,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
>(
    t: &SetupTriangle,
    plan: &FragPlan,
    g: &GenPlan,
    units: &[UnitPlan<'_>],
    fb: &mut Target<'_>,
    c: &Chunk,
    cov: &[[u8; SAMPLES]; 2],
    texels: &mut [TexLanes; 2],
    stats: &mut Stats,
) {
    // SAFETY: forwarded from the caller.
    unsafe {
        let oow = super::textured::coords_and_sample::<M, FMA, PERSP, true>(t, units, c, texels);
        for r in 0..2 {
            if cov[r].iter().all(|&m| m == 0) {
                continue;
            }
            let (y, x) = ((c.qy + r as i64) as usize, c.x as usize);
            shade_chunk_ms8::<FMA, DEPTH, FLAT, PERSP>(
                t,
                plan,
                g,
                units,
                &texels[r],
                fb,
                (y, x),
                &cov[r],
                oow[r],
                stats,
            );
        }
    }
}

/// Asks for the colour (and with `depth` the depth) line holding pixel `x` of rows `py`
/// and `py + 1` in every sample plane, for the rows that lie in the band.
#[inline(always)]
fn prefetch_planes(fb: &Target<'_>, py: i64, x: i64, depth: bool) {
    let (y0, y1) = (fb.y0 as i64, (fb.y0 + fb.rows) as i64);
    if x < 0 || x >= fb.width as i64 {
        return;
    }
    for y in py..py + 2 {
        if y < y0 || y >= y1 {
            continue;
        }
        let i = (y - y0) as usize * fb.width + x as usize;
        // Wrapping addresses inside the band's rows; a prefetch never faults.
        crate::simd::prefetch(fb.color.as_ptr().wrapping_add(i));
        for p in &fb.samples {
            crate::simd::prefetch(p.color.as_ptr().wrapping_add(i));
        }
        if depth {
            crate::simd::prefetch(fb.depth.as_ptr().wrapping_add(i));
            for p in &fb.samples {
                crate::simd::prefetch(p.depth.as_ptr().wrapping_add(i));
            }
        }
    }
}
