//! The per-draw plan for lines and points: the clamped width and size, and the line
//! stipple stage, in the order of Mesa's draw pipeline (clip → stipple → llvmpipe setup).

use super::batch::Rasterizer;
use super::lines::{raster_line, raster_point, screen_interp, LineStipple};
use super::stipple::stippled_triangle;
use super::Draw;
use crate::fragment::FragPlan;
use crate::geometry::clip::{clip_line, clip_triangle_edges, UserPlanes};
use crate::geometry::setup::{setup_triangle, CullMode, SetupResult, SetupTriangle};
use crate::geometry::unfilled::{
    decompose, determinant, draw_offset, fill_mode, float_units, scaled_units, setup_offset,
    EDGE_0, EDGE_1, EDGE_2,
};
use crate::geometry::{ClipVertex, Viewport};
use crate::pipe::{FillMode, RasterState, MAX_LINE_WIDTH, MAX_POINT_SIZE};
use crate::stats::Stats;
use crate::texture::shadow::FLOAT_BITS;

/// The varyings whose value is the provoking vertex's in a draw under `plan` (bit v:
/// varying v): the colours under GL_FLAT (llvmpipe flat-shades the colour semantics) and
/// a fragment shader's `flat` inputs. Setup keeps these values, the clipper copies them
/// (Mesa's `copy_flat`), and a shader walk reads them from constant planes.
pub fn flat_varyings(plan: &FragPlan) -> u64 {
    let colors = if plan.flat {
        crate::geometry::clip::FLAT_COLORS
    } else {
        0
    };
    colors | plan.shader.as_ref().map_or(0, |s| s.flat)
}

/// The point size llvmpipe rasterizes without attenuation: glPointSize clamped to
/// GL_POINT_SIZE_MIN/MAX by the state tracker, then capped at llvmpipe's maximum.
pub fn point_size(r: &RasterState) -> f32 {
    r.point.clamped_size().min(MAX_POINT_SIZE)
}

/// The enables the primitive stages read.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct PrimEnables {
    /// GL_POINT_SMOOTH.
    pub point_smooth: bool,
    /// GL_LINE_SMOOTH.
    pub line_smooth: bool,
    /// GL_LINE_STIPPLE.
    pub line_stipple: bool,
    /// GL_POLYGON_STIPPLE.
    pub polygon_stipple: bool,
    /// GL_POLYGON_OFFSET_FILL, GL_POLYGON_OFFSET_LINE and GL_POLYGON_OFFSET_POINT.
    pub offset: [bool; 3],
    /// GL_POINT_SPRITE: points are squares with llvmpipe's fill rule
    /// ([`super::sprite`]).
    pub sprite: bool,
    /// The varyings every kind of point replaces with coordinates across its square
    /// (GL_COORD_REPLACE units under GL_POINT_SPRITE, a shader's `gl_PointCoord`).
    pub coords: super::sprite::Sprite,
}

impl PrimEnables {
    /// Whether polygon offset is on for polygons drawn as `mode`.
    pub fn offset(&self, mode: FillMode) -> bool {
        self.offset[match mode {
            FillMode::Fill => 0,
            FillMode::Line => 1,
            FillMode::Point => 2,
        }]
    }
}

/// Draws point `v` (inside the clip volume) of `size`: into a multisample object as the
/// square sampled at the sample points ([`super::ms_prims`]), else as a sprite
/// ([`super::sprite`]) under GL_POINT_SPRITE, else through the aapoint stage when
/// GL_POINT_SMOOTH is on, else as llvmpipe's legacy square.
/// `top_left` is llvmpipe's `bottom_edge_rule = 0` (objects; GL_UPPER_LEFT toggles it),
/// which moves legacy points lying exactly on a pixel row.
pub fn draw_point(
    v: &ClipVertex,
    size: f32,
    enables: &PrimEnables,
    top_left: bool,
    nvary: usize,
    d: &mut Draw<'_, '_>,
) {
    // A NaN size (a vertex shader's or an attenuated one) draws the smallest point:
    // llvmpipe converts it to INT_MIN, then takes its one-pixel minimum.
    let size = if size.is_nan() { 0.0 } else { size };
    if d.plan.ms.is_some() {
        // Multisampling ignores GL_POINT_SMOOTH.
        super::ms_prims::point(v, size, &enables.coords, nvary, d);
    } else if enables.sprite {
        super::sprite::point(v, size, &enables.coords, top_left, nvary, d);
    } else if enables.point_smooth {
        super::smooth::point(v, size, nvary, d);
    } else {
        raster_point(v, size, &enables.coords, top_left, nvary, d);
    }
}

/// Adds llvmpipe's setup-time polygon offset (`lp_do_offset_tri`) to a set-up triangle:
/// computed on the vertices in setup order (clockwise triangles swap v0 and v1) and, as an
/// approximation of llvmpipe's per-fragment addition, folded into the z plane's origin.
///
/// `units` are scaled already, except for a float depth buffer (`float`), whose units
/// llvmpipe scales per triangle by the exponent of its largest |z| ([`float_units`]).
///
/// Inlined so that `v` stays in registers: the setup queue gathers it lane by lane with
/// 4-byte stores, and an out-of-line call read it back with 8-byte loads that could not
/// be forwarded from those stores.
#[inline(always)]
pub fn apply_setup_offset(
    v: [[f32; 4]; 3],
    factor: f32,
    (units, float): (f32, bool),
    t: &mut SetupTriangle,
) {
    use crate::geometry::setup::snap;
    let (x0, y0) = (snap(v[0][0]), snap(v[0][1]));
    let (x1, y1) = (snap(v[1][0]), snap(v[1][1]));
    let (x2, y2) = (snap(v[2][0]), snap(v[2][1]));
    let area = (x0 - x1) * (y2 - y0) - (x2 - x0) * (y0 - y1);
    let order = if area > 0 {
        [v[0], v[1], v[2]]
    } else {
        [v[1], v[0], v[2]]
    };
    let units = if float {
        float_units(units, [v[0][2], v[1][2], v[2][2]])
    } else {
        units
    };
    t.z.a0 += setup_offset(order, factor, units);
}

/// How a draw's lines are drawn.
#[derive(Clone, Copy, Debug)]
pub struct LinePlan {
    /// Width clamped to [1, 255] (the state tracker's clamp).
    pub width: f32,
    /// The stipple stage when GL_LINE_STIPPLE is on (counter at 0).
    pub stipple: Option<LineStipple>,
    /// Varyings per vertex.
    pub nvary: usize,
    /// The user clip planes in clip space (GL_CLIP_PLANEi).
    pub ucp: UserPlanes,
    /// GL_LINE_SMOOTH: segments go through the aaline stage ([`super::smooth`]).
    pub smooth: bool,
    /// The top-left fill rule (llvmpipe's `bottom_edge_rule = 0`: objects, toggled by
    /// GL_UPPER_LEFT), for the lines' horizontal edges and boxes.
    pub top_left: bool,
}

impl LinePlan {
    /// The plan for lines of `r` with the enables `e`.
    pub fn new(r: &RasterState, e: &PrimEnables, nvary: usize) -> Self {
        LinePlan {
            width: r.line.width.clamp(1.0, MAX_LINE_WIDTH),
            stipple: e.line_stipple.then_some(LineStipple {
                pattern: r.line.stipple_pattern,
                factor: r.line.stipple_repeat,
                counter: 0.0,
                rectangular: e.line_smooth,
            }),
            nvary,
            ucp: UserPlanes::default(),
            smooth: e.line_smooth,
            top_left: false,
        }
    }

    /// Clips, stipples and rasterizes segment `va`–`vb` (vertex-stage outputs).
    pub fn draw(
        &self,
        va: &ClipVertex,
        vb: &ClipVertex,
        viewport: &Viewport,
        stipple: Option<&mut LineStipple>,
        d: &mut Draw<'_, '_>,
    ) {
        if va.mask & vb.mask != 0 {
            return;
        }
        let (p, q) = if va.mask | vb.mask != 0 {
            match clip_line(
                va,
                vb,
                va.mask | vb.mask,
                &self.ucp,
                viewport,
                self.nvary,
                flat_varyings(d.plan),
            ) {
                Some(pq) => pq,
                None => return,
            }
        } else {
            (*va, *vb)
        };
        self.draw_window(&p, &q, &vb.vary, stipple, d);
    }

    /// Stipples and rasterizes a segment already in window coordinates; `flat_vary` is the
    /// provoking vertex's varyings.
    pub fn draw_window(
        &self,
        p: &ClipVertex,
        q: &ClipVertex,
        flat_vary: &[f32; crate::geometry::MAX_VARY],
        stipple: Option<&mut LineStipple>,
        d: &mut Draw<'_, '_>,
    ) {
        let n = self.nvary;
        // Under GL_FLAT the draw module's flat-shade stage gives both ends the provoking colour.
        let (width, smooth, flat) = (self.width, self.smooth, d.plan.flat.then_some(flat_vary));
        let top_left = self.top_left;
        let seg = |a: &ClipVertex, b: &ClipVertex, d: &mut Draw<'_, '_>| {
            if d.plan.ms.is_some() {
                // Multisampling ignores GL_LINE_SMOOTH.
                super::ms_prims::line(a, b, flat_vary, width, n, d);
            } else if smooth {
                super::smooth::line(a, b, flat, width, n, d);
            } else {
                raster_line(a, b, flat_vary, (width, top_left), n, d);
            }
        };
        match stipple {
            None => seg(p, q, d),
            Some(s) => {
                s.split([p.win[0], p.win[1]], [q.win[0], q.win[1]], |t0, t1| {
                    let a = if t0 > 0.0 {
                        screen_interp(t0, p, q, n)
                    } else {
                        *p
                    };
                    let b = if t1 < 1.0 {
                        screen_interp(t1, p, q, n)
                    } else {
                        *q
                    };
                    seg(&a, &b, d);
                });
            }
        }
    }
}

/// Inputs of the draw module's triangle pipeline for one draw.
pub struct PolyPipeline<'a> {
    /// Lines (for GL_LINE polygons).
    pub lines: LinePlan,
    /// Point size (for GL_POINT polygons); `None` when each vertex has its own
    /// ([`ClipVertex::psize`], attenuated points).
    pub point_size: Option<f32>,
    /// Polygon modes, offsets and enables.
    pub raster: &'a RasterState,
    /// Stipple and offset enables.
    pub enables: PrimEnables,
    /// Face culling.
    pub cull: CullMode,
    /// Where the back colours start, with two-sided lighting.
    pub back: Option<usize>,
    /// Depth buffer bits (scales the offset units).
    pub depth_bits: u32,
    /// The viewport (for clipping).
    pub viewport: Viewport,
    /// The drawable region.
    pub region: [i64; 4],
}

impl PolyPipeline<'_> {
    /// Whether llvmpipe hands triangles of this state to the draw module's pipeline even
    /// when nothing needs clipping (`draw_need_pipeline` with llvmpipe's split of the
    /// rasterizer state, `lp_state_rasterizer.c`).
    pub fn needed(r: &RasterState, e: &PrimEnables, two_side: bool) -> bool {
        let unfilled =
            r.polygon.mode_front != FillMode::Fill || r.polygon.mode_back != FillMode::Fill;
        let pstipple = e.polygon_stipple;
        let lp_pipeline = unfilled || pstipple || e.line_stipple || e.line_smooth || e.point_smooth;
        let offset = e.offset.iter().any(|&o| o);
        unfilled || pstipple || (lp_pipeline && (offset || two_side))
    }

    /// Runs one triangle (after clipping) through cull, two-side, offset, flat-shade and
    /// unfilled stages, then draws it. `edges` are the boundary-edge bits already masked
    /// by the vertices' edge flags.
    #[allow(clippy::too_many_arguments)]
    pub fn triangle(
        &self,
        v: [&ClipVertex; 3],
        edges: u8,
        reset: bool,
        stipple: &mut Option<LineStipple>,
        nvary: usize,
        plan: &FragPlan,
        rast: &mut Rasterizer<'_, '_>,
        tri: &mut SetupTriangle,
        stats: &mut Stats,
    ) {
        let det = determinant(v);
        if det == 0.0 || det.is_nan() {
            stats.tris_degenerate += 1;
            return;
        }
        let ccw = det < 0.0;
        let front = ccw == self.cull.front_ccw;
        if (front && self.cull.front) || (!front && self.cull.back) {
            stats.tris_culled += 1;
            return;
        }
        // The stipple counter restarts at each primitive that reaches the unfilled stage,
        // and the stipple stage restarts it for every filled triangle and point too.
        if let Some(s) = stipple.as_mut() {
            let pol = &self.raster.polygon;
            let m = fill_mode(det, self.cull.front_ccw, pol.mode_front, pol.mode_back);
            if reset || m != FillMode::Line {
                s.counter = 0.0;
            }
        }
        let mut p = [*v[0], *v[1], *v[2]];
        if let (false, Some(o)) = (front, self.back) {
            for q in &mut p {
                q.vary.copy_within(o..o + 8, 0);
            }
        }
        let pol = &self.raster.polygon;
        let mode = fill_mode(det, self.cull.front_ccw, pol.mode_front, pol.mode_back);
        let offset_on = self.enables.offset(mode);
        if offset_on {
            let units = if self.depth_bits == FLOAT_BITS as u32 {
                float_units(pol.offset_units, [p[0].win[2], p[1].win[2], p[2].win[2]])
            } else {
                scaled_units(pol.offset_units, self.depth_bits)
            };
            let off = draw_offset([&p[0], &p[1], &p[2]], det, pol.offset_factor, units);
            for q in &mut p {
                q.win[2] = (q.win[2] + off).clamp(0.0, 1.0);
            }
        }
        if plan.flat {
            let c: [f32; 8] = std::array::from_fn(|i| p[2].vary[i]);
            p[0].vary[..8].copy_from_slice(&c);
            p[1].vary[..8].copy_from_slice(&c);
        }
        if mode == FillMode::Fill {
            let nocull = CullMode {
                front: false,
                back: false,
                front_ccw: self.cull.front_ccw,
                top_left: self.cull.top_left,
            };
            match setup_triangle([&p[0], &p[1], &p[2]], nvary, nocull, None, tri) {
                SetupResult::Draw if self.enables.polygon_stipple => {}
                SetupResult::Draw => {
                    rast.triangle(tri, stats);
                    return;
                }
                _ => {
                    stats.tris_degenerate += 1;
                    return;
                }
            }
        }
        // Stippled polygons, lines and points are drawn at once, after the batched
        // triangles before them (primitive order).
        let units = rast.units();
        let mut target = rast.target(stats).target();
        let d = &mut Draw::new(self.region, plan, units, &mut target, stats);
        d.prim_front = front;
        match mode {
            FillMode::Fill => stippled_triangle(tri, &self.raster.stipple, d),
            FillMode::Line => {
                for (bit, s, e) in [(EDGE_2, 2, 0), (EDGE_0, 0, 1), (EDGE_1, 1, 2)] {
                    if edges & bit != 0 {
                        let (a, b) = (&p[s], &p[e]);
                        self.lines.draw_window(a, b, &b.vary, stipple.as_mut(), d);
                    }
                }
            }
            FillMode::Point => {
                let enables = self.enables;
                for (bit, k) in [(EDGE_0, 0), (EDGE_1, 1), (EDGE_2, 2)] {
                    if edges & bit != 0 {
                        let size = self.point_size.unwrap_or(p[k].psize);
                        draw_point(&p[k], size, &enables, self.lines.top_left, nvary, d);
                    }
                }
            }
        }
    }

    /// Draws `n` vertices of triangle `mode` through the pipeline: decomposition with edge
    /// flags, clipping, then [`Self::triangle`]. `at(k)` is the k-th vertex and
    /// `edge_flag(k)` its edge flag.
    #[allow(clippy::too_many_arguments)]
    pub fn draw<'v>(
        &self,
        mode: crate::pipe::Primitive,
        n: usize,
        at: impl Fn(usize) -> &'v ClipVertex,
        edge_flag: impl Fn(usize) -> bool,
        nvary: usize,
        plan: &FragPlan,
        rast: &mut Rasterizer<'_, '_>,
        stats: &mut Stats,
    ) {
        let mut stipple = self.lines.stipple;
        let mut tri = SetupTriangle::default();
        let mut triangle = |v: [&ClipVertex; 3], edges, reset, stats: &mut Stats| {
            self.triangle(
                v,
                edges,
                reset,
                &mut stipple,
                nvary,
                plan,
                rast,
                &mut tri,
                stats,
            );
        };
        decompose(mode, n, |a, b, c, flags, reset| {
            let (va, vb, vc) = (at(a), at(b), at(c));
            stats.triangles += 1;
            let mut edges = flags;
            for (bit, k) in [(EDGE_0, a), (EDGE_1, b), (EDGE_2, c)] {
                if !edge_flag(k) {
                    edges &= !bit;
                }
            }
            let or = va.mask | vb.mask | vc.mask;
            if va.mask & vb.mask & vc.mask != 0 {
                stats.tris_clip_rejected += 1;
            } else if or != 0 {
                stats.tris_clipped += 1;
                let mut out: Vec<([ClipVertex; 3], u8)> = Vec::new();
                clip_triangle_edges(
                    [va, vb, vc],
                    edges,
                    or,
                    &self.lines.ucp,
                    &self.viewport,
                    nvary,
                    flat_varyings(plan),
                    self.back,
                    |p, q, r, e| out.push(([*p, *q, *r], e)),
                );
                // The stipple counter restarts only at the polygon's first piece.
                for (k, ([p, q, r], e)) in out.iter().enumerate() {
                    triangle([p, q, r], *e, k == 0, stats);
                }
            } else {
                triangle([va, vb, vc], edges, reset, stats);
            }
        });
    }
}
