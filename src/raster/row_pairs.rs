//! The pairs of rows the quad walks visit (the textured walks, the texture fast path's
//! 8-wide walk and the one-pass multisample walk): rows `qy` and `qy + 1` of a
//! triangle's box from an aligned start (even rows, as llvmpipe's 2x2 quads, unless a
//! walk samples without quads), with each row's covered pixels by one or more sets of
//! edges (one per sample for the multisample walk) and the extent of their union.
//! Pairs that cover nothing are skipped. An iterator rather than a closure walker: a
//! closure body would be compiled outside the callers' CPU-specific entry points
//! (without AVX2/FMA).

use crate::geometry::setup::{row_span, Edge};

/// One pair of rows of [`RowPairs`].
pub(super) struct RowPair<const K: usize> {
    /// The top row.
    pub qy: i64,
    /// Each row's covered pixels `(first, last)` by each set of edges.
    pub spans: [[Option<(i64, i64)>; K]; 2],
    /// The first pixel any row covers.
    pub lo: i64,
    /// The last pixel any row covers.
    pub hi: i64,
}

/// The covered pairs of rows of a box by `K` sets of edges (see the module comment).
pub(super) struct RowPairs<'e, const K: usize> {
    edges: &'e [[Edge; 3]; K],
    b: [i64; 4],
    qy: i64,
}

impl<'e, const K: usize> RowPairs<'e, K> {
    /// The pairs of rows of box `b` (inclusive) covered by `edges`, from row
    /// `b[1] & align` (`!1` for even rows, `!0` from the box's first row).
    #[inline(always)]
    pub fn new(edges: &'e [[Edge; 3]; K], b: [i64; 4], align: i64) -> Self {
        RowPairs {
            edges,
            b,
            qy: b[1] & align,
        }
    }
}

impl<const K: usize> Iterator for RowPairs<'_, K> {
    type Item = RowPair<K>;

    #[inline(always)]
    fn next(&mut self) -> Option<RowPair<K>> {
        let b = self.b;
        while self.qy <= b[3] {
            let qy = self.qy;
            self.qy += 2;
            let mut spans = [[None; K]; 2];
            let (mut lo, mut hi) = (i64::MAX, i64::MIN);
            for (r, row) in spans.iter_mut().enumerate() {
                let py = qy + r as i64;
                if py < b[1] || py > b[3] {
                    continue;
                }
                for (span, e) in row.iter_mut().zip(self.edges) {
                    *span = row_span(e, b[0], b[2], py);
                    if let Some((a, z)) = *span {
                        lo = lo.min(a);
                        hi = hi.max(z);
                    }
                }
            }
            if lo <= hi {
                return Some(RowPair { qy, spans, lo, hi });
            }
        }
        None
    }
}
