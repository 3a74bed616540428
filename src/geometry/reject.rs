//! Trivial rejection ahead of the vertex stage: a streamed draw's triangle whose three
//! vertices are outside the same clip plane is dropped from the clip masks of a pass over
//! the positions alone ([`crate::fixed_function::transform::VertexStage::clip_masks`]),
//! before its vertices are lit, fogged or have their texture coordinates generated. The
//! masks are the ones the whole vertex stage gives, so a triangle is dropped exactly when
//! the clip test after the stage would drop it.
//!
//! [`Rejection`] holds the masks and which vertices some surviving triangle reads (only
//! those run through the stage when the stream transforms runs of vertices ahead).
//!
//! A draw of independent primitives (GL_TRIANGLES, GL_QUADS) is also judged a chunk of
//! [`CHUNK`] primitives at a time: when the masks of every vertex a chunk reads share a
//! plane, every triangle of the chunk is outside it, and the stream counts the chunk's
//! triangles as rejected without assembling them ([`Rejection::dead`]). The same
//! triangles are dropped, and counted, as one at a time. A floor grid of 80,000
//! triangles that MuJoCo draws in each of its six passes a frame is mostly outside the
//! view (69,548 of them in a scene pass, 79,872 in a shadow pass).

use super::assemble::{self, DrawPath};
use super::ClipMask;
use crate::pipe::Primitive;

/// Primitives per chunk of a draw of independent primitives judged at once.
pub const CHUNK: usize = 64;

/// The vertices and triangles of one primitive of `mode` when its primitives share no
/// vertex reference (GL_TRIANGLES, GL_QUADS), else `None`.
pub fn independent(mode: Primitive) -> Option<(usize, usize)> {
    match mode {
        Primitive::Triangles => Some((3, 1)),
        Primitive::Quads => Some((4, 2)),
        _ => None,
    }
}

/// The clip masks of a streamed draw's vertices and the vertices its surviving triangles
/// read.
#[derive(Default)]
pub struct Rejection {
    /// The clip mask of each vertex of the source (empty when no vertex is outside the
    /// clip volume: then nothing is rejected).
    masks: Vec<ClipMask>,
    /// Whether each vertex of the source is read by a triangle that is not rejected
    /// (empty when every triangle survives).
    live: Vec<bool>,
    /// Per chunk of [`CHUNK`] primitives of a draw of independent primitives, whether
    /// every vertex it reads is outside one plane (empty otherwise).
    dead: Vec<bool>,
}

impl Rejection {
    /// The rejection of the triangles of `mode` over `n` vertex references (vertex `ix(k)`
    /// of the source for reference `k`), assembled as `path` and `flat` assemble them,
    /// given the masks of the source's vertices (`masks`, taken). With `live`, also
    /// which vertices the surviving triangles read. A vertex past the masks counts as
    /// inside (its triangles are never rejected here; the clip test after the stage
    /// still rejects them).
    pub fn new(
        masks: Vec<ClipMask>,
        mode: Primitive,
        n: usize,
        path: DrawPath,
        flat: bool,
        ix: impl Fn(usize) -> usize,
        live: bool,
    ) -> Self {
        if masks.iter().all(|&m| m == 0) {
            return Rejection::default();
        }
        let mut r = Rejection {
            masks,
            live: Vec::new(),
            dead: Vec::new(),
        };
        let unit = independent(mode);
        if let Some((verts, _)) = unit {
            // A vertex past the masks counts as inside: its chunk is not dead.
            let m = |i: usize| r.masks.get(i).copied().unwrap_or(0);
            let prims = n / verts;
            r.dead = (0..prims.div_ceil(CHUNK))
                .map(|c| {
                    let (a, b) = (c * CHUNK * verts, ((c + 1) * CHUNK).min(prims) * verts);
                    (a..b).fold(!0, |acc, k| acc & m(ix(k))) != 0
                })
                .collect();
        }
        if live {
            let mut flags = vec![false; r.masks.len()];
            let (mut any, mut skipped) = (false, false);
            let mut keep = |a: usize, b: usize, c: usize| {
                let k = [ix(a), ix(b), ix(c)];
                if r.rejects(k) {
                    any = true;
                } else {
                    for i in k {
                        if let Some(f) = flags.get_mut(i) {
                            *f = true;
                        }
                    }
                }
            };
            match unit {
                Some((verts, _)) => {
                    for (c, &dead) in r.dead.iter().enumerate() {
                        if dead {
                            skipped = true;
                            continue;
                        }
                        let a = c * CHUNK * verts;
                        let len = (n / verts * verts - a).min(CHUNK * verts);
                        assemble::triangles(mode, len, path, flat, |p, q, t| {
                            keep(a + p, a + q, a + t)
                        });
                    }
                }
                None => assemble::triangles(mode, n, path, flat, keep),
            }
            if any || skipped {
                r.live = flags;
            }
        }
        r
    }

    /// Whether every triangle of chunk `c` ([`CHUNK`] primitives from primitive
    /// `c * CHUNK`) of a draw of independent primitives is outside one clip plane.
    #[inline]
    pub fn dead(&self, c: usize) -> bool {
        self.dead.get(c).copied().unwrap_or(false)
    }

    /// The primitive that halves the chunks of primitives `p0..p1` that are not dead
    /// ([`Self::dead`]), at a chunk boundary (`p0 + (p1 - p0) / 2` when none is dead):
    /// where a draw split over two threads cuts, so that each sets up half of what is
    /// drawn. MuJoCo's floor grid, seen from the camera, is drawn by the chunks of its
    /// first half alone.
    pub fn live_middle(&self, p0: usize, p1: usize) -> usize {
        let even = p0 + (p1 - p0) / 2;
        if self.dead.is_empty() || p1 <= p0 {
            return even;
        }
        let alive = |c: usize| !self.dead(c);
        let (c0, c1) = (p0 / CHUNK, p1.div_ceil(CHUNK));
        let total = (c0..c1).filter(|&c| alive(c)).count();
        if total < 2 {
            return even;
        }
        let mut seen = 0;
        for c in c0..c1 {
            seen += usize::from(alive(c));
            if seen * 2 >= total {
                return ((c + 1) * CHUNK).clamp(p0, p1);
            }
        }
        even
    }

    /// Whether the triangle of source vertices `k` is outside one clip plane.
    #[inline(always)]
    pub fn rejects(&self, k: [usize; 3]) -> bool {
        let m = |i: usize| self.masks.get(i).copied().unwrap_or(0);
        m(k[0]) & m(k[1]) & m(k[2]) != 0
    }

    /// Which vertices the surviving triangles read, when some triangle is rejected and
    /// the rejection was asked for them (a vertex past the slice is read).
    pub fn live(&self) -> Option<&[bool]> {
        (!self.live.is_empty()).then_some(&self.live[..])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_triangle_outside_one_plane_is_rejected_and_its_own_vertices_are_not_live() {
        // Vertices 0..3 right of x = w, 3 left of it, 4 and 5 above and below y = w.
        let masks = vec![1, 1, 1, 0, 4, 1];
        let ix = |k: usize| k;
        let r = Rejection::new(
            masks.clone(),
            Primitive::Triangles,
            6,
            DrawPath::Clip,
            false,
            ix,
            true,
        );
        assert!(r.rejects([0, 1, 2]));
        assert!(!r.rejects([3, 4, 5]));
        assert!(!r.rejects([0, 1, 4]), "outside different planes");
        assert!(
            !r.rejects([0, 1, 9]),
            "a vertex past the masks counts as inside"
        );
        assert_eq!(r.live(), Some(&[false, false, false, true, true, true][..]));
        // A strip shares vertices: 1 and 2 are read by the surviving (2, 1, 3).
        let r = Rejection::new(
            masks,
            Primitive::TriangleStrip,
            4,
            DrawPath::Clip,
            false,
            ix,
            true,
        );
        assert_eq!(r.live(), Some(&[false, true, true, true, false, false][..]));
        // Nothing outside: nothing to reject, no pass over the triangles.
        let r = Rejection::new(
            vec![0; 4],
            Primitive::Triangles,
            3,
            DrawPath::ArraysNoClip,
            false,
            ix,
            true,
        );
        assert!(!r.rejects([0, 1, 2]));
        assert_eq!(r.live(), None);
    }

    #[test]
    fn a_chunk_whose_vertices_share_a_plane_is_dead_and_the_same_triangles_are_rejected() {
        // 3 chunks of quads (the last one short): chunk 0 all right of x = w (bit 1) but
        // one vertex also above (1 | 4); chunk 1 left (2) except one inside vertex;
        // chunk 2 all above (4).
        let quads = 2 * CHUNK + 5;
        let mut masks = vec![1u16; CHUNK * 4];
        masks[7] = 1 | 4;
        masks.extend(vec![2u16; CHUNK * 4]);
        masks[CHUNK * 4 + 9] = 0;
        masks.extend(vec![4u16; 5 * 4]);
        let n = quads * 4;
        let ix = |k: usize| k;
        let dead = Rejection::new(
            masks.clone(),
            Primitive::Quads,
            n,
            DrawPath::Clip,
            false,
            ix,
            true,
        );
        assert!(dead.dead(0) && !dead.dead(1) && dead.dead(2) && !dead.dead(3));
        // The live vertices are those the per-triangle judgement gives: only chunk 1's
        // triangles that read the inside vertex survive.
        let mut expect = vec![false; n];
        crate::geometry::assemble::triangles(
            Primitive::Quads,
            n,
            DrawPath::Clip,
            false,
            |a, b, c| {
                if masks[a] & masks[b] & masks[c] == 0 {
                    for v in [a, b, c] {
                        expect[v] = true;
                    }
                }
            },
        );
        assert_eq!(dead.live(), Some(&expect[..]));
        assert!(expect.iter().any(|&l| l));
        // A vertex past the masks counts as inside: its chunk stays alive. Strips share
        // vertices between primitives: no chunks.
        let first_dead = |nmasks: usize, mode: Primitive| {
            Rejection::new(
                vec![4u16; nmasks],
                mode,
                12,
                DrawPath::Clip,
                false,
                ix,
                false,
            )
            .dead(0)
        };
        assert!(!first_dead(10, Primitive::Triangles));
        assert!(first_dead(12, Primitive::Triangles));
        assert!(!first_dead(12, Primitive::TriangleStrip));
    }

    #[test]
    fn a_split_halves_the_chunks_that_are_not_dead() {
        // 8 chunks of triangles; chunks 0, 1, 2, 3 and 6 outside x = w, 4, 5 and 7 inside.
        let n = 8 * CHUNK * 3;
        let masks: Vec<u16> = (0..n)
            .map(|v| u16::from(!matches!(v / (CHUNK * 3), 4 | 5 | 7)))
            .collect();
        let r = Rejection::new(
            masks,
            Primitive::Triangles,
            n,
            DrawPath::Clip,
            false,
            |k| k,
            false,
        );
        assert!(r.dead(0) && r.dead(3) && !r.dead(4) && r.dead(6) && !r.dead(7));
        // Alive 4, 5, 7: the cut follows chunk 5 (two of three before it).
        assert_eq!(r.live_middle(0, 8 * CHUNK), 6 * CHUNK);
        // From chunk 5 on (alive 5 and 7): after chunk 5.
        assert_eq!(r.live_middle(5 * CHUNK, 8 * CHUNK), 6 * CHUNK);
        // One chunk alive, or nothing rejected: the middle primitive.
        assert_eq!(r.live_middle(6 * CHUNK, 8 * CHUNK), 7 * CHUNK);
        assert_eq!(Rejection::default().live_middle(10, 31), 20);
    }
}
