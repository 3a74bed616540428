//! Drawing collected curves and surfaces through GL's evaluators, with SGI's rules for
//! how many steps each Bézier piece gets.

use super::bezier::{curve_piece, surface_piece, Basis};
use super::{is_vertex, trim, CurveDef, Nurbs, SurfDef, TrimPiece};
use super::{DOMAIN_DISTANCE, OUTLINE_PATCH, OUTLINE_POLYGON, PARAMETRIC_ERROR, PATH_LENGTH};
use super::{OBJECT_PARAMETRIC_ERROR, OBJECT_PATH_LENGTH};
use crate::gl::*;

const GL_EVAL_BIT: u32 = 0x0001_0000;
const GL_LINE: GLenum = 0x1B01;
const GL_FILL: GLenum = 0x1B02;
const GL_POLYGON_MODE: GLenum = 0x0B40;
const GL_FRONT: GLenum = 0x0404;
const GL_BACK: GLenum = 0x0405;
const GL_FRONT_AND_BACK: GLenum = 0x0408;
/// SGI subdivides a piece at most this many times to honour its sampling rate.
const MAX_SUBDIVISIONS: u32 = 6;
/// The most steps one piece gets in one direction (SGI has no limit).
const MAX_STEPS: f32 = 4096.0;

/// Reads modelview, projection and viewport into the sampling and culling matrices.
fn auto_load(n: &mut Nurbs) {
    let mut m = [0f32; 16];
    let mut p = [0f32; 16];
    let mut v = [0i32; 4];
    // SAFETY: the arrays have room for what each query writes.
    unsafe {
        glGetFloatv(GL_MODELVIEW_MATRIX, m.as_mut_ptr());
        glGetFloatv(GL_PROJECTION_MATRIX, p.as_mut_ptr());
        glGetIntegerv(GL_VIEWPORT, v.as_mut_ptr());
    }
    n.load_matrices(&m, &p, v);
}

/// A point through a row-vector matrix: non-rational (dim 3, w = 1) or rational (dim 4).
fn xform(m: &[[f32; 4]; 4], p: &[f32]) -> [f32; 4] {
    let mut d = [0f32; 4];
    for (j, x) in d.iter_mut().enumerate() {
        *x = if p.len() >= 4 {
            p[0] * m[0][j] + p[1] * m[1][j] + p[2] * m[2][j] + p[3] * m[3][j]
        } else {
            p[0] * m[0][j] + p[1] * m[1][j] + p.get(2).copied().unwrap_or(0.0) * m[2][j] + m[3][j]
        };
    }
    d
}

/// Control points through the sampling matrix and divided by w; None when the weights
/// change sign (the piece crosses infinity).
fn project(n: &Nurbs, pts: &[f32], dim: usize) -> Option<Vec<[f32; 3]>> {
    let h: Vec<[f32; 4]> = pts.chunks(dim).map(|p| xform(&n.smat, p)).collect();
    let sign = |w: f32| {
        if w > 0.0 {
            1
        } else if w < 0.0 {
            -1
        } else {
            0
        }
    };
    let s0 = sign(h.first()?[3]);
    h.iter()
        .map(|q| (sign(q[3]) == s0).then(|| [q[0] / q[3], q[1] / q[3], q[2] / q[3]]))
        .collect()
}

/// a − b.
fn sub3(a: [f32; 3], b: [f32; 3]) -> [f32; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// The largest `partial`-th difference along a row of points, times SGI's scale factor.
fn velocity(row: &[[f32; 3]], partial: usize, range: f32) -> f32 {
    let k = row.len();
    if k <= partial {
        return 0.0;
    }
    let mut tmp: Vec<[f32; 3]> = row.to_vec();
    for t in 0..partial {
        for j in 0..k - t - 1 {
            let next = tmp[j + 1];
            tmp[j] = sub3(next, tmp[j]);
        }
    }
    let max = tmp[..k - partial]
        .iter()
        .map(|v| v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
        .fold(0.0f32, f32::max);
    let invt = 1.0 / range;
    let mut fac = 1.0f32;
    for t in (k - partial..k).rev() {
        fac *= t as f32 * invt;
    }
    fac * max.sqrt()
}

/// SGI's `setstepsize`: `rate` samples over the range.
fn fixed(rate: f32, range: f32) -> (f32, f32) {
    let s = if rate >= 1.0 { range / rate } else { range };
    (s, s)
}

/// Step size and minimum step size for a row (curve or surface direction) of
/// projected points, per the sampling method.
fn step_of(n: &Nurbs, rows: &[Vec<[f32; 3]>], range: f32, rate: f32) -> (f32, f32) {
    let partial = match n.method {
        PATH_LENGTH => 1,
        PARAMETRIC_ERROR => 2,
        _ => return fixed(rate, range),
    };
    let d = rows
        .iter()
        .map(|r| velocity(r, partial, range))
        .fold(0.0f32, f32::max);
    let t = n.tolerance;
    let step = if d > 0.0 {
        if partial == 1 {
            t / d
        } else {
            (8.0 * t / d).sqrt()
        }
    } else {
        range
    };
    let min = if rate > 0.0 { range / rate } else { 0.0 };
    (step, min)
}

/// Number of grid steps for a range at a step size, as SGI counts them.
fn steps(range: f32, step: f32) -> i32 {
    let q = (range / step).min(MAX_STEPS);
    1 + q as i32
}

/// The Bézier pieces' breakpoints: every map's knots inside the vertex map's range.
fn breakpoints<'a>(bases: impl Iterator<Item = &'a Basis>, range: (f32, f32)) -> Vec<f32> {
    let mut v: Vec<f32> = bases
        .flat_map(|b| b.breakpoints())
        .filter(|&x| x >= range.0 && x <= range.1)
        .collect();
    v.sort_by(f32::total_cmp);
    v.dedup();
    v
}

/// Whether every control point lies outside one clip plane.
fn culled(n: &Nurbs, pts: &[f32], dim: usize) -> bool {
    if !n.culling {
        return false;
    }
    let c: Vec<[f32; 4]> = pts.chunks(dim).map(|p| xform(&n.cmat, p)).collect();
    (0..3).any(|a| c.iter().all(|q| q[a] > q[3]) || c.iter().all(|q| q[a] < -q[3]))
}

/// Draws a curve (`maps` holds exactly one vertex map).
pub fn curve(n: &mut Nurbs, maps: &[CurveDef]) {
    if n.auto_load {
        auto_load(n);
    }
    let Some(geo) = maps.iter().find(|m| is_vertex(m.target)) else {
        return;
    };
    if culled(n, &geo.pts, geo.dim) {
        return;
    }
    let range = geo.basis.range();
    let bp = breakpoints(maps.iter().map(|m| &m.basis), range);
    if n.tessellator {
        super::render_cb::curve(n, maps, &bp);
        return;
    }
    // SAFETY: plain GL calls on the current context; each glMap1f's array holds
    // order × dim floats.
    unsafe {
        glPushAttrib(GL_EVAL_BIT);
        for w in bp.windows(2) {
            let (a, b) = (w[0], w[1]);
            let mut geo_piece = Vec::new();
            for m in maps {
                let (lo, hi) = m.basis.range();
                if a < lo || b > hi {
                    continue;
                }
                let p = curve_piece(&m.basis, &m.pts, m.dim, a, b);
                let (d, k) = (m.dim as i32, m.basis.order as i32);
                glMap1f(m.target, a, b, d, k, p.as_ptr());
                glEnable(m.target);
                if is_vertex(m.target) {
                    geo_piece = p;
                }
            }
            sample_curve(n, &geo_piece, geo.dim, a, b, MAX_SUBDIVISIONS);
        }
        glPopAttrib();
    }
}

/// Splits a Bézier piece at parameter fraction 0.5 (de Casteljau): (lower, upper).
fn split_half(p: &[f32], dim: usize) -> (Vec<f32>, Vec<f32>) {
    let k = p.len() / dim;
    let mut work = p.to_vec();
    let mut lo = Vec::with_capacity(p.len());
    let mut hi = vec![0f32; p.len()];
    for r in 0..k {
        lo.extend_from_slice(&work[0..dim]);
        hi[(k - 1 - r) * dim..(k - r) * dim]
            .copy_from_slice(&work[(k - 1 - r) * dim..(k - r) * dim]);
        for j in 0..k - 1 - r {
            for c in 0..dim {
                work[j * dim + c] = 0.5 * (work[j * dim + c] + work[(j + 1) * dim + c]);
            }
        }
    }
    (lo, hi)
}

/// Picks the step count for [a, b] of the mapped piece and evaluates its line strip.
fn sample_curve(n: &Nurbs, piece: &[f32], dim: usize, a: f32, b: f32, sub: u32) {
    let range = b - a;
    let (step, min) = match n.method {
        DOMAIN_DISTANCE => fixed(n.u_step * range, range),
        PATH_LENGTH | PARAMETRIC_ERROR => match project(n, piece, dim) {
            Some(row) => step_of(n, &[row], range, n.u_step),
            None => fixed(n.u_step, range),
        },
        _ => fixed(n.u_step, range),
    };
    if step < min && sub > 0 && !piece.is_empty() {
        let mid = (a + b) * 0.5;
        let (lo, hi) = split_half(piece, dim);
        sample_curve(n, &lo, dim, a, mid, sub - 1);
        sample_curve(n, &hi, dim, mid, b, sub - 1);
        return;
    }
    let nu = steps(range, step);
    // SAFETY: plain GL calls on the current context.
    unsafe {
        glMapGrid1f(nu, a, b);
        glEvalMesh1(GL_LINE, 0, nu);
    }
}

/// SGI's surface partial velocity: the largest magnitude of the control net's
/// (`sp`, `tp`)-th differences, times the derivative's scale factor.
fn velocity2(q: &[[f32; 3]], ks: usize, kt: usize, sp: usize, tp: usize, rs: f32, rt: f32) -> f32 {
    if ks <= sp || kt <= tp {
        return 0.0;
    }
    let mut g: Vec<[f32; 3]> = q.to_vec();
    let at = |i: usize, j: usize| i * kt + j;
    for r in 0..sp {
        for i in 0..ks - r - 1 {
            for j in 0..kt {
                g[at(i, j)] = sub3(g[at(i + 1, j)], g[at(i, j)]);
            }
        }
    }
    for r in 0..tp {
        for j in 0..kt - r - 1 {
            for i in 0..ks - sp {
                g[at(i, j)] = sub3(g[at(i, j + 1)], g[at(i, j)]);
            }
        }
    }
    let mut max = 0.0f32;
    for i in 0..ks - sp {
        for j in 0..kt - tp {
            let v = g[at(i, j)];
            max = max.max(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        }
    }
    let (invs, invt) = (1.0 / rs, 1.0 / rt);
    let mut fac = 1.0f32;
    for s in (ks - sp..ks).rev() {
        fac *= s as f32 * invs;
    }
    for t in (kt - tp..kt).rev() {
        fac *= t as f32 * invt;
    }
    fac * max.sqrt()
}

/// Grid steps (s, t) for one patch, by SGI's rules for surfaces.
pub fn patch_steps(
    n: &Nurbs,
    p: &[f32],
    dim: usize,
    ks: usize,
    kt: usize,
    s: (f32, f32),
    t: (f32, f32),
) -> (i32, i32) {
    let (rs, rt) = (s.1 - s.0, t.1 - t.0);
    let (ss, ts) = match n.method {
        DOMAIN_DISTANCE => (fixed(n.u_step * rs, rs).0, fixed(n.v_step * rt, rt).0),
        PATH_LENGTH | OBJECT_PATH_LENGTH => match project(n, p, dim) {
            Some(q) => {
                let t1 = n.tolerance;
                let ms = velocity2(&q, ks, kt, 1, 0, rs, rt);
                let mt = velocity2(&q, ks, kt, 0, 1, rs, rt);
                let half = if ms != 0.0 && mt != 0.0 { 2.0 } else { 1.0 };
                let one = |m: f32, r: f32| {
                    let d = if m != 0.0 { t1 / (half * m) } else { r };
                    if d < r {
                        d
                    } else {
                        r
                    }
                };
                (one(ms, rs), one(mt, rt))
            }
            None => (fixed(n.u_step, rs).0, fixed(n.v_step, rt).0),
        },
        PARAMETRIC_ERROR | OBJECT_PARAMETRIC_ERROR => match project(n, p, dim) {
            Some(q) => {
                let t2 = n.param_tolerance;
                let ss = velocity2(&q, ks, kt, 2, 0, rs, rt);
                let st = velocity2(&q, ks, kt, 1, 1, rs, rt);
                let tt = velocity2(&q, ks, kt, 0, 2, rs, rt);
                if ss != 0.0 && tt != 0.0 {
                    let (ttq, ssq) = (ss.sqrt(), tt.sqrt());
                    let ds = (4.0 * t2 * ttq / (ss * ttq + st * ssq)).sqrt();
                    let dt = (4.0 * t2 * ssq / (tt * ssq + st * ttq)).sqrt();
                    (ds.min(rs), dt.min(rt))
                } else if ss != 0.0 {
                    let x = rt * st;
                    (((x * x + 8.0 * t2 * ss).sqrt() - x) / ss, rt)
                } else if tt != 0.0 {
                    let x = rs * st;
                    (rs, ((x * x + 8.0 * t2 * tt).sqrt() - x) / tt)
                } else if st == 0.0 || 4.0 * t2 > st * rs * rt {
                    (rs, rt)
                } else {
                    let area = 4.0 * t2 / st;
                    ((area * rs / rt).sqrt(), (area * rt / rs).sqrt())
                }
            }
            None => (fixed(n.u_step, rs).0, fixed(n.v_step, rt).0),
        },
        _ => (fixed(n.u_step, rs).0, fixed(n.v_step, rt).0),
    };
    (steps(rs, ss), steps(rt, ts))
}

/// One Bézier patch of every map over a domain cell.
pub struct Patch {
    /// The s interval.
    pub s: (f32, f32),
    /// The t interval.
    pub t: (f32, f32),
    /// (target, dim, s order, t order, points) per map.
    pub maps: Vec<(GLenum, usize, usize, usize, Vec<f32>)>,
    /// Grid steps in s and t.
    pub steps: (i32, i32),
}

impl Patch {
    /// Loads every map into GL (inside a pushed GL_EVAL_BIT).
    pub fn load(&self) {
        for (target, dim, ks, kt, p) in &self.maps {
            // SAFETY: the array holds ks × kt points of `dim` floats, t varying fastest.
            unsafe {
                glMap2f(
                    *target,
                    self.s.0,
                    self.s.1,
                    (*kt * *dim) as i32,
                    *ks as i32,
                    self.t.0,
                    self.t.1,
                    *dim as i32,
                    *kt as i32,
                    p.as_ptr(),
                );
                glEnable(*target);
            }
        }
    }
}

/// The surface's Bézier patches.
pub fn patches(n: &Nurbs, maps: &[SurfDef]) -> Vec<Patch> {
    let Some(geo) = maps.iter().find(|m| is_vertex(m.target)) else {
        return Vec::new();
    };
    let sr = geo.s.range();
    let tr = geo.t.range();
    let sb = breakpoints(maps.iter().map(|m| &m.s), sr);
    let tb = breakpoints(maps.iter().map(|m| &m.t), tr);
    let mut out = Vec::new();
    for ws in sb.windows(2) {
        for wt in tb.windows(2) {
            let (s, t) = ((ws[0], ws[1]), (wt[0], wt[1]));
            let mut pm = Vec::new();
            let mut st = (1, 1);
            for m in maps {
                let (sl, sh) = m.s.range();
                let (tl, th) = m.t.range();
                if s.0 < sl || s.1 > sh || t.0 < tl || t.1 > th {
                    continue;
                }
                let p = surface_piece(&m.s, &m.t, &m.pts, m.dim, s, t);
                if is_vertex(m.target) {
                    st = patch_steps(n, &p, m.dim, m.s.order, m.t.order, s, t);
                }
                pm.push((m.target, m.dim, m.s.order, m.t.order, p));
            }
            out.push(Patch {
                s,
                t,
                maps: pm,
                steps: st,
            });
        }
    }
    out
}

/// Draws a surface (`maps` holds exactly one vertex map) with its trim loops.
pub fn surface(n: &mut Nurbs, maps: &[SurfDef], loops: &[Vec<TrimPiece>]) {
    if n.auto_load {
        auto_load(n);
    }
    let Some(geo) = maps.iter().find(|m| is_vertex(m.target)) else {
        return;
    };
    if culled(n, &geo.pts, geo.dim) {
        return;
    }
    let patches = patches(n, maps);
    if n.tessellator {
        super::render_cb::surface(n, &patches, geo, loops);
        return;
    }
    // As SGI's GLU: the display mode is set as the polygon mode for the whole surface
    // (FILL for GLU_FILL, LINE for GLU_OUTLINE_POLYGON), then the front and back modes
    // are put back.
    let outline = n.display == OUTLINE_POLYGON;
    let mut saved = [GL_FILL as i32; 2];
    // SAFETY: GL_POLYGON_MODE writes two integers.
    unsafe {
        glGetIntegerv(GL_POLYGON_MODE, saved.as_mut_ptr());
        glPolygonMode(GL_FRONT_AND_BACK, if outline { GL_LINE } else { GL_FILL });
    }
    if loops.is_empty() && n.display != OUTLINE_PATCH {
        let mode = if outline { GL_LINE } else { GL_FILL };
        // SAFETY: plain GL calls on the current context.
        unsafe {
            glPushAttrib(GL_EVAL_BIT);
            for p in &patches {
                p.load();
                let (nu, nv) = if n.method == DOMAIN_DISTANCE {
                    // SGI's shortcut for untrimmed surfaces sampled by domain distance:
                    // the rate times the patch's extent, truncated, at least 1.
                    let k = |rate: f32, r: (f32, f32)| {
                        ((rate * (r.1 - r.0)).min(MAX_STEPS) as i32).max(1)
                    };
                    (k(n.u_step, p.s), k(n.v_step, p.t))
                } else {
                    p.steps
                };
                // t runs downwards, as in SGI's grid, so that the mesh's quads are
                // counterclockwise in (s, t) and face along the evaluator's s × t normal.
                glMapGrid2f(nu, p.s.0, p.s.1, nv, p.t.1, p.t.0);
                glEvalMesh2(mode, 0, nu, 0, nv);
            }
            glPopAttrib();
        }
    } else {
        trim::draw(n, geo, &patches, loops);
    }
    // SAFETY: plain GL calls on the current context.
    unsafe {
        glPolygonMode(GL_FRONT, saved[0] as GLenum);
        glPolygonMode(GL_BACK, saved[1] as GLenum);
    }
}
