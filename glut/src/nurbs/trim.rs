//! Trimmed surfaces: the trim loops become polylines in the (s, t) domain, each
//! patch's evaluation grid is cut by them (cells wholly inside are two triangles,
//! cells the loops cross are triangulated by the polygon tessellator with the cell's
//! rectangle added as one more contour and the ABS_GEQ_TWO rule, which keeps what is
//! inside both the cell and the loops), and the triangles are evaluated with
//! `glEvalCoord2f`. As in GLU, the region to the left of every loop is kept: outer
//! loops run counterclockwise, holes clockwise.

use super::bezier::curve_piece;
use super::render::Patch;
use super::{Nurbs, SurfDef, TrimPiece, OUTLINE_PATCH};
use crate::gl::*;
use crate::tess::{arrange, sweep, WINDING_ABS_GEQ_TWO};

const GL_EVAL_BIT: u32 = 0x0001_0000;
/// Samples per Bézier segment of a trim curve, per degree.
const TRIM_STEPS_PER_DEGREE: usize = 12;

/// A point of the parameter domain.
pub type Pt = [f64; 2];

/// The trim loops as closed polylines (last point not repeated).
pub fn polylines(geo: &SurfDef, loops: &[Vec<TrimPiece>]) -> Vec<Vec<Pt>> {
    if loops.is_empty() {
        let (s0, s1) = geo.s.range();
        let (t0, t1) = geo.t.range();
        let (s0, s1, t0, t1) = (f64::from(s0), f64::from(s1), f64::from(t0), f64::from(t1));
        return vec![vec![[s0, t0], [s1, t0], [s1, t1], [s0, t1]]];
    }
    let mut out = Vec::new();
    for l in loops {
        let mut poly: Vec<Pt> = Vec::new();
        for piece in l {
            match piece {
                TrimPiece::Pwl(p) => {
                    poly.extend(p.iter().map(|q| [f64::from(q[0]), f64::from(q[1])]))
                }
                TrimPiece::Curve(c) => {
                    let bp = c.basis.breakpoints();
                    let k = c.basis.order;
                    let n = TRIM_STEPS_PER_DEGREE * (k - 1).max(1);
                    for w in bp.windows(2) {
                        let p = curve_piece(&c.basis, &c.pts, c.dim, w[0], w[1]);
                        for i in 0..=n {
                            let u = i as f64 / n as f64;
                            let q = de_casteljau(&p, c.dim, u);
                            let (x, y) = if c.dim == 3 {
                                (q[0] / q[2], q[1] / q[2])
                            } else {
                                (q[0], q[1])
                            };
                            poly.push([x, y]);
                        }
                    }
                }
            }
        }
        poly.dedup();
        while poly.len() > 1 && poly.first() == poly.last() {
            poly.pop();
        }
        if poly.len() >= 3 && poly.iter().all(|p| p[0].is_finite() && p[1].is_finite()) {
            out.push(poly);
        }
    }
    out
}

/// A Bézier curve's point at u in [0, 1] (f64 de Casteljau).
pub fn de_casteljau(p: &[f32], dim: usize, u: f64) -> Vec<f64> {
    let mut w: Vec<f64> = p.iter().map(|&x| f64::from(x)).collect();
    let k = p.len() / dim;
    for r in 1..k {
        for j in 0..k - r {
            for c in 0..dim {
                w[j * dim + c] = (1.0 - u) * w[j * dim + c] + u * w[(j + 1) * dim + c];
            }
        }
    }
    w.truncate(dim);
    w
}

/// Winding number of the loops about a point.
fn winding(loops: &[Vec<Pt>], p: Pt) -> i32 {
    let mut w = 0;
    for l in loops {
        for i in 0..l.len() {
            let (a, b) = (l[i], l[(i + 1) % l.len()]);
            let cross = (b[0] - a[0]) * (p[1] - a[1]) - (p[0] - a[0]) * (b[1] - a[1]);
            if a[1] <= p[1] {
                if b[1] > p[1] && cross > 0.0 {
                    w += 1;
                }
            } else if b[1] <= p[1] && cross < 0.0 {
                w -= 1;
            }
        }
    }
    w
}

/// Whether segment a-b's bounding box meets the closed rectangle.
fn touches(a: Pt, b: Pt, lo: Pt, hi: Pt) -> bool {
    a[0].max(b[0]) >= lo[0]
        && a[0].min(b[0]) <= hi[0]
        && a[1].max(b[1]) >= lo[1]
        && a[1].min(b[1]) <= hi[1]
}

/// The triangles (counterclockwise, in the domain) covering the trimmed part of a
/// patch's grid.
pub fn triangles(p: &Patch, loops: &[Vec<Pt>]) -> Vec<[Pt; 3]> {
    let (ns, nt) = (p.steps.0.max(1) as usize, p.steps.1.max(1) as usize);
    let s =
        |i: usize| f64::from(p.s.0) + (f64::from(p.s.1) - f64::from(p.s.0)) * i as f64 / ns as f64;
    let t =
        |j: usize| f64::from(p.t.0) + (f64::from(p.t.1) - f64::from(p.t.0)) * j as f64 / nt as f64;
    let (plo, phi) = ([s(0), t(0)], [s(ns), t(nt)]);
    // Only loops reaching the patch matter inside it.
    let near: Vec<&Vec<Pt>> = loops
        .iter()
        .filter(|l| (0..l.len()).any(|i| touches(l[i], l[(i + 1) % l.len()], plo, phi)))
        .collect();
    let mut out = Vec::new();
    for i in 0..ns {
        for j in 0..nt {
            let (lo, hi) = ([s(i), t(j)], [s(i + 1), t(j + 1)]);
            let crossing: Vec<&Vec<Pt>> = near
                .iter()
                .copied()
                .filter(|l| (0..l.len()).any(|k| touches(l[k], l[(k + 1) % l.len()], lo, hi)))
                .collect();
            if crossing.is_empty() {
                let mid = [(lo[0] + hi[0]) * 0.5, (lo[1] + hi[1]) * 0.5];
                if winding(loops, mid) > 0 {
                    out.push([lo, [hi[0], lo[1]], hi]);
                    out.push([lo, hi, [lo[0], hi[1]]]);
                }
                continue;
            }
            cut_cell(lo, hi, &crossing, loops, &mut out);
        }
    }
    out
}

/// Triangulates the part of cell [lo, hi] inside the loops.
fn cut_cell(lo: Pt, hi: Pt, crossing: &[&Vec<Pt>], all: &[Vec<Pt>], out: &mut Vec<[Pt; 3]>) {
    let mut input = Vec::new();
    let mut contours = Vec::new();
    let vtx = |q: Pt| arrange::Vtx {
        s: q[0],
        t: q[1],
        xyz: [q[0], q[1], 0.0],
        data: std::ptr::null_mut(),
    };
    let mut add = |pts: &[Pt], input: &mut Vec<arrange::Vtx>| {
        let first = input.len();
        input.extend(pts.iter().map(|&q| vtx(q)));
        contours.push((first..input.len()).collect::<Vec<_>>());
    };
    add(&[lo, [hi[0], lo[1]], hi, [lo[0], hi[1]]], &mut input);
    for l in crossing {
        add(l, &mut input);
    }
    // Loops that do not reach the cell still wind around it: as whole unit squares
    // around the cell, one per unit of their winding.
    let mid = [(lo[0] + hi[0]) * 0.5, (lo[1] + hi[1]) * 0.5];
    let crossing_w = winding(
        &crossing.iter().map(|l| (*l).clone()).collect::<Vec<_>>(),
        mid,
    );
    let rest = winding(all, mid) - crossing_w;
    let (w, h) = (hi[0] - lo[0], hi[1] - lo[1]);
    for _ in 0..rest.max(0) {
        let big = [
            [lo[0] - w, lo[1] - h],
            [hi[0] + w, lo[1] - h],
            [hi[0] + w, hi[1] + h],
            [lo[0] - w, hi[1] + h],
        ];
        add(&big, &mut input);
    }
    let mut combine = |_, _, _, _| Some(std::ptr::null_mut());
    let arr = arrange::arrange(&input, &contours, &mut combine);
    let bounds = sweep::classify(&arr.verts, &arr.segs, WINDING_ABS_GEQ_TWO);
    for tri in sweep::triangulate(&arr.verts, &bounds) {
        let v = tri.map(|k| [arr.verts[k].s, arr.verts[k].t]);
        out.push(v);
    }
}

/// Draws a trimmed surface (or any surface in GLU_OUTLINE_PATCH mode).
pub fn draw(n: &Nurbs, geo: &SurfDef, patches: &[Patch], loops: &[Vec<TrimPiece>]) {
    let lines = polylines(geo, loops);
    // SAFETY: plain GL calls on the current context.
    unsafe {
        glPushAttrib(GL_EVAL_BIT);
        for p in patches {
            p.load();
            if n.display == OUTLINE_PATCH {
                outline(p, &lines);
                continue;
            }
            let tris = triangles(p, &lines);
            // GLU_OUTLINE_POLYGON outlines them through the polygon mode.
            if !tris.is_empty() {
                glBegin(GL_TRIANGLES);
                for t in &tris {
                    t.iter()
                        .for_each(|q| glEvalCoord2f(q[0] as f32, q[1] as f32));
                }
                glEnd();
            }
        }
        glPopAttrib();
    }
}

/// The loop edges lying in a patch, evaluated as lines.
fn outline(p: &Patch, lines: &[Vec<Pt>]) {
    let (lo, hi) = (
        [f64::from(p.s.0), f64::from(p.t.0)],
        [f64::from(p.s.1), f64::from(p.t.1)],
    );
    // SAFETY: plain GL calls on the current context.
    unsafe {
        glBegin(GL_LINES);
        for l in lines {
            for i in 0..l.len() {
                let (a, b) = (l[i], l[(i + 1) % l.len()]);
                let m = [(a[0] + b[0]) * 0.5, (a[1] + b[1]) * 0.5];
                if m[0] >= lo[0] && m[0] <= hi[0] && m[1] >= lo[1] && m[1] <= hi[1] {
                    glEvalCoord2f(a[0] as f32, a[1] as f32);
                    glEvalCoord2f(b[0] as f32, b[1] as f32);
                }
            }
        }
        glEnd();
    }
}
