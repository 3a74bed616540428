//! The AVX2 per-fragment half of the general textured walk (`raster::rows_textured`): one
//! row of a chunk (8 pixels) whose units are sampled, in 256-bit registers from the
//! planes to the store, for any number of units and any texture environment, with the
//! separate specular colour, fog, the alpha test, stencil, depth, blending and the colour
//! mask.
//!
//! It computes exactly what [`super::span::shade_chunk`] computes for
//! [`super::span::ChunkColors::Textured`]: the primary colour and `1 / w` as
//! [`super::simd_tex`] evaluates them (fused only in the FMA variant), every unit's
//! combiner through [`crate::texture::env::Combine::apply8`] (the scalar combiner's
//! operations on eight lanes), the specular sum and the fog blend unfused, the fog
//! factor on 8 lanes by [`crate::fixed_function::fog::FogPlan::factor8`] (its scalar
//! function's bits), `unorm8` as clamp
//! (NaN → 0), ·255 and `cvtps2dq`; depth and blending as [`super::simd`], the stencil
//! test and its updates as [`super::simd_plane`] (8 lanes, the multisample shader's).
//! A wide target (16-bit or float buffer) takes the float colours before the 8-bit
//! conversion to its own 8-lane store ([`super::simd_wide`]). The walk of untextured
//! triangles the AVX2 span shader leaves comes here too, with no units
//! (`raster::untextured`).

#![cfg(target_arch = "x86_64")]
// Lane loops index several arrays in step.
#![allow(clippy::needless_range_loop)]

use super::simd::{blend8, blend_is_over, depth_pass, eval, over8, sat, store_masked};
use super::simd_plane::stencil_depth8;
use super::span::{TexLanes, LANES};
use super::{FragPlan, StencilFacePlan};
use crate::framebuffer::{ColorFormat, Target};
use crate::geometry::setup::SetupTriangle;
use crate::geometry::{VARY_FOG, VARY_SPEC};
use crate::pipe::MAX_TEXTURE_UNITS;
use crate::simd::{F32x8, I32x8};
use crate::stats::Stats;
use crate::texture::env::vec8::{Inputs8, Vec4};
use crate::texture::UnitPlan;

/// Whether [`shade_row`] covers this plan and target: an 8-bit colour format stored as
/// RGBA8 unchanged (blended or logic-opped), or a wide buffer (stored by
/// [`super::simd_wide`]); no sRGB writes, no antialiasing coverage and no one-pass
/// multisampling (those keep the general span shader).
pub fn plan_ok(plan: &FragPlan, fb: &Target<'_>) -> bool {
    plan.smooth.is_none()
        && plan.ms.is_none()
        && !plan.srgb
        && (fb.wide.is_some()
            || matches!(
                fb.format,
                ColorFormat::Rgba | ColorFormat::Bgra | ColorFormat::Argb
            ))
}

/// What [`shade_row`] needs of the plan and triangle, worked out once per triangle.
#[derive(Clone, Copy)]
pub struct GenPlan {
    /// The stencil face of the triangle, when the stencil test is on.
    stencil: Option<StencilFacePlan>,
    /// The blend is [`blend_is_over`].
    over: bool,
    /// The number of units a crossbar environment reads (0 without one).
    crossbar: usize,
    /// The colour mask as a byte mask of a packed RGBA8 pixel.
    mask: i32,
    /// [`alpha_early`]: the alpha test runs in [`test_row`], before sampling.
    alpha_early: bool,
}

impl GenPlan {
    /// The per-triangle form of `plan` for `t`'s face and `units`.
    pub fn new(plan: &FragPlan, t: &SetupTriangle, units: &[UnitPlan<'_>]) -> Self {
        let mut mask = 0u32;
        for (ch, &m) in plan.color_mask.iter().enumerate() {
            if m {
                mask |= 0xFF << (8 * ch);
            }
        }
        GenPlan {
            stencil: plan.stencil.map(|s| if t.front { s.front } else { s.back }),
            over: plan.blend.as_ref().is_some_and(blend_is_over),
            crossbar: if units.iter().any(|u| u.env.crossbar) {
                units.len()
            } else {
                0
            },
            mask: mask as i32,
            alpha_early: alpha_early(plan, units) && alpha_history::worth_it(),
        }
    }

    /// Records, for a triangle drawn with this plan, that `failed` of its `fragments`
    /// failed the alpha test (the counters' growth while it was drawn), when its alpha
    /// test could run early ([`alpha_early`]).
    #[inline(always)]
    pub fn learn_alpha(plan: &FragPlan, units: &[UnitPlan<'_>], fragments: u64, failed: u64) {
        if alpha_early(plan, units) {
            alpha_history::record(fragments, failed);
        }
    }
}

/// How often the alpha tests that could run early killed fragments lately, on this
/// thread: running the test first costs the alpha's computation a second time (about
/// 15% of a frame of wide lines whose alpha test passes everything, sweep state 141), and
/// saves sampling and shading the fragments it kills (half the frame of state 68). The
/// test runs first while at least one fragment in eight failed it in the recent past.
/// Which path a triangle takes changes no byte and no count, so this history (per thread,
/// in whatever order the threads draw) is free to differ between runs.
mod alpha_history {
    use std::cell::Cell;

    thread_local! {
        /// (fragments, of which failed) recently, halved past [`WINDOW`].
        static SEEN: Cell<(u64, u64)> = const { Cell::new((0, 0)) };
    }

    /// Fragments below which the history is too short to say no.
    const WARM_UP: u64 = 512;
    /// The history's length: both counts halve when the fragments pass it.
    const WINDOW: u64 = 1 << 16;

    /// Whether the test should run first.
    #[inline(always)]
    pub(super) fn worth_it() -> bool {
        let (seen, failed) = SEEN.with(Cell::get);
        seen < WARM_UP || failed * 8 >= seen
    }

    /// Adds a triangle's fragments and failures.
    #[inline(always)]
    pub(super) fn record(fragments: u64, failed: u64) {
        SEEN.with(|c| {
            let (mut seen, mut f) = c.get();
            seen += fragments;
            f += failed;
            if seen > WINDOW {
                seen /= 2;
                f /= 2;
            }
            c.set((seen, f));
        });
    }
}

/// Whether a draw's alpha test can run before its units are sampled: it has one, and no
/// unit's alpha reads a texel ([`crate::texture::env::Combine::alpha_reads_texels`]:
/// an RGB, luminance or RGB5 texture under REPLACE, MODULATE, ADD or DECAL, a GL_COMBINE
/// alpha of the primary colour and constants …), so that the alpha a fragment will have
/// is known from its colour planes alone. The colour sum and fog change RGB only. Then
/// [`test_row`] computes that alpha ([`alpha8`]), runs the alpha test and the stencil and
/// depth tests, and only the lanes that pass are sampled and shaded, as llvmpipe's
/// compiled shader skips the sampling of quads its alpha test killed (sweep state 68,
/// flat-shaded fans whose alpha test fails everywhere: `docs/performance.md`, stop 69).
#[inline(always)]
pub fn alpha_early(plan: &FragPlan, units: &[UnitPlan<'_>]) -> bool {
    plan.alpha.is_some()
        && !units.iter().any(|u| u.env.alpha_reads_texels())
        && crate::tuning::tuning().alpha_early
}

/// Whether the general textured walk tests depth before sampling ([`depth_pretest`]): the
/// draw has an alpha test that reads texels (so not [`alpha_early`]), a depth test that
/// can fail and no stencil test (whose depth-fail update must wait for the alpha test).
/// This is llvmpipe's early depth test with a late depth write, which it chooses when a
/// shader can kill fragments and the stencil buffer is not written: the fragments that
/// fail depth are never sampled (sweep state 23, whose every fragment fails a read-only
/// LEQUAL after an alpha test of a blended texel). The bytes are those of the test in GL
/// order, since a fragment killed by either test leaves nothing; of the counters, a
/// fragment that would fail both counts as `depth_failed` rather than `alpha_failed`.
#[inline(always)]
pub fn depth_first(plan: &FragPlan, units: &[UnitPlan<'_>], depth: bool) -> bool {
    depth
        && plan.alpha.is_some()
        && plan.stencil.is_none()
        && plan
            .depth
            .is_some_and(|d| d.func != crate::pipe::CompareFunc::Always)
        && units.iter().any(|u| u.env.alpha_reads_texels())
        && crate::tuning::tuning().depth_first
}

/// The read-only depth test of [`depth_first`] on the `live` lanes of the 8 pixels from
/// `x` in row `py`: returns the lanes that pass as bits (bit i: lane i), and counts the
/// lanes that fail as fragments that read depth and failed it. The lanes that pass are
/// counted, tested again and written by [`shade_row`].
///
/// # Safety
/// As [`shade_row`]; the plan has a depth test.
#[inline(always)]
pub unsafe fn depth_pretest<const FMA: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    fb: &mut Target<'_>,
    py: usize,
    x: usize,
    live: &[bool; LANES],
    stats: &mut Stats,
) -> u32 {
    let bits = live_bits(live);
    let d = plan.depth.expect("depth_first implies a depth plan");
    // SAFETY: forwarded from the caller; the probe reads inside the depth rows and
    // stores nothing.
    let pass = unsafe {
        let (fx, fy) = row_xy(x, py);
        let idx = (py - fb.y0) * fb.width + x;
        super::simd::depth_probe8::<FMA>(t, &d, fb.depth, idx, fx, fy, mask_of(bits))
            .0
            .movemask()
    };
    let failed = u64::from((bits & !pass).count_ones());
    stats.fragments += failed;
    stats.depth_reads += failed;
    stats.depth_failed += failed;
    pass & bits
}

/// Lanes `0..8` as f32.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn lanes_f() -> F32x8 {
    // SAFETY: the caller's AVX2 context.
    unsafe { F32x8::new([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]) }
}

/// The pixel coordinates of the 8 lanes of row `py` from `x`: `x + lane` and `py`, as f32.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn row_xy(x: usize, py: usize) -> (F32x8, F32x8) {
    // SAFETY: the caller's AVX2 context.
    unsafe {
        (
            F32x8::splat(x as f32).add(lanes_f()),
            F32x8::splat(py as f32),
        )
    }
}

/// The lane mask of the bits of `m` (bit i: lane i).
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn mask_of(m: u32) -> I32x8 {
    // SAFETY: the caller's AVX2 context.
    unsafe {
        let bits = I32x8::new([1, 2, 4, 8, 16, 32, 64, 128]);
        I32x8::splat(m as i32).and(bits).cmpeq(bits)
    }
}

/// Varying `k` at the row's lanes: its plane, times `oow` when `PERSP`.
///
/// # Safety
/// AVX2 context (FMA when `FMA`).
#[inline(always)]
pub unsafe fn vary8<const FMA: bool, const PERSP: bool>(
    t: &SetupTriangle,
    k: usize,
    fx: F32x8,
    fy: F32x8,
    oow: F32x8,
) -> F32x8 {
    // SAFETY: the caller's AVX2 (+FMA) context.
    unsafe {
        let a = eval::<FMA>(&t.vary[k], fx, fy);
        if PERSP {
            a.mul(oow)
        } else {
            a
        }
    }
}

/// `v`'s lanes `[0, 2, 4, 6, 1, 3, 5, 7]` back in order.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn interleave(v: F32x8) -> F32x8 {
    // SAFETY: the caller's AVX2 context.
    unsafe {
        v.bits()
            .permute_var(I32x8::new([0, 4, 1, 5, 2, 6, 3, 7]))
            .as_f32()
    }
}

/// One unit's texel values of 8 lanes (RGBA per lane) as four channel registers.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn channels(l: &[[f32; 4]; LANES]) -> Vec4 {
    // SAFETY: the caller's AVX2 context; `l` is 32 contiguous f32.
    unsafe {
        let p = l.as_ptr() as *const f32;
        // Two lanes' RGBA per register: (0, 1), (2, 3), (4, 5), (6, 7).
        let (v0, v1, v2, v3) = (
            F32x8::load(p),
            F32x8::load(p.add(8)),
            F32x8::load(p.add(16)),
            F32x8::load(p.add(24)),
        );
        // Per 128-bit half: r g of lanes (0, 2) | (1, 3), b a of the same, then of 4–7.
        let rg03 = v0.shuffle::<0x44>(v1);
        let ba03 = v0.shuffle::<0xEE>(v1);
        let rg47 = v2.shuffle::<0x44>(v3);
        let ba47 = v2.shuffle::<0xEE>(v3);
        [
            interleave(rg03.shuffle::<0x88>(rg47)),
            interleave(rg03.shuffle::<0xDD>(rg47)),
            interleave(ba03.shuffle::<0x88>(ba47)),
            interleave(ba03.shuffle::<0xDD>(ba47)),
        ]
    }
}

/// The packed RGBA8 colours of the row's lanes, as [`super::span`]'s `shaded_colors`
/// computes them from the units' texels `tex`, and the float colours they were converted
/// from (what a wide buffer stores).
///
/// # Safety
/// AVX2 context (FMA when `FMA`).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub(crate) unsafe fn colors8<const FMA: bool, const FLAT: bool, const PERSP: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    g: &GenPlan,
    units: &[UnitPlan<'_>],
    tex: &TexLanes,
    fx: F32x8,
    fy: F32x8,
    oow: F32x8,
) -> (I32x8, Vec4) {
    // SAFETY: the caller's AVX2 (+FMA) context.
    unsafe {
        let mut frag = [F32x8::zero(); 4];
        for (ch, f) in frag.iter_mut().enumerate() {
            *f = if FLAT {
                F32x8::splat(t.flat[ch])
            } else {
                vary8::<FMA, PERSP>(t, ch, fx, fy, oow)
            };
        }
        // Every unit's texels, for a crossbar environment only: zeroing a table of them per
        // row was a 896-byte `memset` call, 5% of buffer_ushort's profile.
        let all;
        let textures: &[Vec4] = if g.crossbar == 0 {
            &[]
        } else {
            let mut table = [[F32x8::zero(); 4]; MAX_TEXTURE_UNITS];
            for (k, tv) in table.iter_mut().enumerate().take(units.len()) {
                *tv = channels(&tex[k]);
            }
            all = table;
            &all[..g.crossbar]
        };
        let mut prev = frag;
        for (k, u) in units.iter().enumerate() {
            prev = u.env.apply8(&Inputs8 {
                frag,
                tex: channels(&tex[k]),
                prev,
                textures,
            });
        }
        if plan.separate_specular {
            for ch in 0..3 {
                let k = VARY_SPEC + ch;
                let s = if FLAT && k < VARY_FOG {
                    F32x8::splat(t.flat[k])
                } else {
                    vary8::<FMA, PERSP>(t, k, fx, fy, oow)
                };
                prev[ch] = prev[ch].add(s);
            }
        }
        if let Some(fog) = &plan.fog {
            let coord = vary8::<FMA, PERSP>(t, VARY_FOG, fx, fy, oow);
            // A `match`, not a closure: a closure loses this copy's target features.
            let f = match fog.factor8::<FMA>(coord) {
                Some(f) => f,
                None => {
                    // A plan that fuses differently from this copy: the scalar per lane.
                    let coord = coord.to_array();
                    let mut f = [0f32; LANES];
                    for i in 0..LANES {
                        f[i] = fog.factor(coord[i]);
                    }
                    F32x8::load(f.as_ptr())
                }
            };
            let gf = F32x8::splat(1.0).sub(f);
            for ch in 0..3 {
                prev[ch] = F32x8::splat(fog.color[ch]).mul(gf).add(prev[ch].mul(f));
            }
        }
        let mut acc = I32x8::zero();
        for (ch, c) in prev.iter().enumerate() {
            let u = sat(*c).mul(F32x8::splat(255.0)).to_i32();
            acc = acc.or(u.shl_var(I32x8::splat(8 * ch as i32)));
        }
        (acc, prev)
    }
}

/// The alpha byte [`colors8`] gives the row's lanes, in bits 24–31 as in its packed
/// colours, for units whose alpha reads no texel ([`alpha_early`]): the primary colour's
/// alpha through each unit's environment, with no texels and no RGB (which no alpha
/// reads), then saturated and made a byte as `colors8` makes it. The colour sum and fog
/// leave alpha alone.
///
/// # Safety
/// AVX2 context (FMA when `FMA`); [`alpha_early`] holds for the units.
#[inline(always)]
unsafe fn alpha8<const FMA: bool, const FLAT: bool, const PERSP: bool>(
    t: &SetupTriangle,
    g: &GenPlan,
    units: &[UnitPlan<'_>],
    fx: F32x8,
    fy: F32x8,
    oow: F32x8,
) -> I32x8 {
    // SAFETY: the caller's AVX2 (+FMA) context.
    unsafe {
        let zero = F32x8::zero();
        let a = if FLAT {
            F32x8::splat(t.flat[3])
        } else {
            vary8::<FMA, PERSP>(t, 3, fx, fy, oow)
        };
        let frag = [zero, zero, zero, a];
        let table = [[zero; 4]; MAX_TEXTURE_UNITS];
        let mut prev = frag;
        for u in units {
            prev = u.env.apply8(&Inputs8 {
                frag,
                tex: [zero; 4],
                prev,
                textures: &table[..g.crossbar],
            });
        }
        sat(prev[3])
            .mul(F32x8::splat(255.0))
            .to_i32()
            .shl_var(I32x8::splat(24))
    }
}

/// Shades the `live` lanes of the 8 pixels from `x` in row `py` whose units were sampled
/// into `tex` (see the module comment); `oow` is the row's `1 / w` (1.0 without `PERSP`).
///
/// # Safety
/// Must be called from a function compiled with AVX2 (and FMA when `FMA`), for a plan and
/// target that [`plan_ok`] accepts, with `g` made from this plan, triangle and units;
/// live lanes lie inside the row.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub unsafe fn shade_row<const FMA: bool, const DEPTH: bool, const FLAT: bool, const PERSP: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    g: &GenPlan,
    units: &[UnitPlan<'_>],
    tex: &TexLanes,
    fb: &mut Target<'_>,
    py: usize,
    x: usize,
    live: &[bool; LANES],
    oow: F32x8,
    stats: &mut Stats,
) {
    let n = LANES.min(fb.width - x);
    // SAFETY: (whole body) AVX2 (+FMA) context guaranteed by the caller; loads and
    // stores touch live (passing) lanes only, which lie in `x..x + n` of row `py`.
    unsafe {
        let live_v = row_mask(live, stats);
        let (fx, fy) = row_xy(x, py);
        let (px, pf) = colors8::<FMA, FLAT, PERSP>(t, plan, g, units, tex, fx, fy, oow);
        test_and_write::<FMA, DEPTH>(t, plan, g, fb, (py, x, n), (fx, fy), live_v, px, pf, stats);
    }
}

/// The tail of [`shade_row`] and [`shade_ready_row`]: the alpha test of the colours `px`
/// on the `live` lanes, the stencil and depth tests with their updates, and the write of
/// the passing lanes (`pf`: the float colours a wide target stores). `at` is the row, the
/// first pixel and the lanes inside the row; `fxy` the lanes' pixel coordinates.
///
/// # Safety
/// As [`shade_row`].
#[inline(always)]
#[allow(clippy::too_many_arguments)]
unsafe fn test_and_write<const FMA: bool, const DEPTH: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    g: &GenPlan,
    fb: &mut Target<'_>,
    (py, x, n): (usize, usize, usize),
    fxy: (F32x8, F32x8),
    live: I32x8,
    px: I32x8,
    pf: Vec4,
    stats: &mut Stats,
) {
    // SAFETY: (whole body) forwarded from the caller.
    unsafe {
        let live = alpha_test8(plan, px, live, stats);
        let idx = (py - fb.y0) * fb.width + x;
        let (st, dp) = (&mut *fb.stencil, &mut *fb.depth);
        let sp = g.stencil.as_ref();
        let pass = stencil_depth8::<FMA, DEPTH>(t, plan, sp, st, dp, (idx, n), fxy, live, stats);
        write_row::<FMA>(plan, g, fb, idx, n, pass, px, pf, stats);
    }
}

/// Whether [`test_row`] may run a row's tests before its colours: no alpha test (the only
/// per-fragment kill of fixed function; nothing after the tests reads their outcome but
/// the colour write) and a stencil or depth test, which can fail; or an alpha test that
/// reads no texel ([`alpha_early`]), which [`test_row`] then runs first. Sampling and
/// shading only the lanes that pass leaves the same bytes and counts, as llvmpipe's
/// early depth test does.
#[inline(always)]
pub fn early_tests(plan: &FragPlan, g: &GenPlan, depth: bool) -> bool {
    g.alpha_early || (plan.alpha.is_none() && (depth || g.stencil.is_some()))
}

/// The first half of [`shade_row`] for a plan where [`early_tests`] holds: counts the
/// `live` fragments of the 8 pixels from `x` in row `py`, runs the alpha test (of the
/// colours computed without texels, [`alpha_early`]), then the stencil and depth tests
/// with their updates, and returns the lanes that pass; [`shade_tested_row`] then
/// shades and stores those.
///
/// # Safety
/// As [`shade_row`].
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub unsafe fn test_row<const FMA: bool, const DEPTH: bool, const FLAT: bool, const PERSP: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    g: &GenPlan,
    units: &[UnitPlan<'_>],
    fb: &mut Target<'_>,
    py: usize,
    x: usize,
    live: &[bool; LANES],
    stats: &mut Stats,
) -> I32x8 {
    let n = LANES.min(fb.width - x);
    // SAFETY: forwarded from the caller; the tests touch live lanes only, inside the row.
    unsafe {
        let mut live_v = row_mask(live, stats);
        let (fx, fy) = row_xy(x, py);
        if g.alpha_early {
            // `1 / w` as `coords_and_sample` computes it for the shading that follows
            let one = F32x8::splat(1.0);
            let oow = if PERSP {
                one.div(super::simd_tex::eval8::<FMA>(&t.w, fx, fy))
            } else {
                one
            };
            let a = alpha8::<FMA, FLAT, PERSP>(t, g, units, fx, fy, oow);
            live_v = alpha_test8(plan, a, live_v, stats);
        }
        let idx = (py - fb.y0) * fb.width + x;
        let (st, dp) = (&mut *fb.stencil, &mut *fb.depth);
        stencil_depth8::<FMA, DEPTH>(
            t,
            plan,
            g.stencil.as_ref(),
            st,
            dp,
            (idx, n),
            (fx, fy),
            live_v,
            stats,
        )
    }
}

/// The second half of [`shade_row`] after [`test_row`]: the colours of the lanes of
/// `pass` (units sampled into `tex` for at least those lanes), blended and stored.
///
/// # Safety
/// As [`shade_row`]; `pass` is what [`test_row`] returned for this row.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub unsafe fn shade_tested_row<const FMA: bool, const FLAT: bool, const PERSP: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    g: &GenPlan,
    units: &[UnitPlan<'_>],
    tex: &TexLanes,
    fb: &mut Target<'_>,
    py: usize,
    x: usize,
    pass: I32x8,
    oow: F32x8,
    stats: &mut Stats,
) {
    let n = LANES.min(fb.width - x);
    // SAFETY: forwarded from the caller; the store touches the lanes of `pass` only.
    unsafe {
        if g.mask == 0 || pass.movemask() == 0 {
            return;
        }
        let (fx, fy) = row_xy(x, py);
        let (px, pf) = colors8::<FMA, FLAT, PERSP>(t, plan, g, units, tex, fx, fy, oow);
        write_row::<FMA>(
            plan,
            g,
            fb,
            (py - fb.y0) * fb.width + x,
            n,
            pass,
            px,
            pf,
            stats,
        );
    }
}

/// The per-fragment operations of [`shade_row`] (alpha test, stencil and depth, blending,
/// logic op, colour mask, store) on the `live` lanes of the 8 pixels from `x` in row
/// `py`, whose colours are ready: `c` as unorm8 channels and `cf` the float colours a wide
/// target stores. What [`super::span::shade_chunk`] does with
/// [`super::span::ChunkColors::Ready`] (`ReadyWide` for a wide target): the fragments of
/// the pixel rectangles of glDrawPixels, glCopyPixels and glBitmap.
///
/// # Safety
/// As [`shade_row`] (`g` made with no units).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub unsafe fn shade_ready_row<const FMA: bool, const DEPTH: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    g: &GenPlan,
    fb: &mut Target<'_>,
    py: usize,
    x: usize,
    live: &[bool; LANES],
    c: &[[u8; LANES]; 4],
    cf: &[[f32; LANES]; 4],
    stats: &mut Stats,
) {
    let n = LANES.min(fb.width - x);
    // SAFETY: (whole body) AVX2 (+FMA) context guaranteed by the caller; loads and
    // stores touch live (passing) lanes only, which lie in `x..x + n` of row `py`.
    unsafe {
        let live_v = row_mask(live, stats);
        let (fx, fy) = row_xy(x, py);
        let mut px = I32x8::zero();
        for (ch, bytes) in c.iter().enumerate() {
            px = px.or(I32x8::from_u8(*bytes).shl_var(I32x8::splat(8 * ch as i32)));
        }
        let pf = if fb.wide.is_some() {
            [
                F32x8::load(cf[0].as_ptr()),
                F32x8::load(cf[1].as_ptr()),
                F32x8::load(cf[2].as_ptr()),
                F32x8::load(cf[3].as_ptr()),
            ]
        } else {
            [F32x8::zero(); 4]
        };
        test_and_write::<FMA, DEPTH>(t, plan, g, fb, (py, x, n), (fx, fy), live_v, px, pf, stats);
    }
}

/// The `live` lanes as bits (bit i: lane i).
#[inline(always)]
fn live_bits(live: &[bool; LANES]) -> u32 {
    let mut bits = 0u32;
    for (i, &l) in live.iter().enumerate() {
        bits |= u32::from(l) << i;
    }
    bits
}

/// The `live` lanes as a mask, counted as fragments.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn row_mask(live: &[bool; LANES], stats: &mut Stats) -> I32x8 {
    let bits = live_bits(live);
    stats.fragments += u64::from(bits.count_ones());
    // SAFETY: the caller's AVX2 context.
    unsafe { mask_of(bits) }
}

/// The logic op `op` of packed RGBA8 sources `s` and destinations `d`, bit by bit (so
/// channel by channel, as [`crate::pipe::LogicOp::apply`]).
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn logic8(op: crate::pipe::LogicOp, s: I32x8, d: I32x8) -> I32x8 {
    use crate::pipe::LogicOp as L;
    // SAFETY: the caller's AVX2 context.
    unsafe {
        let ones = I32x8::splat(-1);
        match op {
            L::Clear => I32x8::zero(),
            L::And => s.and(d),
            L::AndReverse => s.and(d.xor(ones)),
            L::Copy => s,
            L::AndInverted => s.xor(ones).and(d),
            L::Noop => d,
            L::Xor => s.xor(d),
            L::Or => s.or(d),
            L::Nor => s.or(d).xor(ones),
            L::Equiv => s.xor(d).xor(ones),
            L::Invert => d.xor(ones),
            L::OrReverse => s.or(d.xor(ones)),
            L::CopyInverted => s.xor(ones),
            L::OrInverted => s.xor(ones).or(d),
            L::Nand => s.and(d).xor(ones),
            L::Set => ones,
        }
    }
}

/// Blends (or logic-ops) and stores the lanes of `pass` of the 8 pixels at `idx` (`n` inside the row)
/// with the packed colours `px` (8-bit targets) or the float ones `pf` (wide targets).
///
/// # Safety
/// AVX2 context (FMA when a wide store fuses); the lanes of `pass` lie in
/// `idx..idx + n`, inside the target's rows.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
unsafe fn write_row<const FMA: bool>(
    plan: &FragPlan,
    g: &GenPlan,
    fb: &mut Target<'_>,
    idx: usize,
    n: usize,
    pass: I32x8,
    px: I32x8,
    pf: Vec4,
    stats: &mut Stats,
) {
    // SAFETY: forwarded from the caller.
    unsafe {
        let passed = pass.movemask();
        if g.mask == 0 || passed == 0 {
            return;
        }
        if let Some(kind) = fb.wide {
            stats.color_writes += store_wide::<FMA>(plan, fb, kind, idx, n, pass, pf);
            return;
        }
        let cptr = fb.color.as_mut_ptr().add(idx) as *mut i32;
        let full = g.mask == -1;
        let mut out = px;
        if plan.blend.is_some() || plan.logic.is_some() || !full {
            let dst = I32x8::maskload(cptr as *const i32, pass);
            if let Some(b) = &plan.blend {
                stats.color_reads += n as u64;
                out = if g.over {
                    over8(px, dst)
                } else {
                    blend8(b, px, dst)
                };
            } else if let Some(op) = plan.logic {
                stats.color_reads += n as u64;
                out = logic8(op, px, dst);
            }
            if !full {
                let m = I32x8::splat(g.mask);
                out = out.and(m).or(dst.and(m.xor(I32x8::splat(-1))));
            }
        }
        store_masked(cptr, fb.color.len().saturating_sub(idx), pass, out);
        stats.color_writes += u64::from(passed.count_ones());
    }
}

/// The alpha test of the packed colours `px` on 8 lanes: the lanes of `live` whose alpha
/// byte passes the plan's test (all of them without one), the others counted as failed.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
pub unsafe fn alpha_test8(plan: &FragPlan, px: I32x8, live: I32x8, stats: &mut Stats) -> I32x8 {
    let Some((func, reference)) = plan.alpha else {
        return live;
    };
    // SAFETY: the caller's AVX2 context.
    let kept = unsafe {
        let ok = depth_pass(func, px.shr::<24>(), I32x8::splat(i32::from(reference)));
        live.and(ok)
    };
    let failed = live.movemask().count_ones() - kept.movemask().count_ones();
    stats.alpha_failed += u64::from(failed);
    kept
}

/// Stores the lanes of `pass` of the 8 pixels at `idx` (`n` inside the row) of wide
/// target `fb` (precision `kind`) with the float colours `pf`: on 8 lanes
/// ([`super::simd_wide`]) where it covers the store, else pixel by pixel
/// ([`super::wide::store`]). Returns the pixels written.
///
/// # Safety
/// AVX2 context (FMA when `FMA`); the lanes of `pass` lie in `idx..idx + n`, inside the
/// target's rows.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
unsafe fn store_wide<const FMA: bool>(
    plan: &FragPlan,
    fb: &mut Target<'_>,
    kind: crate::framebuffer::WideKind,
    idx: usize,
    n: usize,
    pass: I32x8,
    pf: Vec4,
) -> u64 {
    let dst = super::wide::WideDst {
        kind,
        alpha: fb.format.has_alpha(),
        single: fb.wide_single,
    };
    if super::simd_wide::covers(dst, plan, FMA) {
        // SAFETY: forwarded from the caller; `covers` accepted the store.
        return unsafe {
            super::simd_wide::store8::<FMA>(
                dst,
                plan,
                &mut *fb.color,
                &mut *fb.wide_color,
                idx,
                pass,
                pf,
            )
        };
    }
    let bits = pass.movemask();
    let live: [bool; LANES] = std::array::from_fn(|i| bits & (1 << i) != 0);
    // Not `pf.map(..)`: the generic `map` is not inlined into this AVX2 function, and its
    // closure then stores each register through an out-of-line `_mm256_storeu_ps`.
    let cf = [
        pf[0].to_array(),
        pf[1].to_array(),
        pf[2].to_array(),
        pf[3].to_array(),
    ];
    super::wide::store(dst, plan, &mut fb.plane(0), idx, n, &live, &cf)
}
