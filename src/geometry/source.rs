//! Where a draw's vertices come from, and the post-transform vertex cache.
//!
//! A draw reads its vertices through [`VertexSource`]: an array of fetched vertices
//! (immediate mode, display lists) or the enabled vertex arrays themselves, fetched as the
//! vertex stage needs them ([`FetchSource`]), so an array draw keeps no per-vertex copy of
//! its input. The triangle path transforms vertices on demand through [`VertexCache`], a
//! small direct-mapped cache keyed by vertex index, so memory does not grow with the draw
//! and a vertex shared by neighbouring triangles of an indexed mesh is transformed once.

use super::fetch::{FloatPositions, VertexFetcher, VertexIn};
use super::ClipVertex;

/// A vertex read through [`VertexSource::vertex_into`], reused from one read to the next
/// so that a source rewrites only the attributes that can differ (reading a whole
/// [`VertexIn`], about 200 bytes, per vertex was a visible part of small-triangle draws).
#[derive(Clone, Copy, Debug)]
pub struct VertexSlot {
    /// The vertex last read.
    pub v: VertexIn,
    /// The source's own note of what `v` holds beyond the per-vertex attributes.
    pub tag: usize,
}

/// The vertices of one draw, addressed 0..count.
pub trait VertexSource: Sync {
    /// How many vertices the draw can address.
    fn count(&self) -> usize;
    /// Vertex `i` (`i < count()`).
    fn vertex(&self, i: usize) -> VertexIn;
    /// A slot for [`Self::vertex_into`], made once per draw.
    fn new_slot(&self) -> VertexSlot {
        let cur = crate::pipe::CurrentAttribs::default();
        VertexSlot {
            v: VertexIn::with_current([0.0, 0.0, 0.0, 1.0], &cur),
            tag: usize::MAX,
        }
    }
    /// Reads vertex `i` into `slot` (whose `v` then equals `vertex(i)`); `slot` must come
    /// from this source's [`Self::new_slot`] and have been written only by this method.
    #[inline]
    fn vertex_into(&self, i: usize, slot: &mut VertexSlot) {
        slot.v = self.vertex(i);
    }
    /// The object-space position of vertex `i`: `vertex(i).pos`, without the other
    /// attributes.
    fn position(&self, i: usize) -> [f32; 4] {
        self.vertex(i).pos
    }
    /// The edge flag of vertex `i`.
    fn edge_flag(&self, i: usize) -> bool {
        self.vertex(i).edge_flag
    }
    /// Generic attribute `loc` of vertex `i` from its enabled array (`None`: no array, the
    /// attribute's current value applies).
    fn generic(&self, i: usize, loc: usize) -> Option<[f32; 4]> {
        let _ = (i, loc);
        None
    }
    /// The positions of vertices `0..count()` as a plain float array, when they are
    /// stored as one ([`FloatPositions::get`] reads what [`Self::position`] reads).
    fn float_positions(&self) -> Option<FloatPositions<'_>> {
        None
    }
    /// Boxes around runs of the positions ([`super::boxes`]), when the source keeps them
    /// (a compiled display list's).
    fn position_boxes(&self) -> Option<super::boxes::PositionBoxes<'_>> {
        None
    }
}

impl VertexSource for [VertexIn] {
    #[inline]
    fn count(&self) -> usize {
        self.len()
    }
    #[inline]
    fn vertex(&self, i: usize) -> VertexIn {
        self[i]
    }
    #[inline]
    fn position(&self, i: usize) -> [f32; 4] {
        self[i].pos
    }
    #[inline]
    fn edge_flag(&self, i: usize) -> bool {
        self[i].edge_flag
    }
}

/// Vertices fetched from scattered array elements (a sparse glDrawElements), with their
/// generic attributes from enabled arrays when any is (a vertex shader's; empty
/// otherwise).
#[derive(Default)]
pub struct Gathered {
    /// The vertices.
    pub verts: Vec<VertexIn>,
    /// Each vertex's generic attributes (`None`: no array), or empty.
    pub generic: Vec<[Option<[f32; 4]>; crate::pipe::arrays::MAX_GENERIC]>,
}

impl VertexSource for Gathered {
    #[inline]
    fn count(&self) -> usize {
        self.verts.len()
    }
    #[inline]
    fn vertex(&self, i: usize) -> VertexIn {
        self.verts[i]
    }
    #[inline]
    fn position(&self, i: usize) -> [f32; 4] {
        self.verts[i].pos
    }
    #[inline]
    fn edge_flag(&self, i: usize) -> bool {
        self.verts[i].edge_flag
    }
    fn generic(&self, i: usize, loc: usize) -> Option<[f32; 4]> {
        *self.generic.get(i)?.get(loc)?
    }
}

/// Vertices `base..base + count` of the enabled arrays, fetched when read.
pub struct FetchSource<'a> {
    fetch: VertexFetcher<'a>,
    base: u32,
    count: usize,
}

impl<'a> FetchSource<'a> {
    /// The vertices `base..base + count` of `fetch` (indices past `u32::MAX` read as
    /// element `u32::MAX`, which no real array reaches).
    ///
    /// # Safety
    /// As [`VertexFetcher::fetch`]: enabled client-memory arrays must be valid for every
    /// index in the range.
    pub unsafe fn new(fetch: VertexFetcher<'a>, base: u32, count: usize) -> Self {
        FetchSource { fetch, base, count }
    }

    /// The array element of vertex `i`.
    #[inline]
    fn index(&self, i: usize) -> u32 {
        u32::try_from(i)
            .ok()
            .and_then(|i| self.base.checked_add(i))
            .unwrap_or(u32::MAX)
    }
}

// SAFETY: a `FetchSource` only reads: the buffer stores it borrows, and client memory
// through the array pointers, which `FetchSource::new`'s caller promised valid for the
// draw, during which nothing writes them (the draw's caller is inside the GL call).
// Reading them from the draw's two threads at once is therefore no data race.
unsafe impl Sync for FetchSource<'_> {}

impl VertexSource for FetchSource<'_> {
    #[inline]
    fn count(&self) -> usize {
        self.count
    }
    #[inline]
    fn vertex(&self, i: usize) -> VertexIn {
        // SAFETY: `FetchSource::new` made the caller promise the range is valid.
        unsafe { self.fetch.fetch(self.index(i)) }
    }
    fn new_slot(&self) -> VertexSlot {
        VertexSlot {
            v: self.fetch.base(),
            tag: 0,
        }
    }
    #[inline]
    fn vertex_into(&self, i: usize, slot: &mut VertexSlot) {
        // SAFETY: as in `vertex`; `slot.v` came from `new_slot` and was written only
        // here, so its attributes without an enabled array hold the current values.
        unsafe { self.fetch.fetch_into(self.index(i), &mut slot.v) }
    }
    #[inline]
    fn position(&self, i: usize) -> [f32; 4] {
        // SAFETY: as in `vertex`.
        unsafe { self.fetch.position(self.index(i)) }
    }
    fn generic(&self, i: usize, loc: usize) -> Option<[f32; 4]> {
        // SAFETY: as in `vertex`.
        unsafe { self.fetch.generic(loc, self.index(i)) }
    }
    fn float_positions(&self) -> Option<FloatPositions<'_>> {
        // SAFETY: as in `vertex` (the range is the one `FetchSource::new` was given).
        unsafe { self.fetch.float_positions(self.base, self.count) }
    }
}

/// log2 of the largest cache: 1024 entries keep two rows of a 500-vertex-wide grid mesh.
const CACHE_BITS: u32 = 10;
const CACHE_SIZE: usize = 1 << CACHE_BITS;

/// A direct-mapped post-transform cache: entry `i % size` holds vertex `i` when its tag
/// says so (`size` a power of two, at most 1024). Every entry of a draw is written by the same vertex stage, so an entry that is
/// overwritten needs only the fields that stage writes.
pub struct VertexCache {
    /// Entries minus one (a power of two minus one).
    mask: usize,
    tags: Vec<usize>,
    slots: Vec<ClipVertex>,
    /// Three entries for a triangle whose vertices share a cache slot.
    spill: [ClipVertex; 3],
    /// Vertices transformed (cache misses).
    pub transformed: u64,
}

impl VertexCache {
    /// An empty cache for a draw that assembles `n` vertex references: no more entries
    /// than it can use, so a draw of a few vertices does not clear 1024 of them (180 KB).
    pub fn for_draw(n: usize) -> Self {
        let size = n.clamp(4, CACHE_SIZE).next_power_of_two();
        VertexCache {
            mask: size - 1,
            tags: vec![usize::MAX; size],
            slots: vec![ClipVertex::default(); size],
            spill: [ClipVertex::default(); 3],
            transformed: 0,
        }
    }

    /// Empties the cache, as [`Self::for_draw`] makes it, for another draw of `n` vertex
    /// references, keeping its memory when it is large enough. The entries are cleared
    /// too: the next draw's vertex stage may write fewer fields.
    pub fn reset(&mut self, n: usize) {
        let size = n.clamp(4, CACHE_SIZE).next_power_of_two();
        if self.slots.len() < size {
            *self = Self::for_draw(n);
            return;
        }
        self.mask = size - 1;
        self.tags[..size].fill(usize::MAX);
        self.slots[..size].fill(ClipVertex::default());
        self.spill = [ClipVertex::default(); 3];
        self.transformed = 0;
    }

    /// Transforms vertices `start..end` into their entries ahead of the triangles that
    /// read them: `run(i, out)` fills the entries of vertices `i..i + out.len()` (a run of
    /// consecutive entries; the range is split where the entries wrap). An entry it
    /// overwrites is transformed again when a triangle reads its old vertex. Fills at most
    /// as many vertices as the cache holds; returns the end of what it filled.
    pub fn fill(
        &mut self,
        start: usize,
        end: usize,
        run: impl FnMut(usize, &mut [ClipVertex]),
    ) -> usize {
        self.fill_where(start, end, |_| true, run)
    }

    /// [`Self::fill`] of only the vertices `live` marks (a vertex past it counts as
    /// marked), in runs of consecutive marked vertices: the entries of the others are
    /// left as they are, so a vertex no drawn triangle reads is not transformed.
    pub fn fill_live(
        &mut self,
        start: usize,
        end: usize,
        live: &[bool],
        run: impl FnMut(usize, &mut [ClipVertex]),
    ) -> usize {
        self.fill_where(start, end, |i| live.get(i).copied().unwrap_or(true), run)
    }

    /// [`Self::fill`] of the vertices `keep` accepts.
    #[inline(always)]
    fn fill_where(
        &mut self,
        start: usize,
        end: usize,
        keep: impl Fn(usize) -> bool,
        mut run: impl FnMut(usize, &mut [ClipVertex]),
    ) -> usize {
        let end = end.min(start + self.mask + 1);
        let mut i = start;
        while i < end {
            if !keep(i) {
                i += 1;
                continue;
            }
            let s = i & self.mask;
            let mut len = 1;
            while len < (end - i).min(self.mask + 1 - s) && keep(i + len) {
                len += 1;
            }
            run(i, &mut self.slots[s..s + len]);
            for (j, tag) in self.tags[s..s + len].iter_mut().enumerate() {
                *tag = i + j;
            }
            self.transformed += len as u64;
            i += len;
        }
        end
    }

    /// The transformed vertices `idx` of one triangle; `run(i, out)` transforms vertex
    /// `i` into `out` on a miss.
    #[inline]
    pub fn triangle(
        &mut self,
        idx: [usize; 3],
        mut run: impl FnMut(usize, &mut ClipVertex),
    ) -> [&ClipVertex; 3] {
        let s = idx.map(|i| i & self.mask);
        let clash = |a: usize, b: usize| s[a] == s[b] && idx[a] != idx[b];
        if clash(0, 1) || clash(0, 2) || clash(1, 2) {
            for (k, out) in self.spill.iter_mut().enumerate() {
                run(idx[k], out);
            }
            self.transformed += 3;
            let [a, b, c] = &self.spill;
            return [a, b, c];
        }
        for k in 0..3 {
            if self.tags[s[k]] != idx[k] {
                run(idx[k], &mut self.slots[s[k]]);
                self.tags[s[k]] = idx[k];
                self.transformed += 1;
            }
        }
        [&self.slots[s[0]], &self.slots[s[1]], &self.slots[s[2]]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Draws `tris` through the cache, checking that every corner is its own vertex.
    fn draw(c: &mut VertexCache, tris: &[[usize; 3]]) {
        let run = |i: usize, out: &mut ClipVertex| out.win[0] = i as f32;
        for &t in tris {
            assert_eq!(c.triangle(t, run).map(|v| v.win[0]), t.map(|i| i as f32));
        }
    }

    #[test]
    fn cache_transforms_shared_vertices_once_and_survives_clashes() {
        let mut c = VertexCache::for_draw(CACHE_SIZE);
        draw(&mut c, &[[0, 1, 2], [2, 1, 3]]);
        assert_eq!(c.transformed, 4);
        // 5 and 5 + CACHE_SIZE share a slot.
        draw(&mut c, &[[5, CACHE_SIZE + 5, 6], [1, 2, 3]]);
        assert_eq!(c.transformed, 7);
    }

    #[test]
    fn a_small_draws_cache_is_small_and_still_exact() {
        let mut c = VertexCache::for_draw(6);
        assert_eq!(c.slots.len(), 8);
        assert_eq!(VertexCache::for_draw(100_000).slots.len(), CACHE_SIZE);
        // 1 and 9 share a slot of the 8-entry cache; 0 and 8 too, in two triangles.
        draw(&mut c, &[[1, 9, 2], [0, 2, 3], [8, 2, 3]]);
        // 3 (the spill caches nothing) + 3 (0, 2, 3) + 1 (8 evicts 0).
        assert_eq!(c.transformed, 7);
    }

    #[test]
    fn fill_transforms_runs_ahead_and_a_vertex_it_evicts_comes_back() {
        let mut c = VertexCache::for_draw(8);
        let mut runs = Vec::new();
        let fill = |c: &mut VertexCache, a: usize, b: usize, runs: &mut Vec<(usize, usize)>| {
            c.fill(a, b, |i, out: &mut [ClipVertex]| {
                runs.push((i, out.len()));
                for (j, o) in out.iter_mut().enumerate() {
                    o.win[0] = (i + j) as f32;
                }
            })
        };
        let run = |i: usize, out: &mut ClipVertex| out.win[0] = i as f32;
        assert_eq!(fill(&mut c, 0, 3, &mut runs), 3);
        // A fan around vertex 0: its first triangles read what the fill wrote.
        let t = c.triangle([0, 1, 2], run);
        assert_eq!(t.map(|v| v.win[0]), [0.0, 1.0, 2.0]);
        assert_eq!(c.transformed, 3);
        // 6..12 wraps around the 8 entries: two runs; 8 evicts 0, 9 evicts 1 …
        assert_eq!(fill(&mut c, 6, 12, &mut runs), 12);
        assert_eq!(runs, [(0, 3), (6, 2), (8, 4)]);
        assert_eq!(c.transformed, 9);
        let t = c.triangle([0, 10, 11], run);
        assert_eq!(t.map(|v| v.win[0]), [0.0, 10.0, 11.0]);
        // Only 0 came back (it evicted 8).
        assert_eq!(c.transformed, 10);
        let t = c.triangle([6, 7, 9], run);
        assert_eq!(t.map(|v| v.win[0]), [6.0, 7.0, 9.0]);
        assert_eq!(c.transformed, 10);
        // No more than the cache holds at once.
        runs.clear();
        assert_eq!(fill(&mut c, 20, 40, &mut runs), 28);
        assert_eq!(runs, [(20, 4), (24, 4)]);
        assert_eq!(c.transformed, 18);
    }
}
