//! The row walk of the texture fast path (see [`crate::texture::fast`]): one 2D unit on
//! the 8-bit path with REPLACE, MODULATE or DECAL, no separate specular colour, no fog.
//! Pairs of rows as in `rows_textured`, one `1 / w` per pixel shared by the texture
//! coordinates and the colour, 8-bit texels straight into the specialised environment,
//! then the general per-fragment operations of [`shade_chunk`].
// Lane loops index several arrays in step.
#![allow(clippy::needless_range_loop)]

use super::row_pairs::RowPairs;

#[cfg(target_arch = "x86_64")]
mod vec8;
#[cfg(target_arch = "x86_64")]
use crate::fragment::simd_tex::tex_row;
use crate::fragment::span::{
    frag_colors, one_over_w, shade_chunk, tex_coords_oow, ChunkColors, Madd, LANES,
};
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::setup::SetupTriangle;
use crate::geometry::VARY_TEX;
use crate::stats::Stats;
use crate::texture::fast::{self, FastEnv};
use crate::texture::UnitPlan;

/// The fast path's environment when this draw qualifies: one unit with a fast form, and no
/// colour sum or fog after the environment.
#[inline(always)]
pub(super) fn fast_env(plan: &FragPlan, units: &[UnitPlan<'_>]) -> Option<FastEnv> {
    match units {
        [u] if !plan.separate_specular && plan.fog.is_none() && plan.smooth.is_none() => u.fast,
        _ => None,
    }
}

/// The live lanes of each 8-bit mask (lane i live when bit i is set).
pub(super) const LIVE_MASKS: [[bool; LANES]; 256] = {
    let mut t = [[false; LANES]; 256];
    let mut m = 0;
    while m < 256 {
        let mut i = 0;
        while i < LANES {
            t[m][i] = (m >> i) & 1 == 1;
            i += 1;
        }
        m += 1;
    }
    t
};

/// One chunk of [`Chunks`]: the top row `qy` of its pair, its first column `x`, the lanes'
/// pixel x and the two rows' pixel y as f32, and each row's covered lanes.
pub(super) struct Chunk {
    /// Top row of the pair (even).
    pub qy: i64,
    /// First column (even).
    pub x: i64,
    /// Pixel x of each lane.
    pub fx: [f32; LANES],
    /// Pixel y of the two rows.
    pub fy: [f32; 2],
    /// Covered lanes of each row.
    pub live: [[bool; LANES]; 2],
}

/// The 8-pixel chunks of the pairs of rows (aligned to even pixel coordinates, as
/// llvmpipe's 2x2 quads are, [`RowPairs`]) that `t` covers in `b`; a chunk is visited
/// when either row covers part of it. An iterator rather than a closure walker: a
/// closure body would be compiled outside the callers' CPU-specific entry points
/// (without AVX2/FMA).
pub(super) struct Chunks<'t> {
    pairs: RowPairs<'t, 1>,
    qy: i64,
    spans: [Option<(i64, i64)>; 2],
    x: i64,
    hi: i64,
}

impl<'t> Chunks<'t> {
    /// The chunks of `t` in `b`.
    #[inline(always)]
    pub fn new(t: &'t SetupTriangle, b: [i64; 4]) -> Self {
        Chunks {
            pairs: RowPairs::new(std::array::from_ref(&t.edges), b, !1),
            qy: 0,
            spans: [None; 2],
            x: 0,
            hi: -1,
        }
    }
}

impl Iterator for Chunks<'_> {
    type Item = Chunk;

    #[inline(always)]
    fn next(&mut self) -> Option<Chunk> {
        if self.x > self.hi {
            let p = self.pairs.next()?;
            self.qy = p.qy;
            self.spans = [p.spans[0][0], p.spans[1][0]];
            self.x = p.lo & !1;
            self.hi = p.hi;
        }
        let x = self.x;
        self.x += LANES as i64;
        let mut live = [[false; LANES]; 2];
        for (r, span) in self.spans.iter().enumerate() {
            if let Some((a, z)) = *span {
                // Lane i is live when a <= x + i <= z: lanes lo..hi.
                let lo = (a - x).clamp(0, LANES as i64) as u32;
                let hi = (z - x + 1).clamp(0, LANES as i64) as u32;
                let m = (0xFFu32 << lo) & (0xFFu32 >> (LANES as u32 - hi));
                live[r] = LIVE_MASKS[m as usize & 0xFF];
            }
        }
        // Integers below 2^24 are exact in f32, so this is `(x + i) as f32`.
        let xf = x as f32;
        let mut fx = [0f32; LANES];
        for (i, v) in fx.iter_mut().enumerate() {
            *v = xf + i as f32;
        }
        let fy = [self.qy as f32, (self.qy + 1) as f32];
        Some(Chunk {
            qy: self.qy,
            x,
            fx,
            fy,
            live,
        })
    }
}

/// Shades the rows `b` of `t` through the fast path.
#[inline(always)]
pub(super) fn rows_tex_fast<
    M: Madd,
    const AVX2: bool,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
>(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    u: &UnitPlan<'_>,
    env: FastEnv,
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    // Texels of the current chunk; lanes of skipped quads keep stale values, never used.
    let mut tex = [[[0u8; 4]; LANES]; 2];
    let reads_frag = env.reads_frag();
    let vector = AVX2 && crate::texture::fast_avx2::available();
    #[cfg(target_arch = "x86_64")]
    let simd = vector && crate::fragment::simd_tex::plan_ok(plan, fb);
    // `AVX2` is a constant: the other levels' copies do not contain the 8-wide code.
    #[cfg(target_arch = "x86_64")]
    if AVX2 && simd && fast::vec8_enabled() {
        // SAFETY: `simd` implies AVX2, FMA exactly when `M::FUSED` in the callers that
        // reach here, and a plan `plan_ok` accepts.
        unsafe {
            super::variants::with_fused!(M, |FMA| {
                vec8::rows::<FMA, DEPTH, FLAT, PERSP>(t, b, plan, u, env, fb, stats)
            })
        }
        return;
    }
    // A plan the register walk does not take (the stencil test, the alpha test, a partial
    // colour mask: MuJoCo's reflective floor) shades through the general 8-wide walk,
    // which computes the same bytes as this walk's per-lane shader, in registers.
    #[cfg(target_arch = "x86_64")]
    if AVX2 && vector && general_ok(plan, fb) {
        let units = std::slice::from_ref(u);
        // SAFETY: `general_ok` checked AVX2; this level's copy is compiled with FMA
        // exactly when `M::FUSED`.
        unsafe {
            super::variants::with_fused!(M, |FMA| {
                rows_general::<M, FMA, DEPTH, FLAT, PERSP>(t, b, plan, units, fb, stats)
            })
        }
        return;
    }
    #[cfg(target_arch = "x86_64")]
    let over = plan
        .blend
        .as_ref()
        .is_some_and(crate::fragment::simd::blend_is_over);
    for Chunk {
        qy,
        x,
        fx,
        fy,
        live,
    } in Chunks::new(t, b)
    {
        let fx = &fx;
        let oow = [
            one_over_w::<M, PERSP>(t, fx, fy[0]),
            one_over_w::<M, PERSP>(t, fx, fy[1]),
        ];
        let (s0, t0) = tex_coords_oow::<M, PERSP>(t, VARY_TEX, fx, fy[0], &oow[0]);
        let (s1, t1) = tex_coords_oow::<M, PERSP>(t, VARY_TEX, fx, fy[1], &oow[1]);
        fast::chunk_u8::<AVX2>(u, &[s0, s1], &[t0, t1], &live, vector, &mut tex);
        for r in 0..2 {
            if !live[r].iter().any(|&l| l) {
                continue;
            }
            #[cfg(target_arch = "x86_64")]
            if AVX2 && simd {
                let py = (qy + r as i64) as usize;
                let (x, l, tx) = (x as usize, &live[r], &tex[r]);
                // SAFETY: `simd` implies AVX2 (`fast_avx2::available`), FMA exactly when
                // `M::FUSED` in the callers that reach here, and a plan `plan_ok` accepts;
                // live lanes are inside the row.
                unsafe {
                    // The row of variant (fused, blend, over).
                    macro_rules! row {
                        ($f:literal, $b:literal, $o:literal) => {
                            tex_row::<$f, DEPTH, FLAT, PERSP, $b, $o>(
                                t, plan, env, fb, py, x, l, tx, stats,
                            )
                        };
                    }
                    match (M::FUSED, plan.blend.is_some(), over) {
                        (true, false, _) => row!(true, false, false),
                        (true, true, false) => row!(true, true, false),
                        (true, true, true) => row!(true, true, true),
                        (false, false, _) => row!(false, false, false),
                        (false, true, false) => row!(false, true, false),
                        (false, true, true) => row!(false, true, true),
                    }
                }
                continue;
            }
            let frag = if reads_frag {
                frag_colors::<M, FLAT, PERSP>(t, fx, fy[r], &oow[r])
            } else {
                [[0f32; LANES]; 4]
            };
            let c = fast::env_lanes(env, &tex[r], &frag);
            shade_chunk::<M, DEPTH, FLAT, PERSP, true>(
                t,
                plan,
                &[],
                ChunkColors::Ready(&c),
                fb,
                (qy + r as i64) as usize,
                x as usize,
                live[r],
                stats,
            );
        }
    }
}

/// Whether the general textured walk shades through [`rows_general`]: a CPU with AVX2,
/// the 8-wide walks not turned off (`SOFTGL_TEX_PATH=array` keeps the per-lane walk, to
/// compare the two), and a plan and target that
/// [`crate::fragment::simd_gen::plan_ok`] accepts.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) fn general_ok(plan: &FragPlan, fb: &Target<'_>) -> bool {
    crate::texture::fast_avx2::available()
        && fast::vec8_enabled()
        && crate::fragment::simd_gen::plan_ok(plan, fb)
}

/// The general textured walk (`rows_textured`) with the per-fragment work of each chunk
/// row on 8 lanes ([`crate::fragment::simd_gen::shade_row`]): the units are sampled as
/// the per-lane walk samples them, then every environment, the colour sum, fog, the
/// tests, blending and the store run in registers. The same bytes and counts.
///
/// # Safety
/// Must be called from a function compiled with AVX2 (and FMA when `FMA`, which is
/// `M::FUSED`), after [`general_ok`] accepted the plan and target.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) unsafe fn rows_general<
    M: Madd,
    const FMA: bool,
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
    // SAFETY: forwarded from the caller.
    unsafe {
        chunks_general::<M, FMA, DEPTH, FLAT, PERSP, true>(
            t,
            Chunks::new(t, b),
            plan,
            units,
            fb,
            stats,
        )
    }
}

/// [`rows_general`] over any walk of chunks: the triangles' [`Chunks`], or the chunks of
/// a line, point or stippled polygon (`prim_tex`). With `STR` the units that need an r
/// coordinate get it (the triangle walk); without, none does (`prim_tex`'s per-lane walk
/// samples them so).
///
/// # Safety
/// As [`rows_general`]; the live lanes of every chunk lie inside the target.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) unsafe fn chunks_general<
    M: Madd,
    const FMA: bool,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
    const STR: bool,
>(
    t: &SetupTriangle,
    chunks: impl Iterator<Item = Chunk>,
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    use crate::fragment::simd_gen::{
        depth_first, depth_pretest, early_tests, shade_row, shade_tested_row, test_row, GenPlan,
    };
    use crate::fragment::span::TexLanes;
    use crate::pipe::MAX_TEXTURE_UNITS;
    use crate::simd::I32x8;
    let g = GenPlan::new(plan, t, units);
    let early = early_tests(plan, &g, DEPTH);
    let pretest = !early && depth_first(plan, units, DEPTH);
    let (fragments, failed) = (stats.fragments, stats.alpha_failed);
    // As in `rows_textured`: reused across chunks, lanes not live keep stale values.
    let mut texels: [TexLanes; 2] = [[[[0.0; 4]; LANES]; MAX_TEXTURE_UNITS]; 2];
    for mut c in chunks {
        // The same columns of the chunk rows two rows down, reached after this pair's span:
        // the depth and colour loads of the floor's rows waited on the cache without this.
        for py in c.qy + 2..c.qy + 4 {
            super::prefetch_row(fb, py, c.x, c.x + LANES as i64 - 1, DEPTH, 1);
        }
        if early {
            // The tests first; only the lanes that pass are sampled and shaded.
            // SAFETY: the caller's AVX2 context.
            let mut pass = [unsafe { I32x8::zero() }; 2];
            let mut any = false;
            for r in 0..2 {
                if !c.live[r].iter().any(|&l| l) {
                    continue;
                }
                let (py, x) = ((c.qy + r as i64) as usize, c.x as usize);
                // SAFETY: forwarded from the caller; the live lanes lie inside row `py`.
                pass[r] = unsafe {
                    test_row::<FMA, DEPTH, FLAT, PERSP>(
                        t, plan, &g, units, fb, py, x, &c.live[r], stats,
                    )
                };
                let bits = pass[r].movemask();
                c.live[r] = LIVE_MASKS[bits as usize & 0xFF];
                any |= bits != 0;
            }
            if !any {
                continue;
            }
            // SAFETY: forwarded from the caller.
            let oow = unsafe { coords_and_sample::<M, FMA, PERSP, STR>(t, units, &c, &mut texels) };
            for r in 0..2 {
                let (py, x) = ((c.qy + r as i64) as usize, c.x as usize);
                // SAFETY: forwarded from the caller; the passing lanes lie inside row `py`.
                unsafe {
                    shade_tested_row::<FMA, FLAT, PERSP>(
                        t, plan, &g, units, &texels[r], fb, py, x, pass[r], oow[r], stats,
                    );
                }
            }
            continue;
        }
        if pretest {
            // Depth first, read-only: the lanes that fail it are not sampled.
            let mut any = false;
            for r in 0..2 {
                if !c.live[r].iter().any(|&l| l) {
                    continue;
                }
                let (py, x) = ((c.qy + r as i64) as usize, c.x as usize);
                // SAFETY: forwarded from the caller; the live lanes lie inside row `py`.
                let bits = unsafe { depth_pretest::<FMA>(t, plan, fb, py, x, &c.live[r], stats) };
                c.live[r] = LIVE_MASKS[bits as usize & 0xFF];
                any |= bits != 0;
            }
            if !any {
                continue;
            }
        }
        // SAFETY: forwarded from the caller.
        let oow = unsafe { coords_and_sample::<M, FMA, PERSP, STR>(t, units, &c, &mut texels) };
        for (r, (tex, live)) in texels.iter().zip(&c.live).enumerate() {
            if !live.iter().any(|&l| l) {
                continue;
            }
            let (py, x) = ((c.qy + r as i64) as usize, c.x as usize);
            // SAFETY: forwarded from the caller; the live lanes lie inside row `py`.
            unsafe {
                shade_row::<FMA, DEPTH, FLAT, PERSP>(
                    t, plan, &g, units, tex, fb, py, x, live, oow[r], stats,
                );
            }
        }
    }
    GenPlan::learn_alpha(
        plan,
        units,
        stats.fragments - fragments,
        stats.alpha_failed - failed,
    );
}

/// Whether [`rows_engine`] shades the triangle of box `b` drawn with `plan` and `units`,
/// by `SOFTGL_ENGINE` ([`crate::tuning::Engine`]). Where it is [`Engine::Auto`] (the
/// default), the engine takes the triangles on which it was measured faster than the
/// hand-written 8-lane walk (`docs/performance.md`, stop 63: `multitex_combine` 49 → 40 ms
/// on one thread): the walk would not test depth or stencil, an alpha test that reads
/// no texel, or depth before an alpha test that reads texels
/// ([`crate::fragment::simd_gen::depth_first`]), first (it samples only the lanes that
/// pass those tests, the engine every live lane), its combiners are ones the
/// walk interprets per row (two or more units, or one beyond a plain product), and the
/// box is large enough to fill the executor's batches ([`crate::tuning::ENGINE_MIN_BOX`]).
///
/// [`Engine::Auto`]: crate::tuning::Engine::Auto
#[inline(always)]
fn engine_takes(plan: &FragPlan, units: &[UnitPlan<'_>], b: [i64; 4]) -> bool {
    use crate::tuning::{Engine, ENGINE_MIN_BOX};
    match crate::engine::draw::mode() {
        Engine::Off => false,
        Engine::On => true,
        Engine::Auto => {
            let early = crate::fragment::simd_gen::alpha_early(plan, units)
                || crate::fragment::simd_gen::depth_first(plan, units, plan.depth.is_some())
                || plan.alpha.is_none() && (plan.depth.is_some() || plan.stencil.is_some());
            let interpreted = units.len() >= 2 || units.iter().any(|u| u.env.simple.is_none());
            let area = (b[2] - b[0] + 1).saturating_mul(b[3] - b[1] + 1);
            !early && interpreted && area >= ENGINE_MIN_BOX
        }
    }
}

/// The general textured walk through the engine ([`crate::engine::draw::Walk`]) when
/// [`engine_takes`] the triangle and the draw's state lowers (else `false`, and nothing is drawn): the units are
/// sampled as the walk that would draw the triangle today samples them (8-wide
/// coordinates where [`general_ok`], else per lane), and the per-fragment work of each
/// chunk row runs as the state's compiled program, a batch of rows at a time.
#[inline(always)]
pub(super) fn rows_engine<M: Madd, const AVX2: bool, const PERSP: bool>(
    t: &SetupTriangle,
    b: [i64; 4],
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    fb: &mut Target<'_>,
    stats: &mut Stats,
) -> bool {
    use crate::fragment::span::TexLanes;
    use crate::pipe::MAX_TEXTURE_UNITS;
    if !engine_takes(plan, units, b) {
        return false;
    }
    let Some(mut w) = crate::engine::draw::Walk::new(plan, units, PERSP, fb) else {
        return false;
    };
    w.begin(t, fb, stats);
    #[cfg(target_arch = "x86_64")]
    let wide = AVX2 && general_ok(plan, fb);
    let mut texels: [TexLanes; 2] = [[[[0.0; 4]; LANES]; MAX_TEXTURE_UNITS]; 2];
    for c in Chunks::new(t, b) {
        #[cfg(target_arch = "x86_64")]
        if wide {
            // SAFETY: `general_ok` checked AVX2; this level's copy is compiled with FMA
            // exactly when `M::FUSED`.
            unsafe {
                super::variants::with_fused!(M, |FMA| {
                    coords_and_sample::<M, FMA, PERSP, true>(t, units, &c, &mut texels)
                });
            }
        } else {
            super::sample_chunk::<M, PERSP, true>(t, units, &c, &mut texels);
        }
        #[cfg(not(target_arch = "x86_64"))]
        super::sample_chunk::<M, PERSP, true>(t, units, &c, &mut texels);
        for (r, (tex, live)) in texels.iter().zip(&c.live).enumerate() {
            let py = (c.qy + r as i64) as usize;
            w.row(fb, py, c.x as usize, live, tex, stats);
        }
    }
    w.end(fb, stats);
    true
}

/// `sample_chunk` of the 8-wide walk: every unit's projected coordinates of chunk `c` on
/// 8 lanes (the scalar walk's operations: `1 / w`, each varying times it, `1 / q`, and
/// s, t and r times that), then the unit sampled as that walk samples it
/// (`sample_unit`); r only with `STR`. Returns each row's `1 / w` (1.0 without `PERSP`).
///
/// # Safety
/// AVX2 context (FMA when `FMA`).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
pub(super) unsafe fn coords_and_sample<
    M: Madd,
    const FMA: bool,
    const PERSP: bool,
    const STR: bool,
>(
    t: &SetupTriangle,
    units: &[UnitPlan<'_>],
    c: &Chunk,
    texels: &mut [crate::fragment::span::TexLanes; 2],
) -> [crate::simd::F32x8; 2] {
    use crate::fragment::simd_gen::vary8;
    use crate::simd::F32x8;
    // SAFETY: the caller's AVX2 (+FMA) context; the stores write 8 f32 into 8-lane arrays.
    unsafe {
        let one = F32x8::splat(1.0);
        let fx = F32x8::load(c.fx.as_ptr());
        let fy = [F32x8::splat(c.fy[0]), F32x8::splat(c.fy[1])];
        let mut oow = [one; 2];
        if PERSP {
            for r in 0..2 {
                oow[r] = one.div(crate::fragment::simd_tex::eval8::<FMA>(&t.w, fx, fy[r]));
            }
        }
        for (k, u) in units.iter().enumerate() {
            let base = VARY_TEX + 4 * k;
            let needs_r = STR && u.needs_r();
            let mut s = [[0f32; LANES]; 2];
            let mut tt = [[0f32; LANES]; 2];
            let mut rr = [[0f32; LANES]; 2];
            for r in 0..2 {
                let rq = one.div(vary8::<FMA, PERSP>(t, base + 3, fx, fy[r], oow[r]));
                let sv = vary8::<FMA, PERSP>(t, base, fx, fy[r], oow[r]).mul(rq);
                let tv = vary8::<FMA, PERSP>(t, base + 1, fx, fy[r], oow[r]).mul(rq);
                sv.store(s[r].as_mut_ptr());
                tv.store(tt[r].as_mut_ptr());
                if needs_r {
                    let rv = vary8::<FMA, PERSP>(t, base + 2, fx, fy[r], oow[r]).mul(rq);
                    rv.store(rr[r].as_mut_ptr());
                }
            }
            let rr = if needs_r { Some(&rr) } else { None };
            super::sample_unit::<M>(u, k, &s, &tt, rr, &c.live, texels);
        }
        oow
    }
}
