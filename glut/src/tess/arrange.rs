//! The planar arrangement of a polygon's contours: coincident vertices merged, edges
//! split where they cross (a new vertex, made through the COMBINE callback), where a
//! vertex lies on an edge, and where collinear edges overlap. The result is a set of
//! segments that meet only at their endpoints, each with the net number of contour
//! edges running along it (its winding contribution).

use std::collections::HashMap;
use std::ffi::c_void;

/// A vertex: projected coordinates, object coordinates and the client's data.
#[derive(Clone, Copy, Debug)]
pub struct Vtx {
    /// First coordinate in the projection plane.
    pub s: f64,
    /// Second coordinate in the projection plane.
    pub t: f64,
    /// Object coordinates (as given, or combined).
    pub xyz: [f64; 3],
    /// The client's vertex data.
    pub data: *mut c_void,
}

impl Vtx {
    /// The projected point.
    pub fn st(&self) -> (f64, f64) {
        (self.s, self.t)
    }
}

/// A segment between two vertices, `lo` before `hi` in sweep order, with the net count
/// of contour edges along it: +1 for each running lo → hi, −1 for each running back.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Seg {
    /// The earlier endpoint (smaller s, then smaller t).
    pub lo: usize,
    /// The later endpoint.
    pub hi: usize,
    /// Winding contribution: the region above minus the region below.
    pub w: i32,
}

/// Twice the signed area of triangle (a, b, c): positive when counterclockwise.
pub fn orient(a: (f64, f64), b: (f64, f64), c: (f64, f64)) -> f64 {
    (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0)
}

/// Sweep order: by s, then by t.
pub fn before(a: (f64, f64), b: (f64, f64)) -> bool {
    a.0 < b.0 || (a.0 == b.0 && a.1 < b.1)
}

/// Makes new vertices: `combine(xyz, data, weights, needed)` returns the client data
/// of a new vertex (None when there is no callback or it gave none; `needed` says
/// whether the vertex is an intersection, which cannot do without one).
pub type Combine<'a> =
    dyn FnMut([f64; 3], [*mut c_void; 4], [f32; 4], bool) -> Option<*mut c_void> + 'a;

/// The exact key of a projected point (-0 and +0 are the same point).
fn key(s: f64, t: f64) -> (u64, u64) {
    ((s + 0.0).to_bits(), (t + 0.0).to_bits())
}

/// Vertices, merged by position, and the segments built between them.
struct Builder<'a, 'c> {
    verts: Vec<Vtx>,
    at: HashMap<(u64, u64), usize>,
    combine: &'a mut Combine<'c>,
    /// An intersection needed a new vertex and the client supplied none.
    missing_combine: bool,
}

impl Builder<'_, '_> {
    /// The vertex at `v`'s position: an existing one (merged with `v` through the
    /// combine callback) or `v` added.
    fn add(&mut self, v: Vtx) -> usize {
        let k = key(v.s, v.t);
        if let Some(&i) = self.at.get(&k) {
            let first = self.verts[i];
            let data = [
                first.data,
                v.data,
                std::ptr::null_mut(),
                std::ptr::null_mut(),
            ];
            if let Some(d) = (self.combine)(first.xyz, data, [0.5, 0.5, 0.0, 0.0], false) {
                self.verts[i].data = d;
            }
            return i;
        }
        self.verts.push(v);
        self.at.insert(k, self.verts.len() - 1);
        self.verts.len() - 1
    }

    fn st(&self, i: usize) -> (f64, f64) {
        self.verts[i].st()
    }

    /// Where two segments meet other than at a shared endpoint: adds to `splits` the
    /// (parameter, vertex) pairs at which each must be cut.
    fn meet(&mut self, p: Seg, q: Seg, splits: &mut [Vec<(f64, usize)>; 2]) {
        let (a, b, c, d) = (self.st(p.lo), self.st(p.hi), self.st(q.lo), self.st(q.hi));
        let shared = [p.lo, p.hi]
            .iter()
            .filter(|&&x| x == q.lo || x == q.hi)
            .count();
        if shared == 2 {
            return;
        }
        let (o1, o2) = (orient(a, b, c), orient(a, b, d));
        let (o3, o4) = (orient(c, d, a), orient(c, d, b));
        // A vertex of one lying inside the other (touching or collinear overlap).
        let param = |x: (f64, f64), y: (f64, f64), z: (f64, f64)| {
            let (dx, dy) = (y.0 - x.0, y.1 - x.1);
            ((z.0 - x.0) * dx + (z.1 - x.1) * dy) / (dx * dx + dy * dy)
        };
        let mut touched = false;
        for (side, (x, y), z, zi, o) in [
            (0, (a, b), c, q.lo, o1),
            (0, (a, b), d, q.hi, o2),
            (1, (c, d), a, p.lo, o3),
            (1, (c, d), b, p.hi, o4),
        ] {
            let own = if side == 0 { p } else { q };
            if o == 0.0 && zi != own.lo && zi != own.hi {
                let u = param(x, y, z);
                if u > 0.0 && u < 1.0 {
                    splits[side].push((u, zi));
                    touched = true;
                }
            }
        }
        if touched || shared > 0 {
            return;
        }
        let crosses = ((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0))
            && ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0));
        if !crosses {
            return;
        }
        let u = o3 / (o3 - o4);
        let v = o1 / (o1 - o2);
        let s = a.0 + u * (b.0 - a.0);
        let t = a.1 + u * (b.1 - a.1);
        // The combine callback sees the upper segment (left of the crossing) first,
        // each segment's later endpoint first, as SGI's GLU passes them.
        let p_upper = o3 > 0.0;
        let (up, lo, u_up, u_lo) = if p_upper { (p, q, u, v) } else { (q, p, v, u) };
        let ends = [up.hi, up.lo, lo.hi, lo.lo];
        let wd = [
            0.5 * u_up,
            0.5 * (1.0 - u_up),
            0.5 * u_lo,
            0.5 * (1.0 - u_lo),
        ];
        let weights = wd.map(|w| w as f32);
        let mut xyz = [0.0; 3];
        for (e, w) in ends.iter().zip(wd) {
            for (k, c) in xyz.iter_mut().enumerate() {
                *c += w * self.verts[*e].xyz[k];
            }
        }
        let idx = match self.at.get(&key(s, t)) {
            Some(&i) => i,
            None => {
                let data = ends.map(|e| self.verts[e].data);
                let made = (self.combine)(xyz, data, weights, true);
                if made.is_none() {
                    self.missing_combine = true;
                }
                self.verts.push(Vtx {
                    s,
                    t,
                    xyz,
                    data: made.unwrap_or(std::ptr::null_mut()),
                });
                self.at.insert(key(s, t), self.verts.len() - 1);
                self.verts.len() - 1
            }
        };
        if idx != p.lo && idx != p.hi {
            splits[0].push((u, idx));
        }
        if idx != q.lo && idx != q.hi {
            splits[1].push((v, idx));
        }
    }

    /// A segment between two vertex indices with its direction's contribution.
    fn seg(&self, from: usize, to: usize, w: i32) -> Seg {
        if before(self.st(from), self.st(to)) {
            Seg {
                lo: from,
                hi: to,
                w,
            }
        } else {
            Seg {
                lo: to,
                hi: from,
                w: -w,
            }
        }
    }

    /// One pass: every meeting found, every segment cut; false when nothing was cut.
    fn split_pass(&mut self, segs: &mut Vec<Seg>) -> bool {
        let mut order: Vec<usize> = (0..segs.len()).collect();
        order.sort_by(|&i, &j| self.st(segs[i].lo).0.total_cmp(&self.st(segs[j].lo).0));
        let mut cuts: Vec<Vec<(f64, usize)>> = vec![Vec::new(); segs.len()];
        for (k, &i) in order.iter().enumerate() {
            let end = self.st(segs[i].hi).0;
            for &j in &order[k + 1..] {
                if self.st(segs[j].lo).0 > end {
                    break;
                }
                let mut sp = [Vec::new(), Vec::new()];
                self.meet(segs[i], segs[j], &mut sp);
                let [a, b] = sp;
                cuts[i].extend(a);
                cuts[j].extend(b);
            }
        }
        if cuts.iter().all(Vec::is_empty) {
            return false;
        }
        let mut out = Vec::with_capacity(segs.len() * 2);
        for (sg, mut c) in segs.iter().zip(cuts) {
            c.sort_by(|x, y| x.0.total_cmp(&y.0));
            c.dedup_by_key(|x| x.1);
            let mut from = sg.lo;
            for (_, v) in c {
                if v != from {
                    out.push(self.seg(from, v, sg.w));
                    from = v;
                }
            }
            if from != sg.hi {
                out.push(self.seg(from, sg.hi, sg.w));
            }
        }
        *segs = merge_duplicates(out);
        true
    }
}

/// Segments with the same endpoints become one whose contribution is their sum.
fn merge_duplicates(segs: Vec<Seg>) -> Vec<Seg> {
    let mut index: HashMap<(usize, usize), usize> = HashMap::new();
    let mut out: Vec<Seg> = Vec::with_capacity(segs.len());
    for s in segs {
        match index.get(&(s.lo, s.hi)) {
            Some(&i) => out[i].w += s.w,
            None => {
                index.insert((s.lo, s.hi), out.len());
                out.push(s);
            }
        }
    }
    out
}

/// The arrangement of the contours (lists of indices into `input`).
pub struct Arrangement {
    /// Every vertex: the merged input vertices, then the intersections.
    pub verts: Vec<Vtx>,
    /// Segments meeting only at endpoints, with nonzero contributions.
    pub segs: Vec<Seg>,
    /// An intersection was found and the combine callback supplied no vertex.
    pub missing_combine: bool,
}

/// Builds the arrangement of `contours` over `input`.
pub fn arrange(input: &[Vtx], contours: &[Vec<usize>], combine: &mut Combine) -> Arrangement {
    let mut b = Builder {
        verts: Vec::with_capacity(input.len()),
        at: HashMap::new(),
        combine,
        missing_combine: false,
    };
    let mut segs = Vec::new();
    for c in contours {
        // A vertex repeating its predecessor (or the contour's first, at the end) only
        // makes a zero-length edge: dropped without a combine, as SGI's GLU drops it.
        let mut own: Vec<usize> = c.clone();
        own.dedup_by_key(|&mut i| key(input[i].s, input[i].t));
        while own.len() > 1 && {
            let (f, l) = (input[own[0]], input[own[own.len() - 1]]);
            key(f.s, f.t) == key(l.s, l.t)
        } {
            own.pop();
        }
        // Contours of one or two edges enclose nothing and cut nothing: SGI's GLU
        // drops them before looking for crossings.
        if own.len() < 3 {
            continue;
        }
        let mut ids: Vec<usize> = own.iter().map(|&i| b.add(input[i])).collect();
        ids.dedup();
        while ids.len() > 1 && ids.first() == ids.last() {
            ids.pop();
        }
        if ids.len() < 2 {
            continue;
        }
        for k in 0..ids.len() {
            segs.push(b.seg(ids[k], ids[(k + 1) % ids.len()], 1));
        }
    }
    let mut segs = merge_duplicates(segs);
    // Rounded intersection points can make new meetings: a few passes settle them.
    for _ in 0..8 {
        if !b.split_pass(&mut segs) {
            break;
        }
    }
    segs.retain(|s| s.w != 0);
    Arrangement {
        verts: b.verts,
        segs,
        missing_combine: b.missing_combine,
    }
}
