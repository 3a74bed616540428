//! Sweeps over an arrangement (vertices in s-then-t order, the segments crossing the
//! sweep line kept sorted bottom to top):
//!
//! - [`classify`] gives every region its winding number (the sum of the contributions
//!   of the segments below it) and keeps the segments that separate a region inside
//!   the polygon (per the winding rule) from one outside;
//! - [`triangulate`] cuts the inside regions bounded by those segments into triangles
//!   in one more sweep: each inside region between two segments keeps the vertices
//!   not yet used up as a chain (concave toward the region), triangles are cut off as
//!   new vertices arrive, a vertex inside a region splits it (joined to the region's
//!   latest vertex) and a vertex where two regions meet joins them;
//! - [`boundaries`] links the kept segments into closed loops, the inside on the left.

use super::arrange::{orient, Seg, Vtx};

/// The segments at each vertex: (ending there, starting there), by index.
fn incidence(n: usize, segs: &[Seg]) -> Vec<(Vec<usize>, Vec<usize>)> {
    let mut inc = vec![(Vec::new(), Vec::new()); n];
    for (i, s) in segs.iter().enumerate() {
        inc[s.hi].0.push(i);
        inc[s.lo].1.push(i);
    }
    inc
}

/// The vertices with segments, in sweep order.
fn sweep_order(verts: &[Vtx], inc: &[(Vec<usize>, Vec<usize>)]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..verts.len())
        .filter(|&v| !inc[v].0.is_empty() || !inc[v].1.is_empty())
        .collect();
    order.sort_by(|&a, &b| {
        let (p, q) = (verts[a].st(), verts[b].st());
        p.0.total_cmp(&q.0).then(p.1.total_cmp(&q.1))
    });
    order
}

/// The active list while sweeping: segment indices bottom to top, plus per-entry state.
struct Active<T> {
    entries: Vec<(usize, T)>,
}

impl<T> Active<T> {
    /// Where vertex `v` sits: the first entry ending at `v`, or (none ending there)
    /// the number of entries passing below it; and how many end there.
    fn locate(&self, verts: &[Vtx], segs: &[Seg], v: usize) -> (usize, usize) {
        let ending: Vec<usize> = (0..self.entries.len())
            .filter(|&k| segs[self.entries[k].0].hi == v)
            .collect();
        if let (Some(&first), Some(&last)) = (ending.first(), ending.last()) {
            return (first, last + 1 - first);
        }
        let p = verts[v].st();
        let below = self
            .entries
            .iter()
            .take_while(|(e, _)| {
                let s = segs[*e];
                orient(verts[s.lo].st(), verts[s.hi].st(), p) > 0.0
            })
            .count();
        (below, 0)
    }
}

/// The segments starting at `v`, bottom to top.
fn outgoing_sorted(verts: &[Vtx], segs: &[Seg], v: usize, out: &[usize]) -> Vec<usize> {
    let o = verts[v].st();
    let mut out = out.to_vec();
    out.sort_by(|&a, &b| {
        let (pa, pb) = (verts[segs[a].hi].st(), verts[segs[b].hi].st());
        // a below b when b turns counterclockwise from a.
        0.0_f64.total_cmp(&orient(o, pa, pb))
    });
    out
}

/// Whether a winding number is inside under a GLU winding rule.
pub fn inside(rule: u32, w: i32) -> bool {
    match rule {
        super::WINDING_NONZERO => w != 0,
        super::WINDING_POSITIVE => w > 0,
        super::WINDING_NEGATIVE => w < 0,
        super::WINDING_ABS_GEQ_TWO => w.abs() >= 2,
        _ => w & 1 != 0,
    }
}

/// The segments separating inside from outside, each with whether the inside is
/// above it.
pub fn classify(verts: &[Vtx], segs: &[Seg], rule: u32) -> Vec<(Seg, bool)> {
    let inc = incidence(verts.len(), segs);
    let mut above = vec![0i32; segs.len()];
    let mut active: Active<()> = Active {
        entries: Vec::new(),
    };
    for v in sweep_order(verts, &inc) {
        let (p, m) = active.locate(verts, segs, v);
        active.entries.drain(p..p + m);
        let mut w = if p > 0 {
            above[active.entries[p - 1].0]
        } else {
            0
        };
        let out = outgoing_sorted(verts, segs, v, &inc[v].1);
        for (k, &e) in out.iter().enumerate() {
            w += segs[e].w;
            above[e] = w;
            active.entries.insert(p + k, (e, ()));
        }
    }
    segs.iter()
        .zip(above)
        .filter_map(|(s, a)| {
            let (up, down) = (inside(rule, a), inside(rule, a - s.w));
            (up != down).then_some((*s, up))
        })
        .collect()
}

/// Which boundary of its region a chain vertex lies on.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
enum Side {
    Lower,
    Upper,
    /// The region's first vertex: on both.
    Both,
}

/// The vertices of a region not yet used up: a chain, the newest on top.
type Chain = Vec<(usize, Side)>;

/// An inside region's pending part: one chain, or two meeting at the vertex where
/// two regions joined (the one below, the one above).
enum Region {
    One(Chain),
    Two(Chain, Chain),
}

/// Emits triangles (counterclockwise in the projection plane).
struct Out<'a> {
    verts: &'a [Vtx],
    tris: Vec<[usize; 3]>,
}

impl Out<'_> {
    fn tri(&mut self, a: usize, b: usize, c: usize) {
        let st = |i: usize| self.verts[i].st();
        if orient(st(a), st(b), st(c)) < 0.0 {
            self.tris.push([a, c, b]);
        } else {
            self.tris.push([a, b, c]);
        }
    }

    /// `v` sees every chain vertex: a fan, leaving the newest chain vertex and `v`.
    fn fan(&mut self, mut chain: Chain, v: usize, side: Side) -> Chain {
        for k in 1..chain.len() {
            self.tri(v, chain[k - 1].0, chain[k].0);
        }
        let top = chain.pop().expect("chains are never empty");
        vec![top, (v, side)]
    }

    /// `v` continues the side of the chain's concave run: cut off triangles while
    /// they lie inside, then `v` tops the chain.
    fn along(&mut self, mut chain: Chain, v: usize, side: Side) -> Chain {
        let st = |i: usize| self.verts[i].st();
        let mut last = chain.pop().expect("chains are never empty");
        while let Some(&next) = chain.last() {
            let o = orient(st(next.0), st(last.0), st(v));
            let fits = if side == Side::Upper {
                o < 0.0
            } else {
                o > 0.0
            };
            if !fits {
                break;
            }
            self.tri(next.0, last.0, v);
            last = chain.pop().expect("checked");
        }
        chain.push(last);
        chain.push((v, side));
        chain
    }

    /// `v` arrives on one boundary of a region.
    fn arrive_chain(&mut self, chain: Chain, v: usize, side: Side) -> Chain {
        let top = chain.last().expect("chains are never empty").1;
        if top == side {
            self.along(chain, v, side)
        } else {
            self.fan(chain, v, side)
        }
    }

    fn arrive(&mut self, r: Region, v: usize, side: Side) -> Chain {
        match r {
            Region::One(c) => self.arrive_chain(c, v, side),
            Region::Two(lo, hi) => {
                // The diagonal to the joining vertex closes one part, the other goes on.
                if side == Side::Lower {
                    self.fan(lo, v, side);
                    self.along(hi, v, side)
                } else {
                    self.fan(hi, v, side);
                    self.along(lo, v, side)
                }
            }
        }
    }

    /// The region closes at `v`.
    fn finish(&mut self, r: Region, v: usize) {
        match r {
            Region::One(c) => {
                self.fan(c, v, Side::Both);
            }
            Region::Two(a, b) => {
                self.fan(a, v, Side::Both);
                self.fan(b, v, Side::Both);
            }
        }
    }

    /// `v` lies inside the region and starts segments: joined to the region's newest
    /// vertex, it splits the region into the part below and the part above.
    fn split(&mut self, r: Region, v: usize) -> (Chain, Chain) {
        match r {
            Region::Two(lo, hi) => (
                self.along(lo, v, Side::Upper),
                self.along(hi, v, Side::Lower),
            ),
            Region::One(c) => {
                let top = *c.last().expect("chains are never empty");
                match top.1 {
                    Side::Upper => (self.along(c, v, Side::Upper), vec![top, (v, Side::Lower)]),
                    Side::Lower => (vec![top, (v, Side::Upper)], self.along(c, v, Side::Lower)),
                    Side::Both => (
                        vec![(top.0, Side::Lower), (v, Side::Upper)],
                        vec![(top.0, Side::Upper), (v, Side::Lower)],
                    ),
                }
            }
        }
    }
}

/// Triangles covering the inside of `bounds` (from [`classify`]), counterclockwise.
pub fn triangulate(verts: &[Vtx], bounds: &[(Seg, bool)]) -> Vec<[usize; 3]> {
    let segs: Vec<Seg> = bounds.iter().map(|b| b.0).collect();
    let inc = incidence(verts.len(), &segs);
    let mut out = Out {
        verts,
        tris: Vec::new(),
    };
    // Each entry: a segment and the inside region directly above it, if any.
    let mut active: Active<Option<Region>> = Active {
        entries: Vec::new(),
    };
    for v in sweep_order(verts, &inc) {
        let (p, m) = active.locate(verts, &segs, v);
        let outs = outgoing_sorted(verts, &segs, v, &inc[v].1);
        let n = outs.len();
        let (below, mut above) = if m > 0 {
            let below = if p > 0 {
                active.entries[p - 1].1.take()
            } else {
                None
            };
            let below = below.map(|r| out.arrive(r, v, Side::Upper));
            for k in p..p + m - 1 {
                if let Some(r) = active.entries[k].1.take() {
                    out.finish(r, v);
                }
            }
            let above = active.entries[p + m - 1].1.take();
            let above = above.map(|r| out.arrive(r, v, Side::Lower));
            active.entries.drain(p..p + m);
            (below, above)
        } else {
            let here = if p > 0 {
                active.entries[p - 1].1.take()
            } else {
                None
            };
            match here {
                Some(r) if n > 0 => {
                    let (lo, hi) = out.split(r, v);
                    (Some(lo), Some(hi))
                }
                None if n > 0 => (None, None),
                here => {
                    // A lone vertex: nothing changes.
                    if p > 0 {
                        active.entries[p - 1].1 = here;
                    }
                    continue;
                }
            }
        };
        if n == 0 {
            let joined = match (below, above) {
                (Some(a), Some(b)) => Some(Region::Two(a, b)),
                (a, b) => a.or(b).map(Region::One),
            };
            if p > 0 {
                active.entries[p - 1].1 = joined;
            }
            continue;
        }
        if p > 0 {
            active.entries[p - 1].1 = below.map(Region::One);
        }
        for (k, &e) in outs.iter().enumerate() {
            let state = if k + 1 == n {
                above.take().map(Region::One)
            } else if bounds[e].1 {
                Some(Region::One(vec![(v, Side::Both)]))
            } else {
                None
            };
            active.entries.insert(p + k, (e, state));
        }
    }
    out.tris
}

/// The boundary loops of the inside: vertex lists, the inside on the left (outer
/// loops counterclockwise, holes clockwise).
pub fn boundaries(verts: &[Vtx], bounds: &[(Seg, bool)]) -> Vec<Vec<usize>> {
    // Directed edges: lo → hi when the inside is above.
    let edges: Vec<(usize, usize)> = bounds
        .iter()
        .map(|(s, up)| if *up { (s.lo, s.hi) } else { (s.hi, s.lo) })
        .collect();
    let mut from: Vec<Vec<usize>> = vec![Vec::new(); verts.len()];
    for (i, e) in edges.iter().enumerate() {
        from[e.0].push(i);
    }
    let angle = |a: usize, b: usize| {
        let (p, q) = (verts[a].st(), verts[b].st());
        (q.1 - p.1).atan2(q.0 - p.0)
    };
    let mut used = vec![false; edges.len()];
    let mut loops = Vec::new();
    for start in 0..edges.len() {
        if used[start] {
            continue;
        }
        let mut lp = Vec::new();
        let mut e = start;
        loop {
            used[e] = true;
            let (a, b) = edges[e];
            lp.push(a);
            // The next edge: the first clockwise from the way back.
            let back = angle(b, a);
            let next = from[b]
                .iter()
                .copied()
                .filter(|&x| !used[x] || x == start)
                .min_by(|&x, &y| {
                    let turn = |z: usize| {
                        let d = (back - angle(b, edges[z].1)).rem_euclid(std::f64::consts::TAU);
                        if d == 0.0 {
                            std::f64::consts::TAU
                        } else {
                            d
                        }
                    };
                    turn(x).total_cmp(&turn(y))
                });
            match next {
                Some(x) if x != start && !used[x] => e = x,
                _ => break,
            }
        }
        if lp.len() >= 3 {
            loops.push(lp);
        }
    }
    loops
}
