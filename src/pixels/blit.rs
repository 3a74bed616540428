//! glBlitFramebuffer: copies a rectangle of the read framebuffer into a rectangle of the
//! draw framebuffer, scaled and flipped as the two rectangles say, through the scissor
//! and nothing else of the fragment pipeline.
//!
//! # Arithmetic
//! Each destination pixel centre maps back into the source rectangle:
//! `u = sx0 + (x + 0.5 − dx0) · (sx1 − sx0) / (dx1 − dx0)` (the same for y), in f32.
//! GL_NEAREST takes texel `floor(u)`; GL_LINEAR interpolates the four texels around
//! `u − 0.5`, clamped to the source buffer's edge, and rounds to nearest. Destination pixels
//! whose source texel falls outside the read buffer are left alone (GL 3.0 §4.3.2 leaves
//! them undefined). Depth and stencil are copied as stored values (the formats must match).

use crate::context::{Context, GlError, GlResult};
use crate::framebuffer::Framebuffer;

/// Which buffers a blit copies.
#[derive(Clone, Copy, Debug, Default)]
pub struct BlitMask {
    /// GL_COLOR_BUFFER_BIT.
    pub color: bool,
    /// GL_DEPTH_BUFFER_BIT.
    pub depth: bool,
    /// GL_STENCIL_BUFFER_BIT.
    pub stencil: bool,
}

/// One axis of a blit: the destination range and the map back into the source.
struct Axis {
    /// First and last-plus-one destination pixel (after clipping to the buffer).
    lo: i64,
    hi: i64,
    /// `src = s0 + (d + 0.5 − d0) · scale`.
    s0: f32,
    d0: f32,
    scale: f32,
}

impl Axis {
    fn new(s0: i32, s1: i32, d0: i32, d1: i32, limit: (i64, i64)) -> Option<Axis> {
        if d0 == d1 || s0 == s1 {
            return None;
        }
        let lo = (d0.min(d1) as i64).max(limit.0);
        let hi = (d0.max(d1) as i64).min(limit.1);
        (lo < hi).then(|| Axis {
            lo,
            hi,
            s0: s0 as f32,
            d0: d0 as f32,
            scale: (s1 as f32 - s0 as f32) / (d1 as f32 - d0 as f32),
        })
    }

    /// The source coordinate of destination pixel `d`'s centre.
    #[inline]
    fn src(&self, d: i64) -> f32 {
        self.s0 + (d as f32 + 0.5 - self.d0) * self.scale
    }
}

/// glBlitFramebuffer after argument checks: `src`/`dst` are (x0, y0, x1, y1) in GL window
/// coordinates (y up).
pub fn blit(
    ctx: &mut Context,
    src: [i32; 4],
    dst: [i32; 4],
    mask: BlitMask,
    linear: bool,
) -> GlResult<()> {
    ctx.check_draw_framebuffer()?;
    ctx.check_read_framebuffer()?;
    // Reading and drawing one buffer: read a snapshot.
    let mut sfb = match ctx.read_framebuffer_copy() {
        Some(f) => f,
        None => match ctx.fb.as_ref() {
            Some(f) => f.clone(),
            None => return Ok(()),
        },
    };
    sfb.resolve();
    let Some(dfb) = ctx.fb.as_ref() else {
        return Ok(());
    };
    if mask.depth && (sfb.depth.is_empty() || dfb.depth.is_empty()) {
        return Ok(());
    }
    if mask.depth && sfb.depth_format != dfb.depth_format {
        return Err(GlError::InvalidOperation);
    }
    // The destination rectangle, clipped to the buffer and the scissor (y-down rows).
    let Some(region) = ctx.draw_region() else {
        return Ok(());
    };
    let (dw, dh) = (dfb.width as i64, dfb.height as i64);
    let gl_rows = if dfb.y_flip {
        (dh - region[3], dh - region[1])
    } else {
        (region[1], region[3])
    };
    let d_flip = dfb.y_flip;
    let (Some(ax), Some(ay)) = (
        Axis::new(src[0], src[2], dst[0], dst[2], (region[0], region[2])),
        Axis::new(src[1], src[3], dst[1], dst[3], gl_rows),
    ) else {
        return Ok(());
    };
    let (sw, sh) = (sfb.width as i64, sfb.height as i64);
    let Some(dfb) = ctx.fb.as_mut() else {
        return Ok(());
    };
    dfb.resolve();
    dfb.uniform_color = None;
    ctx.dirty = true;
    let s_flip = sfb.y_flip;
    let s_index = |x: i64, y: i64| (if s_flip { sh - 1 - y } else { y } * sw + x) as usize;
    for y in ay.lo..ay.hi {
        let v = ay.src(y);
        let drow = (if d_flip { dh - 1 - y } else { y } * dw) as usize;
        for x in ax.lo..ax.hi {
            let u = ax.src(x);
            let d = drow + x as usize;
            if mask.color {
                let c = if linear {
                    Some(bilinear(&sfb, u, v))
                } else {
                    texel(u, v, sw, sh).map(|(sx, sy)| sfb.color[s_index(sx, sy)])
                };
                if let Some(c) = c {
                    dfb.color[d] = dfb.store_rgba8(c);
                }
            }
            if let Some((sx, sy)) = texel(u, v, sw, sh) {
                let s = s_index(sx, sy);
                if mask.depth {
                    dfb.depth[d] = sfb.depth[s];
                }
                if mask.stencil && !sfb.stencil.is_empty() && !dfb.stencil.is_empty() {
                    dfb.stencil[d] = sfb.stencil[s];
                }
            }
        }
    }
    Ok(())
}

/// The texel under source coordinate (u, v), or `None` outside the buffer.
#[inline]
fn texel(u: f32, v: f32, w: i64, h: i64) -> Option<(i64, i64)> {
    let (x, y) = (u.floor() as i64, v.floor() as i64);
    (x >= 0 && y >= 0 && x < w && y < h).then_some((x, y))
}

/// The bilinear filter of the colour texels around (u, v), clamped to the buffer's edge.
fn bilinear(fb: &Framebuffer, u: f32, v: f32) -> [u8; 4] {
    let (w, h) = (fb.width as i64, fb.height as i64);
    let (u, v) = (u - 0.5, v - 0.5);
    let (x0, y0) = (u.floor(), v.floor());
    let (fx, fy) = (u - x0, v - y0);
    let at = |x: i64, y: i64| {
        let (x, y) = (x.clamp(0, w - 1), y.clamp(0, h - 1));
        fb.color[fb.row(y as usize) * w as usize + x as usize]
    };
    let (x0, y0) = (x0 as i64, y0 as i64);
    let (a, b, c, d) = (
        at(x0, y0),
        at(x0 + 1, y0),
        at(x0, y0 + 1),
        at(x0 + 1, y0 + 1),
    );
    std::array::from_fn(|i| {
        let top = a[i] as f32 + (b[i] as f32 - a[i] as f32) * fx;
        let bot = c[i] as f32 + (d[i] as f32 - c[i] as f32) * fx;
        (top + (bot - top) * fy).round().clamp(0.0, 255.0) as u8
    })
}
