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
// Lane loops index several arrays in step.
#![allow(clippy::needless_range_loop)]

use super::span::LANES;
use super::span::{alpha_test, chunk_colors, stencil_depth, store_chunk, StoreFormat};
use super::span::{ChunkAt, ChunkColors, Madd};
use super::{FragPlan, MsPass};
use crate::framebuffer::Target;
use crate::geometry::setup::SetupTriangle;
use crate::stats::Stats;
use crate::texture::UnitPlan;

/// Samples of a multisample pixel.
pub const SAMPLES: usize = crate::geometry::setup::SAMPLE_POS.len();

/// Shades the chunk of [`LANES`] pixels starting at `x` in row `py` whose sample s is
/// covered in the lanes `cov[s]`, and writes each covered sample into its plane (`fb`'s
/// own rows for sample 0, [`Target::samples`] for the others). `WIDE` for a wide target.
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn shade_chunk_ms<
    M: Madd,
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
    cov: &[[bool; LANES]; SAMPLES],
    stats: &mut Stats,
) {
    let ms = plan.ms.expect("a multisample plan");
    let w = fb.width;
    let n = LANES.min(w - x);
    let row = (py - fb.y0) * w + x;
    let mut live: [bool; LANES] = std::array::from_fn(|i| cov.iter().any(|c| c[i]));
    stats.fragments += live.iter().filter(|&&l| l).count() as u64;
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
    let out = StoreFormat::of(fb);
    let no_color = plan.color_mask == [false; 4];
    for s in 0..SAMPLES {
        if ms.mask & (1 << s) == 0 {
            continue;
        }
        let mut ls: [bool; LANES] = std::array::from_fn(|i| live[i] && cov[s][i]);
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
