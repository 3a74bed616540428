//! The span shader: shades the covered pixels `x0..=x1` of one row, monomorphised over the
//! multiply-add flavour and the plan's booleans so the per-pixel loop has no state branches.
// Lane loops index several arrays in step; iterators would hide that.
#![allow(clippy::needless_range_loop)]

use super::blend::Lanes;
use super::FragPlan;
use crate::framebuffer::samples::PlaneRows;
use crate::framebuffer::{DepthFormat, Target};
use crate::geometry::setup::{Plane, SetupTriangle};
use crate::geometry::{VARY_FOG, VARY_SPEC};
use crate::pipe::MAX_TEXTURE_UNITS;
use crate::stats::Stats;
use crate::texture::UnitPlan;

/// How `a * b + c` rounds: llvmpipe fuses it exactly when the CPU has FMA.
pub trait Madd {
    /// Whether [`Madd::madd`] fuses (selects the FMA variant of the AVX2 code).
    const FUSED: bool;
    /// `a * b + c`.
    fn madd(a: f32, b: f32, c: f32) -> f32;
}

/// One rounding (`vfmadd` inside an FMA-enabled function).
pub struct Fused;
/// Two roundings.
pub struct Unfused;

impl Madd for Fused {
    const FUSED: bool = true;
    #[inline(always)]
    fn madd(a: f32, b: f32, c: f32) -> f32 {
        a.mul_add(b, c)
    }
}

impl Madd for Unfused {
    const FUSED: bool = false;
    #[inline(always)]
    fn madd(a: f32, b: f32, c: f32) -> f32 {
        a * b + c
    }
}

/// Evaluates a plane at pixel (fx, fy) as llvmpipe's interpolator does.
#[inline(always)]
pub fn eval<M: Madd>(p: &Plane, fx: f32, fy: f32) -> f32 {
    M::madd(p.dady, fy, M::madd(p.dadx, fx, p.a0))
}

/// Pixels shaded together: one AVX2 register of f32.
pub const LANES: usize = 8;

/// What a span shader shades: pixels `x0..=x1` of row `y` (y-down, inside the target).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Span {
    /// The row.
    pub y: usize,
    /// The first pixel.
    pub x0: usize,
    /// The last pixel (inclusive).
    pub x1: usize,
}

impl Span {
    /// Pixels `x0..=x1` of row `y` (a rasterizer's clipped, non-negative coordinates).
    #[inline(always)]
    pub fn of(y: i64, x0: i64, x1: i64) -> Self {
        Span {
            y: y as usize,
            x0: x0 as usize,
            x1: x1 as usize,
        }
    }
}

/// `round_half_even(v)` for 0 <= v < 2^23 - 1 as an integer, without a rounding
/// instruction: adding 2^23 leaves the rounded value in the low mantissa bits (vectorises
/// everywhere). Only for values whose rounding cannot reach 2^23.
#[inline(always)]
fn round_small(v: f32) -> u32 {
    (v + 8_388_608.0).to_bits() & 0x7F_FFFF
}

/// [`crate::framebuffer::float_to_ubyte`] in a form the compiler vectorises: clamp (NaN → 0), scale, round.
#[inline(always)]
pub fn unorm8(c: f32) -> u8 {
    let c = if c > 0.0 { c } else { 0.0 };
    let c = if c < 1.0 { c } else { 1.0 };
    round_small(c * 255.0) as u8
}

/// A clamped depth quantised as [`DepthFormat::quantize`] does, vectorisable.
#[inline(always)]
pub(crate) fn quantize_depth(format: DepthFormat, z: f32) -> u32 {
    let z = if z > 0.0 { z } else { 0.0 };
    let z = if z < 1.0 { z } else { 1.0 };
    match format {
        DepthFormat::Z24 => {
            // Below 2^23, adding and subtracting 2^23 rounds half to even (and may give
            // exactly 2^23); above it every f32 is already an integer.
            let q = z * 16_777_215.0f32;
            let r = if q < 8_388_608.0 {
                (q + 8_388_608.0) - 8_388_608.0
            } else {
                q
            };
            r as u32
        }
        DepthFormat::Z32F => z.to_bits(),
        _ => format.quantize(z),
    }
}

/// The 8-bit colours of [`LANES`] pixels at `fx`, row `fy` (a function, not a closure, so
/// that it inlines into the CPU-specific entry points).
#[inline(always)]
fn colors<M: Madd, const FLAT: bool, const PERSP: bool>(
    t: &SetupTriangle,
    fx: &[f32; LANES],
    fy: f32,
    flat_color: [u8; 4],
) -> Lanes {
    if FLAT {
        let mut c = [[0u8; LANES]; 4];
        for ch in 0..4 {
            c[ch] = [flat_color[ch]; LANES];
        }
        return c;
    }
    let mut c = [[0u8; LANES]; 4];
    let mut oow = [1f32; LANES];
    if PERSP {
        for i in 0..LANES {
            oow[i] = 1.0f32 / eval::<M>(&t.w, fx[i], fy);
        }
    }
    for ch in 0..4 {
        let p = &t.vary[ch];
        for i in 0..LANES {
            let a = eval::<M>(p, fx[i], fy);
            c[ch][i] = unorm8(if PERSP { a * oow[i] } else { a });
        }
    }
    c
}

/// The texture values of one chunk: per enabled unit, per lane, RGBA as the sampler
/// returns it.
pub type TexLanes = [[[f32; 4]; LANES]; MAX_TEXTURE_UNITS];

/// `1 / w` of [`LANES`] pixels of row `fy` (all 1 without perspective).
#[inline(always)]
pub fn one_over_w<M: Madd, const PERSP: bool>(
    t: &SetupTriangle,
    fx: &[f32; LANES],
    fy: f32,
) -> [f32; LANES] {
    let mut oow = [1f32; LANES];
    if PERSP {
        for i in 0..LANES {
            oow[i] = 1.0f32 / eval::<M>(&t.w, fx[i], fy);
        }
    }
    oow
}

/// Varying `k` at pixel (fx, fy): its plane, times the pixel's `1 / w` when `PERSP`.
#[inline(always)]
pub(crate) fn vary_at<M: Madd, const PERSP: bool>(
    t: &SetupTriangle,
    k: usize,
    fx: f32,
    fy: f32,
    oow: f32,
) -> f32 {
    let a = eval::<M>(&t.vary[k], fx, fy);
    if PERSP {
        a * oow
    } else {
        a
    }
}

/// Perspective-correct, projected texture coordinates (s, t) of one unit at [`LANES`]
/// pixels of row `fy` whose `1 / w` is `oow` ([`one_over_w`]): `a_plane * (1 / w_plane)`,
/// then `coord * (1 / q)` as llvmpipe's lowered projective sampling does.
#[inline(always)]
pub fn tex_coords_oow<M: Madd, const PERSP: bool>(
    t: &SetupTriangle,
    base: usize,
    fx: &[f32; LANES],
    fy: f32,
    oow: &[f32; LANES],
) -> ([f32; LANES], [f32; LANES]) {
    let (mut s, mut tt, mut q) = ([0f32; LANES], [0f32; LANES], [0f32; LANES]);
    for i in 0..LANES {
        let e = |k: usize| vary_at::<M, PERSP>(t, base + k, fx[i], fy, oow[i]);
        s[i] = e(0);
        tt[i] = e(1);
        q[i] = e(3);
    }
    for i in 0..LANES {
        let r = 1.0f32 / q[i];
        s[i] *= r;
        tt[i] *= r;
    }
    (s, tt)
}

/// The projected r coordinate of one unit at [`LANES`] pixels of row `fy` whose `1 / w`
/// is `oow` (3D textures, cube maps): `r·(1/q)` with the same `1/q` as
/// [`tex_coords_oow`] (a loop, not `array::from_fn`: a closure the compiler leaves out of
/// line loses the caller's target features).
#[inline(always)]
pub fn tex_r_oow<M: Madd, const PERSP: bool>(
    t: &SetupTriangle,
    base: usize,
    fx: &[f32; LANES],
    fy: f32,
    oow: &[f32; LANES],
) -> [f32; LANES] {
    let mut r = [0f32; LANES];
    for i in 0..LANES {
        let rr = vary_at::<M, PERSP>(t, base + 2, fx[i], fy, oow[i]);
        let q = vary_at::<M, PERSP>(t, base + 3, fx[i], fy, oow[i]);
        r[i] = rr * (1.0f32 / q);
    }
    r
}

/// The primary colour of [`LANES`] pixels of row `fy` in f32, as the fragment shader
/// receives it (perspective-correct with the row's `oow`).
#[inline(always)]
pub fn frag_colors<M: Madd, const FLAT: bool, const PERSP: bool>(
    t: &SetupTriangle,
    fx: &[f32; LANES],
    fy: f32,
    oow: &[f32; LANES],
) -> [[f32; LANES]; 4] {
    let mut frag = [[0f32; LANES]; 4];
    if FLAT {
        for ch in 0..4 {
            frag[ch] = [t.flat[ch]; LANES];
        }
    } else {
        for ch in 0..4 {
            for i in 0..LANES {
                frag[ch][i] = vary_at::<M, PERSP>(t, ch, fx[i], fy, oow[i]);
            }
        }
    }
    frag
}

/// Where the colours of a chunk come from.
#[derive(Clone, Copy)]
pub enum ChunkColors<'a> {
    /// Interpolated (with the separate specular colour and fog when the plan has them).
    Shaded,
    /// Shaded with these sampled values of the enabled texture units.
    Textured(&'a TexLanes),
    /// Already computed (the texture fast path).
    Ready(&'a Lanes),
    /// Already computed, with the float colours a wide target stores (pixel rectangles).
    ReadyWide(&'a Lanes, &'a [[f32; LANES]; 4]),
}

/// The colours of [`LANES`] pixels as Mesa's fixed-function fragment shader computes them
/// in f32: the texture environment of every enabled unit, then the separate specular
/// colour, then fog; converted to 8 bits (and kept as floats in `float_out` for wide
/// buffers).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn shaded_colors<M: Madd, const FLAT: bool, const PERSP: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    fx: &[f32; LANES],
    fy: f32,
    units: &[UnitPlan<'_>],
    texels: Option<&TexLanes>,
    cov: Option<&[f32; LANES]>,
    alpha_out: Option<&mut [f32; LANES]>,
    float_out: Option<&mut [[f32; LANES]; 4]>,
) -> Lanes {
    let oow = one_over_w::<M, PERSP>(t, fx, fy);
    let frag = frag_colors::<M, FLAT, PERSP>(t, fx, fy, &oow);
    // Secondary colour and fog coordinate (perspective-correct like every varying), each
    // lane's value computed before the lane loop so that these loops vectorise.
    let extra = |k: usize| -> [f32; LANES] {
        let mut v = [0f32; LANES];
        for i in 0..LANES {
            v[i] = if FLAT && k < VARY_FOG {
                t.flat[k]
            } else {
                vary_at::<M, PERSP>(t, k, fx[i], fy, oow[i])
            };
        }
        v
    };
    let spec: [[f32; LANES]; 3] = if plan.separate_specular {
        [extra(VARY_SPEC), extra(VARY_SPEC + 1), extra(VARY_SPEC + 2)]
    } else {
        [[0f32; LANES]; 3]
    };
    let fog_coord = if plan.fog.is_some() {
        extra(VARY_FOG)
    } else {
        [0f32; LANES]
    };
    // A crossbar environment (GL_TEXTUREn) reads every active unit's texel of the lane.
    let crossbar = if units.iter().any(|u| u.env.crossbar) {
        units.len()
    } else {
        0
    };
    let mut all = [[0.0f32; 4]; MAX_TEXTURE_UNITS];
    // The shader's final colours, converted to 8 bits after the lane loop (a loop over
    // lanes of one channel vectorises; the conversion inside the lane loop did not).
    let mut out = [[0f32; LANES]; 4];
    for i in 0..LANES {
        let f = [frag[0][i], frag[1][i], frag[2][i], frag[3][i]];
        let mut prev = f;
        if let Some(tx) = texels {
            for (k, a) in all.iter_mut().enumerate().take(crossbar) {
                *a = tx[k][i];
            }
            for (k, u) in units.iter().enumerate() {
                prev = u.env.apply(f, tx[k][i], prev, &all[..crossbar]);
            }
        }
        if plan.separate_specular {
            for ch in 0..3 {
                prev[ch] += spec[ch][i];
            }
        }
        if let Some(fog) = &plan.fog {
            let factor = fog.factor(fog_coord[i]);
            prev = fog.apply(prev, factor);
        }
        // Antialiasing stages multiply the shader's final alpha by their coverage.
        if let Some(cv) = cov {
            prev[3] *= cv[i];
        }
        for ch in 0..4 {
            out[ch][i] = prev[ch];
        }
    }
    if let Some(a) = alpha_out {
        *a = out[3];
    }
    if let Some(f) = float_out {
        *f = out;
    }
    let mut c = [[0u8; LANES]; 4];
    for ch in 0..4 {
        for i in 0..LANES {
            c[ch][i] = unorm8(out[ch][i]);
        }
    }
    c
}

/// Shades span `s` of triangle `t`, [`LANES`] pixels at a time.
///
/// `FULL` selects the general path (alpha test, stencil, blending, logic op, read from
/// the plan at run time); without it only the depth test and the colour write run.
#[inline(always)]
pub fn shade_span<
    M: Madd,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
    const FULL: bool,
>(
    t: &SetupTriangle,
    plan: &FragPlan,
    fb: &mut Target<'_>,
    s: Span,
    stats: &mut Stats,
) {
    let mut x = s.x0;
    while x <= s.x1 {
        let n = LANES.min(s.x1 + 1 - x);
        let mut live = [false; LANES];
        for (i, l) in live.iter_mut().enumerate() {
            *l = i < n;
        }
        shade_chunk::<M, DEPTH, FLAT, PERSP, FULL>(
            t,
            plan,
            &[],
            ChunkColors::Shaded,
            fb,
            s.y,
            x,
            live,
            stats,
        );
        x += n;
    }
}

/// Shades the `live` lanes of the chunk of [`LANES`] pixels starting at `x` in row `py`.
/// `units` are the enabled texture units, whose sampled values `source` carries (textured
/// draws always take the `FULL` path). A wide target (which the rasterizer draws through
/// the `FULL` path) takes [`shade_chunk_wide`].
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn shade_chunk<
    M: Madd,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
    const FULL: bool,
>(
    t: &SetupTriangle,
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    source: ChunkColors<'_>,
    fb: &mut Target<'_>,
    py: usize,
    x: usize,
    live: [bool; LANES],
    stats: &mut Stats,
) {
    if FULL && float_store(plan, fb) {
        shade_chunk_wide::<M, DEPTH, FLAT, PERSP>(t, plan, units, source, fb, py, x, live, stats);
    } else {
        shade_chunk_as::<M, DEPTH, FLAT, PERSP, FULL, false>(
            t, plan, units, source, fb, py, x, live, stats,
        );
    }
}

/// [`shade_chunk`] into a wide target: the colours stay f32 to the store
/// ([`super::wide`]). Out of line: it serves the rare 16-bit and float buffers, and the
/// 8-bit paths keep their size (a fused multiply-add here may become a call to `fmaf`,
/// which rounds alike).
#[inline(never)]
#[allow(clippy::too_many_arguments)]
fn shade_chunk_wide<M: Madd, const DEPTH: bool, const FLAT: bool, const PERSP: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    source: ChunkColors<'_>,
    fb: &mut Target<'_>,
    py: usize,
    x: usize,
    live: [bool; LANES],
    stats: &mut Stats,
) {
    shade_chunk_as::<M, DEPTH, FLAT, PERSP, true, true>(
        t, plan, units, source, fb, py, x, live, stats,
    );
}

/// [`shade_chunk`]'s body; `WIDE` keeps the float colours for [`super::wide::store`].
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn shade_chunk_as<
    M: Madd,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
    const FULL: bool,
    const WIDE: bool,
>(
    t: &SetupTriangle,
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    source: ChunkColors<'_>,
    fb: &mut Target<'_>,
    py: usize,
    x: usize,
    mut live: [bool; LANES],
    stats: &mut Stats,
) {
    let w = fb.width;
    let fy = py as f32;
    // Lanes that address pixels inside the row (lanes past the right edge are never live).
    let n = LANES.min(w - x);
    stats.fragments += live.iter().filter(|&&l| l).count() as u64;
    let row = (py - fb.y0) * w + x;
    let fx: [f32; LANES] = std::array::from_fn(|i| (x + i) as f32);
    let mut c: Lanes = [[0u8; LANES]; 4];
    let mut cf = [[0f32; LANES]; 4];
    if FULL {
        c = chunk_colors::<M, FLAT, PERSP, WIDE>(
            t, plan, units, source, &fx, fy, &mut live, None, &mut cf,
        );
        alpha_test(plan, &c, &mut live, n, stats);
    }
    let out = StoreFormat::of(fb);
    let mut rows = fb.plane(0);
    let at = ChunkAt {
        row,
        n,
        fx: &fx,
        fy,
    };
    stencil_depth::<M, DEPTH, FULL>(t, plan, &mut rows, &at, &mut live, stats);
    if plan.color_mask == [false; 4] || !live[..n].iter().any(|&l| l) {
        return;
    }
    if !FULL {
        c = colors::<M, FLAT, PERSP>(t, &fx, fy, t.flat_u8);
    }
    store_chunk::<FULL, WIDE>(plan, out, &mut rows, (row, n), &live, c, &cf, stats);
}

/// Whether a draw's colours stay f32 to the store into `fb`: a wide (16-bit or float)
/// target or sRGB writes. The texture fast path and the untextured AVX2 span shader never
/// see them: the general 8-lane walks store wide targets through [`super::simd_wide`],
/// the per-lane ones (and sRGB writes) through [`store_chunk`].
#[inline(always)]
pub fn float_store(plan: &FragPlan, fb: &Target<'_>) -> bool {
    fb.wide.is_some() || plan.srgb
}

/// How a target stores colour: its format, and its precision when wide (with the
/// one-channel flag, [`crate::framebuffer::Framebuffer::wide_single`]).
#[derive(Clone, Copy)]
pub(crate) struct StoreFormat {
    /// The colour format of the 8-bit plane.
    pub format: crate::framebuffer::ColorFormat,
    /// The wide plane's precision, if any.
    pub wide: Option<crate::framebuffer::WideKind>,
    /// The wide plane is one channel.
    pub single: bool,
}

impl StoreFormat {
    /// The store format of `fb`.
    #[inline(always)]
    pub fn of(fb: &Target<'_>) -> Self {
        StoreFormat {
            format: fb.format,
            wide: fb.wide,
            single: fb.wide_single,
        }
    }
}

/// Stores the live lanes of a chunk (`at` = its first pixel's index in `rows` and the
/// lanes inside the row) into one plane's `rows`: sRGB writes encode and blend in linear
/// space ([`super::srgb`]), wide buffers convert, blend and store at their precision
/// ([`super::wide`]), both from the float colours `cf` that `WIDE` keeps (the rasterizer
/// takes the FULL path for them); 8-bit buffers blend and write `c` ([`write_colors`]).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn store_chunk<const FULL: bool, const WIDE: bool>(
    plan: &FragPlan,
    out: StoreFormat,
    rows: &mut PlaneRows<'_>,
    at: (usize, usize),
    live: &[bool; LANES],
    c: Lanes,
    cf: &[[f32; LANES]; 4],
    stats: &mut Stats,
) {
    let (row, n) = at;
    let alpha = out.format.has_alpha();
    if WIDE && plan.srgb {
        let dst = &mut rows.color[row..row + n];
        stats.color_writes += super::srgb::store(plan, alpha, dst, live, cf);
        return;
    }
    if let (true, Some(kind)) = (WIDE, out.wide) {
        let single = out.single;
        let dst = super::wide::WideDst {
            kind,
            alpha,
            single,
        };
        stats.color_writes += super::wide::store(dst, plan, rows, row, n, live, cf);
        return;
    }
    write_colors::<FULL>(
        plan,
        out.format,
        &mut rows.color[row..row + n],
        c,
        live,
        stats,
    );
}

/// Where a chunk's per-sample operations work: its first pixel's index `row` in the
/// band's rows, the `n` lanes inside the row, and the coordinates its depth is
/// evaluated at (lane x, row y).
pub(crate) struct ChunkAt<'a> {
    /// Index of the chunk's first pixel in the band's rows.
    pub row: usize,
    /// Lanes inside the row.
    pub n: usize,
    /// Depth's x per lane.
    pub fx: &'a [f32; LANES],
    /// Depth's y.
    pub fy: f32,
}

/// The colours of a chunk on the `FULL` path, from `source`, at pixel coordinates
/// (`fx`, `fy`); antialiasing coverage (smooth lines and points) clears the lanes it
/// leaves out of `live`. With `alpha_out` the final float alpha of each lane is kept,
/// with `WIDE` the float colours in `cf`.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) fn chunk_colors<M: Madd, const FLAT: bool, const PERSP: bool, const WIDE: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    source: ChunkColors<'_>,
    fx: &[f32; LANES],
    fy: f32,
    live: &mut [bool; LANES],
    alpha_out: Option<&mut [f32; LANES]>,
    cf: &mut [[f32; LANES]; 4],
) -> Lanes {
    let cov = plan
        .smooth
        .map(|s| crate::raster::smooth::coverage::<M, PERSP>(t, s, fx, fy, live));
    let cov = cov.as_ref();
    // A wide buffer stores the float colours ([`super::wide`]).
    let float_out = if WIDE { Some(cf) } else { None };
    match source {
        ChunkColors::Ready(c) => *c,
        ChunkColors::ReadyWide(c, f) => {
            if let Some(o) = float_out {
                *o = *f;
            }
            *c
        }
        ChunkColors::Textured(tx) => shaded_colors::<M, FLAT, PERSP>(
            t,
            plan,
            fx,
            fy,
            units,
            Some(tx),
            cov,
            alpha_out,
            float_out,
        ),
        ChunkColors::Shaded
            if plan.separate_specular
                || plan.fog.is_some()
                || cov.is_some()
                || alpha_out.is_some()
                || float_out.is_some() =>
        {
            shaded_colors::<M, FLAT, PERSP>(t, plan, fx, fy, units, None, cov, alpha_out, float_out)
        }
        ChunkColors::Shaded => colors::<M, FLAT, PERSP>(t, fx, fy, t.flat_u8),
    }
}

/// The alpha test on the 8-bit colours `c`: clears the live lanes (of the `n` inside the
/// row) that fail.
#[inline(always)]
pub(crate) fn alpha_test(
    plan: &FragPlan,
    c: &Lanes,
    live: &mut [bool; LANES],
    n: usize,
    stats: &mut Stats,
) {
    if let Some((func, reference)) = plan.alpha {
        for i in 0..n {
            if live[i] && !func.test(c[3][i], reference) {
                live[i] = false;
                stats.alpha_failed += 1;
            }
        }
    }
}

/// The stencil and depth tests of the chunk `at` in `rows` (depth evaluated at `at`'s
/// coordinates) with their updates, and the occlusion count: clears the lanes that fail.
/// Without `FULL` only the depth test (no stencil, no count).
#[inline(always)]
pub(crate) fn stencil_depth<M: Madd, const DEPTH: bool, const FULL: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    rows: &mut PlaneRows<'_>,
    at: &ChunkAt<'_>,
    live: &mut [bool; LANES],
    stats: &mut Stats,
) {
    let mut q = [0u32; LANES];
    if DEPTH {
        let d = plan.depth.expect("DEPTH implies a depth plan");
        for i in 0..LANES {
            q[i] = quantize_depth(d.format, eval::<M>(&t.z, at.fx[i], at.fy));
        }
    }
    stencil_depth_q::<DEPTH, FULL>(t.front, plan, rows, (at.row, at.n), &q, live, stats);
}

/// [`stencil_depth`] of the face `front` with the fragments' quantised depths `q`.
#[inline(always)]
pub(crate) fn stencil_depth_q<const DEPTH: bool, const FULL: bool>(
    front: bool,
    plan: &FragPlan,
    rows: &mut PlaneRows<'_>,
    (row, n): (usize, usize),
    q: &[u32; LANES],
    live: &mut [bool; LANES],
    stats: &mut Stats,
) {
    let stencil = plan.stencil.map(|s| if front { s.front } else { s.back });
    if FULL {
        if let Some(sp) = &stencil {
            for i in 0..n {
                if live[i] {
                    stats.stencil_reads += 1;
                    let s = rows.stencil[row + i];
                    if !sp.test(s) {
                        rows.stencil[row + i] = sp.update(sp.fail, s);
                        live[i] = false;
                        stats.stencil_failed += 1;
                    }
                }
            }
        }
    }
    if DEPTH {
        let d = plan.depth.expect("DEPTH implies a depth plan");
        let dst = &mut rows.depth[row..row + n];
        for i in 0..n {
            if !live[i] {
                continue;
            }
            stats.depth_reads += 1;
            if d.func.test(q[i], dst[i]) {
                if d.write {
                    dst[i] = q[i];
                }
            } else {
                live[i] = false;
                stats.depth_failed += 1;
                if FULL {
                    if let Some(sp) = &stencil {
                        let s = rows.stencil[row + i];
                        rows.stencil[row + i] = sp.update(sp.zfail, s);
                    }
                }
            }
        }
    }
    if FULL {
        if let Some(sp) = &stencil {
            for i in 0..n {
                if live[i] {
                    let s = rows.stencil[row + i];
                    rows.stencil[row + i] = sp.update(sp.zpass, s);
                }
            }
        }
    }
    if FULL && plan.count_samples {
        stats.samples_passed += live[..n].iter().filter(|&&l| l).count() as u64;
    }
}

/// Blends (or applies the logic op to) the 8-bit colours `c` with `dst` (the chunk's
/// pixels inside the row) and writes the live lanes through the colour mask, in the
/// buffer's `format`.
#[inline(always)]
pub(crate) fn write_colors<const FULL: bool>(
    plan: &FragPlan,
    format: crate::framebuffer::ColorFormat,
    dst: &mut [[u8; 4]],
    mut c: Lanes,
    live: &[bool; LANES],
    stats: &mut Stats,
) {
    let n = dst.len();
    let mask = plan.color_mask;
    let full_mask = mask == [true; 4];
    let store_plain =
        format.has_alpha() && !matches!(format, crate::framebuffer::ColorFormat::Rgb565);
    if FULL && (plan.blend.is_some() || plan.logic.is_some()) {
        let mut d: Lanes = [[0u8; LANES]; 4];
        for i in 0..n {
            for k in 0..4 {
                d[k][i] = dst[i][k];
            }
        }
        stats.color_reads += n as u64;
        if let Some(b) = &plan.blend {
            c = super::blend::blend_lanes(b, &c, &d);
        } else if let Some(op) = plan.logic {
            for k in 0..4 {
                for i in 0..LANES {
                    c[k][i] = op.apply(c[k][i], d[k][i]);
                }
            }
        }
    }
    for i in 0..n {
        if !live[i] {
            continue;
        }
        let mut v = [c[0][i], c[1][i], c[2][i], c[3][i]];
        if !store_plain {
            v = format.store_rgba8(v);
        }
        if full_mask {
            dst[i] = v;
        } else {
            for k in 0..4 {
                if mask[k] {
                    dst[i][k] = v[k];
                }
            }
        }
        stats.color_writes += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn vector_conversions_match_scalar_rules() {
        let mut z = 0.0f32;
        while z <= 1.0 {
            assert_eq!(
                quantize_depth(DepthFormat::Z24, z),
                DepthFormat::Z24.quantize(z),
                "z = {z}"
            );
            assert_eq!(unorm8(z), crate::framebuffer::float_to_ubyte(z), "c = {z}");
            z += 1.0 / 8191.0;
        }
        for z in [0.5f32, 0.25, 0.75, 1.0, 0.0, 0.499_999_97, 0.500_000_06] {
            assert_eq!(
                quantize_depth(DepthFormat::Z24, z),
                DepthFormat::Z24.quantize(z),
                "z = {z}"
            );
        }
        assert_eq!(unorm8(f32::NAN), 0);
        assert_eq!(quantize_depth(DepthFormat::Z24, f32::NAN), 0);
    }
}
