//! Point sprites (GL_POINT_SPRITE): llvmpipe's quad rasterization of points
//! (`lp_setup_point.c`, `point_quad_rasterization`), with texture coordinates replaced
//! across the square.
//!
//! **Coverage.** The square has side `fw = max(256, iround(256·size))` in 1/256 pixel
//! (size capped at 255) and starts at `x0 = iround(256·(x − 0.5)) − fw/2` (likewise `y0`),
//! so that pixel `px` is sampled at `256·px`. Its edges follow the triangles' fill rule:
//! the left edge is inside and the right one outside; the top edge is inside under
//! llvmpipe's top-left rule (`bottom_edge_rule = 0`) and the bottom one under the
//! bottom-left rule. Points are never smoothed (Mesa turns GL_POINT_SMOOTH off with
//! sprites).
//!
//! **Coordinates** (`texcoord_coef`): for each replaced set, `s` is the plane
//! `dadx = 256/fw` (f32), `a0 = 0.5 − dadx·(x − 0.5)` (the subtraction in double, as the C
//! literal makes it), `t` the same along y with `dady = ±256/fw` (negative under
//! llvmpipe's `PIPE_SPRITE_COORD_LOWER_LEFT`), `r = 0` and `q = 1`. Texture coordinates
//! interpolate with perspective, so every coefficient is then multiplied by the point's
//! `1/w` (llvmpipe's `w0`), which the walk divides out again per pixel.
//!
//! **Every point replaces `gl_PointCoord`** with the same planes, sprite or not: legacy
//! square points (`lines::raster_point`, over their whole-pixel width) and multisampled
//! points (`ms_prims::point`) call [`replace_coords`] too, in upper-left mode unless a
//! sprite asks for lower-left (Mesa leaves `sprite_coord_mode` zero without sprites). A
//! NaN size draws one pixel, as llvmpipe's integer conversion of it does.

use super::lines::{point_planes, util_iround};
use super::prim_tex::BoxCover;
use super::Draw;
use crate::geometry::setup::{Plane, SetupTriangle};
use crate::geometry::ClipVertex;

/// The sprite state of a draw with GL_POINT_SPRITE on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Sprite {
    /// llvmpipe's `PIPE_SPRITE_COORD_LOWER_LEFT` (in raster rows): `t` decreases down
    /// the rows. Mesa derives it from GL_POINT_SPRITE_COORD_ORIGIN and whether the rows
    /// are flipped.
    pub lower_left: bool,
    /// Bit `i` set: varyings `i..i + 4` are a texture coordinate set that GL_COORD_REPLACE
    /// replaces.
    pub replace: u64,
}

/// llvmpipe's largest point (`LP_MAX_POINT_WIDTH`).
const MAX_WIDTH: f32 = 255.0;
/// Coordinates beyond this many pixels are not drawn (as the other point paths).
const MAX_COORD: f32 = (1u64 << 21) as f32;

/// The side of a sprite of `size` in 1/256 pixel.
pub(super) fn fixed_width(size: f32) -> i64 {
    util_iround(256.0 * size.min(MAX_WIDTH)).max(256)
}

/// Replaces the planes of `sprite`'s coordinate sets in `t` (the point's planes, `v` its
/// vertex, `fw` its side in 1/256 pixel).
pub(super) fn replace_coords(t: &mut SetupTriangle, v: &ClipVertex, fw: i64, sprite: &Sprite) {
    let w0 = v.win[3];
    let step = 256.0f32 / fw as f32;
    let (x0, y0) = (v.win[0] - 0.5, v.win[1] - 0.5);
    let dady = if sprite.lower_left { -step } else { step };
    let persp = |p: Plane| Plane {
        a0: p.a0 * w0,
        dadx: p.dadx * w0,
        dady: p.dady * w0,
    };
    let s = Plane {
        a0: (0.5 - f64::from(step * x0 + 0.0 * y0)) as f32,
        dadx: step,
        dady: 0.0,
    };
    let tt = Plane {
        a0: (0.5 - f64::from(0.0 * x0 + dady * y0)) as f32,
        dadx: 0.0,
        dady,
    };
    let r = Plane::default();
    let q = Plane {
        a0: 1.0,
        dadx: 0.0,
        dady: 0.0,
    };
    let mut bits = sprite.replace;
    while bits != 0 {
        let i = bits.trailing_zeros() as usize;
        bits &= bits - 1;
        for (k, p) in [s, tt, r, q].into_iter().enumerate() {
            if let Some(slot) = t.vary.get_mut(i + k) {
                *slot = persp(p);
            }
        }
    }
}

/// The pixels a sprite covers, `[x0, y0, x1, y1]` inclusive, before clipping.
fn covered(v: &ClipVertex, fw: i64, top_left: bool) -> [i64; 4] {
    let snap = |a: f32| util_iround(256.0 * (a - 0.5));
    let (x0, y0) = (snap(v.win[0]) - fw / 2, snap(v.win[1]) - fw / 2);
    let (x1, y1) = (x0 + fw, y0 + fw);
    let ceil = |a: i64| (a + 255) >> 8;
    let (top, bottom) = if top_left {
        (ceil(y0), ceil(y1) - 1)
    } else {
        ((y0 >> 8) + 1, y1 >> 8)
    };
    [ceil(x0), top, ceil(x1) - 1, bottom]
}

/// Draws `v` (inside the clip volume) as a sprite of `size` (single-sample).
pub fn point(
    v: &ClipVertex,
    size: f32,
    sprite: &Sprite,
    top_left: bool,
    nvary: usize,
    d: &mut Draw<'_, '_>,
) {
    let (x, y) = (v.win[0], v.win[1]);
    if !(x.abs() < MAX_COORD && y.abs() < MAX_COORD) {
        return;
    }
    let fw = fixed_width(size);
    let b = d.clip(covered(v, fw, top_left));
    if b[0] > b[2] || b[1] > b[3] {
        return;
    }
    let mut t = point_planes(v, nvary);
    replace_coords(&mut t, v, fw, sprite);
    let plan = d.plan;
    if let Some(sh) = &plan.shader {
        t.front = d.prim_front;
        super::shaded::covered(&t, b, &BoxCover, sh, d);
    } else if !d.units.is_empty() {
        super::prim_tex::shade_covered(&t, b, &BoxCover, d);
    } else {
        super::prim_spans::shade_rows(&t, b[1], b[3], |_| (b[0], b[2]), d);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(x: f32, y: f32) -> ClipVertex {
        ClipVertex {
            win: [x, y, 0.5, 1.0],
            ..Default::default()
        }
    }

    /// Squares measured on llvmpipe's rules by hand: a size-4 sprite centred on a pixel
    /// corner covers 4 pixels each way, one centred on a pixel centre (2.5) covers the 4
    /// whose centres lie inside or on its left/top edges, and the bottom-left rule moves
    /// the rows a tie falls on.
    #[test]
    fn coverage_follows_the_fill_rule() {
        let fw = fixed_width(4.0);
        assert_eq!(fw, 1024);
        // centre (10, 10): x0 = 9.5·256 − 512 = 1920 (7.5), x1 = 11.5 → pixels 8..=11
        assert_eq!(covered(&at(10.0, 10.0), fw, true), [8, 8, 11, 11]);
        // centre (10.5, 10.5): x0 = 8.0 exactly: left edge inside, right (12.0) outside
        assert_eq!(covered(&at(10.5, 10.5), fw, true), [8, 8, 11, 11]);
        // the bottom-left rule: the top edge (8.0) is out, the bottom one (12.0) in
        assert_eq!(covered(&at(10.5, 10.5), fw, false), [8, 9, 11, 12]);
        // tiny sprites are one pixel wide
        assert_eq!(fixed_width(0.1), 256);
        assert_eq!(fixed_width(1000.0), 255 * 256);
    }

    /// The replaced coordinates run from 0 to 1 across the square at pixel centres,
    /// `t` downwards unless lower-left, and `q` is 1.
    #[test]
    fn coordinates_span_the_square() {
        let v = at(10.5, 10.5);
        let mut t = point_planes(&v, 16);
        let sprite = Sprite {
            lower_left: false,
            replace: 1 << 12,
        };
        replace_coords(&mut t, &v, fixed_width(4.0), &sprite);
        let eval = |p: &Plane, x: f32, y: f32| p.a0 + p.dadx * x + p.dady * y;
        // pixel 8's sample is x = 8 in the shifted frame: s = 0.5 − 0.25·(10 − 8) = 0
        assert_eq!(eval(&t.vary[12], 8.0, 8.0), 0.0);
        assert_eq!(eval(&t.vary[12], 11.0, 8.0), 0.75);
        assert_eq!(eval(&t.vary[13], 8.0, 11.0), 0.75);
        assert_eq!(eval(&t.vary[14], 9.0, 9.0), 0.0);
        assert_eq!(eval(&t.vary[15], 9.0, 9.0), 1.0);
        let lower = Sprite {
            lower_left: true,
            ..sprite
        };
        replace_coords(&mut t, &v, fixed_width(4.0), &lower);
        assert_eq!(eval(&t.vary[13], 8.0, 8.0), 1.0);
    }
}
