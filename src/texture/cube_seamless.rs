//! GL_TEXTURE_CUBE_MAP_SEAMLESS: LINEAR filtering that reads across the face edges, as
//! llvmpipe does it (`lp_build_sample_image_linear` with `seamless_cube_filter`, and
//! `lp_build_cube_new_coords`, in `gallivm/lp_bld_sample*.c`).
//!
//! - The face and its coordinates come from the same projection and LOD (per pixel when
//!   mipmapped) as without seamless filtering ([`super::cube`]). llvmpipe samples on the float (SoA)
//!   path whenever a cube map is seamless and either image filter is LINEAR, so the plan
//!   is never `aos` then; NEAREST filtering is unchanged (CLAMP_TO_EDGE on the face).
//! - On a level of size `n`: `u = max(s, 0)·n − 0.5` (NaN → 0; no clamp), `x0 = floor(u)`,
//!   `x1 = x0 + 1`, weight `u − floor(u)`; likewise y. A tap outside the face
//!   (`x0 < 0`, `x1 > n−1`, `y0 < 0`, `y1 > n−1`) is read from the neighbouring face, at
//!   the texel across the shared edge ([`neighbours`] tabulates gallium's rules; the y of
//!   an x-neighbour is first clamped into the face, so a tap that falls off both axes
//!   reads a texel of the x-neighbour).
//! - Taps inside the face, and lanes with no edge, filter as usual:
//!   `lerp(t, lerp(s, n00, n01), lerp(s, n10, n11))`, each lerp `fmuladd`.
//! - **Corners**: a tap that falls off both axes has no texel. When any pixel of the
//!   vector llvmpipe samples together (here: the 2x2 quad) has such a tap, every pixel of
//!   it is filtered as a weighted sum instead: `w00 = (1−fs)(1−ft)`, `w01 = fs(1−ft)`,
//!   `w10 = (1−fs)ft`, `w11 = fs·ft`; a third of the missing corner's weight
//!   (`w·f32(1/3)`) is added to each of the other three and the corner's becomes 0; the
//!   colour is `((w00·n00 + w01·n01) + w10·n10) + w11·n11`, separate multiplies and adds.

use super::cube::{project, quad_levels, Faces};
use super::sample::{lerpfx4, sample_levels_in, texel_float};
use super::{Filter, Level, UnitPlan};

/// A texel: face, x, y.
type At = (usize, usize, usize);

/// The four taps of one pixel on one level, in llvmpipe's order n00, n01, n10, n11
/// (x0y0, x1y0, x0y1, x1y1).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Taps {
    /// Where each tap reads.
    at: [At; 4],
    /// The s and t weights.
    w: [f32; 2],
    /// Which tap is a missing corner texel.
    corner: [bool; 4],
}

/// The texels across each edge of `face` (`max` = size − 1): for the edges x−, x+, y−,
/// y+ the neighbouring face, and the `(x, y)` there of the taps at rows `y0`, `y1` (x
/// edges) or columns `x0`, `x1` (y edges). Gallium's table, written out per face.
#[allow(clippy::type_complexity)]
fn neighbours(
    face: usize,
    (x0, x1): (i32, i32),
    (y0, y1): (i32, i32),
    max: i32,
) -> ([usize; 4], [[(i32, i32); 2]; 4]) {
    // faces: +X −X +Y −Y +Z −Z
    let (pos_y_or_neg_y, low_face) = ((face & !4) > 1, face < 2);
    let odd = face & 1 == 1;
    let x_minus = if !low_face {
        usize::from(face != 5)
    } else {
        (face & 1) + 4
    };
    let y_plus = if pos_y_or_neg_y { face + 2 } else { 3 };
    let next = [x_minus, x_minus ^ 1, y_plus ^ 1, y_plus];
    // x edges: the row's y becomes an x on ±Y, stays y elsewhere
    let xe = |y: i32| {
        let x_plus_x = if pos_y_or_neg_y {
            if face == 2 {
                max - y
            } else {
                y
            }
        } else {
            0
        };
        let yy = if pos_y_or_neg_y {
            if face == 2 {
                0
            } else {
                max
            }
        } else {
            y
        };
        ((max - x_plus_x, yy), (x_plus_x, yy))
    };
    // y edges: the column's x
    let ye = |x: i32| {
        let x_plus_y = if !low_face {
            if odd {
                max - x
            } else {
                x
            }
        } else if odd {
            0
        } else {
            max
        };
        let y_plus_y = if !low_face {
            if odd {
                max
            } else {
                0
            }
        } else if odd {
            max - x
        } else {
            x
        };
        let x_minus_y = if pos_y_or_neg_y {
            max - x_plus_y
        } else {
            x_plus_y
        };
        let y_minus_y = if pos_y_or_neg_y {
            y_plus_y
        } else {
            max - y_plus_y
        };
        ((x_minus_y, y_minus_y), (x_plus_y, y_plus_y))
    };
    let ((xm0, xp0), (xm1, xp1)) = (xe(y0), xe(y1));
    let ((ym0, yp0), (ym1, yp1)) = (ye(x0), ye(x1));
    (next, [[xm0, xm1], [xp0, xp1], [ym0, ym1], [yp0, yp1]])
}

/// The taps of face coordinates `(s, t)` on a level of size `n`.
#[inline(always)]
fn taps(face: usize, s: f32, t: f32, n: usize) -> Taps {
    let size = n as f32;
    let max = n as i32 - 1;
    // max(c, 0) with a NaN giving 0, then ·n − 0.5 (two roundings), floor and fraction
    let split = |c: f32| {
        let u = if c > 0.0 { c } else { 0.0 } * size - 0.5;
        let f = u.floor();
        (f as i32, u - f)
    };
    let ((x0, fs), (y0, ft)) = (split(s), split(t));
    let (x1, y1) = (x0 + 1, y0 + 1);
    let off = [x0 < 0, x1 > max, y0 < 0, y1 > max];
    let (y0c, y1c) = (y0.max(0), y1.min(max));
    let (next, c) = neighbours(face, (x0, x1), (y0c, y1c), max);
    let mut at = [
        (face, x0, y0c),
        (face, x1, y0c),
        (face, x0, y1c),
        (face, x1, y1c),
    ];
    // x edges first (taps 00/10 on x−, 01/11 on x+) ...
    for (k, e) in [(0, 0), (2, 0), (1, 1), (3, 1)] {
        if off[e] {
            let (x, y) = c[e][k / 2];
            at[k] = (next[e], x, y);
        }
    }
    // ... then y edges, for the taps not already moved across an x edge
    for (k, e, xe) in [(0, 2, 0), (1, 2, 1), (2, 3, 0), (3, 3, 1)] {
        if off[e] && !off[xe] {
            let (x, y) = c[e][k % 2];
            at[k] = (next[e], x, y);
        }
    }
    // (every tap is inside its face for coordinates in [0, 1]; the clamp only guards reads)
    let inside = |v: i32| v.clamp(0, max) as usize;
    Taps {
        at: at.map(|(f, x, y)| (f, inside(x), inside(y))),
        w: [fs, ft],
        corner: [
            off[0] && off[2],
            off[1] && off[2],
            off[0] && off[3],
            off[1] && off[3],
        ],
    }
}

/// Filters one pixel's taps `n` (n00, n01, n10, n11): bilinear, or (`corners`: the
/// quad has a corner tap) the weighted sum of the module comment.
#[inline(always)]
fn filter(fma: bool, tp: &Taps, n: [[f32; 4]; 4], corners: bool) -> [f32; 4] {
    let [fs, ft] = tp.w;
    if !corners {
        let r0 = lerpfx4(fma, fs, n[0], n[1]);
        let r1 = lerpfx4(fma, fs, n[2], n[3]);
        return lerpfx4(fma, ft, r0, r1);
    }
    let (wx0, wy0) = (1.0 - fs, 1.0 - ft);
    let w = [wx0 * wy0, fs * wy0, wx0 * ft, fs * ft];
    // (llvmpipe selects c00, c01, c10, c11 in turn; at most one is a corner)
    let mut cw = 0.0;
    for (&wk, &corner) in w.iter().zip(&tp.corner) {
        if corner {
            cw = wk;
        }
    }
    let cw = cw * (1.0f32 / 3.0);
    let w: [f32; 4] = each4!(|k| if tp.corner[k] { 0.0 } else { w[k] + cw });
    each4!(|c| {
        let mut v = w[0] * n[0][c];
        v += w[1] * n[1][c];
        v += w[2] * n[2][c];
        v += w[3] * n[3][c];
        v
    })
}

/// One level per pixel of a quad, seamless LINEAR: `px` are the pixels' faces and
/// coordinates, `levels` the level each pixel reads.
#[inline(always)]
fn linear_level(
    p: &UnitPlan<'_>,
    faces: &Faces<'_>,
    levels: [usize; 4],
    px: &[(usize, f32, f32); 4],
) -> [[f32; 4]; 4] {
    let taps: [Taps; 4] = each4!(|i| {
        let (f, s, t) = px[i];
        let n = faces[f][levels[i]].as_ref().expect("cube complete").width;
        taps(f, s, t, n)
    });
    let corners = taps.iter().any(|tp| tp.corner.contains(&true));
    each4!(|i| {
        let tp = &taps[i];
        let img = |f: usize| -> &Level { faces[f][levels[i]].as_ref().expect("cube complete") };
        // Float and 16-bit cube maps keep their float texels (ARB_texture_float).
        let texels = each4!(|k| {
            let (f, x, y) = tp.at[k];
            let l = img(f);
            if p.ext.floats {
                l.ftexel(y * l.width + x)
            } else {
                texel_float(p, l.texel(x, y))
            }
        });
        filter(p.fma, tp, texels, corners)
    })
}

/// Samples a 2x2 quad (TL, TR, BL, BR) of direction vectors of a seamless cube map.
#[inline(always)]
pub fn sample_quad(
    p: &UnitPlan<'_>,
    faces: &Faces<'_>,
    s: [f32; 4],
    t: [f32; 4],
    r: [f32; 4],
) -> [[f32; 4]; 4] {
    let (sels, need_derivs) = quad_levels(p, s, t, r);
    let px: [(usize, f32, f32); 4] = each4!(|i| project(s[i], t[i], r[i], need_derivs));
    if sels.iter().all(|sel| sel.0 == Filter::Nearest) {
        return each4!(|i| {
            let (f, fs, ft) = px[i];
            sample_levels_in(p, faces[f], sels[i], fs, ft)
        });
    }
    let a = linear_level(p, faces, sels.map(|sel| sel.1), &px);
    let b = if sels.iter().any(|sel| sel.2 != sel.1) {
        linear_level(p, faces, sels.map(|sel| sel.2), &px)
    } else {
        a
    };
    each4!(|i| {
        let (f, fs, ft) = px[i];
        match sels[i] {
            (Filter::Nearest, ..) => sample_levels_in(p, faces[f], sels[i], fs, ft),
            (_, l0, l1, frac) if l1 != l0 => lerpfx4(p.fma, frac, a[i], b[i]),
            _ => a[i],
        }
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn inside_a_face_the_taps_stay_there() {
        let tp = taps(4, 0.5, 0.5, 4);
        assert_eq!(tp.at, [(4, 1, 1), (4, 2, 1), (4, 1, 2), (4, 2, 2)]);
        assert_eq!(tp.w, [0.5, 0.5]);
        assert_eq!(tp.corner, [false; 4]);
    }

    #[test]
    fn left_edge_of_pos_z_reads_neg_x() {
        // +Z's x− edge is −X's x+ edge (sc = rx on +Z, sc = rz on −X)
        let tp = taps(4, 0.0, 0.5, 4);
        assert_eq!(tp.at[0], (1, 3, 1));
        assert_eq!(tp.at[2], (1, 3, 2));
        assert_eq!(tp.at[1], (4, 0, 1));
    }

    #[test]
    fn corner_taps_are_marked() {
        let tp = taps(0, 0.0, 0.0, 4);
        assert_eq!(tp.corner, [true, false, false, false]);
    }
}
