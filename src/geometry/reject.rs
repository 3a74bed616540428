//! Trivial rejection ahead of the vertex stage: a streamed draw's triangle whose three
//! vertices are outside the same clip plane is dropped from the clip masks of a pass over
//! the positions alone ([`crate::fixed_function::transform::VertexStage::clip_masks`]),
//! before its vertices are lit, fogged or have their texture coordinates generated. The
//! masks are the ones the whole vertex stage gives, so a triangle is dropped exactly when
//! the clip test after the stage would drop it.
//!
//! [`Rejection`] holds the masks and which vertices some surviving triangle reads (only
//! those run through the stage when the stream transforms runs of vertices ahead).

use super::assemble::{self, DrawPath};
use super::ClipMask;
use crate::pipe::Primitive;

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
        };
        if live {
            let mut flags = vec![false; r.masks.len()];
            let mut any = false;
            assemble::triangles(mode, n, path, flat, |a, b, c| {
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
            });
            if any {
                r.live = flags;
            }
        }
        r
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
}
