//! Rasterization: walks the rows of a set-up triangle, computes each row's exact covered
//! span from the integer edge functions (no per-pixel edge test), and hands spans (or, for
//! a triangle less than 4 pixels wide, 4x2 blocks) to the fragment stage's span shader
//! chosen once per triangle (`variants`; untextured states that shader leaves, and wide
//! targets, take `untextured`; the texture fast path's walk is `textured`; the general
//! textured walks sample a unit a row at a time where an 8-wide sampler covers it,
//! `sample8`).
//! Also here: batching triangles over bands of rows on the thread pool ([`batch`]), lines
//! and points ([`lines`], [`prims`]; untextured ones shaded row by row, [`prim_spans`];
//! large draws of them on two bands of rows at once, [`banded`]),
//! antialiased ones ([`smooth`]), textured lines, points and stippled polygons
//! ([`prim_tex`]) and polygon stipple ([`stipple`]).

use crate::cpu::Isa;
use crate::fragment::span::{
    one_over_w, shade_chunk, tex_coords_oow, tex_r_oow, ChunkColors, Madd, Span, TexLanes, LANES,
};
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::setup::{SetupTriangle, NARROW};
use crate::geometry::VARY_TEX;
use crate::pipe::MAX_TEXTURE_UNITS;
use crate::stats::Stats;
use crate::texture::UnitPlan;

pub mod banded;
pub mod batch;
pub mod lines;
pub mod ms_prims;
pub mod multisample;
pub mod prim_spans;
pub mod prim_tex;
pub mod prims;
mod row_pairs;
mod sample8;
mod shaded;
pub mod smooth;
pub mod sprite;
pub mod stipple;
mod textured;
mod untextured;
mod variants;

use variants::{with_flags, Walks};
#[cfg(target_arch = "x86_64")]
use variants::{with_simd_variant, SimdWalks};

/// What a primitive is drawn with and into: the per-draw references every entry point
/// of the rasterizer takes (the drawable region, the fragment plan, the enabled texture
/// units, the rows being drawn and the counters), made once per draw (or per band of a
/// batch) and passed by reference. The walks compiled per instruction-set level
/// ([`variants`]) still take the references one by one.
pub struct Draw<'d, 'f> {
    /// The drawable region (y-down pixels, exclusive high end).
    pub region: [i64; 4],
    /// The per-fragment plan.
    pub plan: &'d FragPlan,
    /// The enabled texture units' plans.
    pub units: &'d [UnitPlan<'d>],
    /// The rows drawn into.
    pub fb: &'d mut Target<'f>,
    /// The counters.
    pub stats: &'d mut Stats,
    /// A shader draw's walk with rows not yet run ([`shaded`]); run when the draw's
    /// references end.
    shaded: Option<shaded::Pending>,
    /// The facing a shader sees on the lines and points drawn (`gl_FrontFacing`): true,
    /// except for the edges and vertices of an unfilled back-facing polygon (Mesa's
    /// unfilled stage passes the polygon's facing on).
    pub prim_front: bool,
}

impl Drop for Draw<'_, '_> {
    fn drop(&mut self) {
        if let Some(p) = self.shaded.take() {
            p.end(self.units, self.fb, self.stats);
        }
    }
}

impl<'d, 'f> Draw<'d, 'f> {
    /// The references of one draw into `fb`.
    #[inline]
    pub fn new(
        region: [i64; 4],
        plan: &'d FragPlan,
        units: &'d [UnitPlan<'d>],
        fb: &'d mut Target<'f>,
        stats: &'d mut Stats,
    ) -> Self {
        Draw {
            region,
            plan,
            units,
            fb,
            stats,
            shaded: None,
            prim_front: true,
        }
    }

    /// The inclusive box `bbox` cut to the region and to the target's rows (empty when
    /// x0 > x1 or y0 > y1).
    #[inline(always)]
    pub fn clip(&self, bbox: [i64; 4]) -> [i64; 4] {
        let (r, fb) = (self.region, &self.fb);
        [
            bbox[0].max(r[0]),
            bbox[1].max(r[1]).max(fb.y0 as i64),
            bbox[2].min(r[2] - 1),
            bbox[3].min(r[3] - 1).min((fb.y0 + fb.rows) as i64 - 1),
        ]
    }
}

/// Rasterizes `t` inside the region and the target's rows; returns whether any row of
/// the triangle's box was inside them.
pub fn raster_triangle(t: &SetupTriangle, d: &mut Draw<'_, '_>) -> bool {
    let b = d.clip(t.bbox);
    if b[0] > b[2] || b[1] > b[3] {
        return false;
    }
    if let Some(sh) = &d.plan.shader {
        shaded::triangle(t, b, sh, d);
        return true;
    }
    if d.plan.ms.is_some() {
        raster_samples(t, b, d);
        return true;
    }
    // SAFETY: (all five) `cpu::isa` and `cpu::avx512` only report features the CPU has,
    // and each arm runs that level's walks.
    unsafe {
        match crate::cpu::isa() {
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2Fma if crate::cpu::avx512() && simd_ok(d) => {
                rows_simd::<variants::Avx512>(t, b, d)
            }
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2Fma => tri_simd::<variants::Avx2Fma>(t, b, d),
            #[cfg(target_arch = "x86_64")]
            Isa::Fma => raster_rows::<variants::Fma>(t, b, d),
            _ => raster_rows::<variants::Base>(t, b, d),
        }
    }
    true
}

/// Rasterizes `t` (edges set up for the four samples, as
/// [`crate::geometry::setup::setup_triangle_samples`] makes them) in box `b` (already cut
/// to the region) with the one-pass multisample walk ([`multisample`]); the draw's plan
/// must be a multisample one.
#[inline]
pub fn raster_samples(t: &SetupTriangle, b: [i64; 4], d: &mut Draw<'_, '_>) {
    // Lines and points come here as quads (`ms_prims`).
    if let Some(sh) = &d.plan.shader {
        shaded::triangle(t, b, sh, d);
        return;
    }
    // Its own walk, in the CPU's level (the walks of a level fuse as llvmpipe does on
    // that CPU).
    // SAFETY: (all four) `cpu::isa` only reports features the CPU has, and each arm runs
    // that level's walks.
    unsafe {
        match crate::cpu::isa() {
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2Fma => multisample::triangle::<variants::Avx2Fma>(t, b, d),
            #[cfg(target_arch = "x86_64")]
            Isa::Fma => multisample::triangle::<variants::Fma>(t, b, d),
            _ => multisample::triangle::<variants::Base>(t, b, d),
        }
    }
}

/// An AVX2 level: the AVX2 span shader when it covers the plan, else the general walks.
///
/// # Safety
/// `W`'s instruction set is the CPU's ([`Walks`]).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn tri_simd<W: Walks + SimdWalks>(t: &SetupTriangle, b: [i64; 4], d: &mut Draw<'_, '_>) {
    // SAFETY: (both) forwarded from the caller.
    unsafe {
        if simd_ok(d) {
            rows_simd::<W>(t, b, d)
        } else {
            raster_rows::<W>(t, b, d)
        }
    }
}

/// Whether the AVX2 span shader covers this plan (see `fragment::simd`).
#[cfg(target_arch = "x86_64")]
fn simd_ok(d: &Draw<'_, '_>) -> bool {
    use crate::framebuffer::ColorFormat;
    let plan = d.plan;
    d.units.is_empty()
        && plan.alpha.is_none()
        && plan.stencil.is_none()
        && plan.logic.is_none()
        && !plan.separate_specular
        && plan.fog.is_none()
        && !plan.count_samples
        && plan.smooth.is_none()
        && !crate::fragment::span::float_store(plan, d.fb)
        && (plan.color_mask == [true; 4] || plan.color_mask == [false; 4])
        && matches!(
            d.fb.format,
            ColorFormat::Rgba | ColorFormat::Bgra | ColorFormat::Argb
        )
}

/// Asks for the colour (and with `depth` the depth) lines of absolute row `py` from pixel
/// `lo` to `hi`, at most `max_lines` 64-byte lines, when the row lies in the band.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(crate) fn prefetch_row(
    fb: &Target<'_>,
    py: i64,
    lo: i64,
    hi: i64,
    depth: bool,
    max_lines: usize,
) {
    let (y0, y1) = (fb.y0 as i64, (fb.y0 + fb.rows) as i64);
    if py < y0 || py >= y1 || lo > hi || lo < 0 {
        return;
    }
    let i = (py - y0) as usize * fb.width + lo as usize;
    // 16 four-byte pixels per line.
    let lines = (((hi - lo) / 16) as usize + 1).min(max_lines);
    for k in 0..lines {
        // The addresses are formed with wrapping arithmetic (they lie inside the band's
        // rows anyway); a prefetch never faults.
        crate::simd::prefetch(fb.color.as_ptr().wrapping_add(i + 16 * k));
        if depth {
            crate::simd::prefetch(fb.depth.as_ptr().wrapping_add(i + 16 * k));
        }
    }
}

/// Whether the AVX2 row walk draws boxes less than [`NARROW`] pixels wide as 4x2 blocks
/// ([`crate::fragment::simd::shade_pair`]); `SOFTGL_NARROW=0` turns this off for A/B
/// measurements (the pixels are the same either way).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn narrow_blocks() -> bool {
    #[cfg(test)]
    if tests::SPANS_ONLY.with(|s| s.get()) {
        return false;
    }
    crate::tuning::tuning().narrow
}

/// The row walk for the AVX2 span shader: picks the span shader's variant once per
/// triangle (depth function, blend, flat / smooth / perspective) and calls `W`'s copy.
///
/// # Safety
/// `W`'s instruction set is the CPU's ([`SimdWalks`]), and [`simd_ok`] holds.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn rows_simd<W: SimdWalks>(t: &SetupTriangle, b: [i64; 4], d: &mut Draw<'_, '_>) {
    let (plan, fb, stats) = (d.plan, &mut *d.fb, &mut *d.stats);
    with_simd_variant!((plan, t.persp), |D, F, P, B| {
        // SAFETY: forwarded from the caller.
        unsafe { W::simd::<D, F, P, B>(t, b, plan, fb, stats) }
    })
}

/// The row loop of [`rows_simd`] for one span shader variant.
///
/// # Safety
/// As [`rows_simd`].
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn rows_simd_walk<
    const FMA: bool,
    const D: u8,
    const FLAT: bool,
    const PERSP: bool,
    const B: u8,
>(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    use crate::fragment::simd::{shade_pair, shade_span};
    if b[2] - b[0] < NARROW && narrow_blocks() {
        // A narrow box (most small triangles): its rows two at a time, each pair of rows
        // as one chunk of 4x2 pixels, instead of a span per row.
        let mut py = b[1];
        while py <= b[3] {
            let mut mask = t.row_mask(b[0], b[2], py);
            if py < b[3] {
                mask |= t.row_mask(b[0], b[2], py + 1) << NARROW;
            }
            if mask != 0 {
                // SAFETY: forwarded from the caller; the pixels of `mask` lie in the box,
                // which is inside the target.
                unsafe {
                    shade_pair::<FMA, D, FLAT, PERSP, B>(
                        t,
                        plan,
                        fb,
                        py as usize,
                        b[0] as usize,
                        mask,
                        stats,
                    )
                }
            }
            py += 2;
        }
        return;
    }
    for py in b[1]..=b[3] {
        if let Some((lo, hi)) = row_span(t, b, py) {
            // The span two rows down starts near this one's: ask for its first depth and
            // colour lines now, so that their loads do not wait on the cache when it is
            // reached (the hardware fetches the line after; more lines measured no faster
            // on immediate_100k at 1024²).
            let depth = D != crate::fragment::simd::D_NONE;
            prefetch_row(fb, py + 2, lo, hi, depth, 1);
            // SAFETY: forwarded from the caller.
            unsafe {
                shade_span::<FMA, D, FLAT, PERSP, B>(t, plan, fb, Span::of(py, lo, hi), stats)
            }
        }
    }
}

/// The general walks of level `W`: the texture fast path, the textured walk, or the
/// general span shader, each variant picked here and called once.
///
/// # Safety
/// `W`'s instruction set is the CPU's ([`Walks`]).
#[inline(always)]
unsafe fn raster_rows<W: Walks>(t: &SetupTriangle, b: [i64; 4], d: &mut Draw<'_, '_>) {
    let (plan, units, fb, stats) = (d.plan, d.units, &mut *d.fb, &mut *d.stats);
    let depth = plan.depth.is_some();
    // Wide buffers and sRGB writes take the general per-fragment walks (the 8-lane ones
    // where they cover the plan: `untextured`, `fragment::simd_wide`).
    let wide = crate::fragment::span::float_store(plan, fb);
    if let Some(env) = textured::fast_env(plan, units).filter(|_| !wide) {
        let u = &units[0];
        with_flags!((depth, plan.flat, t.persp), |D, F, P| {
            // SAFETY: forwarded from the caller.
            unsafe { W::tex_fast::<D, F, P>(t, b, plan, u, env, fb, stats) }
        })
    } else if !units.is_empty() {
        with_flags!((depth, plan.flat, t.persp), |D, F, P| {
            // SAFETY: forwarded from the caller.
            unsafe { W::textured::<D, F, P>(t, b, plan, units, fb, stats) }
        })
    } else {
        // Flat colours need no divide, but the fog coordinate is still perspective-correct.
        let persp = t.persp && (!plan.flat || plan.fog.is_some() || plan.smooth.is_some());
        with_flags!((depth, plan.flat, persp), |D, F, P| {
            // SAFETY: forwarded from the caller.
            unsafe { W::untextured::<D, F, P>(t, b, plan, fb, stats) }
        })
    }
}

/// The covered pixels of row `py` within `b`, or `None`.
#[inline(always)]
fn row_span(t: &SetupTriangle, b: [i64; 4], py: i64) -> Option<(i64, i64)> {
    if py < b[1] || py > b[3] {
        return None;
    }
    t.row_span(b[0], b[2], py)
}

/// Textured triangles walk pairs of rows, so that every 2x2 quad (aligned to even pixel
/// coordinates, as llvmpipe's quads are) gets one level of detail from its TL, TR and BL
/// texture coordinates; helper pixels outside the triangle are evaluated on the planes.
#[inline(always)]
fn rows_textured<
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
    if textured::rows_engine::<M, AVX2, PERSP>(t, b, plan, units, fb, stats) {
        return;
    }
    // `AVX2` is a constant: the other levels' copies do not contain the 8-wide code.
    #[cfg(target_arch = "x86_64")]
    if AVX2 && textured::general_ok(plan, fb) {
        // SAFETY: `general_ok` checked AVX2; this level's copy is compiled with FMA exactly
        // when `M::FUSED`.
        unsafe {
            variants::with_fused!(M, |FMA| {
                textured::rows_general::<M, FMA, DEPTH, FLAT, PERSP>(t, b, plan, units, fb, stats)
            })
        }
        return;
    }
    // Texel values of the current chunk, reused across chunks (lanes that are not live keep
    // stale values, which are never used): zeroing 2 KiB per chunk cost more than sampling.
    let mut texels: [TexLanes; 2] = [[[[0.0; 4]; LANES]; MAX_TEXTURE_UNITS]; 2];
    for c in textured::Chunks::new(t, b) {
        sample_chunk::<M, PERSP, true>(t, units, &c, &mut texels);
        shade_chunk_rows::<M, DEPTH, FLAT, PERSP>(t, plan, units, &texels, fb, &c, stats);
    }
}

/// Samples every unit for the 2x2 quads of chunk `c` that hold a live pixel, into
/// `texels` (lanes of the other quads keep stale values); with `STR` also the r
/// coordinate of the units that need it. A unit an 8-wide sampler covers ([`sample8`])
/// is sampled a row at a time, the others a quad at a time.
#[inline(always)]
fn sample_chunk<M: Madd, const PERSP: bool, const STR: bool>(
    t: &SetupTriangle,
    units: &[UnitPlan<'_>],
    c: &textured::Chunk,
    texels: &mut [TexLanes; 2],
) {
    let (fx, fy, live) = (&c.fx, c.fy, &c.live);
    // One `1 / w` per pixel for every unit (the values each unit's own would be).
    let oow = [
        one_over_w::<M, PERSP>(t, fx, fy[0]),
        one_over_w::<M, PERSP>(t, fx, fy[1]),
    ];
    for (k, u) in units.iter().enumerate() {
        let base = VARY_TEX + 4 * k;
        let (s0, t0) = tex_coords_oow::<M, PERSP>(t, base, fx, fy[0], &oow[0]);
        let (s1, t1) = tex_coords_oow::<M, PERSP>(t, base, fx, fy[1], &oow[1]);
        // An `if`, not `bool::then`: a closure that is not inlined loses the caller's
        // target features, and its fused multiply-adds become calls to `fmaf`.
        let rr = if STR && u.needs_r() {
            Some([
                tex_r_oow::<M, PERSP>(t, base, fx, fy[0], &oow[0]),
                tex_r_oow::<M, PERSP>(t, base, fx, fy[1], &oow[1]),
            ])
        } else {
            None
        };
        sample_unit::<M>(u, k, &[s0, s1], &[t0, t1], rr.as_ref(), live, texels);
    }
}

/// Samples unit `k` (`u`) of a chunk at the two rows' coordinates `s`, `t` (and `r` for
/// the units that need it) into `texels`, for the 2x2 quads that hold a `live` pixel:
/// row by row where an 8-wide sampler covers the unit ([`sample8`]), else a quad at a
/// time.
#[inline(always)]
fn sample_unit<M: Madd>(
    u: &UnitPlan<'_>,
    k: usize,
    s: &[[f32; LANES]; 2],
    t: &[[f32; LANES]; 2],
    rr: Option<&[[f32; LANES]; 2]>,
    live: &[[bool; LANES]; 2],
    texels: &mut [TexLanes; 2],
) {
    if sample8::rows::<M>(u, k, &sample8::Rows { s, t, r: rr, live }, texels) {
        return;
    }
    let ([s0, s1], [t0, t1]) = (s, t);
    for j in 0..LANES / 2 {
        let (l, r) = (2 * j, 2 * j + 1);
        if !(live[0][l] || live[0][r] || live[1][l] || live[1][r]) {
            continue;
        }
        let (s, tt) = ([s0[l], s0[r], s1[l], s1[r]], [t0[l], t0[r], t1[l], t1[r]]);
        let rq = rr.map(|[r0, r1]| [r0[l], r0[r], r1[l], r1[r]]);
        let v = variants::sample_quad::<M>(u, s, tt, rq);
        texels[0][k][l] = v[0];
        texels[0][k][r] = v[1];
        texels[1][k][l] = v[2];
        texels[1][k][r] = v[3];
    }
}

/// Shades the live lanes of both rows of chunk `c` through the full per-fragment path,
/// with the units' `texels` (the untextured walk is [`untextured`]).
#[inline(always)]
fn shade_chunk_rows<M: Madd, const DEPTH: bool, const FLAT: bool, const PERSP: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    texels: &[TexLanes; 2],
    fb: &mut Target<'_>,
    c: &textured::Chunk,
    stats: &mut Stats,
) {
    for (r, (tex, live)) in texels.iter().zip(c.live).enumerate() {
        if live.iter().any(|&l| l) {
            let (y, x) = ((c.qy + r as i64) as usize, c.x as usize);
            let colors = ChunkColors::Textured(tex);
            shade_chunk::<M, DEPTH, FLAT, PERSP, true>(
                t, plan, units, colors, fb, y, x, live, stats,
            );
        }
    }
}

#[cfg(all(test, target_arch = "x86_64"))]
mod tests {
    use super::*;
    use crate::fragment::{BlendPlan, DepthPlan};
    use crate::framebuffer::{ColorFormat, DepthFormat, Framebuffer};
    use crate::geometry::setup::{setup_triangle_shaded, CullMode, SetupResult};
    use crate::geometry::ClipVertex;
    use crate::pipe::CompareFunc;
    use crate::pipe::{BlendEquation, BlendFactor};
    use std::cell::Cell;

    thread_local! {
        /// Set by a test on its own thread: the AVX2 walk draws every box span by span.
        pub(super) static SPANS_ONLY: Cell<bool> = const { Cell::new(false) };
    }

    /// Draws `tris` into a framebuffer prefilled with pseudo-random colour and depth,
    /// with narrow boxes as 4x2 blocks or not; returns the colour, depth and counters.
    fn draw(
        plan: &FragPlan,
        tris: &[SetupTriangle],
        blocks: bool,
    ) -> (Vec<[u8; 4]>, Vec<u32>, Stats) {
        let (w, h) = (37, 29);
        let mut fb = Framebuffer::new(w, h, ColorFormat::Rgba, DepthFormat::Z24, false);
        let mut next = crate::test_rng::xorshift32(77);
        for (c, d) in fb.color.iter_mut().zip(fb.depth.iter_mut()) {
            *c = next().to_le_bytes();
            *d = next() & 0xFF_FFFF;
        }
        SPANS_ONLY.with(|s| s.set(!blocks));
        let mut stats = Stats::default();
        {
            let mut target = fb.target();
            for t in tris {
                let region = [0, 0, w as i64, h as i64];
                let mut d = Draw::new(region, plan, &[], &mut target, &mut stats);
                raster_triangle(t, &mut d);
            }
        }
        SPANS_ONLY.with(|s| s.set(false));
        (fb.color.to_vec(), fb.depth.to_vec(), stats)
    }

    /// The fragment plan of test round `round`: depth off or LESS / LEQUAL / GREATER
    /// (written or not), no blend, over or an additive blend, flat or smooth; the
    /// plans the AVX2 span shader covers.
    pub(super) fn plan_of_round(round: usize) -> FragPlan {
        let depth = (!round.is_multiple_of(4)).then_some(DepthPlan {
            func: [CompareFunc::Less, CompareFunc::LEqual, CompareFunc::Greater][round % 3],
            write: !round.is_multiple_of(5),
            format: DepthFormat::Z24,
        });
        let (src, dst) = if round % 8 >= 6 {
            (BlendFactor::DstColor, BlendFactor::One)
        } else {
            (BlendFactor::SrcAlpha, BlendFactor::OneMinusSrcAlpha)
        };
        let blend = (round % 4 >= 2).then_some(BlendPlan {
            src_rgb: src,
            dst_rgb: dst,
            src_a: src,
            dst_a: dst,
            eq_rgb: BlendEquation::Add,
            eq_a: BlendEquation::Add,
            color: [0; 4],
        });
        FragPlan {
            depth,
            flat: round % 6 == 5,
            color_mask: [true; 4],
            fma: crate::cpu::isa().fused(),
            alpha: None,
            stencil: None,
            blend,
            logic: None,
            separate_specular: false,
            fog: None,
            count_samples: false,
            smooth: None,
            ms: None,
            blend_color: [0.0; 4],
            srgb: false,
            shader: None,
            more_buffers: 0,
        }
    }

    /// A vertex in the box at `(x, y)` of size `(sx, sy)` with depth, `w` (1 unless
    /// `persp`) and the first four varyings from `unit`.
    pub(super) fn vertex(
        unit: &mut impl FnMut() -> f32,
        [x, y, sx, sy]: [f32; 4],
        persp: bool,
    ) -> ClipVertex {
        let mut p = ClipVertex {
            win: [
                x + unit() * sx,
                y + unit() * sy,
                unit(),
                if persp { 0.2 + unit() } else { 1.0 },
            ],
            ..ClipVertex::default()
        };
        for i in 0..4 {
            p.vary[i] = unit() * 1.2 - 0.1;
        }
        p
    }

    /// The triangle `v` set up with `nvary` varyings and no culling, unless it covers no
    /// pixel centre.
    pub(super) fn setup_of(v: [ClipVertex; 3], nvary: usize, flat: bool) -> Option<SetupTriangle> {
        let mut t = SetupTriangle::default();
        let cull = CullMode {
            front: false,
            back: false,
            front_ccw: true,
            top_left: false,
        };
        let r = setup_triangle_shaded([&v[0], &v[1], &v[2]], nvary, cull, None, flat, &mut t);
        (r == SetupResult::Draw).then_some(t)
    }

    #[test]
    fn narrow_blocks_match_spans_byte_for_byte() {
        if !crate::cpu::isa().avx2() {
            return;
        }
        let mut next = crate::test_rng::xorshift32(0x4e41_5252);
        let mut unit = move || next() as f32 / u32::MAX as f32;
        let mut narrow = 0;
        for round in 0..96 {
            let plan = plan_of_round(round);
            let persp = round % 2 == 0;
            // Small triangles (boxes of 1 to 6 pixels a side), some crossing the edges of
            // the buffer, some thin and tall.
            let mut tris = vec![];
            while tris.len() < 300 {
                let (cx, cy) = (unit() * 41.0 - 2.0, unit() * 33.0 - 2.0);
                let (sx, sy) = (0.5 + unit() * 4.5, 0.5 + unit() * 4.5);
                let v = std::array::from_fn(|_| vertex(&mut unit, [cx, cy, sx, sy], persp));
                if let Some(t) = setup_of(v, 4, plan.flat) {
                    narrow += usize::from(t.bbox[2] - t.bbox[0] < NARROW);
                    tris.push(t);
                }
            }
            let spans = draw(&plan, &tris, false);
            let blocks = draw(&plan, &tris, true);
            assert!(spans.0 == blocks.0, "colour differs in round {round}");
            assert!(spans.1 == blocks.1, "depth differs in round {round}");
            assert_eq!(spans.2, blocks.2, "counters differ in round {round}");
            assert!(spans.2.fragments > 0);
        }
        // Most boxes are narrow, so the blocks were drawn.
        assert!(narrow > 96 * 300 / 2, "{narrow}");
    }
}
