//! Polygon stipple (GL_POLYGON_STIPPLE): llvmpipe's draw "pstipple" stage kills the
//! fragments whose window position falls on a zero bit of the 32x32 pattern; the state
//! tracker flips the pattern for the y-down window buffer, so the pattern is anchored at
//! GL window (0, 0) with row 0 at the bottom. A fragment shader's triangles take the same
//! coverage through the shader walk.

use super::lines::shade_span_dispatch;
use super::Draw;
use crate::fragment::span::Span;
use crate::geometry::setup::SetupTriangle;
use crate::pipe::PolygonStipple;

/// Rasterizes `t` inside the region, shading only the pixels the stipple lets through
/// (textured ones through [`super::prim_tex`]).
pub fn stippled_triangle(t: &SetupTriangle, stipple: &PolygonStipple, d: &mut Draw<'_, '_>) {
    let b = d.clip(t.bbox);
    let [x_lo, y_lo, x_hi, y_hi] = b;
    let h = d.fb.height as i64;
    let cover = super::prim_tex::StippleCover {
        edges: &t.edges,
        stipple,
        height: h,
        y_flip: d.fb.y_flip,
    };
    if let Some(sh) = &d.plan.shader {
        // The draw module's pstipple stage kills fragments in the program; the walk
        // gives the program only the covered pixels of each chunk.
        super::shaded::covered(t, b, &cover, sh, d);
        return;
    }
    if !d.units.is_empty() {
        super::prim_tex::shade_covered(t, b, &cover, d);
        return;
    }
    for py in y_lo..=y_hi {
        let (lo, hi) = t.cut_span(py, x_lo, x_hi);
        let gl_y = if d.fb.y_flip { h - 1 - py } else { py };
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
            shade_span_dispatch(t, d, Span::of(py, start, x - 1));
        }
    }
}
