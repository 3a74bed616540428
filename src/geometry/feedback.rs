//! The primitive stages of the feedback and selection render modes, as Mesa runs them
//! through its private draw module (`st_cb_feedback.c`, `st_draw_feedback.c`): the
//! draw module's decomposition, clipping, cull, two-side, polygon offset, flat-shade and
//! unfilled stages, then a [`PrimSink`] in place of the rasterizer. Mesa turns wide
//! lines, wide points and line stipple off for this draw context, so none of them
//! change what feedback reports.

use super::clip::{clip_line, clip_triangle_edges, UserPlanes};
use super::setup::CullMode;
use super::unfilled::{
    decompose, determinant, draw_offset, fill_mode, scaled_units, EDGE_0, EDGE_1, EDGE_2,
};
use super::{ClipVertex, Viewport};
use crate::pipe::Primitive;
use crate::pipe::{FillMode, PolygonState};

/// Where the primitives that survive the stages go.
pub trait PrimSink {
    /// A point.
    fn point(&mut self, v: &ClipVertex);
    /// A line segment.
    fn line(&mut self, a: &ClipVertex, b: &ClipVertex);
    /// A filled triangle.
    fn triangle(&mut self, v: [&ClipVertex; 3]);
    /// The unfilled stage restarts the line stipple (a triangle flagged as the start of
    /// a primitive, drawn as lines).
    fn reset_stipple(&mut self);
}

/// The state the stages read, taken from the context once per draw.
#[derive(Clone, Copy, Debug)]
pub struct PrimStages<'a> {
    /// Enabled user clip planes in clip space.
    pub ucp: &'a UserPlanes,
    /// The viewport (clipped vertices get window coordinates from it).
    pub viewport: Viewport,
    /// Varyings the vertex stage wrote.
    pub nvary: usize,
    /// GL_FLAT shading.
    pub flat: bool,
    /// Face culling (both flags off when GL_CULL_FACE is disabled).
    pub cull: CullMode,
    /// Offset of the back colours among the varyings (two-sided lighting).
    pub back: Option<usize>,
    /// Polygon modes and offset.
    pub polygon: PolygonState,
    /// GL_POLYGON_OFFSET_FILL, _LINE and _POINT.
    pub offset: [bool; 3],
    /// Depth buffer bits (scales the offset units).
    pub depth_bits: u32,
}

impl PrimStages<'_> {
    /// The varyings the clipper copies from the provoking vertex (the colours under
    /// GL_FLAT).
    fn flat_mask(&self) -> u64 {
        if self.flat {
            super::clip::FLAT_COLORS
        } else {
            0
        }
    }

    /// Runs `n` vertices of `mode` (the k-th is `at(k)`, its edge flag `edge_flag(k)`)
    /// through the stages into `sink`.
    pub fn run<'v>(
        &self,
        mode: Primitive,
        n: usize,
        at: impl Fn(usize) -> &'v ClipVertex,
        edge_flag: impl Fn(usize) -> bool,
        sink: &mut impl PrimSink,
    ) {
        match mode {
            Primitive::Points => (0..n).map(&at).filter(|v| v.mask == 0).for_each(|v| {
                sink.point(v);
            }),
            Primitive::Lines | Primitive::LineStrip | Primitive::LineLoop => {
                super::assemble::lines(mode, n, |a, b, _| self.line(at(a), at(b), sink));
            }
            _ => decompose(mode, n, |a, b, c, flags, reset| {
                let v = [at(a), at(b), at(c)];
                let mut edges = flags;
                for (bit, k) in [(EDGE_0, a), (EDGE_1, b), (EDGE_2, c)] {
                    if !edge_flag(k) {
                        edges &= !bit;
                    }
                }
                let or = v[0].mask | v[1].mask | v[2].mask;
                if v[0].mask & v[1].mask & v[2].mask != 0 {
                } else if or != 0 {
                    let (vp, ucp, nvary) = (&self.viewport, self.ucp, self.nvary);
                    let mut first = true;
                    // Mesa's clipper keeps the polygon's edge flags (frustum edges and
                    // fan diagonals hidden) and restarts the stipple at the first piece.
                    clip_triangle_edges(
                        v,
                        edges,
                        or,
                        ucp,
                        vp,
                        nvary,
                        self.flat_mask(),
                        self.back,
                        |p, q, r, e| self.triangle([p, q, r], e, std::mem::take(&mut first), sink),
                    );
                } else {
                    self.triangle(v, edges, reset, sink);
                }
            }),
        }
    }

    fn line(&self, a: &ClipVertex, b: &ClipVertex, sink: &mut impl PrimSink) {
        let or = a.mask | b.mask;
        if a.mask & b.mask != 0 {
            return;
        }
        if or == 0 {
            return sink.line(a, b);
        }
        let clipped = clip_line(
            a,
            b,
            or,
            self.ucp,
            &self.viewport,
            self.nvary,
            self.flat_mask(),
        );
        if let Some((p, q)) = clipped {
            sink.line(&p, &q);
        }
    }

    /// One triangle after clipping: cull, two-side, offset, flat-shade, unfilled.
    fn triangle(&self, v: [&ClipVertex; 3], edges: u8, reset: bool, sink: &mut impl PrimSink) {
        let pol = &self.polygon;
        let unfilled = pol.mode_front != FillMode::Fill || pol.mode_back != FillMode::Fill;
        let offset_any = self.offset.iter().any(|&o| o);
        // The cull stage (present when anything needs the determinant or culling is on)
        // drops culled faces; a zero-area triangle counts as back-facing there.
        let det = determinant(v);
        let culling = self.cull.front || self.cull.back;
        if unfilled || offset_any || self.back.is_some() || culling {
            let face_back = if det != 0.0 {
                (det < 0.0) != self.cull.front_ccw
            } else {
                true
            };
            if (face_back && self.cull.back) || (!face_back && self.cull.front) {
                return;
            }
        }
        let mut p = [*v[0], *v[1], *v[2]];
        // Two-side: back colours when det · sign < 0 (sign −1 for GL_CCW).
        if let Some(o) = self.back {
            let sign = if self.cull.front_ccw { -1.0 } else { 1.0 };
            if det * sign < 0.0 {
                for q in &mut p {
                    q.vary.copy_within(o..o + 8, 0);
                }
            }
        }
        let mode = fill_mode(det, self.cull.front_ccw, pol.mode_front, pol.mode_back);
        let offset_on = match mode {
            FillMode::Fill => self.offset[0],
            FillMode::Line => self.offset[1],
            FillMode::Point => self.offset[2],
        };
        if offset_on {
            let units = scaled_units(pol.offset_units, self.depth_bits);
            let off = draw_offset([&p[0], &p[1], &p[2]], det, pol.offset_factor, units);
            for q in &mut p {
                q.win[2] = (q.win[2] + off).clamp(0.0, 1.0);
            }
        }
        // The flat-shade stage is in the pipeline only with unfilled polygons.
        if unfilled && self.flat {
            let c: [f32; 8] = std::array::from_fn(|i| p[2].vary[i]);
            p[0].vary[..8].copy_from_slice(&c);
            p[1].vary[..8].copy_from_slice(&c);
        }
        match mode {
            FillMode::Fill => sink.triangle([&p[0], &p[1], &p[2]]),
            FillMode::Line => {
                if reset {
                    sink.reset_stipple();
                }
                for (bit, s, e) in [(EDGE_2, 2, 0), (EDGE_0, 0, 1), (EDGE_1, 1, 2)] {
                    if edges & bit != 0 {
                        sink.line(&p[s], &p[e]);
                    }
                }
            }
            FillMode::Point => {
                for (bit, k) in [(EDGE_0, 0), (EDGE_1, 1), (EDGE_2, 2)] {
                    if edges & bit != 0 {
                        sink.point(&p[k]);
                    }
                }
            }
        }
    }
}
