//! Pairing: two triangles that make an axis-aligned rectangle (the two halves of a quad)
//! are drawn as one rectangle, so their shared diagonal is walked once.

use super::*;

/// A triangle held back because it may make a rectangle with the next one ([`pair`]).
#[derive(Default)]
pub(super) struct Pairing {
    held: Option<Box<SetupTriangle>>,
    /// Whether `held` holds such a triangle.
    holding: bool,
}

impl Pairing {
    /// Passes `t` (whose box holds `area > 0` pixels of `region`) on to `emit` in primitive
    /// order: held back when it is half of an axis-aligned rectangle and `on`, drawn as one
    /// rectangle with the held triangle when they pair up.
    #[inline]
    #[allow(clippy::too_many_arguments)]
    pub(super) fn offer(
        &mut self,
        t: &SetupTriangle,
        area: i64,
        on: bool,
        nvary: usize,
        region: [i64; 4],
        stats: &mut Stats,
        mut emit: impl FnMut(&SetupTriangle, i64, &mut Stats),
    ) {
        if self.holding {
            self.holding = false;
            let mut h = self.held.take().unwrap_or_default();
            let paired = pair(&mut h, t, nvary);
            stats.tris_paired += paired as u64;
            emit(&h, box_area(&h, region), stats);
            self.held = Some(h);
            if paired {
                return;
            }
        }
        if on && half_rect(t).is_some() {
            let h = self.held.get_or_insert_with(Box::default);
            copy_triangle(h, t, nvary);
            self.holding = true;
            return;
        }
        emit(t, area, stats);
    }

    /// Passes the held triangle, if any, on to `emit`.
    pub(super) fn release(
        &mut self,
        region: [i64; 4],
        stats: &mut Stats,
        mut emit: impl FnMut(&SetupTriangle, i64, &mut Stats),
    ) {
        if self.holding {
            self.holding = false;
            if let Some(h) = self.held.take() {
                emit(&h, box_area(&h, region), stats);
                self.held = Some(h);
            }
        }
    }
}

/// Whether `t` is a right triangle with a horizontal and a vertical edge (half of an
/// axis-aligned rectangle): the index of its third (diagonal) edge.
#[inline(always)]
fn half_rect(t: &SetupTriangle) -> Option<usize> {
    let [e0, e1, e2] = &t.edges;
    // Cheap test first: most triangles have no horizontal or no vertical edge.
    if !((e0.a == 0) | (e1.a == 0) | (e2.a == 0)) || !((e0.b == 0) | (e1.b == 0) | (e2.b == 0)) {
        return None;
    }
    let kind = t.edges.map(|e| (e.a == 0) as u8 | ((e.b == 0) as u8) << 1);
    let mut seen = [0u8; 4];
    for k in kind {
        seen[k as usize] += 1;
    }
    (seen == [1, 1, 1, 0]).then(|| kind.iter().position(|&k| k == 0).unwrap_or(0))
}

/// An edge that every pixel is inside (`c > 0`, no slope).
const INSIDE: Edge = Edge { a: 0, b: 0, c: 1 };

/// Makes `h` the pixel rectangle that `h` and `t` cover together, when they are the two
/// halves of one axis-aligned rectangle with the same planes, flat values and facing;
/// returns whether it did.
///
/// Exactness:
/// - *Coverage.* Each half is a right triangle with a horizontal and a vertical leg, and
///   the third edge of one is the third edge of the other reversed (`a`, `b` negated,
///   `c₁ + c₂ = 1`: the same line, one fill-rule bias). Both triangles' edge functions are
///   positive inside, so they lie on opposite sides of the diagonal, and the two diagonal
///   functions sum to 1 at every pixel centre: each centre is inside exactly one of them
///   (the top-left rule's guarantee that shared edges neither crack nor overlap). A centre
///   is therefore covered by the pair exactly when it is inside the four legs, except at
///   a corner of the rectangle where the leg and diagonal biases meet; so pairs with a
///   corner on a pixel centre are left alone. Inside four axis-aligned edges is a pixel
///   rectangle: it becomes `h`'s box, with edges every pixel is inside.
/// - *Values.* Every pixel is computed from the same planes whichever triangle covers it:
///   bit-identical, except that a zero slope may be +0 in one and −0 in the other (a
///   constant attribute: `0 · d` takes the sign of d), allowed when `a0` is not −0: then
///   every sum of `a0` with the slope terms is the same value either way (x + ±0 = x for
///   x ≠ −0, and +0 + −0 = +0), and pixel coordinates are never negative.
fn pair(h: &mut SetupTriangle, t: &SetupTriangle, nvary: usize) -> bool {
    let (Some(i), Some(j)) = (half_rect(h), half_rect(t)) else {
        return false;
    };
    let (d1, d2) = (h.edges[i], t.edges[j]);
    if d2.a != -d1.a || d2.b != -d1.b || d1.c.checked_add(d2.c) != Some(1) {
        return false;
    }
    let zero_ok = |a: f32, b: f32| a.to_bits() == b.to_bits() || (a == 0.0 && b == 0.0);
    let same = |p: &Plane, q: &Plane| {
        p.a0.to_bits() == q.a0.to_bits()
            && ((p.dadx.to_bits() == q.dadx.to_bits() && p.dady.to_bits() == q.dady.to_bits())
                || (p.a0.to_bits() != (-0.0f32).to_bits()
                    && zero_ok(p.dadx, q.dadx)
                    && zero_ok(p.dady, q.dady)))
    };
    let planes_match = h.front == t.front
        && h.persp == t.persp
        && h.flat_u8 == t.flat_u8
        && same(&h.z, &t.z)
        && same(&h.w, &t.w)
        && (0..nvary)
            .all(|k| same(&h.vary[k], &t.vary[k]) && h.flat[k].to_bits() == t.flat[k].to_bits());
    if !planes_match {
        return false;
    }
    // The legs: vertical ones (b = 0) bound x, horizontal ones (a = 0) bound y. A leg from
    // vertex i to j has c = a·x_i − b·y_i plus 1 when it includes its centres.
    let legs = h
        .edges
        .iter()
        .chain(&t.edges)
        .filter(|e| e.a == 0 || e.b == 0);
    let (mut xs, mut ys) = ([0i64; 2], [0i64; 2]);
    let (mut nx, mut ny) = (0, 0);
    let (mut cols, mut rows) = ((i64::MIN, i64::MAX), (i64::MIN, i64::MAX));
    for e in legs {
        let bias = (e.a < 0 || (e.a == 0 && e.b < 0)) as i64;
        // (Setup's bottom-edge rule; a leg biased otherwise, as by the top-left rule,
        // leaves a remainder unless it is one unit long: then leave the pair.)
        if (e.a + e.b).abs() < 2 || (e.c - bias) % (e.a + e.b) != 0 {
            return false;
        }
        // The range of pixels inside: columns for a vertical leg, rows for a horizontal
        // one (`c + b·256·py > 0` is `Edge::span` of the edge with `a = −b`).
        let (range, at, n) = if e.b == 0 {
            (e.span(0), (e.c - bias) / e.a, &mut nx)
        } else {
            let across = Edge {
                a: -e.b,
                b: 0,
                c: e.c,
            };
            (across.span(0), -(e.c - bias) / e.b, &mut ny)
        };
        let Some((lo, hi)) = range else { return false };
        if e.b == 0 {
            if *n < 2 {
                xs[*n] = at;
            }
            cols = (cols.0.max(lo), cols.1.min(hi));
        } else {
            if *n < 2 {
                ys[*n] = at;
            }
            rows = (rows.0.max(lo), rows.1.min(hi));
        }
        *n += 1;
    }
    // Two distinct vertical and two distinct horizontal legs (the halves differ), no corner
    // on a pixel centre (pixel centres are the multiples of 256 in snapped coordinates),
    // and at least one pixel.
    let centre = |v: i64| v.rem_euclid(256) == 0;
    if nx != 2
        || ny != 2
        || xs[0] == xs[1]
        || ys[0] == ys[1]
        || xs.iter().any(|&x| centre(x)) && ys.iter().any(|&y| centre(y))
        || cols.0 > cols.1
        || rows.0 > rows.1
    {
        return false;
    }
    h.edges = [INSIDE; 3];
    h.bbox = [cols.0, rows.0, cols.1, rows.1];
    true
}

/// Copies `t` (its first `nvary` varyings) into `h`.
fn copy_triangle(h: &mut SetupTriangle, t: &SetupTriangle, nvary: usize) {
    h.edges = t.edges;
    h.bbox = t.bbox;
    h.front = t.front;
    h.z = t.z;
    h.w = t.w;
    h.persp = t.persp;
    h.flat_u8 = t.flat_u8;
    h.vary[..nvary].copy_from_slice(&t.vary[..nvary]);
    h.flat[..nvary].copy_from_slice(&t.flat[..nvary]);
}
