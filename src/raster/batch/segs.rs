//! Batches that span several draws ([`super`]): a glBegin/glEnd draw too small to be worth
//! the pool on its own leaves its set-up triangles in the batch it was filling, closed
//! with the draw's own record ([`DrawRec`]: fragment plan, copies of the unit plans,
//! region, varyings), and the next draw goes on filling the same batch. A program's
//! strips of a hundred triangles each so become batches of hundreds of triangles over
//! many bands, which both threads draw, where each strip alone fitted one or two bands.
//!
//! The triangles of one draw are consecutive in the batch, so a batch is a list of
//! segments: segment `k` holds the heads from the end of segment `k − 1` to its own
//! [`Seg::end`], and the heads after the last segment belong to the batch's own draw (the
//! rasterizer that fills it, or the [`super::Work`] it was launched as). A band's bin
//! lists its triangles in order, so drawing it segment after segment, each with its own
//! draw's plan, keeps primitive order: the images are those of the draws one at a time.

use super::Batch;
use crate::fragment::FragPlan;
use crate::framebuffer::Target;
use crate::geometry::setup::SetupTriangle;
use crate::raster::{raster_triangle, Draw};
use crate::stats::Stats;
use crate::texture::UnitPlan;

/// Where a segment's triangles start (or end) in a batch's buffers.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Start {
    /// Index of the first head.
    pub head: usize,
    /// Index of its first varying plane.
    pub plane: usize,
    /// Index of its first flat value.
    pub flat: usize,
}

/// What drawing one draw's triangles needs, kept with them in a batch after the draw has
/// returned. The unit plans are copies whose texture images stay untouched until the
/// batch is drawn (every GL call that could change them settles the batch first), so the
/// lifetime is that protocol's, as for [`super::Work`]'s units.
pub(super) struct DrawRec {
    pub plan: FragPlan,
    pub units: Vec<UnitPlan<'static>>,
    pub region: [i64; 4],
    pub nvary: usize,
    pub nflat: usize,
}

/// The triangles of one earlier draw in a batch: those before `end` (and after the
/// previous segment's end).
pub(super) struct Seg {
    pub end: Start,
    pub rec: DrawRec,
}

/// The batch's own draw: the plan its heads after the last segment are drawn with, and
/// their varyings and flat values per triangle.
#[derive(Clone, Copy)]
pub(super) struct Own<'x> {
    pub plan: &'x FragPlan,
    pub units: &'x [UnitPlan<'x>],
    pub region: [i64; 4],
    pub nvary: usize,
    pub nflat: usize,
}

impl Batch {
    /// Where the next head, plane and flat value go.
    pub(super) fn end(&self) -> Start {
        Start {
            head: self.heads.len(),
            plane: self.planes.len(),
            flat: self.flats.len(),
        }
    }

    /// Closes the triangles added since the last segment as one drawn with `rec`, when
    /// there are any; the batch's own draw then starts after them.
    pub(super) fn close(&mut self, rec: DrawRec) {
        let end = self.end();
        if end.head > self.own.head {
            self.segs.push(Seg { end, rec });
            self.own = end;
        }
    }

    /// Copies triangle `i` of a segment starting at `from`, whose triangles carry `nvary`
    /// varyings and `nflat` flat values, into `t`.
    #[inline]
    pub(super) fn load_in(
        &self,
        i: usize,
        from: Start,
        nvary: usize,
        nflat: usize,
        t: &mut SetupTriangle,
    ) {
        let h = &self.heads[i];
        t.edges = h.edges;
        t.bbox = h.bbox.map(i64::from);
        t.front = h.front;
        t.z = h.z;
        t.w = h.w;
        t.persp = h.persp;
        t.flat_u8 = h.flat_u8;
        let k = i - from.head;
        let p = from.plane + k * nvary;
        t.vary[..nvary].copy_from_slice(&self.planes[p..p + nvary]);
        let f = from.flat + k * nflat;
        t.flat[..nflat].copy_from_slice(&self.flats[f..f + nflat]);
    }
}

/// Draws triangles `idx` (ascending) of `batch` into `target`: each segment's with its
/// draw's plan, the rest with `own`.
pub(super) fn draw_indices(
    batch: &Batch,
    idx: &[u32],
    own: Own<'_>,
    target: &mut Target<'_>,
    stats: &mut Stats,
) {
    let mut rest = idx;
    let mut from = Start::default();
    for seg in &batch.segs {
        let n = rest.partition_point(|&i| (i as usize) < seg.end.head);
        let (mine, after) = rest.split_at(n);
        let it = mine.iter().map(|&i| i as usize);
        draw_seg(batch, it, from, seg_own(&seg.rec), target, stats);
        rest = after;
        from = seg.end;
    }
    let it = rest.iter().map(|&i| i as usize);
    draw_seg(batch, it, from, own, target, stats);
}

/// Draws every triangle of `batch` into `target` in order (see [`draw_indices`]).
pub(super) fn draw_all(batch: &Batch, own: Own<'_>, target: &mut Target<'_>, stats: &mut Stats) {
    let mut from = Start::default();
    for seg in &batch.segs {
        let it = from.head..seg.end.head;
        draw_seg(batch, it, from, seg_own(&seg.rec), target, stats);
        from = seg.end;
    }
    let it = from.head..batch.heads.len();
    draw_seg(batch, it, from, own, target, stats);
}

/// A segment's record as the plan to draw it with.
fn seg_own(r: &DrawRec) -> Own<'_> {
    Own {
        plan: &r.plan,
        units: &r.units,
        region: r.region,
        nvary: r.nvary,
        nflat: r.nflat,
    }
}

/// Draws triangles `idx` of the segment starting at `from` with `own`, if there are any.
fn draw_seg(
    batch: &Batch,
    idx: impl Iterator<Item = usize>,
    from: Start,
    own: Own<'_>,
    target: &mut Target<'_>,
    stats: &mut Stats,
) {
    let mut idx = idx.peekable();
    if idx.peek().is_none() {
        return;
    }
    let d = &mut Draw::new(own.region, own.plan, own.units, target, stats);
    // A fresh triangle per segment: varyings past a draw's count stay zero.
    let mut t = SetupTriangle::default();
    for i in idx {
        batch.load_in(i, from, own.nvary, own.nflat, &mut t);
        raster_triangle(&t, d);
    }
}

/// Draws every triangle of `batch`, all of them in closed segments (a batch left pending
/// by a draw, [`Batch::close`]), into `target`.
pub(super) fn draw_closed(batch: &Batch, target: &mut Target<'_>, stats: &mut Stats) {
    if let Some(last) = batch.segs.last() {
        draw_all(batch, seg_own(&last.rec), target, stats);
    }
}
