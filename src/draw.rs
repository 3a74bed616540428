//! A draw call, stage by stage: vertex stage → assembly → clipping → setup → raster.
//!
//! The clip decision is per draw, as in llvmpipe's draw module: if any vertex is outside
//! the clip volume the whole draw takes the clipping path, which also changes the
//! GL_QUADS/GL_QUAD_STRIP triangle split (llvmpipe-rules §5).

use crate::context::feedback::{FeedbackSink, RenderMode};
use crate::context::state::Cap;
use crate::context::Context;
use crate::fixed_function::fog::FogPlan;
use crate::fixed_function::lighting::LightPlan;
use crate::fixed_function::point_size::PointAtten;
use crate::fixed_function::transform::VertexStage;
use crate::fragment::FragPlan;
use crate::geometry::assemble::{self, DrawPath};
use crate::geometry::clip::{clip_triangle, UserPlanes};
use crate::geometry::setup::{CullMode, SetupResult, SetupTriangle, SetupVariant};
use crate::geometry::setup8::{SetupQueue, QUEUE_VARY};
use crate::geometry::source::{VertexCache, VertexSlot, VertexSource};
use crate::geometry::{cpu_has_fma, ClipMask, ClipVertex, Viewport};
use crate::pipe::Material;
use crate::pipe::{Face, Primitive};
use crate::raster::batch::{geom_section, Binner, Rasterizer, TriangleSink};
use crate::raster::prims::{draw_point, point_size, LinePlan, PolyPipeline};

/// Draws `verts` as `mode`, through `indices` when given (each index < verts.count()).
pub fn draw<S: VertexSource + ?Sized>(
    ctx: &mut Context,
    mode: Primitive,
    verts: &S,
    indices: Option<&[u32]>,
) {
    draw_lit(ctx, mode, verts, indices, None)
}

/// [`draw`] with an optional material per vertex (glMaterial inside glBegin/glEnd).
pub fn draw_lit<S: VertexSource + ?Sized>(
    ctx: &mut Context,
    mode: Primitive,
    verts: &S,
    indices: Option<&[u32]>,
    materials: Option<&[[Material; 2]]>,
) {
    draw_inner(ctx, mode, verts, indices, materials, false)
}

/// [`draw`] for a chunk of a long glBegin/glEnd batch drawn while the batch is still being
/// specified ([`Context::stream_immediate`]): the chunk's last batch of triangles may be
/// left drawing on the pool ([`Context::settle_draws`]) while the program sends the next
/// chunk's vertices.
pub fn draw_chunk<S: VertexSource + ?Sized>(ctx: &mut Context, mode: Primitive, verts: &S) {
    draw_inner(ctx, mode, verts, None, None, true)
}

/// [`draw_lit`], leaving the last batch on the pool when `detach` allows it. A draw into
/// a 4x multisample object is one pass per sample plane ([`draw_multisample`]).
fn draw_inner<S: VertexSource + ?Sized>(
    ctx: &mut Context,
    mode: Primitive,
    verts: &S,
    indices: Option<&[u32]>,
    materials: Option<&[[Material; 2]]>,
    detach: bool,
) {
    if ctx.draw_samples() == 0 || ctx.feedback.mode != RenderMode::Render {
        return draw_pass(ctx, mode, verts, indices, materials, detach, None);
    }
    draw_multisample(ctx, mode, verts, indices, materials);
}

/// A draw into a 4x multisample object, as llvmpipe draws it (docs/fbo-rules.md §3).
///
/// With GL_MULTISAMPLE on, filled triangles are drawn once per sample plane, each pass
/// rasterised at its sample point ([`crate::geometry::setup::setup_triangle_ms`]) and
/// shaded as [`crate::fragment::MsPass`] says; a sample that glSampleCoverage's mask
/// leaves out (`(1 << (int)(v·4)) − 1`, inverted on request) is not drawn at all. Points
/// and lines are drawn into every plane with the single-sample rules (llvmpipe draws them
/// as rectangles sampled at the sample points: not reproduced).
///
/// With GL_MULTISAMPLE off, llvmpipe rasterises at pixel centres, tests and writes depth
/// and stencil of sample 0 only, and writes the colour of the fragments that pass into
/// every sample (blending with each sample's colour). Each plane s > 0 is drawn with a
/// copy of plane 0's depth and stencil as they were before the draw (so that it sees the
/// same tests pass, in the same order), its own depth and stencil put back afterwards;
/// plane 0 is drawn last, normally.
fn draw_multisample<S: VertexSource + ?Sized>(
    ctx: &mut Context,
    mode: Primitive,
    verts: &S,
    indices: Option<&[u32]>,
    materials: Option<&[[Material; 2]]>,
) {
    ctx.settle_draws();
    crate::context::pixel_ops::bitmap_cache::flush(ctx);
    let caps = &ctx.state.caps;
    if !caps.get(Cap::Multisample) {
        let Some(fb) = ctx.fb.as_mut() else { return };
        fb.resolve();
        let (depth0, stencil0) = (fb.depth.clone(), fb.stencil.clone());
        ctx.for_each_sample(|c, s| {
            if s == 0 {
                return;
            }
            let Some(fb) = c.fb.as_mut() else { return };
            fb.resolve();
            let own_d = std::mem::replace(&mut fb.depth, depth0.clone());
            let own_s = std::mem::replace(&mut fb.stencil, stencil0.clone());
            draw_pass(c, mode, verts, indices, materials, false, None);
            if let Some(fb) = c.fb.as_mut() {
                fb.depth = own_d;
                fb.stencil = own_s;
            }
        });
        return draw_pass(ctx, mode, verts, indices, materials, false, None);
    }
    // glSampleCoverage's mask (only with GL_SAMPLE_COVERAGE on; st_atom_msaa.c).
    let mut mask = 0xF_u32;
    if caps.get(Cap::SampleCoverage) {
        let l = &ctx.state.legacy;
        let nr = (l.sample_coverage_value * 4.0) as u32;
        let m = (1u32 << nr.min(4)) - 1;
        mask = if l.sample_coverage_invert {
            !m & 0xF
        } else {
            m
        };
    }
    let a2c = caps.get(Cap::SampleAlphaToCoverage);
    let triangles = !matches!(
        mode,
        Primitive::Points | Primitive::Lines | Primitive::LineLoop | Primitive::LineStrip
    );
    ctx.for_each_sample(|c, s| {
        if mask & (1 << s) != 0 {
            let pass = triangles.then(|| crate::fragment::MsPass::new(s, a2c));
            draw_pass(c, mode, verts, indices, materials, false, pass);
        }
    });
}

/// One pass of a draw: the whole pipeline into the framebuffer in `ctx.fb` (for a
/// multisample pass `ms`, the plane of its sample).
fn draw_pass<S: VertexSource + ?Sized>(
    ctx: &mut Context,
    mode: Primitive,
    verts: &S,
    indices: Option<&[u32]>,
    materials: Option<&[[Material; 2]]>,
    detach: bool,
    ms: Option<crate::fragment::MsPass>,
) {
    // Nothing may touch the framebuffer, nor start a rasterizer, while a draw is on the pool.
    ctx.settle_draws();
    crate::context::pixel_ops::bitmap_cache::flush(ctx);
    let Some(fb) = ctx.fb.as_ref() else { return };
    let n = indices.map_or(verts.count(), |i| i.len());
    if n == 0 {
        return;
    }
    // A draw whose vertices could not all be held at once is refused with
    // GL_OUT_OF_MEMORY (as when every vertex was fetched before drawing) rather than
    // streamed for minutes: the probe reserves address space and touches none of it.
    if Vec::<ClipVertex>::new()
        .try_reserve_exact(verts.count())
        .is_err()
    {
        ctx.record_error(crate::gl::error::GlError::OutOfMemory);
        return;
    }
    ctx.stats.draws += 1;
    ctx.dirty = true;
    ctx.fbo.drawn = true;
    let fma = cpu_has_fma();
    let st = &ctx.state;
    let cc = st.clip_control;
    let viewport = Viewport::with_convention(st.viewport, st.depth_range, fb.height, fb.y_flip, cc);
    let y_flip = fb.y_flip;
    let modelview = *ctx.matrices.modelview.top();
    let mvp = ctx.matrices.projection.top().mul(&modelview);
    let mut stage = VertexStage::new(mvp, modelview, viewport, fma);
    let ucp = &ctx.clip_planes;
    stage.set_user_planes(&ucp.eye, ucp.enabled, &ctx.matrices.projection);
    stage.fog = st.caps.get(Cap::Fog).then_some(ctx.light.fog);
    // Mesa's feedback vertex program always writes unit 0's texture coordinates; the
    // texture matrix and texgen apply only when the unit has a complete enabled texture.
    let feedback = ctx.feedback.mode != RenderMode::Render;
    let feedback_tex0 = feedback && ctx.textures.unit_plan(0).is_some();
    if feedback_tex0 {
        stage.add_texture_unit(0, ctx.matrices.texture[0].top());
    }
    let tex_plans: Vec<crate::texture::UnitPlan<'_>> = (0..crate::pipe::MAX_TEXTURE_UNITS)
        .filter(|_| !feedback)
        .filter_map(|u| {
            let p = ctx.textures.unit_plan(u)?;
            stage.add_texture_unit(u, ctx.matrices.texture[u].top());
            Some(p)
        })
        .collect();
    // the offset's view of the depth buffer: its bits, or the float tag
    let depth_bits = fb.depth_format.texel_bits() as i32;
    let mv_flags = ctx.matrices.modelview.top_flags();
    let (normalize, rescale) = (st.caps.get(Cap::Normalize), st.caps.get(Cap::RescaleNormal));
    let texgen_eye = stage.add_texgen(&ctx.texgen, mv_flags, normalize, rescale);
    if feedback && !feedback_tex0 {
        stage.add_texture_unit(0, &crate::fixed_function::matrix::IDENTITY);
    }
    stage.point_atten = PointAtten::new(&ctx.raster.point);
    stage.light = LightPlan::new(
        &ctx.light,
        &st.caps,
        st.current.color,
        &modelview,
        Some(mv_flags),
        texgen_eye || stage.point_atten.is_some(),
        fma,
    );
    let mut plan = FragPlan::new(st, fb.depth_format, !fb.stencil.is_empty(), fma);
    plan.ms = ms;
    stage.color_sum = stage.light.is_none() && st.caps.get(Cap::ColorSum);
    if feedback {
        drop(tex_plans);
        return draw_feedback(ctx, &mut stage, mode, verts, indices, materials);
    }
    plan.separate_specular =
        stage.color_sum || stage.light.as_ref().is_some_and(|l| l.separate_specular());
    plan.fog = stage.fog.map(|f| FogPlan::new(&f, fma));
    plan.count_samples = ctx.queries.active.is_some();
    // Triangles that take the polygon pipeline (unfilled, smooth, two-sided …) are drawn
    // with the single-sample rules in every plane.
    if PolyPipeline::needed(&ctx.raster, &st.caps, stage.two_side()) {
        plan.ms = None;
    }
    let Some(region) = ctx.draw_region() else {
        return;
    };
    if !plan.writes_anything() {
        return;
    }
    let cull_on = st.caps.get(Cap::CullFace);
    let cull = CullMode {
        front: cull_on && matches!(st.cull_face, Face::Front | Face::FrontAndBack),
        back: cull_on && matches!(st.cull_face, Face::Back | Face::FrontAndBack),
        // Unflipped (object) rows turn the winding over, and so does GL_UPPER_LEFT; each
        // also toggles llvmpipe's `bottom_edge_rule` (st_atom_rasterizer.c).
        front_ccw: (st.front_ccw == y_flip) != cc.upper_left,
        top_left: y_flip == cc.upper_left,
    };

    // Filled triangles, strips, fans, polygons, quads and quad strips stream through the
    // post-transform cache; points, lines and draws that need edge flags or per-vertex
    // materials transform every vertex first.
    let streamed = materials.is_none()
        && matches!(
            mode,
            Primitive::Triangles
                | Primitive::TriangleStrip
                | Primitive::TriangleFan
                | Primitive::Polygon
                | Primitive::Quads
                | Primitive::QuadStrip
        )
        && !PolyPipeline::needed(&ctx.raster, &st.caps, stage.two_side());
    let cv = if streamed {
        Vec::new()
    } else {
        run_vertices(&mut stage, verts, materials)
    };
    ctx.stats.vertices += cv.len() as u64;
    let any_outside = if streamed {
        // Only the split of quads and quad strips depends on whether any vertex is
        // outside (llvmpipe-rules §5; indexed or flat quads split one way on both paths):
        // a pass over the positions alone decides it before anything is assembled.
        let split_varies = match mode {
            Primitive::Quads => indices.is_none() && !plan.flat,
            Primitive::QuadStrip => true,
            _ => false,
        };
        split_varies && any_vertex_outside(&stage, verts, indices)
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
    let stats = &mut ctx.stats;
    let Some(fb) = ctx.fb.as_mut() else { return };
    // SAFETY: `rast` is a local dropped at the end of this function, never leaked.
    let mut rast = unsafe { Rasterizer::new(fb, &plan, &tex_plans, region, nvary) };
    // llvmpipe's own polygon offset (filled triangles outside the draw pipeline).
    let lp_offset = (st.caps.get(Cap::PolygonOffsetFill)
        && (ctx.raster.polygon.offset_factor != 0.0 || ctx.raster.polygon.offset_units != 0.0))
        .then(|| {
            let p = &ctx.raster.polygon;
            let units =
                crate::geometry::unfilled::scaled_units(p.offset_units, depth_bits.max(0) as u32);
            let float = depth_bits == crate::texture::shadow::FLOAT_BITS as i32;
            (p.offset_factor, (units, float))
        });
    let pipe = TriPipe {
        setup: match plan.ms {
            Some(m) => SetupVariant::multisample(m.sample),
            None => SetupVariant::detect(),
        },
        nvary,
        cull,
        back,
        flat: plan.flat,
        lp_offset,
        ucp: &stage.ucp,
        viewport: &viewport,
    };
    match mode {
        Primitive::Points => {
            let size = point_size(&ctx.raster);
            let per_vertex = stage.point_atten.is_some();
            let mut target = rast.target(stats).target();
            for k in 0..n {
                let v = at(k);
                if v.mask == 0 {
                    draw_point(
                        v,
                        if per_vertex { v.psize } else { size },
                        &st.caps,
                        nvary,
                        region,
                        &plan,
                        &tex_plans,
                        &mut target,
                        stats,
                    );
                }
            }
        }
        Primitive::Lines | Primitive::LineLoop | Primitive::LineStrip => {
            let mut lines = LinePlan::new(&ctx.raster, &st.caps, nvary);
            lines.ucp = stage.ucp;
            let mut stipple = lines.stipple;
            let mut target = rast.target(stats).target();
            assemble::lines(mode, n, |a, b, reset| {
                if reset {
                    if let Some(s) = stipple.as_mut() {
                        s.counter = 0.0;
                    }
                }
                let (va, vb) = (at(a), at(b));
                lines.draw(
                    va,
                    vb,
                    &viewport,
                    plan.flat,
                    stipple.as_mut(),
                    region,
                    &plan,
                    &tex_plans,
                    &mut target,
                    stats,
                );
            });
        }
        _ if PolyPipeline::needed(&ctx.raster, &st.caps, back.is_some()) => {
            let pp = PolyPipeline {
                lines: LinePlan {
                    ucp: stage.ucp,
                    ..LinePlan::new(&ctx.raster, &st.caps, nvary)
                },
                point_size: stage.point_atten.is_none().then(|| point_size(&ctx.raster)),
                raster: &ctx.raster,
                caps: &st.caps,
                cull,
                back,
                depth_bits: depth_bits.max(0) as u32,
                viewport,
                region,
            };
            let edge = |k: usize| verts.edge_flag(indices.map_or(k, |ix| ix[k] as usize));
            pp.draw(mode, n, at, edge, nvary, &plan, &mut rast, stats);
        }
        _ if streamed => {
            let streamer = Streamer {
                verts,
                indices,
                stage: &stage,
                pipe,
                mode,
                path,
            };
            let mut state = streamer.state(n);
            let section = geom_section();
            let ntris = n / 3;
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
                        || streamer.state(n),
                        geom,
                    );
                } else {
                    streamer.run(probe, ntris - probe, &mut state, &mut rast, stats);
                }
            } else {
                streamer.stream(streamer.mode, 0, n, &mut state, &mut rast, stats);
            }
        }
        _ => {
            let mut tri = SetupTriangle::default();
            assemble::triangles(mode, n, path, plan.flat, |a, b, c| {
                pipe.triangle(at(a), at(b), at(c), None, &mut tri, &mut rast, stats)
            });
        }
    }
    let kept = if detach {
        // SAFETY: the framebuffer goes into the returned batch below (`keep_inflight`)
        // before anything else touches it, and `ctx.settle_draws` (run by every draw
        // before it starts a rasterizer) hands it back once the batch is drawn; this draw
        // settled the previous one first.
        unsafe { rast.flush_detached(stats) }
    } else {
        rast.flush(stats);
        None
    };
    drop(rast);
    drop(tex_plans);
    if ctx.state.caps.get(Cap::ColorMaterial) {
        ctx.light.sync_color_material(ctx.state.current.color);
    }
    if let Some(f) = kept {
        // SAFETY: `f` draws into `ctx.fb`, untouched since the rasterizer was dropped
        // (only the colour-material sync ran), and this draw settled everything first.
        unsafe { ctx.keep_inflight(f) };
    }
}

/// The per-triangle stages after the vertex stage: clipping, setup, llvmpipe's polygon
/// offset, then the sink (the draw's rasterizer, or a section's batch of a split draw).
#[derive(Clone, Copy)]
struct TriPipe<'a> {
    setup: SetupVariant,
    nvary: usize,
    cull: CullMode,
    back: Option<usize>,
    flat: bool,
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
        stats: &mut crate::stats::Stats,
    ) {
        let r = self
            .setup
            .shaded(v, self.nvary, self.cull, self.back, self.flat, tri);
        if let (SetupResult::Draw, Some((factor, units))) = (r, self.lp_offset) {
            // a float depth buffer scales the units per triangle (`FLOAT_BITS` as bits)
            crate::raster::prims::apply_setup_offset(v, factor, units, tri);
        }
        Self::emit(r, tri, sink, stats);
    }

    /// Passes a set-up triangle to `sink`, or counts why setup dropped it.
    #[inline(always)]
    fn emit<K: TriangleSink>(
        r: SetupResult,
        tri: &SetupTriangle,
        sink: &mut K,
        stats: &mut crate::stats::Stats,
    ) {
        match r {
            SetupResult::Draw => sink.triangle(tri, stats),
            SetupResult::Degenerate => stats.tris_degenerate += 1,
            SetupResult::Culled => stats.tris_culled += 1,
            // What the rasterizer counts for a box without pixels.
            SetupResult::Empty => stats.tris_offscreen += 1,
        }
    }

    /// Whether this draw's triangles can be set up eight at a time ([`SetupQueue`]): on
    /// the AVX2 setup, without two-sided colours or llvmpipe's polygon offset (both look
    /// at a triangle's vertices after setup), and `SOFTGL_SETUP8=0` turns it off for A/B.
    fn queue_ok(&self) -> bool {
        static ON: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
        let on = *ON.get_or_init(|| std::env::var("SOFTGL_SETUP8").as_deref() != Ok("0"));
        on && self.setup.is_avx2()
            && self.back.is_none()
            && self.lp_offset.is_none()
            && self.nvary <= QUEUE_VARY
    }

    /// Sets up the triangles waiting in `queue` and passes them to `sink` in order.
    #[inline(never)]
    fn flush<K: TriangleSink>(
        &self,
        queue: &mut SetupQueue,
        tri: &mut SetupTriangle,
        sink: &mut K,
        stats: &mut crate::stats::Stats,
    ) {
        // SAFETY: a draw has a queue only when its setup is the AVX2 copy
        // (`Self::queue_ok`), which `SetupVariant::detect` picks only on AVX2 CPUs.
        unsafe {
            queue.flush(self.cull, self.flat, tri, |r, t| {
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
        stats: &mut crate::stats::Stats,
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
        stats: &mut crate::stats::Stats,
    ) {
        stats.tris_clipped += 1;
        clip_triangle(
            v,
            or,
            self.ucp,
            self.viewport,
            self.nvary,
            self.flat,
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
}

impl<S: VertexSource + ?Sized> Streamer<'_, S> {
    /// A new cache, slot and set-up triangle for a draw of `n` vertex references.
    fn state(&self, n: usize) -> Box<StreamState> {
        Box::new(StreamState {
            cache: VertexCache::for_draw(n),
            slot: self.verts.new_slot(),
            tri: SetupTriangle::default(),
            queue: self
                .pipe
                .queue_ok()
                .then(|| SetupQueue::new(self.pipe.nvary)),
        })
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
        stats: &mut crate::stats::Stats,
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

    /// Streams vertices `first..first + n` as `mode`.
    fn stream<K: TriangleSink>(
        &self,
        mode: Primitive,
        first: usize,
        n: usize,
        state: &mut StreamState,
        sink: &mut K,
        stats: &mut crate::stats::Stats,
    ) {
        let StreamState {
            cache,
            slot,
            tri,
            queue,
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
        let block = stage.block_ok();
        let indexed = self.indices.is_some();
        let (mut filled, end) = if indexed {
            (0, verts.count())
        } else {
            (first, first + n)
        };
        assemble::triangles(mode, n, self.path, self.pipe.flat, |a, b, c| {
            let k = [ix(first + a), ix(first + b), ix(first + c)];
            let top = k[0].max(k[1]).max(k[2]) + 1;
            if block && top > filled {
                if indexed && top - filled > BLOCK {
                    filled = top;
                } else {
                    let from = filled.max(k[0].min(k[1]).min(k[2]));
                    let to = (from + BLOCK).max(top).min(end);
                    filled = cache.fill(from, to, |i, out| stage.run_block(verts, i, slot, out));
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
        stats.vertices += cache.transformed;
        cache.transformed = 0;
    }
}

/// Vertices a streamed draw transforms in one run ([`Streamer::stream`]).
const BLOCK: usize = 32;

/// A draw of GL_TRIANGLES is split over two threads when the mean pixel box of its first
/// [`split_probe`] triangles is at most this: set-up then costs more than drawing.
const SPLIT_MAX_AREA: f64 = 32.0;

/// Triangles a draw that may be split sets up the ordinary way first, to measure their
/// boxes (`SOFTGL_SPLIT_PROBE` for measurements; at most a section).
fn split_probe() -> usize {
    static P: std::sync::OnceLock<usize> = std::sync::OnceLock::new();
    *P.get_or_init(|| {
        std::env::var("SOFTGL_SPLIT_PROBE")
            .ok()
            .and_then(|v| v.parse::<usize>().ok())
            .unwrap_or(SPLIT_PROBE)
    })
}

/// [`split_probe`]'s default.
const SPLIT_PROBE: usize = 1024;

/// A draw in feedback or selection mode: the vertex stage, then the draw module's
/// primitive stages into the feedback buffer or the hit record; nothing is rasterized.
fn draw_feedback<S: VertexSource + ?Sized>(
    ctx: &mut Context,
    stage: &mut VertexStage,
    mode: Primitive,
    verts: &S,
    indices: Option<&[u32]>,
    materials: Option<&[[Material; 2]]>,
) {
    let Some(fb) = ctx.fb.as_ref() else { return };
    let st = &ctx.state;
    let n = indices.map_or(verts.count(), |i| i.len());
    let cv = run_vertices(stage, verts, materials);
    let at = |k: usize| -> &ClipVertex {
        match indices {
            Some(ix) => &cv[ix[k] as usize],
            None => &cv[k],
        }
    };
    let edge = |k: usize| verts.edge_flag(indices.map_or(k, |ix| ix[k] as usize));
    let cull_on = st.caps.get(Cap::CullFace);
    let stages = crate::geometry::feedback::PrimStages {
        ucp: &stage.ucp,
        viewport: stage.viewport,
        nvary: stage.nvary(),
        flat: st.shade_model == crate::pipe::ShadeModel::Flat,
        cull: CullMode {
            front: cull_on && matches!(st.cull_face, Face::Front | Face::FrontAndBack),
            back: cull_on && matches!(st.cull_face, Face::Back | Face::FrontAndBack),
            // As the rasterizer state the draw module reads (see `draw_inner`).
            front_ccw: (st.front_ccw == fb.y_flip) != st.clip_control.upper_left,
            top_left: fb.y_flip == st.clip_control.upper_left,
        },
        back: stage.two_side().then(|| stage.back_offset()),
        polygon: ctx.raster.polygon,
        offset: [
            st.caps.get(Cap::PolygonOffsetFill),
            st.caps.get(Cap::PolygonOffsetLine),
            st.caps.get(Cap::PolygonOffsetPoint),
        ],
        // Mesa's private feedback draw context never learns the depth format (its
        // minimum resolvable depth stays 0), so the offset units add nothing.
        depth_bits: 0,
    };
    let mut sink = FeedbackSink {
        state: &mut ctx.feedback,
        height: fb.height as f32,
        tex0: crate::geometry::VARY_TEX,
    };
    stages.run(mode, n, at, edge, &mut sink);
}

/// Whether any vertex the draw reads (every vertex of `verts`, or those `indices` name)
/// is outside the clip volume or a user clip plane: the clip masks [`run_vertices`] would
/// give, from the positions alone.
fn any_vertex_outside<S: VertexSource + ?Sized>(
    stage: &VertexStage,
    verts: &S,
    indices: Option<&[u32]>,
) -> bool {
    let outside = |p: [f32; 4]| stage.clip_position(p).1 != 0;
    if let Some(fp) = verts.float_positions() {
        // The same positions, read without a per-vertex fetch (a pass over 40k sprite
        // corners was 4% of their frame).
        let n = fp.count();
        return match indices {
            Some(ix) => ix.iter().any(|&i| {
                let i = i as usize;
                outside(if i < n { fp.get(i) } else { verts.position(i) })
            }),
            None => (0..n).any(|i| outside(fp.get(i))),
        };
    }
    match indices {
        Some(ix) => ix.iter().any(|&i| outside(verts.position(i as usize))),
        None => (0..verts.count()).any(|i| outside(verts.position(i))),
    }
}

/// Runs the vertex stage over `verts`, lighting each with its own material when
/// glMaterial was called between glBegin and glEnd.
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
                    stage.ucp = std::array::from_fn(|_| std::array::from_fn(|_| val(&mut next)));
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
                assert_eq!(
                    any_vertex_outside(&stage, verts.as_slice(), None),
                    want_arrays
                );
                assert_eq!(
                    any_vertex_outside(&stage, verts.as_slice(), Some(&indices)),
                    want_elems
                );
            }
        }
        // Both answers occur.
        assert!(seen[0] > 20 && seen[1] > 20, "{seen:?}");
    }
}
