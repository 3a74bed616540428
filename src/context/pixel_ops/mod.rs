//! The pixel-rectangle commands on the state: glRasterPos/glWindowPos ([`raster_pos`]),
//! glDrawPixels, glBitmap (through Mesa's [`bitmap_cache`]), glCopyPixels and
//! glBlitFramebuffer ([`blit`]). Each reads the context once and hands plain values to
//! the pipeline's [`crate::pixels`], which rasterises the rectangles (the rules Mesa
//! follows are documented there).

pub mod bitmap_cache;
pub mod blit;
pub mod raster_pos;

use super::feedback::{FeedbackVertex, RenderMode};
use super::pixel_transfer::PixelTransfer;
use super::state::Cap;
use super::Context;
use crate::fixed_function::fog::FogPlan;
use crate::geometry::cpu_has_fma;
use crate::gl::enums::{GL_BITMAP_TOKEN, GL_COPY_PIXEL_TOKEN, GL_DRAW_PIXEL_TOKEN};
use crate::pipe::{CompareFunc, MAX_TEXTURE_UNITS};
use crate::pixels::draw::{self as px, CopyKind, CopySource, Shader, Source};
use crate::pixels::image::{Image, Pixels};
use crate::pixels::rect::Quad;

/// The fragment shader of pixel rectangles under the current state.
fn shader(ctx: &Context, fma: bool) -> Shader<'_> {
    let units = (0..MAX_TEXTURE_UNITS)
        .filter_map(|u| Some((ctx.textures.unit_plan(u)?, ctx.state.current.texcoord[u])))
        .collect();
    let fog = ctx
        .state
        .caps
        .get(Cap::Fog)
        .then(|| FogPlan::new(&ctx.light.fog, fma));
    Shader::new(units, fog)
}

/// Runs the fragments of `q` into the draw buffer with the current per-fragment state.
fn run(ctx: &mut Context, q: &Quad, src: Source<'_>) {
    let fma = cpu_has_fma();
    let Some(region) = ctx.draw_region() else {
        return;
    };
    let Some(fbr) = ctx.fb.as_ref() else { return };
    let mut plan =
        crate::context::draw::frag_plan(&ctx.state, fbr.depth_format, !fbr.stencil.is_empty(), fma);
    plan.count_samples = ctx.queries.active.is_some();
    ctx.dirty = true;
    ctx.fbo.drawn = true;
    ctx.stats.draws += 1;
    let stencil_mask = (ctx.state.frag.stencil_front.writemask & 0xFF) as u8;
    let stats = &mut ctx.stats;
    let Some(fb) = ctx.fb.as_mut() else { return };
    let t = px::Target {
        fb,
        plan: &plan,
        region,
        stencil_mask,
        fma,
        stats,
        c8: &mut ctx.pixel_scratch.c8,
    };
    px::run(t, q, src);
}

/// The raster position rounded as Mesa's glDrawPixels/glCopyPixels round it (`lroundf`).
fn raster_xy(ctx: &Context) -> (i32, i32) {
    let p = ctx.raster_pos.pos;
    (p[0].round() as i32, p[1].round() as i32)
}

fn quad(ctx: &Context, x: i32, y: i32, w: usize, h: usize, flip_t: bool) -> Quad {
    Quad {
        x,
        y,
        w,
        h,
        zoom: ctx.pixel_modes.zoom,
        z: ctx.raster_pos.pos[2],
        flip_t,
    }
}

/// Colour texels through the pixel transfer (when `transfer`) and the fragment shader
/// ([`px::shade_colors`]).
fn shade_colors(
    ctx: &Context,
    texels: &[[f32; 4]],
    w: usize,
    transfer: bool,
    out: &mut Vec<[f32; 4]>,
) {
    let sh = shader(ctx, cpu_has_fma());
    let t = &ctx.pixel_modes.transfer;
    let sb = |c| t.apply_scale_bias(c);
    let map = |c| ctx.pixel_maps.map_rg_texture(c);
    let sb: Option<&dyn Fn([f32; 4]) -> [f32; 4]> = (transfer && t.scale_bias()).then_some(&sb);
    let map: Option<&dyn Fn([f32; 4]) -> [f32; 2]> = (transfer && t.map_color).then_some(&map);
    px::shade_colors(&sh, texels, w, sb, map, out)
}

/// Runs the colours of `texels` (`w` wide; see [`shade_colors`]) over the quad `q`, in
/// the context's reused buffers.
fn run_colors(ctx: &mut Context, q: &Quad, texels: &[[f32; 4]], w: usize, transfer: bool) {
    let mut c = std::mem::take(&mut ctx.pixel_scratch.colors);
    shade_colors(ctx, texels, w, transfer, &mut c);
    run(ctx, q, Source::Color(&c));
    ctx.pixel_scratch.colors = c;
    ctx.pixel_scratch.trim();
}

/// Outside render mode a pixel rectangle draws nothing: feedback mode writes `token`
/// and the raster position as a vertex (Mesa's `drawpix.c`). Returns whether the mode
/// is not GL_RENDER.
fn feedback_token(ctx: &mut Context, token: u32) -> bool {
    if ctx.feedback.mode == RenderMode::Render {
        return false;
    }
    let r = &ctx.raster_pos;
    let v = FeedbackVertex {
        win: r.pos,
        color: r.color,
        texcoord: r.texcoords[0],
    };
    ctx.feedback.raster_token(token, &v);
    true
}

/// glDrawPixels of a decoded image at the current raster position (validated by the
/// caller; an invalid raster position draws nothing).
pub fn draw_pixels(ctx: &mut Context, img: &Image) {
    bitmap_cache::flush(ctx);
    if !ctx.raster_pos.valid || feedback_token(ctx, GL_DRAW_PIXEL_TOKEN) {
        return;
    }
    if img.w == 0 || img.h == 0 {
        return;
    }
    let (x, y) = raster_xy(ctx);
    let q = quad(ctx, x, y, img.w, img.h, false);
    let tr = ctx.pixel_modes.transfer;
    match &img.pixels {
        Pixels::Color(texels) => run_colors(ctx, &q, texels, img.w, true),
        Pixels::Index(ix) => {
            let texels: Vec<[f32; 4]> = ix.iter().map(|&i| index_to_rgba(ctx, i)).collect();
            run_colors(ctx, &q, &texels, img.w, false);
        }
        Pixels::Depth(z) => {
            let z: Vec<f32> = z.iter().map(|&v| tr.apply_depth(v)).collect();
            run(ctx, &q, Source::Depth(&z, ctx.raster_pos.color));
        }
        Pixels::Stencil(s) => {
            // Measured: llvmpipe (stencil export) stores the image into a stencil texture
            // as is (`st_cb_drawpixels.c`, `make_texture`, with the transfer state cleared),
            // so neither GL_INDEX_SHIFT/OFFSET nor GL_MAP_STENCIL applies.
            let s: Vec<u8> = s.iter().map(|&v| v as u8).collect();
            run(ctx, &q, Source::Stencil(&s));
        }
    }
}

/// A colour index of an image as RGBA (glDrawPixels, and glTexImage of GL_COLOR_INDEX
/// data): GL_INDEX_SHIFT and GL_INDEX_OFFSET, then the GL_PIXEL_MAP_I_TO_R/G/B/A maps
/// (indexed modulo their size, as Mesa's `_mesa_map_ci_to_rgba`), whatever GL_MAP_COLOR
/// says; no RGBA scale, bias or maps follow.
pub fn index_to_rgba(ctx: &Context, i: i64) -> [f32; 4] {
    let i = shift_offset(&ctx.pixel_modes.transfer, i);
    std::array::from_fn(|ch| {
        let m = &ctx.pixel_maps.maps[2 + ch];
        m[(i as usize) & (m.len() - 1)]
    })
}

fn shift_offset(t: &PixelTransfer, i: i64) -> i64 {
    let s = if t.index_shift >= 0 {
        i << t.index_shift.min(31)
    } else {
        i >> (-t.index_shift).min(31)
    };
    s + t.index_offset as i64
}

/// glBitmap: draws the set bits of a `w` x `h` mask (row 0 at the bottom) at the raster
/// position minus the origin (through Mesa's bitmap cache), then moves the raster
/// position. Nothing happens with an invalid raster position.
pub fn bitmap(ctx: &mut Context, w: usize, h: usize, orig: [f32; 2], mv: [f32; 2], bits: &[bool]) {
    if !ctx.raster_pos.valid {
        return;
    }
    if feedback_token(ctx, GL_BITMAP_TOKEN) {
    } else if w > 0 && h > 0 && bits.len() >= w * h {
        let p = ctx.raster_pos.pos;
        let x = (p[0] + 0.0001 - orig[0]).floor() as i32;
        let y = (p[1] + 0.0001 - orig[1]).floor() as i32;
        // Replayed from a display list, Mesa draws the cache, then the bitmap at once.
        let from_list = ctx.lists.depth > 0;
        if from_list {
            bitmap_cache::flush(ctx);
        }
        bitmap_cache::snapshot(ctx);
        if from_list || !bitmap_cache::accumulate(ctx, x, y, w, h, bits) {
            let (z, color) = (p[2], ctx.raster_pos.color);
            draw_mask(ctx, [x, y], w, h, z, color, bits);
        }
    }
    ctx.raster_pos.pos[0] += mv[0];
    ctx.raster_pos.pos[1] += mv[1];
}

/// Draws the set texels of a `w` x `h` mask at window position `pos` with depth `z` and
/// primary colour `color` (a glBitmap quad).
pub fn draw_mask(
    ctx: &mut Context,
    pos: [i32; 2],
    w: usize,
    h: usize,
    z: f32,
    color: [f32; 4],
    bits: &[bool],
) {
    let c = shader(ctx, cpu_has_fma()).shade(color);
    let q = Quad {
        x: pos[0],
        y: pos[1],
        w,
        h,
        zoom: [1.0, 1.0],
        z,
        flip_t: false,
    };
    // Into a multisample object every sample plane gets the bitmap (llvmpipe's
    // pixel-aligned quad covers every sample of the pixels it covers).
    ctx.for_each_sample(|ctx, _| run(ctx, &q, Source::Mask(bits, c)));
}

/// Whether the per-fragment state lets glCopyPixels of colour be a blit.
fn plain_fragment_state(ctx: &Context) -> bool {
    let st = &ctx.state;
    let fr = &st.frag;
    let t = &ctx.pixel_modes.transfer;
    !t.scale_bias()
        && !t.map_color
        && !st.caps.get(Cap::Blend)
        && !st.caps.get(Cap::AlphaTest)
        && (!st.caps.get(Cap::ColorLogicOp) || fr.logic_op == crate::pipe::LogicOp::Copy)
        && (!st.caps.get(Cap::DepthTest)
            || (st.depth_func == CompareFunc::Always && !st.depth_mask))
        && !st.caps.get(Cap::Fog)
        && (!st.caps.get(Cap::StencilTest)
            || [
                fr.stencil_front.fail,
                fr.stencil_front.zfail,
                fr.stencil_front.zpass,
            ]
            .iter()
            .all(|&o| o == crate::pipe::StencilOp::Keep))
}

/// glCopyPixels of the `w` x `h` rectangle at (sx, sy) (GL window coordinates) to the
/// raster position (validated by the caller).
pub fn copy_pixels(ctx: &mut Context, sx: i32, sy: i32, w: usize, h: usize, kind: CopyKind) {
    bitmap_cache::flush(ctx);
    if !ctx.raster_pos.valid || feedback_token(ctx, GL_COPY_PIXEL_TOKEN) {
        return;
    }
    if w == 0 || h == 0 {
        return;
    }
    if kind == CopyKind::DepthStencil {
        // llvmpipe draws one quad exporting depth and stencil (its Z24S8 buffer cannot
        // be blitted to), with the depth-stencil-alpha state replaced: stencil ALWAYS /
        // REPLACE under the write mask, depth ALWAYS under glDepthMask, no alpha test, no
        // colour written. That is the stencil copy (which writes just so), then a depth
        // copy under that state.
        copy_pixels(ctx, sx, sy, w, h, CopyKind::Stencil);
        let saved = ctx.state.clone();
        ctx.state.caps.set(Cap::DepthTest, true);
        ctx.state.depth_func = CompareFunc::Always;
        ctx.state.caps.set(Cap::StencilTest, false);
        ctx.state.caps.set(Cap::AlphaTest, false);
        ctx.state.color_mask = [false; 4];
        copy_pixels(ctx, sx, sy, w, h, CopyKind::Depth);
        ctx.state = saved;
        return;
    }
    let Some(fb) = ctx.fb.as_ref() else { return };
    let src = CopySource {
        x: sx,
        y: sy,
        w,
        h,
        fw: fb.width as i64,
        fh: fb.height as i64,
        y_flip: fb.y_flip,
    };
    let (dx, dy) = raster_xy(ctx);
    let zoom1 = ctx.pixel_modes.zoom == [1.0, 1.0];
    // The blit needs a renderable source: never for depth/stencil (Z24S8).
    let blit = zoom1
        && kind == CopyKind::Color
        && plain_fragment_state(ctx)
        && ctx.queries.active.is_none()
        && !src.overlaps(dx, dy);
    if blit {
        let Some(region) = ctx.draw_region() else {
            return;
        };
        let Some(fb) = ctx.fb.as_mut() else { return };
        ctx.dirty = true;
        ctx.fbo.drawn = true;
        src.blit(fb, dx, dy, region, kind);
        return;
    }
    let q = quad(ctx, dx, dy, w, h, true);
    match kind {
        CopyKind::Color => {
            let texels = src.colors(fb);
            run_colors(ctx, &q, &texels, w, true);
        }
        CopyKind::Depth => {
            let z = src.depths(fb);
            run(ctx, &q, Source::Depth(&z, ctx.state.current.color));
        }
        CopyKind::Stencil | CopyKind::DepthStencil => {
            let s = src.stencils(fb);
            run(ctx, &q, Source::Stencil(&s));
        }
    }
}
