//! A draw call, stage by stage: vertex stage → assembly → clipping → setup → raster.
//!
//! The clip decision is per draw, as in llvmpipe's draw module: if any vertex is outside
//! the clip volume the whole draw takes the clipping path, which also changes the
//! GL_QUADS/GL_QUAD_STRIP triangle split (llvmpipe-rules §5).

use crate::context::state::{Cap, Face, Primitive};
use crate::context::Context;
use crate::fixed_function::fog::FogPlan;
use crate::fixed_function::lighting::LightPlan;
use crate::fixed_function::transform::VertexStage;
use crate::fragment::FragPlan;
use crate::geometry::assemble::{self, DrawPath};
use crate::geometry::clip::{clip_line, clip_triangle};
use crate::geometry::fetch::VertexIn;
use crate::geometry::setup::{setup_triangle, CullMode, SetupResult, SetupTriangle};
use crate::geometry::{cpu_has_fma, ClipVertex, Viewport};
use crate::raster::batch::Rasterizer;
use crate::raster::lines::{raster_line, raster_point};

/// Draws `verts` as `mode`, through `indices` when given (each index < verts.len()).
pub fn draw(ctx: &mut Context, mode: Primitive, verts: &[VertexIn], indices: Option<&[u32]>) {
    let Some(fb) = ctx.fb.as_ref() else { return };
    let n = indices.map_or(verts.len(), |i| i.len());
    if n == 0 {
        return;
    }
    ctx.stats.draws += 1;
    ctx.dirty = true;
    let fma = cpu_has_fma();
    let st = &ctx.state;
    let viewport = Viewport::new(st.viewport, st.depth_range, fb.height);
    let modelview = *ctx.matrices.modelview.top();
    let mvp = ctx.matrices.projection.top().mul(&modelview);
    let mut stage = VertexStage::new(mvp, modelview, viewport, fma);
    stage.light = LightPlan::new(
        &ctx.light,
        &st.caps,
        st.current.color,
        &modelview,
        Some(ctx.matrices.modelview.top_flags()),
        false,
        fma,
    );
    stage.fog = st.caps.get(Cap::Fog).then_some(ctx.light.fog);
    let tex_plans: Vec<crate::texture::UnitPlan<'_>> = (0
        ..crate::context::state::MAX_TEXTURE_UNITS)
        .filter_map(|u| {
            let p = ctx.textures.unit_plan(u)?;
            stage.add_texture_unit(u, ctx.matrices.texture[u].top());
            Some(p)
        })
        .collect();
    let mut plan = FragPlan::new(st, fb.depth_format, !fb.stencil.is_empty(), fma);
    plan.separate_specular = stage.light.as_ref().is_some_and(|l| l.separate_specular());
    plan.fog = stage.fog.map(|f| FogPlan::new(&f, fma));
    plan.count_samples = ctx.queries.active.is_some();
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
        front_ccw: st.front_ccw,
    };

    let cv: Vec<ClipVertex> = verts.iter().map(|v| stage.run(v)).collect();
    ctx.stats.vertices += cv.len() as u64;
    let any_outside = match indices {
        Some(ix) => ix.iter().any(|&i| cv[i as usize].mask != 0),
        None => cv.iter().any(|v| v.mask != 0),
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
    let mut rast = Rasterizer::new(fb, &plan, &tex_plans, region);
    let mut tri = SetupTriangle::default();
    let mut one = |a: &ClipVertex,
                   b: &ClipVertex,
                   c: &ClipVertex,
                   rast: &mut Rasterizer<'_, '_>,
                   stats: &mut crate::stats::Stats| {
        match setup_triangle([a, b, c], nvary, cull, back, &mut tri) {
            SetupResult::Draw => rast.triangle(&tri, stats),
            SetupResult::Degenerate => stats.tris_degenerate += 1,
            SetupResult::Culled => stats.tris_culled += 1,
        }
    };
    match mode {
        Primitive::Points => {
            let mut target = rast.target(stats).target();
            for k in 0..n {
                let v = at(k);
                if v.mask == 0 {
                    raster_point(v, region, &plan, &mut target, stats);
                }
            }
        }
        Primitive::Lines | Primitive::LineLoop | Primitive::LineStrip => {
            let mut scratch = Vec::new();
            let mut target = rast.target(stats).target();
            assemble::lines(mode, n, |a, b| {
                let (va, vb) = (at(a), at(b));
                if va.mask & vb.mask != 0 {
                    return;
                }
                let (p, q) = if va.mask | vb.mask != 0 {
                    match clip_line(va, vb, va.mask | vb.mask, &viewport, nvary, plan.flat) {
                        Some(pq) => pq,
                        None => return,
                    }
                } else {
                    (*va, *vb)
                };
                raster_line(
                    &p,
                    &q,
                    &vb.vary,
                    region,
                    &plan,
                    &mut target,
                    stats,
                    &mut scratch,
                );
            });
        }
        _ => assemble::triangles(mode, n, path, plan.flat, |a, b, c| {
            let (va, vb, vc) = (at(a), at(b), at(c));
            stats.triangles += 1;
            let or = va.mask | vb.mask | vc.mask;
            if va.mask & vb.mask & vc.mask != 0 {
                stats.tris_clip_rejected += 1;
            } else if or != 0 {
                stats.tris_clipped += 1;
                let mut out: Vec<[ClipVertex; 3]> = Vec::new();
                clip_triangle([va, vb, vc], or, &viewport, nvary, plan.flat, |p, q, r| {
                    out.push([*p, *q, *r])
                });
                for [p, q, r] in &out {
                    one(p, q, r, &mut rast, stats);
                }
            } else {
                one(va, vb, vc, &mut rast, stats);
            }
        }),
    }
    rast.flush(stats);
    if ctx.state.caps.get(Cap::ColorMaterial) {
        ctx.light.sync_color_material(ctx.state.current.color);
    }
}
