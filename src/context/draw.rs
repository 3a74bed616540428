//! The state's side of a draw: flush what must be settled first, gather references to
//! the parameter blocks into one [`DrawState`], have [`crate::plan::build`] translate them
//! into a [`DrawPlan`], and hand that to the pipeline ([`crate::render`]). Multisample
//! triangle draws write the four sample planes in one pass; other multisample draws are
//! one pass per sample plane.

use super::feedback::{FeedbackSink, RenderMode};
use super::program_draw::ProgramDraw;
use super::state::{Cap, State};
use super::Context;
use crate::fragment::FragPlan;
use crate::framebuffer::DepthFormat;
use crate::geometry::source::VertexSource;
use crate::geometry::ClipVertex;
use crate::pipe::{Material, Primitive};
use crate::plan::{DrawState, FragState, Target};
use crate::render::DrawPlan;

/// Draws `verts` as `mode`, through `indices` when given (each index < verts.count()):
/// glDrawArrays and glDrawElements. Its last batch of triangles may be left drawing on the
/// pool, as a glBegin/glEnd draw's: the vertices are all fetched (from client arrays or
/// buffer objects) before the call returns, and the batch owns what it draws with.
pub fn draw<S: VertexSource + ?Sized>(
    ctx: &mut Context,
    mode: Primitive,
    verts: &S,
    indices: Option<&[u32]>,
) {
    draw_batch(ctx, mode, verts, indices, None, true)
}

/// [`draw`] with an optional material per vertex (glMaterial inside glBegin/glEnd), for
/// a finished glBegin/glEnd batch or a display list's vertex node too: with `keep`, its
/// last batch of triangles may be left drawing on the pool ([`Context::settle_draws`])
/// while the program goes on with state calls that keep it and the next draw, which
/// takes it back.
pub fn draw_batch<S: VertexSource + ?Sized>(
    ctx: &mut Context,
    mode: Primitive,
    verts: &S,
    indices: Option<&[u32]>,
    materials: Option<&[[Material; 2]]>,
    keep: bool,
) {
    let prims = Prims {
        mode,
        verts,
        indices,
        materials,
    };
    draw_inner(ctx, prims, keep)
}

/// [`draw`] for a chunk of a long glBegin/glEnd batch drawn while the batch is still being
/// specified ([`Context::stream_immediate`]): the chunk's last batch of triangles may be
/// left drawing on the pool ([`Context::settle_draws`]) while the program sends the next
/// chunk's vertices.
pub fn draw_chunk<S: VertexSource + ?Sized>(ctx: &mut Context, mode: Primitive, verts: &S) {
    let prims = Prims {
        mode,
        verts,
        indices: None,
        materials: None,
    };
    draw_inner(ctx, prims, true)
}

/// What one draw draws: `verts` as `mode`, through `indices` when given, with a material
/// per vertex when given.
struct Prims<'a, S: ?Sized> {
    mode: Primitive,
    verts: &'a S,
    indices: Option<&'a [u32]>,
    materials: Option<&'a [[Material; 2]]>,
}

impl<S: ?Sized> Clone for Prims<'_, S> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<S: ?Sized> Copy for Prims<'_, S> {}

/// [`draw_batch`], leaving the last batch on the pool when `detach` allows it. A draw into
/// a 4x multisample object goes through [`draw_multisample`].
fn draw_inner<S: VertexSource + ?Sized>(ctx: &mut Context, prims: Prims<'_, S>, detach: bool) {
    if ctx.draw_samples() == 0 || ctx.feedback.mode != RenderMode::Render {
        draw_pass(ctx, prims, detach, None);
        return;
    }
    draw_multisample(ctx, prims, detach);
}

/// A draw into a 4x multisample object, as llvmpipe draws it (docs/fbo-rules.md §3).
///
/// With GL_MULTISAMPLE on, filled triangles, lines (rectangles), points (squares) and
/// polygons drawn as lines or points are drawn once into the four sample planes
/// ([`crate::fragment::MsPass`]: rasterised at the four sample points, shaded once per
/// pixel, tested and written per sample; [`crate::raster::ms_prims`]); a sample that
/// glSampleCoverage's mask (`(1 << (int)(v·4)) − 1`, inverted on request) leaves out is
/// not drawn at all. Filled triangles that take the polygon pipeline (stippled, …) are
/// drawn into every plane with the single-sample rules, one pass per plane.
///
/// With GL_MULTISAMPLE off, llvmpipe rasterises at pixel centres, tests and writes depth
/// and stencil of sample 0 only, and writes the colour of the fragments that pass into
/// every sample (blending with each sample's colour). Each plane s > 0 is drawn with a
/// copy of plane 0's depth and stencil as they were before the draw (so that it sees the
/// same tests pass, in the same order), its own depth and stencil put back afterwards;
/// plane 0 is drawn last, normally.
///
/// The one-pass draw may leave its last batch on the pool (`detach`), holding the sample
/// planes with plane 0 (`fbo.ms_held`); the other ways settle it first.
fn draw_multisample<S: VertexSource + ?Sized>(
    ctx: &mut Context,
    prims: Prims<'_, S>,
    detach: bool,
) {
    crate::context::pixel_ops::bitmap_cache::flush(ctx);
    let caps = &ctx.state.caps;
    if !caps.get(Cap::Multisample) {
        ctx.settle_draws();
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
            draw_pass(c, prims, false, None);
            if let Some(fb) = c.fb.as_mut() {
                fb.depth = own_d;
                fb.stencil = own_s;
            }
        });
        draw_pass(ctx, prims, false, None);
        return;
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
    if mask == 0 {
        ctx.settle_draws();
        return;
    }
    let pass = crate::fragment::MsPass {
        mask: mask as u8,
        alpha_to_coverage: caps.get(Cap::SampleAlphaToCoverage),
    };
    if draw_pass(ctx, prims, detach, Some(pass)) {
        return;
    }
    ctx.for_each_sample(|c, s| {
        if mask & (1 << s) != 0 {
            draw_pass(c, prims, false, None);
        }
    });
}

/// One pass of a draw: the whole pipeline into the framebuffer in `ctx.fb`; with `ms`,
/// the triangles of a multisample draw into all four sample planes at once (plane 0 in
/// `ctx.fb`, the others in `ctx.fbo.ms_planes`). Returns false only when `ms` was asked
/// for and the draw's triangles take the polygon pipeline instead, which draws with the
/// single-sample rules: then nothing was drawn (the caller draws each plane).
fn draw_pass<S: VertexSource + ?Sized>(
    ctx: &mut Context,
    prims: Prims<'_, S>,
    detach: bool,
    ms: Option<crate::fragment::MsPass>,
) -> bool {
    // Nothing may touch the framebuffer, nor start a rasterizer, while a draw is on the
    // pool: a draw that may leave its own last batch there (no bitmaps pending, not in
    // feedback; a multisample one only in one pass, its planes held with plane 0) takes
    // the previous one back in its rasterizer, after setting up its triangles; any other
    // draw settles it first.
    let detach =
        detach && ctx.bitmap_cache.pending.is_none() && ctx.feedback.mode == RenderMode::Render;
    let mut adopt = if detach {
        ctx.release_inflight()
    } else {
        ctx.settle_draws();
        None
    };
    let drawn = draw_pass_with(ctx, prims, detach, ms, &mut adopt);
    if let Some(a) = adopt {
        a.settle(&mut ctx.stats, ctx.fb.as_mut());
    }
    // Unless this draw's batch holds the sample planes now, they go back.
    ctx.unhold_samples();
    drawn
}

/// The size of a draw's transformed vertices from which [`draw_pass_with`] checks that
/// they could be held at once (1 GiB: about 5.6 million vertices).
const OOM_PROBE_BYTES: usize = 1 << 30;

/// [`draw_pass`] once the previous draw's batch is settled or in `adopt` (taken by the
/// draw's rasterizer, or left for the caller to settle when nothing is drawn).
fn draw_pass_with<S: VertexSource + ?Sized>(
    ctx: &mut Context,
    prims: Prims<'_, S>,
    detach: bool,
    ms: Option<crate::fragment::MsPass>,
    adopt: &mut Option<crate::raster::batch::Adopted>,
) -> bool {
    crate::context::pixel_ops::bitmap_cache::flush(ctx);
    let Some(fb) = ctx.fb.as_ref() else {
        return true;
    };
    let n = prims.indices.map_or(prims.verts.count(), |i| i.len());
    if n == 0 {
        return true;
    }
    // A draw whose vertices could not all be held at once is refused with
    // GL_OUT_OF_MEMORY (as when every vertex was fetched before drawing) rather than
    // streamed for minutes: the probe reserves address space and touches none of it.
    // Below [`OOM_PROBE_BYTES`] the reservation cannot fail short of a broken allocator,
    // and is not made: it cost a malloc and free per draw, and an mmap and munmap from
    // 128 KiB (530 vertices) up.
    let count = prims.verts.count();
    if count.saturating_mul(std::mem::size_of::<ClipVertex>()) >= OOM_PROBE_BYTES
        && Vec::<ClipVertex>::new().try_reserve_exact(count).is_err()
    {
        ctx.record_error(crate::gl::error::GlError::OutOfMemory);
        return true;
    }
    let target = Target {
        height: fb.height,
        y_flip: fb.y_flip,
        depth_format: fb.depth_format,
        has_stencil: !fb.stencil.is_empty(),
        srgb: fb.srgb,
        more_buffers: fb.more_color_mask(),
    };
    let region = ctx.draw_region();
    let program = ctx.program_draw();
    if matches!(program, ProgramDraw::Refused) && ctx.feedback.mode == RenderMode::Render {
        ctx.stats.program_draws_refused += 1;
        return true;
    }
    let shader = match &program {
        ProgramDraw::Shader(fs, vs) => Some(crate::plan::ShaderInput {
            frag: fs.as_ref().map(|(f, u)| (&**f, &u[..])),
            vert: vs.as_ref().map(|v| crate::plan::VertInput {
                shader: &v.shader,
                uniforms: &v.uniforms,
                generic: v.generic,
            }),
        }),
        _ => None,
    };
    let st = &ctx.state;
    let input = DrawState {
        caps: &st.caps,
        viewport: st.viewport,
        depth_range: st.depth_range,
        clip_control: st.clip_control,
        frag: frag_state(st),
        cull_face: st.cull_face,
        front_ccw: st.front_ccw,
        current_color: st.current.color,
        modelview: &ctx.matrices.modelview,
        projection: &ctx.matrices.projection,
        texture: &ctx.matrices.texture,
        clip_planes: &ctx.clip_planes,
        light: &ctx.light,
        texgen: &ctx.texgen,
        raster: &ctx.raster,
        textures: &ctx.textures,
        target,
        feedback: ctx.feedback.mode != RenderMode::Render,
        count_samples: ctx.queries.active.is_some(),
        ms,
        points_lines: matches!(
            prims.mode,
            Primitive::Points | Primitive::Lines | Primitive::LineLoop | Primitive::LineStrip
        ),
        shader,
    };
    let mut plan = crate::plan::build(&input);
    if ms.is_some() && plan.frag.ms.is_none() {
        return false;
    }
    ctx.stats.draws += 1;
    if target.more_buffers != 0 && plan.frag.shader.is_none() {
        ctx.stats.ff_draws_one_buffer += 1;
    }
    ctx.dirty = true;
    ctx.fbo.drawn = true;
    if plan.feedback {
        let mut sink = FeedbackSink {
            state: &mut ctx.feedback,
            height: target.height as f32,
            tex0: crate::geometry::VARY_TEX,
        };
        let Prims {
            mode,
            verts,
            indices,
            materials,
        } = prims;
        crate::render::feedback(&mut plan, mode, verts, indices, materials, &mut sink);
        return true;
    }
    let Some(region) = region else {
        return true;
    };
    if !plan.frag.writes_anything() {
        return true;
    }
    let Some(fb) = ctx.fb.as_mut() else {
        return true;
    };
    let one_pass = plan.frag.ms.is_some();
    if one_pass && !ctx.fbo.ms_held {
        // The other planes ride along with plane 0 (`Framebuffer::samples`), until the
        // draw and any batch it leaves on the pool are done (`Context::unhold_samples`);
        // a draw that took over such a batch finds them there.
        fb.hold_samples(std::mem::take(&mut ctx.fbo.ms_planes));
        ctx.fbo.ms_held = true;
    }
    let kept = run(
        &mut plan,
        prims,
        fb,
        region,
        &mut ctx.stats,
        detach,
        adopt.take(),
    );
    if ctx.state.caps.get(Cap::ColorMaterial) {
        ctx.light.sync_color_material(ctx.state.current.color);
    }
    if let Some(f) = kept {
        // SAFETY: `f` draws into `ctx.fb`, untouched since the pipeline returned it (only
        // the colour-material sync ran), and this draw settled everything first.
        unsafe { ctx.keep_inflight(f) };
    }
    true
}

/// [`crate::render::run`], for a draw that settled the previous one first or hands it
/// over (`adopt`).
fn run<S: VertexSource + ?Sized>(
    plan: &mut DrawPlan<'_>,
    prims: Prims<'_, S>,
    fb: &mut crate::framebuffer::Framebuffer,
    region: [i64; 4],
    stats: &mut crate::stats::Stats,
    detach: bool,
    adopt: Option<crate::raster::batch::Adopted>,
) -> Option<crate::raster::batch::InFlight> {
    // SAFETY: with `detach`, the caller keeps the returned batch (`keep_inflight`) before
    // anything else touches `fb`, and every draw settles the draws on the pool
    // (`Context::settle_draws`) before it starts a rasterizer, or hands the one in flight
    // into `fb` to this draw's rasterizer (`adopt`), which takes it back first.
    unsafe {
        crate::render::run(
            plan,
            prims.mode,
            prims.verts,
            prims.indices,
            prims.materials,
            fb,
            region,
            stats,
            detach,
            adopt,
        )
    }
}

/// The fragment operations' part of `st`.
fn frag_state(st: &State) -> FragState<'_> {
    FragState {
        caps: &st.caps,
        ops: &st.frag,
        depth_func: st.depth_func,
        depth_mask: st.depth_mask,
        shade_model: st.shade_model,
        color_mask: st.color_write_mask(),
    }
}

/// The fragment plan of `st` for buffers of `depth_format` (and a stencil buffer when
/// `has_stencil`), for the pixel-rectangle paths.
pub fn frag_plan(st: &State, depth_format: DepthFormat, has_stencil: bool, fma: bool) -> FragPlan {
    crate::plan::fragment(&frag_state(st), depth_format, has_stencil, fma)
}
