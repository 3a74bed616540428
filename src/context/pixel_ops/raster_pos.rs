//! glRasterPos and glWindowPos, following Mesa's `_mesa_RasterPos` and `window_pos3f`
//! (`main/rastpos.c`), which llvmpipe's state tracker uses for fixed function.
//!
//! Numbers: eye = MV·v and clip = P·eye with `TRANSFORM_POINT` (left-to-right f32 sums);
//! the point is invalid when `z < -w`, `z > w`, `|x| > w`, `|y| > w` or a user plane's
//! `dot4(clip, plane) < 0`; window = `(clip·(1/w))·scale + translate` with the viewport
//! in GL's y-up orientation (y scale negated under GL_UPPER_LEFT; z `f−n`, `n` under
//! GL_ZERO_TO_ONE, whose near plane the clip test ignores, as Mesa's does); raster w = clip w; the distance is `sqrtf(|eye.xyz|²)` (or
//! the fog coordinate). Without lighting the colours are the current ones, unclamped.
//! Texture coordinates go through texgen and the texture matrix.
//!
//! Approximations: with lighting, the colour comes from the vertex-program lighting
//! ([`crate::fixed_function::lighting`]) rather than Mesa's C `shade_rastpos`, and
//! generated coordinates from [`crate::fixed_function::texgen`] rather than the C
//! `compute_texgen`; both may differ from Mesa in the last bits.

use crate::context::state::Cap;
use crate::context::texgen_state::plane_times_inverse;
use crate::context::Context;
use crate::fixed_function::lighting::{eye_normal, light_vertex, LightPlan};
use crate::fixed_function::texgen::{generate, NormalXform, TexGenPlan};
use crate::pipe::transform_point;
use crate::pipe::MAX_TEXTURE_UNITS;

/// glRasterPos4f with object coordinates `v`.
pub fn raster_pos(ctx: &mut Context, v: [f32; 4]) {
    let mv = *ctx.matrices.modelview.top();
    let eye = transform_point(&mv.0, v);
    let clip = transform_point(&ctx.matrices.projection.top().0, eye);
    let [x, y, z, w] = clip;
    let mut valid = !(z < -w || z > w || x > w || x < -w || y > w || y < -w);
    let cp = ctx.clip_planes;
    for i in 0..8 {
        if valid && cp.enabled & (1 << i) != 0 {
            let p = plane_times_inverse(&ctx.matrices.projection, cp.eye[i]);
            if x * p[0] + y * p[1] + z * p[2] + w * p[3] < 0.0 {
                valid = false;
            }
        }
    }
    ctx.raster_pos.valid = valid;
    if !valid {
        return;
    }
    let st = &ctx.state;
    let d = if w == 0.0 { 1.0 } else { 1.0 / w };
    let ndc = [x * d, y * d, z * d];
    let vp = st.viewport;
    let (hw, hh) = (0.5f32 * vp[2] as f32, 0.5f32 * vp[3] as f32);
    let (n, f) = (st.depth_range[0], st.depth_range[1]);
    // `_mesa_get_viewport_xform`, with glClipControl's y and z (the clip test above keeps
    // `z < -w` in Mesa whatever the depth mode).
    let cc = st.clip_control;
    let sy = if cc.upper_left { -hh } else { hh };
    let (sz, tz) = if cc.zero_to_one {
        ((f - n) as f32, n as f32)
    } else {
        ((0.5 * (f - n)) as f32, (0.5 * (n + f)) as f32)
    };
    let scale = [hw, sy, sz];
    let translate = [hw + vp[0] as f32, hh + vp[1] as f32, tz];
    let r = &mut ctx.raster_pos;
    for i in 0..3 {
        r.pos[i] = ndc[i] * scale[i] + translate[i];
    }
    if ctx.feedback.mode == crate::context::feedback::RenderMode::Select {
        ctx.feedback.update_hit(r.pos[2]);
    }
    r.pos[3] = w;
    r.distance = if ctx.light.fog.coord_from_attrib {
        st.current.fog_coord
    } else {
        (eye[0] * eye[0] + eye[1] * eye[1] + eye[2] * eye[2]).sqrt()
    };
    let flags = ctx.matrices.modelview.top_flags();
    let (normalize, rescale) = (st.caps.get(Cap::Normalize), st.caps.get(Cap::RescaleNormal));
    let plans: [Option<TexGenPlan>; MAX_TEXTURE_UNITS] =
        std::array::from_fn(|u| TexGenPlan::new(&ctx.texgen.units[u]));
    let texgen_eye = plans.iter().flatten().any(|p| p.needs_eye());
    let cur = st.current;
    match LightPlan::new(
        &ctx.light,
        &crate::plan::light_enables(&st.caps),
        cur.color,
        &mv,
        Some(flags),
        texgen_eye,
        crate::geometry::cpu_has_fma(),
    ) {
        Some(lp) => {
            let lit = light_vertex(&lp, eye, eye_normal(&lp, cur.normal), cur.color);
            r.color = lit.front;
            r.secondary = lit.front_spec;
        }
        None => {
            r.color = cur.color;
            r.secondary = cur.secondary_color;
        }
    }
    let nx = NormalXform::new(&mv, flags, normalize, rescale).apply(cur.normal);
    for (u, plan) in plans.iter().enumerate() {
        let mut tc = cur.texcoord[u];
        if let Some(p) = plan {
            tc = generate(p, tc, v, eye, nx);
        }
        r.texcoords[u] = transform_point(&ctx.matrices.texture[u].top().0, tc);
    }
}

/// glWindowPos3f: window coordinates directly; z is clamped and mapped to the depth
/// range; the colours are the current ones clamped to [0,1].
pub fn window_pos(ctx: &mut Context, x: f32, y: f32, z: f32) {
    let st = &ctx.state;
    let (n, f) = (st.depth_range[0], st.depth_range[1]);
    let r = &mut ctx.raster_pos;
    r.pos = [x, y, (z.clamp(0.0, 1.0) as f64 * (f - n) + n) as f32, 1.0];
    r.valid = true;
    r.distance = if ctx.light.fog.coord_from_attrib {
        st.current.fog_coord
    } else {
        0.0
    };
    r.color = st.current.color.map(|c| c.clamp(0.0, 1.0));
    r.secondary = st.current.secondary_color.map(|c| c.clamp(0.0, 1.0));
    r.texcoords = st.current.texcoord;
    if ctx.feedback.mode == crate::context::feedback::RenderMode::Select {
        ctx.feedback.update_hit(r.pos[2]);
    }
}
