//! glDrawPixels, glCopyPixels and glBitmap as Mesa's state tracker runs them on llvmpipe
//! (`st_cb_drawpixels.c`, `st_cb_bitmap.c`): a textured quad ([`super::rect`]) whose
//! fragments go through the per-fragment operations.
//!
//! Rules measured on Mesa 22.3 (OSMesa, llvmpipe):
//! - Colour fragments run the fixed-function fragment shader with the image texel (or, for
//!   bitmaps, the raster colour) as the primary colour. Enabled texture units sample at the
//!   *current* texture coordinates (glTexCoord, not the raster position's, without the
//!   texture matrix), and fog uses a fog coordinate of 0.
//! - Pixel transfer (scale, bias, colour maps) is applied to colour texels in that shader;
//!   depth scale and bias when the depth image is stored. Stencil images take no
//!   transfer operation (the image is stored in a stencil texture as is); glReadPixels
//!   applies GL_INDEX_SHIFT/OFFSET and GL_MAP_STENCIL.
//! - Depth images write the raster colour (glCopyPixels: the current colour) with the image
//!   depth, through the usual tests; stencil images replace the stencil value through the
//!   stencil write mask with every other test off and no colour written.
//! - glCopyPixels of colour with zoom 1, no overlap, no transfer operations and plain
//!   fragment state is a blit: it ignores the colour mask. Depth and stencil copies
//!   always draw the quad (Mesa's blit cannot render to Z24S8).

use super::image::{Image, Pixels};
use super::rect::{rasterize, Dest, Fragments, Quad};
use crate::context::state::Cap;
use crate::context::Context;
use crate::fixed_function::fog::FogPlan;
use crate::fragment::span::unorm8;
use crate::geometry::cpu_has_fma;
use crate::pipe::{CompareFunc, MAX_TEXTURE_UNITS};
use crate::texture::UnitPlan;

/// The fixed-function colour computation of pixel-rectangle fragments.
struct Shader<'a> {
    units: Vec<(UnitPlan<'a>, [f32; 4])>,
    fog: Option<FogPlan>,
}

impl<'a> Shader<'a> {
    fn new(ctx: &'a Context, fma: bool) -> Self {
        let units = (0..MAX_TEXTURE_UNITS)
            .filter_map(|u| {
                let p = ctx.textures.unit_plan(u)?;
                let tc = ctx.state.current.texcoord[u];
                let r = 1.0f32 / tc[3];
                let (s, t) = (tc[0] * r, tc[1] * r);
                let lod = p.quad_lod([s; 4], [t; 4]);
                let texel = p.sample_one(s, t, lod);
                Some((p, texel))
            })
            .collect();
        let fog = ctx
            .state
            .caps
            .get(Cap::Fog)
            .then(|| FogPlan::new(&ctx.light.fog, fma));
        Shader { units, fog }
    }

    fn shade(&self, primary: [f32; 4]) -> [u8; 4] {
        let mut prev = primary;
        for (u, tex) in &self.units {
            prev = u.env(primary, *tex, prev);
        }
        if let Some(f) = &self.fog {
            prev = f.apply(prev, f.factor(0.0));
        }
        prev.map(unorm8)
    }
}

/// What the fragments of a rectangle carry.
enum Source<'a> {
    /// Final colours per texel.
    Color(&'a [[u8; 4]]),
    /// One colour; only texels that are set draw.
    Mask(&'a [bool], [u8; 4]),
    /// Depth per texel, one colour.
    Depth(&'a [f32], [u8; 4]),
    /// Stencil values per texel.
    Stencil(&'a [u8]),
}

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
    fb.uniform_color = None;
    let d = Dest {
        fb_w: fb.width,
        fb_h: fb.height,
        region,
        fma,
        y_flip: fb.y_flip,
    };
    let w = q.w;
    if let Source::Stencil(vals) = src {
        let fw = fb.width;
        if fb.stencil.is_empty() {
            return;
        }
        rasterize(q, &d, |_, px, py, col, row| {
            let s = &mut fb.stencil[py * fw + px];
            *s = (*s & !stencil_mask) | (vals[row * w + col] & stencil_mask);
        });
        return;
    }
    let mut frags = Fragments {
        plan: &plan,
        target: fb.target(),
        stats,
    };
    match src {
        Source::Color(c) => rasterize(q, &d, |t, px, py, col, row| {
            frags.put(t, px, py, c[row * w + col], None)
        }),
        Source::Mask(m, c) => rasterize(q, &d, |t, px, py, col, row| {
            if m[row * w + col] {
                frags.put(t, px, py, c, None)
            }
        }),
        Source::Depth(z, c) => rasterize(q, &d, |t, px, py, col, row| {
            frags.put(t, px, py, c, Some(z[row * w + col]))
        }),
        Source::Stencil(_) => {}
    }
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

/// Colour texels (`w` wide, in the temporary texture's row order) through the
/// pixel-transfer operations and the fragment shader.
///
/// GL_MAP_COLOR as Mesa 22.3 runs it (`nir_lower_drawpixels.c`): red and green are looked
/// up in the pixel-map texture, but the second lookup, meant for blue and alpha, carries no
/// texture source and so samples texture 0, the image itself: blue and alpha become the
/// red and green of the image texel at (b, a), NEAREST with CLAMP_TO_EDGE.
fn shade_colors(ctx: &Context, texels: &[[f32; 4]], w: usize, transfer: bool) -> Vec<[u8; 4]> {
    let sh = Shader::new(ctx, cpu_has_fma());
    let t = &ctx.pixel_modes.transfer;
    let (sb, map) = (transfer && t.scale_bias(), transfer && t.map_color);
    let h = texels.len() / w.max(1);
    let nearest = |c: f32, n: usize| {
        (c.clamp(-1.0, 2.0) * n as f32)
            .floor()
            .clamp(0.0, (n - 1) as f32) as usize
    };
    texels
        .iter()
        .map(|&c| {
            let mut c = c;
            if sb {
                c = t.apply_scale_bias(c);
            }
            if map {
                let [r, g] = ctx.pixel_maps.map_rg_texture(c);
                let texel = texels[nearest(c[3], h) * w + nearest(c[2], w)];
                c = [r, g, texel[0], texel[1]];
            }
            sh.shade(c)
        })
        .collect()
}

/// Outside render mode a pixel rectangle draws nothing: feedback mode writes `token`
/// and the raster position as a vertex (Mesa's `drawpix.c`). Returns whether the mode
/// is not GL_RENDER.
fn feedback_token(ctx: &mut Context, token: u32) -> bool {
    use crate::context::feedback::{FeedbackVertex, RenderMode};
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
    super::cache::flush(ctx);
    if !ctx.raster_pos.valid || feedback_token(ctx, crate::gl::enums::GL_DRAW_PIXEL_TOKEN) {
        return;
    }
    if img.w == 0 || img.h == 0 {
        return;
    }
    let (x, y) = raster_xy(ctx);
    let q = quad(ctx, x, y, img.w, img.h, false);
    let tr = ctx.pixel_modes.transfer;
    match &img.pixels {
        Pixels::Color(texels) => {
            let c = shade_colors(ctx, texels, img.w, true);
            run(ctx, &q, Source::Color(&c));
        }
        Pixels::Index(ix) => {
            let texels: Vec<[f32; 4]> = ix.iter().map(|&i| index_to_rgba(ctx, i)).collect();
            let c = shade_colors(ctx, &texels, img.w, false);
            run(ctx, &q, Source::Color(&c));
        }
        Pixels::Depth(z) => {
            let z: Vec<f32> = z.iter().map(|&v| tr.apply_depth(v)).collect();
            let c = ctx.raster_pos.color.map(unorm8);
            run(ctx, &q, Source::Depth(&z, c));
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
pub(crate) fn index_to_rgba(ctx: &Context, i: i64) -> [f32; 4] {
    let i = shift_offset(&ctx.pixel_modes.transfer, i);
    std::array::from_fn(|ch| {
        let m = &ctx.pixel_maps.maps[2 + ch];
        m[(i as usize) & (m.len() - 1)]
    })
}

fn shift_offset(t: &crate::context::pixel_transfer::PixelTransfer, i: i64) -> i64 {
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
    if feedback_token(ctx, crate::gl::enums::GL_BITMAP_TOKEN) {
    } else if w > 0 && h > 0 && bits.len() >= w * h {
        let p = ctx.raster_pos.pos;
        let x = (p[0] + 0.0001 - orig[0]).floor() as i32;
        let y = (p[1] + 0.0001 - orig[1]).floor() as i32;
        // Replayed from a display list, Mesa draws the cache, then the bitmap at once.
        let from_list = ctx.lists.depth > 0;
        if from_list {
            super::cache::flush(ctx);
        }
        super::cache::snapshot(ctx);
        if from_list || !super::cache::accumulate(ctx, x, y, w, h, bits) {
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
    let c = Shader::new(ctx, cpu_has_fma()).shade(color);
    let q = Quad {
        x: pos[0],
        y: pos[1],
        w,
        h,
        zoom: [1.0, 1.0],
        z,
        flip_t: false,
    };
    run(ctx, &q, Source::Mask(bits, c));
}

/// What glCopyPixels copies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CopyKind {
    /// GL_COLOR
    Color,
    /// GL_DEPTH
    Depth,
    /// GL_STENCIL
    Stencil,
    /// GL_DEPTH_STENCIL (EXT_packed_depth_stencil): stencil, then depth.
    DepthStencil,
}

/// glCopyPixels of the `w` x `h` rectangle at (sx, sy) (GL window coordinates) to the
/// raster position (validated by the caller).
pub fn copy_pixels(ctx: &mut Context, sx: i32, sy: i32, w: usize, h: usize, kind: CopyKind) {
    super::cache::flush(ctx);
    if !ctx.raster_pos.valid || feedback_token(ctx, crate::gl::enums::GL_COPY_PIXEL_TOKEN) {
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
    let (fw, fh) = (fb.width as i64, fb.height as i64);
    let y_flip = fb.y_flip;
    let row = move |y: i64| if y_flip { fh - 1 - y } else { y };
    let (dx, dy) = raster_xy(ctx);
    // Source texels, bottom row first; pixels outside the buffer read as zero.
    let src_index = |i: usize, j: usize| -> Option<usize> {
        let (x, y) = (sx as i64 + i as i64, sy as i64 + j as i64);
        (x >= 0 && y >= 0 && x < fw && y < fh).then(|| (row(y) * fw + x) as usize)
    };
    let st = &ctx.state;
    let fr = &st.frag;
    let zoom1 = ctx.pixel_modes.zoom == [1.0, 1.0];
    let t = &ctx.pixel_modes.transfer;
    let simple = !t.scale_bias()
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
            .all(|&o| o == crate::pipe::StencilOp::Keep));
    let overlap = {
        let (ax0, ay0, ax1, ay1) = (
            sx as i64,
            sy as i64,
            sx as i64 + w as i64,
            sy as i64 + h as i64,
        );
        let (bx0, by0, bx1, by1) = (
            dx as i64,
            dy as i64,
            dx as i64 + w as i64,
            dy as i64 + h as i64,
        );
        ax0 < bx1 && bx0 < ax1 && ay0 < by1 && by0 < ay1
    };
    // The blit needs a renderable source: never for depth/stencil (Z24S8).
    let blit =
        zoom1 && kind == CopyKind::Color && simple && ctx.queries.active.is_none() && !overlap;
    if blit {
        let Some(region) = ctx.draw_region() else {
            return;
        };
        let Some(fb) = ctx.fb.as_mut() else { return };
        ctx.dirty = true;
        ctx.fbo.drawn = true;
        fb.resolve();
        fb.uniform_color = None;
        for j in 0..h {
            for i in 0..w {
                let Some(s) = src_index(i, j) else { continue };
                let gy = dy as i64 + j as i64;
                let yd = row(gy);
                let x = dx as i64 + i as i64;
                if x < region[0] || x >= region[2] || yd < region[1] || yd >= region[3] {
                    continue;
                }
                let d = (yd * fw + x) as usize;
                match kind {
                    CopyKind::Color => fb.color[d] = fb.color[s],
                    CopyKind::Depth => fb.depth[d] = fb.depth[s],
                    CopyKind::Stencil | CopyKind::DepthStencil => fb.stencil[d] = fb.stencil[s],
                }
            }
        }
        return;
    }
    // Mesa's temporary texture is y-down (top source row first) and sampled with t flipped.
    let q = quad(ctx, dx, dy, w, h, true);
    let src_index = |i: usize, j: usize| src_index(i, h - 1 - j);
    match kind {
        CopyKind::Color => {
            let texels: Vec<[f32; 4]> = (0..w * h)
                .map(|k| {
                    src_index(k % w, k / w).map_or([0.0; 4], |s| {
                        fb.color_at(s).map(|v| v as f32 * (1.0 / 255.0))
                    })
                })
                .collect();
            let c = shade_colors(ctx, &texels, w, true);
            run(ctx, &q, Source::Color(&c));
        }
        CopyKind::Depth => {
            let f = fb.depth_format;
            let z: Vec<f32> = (0..w * h)
                .map(|k| src_index(k % w, k / w).map_or(0.0, |s| f.sample_float(fb.depth_at(s))))
                .collect();
            let c = ctx.state.current.color.map(unorm8);
            run(ctx, &q, Source::Depth(&z, c));
        }
        CopyKind::Stencil | CopyKind::DepthStencil => {
            let s: Vec<u8> = (0..w * h)
                .map(|k| src_index(k % w, k / w).map_or(0, |s| fb.stencil[s]))
                .collect();
            run(ctx, &q, Source::Stencil(&s));
        }
    }
}
