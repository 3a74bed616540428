//! Textured lines, points and stippled polygons: the same fragment pipeline as textured
//! triangles (every enabled unit, colour sum, fog, alpha test …) over a coverage that is
//! not a plain triangle.
//!
//! llvmpipe shades every primitive in 2x2 quads aligned to even pixel coordinates and takes
//! one texture LOD per quad from the TL/TR/BL coordinates; pixels of a quad outside the
//! primitive are helper pixels evaluated on the same planes. A line's planes vary along its
//! major axis only (`lp_setup_line.c`), so its LOD comes from that axis; a point's planes
//! are constant, so points always magnify. The walk here is the triangle path's
//! (`rows_textured`) with the coverage given by a [`Cover`]: on the AVX2 levels each
//! chunk row is shaded on 8 lanes (`textured::chunks_general`, the per-fragment work of
//! `fragment::simd_gen::shade_row`) when the plan allows, else lane by lane (on textured
//! line loops, sweep states 186 and 128, 1.6–1.7x less CPU per frame than the per-lane
//! walk, the sampling unchanged).
// Lane loops index several arrays in step.
#![allow(clippy::needless_range_loop)]

use super::textured::{Chunk, LIVE_MASKS};
use super::variants::{with_flags, Walks};
use super::Draw;
use crate::cpu::Isa;
use crate::fragment::span::{Madd, TexLanes, LANES};
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::setup::{Edge, SetupTriangle};
use crate::pipe::PolygonStipple;
use crate::pipe::MAX_TEXTURE_UNITS;
use crate::stats::Stats;
use crate::texture::UnitPlan;

/// The pixels a primitive covers.
pub trait Cover {
    /// The covered pixels of row `py` (y-down) as an inclusive range, or `None`.
    fn span(&self, py: i64) -> Option<(i64, i64)>;
    /// Which of the covered pixels `x..x + 8` of row `py` survive a per-pixel mask
    /// (polygon stipple), as bits (bit i: pixel `x + i`).
    #[inline(always)]
    fn keep8(&self, _x: i64, _py: i64) -> u32 {
        0xFF
    }
}

/// Coverage of the intersection of integer edge functions (a triangle or a line's
/// parallelogram).
pub struct EdgeCover<'e>(pub &'e [Edge]);

impl Cover for EdgeCover<'_> {
    #[inline(always)]
    fn span(&self, py: i64) -> Option<(i64, i64)> {
        let (mut lo, mut hi) = (i64::MIN, i64::MAX);
        for e in self.0 {
            let (a, z) = e.span(py)?;
            lo = lo.max(a);
            hi = hi.min(z);
        }
        (lo <= hi).then_some((lo, hi))
    }
}

/// A rectangle of whole pixels (the box is the walk's bounds).
pub struct BoxCover;

impl Cover for BoxCover {
    #[inline(always)]
    fn span(&self, _py: i64) -> Option<(i64, i64)> {
        Some((i64::MIN, i64::MAX))
    }
}

/// A triangle's coverage with the polygon stipple applied (`gl_y(py)` is GL's row).
pub struct StippleCover<'e> {
    /// The triangle's edges.
    pub edges: &'e [Edge],
    /// The 32x32 pattern.
    pub stipple: &'e PolygonStipple,
    /// Framebuffer height (to turn y-down rows into GL rows).
    pub height: i64,
    /// Whether rows are y-down (else they are GL rows already).
    pub y_flip: bool,
}

impl Cover for StippleCover<'_> {
    #[inline(always)]
    fn span(&self, py: i64) -> Option<(i64, i64)> {
        EdgeCover(self.edges).span(py)
    }

    #[inline(always)]
    fn keep8(&self, x: i64, py: i64) -> u32 {
        let gl_y = if self.y_flip {
            self.height - 1 - py
        } else {
            py
        };
        self.stipple.passes8(x, gl_y)
    }
}

/// Shades the pixels of `cover` inside the inclusive box `b` (already cut to the region
/// and the target's rows) with the planes of `t`, sampling the units per 2x2 quad.
pub fn shade_covered<C: Cover>(t: &SetupTriangle, b: [i64; 4], cover: &C, d: &mut Draw<'_, '_>) {
    if b[0] > b[2] || b[1] > b[3] {
        return;
    }
    let (plan, units, fb, stats) = (d.plan, d.units, &mut *d.fb, &mut *d.stats);
    // The walks see the chunks through `dyn Iterator` (one indirect call per 8-pixel chunk):
    // one copy of each walk serves every kind of coverage, instead of one per kind.
    let mut chunks = CoverChunks::new(cover, b);
    // Level `$w`'s variant for the plan.
    macro_rules! walk {
        ($w:ty) => {
            with_flags!((plan.depth.is_some(), plan.flat, t.persp), |D, F, P| {
                // SAFETY: `cpu::isa` only reports a variant whose features the CPU has.
                unsafe { <$w as Walks>::covered::<D, F, P>(t, &mut chunks, plan, units, fb, stats) }
            })
        };
    }
    match crate::cpu::isa() {
        #[cfg(target_arch = "x86_64")]
        Isa::Avx2Fma => walk!(super::variants::Avx2Fma),
        #[cfg(target_arch = "x86_64")]
        Isa::Fma => walk!(super::variants::Fma),
        _ => walk!(super::variants::Base),
    }
}

/// The covered range of row `py` inside `b`.
#[inline(always)]
fn row<C: Cover>(cover: &C, b: [i64; 4], py: i64) -> Option<(i64, i64)> {
    if py < b[1] || py > b[3] {
        return None;
    }
    let (lo, hi) = cover.span(py)?;
    let (lo, hi) = (lo.max(b[0]), hi.min(b[2]));
    (lo <= hi).then_some((lo, hi))
}

/// The 8-pixel chunks of 2x2 quads of the pairs of rows that `cover` covers in `b`, as
/// [`super::textured::Chunks`] walks a triangle's (a chunk is visited when a lane of
/// either row survives [`Cover::keep`]).
pub(super) struct CoverChunks<'c, C> {
    cover: &'c C,
    b: [i64; 4],
    qy: i64,
    spans: [Option<(i64, i64)>; 2],
    x: i64,
    hi: i64,
}

impl<'c, C: Cover> CoverChunks<'c, C> {
    /// The chunks of `cover` in `b`.
    #[inline(always)]
    pub(super) fn new(cover: &'c C, b: [i64; 4]) -> Self {
        CoverChunks {
            cover,
            b,
            qy: (b[1] & !1) - 2,
            spans: [None; 2],
            x: 0,
            hi: -1,
        }
    }
}

impl<C: Cover> Iterator for CoverChunks<'_, C> {
    type Item = Chunk;

    #[inline(always)]
    fn next(&mut self) -> Option<Chunk> {
        loop {
            while self.x > self.hi {
                self.qy += 2;
                if self.qy > self.b[3] {
                    return None;
                }
                let (cover, b, qy) = (self.cover, self.b, self.qy);
                self.spans = [row(cover, b, qy), row(cover, b, qy + 1)];
                let lo = self.spans.iter().flatten().map(|s| s.0).min();
                let hi = self.spans.iter().flatten().map(|s| s.1).max();
                if let (Some(lo), Some(hi)) = (lo, hi) {
                    self.x = lo & !1;
                    self.hi = hi;
                }
            }
            let (x, qy) = (self.x, self.qy);
            self.x += LANES as i64;
            // Each row's lanes as bits: the span's, then the per-pixel mask's.
            let mut bits = [0u32; 2];
            for (r, span) in self.spans.iter().enumerate() {
                if let Some((a, z)) = *span {
                    let (lo, hi) = ((a - x).clamp(0, 8), (z - x + 1).clamp(0, 8));
                    if lo < hi {
                        let m = (0xFFu32 >> (8 - (hi - lo))) << lo;
                        bits[r] = m & self.cover.keep8(x, qy + r as i64);
                    }
                }
            }
            if bits != [0, 0] {
                let live = bits.map(|b| LIVE_MASKS[b as usize]);
                return Some(Chunk {
                    qy,
                    x,
                    fx: std::array::from_fn(|i| (x + i as i64) as f32),
                    fy: [qy as f32, (qy + 1) as f32],
                    live,
                });
            }
        }
    }
}

/// Pairs of rows in 8-pixel chunks of 2x2 quads, as `rows_textured` walks triangles: on
/// an AVX2 level whose plan [`super::textured::general_ok`] accepts, each chunk row is
/// shaded on 8 lanes ([`super::textured::chunks_general`]), else lane by lane.
#[inline(always)]
pub(super) fn rows<
    M: Madd,
    const AVX2: bool,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
>(
    t: &SetupTriangle,
    chunks: &mut dyn Iterator<Item = Chunk>,
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    // `AVX2` is a constant: the other levels' copies do not contain the 8-wide code.
    #[cfg(target_arch = "x86_64")]
    if AVX2 && super::textured::general_ok(plan, fb) {
        use super::textured::chunks_general;
        // SAFETY: `general_ok` checked AVX2; this level's copy is compiled with FMA exactly
        // when `M::FUSED`; the chunks lie in `b`, inside the target.
        unsafe {
            super::variants::with_fused!(M, |FMA| {
                chunks_general::<M, FMA, DEPTH, FLAT, PERSP, false>(
                    t, chunks, plan, units, fb, stats,
                )
            })
        }
        return;
    }
    let mut texels: [TexLanes; 2] = [[[[0.0; 4]; LANES]; MAX_TEXTURE_UNITS]; 2];
    for c in chunks {
        super::sample_chunk::<M, PERSP, false>(t, units, &c, &mut texels);
        super::shade_chunk_rows::<M, DEPTH, FLAT, PERSP>(t, plan, units, &texels, fb, &c, stats);
    }
}
