//! The span shader of a one-pass 4x multisample triangle draw ([`super::MsPass`]): one
//! chunk of pixels shaded once, then written into each covered sample's plane.
//!
//! Why this is the four per-sample passes' result, byte for byte: colour, texturing, fog
//! and the alpha test depend on the pixel alone (attributes are evaluated at the pixel
//! centre whatever the sample), so computing them once for the pixels where any sample is
//! covered gives each sample the values its own pass computed; the texture coordinates of
//! a 2x2 quad are evaluated on the planes whether its pixels are covered or not, so a
//! quad's level of detail does not depend on which of its pixels are live. Everything
//! that differs per sample (coverage, alpha to coverage, stencil, depth at the sample
//! point, blending and the write) runs per sample on that sample's plane with the same
//! arithmetic as a pass. The planes share nothing, so drawing sample 0..4 of one chunk
//! before the next chunk gives each plane the same writes in the same order as drawing
//! the whole draw into one plane after the other.
//!
//! On AVX2 the per-sample half runs 8 lanes at a time ([`samples8`]), and chunks whose
//! colours the general shader computes (textured, specular, fog) take the single-sample
//! general walk's 8-lane colours too ([`shade_chunk_ms8`]): at MuJoCo's humanoid
//! 1920x1080 s4 the lane-by-lane shader was about a quarter of the walk.
// Lane loops index several arrays in step.
#![allow(clippy::needless_range_loop)]

#[cfg(target_arch = "x86_64")]
use super::simd::blend_is_over;
#[cfg(target_arch = "x86_64")]
use super::simd_gen::{alpha_test8, colors8, GenPlan};
#[cfg(target_arch = "x86_64")]
use super::simd_plane::{stencil_depth8, write8_in, Bits8};
#[cfg(target_arch = "x86_64")]
use super::span::TexLanes;
use super::span::LANES;
use super::span::{alpha_test, chunk_colors, stencil_depth, store_chunk, StoreFormat};
use super::span::{ChunkAt, ChunkColors, Madd};
use super::{FragPlan, MsPass};
use crate::framebuffer::Target;
use crate::geometry::setup::SetupTriangle;
#[cfg(target_arch = "x86_64")]
use crate::simd::{F32x8, I32x8};
use crate::stats::Stats;
use crate::texture::UnitPlan;

/// Samples of a multisample pixel.
pub const SAMPLES: usize = crate::geometry::setup::SAMPLE_POS.len();

/// Shades the chunk of [`LANES`] pixels starting at `x` in row `py` whose sample s is
/// covered in the lanes set in `cov[s]` (bit i for lane i), and writes each covered sample
/// into its plane (`fb`'s own rows for sample 0, [`Target::samples`] for the others).
/// `WIDE` for a wide target; `AVX2` when the walk is compiled for AVX2 (with FMA exactly
/// when `M` fuses), which runs the per-sample work 8 lanes at a time ([`samples8`]).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn shade_chunk_ms<
    M: Madd,
    const AVX2: bool,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
    const WIDE: bool,
>(
    t: &SetupTriangle,
    plan: &FragPlan,
    units: &[UnitPlan<'_>],
    source: ChunkColors<'_>,
    fb: &mut Target<'_>,
    py: usize,
    x: usize,
    cov: &[u8; SAMPLES],
    stats: &mut Stats,
) {
    let ms = plan.ms.expect("a multisample plan");
    let w = fb.width;
    let n = LANES.min(w - x);
    let row = (py - fb.y0) * w + x;
    let any = cov.iter().fold(0, |a, &c| a | c);
    let mut live: [bool; LANES] = std::array::from_fn(|i| any & (1 << i) != 0);
    stats.fragments += u64::from(any.count_ones());
    // Attributes at the pixel centre (integers and these offsets add exactly in f32).
    let fx: [f32; LANES] = std::array::from_fn(|i| (x + i) as f32 + 0.5);
    let fy = py as f32 + 0.5;
    let mut alpha = [0f32; LANES];
    let mut cf = [[0f32; LANES]; 4];
    let alpha_out = if ms.alpha_to_coverage {
        Some(&mut alpha)
    } else {
        None
    };
    let c = chunk_colors::<M, FLAT, PERSP, WIDE>(
        t, plan, units, source, &fx, fy, &mut live, alpha_out, &mut cf,
    );
    alpha_test(plan, &c, &mut live, n, stats);
    #[cfg(target_arch = "x86_64")]
    if AVX2 && !WIDE && samples8_ok(plan, fb) {
        let live = (0..n).fold(0u8, |a, i| a | (u8::from(live[i]) << i));
        // SAFETY: `AVX2` walks are compiled with AVX2, and with FMA exactly when `M`
        // fuses; lanes `n..` (past the row) are not live.
        unsafe {
            let mut px = I32x8::zero();
            for ch in 0..4 {
                px = px.or(I32x8::from_u8(c[ch]).shl_var(I32x8::splat(8 * ch as i32)));
            }
            let at = MsChunk {
                row,
                n,
                x,
                py,
                live,
                cov,
                alpha: &alpha,
                px,
            };
            if M::FUSED {
                samples8::<true, DEPTH>(t, plan, fb, &at, stats)
            } else {
                samples8::<false, DEPTH>(t, plan, fb, &at, stats)
            }
        }
        return;
    }
    let out = StoreFormat::of(fb);
    let no_color = plan.color_mask == [false; 4];
    for s in 0..SAMPLES {
        if ms.mask & (1 << s) == 0 {
            continue;
        }
        let mut ls: [bool; LANES] = std::array::from_fn(|i| live[i] && cov[s] & (1 << i) != 0);
        if ms.alpha_to_coverage {
            let threshold = MsPass::coverage_threshold(s);
            for i in 0..n {
                // NaN alpha keeps no sample, as the ordered compare.
                ls[i] &= alpha[i] > threshold;
            }
        }
        if !ls[..n].iter().any(|&l| l) {
            continue;
        }
        // Depth at the sample point.
        let [sx, sy] = MsPass::pos(s);
        let fx_z: [f32; LANES] = std::array::from_fn(|i| (x + i) as f32 + sx);
        let at = ChunkAt {
            row,
            n,
            fx: &fx_z,
            fy: py as f32 + sy,
        };
        let mut rows = fb.plane(s);
        stencil_depth::<M, DEPTH, true>(t, plan, &mut rows, &at, &mut ls, stats);
        if no_color || !ls[..n].iter().any(|&l| l) {
            continue;
        }
        store_chunk::<true, WIDE>(plan, out, &mut rows, (row, n), &ls, c, &cf, stats);
    }
}

/// Whether [`shade_chunk_ms8`] serves the plan on the 8-bit target `fb` for chunks
/// shaded by `shaded_colors` (textured, or untextured with the separate specular colour
/// or fog): what [`samples8`] serves, without antialiasing coverage or alpha to coverage
/// (which need the float alpha).
#[cfg(target_arch = "x86_64")]
pub fn colors8_ok(plan: &FragPlan, fb: &Target<'_>, textured: bool) -> bool {
    let ms = plan.ms.expect("a multisample plan");
    samples8_ok(plan, fb)
        && fb.wide.is_none()
        && !crate::fragment::span::float_store(plan, fb)
        && plan.smooth.is_none()
        && !ms.alpha_to_coverage
        && (textured || plan.separate_specular || plan.fog.is_some())
}

/// [`shade_chunk_ms`] of an AVX2 walk for a plan [`colors8_ok`] accepts, on 8 lanes
/// from the planes on: the colours of the chunk as the single-sample general walk
/// computes them ([`colors8`], the operations of `shaded_colors`: the pixel-centre lanes
/// `fx`, `fy` and their `1 / w` `oow`, the units' texels `tex`), the alpha test, then
/// [`samples8`]. The same bytes and counters as [`shade_chunk_ms`].
///
/// # Safety
/// AVX2 context (FMA exactly when `FMA`); `g` made from this plan, triangle and units;
/// the covered lanes lie inside row `py`.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub unsafe fn shade_chunk_ms8<
    const FMA: bool,
    const DEPTH: bool,
    const FLAT: bool,
    const PERSP: bool,
>(
    t: &SetupTriangle,
    plan: &FragPlan,
    g: &GenPlan,
    units: &[UnitPlan<'_>],
    tex: &TexLanes,
    fb: &mut Target<'_>,
    (py, x): (usize, usize),
    cov: &[u8; SAMPLES],
    oow: F32x8,
    stats: &mut Stats,
) {
    let w = fb.width;
    let n = LANES.min(w - x);
    let row = (py - fb.y0) * w + x;
    let any = cov.iter().fold(0, |a, &c| a | c);
    stats.fragments += u64::from(any.count_ones());
    // SAFETY: (whole body) forwarded from the caller.
    unsafe {
        let lane_bits = I32x8::new([1, 2, 4, 8, 16, 32, 64, 128]);
        // Pixel centres: integers and these offsets add exactly in f32.
        let fx = F32x8::splat(x as f32)
            .add(F32x8::new([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]))
            .add(F32x8::splat(0.5));
        let fy = F32x8::splat(py as f32 + 0.5);
        let (px, _) = colors8::<FMA, FLAT, PERSP>(t, plan, g, units, tex, fx, fy, oow);
        let mut live = I32x8::splat(i32::from(any)).and(lane_bits).cmpeq(lane_bits);
        live = alpha_test8(plan, px, live, stats);
        let alpha = [0f32; LANES];
        let at = MsChunk {
            row,
            n,
            x,
            py,
            live: live.movemask() as u8,
            cov,
            alpha: &alpha,
            px,
        };
        samples8::<FMA, DEPTH>(t, plan, fb, &at, stats);
    }
}

/// Whether [`samples8`] serves the plan on the 8-bit target `fb`: every plan but a
/// logic op, into every format but RGB565 (those keep the lane-by-lane store).
#[cfg(target_arch = "x86_64")]
#[inline(always)]
fn samples8_ok(plan: &FragPlan, fb: &Target<'_>) -> bool {
    plan.logic.is_none() && fb.format != crate::framebuffer::ColorFormat::Rgb565
}

/// A shaded chunk for [`samples8`]: where it is (`row` in the band's rows, `n` lanes
/// inside the row, first pixel `x` of row `py`), its live lanes after the alpha test and
/// each sample's coverage (bit i for lane i), the shaded alpha (for alpha to coverage)
/// and the 8-bit colours.
#[cfg(target_arch = "x86_64")]
struct MsChunk<'a> {
    /// Index of the first pixel in the band's rows.
    row: usize,
    /// Lanes inside the row.
    n: usize,
    /// First pixel's column.
    x: usize,
    /// Pixel row.
    py: usize,
    /// Live lanes.
    live: u8,
    /// Each sample's covered lanes.
    cov: &'a [u8; SAMPLES],
    /// Shaded alpha per lane.
    alpha: &'a [f32; LANES],
    /// The 8-bit colours, packed RGBA8 per lane.
    px: I32x8,
}

/// The per-sample half of [`shade_chunk_ms`] on an 8-bit target, 8 lanes at a time: each
/// drawn sample's lanes (coverage, live, alpha to coverage) as a mask, then on that
/// sample's plane the stencil test, the depth test at the sample point
/// ([`depth_test8`]), the stencil updates and the colour write ([`write8_in`]) — the
/// same operations the single-sample AVX2 paths run on a target's rows, giving what the
/// lane-by-lane loop gives.
///
/// # Safety
/// AVX2 (+FMA when `FMA`) context; lanes `at.n..` are not live.
#[cfg(target_arch = "x86_64")]
#[inline(always)]
unsafe fn samples8<const FMA: bool, const DEPTH: bool>(
    t: &SetupTriangle,
    plan: &FragPlan,
    fb: &mut Target<'_>,
    at: &MsChunk<'_>,
    stats: &mut Stats,
) {
    let ms = plan.ms.expect("a multisample plan");
    let (row, n) = (at.row, at.n);
    let stencil = plan.stencil.map(|s| if t.front { s.front } else { s.back });
    let color = plan.color_mask != [false; 4];
    let bits = Bits8::of(plan.color_mask, fb.format);
    let over = plan.blend.as_ref().is_some_and(blend_is_over);
    // SAFETY: (whole body) forwarded from the caller; the masked accesses touch live
    // lanes only, inside the row.
    unsafe {
        let lane_bits = I32x8::new([1, 2, 4, 8, 16, 32, 64, 128]);
        let fx =
            F32x8::splat(at.x as f32).add(F32x8::new([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0]));
        let alpha = F32x8::load(at.alpha.as_ptr());
        let px = at.px;
        for s in 0..SAMPLES {
            let m = at.live & at.cov[s];
            if ms.mask & (1 << s) == 0 || m == 0 {
                continue;
            }
            let mut live = I32x8::splat(i32::from(m)).and(lane_bits).cmpeq(lane_bits);
            if ms.alpha_to_coverage {
                // NaN alpha keeps no sample (ordered compare).
                let threshold = F32x8::splat(MsPass::coverage_threshold(s));
                live = live.and(alpha.cmp_gt(threshold).bits());
                if live.movemask() == 0 {
                    continue;
                }
            }
            // Depth at the sample point.
            let [sx, sy] = MsPass::pos(s);
            let (fxs, fys) = (fx.add(F32x8::splat(sx)), F32x8::splat(at.py as f32 + sy));
            let rows = fb.plane(s);
            let (st, dp) = (&mut *rows.stencil, &mut *rows.depth);
            let sp = stencil.as_ref();
            live = stencil_depth8::<FMA, DEPTH>(
                t,
                plan,
                sp,
                st,
                dp,
                (row, n),
                (fxs, fys),
                live,
                stats,
            );
            if !color || live.movemask() == 0 {
                continue;
            }
            match (plan.blend.is_some(), over) {
                (false, _) => {
                    write8_in::<false, false>(plan, rows.color, row, n, live, px, bits, stats)
                }
                (true, false) => {
                    write8_in::<true, false>(plan, rows.color, row, n, live, px, bits, stats)
                }
                (true, true) => {
                    write8_in::<false, true>(plan, rows.color, row, n, live, px, bits, stats)
                }
            }
        }
    }
}

#[cfg(all(test, target_arch = "x86_64"))]
mod tests;
