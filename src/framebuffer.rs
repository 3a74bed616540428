//! The framebuffer: colour (8-bit RGBA per pixel), depth (16, 24 or 32-bit unorm, or
//! 32-bit float) and stencil, on huge pages when large ([`HugeBuf`]); in y-down rows as
//! llvmpipe keeps OSMesa's window buffer, or in GL's rows for a framebuffer object's
//! working copy ([`Framebuffer::y_flip`]). It also owns the deferred full-buffer clears
//! (values recorded by glClear, written by the bands a draw reaches or when something
//! reads), the row and band views the rasterizer draws through ([`Target`]), and the copy
//! into the user's OSMesa buffer (8-bit, 16-bit and float layouts).
//!
//! The user buffer is written only by [`Framebuffer::copy_to_user`] (glFlush/glFinish), as
//! Mesa does: a new buffer starts zeroed, colour (0,0,0,0) and depth 0.

use crate::memory::HugeBuf;

pub mod draw_buffers;
pub mod samples;
pub mod srgb;
mod user;
pub mod wide;

#[cfg(test)]
use user::stream_copy;
pub use user::WideType;
pub use wide::WideKind;

/// The colour layout of the OSMesa user buffer.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorFormat {
    /// OSMESA_RGBA: bytes R, G, B, A.
    Rgba,
    /// OSMESA_BGRA: bytes B, G, R, A.
    Bgra,
    /// OSMESA_ARGB: bytes A, R, G, B.
    Argb,
    /// OSMESA_RGB: bytes R, G, B (no alpha: alpha reads as 1).
    Rgb,
    /// OSMESA_RGB_565: native-endian u16, R in the high 5 bits (no alpha).
    Rgb565,
}

impl ColorFormat {
    /// Bytes per pixel in the user buffer.
    pub fn bytes_per_pixel(self) -> usize {
        match self {
            ColorFormat::Rgba | ColorFormat::Bgra | ColorFormat::Argb => 4,
            ColorFormat::Rgb => 3,
            ColorFormat::Rgb565 => 2,
        }
    }
    /// Bits per colour channel (r, g, b, a) for glGet(GL_RED_BITS …).
    pub fn channel_bits(self) -> [i32; 4] {
        match self {
            ColorFormat::Rgba | ColorFormat::Bgra | ColorFormat::Argb => [8, 8, 8, 8],
            ColorFormat::Rgb => [8, 8, 8, 0],
            ColorFormat::Rgb565 => [5, 6, 5, 0],
        }
    }
    /// Whether the format stores alpha.
    pub fn has_alpha(self) -> bool {
        self.channel_bits()[3] > 0
    }
}

/// The depth buffer layout OSMesa chose (docs/llvmpipe-rules.md §8).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DepthFormat {
    /// No depth buffer.
    None,
    /// 16-bit unorm.
    Z16,
    /// 24-bit unorm (Z24X8 or Z24S8).
    Z24,
    /// 32-bit unorm (GL_DEPTH_COMPONENT32: llvmpipe's Z32_UNORM). Stored values reach
    /// 0xFFFFFFFF, so the depth test compares them unsigned (the SIMD paths flip the sign
    /// bit of both sides first).
    Z32,
    /// 32-bit float (GL_DEPTH_COMPONENT32F, GL_DEPTH32F_STENCIL8: llvmpipe's Z32_FLOAT and
    /// Z32_FLOAT_S8X24_UINT). The plane holds the f32's bits: the fragment z clamped to
    /// [0, 1] (NaN and −0 become +0), so the unsigned (and signed) integer order of the
    /// stored values is the float order and the depth test compares them as integers.
    Z32F,
}

impl DepthFormat {
    /// Depth bits.
    pub fn bits(self) -> i32 {
        match self {
            DepthFormat::None => 0,
            DepthFormat::Z16 => 16,
            DepthFormat::Z24 => 24,
            DepthFormat::Z32 | DepthFormat::Z32F => 32,
        }
    }
    /// The largest stored value (1.0).
    pub fn max_value(self) -> u32 {
        match self {
            DepthFormat::None => 0,
            DepthFormat::Z16 => 0xFFFF,
            DepthFormat::Z24 => 0xFF_FFFF,
            DepthFormat::Z32 => u32::MAX,
            DepthFormat::Z32F => 1.0f32.to_bits(),
        }
    }
    /// The "bits" argument of the depth conversions in [`crate::texture::shadow`] for
    /// this format's stored values.
    pub fn texel_bits(self) -> u8 {
        match self {
            DepthFormat::Z32F => crate::texture::shadow::FLOAT_BITS,
            _ => self.bits() as u8,
        }
    }
    /// The float a stored value stands for (the depth test's and a blit's view of it).
    pub fn to_float(self, z: u32) -> f32 {
        match self {
            DepthFormat::Z32F => f32::from_bits(z),
            DepthFormat::Z32 => (z as f64 / u32::MAX as f64) as f32,
            _ => z as f32 / self.max_value() as f32,
        }
    }
    /// A stored depth as llvmpipe's texture sampler unpacks it (glCopyPixels samples a
    /// copy of the depth buffer): a unorm value times the f32 reciprocal of its maximum
    /// (`lp_build_unsigned_norm_to_float`), which can differ from [`Self::to_float`]'s
    /// correctly rounded quotient in the last bit.
    pub fn sample_float(self, z: u32) -> f32 {
        match self {
            DepthFormat::Z32F => f32::from_bits(z),
            DepthFormat::Z32 => crate::texture::shadow::sample_value(z, 32),
            _ => z as f32 * (1.0 / self.max_value() as f64) as f32,
        }
    }

    /// A fragment depth (already clamped to [0,1]) quantised as llvmpipe's shader does.
    #[inline(always)]
    pub fn quantize(self, z: f32) -> u32 {
        match self {
            DepthFormat::Z24 => (z * 16_777_215.0f32).round_ties_even() as u32,
            DepthFormat::Z32 => z32_unorm(z),
            DepthFormat::Z16 => {
                let t = z * (65535.0f32 / 65536.0f32) + 128.0f32;
                t.to_bits() & 0xFFFF
            }
            // llvmpipe clamps z to [0, 1] (`lp_build_depth_clamp`, max then min: NaN
            // and −0 give +0) and stores the float.
            DepthFormat::Z32F => {
                let z = if z > 0.0 { z } else { 0.0 };
                (if z < 1.0 { z } else { 1.0 }).to_bits()
            }
            DepthFormat::None => 0,
        }
    }
    /// A clear value quantised as gallium's `util_pack_z` (double precision, lrint; the
    /// float format stores `(float)z`).
    pub fn quantize_clear(self, z: f64) -> u32 {
        let max = self.max_value();
        if self == DepthFormat::Z32F {
            self.quantize(z as f32)
        } else if z <= 0.0 {
            0
        } else if z >= 1.0 {
            max
        } else {
            (z * max as f64).round_ties_even() as u32
        }
    }
}

/// A depth in [0, 1] as llvmpipe's shader writes it to Z32_UNORM
/// (`lp_build_clamped_float_to_unsigned_norm` at 32 bits: the exact product `r = z·2³¹`
/// truncated, then `(r << 1) − (r >> 31)`, so 1.0 gives 0xFFFFFFFF and every other value
/// is even).
#[inline(always)]
pub fn z32_unorm(z: f32) -> u32 {
    let r = (z * 2_147_483_648.0f32) as u32;
    (r << 1).wrapping_sub(r >> 31)
}

/// Colour, depth and stencil storage of one context.
#[derive(Clone, Debug)]
pub struct Framebuffer {
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// The user buffer's colour layout (decides quantisation on store).
    pub format: ColorFormat,
    /// RGBA8 colour, row 0 = top row (on huge pages when large: [`HugeBuf`]).
    pub color: HugeBuf<[u8; 4]>,
    /// Depth layout.
    pub depth_format: DepthFormat,
    /// Depth values (empty without a depth buffer), row 0 = top row.
    pub depth: HugeBuf<u32>,
    /// Stencil values (empty without a stencil buffer), row 0 = top row.
    pub stencil: HugeBuf<u8>,
    /// The value every colour pixel holds, when known: set by a full-buffer glClear and
    /// dropped by anything else that may write colour ([`Framebuffer::target`],
    /// [`Framebuffer::bands`] and the few direct writers), so that glFlush fills the user
    /// buffer instead of reading the colour buffer back.
    pub uniform_color: Option<[u8; 4]>,
    /// A full-buffer colour clear recorded by glClear but not written yet: the rows marked
    /// in [`Framebuffer::pending_rows`] have stale memory and hold this value.
    /// [`Framebuffer::resolve`], [`Framebuffer::target`] and the bands of
    /// [`Framebuffer::bands`] that a draw reaches write it.
    pub pending_color: Option<[u8; 4]>,
    /// A full-buffer depth clear recorded but not written yet (as `pending_color`).
    pub pending_depth: Option<u32>,
    /// Per row (y-down): whether the row still holds the recorded clears instead of its
    /// memory. Bands that no triangle reaches stay pending through a draw, so a frame
    /// whose sky is empty never writes the sky's depth, and glFlush fills its colour rows
    /// from the clear colour instead of copying them.
    pub pending_rows: Vec<bool>,
    /// Whether row 0 is the top row (the OSMesa window, y flipped as llvmpipe's window
    /// surfaces are) or GL's row 0 (framebuffer objects, which llvmpipe draws unflipped).
    pub y_flip: bool,
    /// The precision of a colour buffer wider than 8 bits ([`wide`]); `None` for 8-bit
    /// buffers.
    pub wide: Option<WideKind>,
    /// The wide colour plane (empty for 8-bit buffers), row-major like `color`, which
    /// then holds its 8-bit mirror ([`wide`]).
    pub wide_color: Vec<[f32; 4]>,
    /// The wide buffer is an image of one channel (red, alpha, luminance or intensity),
    /// which llvmpipe blends with its single-channel rules (`crate::fragment::wide`).
    pub wide_single: bool,
    /// Whether the colour buffer is sRGB-encoded (an sRGB attachment; [`srgb`]). Its bytes
    /// are stored like RGBA8 ones; whether a draw encodes is the plan's choice
    /// (`FragPlan::srgb`).
    pub srgb: bool,
    /// A multisample object's planes 1..4 while a one-pass multisample draw runs (empty
    /// otherwise): [`samples`].
    pub samples: Vec<Framebuffer>,
    /// The colour of draw buffers 1.. while an object with several is bound (empty
    /// otherwise): [`draw_buffers`].
    pub more_colors: Vec<HugeBuf<[u8; 4]>>,
}

impl Framebuffer {
    /// The memory row of GL window row `y` (the map is its own inverse).
    #[inline]
    pub fn row(&self, y: usize) -> usize {
        if self.y_flip {
            self.height - 1 - y
        } else {
            y
        }
    }

    /// A zero-filled framebuffer (Mesa's initial contents).
    pub fn new(
        width: usize,
        height: usize,
        format: ColorFormat,
        depth_format: DepthFormat,
        stencil: bool,
    ) -> Self {
        let n = width * height;
        Framebuffer {
            width,
            height,
            format,
            color: HugeBuf::filled(n, [0, 0, 0, if format.has_alpha() { 0 } else { 255 }]),
            depth_format,
            depth: if depth_format == DepthFormat::None {
                HugeBuf::empty()
            } else {
                HugeBuf::filled(n, 0)
            },
            stencil: if stencil {
                HugeBuf::filled(n, 0)
            } else {
                HugeBuf::empty()
            },
            uniform_color: None,
            pending_color: None,
            pending_depth: None,
            pending_rows: vec![false; height],
            y_flip: true,
            wide: None,
            wide_color: Vec::new(),
            wide_single: false,
            srgb: false,
            samples: Vec::new(),
            more_colors: Vec::new(),
        }
    }

    /// Gives the buffer a wide colour plane of `kind` (or takes it away), zero as a new
    /// buffer is (alpha 1 without alpha), and the 8-bit plane its mirror.
    pub fn set_wide(&mut self, kind: Option<WideKind>) {
        self.resolve();
        self.uniform_color = None;
        self.wide = kind;
        self.wide_color = Vec::new();
        if let Some(k) = kind {
            let a = if self.format.has_alpha() {
                0.0
            } else {
                k.one()
            };
            let v = [0.0, 0.0, 0.0, a];
            self.wide_color = vec![v; self.width * self.height];
            fill_color(&mut self.color, k.mirror(v));
        }
    }

    /// Stored wide colour of pixel `i` (y-down row-major) of a wide buffer: the wide
    /// plane's value, or the 8-bit value widened where a path that only knows 8 bits wrote
    /// the pixel last ([`wide`]).
    #[inline]
    pub fn wide_at(&self, i: usize) -> [f32; 4] {
        let k = self.wide.expect("a wide buffer");
        let c8 = self.color_at(i);
        let w = self.wide_color[i];
        if k.mirror(w) == c8 {
            w
        } else {
            k.from_u8(c8)
        }
    }

    /// Writes the stored wide colour `v` into the channels `mask` of the pixels `x0..x1`
    /// of memory rows `y0..y1` of a wide buffer (glClear), with their 8-bit mirror.
    pub fn clear_wide(&mut self, [x0, y0, x1, y1]: [usize; 4], mask: [bool; 4], v: [f32; 4]) {
        let Some(k) = self.wide else { return };
        self.resolve();
        self.uniform_color = None;
        let w = self.width;
        let alpha = self.format.has_alpha();
        if mask[..3] == [true; 3] && (mask[3] || !alpha) {
            // Every stored channel is replaced: the old values do not matter, so the rows
            // are filled with one pixel and its mirror.
            let p = [v[0], v[1], v[2], if alpha { v[3] } else { k.one() }];
            let m = k.mirror(p);
            for y in y0..y1 {
                let r = y * w + x0..y * w + x1;
                self.wide_color[r.clone()].fill(p);
                fill_color(&mut self.color[r], m);
            }
            return;
        }
        for y in y0..y1 {
            for i in y * w + x0..y * w + x1 {
                let mut p = self.wide_at(i);
                for c in 0..4 {
                    if mask[c] {
                        p[c] = v[c];
                    }
                }
                if !self.format.has_alpha() {
                    p[3] = k.one();
                }
                self.wide_color[i] = p;
                self.color[i] = k.mirror(p);
            }
        }
    }

    /// Clears the whole rows `rows` (y-down) of the colour buffer to `color` and of the
    /// depth buffer to `depth` (each when given, already in stored form): the full-width
    /// fast clear. Leaves [`Framebuffer::uniform_color`] alone (the caller knows whether
    /// the clear covers the buffer). This signature is kept stable for the threaded clear,
    /// which may instead call [`Target::clear`] per band.
    pub fn clear_rows(
        &mut self,
        rows: std::ops::Range<usize>,
        color: Option<[u8; 4]>,
        depth: Option<u32>,
    ) {
        let (w, y0, y1) = (
            self.width,
            rows.start.min(self.height),
            rows.end.min(self.height),
        );
        if y0 >= y1 {
            return;
        }
        if let Some(c) = color {
            fill_color(&mut self.color[y0 * w..y1 * w], c);
        }
        if let (Some(d), false) = (depth, self.depth.is_empty()) {
            self.depth[y0 * w..y1 * w].fill(d);
        }
    }

    /// Records a clear of the whole colour buffer to `color` and of the whole depth buffer
    /// to `depth` (each when given, in stored form) without writing them: a frame that is
    /// cleared and drawn writes each band's clear values while the band is in the cache
    /// (see [`Framebuffer::bands`]), and a frame that is only cleared never writes them
    /// (glFlush fills the user buffer from [`Framebuffer::uniform_color`]).
    pub fn defer_clear(&mut self, color: Option<[u8; 4]>, depth: Option<u32>) {
        let depth = depth.filter(|_| !self.depth.is_empty());
        if color.is_none() && depth.is_none() {
            return;
        }
        // Both buffers share the row marks: an earlier clear of the buffer this one leaves
        // alone is written first when some rows have been written since (their marks are
        // about to be set for the new clear).
        let keeps = (self.pending_color.is_some() && color.is_none())
            || (self.pending_depth.is_some() && depth.is_none());
        if keeps && !self.pending_rows.iter().all(|&p| p) {
            self.resolve();
        }
        if let Some(c) = color {
            self.uniform_color = Some(c);
            self.pending_color = Some(c);
        }
        if let Some(d) = depth {
            self.pending_depth = Some(d);
        }
        self.pending_rows.fill(true);
    }

    /// Writes the recorded clears ([`Framebuffer::defer_clear`]) into the buffers; called
    /// before anything reads or writes their memory directly.
    pub fn resolve(&mut self) {
        let (color, depth) = (self.pending_color.take(), self.pending_depth.take());
        resolve_rows(
            self.width,
            &mut self.pending_rows,
            &mut self.color,
            &mut self.depth,
            color,
            depth,
        );
    }

    /// Whether row `y` still holds the recorded clears (see [`Framebuffer::pending_rows`]).
    #[inline]
    fn row_pending(&self, y: usize) -> bool {
        self.pending_rows.get(y).copied().unwrap_or(false)
    }

    /// The recorded colour clear that memory row `y` holds instead of its memory, if any.
    #[inline]
    pub fn pending_color_row(&self, y: usize) -> Option<[u8; 4]> {
        self.pending_color.filter(|_| self.row_pending(y))
    }

    /// The recorded depth clear that memory row `y` holds instead of its memory, if any.
    #[inline]
    pub fn pending_depth_row(&self, y: usize) -> Option<u32> {
        self.pending_depth.filter(|_| self.row_pending(y))
    }

    /// Colour pixel `i` (y-down row-major), recorded clears included.
    #[inline]
    pub fn color_at(&self, i: usize) -> [u8; 4] {
        match self.pending_color {
            Some(c) if self.row_pending(i / self.width) => c,
            _ => self.color[i],
        }
    }

    /// Depth value `i` (y-down row-major), recorded clears included.
    #[inline]
    pub fn depth_at(&self, i: usize) -> u32 {
        match self.pending_depth {
            Some(d) if self.row_pending(i / self.width) => d,
            _ => self.depth[i],
        }
    }

    /// Stencil bits (0 or 8).
    pub fn stencil_bits(&self) -> i32 {
        if self.stencil.is_empty() {
            0
        } else {
            8
        }
    }

    /// Converts an RGBA8 value to what the buffer stores ([`ColorFormat::store_rgba8`]).
    #[inline(always)]
    pub fn store_rgba8(&self, c: [u8; 4]) -> [u8; 4] {
        self.format.store_rgba8(c)
    }

    /// The stored colour of a glClear value (clamped to [0,1] here, NaN giving 0).
    pub fn clear_value(&self, c: [f32; 4]) -> [u8; 4] {
        self.format
            .pack_float(c.map(|v| if v > 0.0 { v.min(1.0) } else { 0.0 }))
    }
}

impl ColorFormat {
    /// What a buffer of this format stores for the RGBA8 value `c`: RGB565 truncates and
    /// replicates bits, formats without alpha store 255.
    #[inline(always)]
    pub fn store_rgba8(self, c: [u8; 4]) -> [u8; 4] {
        match self {
            ColorFormat::Rgb565 => {
                let (r, g, b) = (c[0] >> 3, c[1] >> 2, c[2] >> 3);
                [
                    (r << 3) | (r >> 2),
                    (g << 2) | (g >> 4),
                    (b << 3) | (b >> 2),
                    255,
                ]
            }
            ColorFormat::Rgb => [c[0], c[1], c[2], 255],
            _ => c,
        }
    }

    /// The bytes [`Framebuffer::copy_to_user`] writes for stored colour `c` (the first
    /// [`ColorFormat::bytes_per_pixel`] of them).
    pub fn user_bytes(self, c: [u8; 4]) -> [u8; 4] {
        match self {
            ColorFormat::Rgba | ColorFormat::Rgb => c,
            ColorFormat::Bgra => [c[2], c[1], c[0], c[3]],
            ColorFormat::Argb => [c[3], c[0], c[1], c[2]],
            ColorFormat::Rgb565 => {
                let v = ((c[0] as u16 >> 3) << 11) | ((c[1] as u16 >> 2) << 5) | (c[2] as u16 >> 3);
                let b = v.to_ne_bytes();
                [b[0], b[1], 0, 0]
            }
        }
    }

    /// A float colour in [0,1] packed as gallium's format packing does (glClear's fast
    /// path, glAccum's GL_RETURN): rounded, RGB565 to 5/6 bits, no alpha stored as 255.
    #[inline]
    pub fn pack_float(self, c: [f32; 4]) -> [u8; 4] {
        match self {
            ColorFormat::Rgb565 => {
                let q = |v: f32, max: f32| (v.clamp(0.0, 1.0) * max).round() as u8;
                let (r, g, b) = (q(c[0], 31.0), q(c[1], 63.0), q(c[2], 31.0));
                [
                    (r << 3) | (r >> 2),
                    (g << 2) | (g >> 4),
                    (b << 3) | (b >> 2),
                    255,
                ]
            }
            ColorFormat::Rgb => {
                let q = clear_float_to_ubyte;
                [q(c[0]), q(c[1]), q(c[2]), 255]
            }
            _ => c.map(clear_float_to_ubyte),
        }
    }
}

/// A band of framebuffer rows that one thread rasterizes into: rows `y0..y0 + rows` of the
/// colour, depth and stencil buffers (indices inside are relative to row `y0`).
pub struct Target<'a> {
    /// Framebuffer width.
    pub width: usize,
    /// Framebuffer height (all rows, for y flips).
    pub height: usize,
    /// Whether rows are y-down ([`Framebuffer::y_flip`]).
    pub y_flip: bool,
    /// First row of the band.
    pub y0: usize,
    /// Number of rows in the band.
    pub rows: usize,
    /// Colour layout.
    pub format: ColorFormat,
    /// The band's colour rows.
    pub color: &'a mut [[u8; 4]],
    /// The band's depth rows (empty without a depth buffer).
    pub depth: &'a mut [u32],
    /// The band's stencil rows (empty without a stencil buffer).
    pub stencil: &'a mut [u8],
    /// A recorded colour clear this band has not written yet ([`Target::resolve`]).
    pub pending_color: Option<[u8; 4]>,
    /// A recorded depth clear this band has not written yet ([`Target::resolve`]).
    pub pending_depth: Option<u32>,
    /// The band's rows' marks in [`Framebuffer::pending_rows`].
    pub pending_rows: &'a mut [bool],
    /// The precision of a wide colour buffer ([`Framebuffer::wide`]).
    pub wide: Option<WideKind>,
    /// The band's rows of the wide colour plane (empty for 8-bit buffers).
    pub wide_color: &'a mut [[f32; 4]],
    /// [`Framebuffer::wide_single`].
    pub wide_single: bool,
    /// The same rows of a multisample object's planes 1..4 during a one-pass multisample
    /// draw (empty otherwise; [`samples`]).
    pub samples: [samples::PlaneRows<'a>; samples::MORE_SAMPLES],
    /// The same rows of draw buffers 1.. ([`draw_buffers`]; empty without them).
    pub more_colors: draw_buffers::MoreRows<'a>,
}

impl Framebuffer {
    /// The whole framebuffer as one band, every recorded clear written.
    pub fn target(&mut self) -> Target<'_> {
        self.resolve();
        // Nothing is pending any more: the band of no rows only makes the target.
        self.target_rows(0..0)
    }

    /// The whole framebuffer as one band, for drawing that stays inside rows `rows`
    /// (y-down): only those rows' recorded clears are written, the others stay pending.
    ///
    /// Inlined, with the rows' marks looked at first: single-threaded, each small
    /// triangle is drawn through its own target, and building it in a call that always
    /// went through [`resolve_rows`] was 8% of a frame of 200k one-pixel triangles,
    /// whose rows had almost all been written by then.
    #[inline(always)]
    pub fn target_rows(&mut self, rows: std::ops::Range<usize>) -> Target<'_> {
        let y1 = rows.end.min(self.height);
        let y0 = rows.start.min(y1);
        if self.pending_rows[y0..y1].contains(&true) {
            self.resolve_range(y0, y1);
        }
        self.uniform_color = None;
        Target {
            width: self.width,
            height: self.height,
            y_flip: self.y_flip,
            y0: 0,
            rows: self.height,
            format: self.format,
            color: &mut self.color,
            depth: &mut self.depth,
            stencil: &mut self.stencil,
            pending_color: None,
            pending_depth: None,
            // Nothing for `Target::resolve` to do: the rows drawn into are written.
            pending_rows: &mut [],
            wide: self.wide,
            wide_color: &mut self.wide_color,
            wide_single: self.wide_single,
            samples: samples::whole(&mut self.samples),
            more_colors: draw_buffers::whole(&mut self.more_colors),
        }
    }

    /// Writes the recorded clears of the marked rows among `y0..y1` and clears their marks
    /// ([`Self::target_rows`]'s rare part).
    #[inline(never)]
    fn resolve_range(&mut self, y0: usize, y1: usize) {
        let w = self.width;
        let depth_rows: &mut [u32] = if self.depth.is_empty() {
            &mut []
        } else {
            &mut self.depth[y0 * w..y1 * w]
        };
        resolve_rows(
            w,
            &mut self.pending_rows[y0..y1],
            &mut self.color[y0 * w..y1 * w],
            depth_rows,
            self.pending_color,
            self.pending_depth,
        );
    }

    /// The framebuffer split into bands of `band_rows` rows (an even number, so 2x2 quads
    /// never straddle two bands), for threads that each own some bands. Each band carries
    /// the recorded clears and its rows' marks: the caller must [`Target::resolve`] a band
    /// before it draws into it; a band it does not draw into stays pending.
    pub fn bands(&mut self, band_rows: usize) -> Vec<Target<'_>> {
        self.uniform_color = None;
        let (pending_color, pending_depth) = (self.pending_color, self.pending_depth);
        let (w, h, format) = (self.width, self.height, self.format);
        let band_rows = band_rows.max(2) & !1;
        let n = w * band_rows;
        let mut color = self.color.chunks_mut(n);
        let mut depth = (!self.depth.is_empty()).then(|| self.depth.chunks_mut(n));
        let mut stencil = (!self.stencil.is_empty()).then(|| self.stencil.chunks_mut(n));
        let mut marks = self.pending_rows.chunks_mut(band_rows);
        let wide = self.wide;
        let mut wide_color = (wide.is_some()).then(|| self.wide_color.chunks_mut(n));
        let mut more = samples::Bands::new(&mut self.samples, n);
        let mut more_colors = draw_buffers::Bands::new(&mut self.more_colors, n);
        let mut out = Vec::new();
        let mut y0 = 0;
        while y0 < h {
            let rows = band_rows.min(h - y0);
            out.push(Target {
                width: w,
                height: h,
                y_flip: self.y_flip,
                y0,
                rows,
                format,
                color: color.next().unwrap_or_default(),
                depth: depth.as_mut().and_then(|d| d.next()).unwrap_or_default(),
                stencil: stencil.as_mut().and_then(|s| s.next()).unwrap_or_default(),
                pending_color,
                pending_depth,
                pending_rows: marks.next().unwrap_or_default(),
                wide,
                wide_color: wide_color
                    .as_mut()
                    .and_then(|c| c.next())
                    .unwrap_or_default(),
                wide_single: self.wide_single,
                samples: more.next_band(),
                more_colors: more_colors.next_band(),
            });
            y0 += rows;
        }
        out
    }
}

impl Target<'_> {
    /// Writes the band's share of the recorded clears (see [`Framebuffer::bands`]).
    #[inline]
    pub fn resolve(&mut self) {
        let (color, depth) = (self.pending_color.take(), self.pending_depth.take());
        resolve_rows(
            self.width,
            self.pending_rows,
            self.color,
            self.depth,
            color,
            depth,
        );
    }

    /// Clears the band's colour rows to `color` and depth rows to `depth` (each when
    /// given, in stored form): [`Framebuffer::clear_rows`] for one band of a threaded clear.
    pub fn clear(&mut self, color: Option<[u8; 4]>, depth: Option<u32>) {
        if let Some(c) = color {
            fill_color(self.color, c);
        }
        if let Some(d) = depth {
            self.depth.fill(d);
        }
    }
}

/// Writes the recorded clears `color` and `depth` into the rows of `color_rows` and
/// `depth_rows` (`width` pixels each) that `marks` flags, and clears the flags.
fn resolve_rows(
    width: usize,
    marks: &mut [bool],
    color_rows: &mut [[u8; 4]],
    depth_rows: &mut [u32],
    color: Option<[u8; 4]>,
    depth: Option<u32>,
) {
    if color.is_none() && depth.is_none() {
        marks.fill(false);
        return;
    }
    let mut y = 0;
    while y < marks.len() {
        if !marks[y] {
            y += 1;
            continue;
        }
        // A run of marked rows, written in one fill per buffer.
        let start = y;
        while y < marks.len() && marks[y] {
            marks[y] = false;
            y += 1;
        }
        if let Some(c) = color {
            fill_color(&mut color_rows[start * width..y * width], c);
        }
        if let (Some(d), false) = (depth, depth_rows.is_empty()) {
            depth_rows[start * width..y * width].fill(d);
        }
    }
}

/// Fills colour pixels with `c` in 32-bit stores (the byte-array form does not always
/// become wide stores).
#[inline]
pub fn fill_color(dst: &mut [[u8; 4]], c: [u8; 4]) {
    fill_color_bytes(dst.as_flattened_mut(), c);
}

/// Fills `dst` (a multiple of 4 bytes) with the 4-byte pattern `c`, in aligned 32-bit
/// stores where possible.
#[inline]
fn fill_color_bytes(dst: &mut [u8], c: [u8; 4]) {
    debug_assert_eq!(dst.len() % 4, 0);
    // SAFETY: every bit pattern is a valid u32, so viewing the aligned middle of a byte
    // slice as u32 is sound.
    let (head, mid, tail) = unsafe { dst.align_to_mut::<u32>() };
    if head.is_empty() {
        mid.fill(u32::from_ne_bytes(c));
        for (o, v) in tail.iter_mut().zip(c) {
            *o = v;
        }
    } else {
        // Unaligned start: the pattern does not line up with the words.
        for o in dst.chunks_exact_mut(4) {
            o.copy_from_slice(&c);
        }
    }
}

/// Float colour to unorm8 as llvmpipe's shader output does: clamp to [0,1] (NaN gives 0),
/// then `round_half_even(f32(c * 255))`.
#[inline(always)]
pub fn float_to_ubyte(c: f32) -> u8 {
    let c = if c > 0.0 { c.min(1.0) } else { 0.0 };
    crate::geometry::round_even(c * 255.0f32) as u8
}

/// Float to unorm8 as gallium's fast clear packs it (`util` float_to_ubyte): scale by
/// 255/256, add 2^15 and keep the low mantissa byte.
#[inline]
pub fn clear_float_to_ubyte(f: f32) -> u8 {
    if f.is_nan() || f <= 0.0 {
        0
    } else if f >= 1.0 {
        255
    } else {
        let t = f * (255.0f32 / 256.0f32) + 32768.0f32;
        t.to_bits() as u8
    }
}

#[cfg(test)]
#[path = "framebuffer/tests.rs"]
mod tests;
