//! Mesa's bitmap cache (`st_cb_bitmap.c`): glBitmap calls of at most 512x32 pixels are
//! collected into one 512x32 mask and drawn together later, which is visible in the
//! pixels.
//!
//! - The cache starts at the first bitmap: its x, its y minus `(32 − h) / 2`, the raster z,
//!   the raster colour, the fragment-shader key (fog and texture enables) and the scissor
//!   enable. A later bitmap that falls outside the 512x32 window, or changes any of those
//!   (z by more than 1e-6), draws the cache first.
//! - The cache is drawn when something renders or reads (a draw, glClear, glDrawPixels,
//!   glCopyPixels, glReadPixels, glScissor, glFlush/glFinish) or a bitmap does not fit,
//!   with the per-fragment state of the last glBitmap call (Mesa validates state at each
//!   glBitmap and draws the cache before validating anything else): a
//!   glDisable(GL_BLEND) after a glBitmap does not change how it is drawn, but one before
//!   a later, non-fitting glBitmap does. glBitmap replayed from a display list draws the
//!   cache first and then itself at once.
//! - Overlapping bitmaps in one cache light each pixel once (the mask is a union).
//! - Bitmaps larger than the window are drawn at once, without drawing the cache first.

use super::draw_mask;
use crate::context::state::{Cap, State};
use crate::context::Context;
use crate::pipe::MAX_TEXTURE_UNITS;

/// Cache width.
pub const CACHE_W: usize = 512;
/// Cache height.
pub const CACHE_H: usize = 32;

/// The cache and the state it will be drawn with.
#[derive(Clone, Debug, Default)]
pub struct BitmapCache {
    /// Bitmaps not drawn yet.
    pub pending: Option<Pending>,
    /// The state of the last glBitmap call.
    pub state: Option<Box<State>>,
}

/// The pending bitmaps.
#[derive(Clone, Debug, PartialEq)]
pub struct Pending {
    /// Window position of the cache's lower-left corner.
    pub pos: [i32; 2],
    /// Raster z.
    pub z: f32,
    /// Raster colour.
    pub color: [f32; 4],
    /// Fragment-shader key.
    pub key: u32,
    /// Scissor enable.
    pub scissor: bool,
    /// CACHE_W x CACHE_H mask, row 0 at the bottom.
    pub mask: Vec<bool>,
}

/// What selects Mesa's fixed-function fragment program (a change flushes the cache).
fn shader_key(ctx: &Context) -> u32 {
    let mut k = 0u32;
    for u in 0..MAX_TEXTURE_UNITS {
        if ctx.textures.unit_plan(u).is_some() {
            k |= 1 << u;
        }
    }
    if ctx.state.caps.get(Cap::Fog) {
        k |= 1 << 16 | (ctx.light.fog.mode as u32) << 17;
    }
    k
}

/// Draws the pending bitmaps, if any.
pub fn flush(ctx: &mut Context) {
    let Some(c) = ctx.bitmap_cache.pending.take() else {
        return;
    };
    // No draw is left on the pool while bitmaps are pending (glBitmap waits for it, and a
    // draw with bitmaps pending leaves nothing there); waiting here keeps it so.
    ctx.settle_draws();
    let mut st = match &ctx.bitmap_cache.state {
        Some(s) => (**s).clone(),
        None => ctx.state.clone(),
    };
    st.caps.set(Cap::ScissorTest, c.scissor);
    std::mem::swap(&mut ctx.state, &mut st);
    draw_mask(ctx, c.pos, CACHE_W, CACHE_H, c.z, c.color, &c.mask);
    std::mem::swap(&mut ctx.state, &mut st);
}

/// Records the state of a glBitmap call (after any cache flush a replayed bitmap needs).
pub fn snapshot(ctx: &mut Context) {
    ctx.bitmap_cache.state = Some(Box::new(ctx.state.clone()));
}

/// Adds a `w` x `h` bitmap at window position (x, y); false when it is too large to cache.
pub fn accumulate(ctx: &mut Context, x: i32, y: i32, w: usize, h: usize, bits: &[bool]) -> bool {
    if w > CACHE_W || h > CACHE_H {
        return false;
    }
    let z = ctx.raster_pos.pos[2];
    let color = ctx.raster_pos.color;
    let key = shader_key(ctx);
    let scissor = ctx.state.caps.get(Cap::ScissorTest);
    if let Some(c) = &ctx.bitmap_cache.pending {
        let (px, py) = (x as i64 - c.pos[0] as i64, y as i64 - c.pos[1] as i64);
        if px < 0
            || px + w as i64 > CACHE_W as i64
            || py < 0
            || py + h as i64 > CACHE_H as i64
            || c.color != color
            || c.key != key
            || c.scissor != scissor
            || (z - c.z).abs() > 1e-6
        {
            flush(ctx);
        }
    }
    let c = ctx.bitmap_cache.pending.get_or_insert_with(|| Pending {
        pos: [x, y - ((CACHE_H - h) / 2) as i32],
        z,
        color,
        key,
        scissor,
        mask: vec![false; CACHE_W * CACHE_H],
    });
    let (px, py) = ((x - c.pos[0]) as usize, (y - c.pos[1]) as usize);
    for j in 0..h {
        for i in 0..w {
            if bits[j * w + i] {
                c.mask[(py + j) * CACHE_W + px + i] = true;
            }
        }
    }
    true
}
