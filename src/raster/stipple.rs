//! Polygon stipple (GL_POLYGON_STIPPLE): llvmpipe's draw "pstipple" stage kills the
//! fragments whose window position falls on a zero bit of the 32x32 pattern; the state
//! tracker flips the pattern for the y-down window buffer, so the pattern is anchored at
//! GL window (0, 0) with row 0 at the bottom.

use super::lines::shade_span_dispatch;
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::setup::SetupTriangle;
use crate::pipe::PolygonStipple;
use crate::stats::Stats;

/// Rasterizes `t` inside `region`, shading only the pixels the stipple lets through
/// (textured ones through [`super::prim_tex`]).
pub fn stippled_triangle(
    t: &SetupTriangle,
    stipple: &PolygonStipple,
    region: [i64; 4],
    plan: &FragPlan,
    units: &[crate::texture::UnitPlan<'_>],
    fb: &mut Target<'_>,
    stats: &mut Stats,
) {
    let x_lo = t.bbox[0].max(region[0]);
    let x_hi = t.bbox[2].min(region[2] - 1);
    let y_lo = t.bbox[1].max(region[1]).max(fb.y0 as i64);
    let y_hi = t.bbox[3]
        .min(region[3] - 1)
        .min((fb.y0 + fb.rows) as i64 - 1);
    let h = fb.height as i64;
    if !units.is_empty() {
        let cover = super::prim_tex::StippleCover {
            edges: &t.edges,
            stipple,
            height: h,
            y_flip: fb.y_flip,
        };
        let b = [x_lo, y_lo, x_hi, y_hi];
        super::prim_tex::shade_covered(t, b, &cover, plan, units, fb, stats);
        return;
    }
    for py in y_lo..=y_hi {
        let (lo, hi) = t.cut_span(py, x_lo, x_hi);
        let gl_y = if fb.y_flip { h - 1 - py } else { py };
        let mut x = lo;
        while x <= hi {
            if !stipple.passes(x, gl_y) {
                x += 1;
                continue;
            }
            let start = x;
            while x <= hi && stipple.passes(x, gl_y) {
                x += 1;
            }
            shade_span_dispatch(
                t,
                plan,
                fb,
                py as usize,
                start as usize,
                (x - 1) as usize,
                stats,
            );
        }
    }
}
