//! Runs a draw's plan ([`DrawPlan`], made by the plan step, `plan/`), stage by stage:
//! vertex stage → assembly → clipping → setup → raster.
//!
//! The clip decision is per draw, as in llvmpipe's draw module: if any vertex is outside
//! the clip volume the whole draw takes the clipping path, which also changes the
//! GL_QUADS/GL_QUAD_STRIP triangle split (docs/llvmpipe-rules.md §5).
//!
//! A streamed draw (filled triangles through the post-transform cache) first takes every
//! vertex's clip mask from its position alone ([`VertexStage::clip_masks`]): the masks
//! make that decision, and a triangle outside one clip plane is counted and dropped
//! before its vertices are lit ([`crate::geometry::reject`]).

use crate::fixed_function::transform::VertexStage;
use crate::fragment::FragPlan;
use crate::framebuffer::Framebuffer;
use crate::geometry::assemble::{self, DrawPath};
use crate::geometry::clip::{clip_triangle, UserPlanes};
use crate::geometry::feedback::PrimSink;
use crate::geometry::reject::{independent, Rejection, CHUNK};
use crate::geometry::setup::{CullMode, SetupResult, SetupTriangle, SetupVariant};
use crate::geometry::setup8::{SetupQueue, QUEUE_VARY};
use crate::geometry::source::{VertexCache, VertexSlot, VertexSource};
use crate::geometry::{ClipMask, ClipVertex, Viewport};
use crate::pipe::{Material, Primitive, RasterState};
use crate::raster::banded::draw_banded;
use crate::raster::batch::{
    fork2_split, geom_section, Adopted, Binner, InFlight, Rasterizer, TriangleSink,
};
use crate::raster::prims::{draw_point, LinePlan, PolyPipeline, PrimEnables};
use crate::stats::Stats;
use crate::texture::UnitPlan;
use std::cell::Cell;

/// What every stage of one draw does, derived from the state once (by `plan/`).
pub struct DrawPlan<'a> {
    /// The vertex stage: transforms, user clip planes, lighting, fog, texgen, point
    /// attenuation and the texture units' matrices.
    pub stage: VertexStage,
    /// The fragment operations.
    pub frag: FragPlan,
    /// The texture units with a complete enabled texture, in unit order (none in feedback
    /// mode).
    pub tex: Vec<UnitPlan<'a>>,
    /// The viewport transform.
    pub viewport: Viewport,
    /// Face culling and winding.
    pub cull: CullMode,
    /// Triangles go through the draw module's polygon pipeline (unfilled, stippled,
    /// offset or smooth polygons, two-sided colours, …) ([`PolyPipeline::needed`]).
    pub poly: bool,
    /// llvmpipe's own polygon offset for filled triangles: factor and scaled units (and
    /// whether the depth buffer is float).
    pub lp_offset: Option<(f32, (f32, bool))>,
    /// How lines are drawn.
    pub lines: LinePlan,
    /// The point size, or `None` when each vertex carries its own
    /// ([`ClipVertex::psize`]: attenuated, or a vertex shader's `gl_PointSize`).
    pub point_size: Option<f32>,
    /// The program's varyings leave no room for its back colours or clip vertex
    /// (`geometry::MAX_VARY`): the draw is refused.
    pub unfit: bool,
    /// Depth buffer bits (the polygon pipeline's offset units scale with them).
    pub depth_bits: u32,
    /// Polygon modes, offsets and stipple.
    pub raster: &'a RasterState,
    /// The enables the primitive stages read (stipples, smoothing, offsets).
    pub prims: PrimEnables,
    /// Feedback or selection mode: nothing is rasterized ([`feedback`]).
    pub feedback: bool,
    /// The program's vertex shader, which replaces the fixed-function vertex stage
    /// (`stage` then only gives the viewport and the varyings' count).
    pub vertex: Option<crate::shader::vertex_draw::VertexRun<'a>>,
}

/// Runs `plan` for `verts` drawn as `mode` (through `indices` when given) into `fb`, inside
/// `region`; `materials`, when given, is each vertex's own material. With `detach`, the
/// last batch of triangles may be left drawing on the pool: it is returned. `adopt` is
/// the previous draw's batch still drawing into `fb`, taken back by this draw's
/// rasterizer ([`Rasterizer::adopt`]) before it draws anything.
///
/// # Safety
/// With `detach`, as [`Rasterizer::flush_detached`]: the caller must put `fb` into the
/// returned batch before anything else touches it, and start no other rasterizer before
/// the batch is settled.
#[allow(clippy::too_many_arguments)]
pub unsafe fn run<S: VertexSource + ?Sized>(
    plan: &mut DrawPlan<'_>,
    mode: Primitive,
    verts: &S,
    indices: Option<&[u32]>,
    materials: Option<&[[Material; 2]]>,
    fb: &mut Framebuffer,
    region: [i64; 4],
    stats: &mut Stats,
    detach: bool,
    adopt: Option<Adopted>,
) -> Option<InFlight> {
    // Borrowed, not moved: the plan is kilobytes (the vertex stage 2.5 KB), and moving
    // it in and apart was a memcpy per draw.
    let DrawPlan {
        stage,
        frag: plan,
        tex: tex_plans,
        viewport,
        cull,
        poly,
        lp_offset,
        lines,
        point_size: size,
        unfit,
        depth_bits,
        raster,
        prims,
        feedback: _,
        vertex,
    } = plan;
    let (plan, tex_plans, vertex) = (&*plan, &tex_plans[..], &*vertex);
    let lines = &*lines;
    let (viewport, cull, poly, lp_offset, size, depth_bits, raster, prims) = (
        *viewport,
        *cull,
        *poly,
        *lp_offset,
        *size,
        *depth_bits,
        *raster,
        *prims,
    );
    // A fragment shader runs on triangles, lines and points (see `shader::draw`), also
    // through the polygon pipeline (unfilled modes, offsets, stipple), smoothed and
    // multisampled.
    if *unfit {
        stats.program_draws_refused += 1;
        if let Some(a) = adopt {
            a.settle(stats, Some(&mut *fb));
        }
        return None;
    }
    if plan.shader.is_some() || vertex.is_some() {
        stats.program_draws += 1;
    }
    let n = indices.map_or(verts.count(), |i| i.len());
    // Filled triangles, strips, fans, polygons, quads and quad strips stream through the
    // post-transform cache; points, lines and draws that need edge flags or per-vertex
    // materials transform every vertex first.
    let streamed = materials.is_none()
        && vertex.is_none()
        && matches!(
            mode,
            Primitive::Triangles
                | Primitive::TriangleStrip
                | Primitive::TriangleFan
                | Primitive::Polygon
                | Primitive::Quads
                | Primitive::QuadStrip
        )
        && !poly;
    let cv = match &vertex {
        _ if streamed => Vec::new(),
        Some(vs) => vs.run(verts),
        None => run_vertices(stage, verts, materials),
    };
    stats.vertices += cv.len() as u64;
    // A streamed draw's clip masks, from a pass over the positions alone.
    let mut masks = Vec::new();
    let any_outside = if streamed {
        clip_masks_par(stage, verts, &mut masks);
        // Only the split of quads and quad strips depends on whether any vertex is
        // outside (llvmpipe-rules §5; indexed or flat quads split one way on both paths):
        // the masks decide it before anything is assembled.
        let split_varies = match mode {
            Primitive::Quads => indices.is_none() && !plan.flat,
            Primitive::QuadStrip => true,
            _ => false,
        };
        split_varies && any_vertex_outside(stage, verts, indices, &masks)
    } else {
        match indices {
            Some(ix) => ix.iter().any(|&i| cv[i as usize].mask != 0),
            None => cv.iter().any(|v| v.mask != 0),
        }
    };
    let path = if any_outside {
        DrawPath::Clip
    } else if indices.is_some() {
        DrawPath::ElementsNoClip
    } else {
        DrawPath::ArraysNoClip
    };
    let at = |k: usize| -> &ClipVertex {
        match indices {
            Some(ix) => &cv[ix[k] as usize],
            None => &cv[k],
        }
    };
    let nvary = stage.nvary();
    let back = stage.two_side().then(|| stage.back_offset());
    // SAFETY: `rast` is a local dropped at the end of this function, never leaked.
    let mut rast = unsafe { Rasterizer::new(fb, plan, tex_plans, region, nvary) };
    if let Some(a) = adopt {
        rast.adopt(a, stats);
    }
    let pipe = TriPipe {
        setup: match plan.ms {
            Some(_) => SetupVariant::all_samples(),
            None => SetupVariant::detect(),
        },
        nvary,
        cull,
        back,
        flat: plan.flat,
        flat_vary: crate::raster::prims::flat_varyings(plan),
        lp_offset,
        ucp: &stage.ucp,
        viewport: &viewport,
    };
    match mode {
        Primitive::Points => {
            let size_of = |v: &ClipVertex| size.unwrap_or(v.psize);
            let work = || {
                (0..n)
                    .map(&at)
                    .filter(|v| v.mask == 0)
                    .map(|v| f64::from(size_of(v).max(1.0)).powi(2))
                    .sum()
            };
            let fb = rast.target(stats);
            draw_banded(fb, region, plan, tex_plans, stats, work, |d| {
                for k in 0..n {
                    let v = at(k);
                    if v.mask == 0 {
                        draw_point(v, size_of(v), &prims, lines.top_left, nvary, d);
                    }
                }
            });
        }
        Primitive::Lines | Primitive::LineLoop | Primitive::LineStrip => {
            let work = || {
                let mut w = 0.0;
                assemble::lines(mode, n, |a, b, _| w += line_work(at(a), at(b)));
                w * f64::from(lines.width.max(1.0))
            };
            let fb = rast.target(stats);
            draw_banded(fb, region, plan, tex_plans, stats, work, |d| {
                let mut stipple = lines.stipple;
                assemble::lines(mode, n, |a, b, reset| {
                    if reset {
                        if let Some(s) = stipple.as_mut() {
                            s.counter = 0.0;
                        }
                    }
                    lines.draw(at(a), at(b), &viewport, stipple.as_mut(), d);
                });
            });
        }
        _ if poly => {
            let pp = PolyPipeline {
                lines: *lines,
                point_size: size,
                raster,
                enables: prims,
                cull,
                back,
                depth_bits,
                viewport,
                region,
            };
            let edge = |k: usize| verts.edge_flag(indices.map_or(k, |ix| ix[k] as usize));
            pp.draw(mode, n, at, edge, nvary, plan, &mut rast, stats);
        }
        _ if streamed => {
            let ix = |k: usize| indices.map_or(k, |ix| ix[k] as usize);
            let block = stage.block_ok();
            let reject = Rejection::new(masks, mode, n, path, plan.flat, ix, block);
            // A draw of independent primitives whose vertex references run in order reads
            // each vertex once, in runs: a small cache holds them (clearing one sized for
            // the draw cost more than the runs' work on MuJoCo's replays of a few hundred
            // quads).
            let sequential = independent(mode).is_some()
                && indices.is_none_or(|ix| ix.iter().enumerate().all(|(k, &i)| i as usize == k));
            let streamer = Streamer {
                verts,
                indices,
                stage,
                pipe,
                mode,
                path,
                reject: &reject,
                n_cache: if sequential {
                    SEQUENTIAL_CACHE.min(n)
                } else {
                    n
                },
            };
            let mut state = streamer.state();
            let section = geom_section();
            let ntris = match mode {
                Primitive::Quads => n / 4 * 2,
                _ => n / 3,
            };
            if mode == Primitive::Triangles
                && section > 0
                && ntris >= 2 * section
                && rast.can_split()
            {
                // The first triangles the ordinary way; the rest on two threads at once
                // (`raster::batch::split`) when they are small: then setting them up
                // takes longer than drawing them.
                let probe = split_probe().clamp(1, section);
                rast.start_pool();
                let boxes = rast.box_area_sum();
                let tris = stats.tris_rasterized;
                streamer.run(0, probe, &mut state, &mut rast, stats);
                let area = (rast.box_area_sum() - boxes) as f64;
                let rasterized = (stats.tris_rasterized - tris) as f64;
                if area <= SPLIT_MAX_AREA * rasterized {
                    let rest = ntris - probe;
                    let geom = |state: &mut Box<StreamState>,
                                s: usize,
                                sink: &mut Binner,
                                stats: &mut _| {
                        let first = probe + section * s;
                        streamer.run(first, section.min(ntris - first), state, sink, stats);
                    };
                    rast.split_geometry(
                        rest.div_ceil(section),
                        section,
                        stats,
                        || streamer.state(),
                        geom,
                    );
                } else {
                    streamer.run(probe, ntris - probe, &mut state, &mut rast, stats);
                }
            } else if let Some(unit) = independent(mode) {
                streamer.stream_chunks(unit, n, &mut state, &mut rast, stats);
            } else {
                streamer.stream(streamer.mode, 0, n, &mut state, &mut rast, stats);
            }
            Streamer::<S>::recycle(state);
        }
        _ => {
            let mut tri = SetupTriangle::default();
            assemble::triangles(mode, n, path, plan.flat, |a, b, c| {
                pipe.triangle(at(a), at(b), at(c), None, &mut tri, &mut rast, stats)
            });
        }
    }
    let kept = if detach {
        // SAFETY: forwarded from the caller.
        unsafe { rast.flush_detached(stats) }
    } else {
        rast.flush(stats);
        None
    };
    drop(rast);
    kept
}

/// Vertices from which a draw's clip masks are computed on two threads when the pool has
/// a task polling for work ([`fork2_split`]): MuJoCo's floor grid of 160,000 vertices took
/// 0.37 ms a pass for its masks on one thread, and its draws keep the pool idle.
const PAR_MASKS: usize = 16 * 1024;

/// [`VertexStage::clip_masks`], the two halves on two threads for a large draw.
fn clip_masks_par<S: VertexSource + ?Sized>(
    stage: &VertexStage,
    verts: &S,
    out: &mut Vec<ClipMask>,
) {
    let n = verts.count();
    if n < PAR_MASKS {
        stage.clip_masks(verts, out);
        return;
    }
    out.clear();
    out.resize(n, 0);
    let mid = n / 2;
    fork2_split(out, mid, |k, part| {
        stage.clip_masks_into(verts, k * mid, part)
    });
}

/// The per-triangle stages after the vertex stage: clipping, setup, llvmpipe's polygon
/// offset, then the sink (the draw's rasterizer, or a section's batch of a split draw).
#[derive(Clone, Copy)]
struct TriPipe<'a> {
    setup: SetupVariant,
    nvary: usize,
    cull: CullMode,
    back: Option<usize>,
    /// GL_FLAT (the decomposition of quads and polygons).
    flat: bool,
    /// The varyings taken from the provoking vertex (`raster::prims::flat_varyings`):
    /// setup keeps their values and the clipper copies them.
    flat_vary: u64,
    /// llvmpipe's own polygon offset: factor and scaled units.
    lp_offset: Option<(f32, (f32, bool))>,
    ucp: &'a UserPlanes,
    viewport: &'a Viewport,
}

impl TriPipe<'_> {
    /// Sets up one triangle inside the clip volume and passes it to `sink`.
    #[inline(always)]
    fn one<K: TriangleSink>(
        &self,
        v: [&ClipVertex; 3],
        tri: &mut SetupTriangle,
        sink: &mut K,
        stats: &mut Stats,
    ) {
        let r = self.setup.shaded(
            v,
            self.nvary,
            self.cull,
            self.back,
            self.flat_vary != 0,
            tri,
        );
        if let (SetupResult::Draw, Some((factor, units))) = (r, self.lp_offset) {
            // a float depth buffer scales the units per triangle (`FLOAT_BITS` as bits)
            let win = [v[0].win, v[1].win, v[2].win];
            crate::raster::prims::apply_setup_offset(win, factor, units, tri);
        }
        Self::emit(r, tri, sink, stats);
    }

    /// Passes a set-up triangle to `sink`, or counts why setup dropped it.
    #[inline(always)]
    fn emit<K: TriangleSink>(r: SetupResult, tri: &SetupTriangle, sink: &mut K, stats: &mut Stats) {
        match r {
            SetupResult::Draw => sink.triangle(tri, stats),
            SetupResult::Degenerate => stats.tris_degenerate += 1,
            SetupResult::Culled => stats.tris_culled += 1,
            // What the rasterizer counts for a box without pixels.
            SetupResult::Empty => stats.tris_offscreen += 1,
        }
    }

    /// Whether this draw's triangles can be set up eight at a time ([`SetupQueue`]): on
    /// the AVX2 setup, without two-sided colours (which look at a triangle's vertices
    /// after setup; llvmpipe's polygon offset reads only their window positions, which
    /// the queue keeps), and `SOFTGL_SETUP8=0` turns it off for A/B.
    fn queue_ok(&self) -> bool {
        crate::tuning::tuning().setup8
            && self.setup.is_avx2()
            && self.back.is_none()
            && self.nvary <= QUEUE_VARY
    }

    /// Sets up the triangles waiting in `queue` and passes them to `sink` in order.
    #[inline(never)]
    fn flush<K: TriangleSink>(
        &self,
        queue: &mut SetupQueue,
        tri: &mut SetupTriangle,
        sink: &mut K,
        stats: &mut Stats,
    ) {
        // SAFETY: a draw has a queue only when its setup is the AVX2 copy
        // (`Self::queue_ok`), which `SetupVariant::detect` picks only on AVX2 CPUs.
        unsafe {
            queue.flush(self.cull, self.flat_vary != 0, tri, |r, t, win| {
                if let (SetupResult::Draw, Some((factor, units))) = (r, self.lp_offset) {
                    crate::raster::prims::apply_setup_offset(win, factor, units, t);
                }
                Self::emit(r, t, sink, stats)
            })
        };
    }

    /// Rejects, clips or sets up one assembled triangle. With a `queue`, a triangle
    /// inside the clip volume waits there until eight have come (or the stream ends:
    /// [`Self::flush`]), and one that needs clipping first sets up those waiting, so that
    /// `sink` sees the triangles in order.
    #[inline]
    #[allow(clippy::too_many_arguments)]
    fn triangle<K: TriangleSink>(
        &self,
        va: &ClipVertex,
        vb: &ClipVertex,
        vc: &ClipVertex,
        queue: Option<&mut SetupQueue>,
        tri: &mut SetupTriangle,
        sink: &mut K,
        stats: &mut Stats,
    ) {
        stats.triangles += 1;
        let or = va.mask | vb.mask | vc.mask;
        if va.mask & vb.mask & vc.mask != 0 {
            stats.tris_clip_rejected += 1;
        } else if or != 0 {
            if let Some(q) = queue {
                self.flush(q, tri, sink, stats);
            }
            self.clipped([va, vb, vc], or, tri, sink, stats);
        } else if let Some(q) = queue {
            if q.push([va, vb, vc]) {
                self.flush(q, tri, sink, stats);
            }
        } else {
            self.one([va, vb, vc], tri, sink, stats);
        }
    }

    /// Clips a triangle that crosses the clip volume (`or`: its vertices' masks ORed) and
    /// sets up the pieces. Out of line: the clipper's vertex arrays made
    /// [`Self::triangle`]'s stack frame 11 KB, probed page by page for every triangle.
    #[cold]
    #[inline(never)]
    fn clipped<K: TriangleSink>(
        &self,
        v: [&ClipVertex; 3],
        or: ClipMask,
        tri: &mut SetupTriangle,
        sink: &mut K,
        stats: &mut Stats,
    ) {
        stats.tris_clipped += 1;
        clip_triangle(
            v,
            or,
            self.ucp,
            self.viewport,
            self.nvary,
            self.flat_vary,
            self.back,
            |p, q, r| self.one([p, q, r], tri, sink, stats),
        );
    }
}

/// A streamed draw's own post-transform cache, vertex slot and set-up triangle (one per
/// thread of a split draw). They are written for every vertex and triangle, so they live
/// on the heap on lines of their own ([`Streamer::state`]), not on the draw thread's stack
/// next to what the other thread polls or reads there (a split draw's shared state, the
/// fragment plan): sharing a cache line with those made every such write wait for the
/// other core.
#[repr(align(128))]
struct StreamState {
    cache: VertexCache,
    slot: VertexSlot,
    tri: SetupTriangle,
    /// Triangles waiting to be set up eight at a time, when the draw allows it.
    queue: Option<Box<SetupQueue>>,
    /// Where an indexed draw streamed in pieces ([`Streamer::stream_chunks`]) goes on
    /// transforming runs of vertices: the end of the last piece's runs (`None`: each
    /// call starts from vertex 0).
    resume: Option<usize>,
}

thread_local! {
    /// The stream state of the last streamed draw on this thread, kept for the next
    /// ([`Streamer::state`]): a new one cost an aligned allocation (glibc's `memalign`,
    /// with the heap consolidation it set off) per draw, about 8% of a frame of 400
    /// small polygons (sweep state 181).
    static SPARE_STATE: Cell<Option<Box<StreamState>>> = const { Cell::new(None) };
}

/// The streamed triangles of a draw: each vertex fetched and transformed when first
/// assembled (through the post-transform cache), then clipped and set up ([`TriPipe`]).
struct Streamer<'a, S: ?Sized> {
    verts: &'a S,
    indices: Option<&'a [u32]>,
    stage: &'a VertexStage,
    pipe: TriPipe<'a>,
    mode: Primitive,
    path: DrawPath,
    /// The triangles dropped before their vertices run through the stage.
    reject: &'a Rejection,
    /// The vertex references a thread's post-transform cache is sized for.
    n_cache: usize,
}

impl<S: VertexSource + ?Sized> Streamer<'_, S> {
    /// A new cache, slot and set-up triangle for the draw: the ones the last draw on this
    /// thread gave back ([`Self::recycle`]), emptied, when there are any.
    fn state(&self) -> Box<StreamState> {
        let nvary = self.pipe.nvary;
        let queue_ok = self.pipe.queue_ok();
        if let Some(mut st) = SPARE_STATE.with(Cell::take) {
            st.cache.reset(self.n_cache);
            st.slot = self.verts.new_slot();
            st.tri = SetupTriangle::default();
            st.queue = match (queue_ok, st.queue.take()) {
                (true, Some(mut q)) => {
                    q.reset(nvary);
                    Some(q)
                }
                (true, None) => Some(SetupQueue::new(nvary)),
                (false, _) => None,
            };
            st.resume = None;
            return st;
        }
        Box::new(StreamState {
            cache: VertexCache::for_draw(self.n_cache),
            slot: self.verts.new_slot(),
            tri: SetupTriangle::default(),
            queue: queue_ok.then(|| SetupQueue::new(nvary)),
            resume: None,
        })
    }

    /// Keeps a finished draw's state for the next draw on this thread ([`Self::state`]).
    fn recycle(st: Box<StreamState>) {
        SPARE_STATE.with(|c| c.set(Some(st)));
    }

    /// Streams `count` independent triangles from triangle `first` of a GL_TRIANGLES draw
    /// into `sink`. The cache carries over from the sections this thread streamed before:
    /// a vertex transforms the same in every section of a draw.
    fn run<K: TriangleSink>(
        &self,
        first: usize,
        count: usize,
        state: &mut StreamState,
        sink: &mut K,
        stats: &mut Stats,
    ) {
        self.stream(
            Primitive::Triangles,
            first * 3,
            count * 3,
            state,
            sink,
            stats,
        );
    }

    /// Streams the `n` vertex references of a draw of independent primitives of
    /// `unit` = (vertices, triangles) each ([`independent`]), a [`CHUNK`] of primitives
    /// at a time, until the pool is free to set up the second half of the rest while
    /// this thread sets up the first ([`Rasterizer::offload`]): halves of the chunks that
    /// are not rejected whole ([`Rejection::live_middle`]).
    fn stream_chunks(
        &self,
        unit: (usize, usize),
        n: usize,
        state: &mut StreamState,
        rast: &mut Rasterizer<'_, '_>,
        stats: &mut Stats,
    ) {
        let prims = n / unit.0;
        let mut pos = 0;
        state.resume = Some(0);
        while pos < prims {
            let left = prims - pos;
            if rast.can_offload(left * unit.1, stats) {
                let mid = self.reject.live_middle(pos, prims);
                rast.offload(
                    stats,
                    |binner, s| {
                        let mut st = self.state();
                        st.resume = Some(0);
                        self.stream_range(unit, mid, prims, &mut st, binner, s);
                    },
                    |rast, stats, second| {
                        let (a, b) = if second { (mid, prims) } else { (pos, mid) };
                        self.stream_range(unit, a, b, state, rast, stats);
                    },
                );
                break;
            }
            let step = CHUNK.min(left);
            self.stream_range(unit, pos, pos + step, state, rast, stats);
            pos += step;
        }
        state.resume = None;
    }

    /// Streams primitives `p0..p1` of a draw of independent primitives of `unit` =
    /// (vertices, triangles) each, counting the triangles of chunks the rejection found
    /// outside one clip plane ([`Rejection::dead`]) without assembling them.
    fn stream_range<K: TriangleSink>(
        &self,
        unit: (usize, usize),
        p0: usize,
        p1: usize,
        state: &mut StreamState,
        sink: &mut K,
        stats: &mut Stats,
    ) {
        let (verts, tris) = unit;
        let mut p = p0;
        while p < p1 {
            // The run of chunks from `p` that are all dead or all alive.
            let dead = self.reject.dead(p / CHUNK);
            let mut q = ((p / CHUNK + 1) * CHUNK).min(p1);
            while q < p1 && self.reject.dead(q / CHUNK) == dead {
                q = (q + CHUNK).min(p1);
            }
            if dead {
                let t = ((q - p) * tris) as u64;
                stats.triangles += t;
                stats.tris_clip_rejected += t;
            } else {
                self.stream(self.mode, p * verts, (q - p) * verts, state, sink, stats);
            }
            p = q;
        }
    }

    /// Streams vertices `first..first + n` as `mode`.
    fn stream<K: TriangleSink>(
        &self,
        mode: Primitive,
        first: usize,
        n: usize,
        state: &mut StreamState,
        sink: &mut K,
        stats: &mut Stats,
    ) {
        let StreamState {
            cache,
            slot,
            tri,
            queue,
            resume,
        } = state;
        let ix = |k: usize| self.indices.map_or(k, |ix| ix[k] as usize);
        let (verts, stage) = (self.verts, self.stage);
        // Vertices read in order are transformed ahead in runs of `BLOCK`
        // ([`VertexStage::run_block`]), `filled` being where the next run starts. Without
        // indices that is every vertex. With indices, a triangle whose highest vertex is at
        // most `BLOCK` past `filled` continues the run (a grid's rows, indices in the order
        // of first use); one further ahead only moves `filled` past itself, its vertices
        // being transformed one by one on a miss, so a jump starts no run of vertices the
        // draw may never read.
        //
        // A triangle outside one clip plane by the masks of the position pass is counted
        // and dropped first ([`Rejection`]), as the clip test after the stage would drop
        // it: its vertices are not lit, and a run skips the vertices that only rejected
        // triangles read.
        let block = stage.block_ok();
        let indexed = self.indices.is_some();
        let (mut filled, end) = if indexed {
            (resume.unwrap_or(0), verts.count())
        } else {
            (first, first + n)
        };
        let (reject, live) = (self.reject, self.reject.live());
        assemble::triangles(mode, n, self.path, self.pipe.flat, |a, b, c| {
            let k = [ix(first + a), ix(first + b), ix(first + c)];
            if reject.rejects(k) {
                stats.triangles += 1;
                stats.tris_clip_rejected += 1;
                // The vertices before the triangle's lowest are read in order: a run may
                // start past them (its own may be read by a later triangle).
                filled = filled.max(k[0].min(k[1]).min(k[2]));
                return;
            }
            let top = k[0].max(k[1]).max(k[2]) + 1;
            if block && top > filled {
                if indexed && top - filled > BLOCK {
                    filled = top;
                } else {
                    let from = filled.max(k[0].min(k[1]).min(k[2]));
                    let to = (from + BLOCK).max(top).min(end);
                    let run = |i, out: &mut [ClipVertex]| stage.run_block(verts, i, slot, out);
                    filled = match live {
                        Some(live) => cache.fill_live(from, to, live, run),
                        None => cache.fill(from, to, run),
                    };
                }
            }
            let [va, vb, vc] = cache.triangle(k, |i, out| {
                verts.vertex_into(i, slot);
                stage.run_into(&slot.v, out)
            });
            let q = queue.as_deref_mut();
            self.pipe.triangle(va, vb, vc, q, tri, sink, stats);
        });
        if let Some(q) = queue.as_deref_mut() {
            self.pipe.flush(q, tri, sink, stats);
        }
        if let Some(r) = resume.as_mut() {
            *r = filled;
        }
        stats.vertices += cache.transformed;
        cache.transformed = 0;
    }
}

/// Entries of the post-transform cache of a draw of independent primitives whose
/// vertex references run in order: two runs of [`BLOCK`] vertices, so that a triangle
/// across two runs still finds the first one's vertices.
const SEQUENTIAL_CACHE: usize = 2 * BLOCK;

/// Vertices a streamed draw transforms in one run ([`Streamer::stream`]).
const BLOCK: usize = 32;

/// A draw of GL_TRIANGLES is split over two threads when the mean pixel box of its first
/// [`split_probe`] triangles is at most this: set-up then costs more than drawing.
const SPLIT_MAX_AREA: f64 = 32.0;

/// Triangles a draw that may be split sets up the ordinary way first, to measure their
/// boxes (`SOFTGL_SPLIT_PROBE` for measurements, default 1024; at most a section).
fn split_probe() -> usize {
    crate::tuning::tuning().split_probe
}

/// A draw in feedback or selection mode: the vertex stage, then the draw module's
/// primitive stages into `sink` (the feedback buffer or the hit record); nothing is
/// rasterized.
pub fn feedback<S: VertexSource + ?Sized>(
    plan: &mut DrawPlan<'_>,
    mode: Primitive,
    verts: &S,
    indices: Option<&[u32]>,
    materials: Option<&[[Material; 2]]>,
    sink: &mut impl PrimSink,
) {
    let stage = &mut plan.stage;
    let n = indices.map_or(verts.count(), |i| i.len());
    let cv = match &plan.vertex {
        Some(vs) => vs.run(verts),
        None => run_vertices(stage, verts, materials),
    };
    let at = |k: usize| -> &ClipVertex {
        match indices {
            Some(ix) => &cv[ix[k] as usize],
            None => &cv[k],
        }
    };
    let edge = |k: usize| verts.edge_flag(indices.map_or(k, |ix| ix[k] as usize));
    let stages = crate::geometry::feedback::PrimStages {
        ucp: &stage.ucp,
        viewport: stage.viewport,
        nvary: stage.nvary(),
        flat: plan.frag.flat,
        // As the rasterizer state the draw module reads.
        cull: plan.cull,
        back: stage.two_side().then(|| stage.back_offset()),
        polygon: plan.raster.polygon,
        offset: plan.prims.offset,
        // Mesa's private feedback draw context never learns the depth format (its
        // minimum resolvable depth stays 0), so the offset units add nothing.
        depth_bits: 0,
    };
    stages.run(mode, n, at, edge, sink);
}

/// Whether any vertex the draw reads (every vertex of `verts`, or those `indices` name)
/// is outside the clip volume or a user clip plane, given `masks`, the clip masks of
/// `verts` ([`VertexStage::clip_masks`]); an index past them is tested on its own.
fn any_vertex_outside<S: VertexSource + ?Sized>(
    stage: &VertexStage,
    verts: &S,
    indices: Option<&[u32]>,
    masks: &[ClipMask],
) -> bool {
    match indices {
        Some(ix) => ix.iter().any(|&i| {
            let i = i as usize;
            match masks.get(i) {
                Some(&m) => m != 0,
                None => stage.clip_position(verts.position(i)).1 != 0,
            }
        }),
        None => masks.iter().any(|&m| m != 0),
    }
}

/// A line segment's pixels along its major axis, for [`draw_banded`]'s estimate: from
/// the window positions of two vertices inside the clip volume, else a fixed 64.
fn line_work(p: &ClipVertex, q: &ClipVertex) -> f64 {
    if p.mask != 0 || q.mask != 0 {
        return 64.0;
    }
    let (dx, dy) = (p.win[0] - q.win[0], p.win[1] - q.win[1]);
    f64::from(dx.abs().max(dy.abs())).min(1e6) + 1.0
}

/// Runs the vertex stage over `verts`, lighting each with its own material when
/// glMaterial was called between glBegin and glEnd, else in blocks of eight where the
/// stage allows ([`VertexStage::block_ok`]).
fn run_vertices<S: VertexSource + ?Sized>(
    stage: &mut VertexStage,
    verts: &S,
    materials: Option<&[[Material; 2]]>,
) -> Vec<ClipVertex> {
    let n = verts.count();
    match (materials, stage.light.is_some()) {
        (Some(m), true) if m.len() == n => {
            if let Some(l) = stage.light.as_mut() {
                l.vary_material(m);
            }
            (0..n)
                .zip(m)
                .map(|(i, m)| {
                    if let Some(l) = stage.light.as_mut() {
                        l.vertex_material = Some(*m);
                    }
                    stage.run(&verts.vertex(i))
                })
                .collect()
        }
        _ if stage.block_ok() => {
            // Eight vertices at a time, as the streamed triangles run them: lit lines
            // spent a quarter of their frame lighting one vertex at a time (sweep state
            // 178, a line loop with three lights).
            let mut slot = verts.new_slot();
            let mut out = vec![ClipVertex::default(); n];
            stage.run_block(verts, 0, &mut slot, &mut out);
            out
        }
        _ => {
            let mut slot = verts.new_slot();
            (0..n)
                .map(|i| {
                    verts.vertex_into(i, &mut slot);
                    stage.run(&slot.v)
                })
                .collect()
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fixed_function::matrix::Mat4;
    use crate::geometry::fetch::VertexIn;
    use crate::pipe::CurrentAttribs;

    /// Special values mixed into the random inputs.
    const ODD: [f32; 8] = [
        f32::NAN,
        f32::INFINITY,
        f32::NEG_INFINITY,
        0.0,
        -0.0,
        1.0,
        -1.0,
        1e30,
    ];

    #[test]
    fn position_pass_finds_the_vertex_stage_masks() {
        let mut next = crate::test_rng::xorshift32(0x9e37_79b9);
        let val = |next: &mut dyn FnMut() -> u32| {
            let r = next();
            if r.is_multiple_of(16) {
                ODD[(r >> 4) as usize % ODD.len()]
            } else {
                (r >> 8) as f32 / (1 << 23) as f32 * 4.0 - 2.0
            }
        };
        let cur = CurrentAttribs::default();
        let viewport = Viewport::new([0, 0, 64, 64], [0.0, 1.0], 64);
        let mut seen = [0; 2];
        for case in 0..400 {
            let m = Mat4(std::array::from_fn(|_| val(&mut next)));
            for fma in [false, true] {
                let mut stage = VertexStage::new(m, m, viewport, fma);
                if case % 3 == 0 {
                    stage.ucp_enabled = (next() & 0xff) as u8;
                    stage.ucp.planes =
                        std::array::from_fn(|_| std::array::from_fn(|_| val(&mut next)));
                }
                // Small draws, so that some are entirely inside.
                let n = 1 + next() as usize % 6;
                let scale = if case % 2 == 0 { 0.3 } else { 3.0 };
                let verts: Vec<VertexIn> = (0..n)
                    .map(|_| {
                        let p = std::array::from_fn(|_| val(&mut next) * scale);
                        VertexIn::with_current(p, &cur)
                    })
                    .collect();
                let indices: Vec<u32> = (0..n).map(|_| next() % n as u32).collect();
                // The reference: the masks of the whole vertex stage.
                let cv = run_vertices(&mut stage, verts.as_slice(), None);
                let want_arrays = cv.iter().any(|v| v.mask != 0);
                let want_elems = indices.iter().any(|&i| cv[i as usize].mask != 0);
                seen[want_arrays as usize] += 1;
                for (v, c) in verts.iter().zip(&cv) {
                    assert_eq!(stage.clip_position(v.pos).1, c.mask);
                }
                let mut masks = Vec::new();
                stage.clip_masks(verts.as_slice(), &mut masks);
                let want: Vec<ClipMask> = cv.iter().map(|v| v.mask).collect();
                assert_eq!(masks, want);
                let outside = |ix| any_vertex_outside(&stage, verts.as_slice(), ix, &masks);
                assert_eq!(outside(None), want_arrays);
                assert_eq!(outside(Some(&indices)), want_elems);
            }
        }
        // Both answers occur.
        assert!(seen[0] > 20 && seen[1] > 20, "{seen:?}");
    }
}
