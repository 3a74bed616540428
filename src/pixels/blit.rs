//! glBlitFramebuffer as Mesa 22.3 and llvmpipe do it (docs/fbo-rules.md §2): the
//! rectangle clipping, the multisample resolve and the copy; `context::pixel_ops::blit`
//! checks the buffers and runs them.
//!
//! # Rectangles
//! Mesa first clips the destination rectangle to the draw buffer ∩ scissor and the source
//! rectangle to the read buffer, moving the other rectangle's edge by
//! `(int)(t·(src1 − src0) ± 0.5)` (`_mesa_clip_blit`). The clipped destination only
//! becomes a scissor (when clipping changed it): the texel each pixel takes comes from the
//! *unclipped* rectangles. Both rectangles then go to memory rows (the window's are
//! flipped), a pair of upside-down rectangles is turned right side up, and the destination
//! box is made positive (the source box may then run backwards: a mirror).
//!
//! # Texel selection
//! An unscaled blit copies texel for texel. A scaled one is llvmpipe's blitter: a quad over
//! the destination box, corners at `x / W · 2 − 1` through the viewport, drawn as the fan
//! (v0, v1, v2), (v0, v2, v3) with llvmpipe's setup, its source coordinates interpolated
//! per pixel (normalised by the source size for an object's image, unnormalised for the
//! window, which gallium keeps as a RECT texture). GL_NEAREST takes texel
//! `clamp(floor(s·W), 0, W − 1)`; GL_LINEAR llvmpipe's 8-bit filter:
//! `f = round_half_even(s·W·256) − 128`, taps `f >> 8` and the next (clamped to the edge),
//! weight `f & 255`, `a + ((w·(b − a) + 128) >> 8)` across, then down. An unscaled blit
//! is never filtered. Depth and stencil take the GL_NEAREST texel's stored value.
//!
//! Not followed yet: a destination rectangle that leaves the draw buffer, whose quad
//! llvmpipe clips geometrically first (its ties can fall the other way).

use super::blit_srgb::SrgbSides;
use crate::fragment::span::{eval, Fused, Madd, Unfused};
use crate::framebuffer::Framebuffer;
use crate::geometry::setup::SetupTriangle;
use crate::geometry::{ClipVertex, Viewport, VARY_TEX};

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

/// `_mesa_clip_blit`'s edge move after cutting the destination at `limit` (one side).
fn cut(s_from: i32, s_to: i32, d_from: i32, d_to: i32, limit: i32) -> i32 {
    let t = (limit - d_from) as f32 / (d_to - d_from) as f32;
    let bias = if s_from < s_to { 0.5f32 } else { -0.5f32 };
    s_from + (t * (s_to - s_from) as f32 + bias) as i32
}

/// Clips one axis of `dst` to `[lo, hi)` and `src` to `[0, size)` as `_mesa_clip_blit`
/// does; `false` when nothing is left.
pub fn clip_axis(s: &mut [i32; 2], d: &mut [i32; 2], lo: i32, hi: i32, size: i32) -> bool {
    if d[0] == d[1] || (d[0] <= lo && d[1] <= lo) || (d[0] >= hi && d[1] >= hi) {
        return false;
    }
    if s[0] == s[1] || (s[0] <= 0 && s[1] <= 0) || (s[0] >= size && s[1] >= size) {
        return false;
    }
    // One pass per (range, limit): the right/top edge first, then the left/bottom one.
    let pass = |s: &mut [i32; 2], d: &mut [i32; 2], lo: i32, hi: i32| {
        if d[1] > hi {
            s[1] = cut(s[0], s[1], d[0], d[1], hi);
            d[1] = hi;
        } else if d[0] > hi {
            s[0] = cut(s[1], s[0], d[1], d[0], hi);
            d[0] = hi;
        }
        if d[0] < lo {
            s[0] = cut(s[0], s[1], d[0], d[1], lo);
            d[0] = lo;
        } else if d[1] < lo {
            s[1] = cut(s[1], s[0], d[1], d[0], lo);
            d[1] = lo;
        }
    };
    pass(s, d, lo, hi);
    pass(d, s, 0, size);
    true
}

/// The single-sample image a multisample resolve reads: per pixel and channel llvmpipe's
/// resolve shader (`util_make_fs_msaa_resolve`): `sum = 0; sum += s_i` in sample order
/// in f32, each sample `u · f32(1/255)`, then `round_half_even(sum · 0.25 · 255)`. Depth
/// and stencil are sample 0's. With sRGB `sides` the samples are decoded and the average
/// stored as the destination stores it ([`super::blit_srgb`]).
///
/// When the samples or the destination are wider than 8 bits (`wide`), the average stays
/// a float: the image returned is an R32G32B32A32_FLOAT one holding `sum · 0.25` (each
/// sample read as [`Framebuffer::float_at`]), which the copy then converts to the
/// destination's format as the resolve shader's output is.
///
/// The 8-bit resolve writes into `scratch` when it fits ([`super::resolve::reuse`]), and
/// only the buffers the blit reads (`mask`): no colour average without
/// GL_COLOR_BUFFER_BIT.
pub fn resolve_samples(
    planes: &[Framebuffer],
    sides: SrgbSides,
    wide: bool,
    fma: bool,
    mask: BlitMask,
    scratch: Option<Framebuffer>,
) -> Framebuffer {
    let mut out = 'resolve: {
        if sides != SrgbSides::default() {
            break 'resolve sides.resolve(planes, fma);
        }
        if !wide && planes[0].wide.is_none() && planes.len() == 4 {
            let mut out = super::resolve::reuse(scratch, &planes[0], mask.depth, mask.stencil);
            if mask.color {
                let colors = std::array::from_fn(|k| &planes[k].color[..]);
                super::resolve::average_rgba8(colors, &mut out.color);
            }
            break 'resolve out;
        }
        let mut out = planes[0].clone();
        if wide || out.wide.is_some() {
            out.set_wide(Some(crate::framebuffer::WideKind::Float32));
            for i in 0..out.width * out.height {
                let mut sum = [0.0f32; 4];
                for p in planes {
                    let c = p.float_at(i);
                    for ch in 0..4 {
                        sum[ch] += c[ch];
                    }
                }
                let avg = sum.map(|v| v * 0.25);
                out.wide_color[i] = avg;
                out.color[i] = crate::framebuffer::WideKind::Float32.mirror(avg);
            }
            break 'resolve out;
        }
        let scale = 1.0f32 / 255.0;
        for (i, px) in out.color.iter_mut().enumerate() {
            for (ch, v) in px.iter_mut().enumerate() {
                let mut sum = 0.0f32;
                for p in planes {
                    sum += p.color[i][ch] as f32 * scale;
                }
                let avg = sum * 0.25;
                *v = crate::fragment::span::unorm8(avg);
            }
        }
        out
    };
    // llvmpipe's blitter reads sample 0's depth as a float and writes it back.
    if mask.depth {
        super::resolve::depth_through_float(&mut out);
    }
    out
}

/// One blit in memory coordinates.
pub struct Job {
    /// Destination box: x, y, width, height (positive).
    pub dst: [i32; 4],
    /// Source box: x, y, width, height (negative: mirrored).
    pub src: [i32; 4],
    /// Pixels that may be written, `[x0, y0, x1, y1)`.
    pub scissor: [i64; 4],
    /// Texture coordinates are normalised (an object's image) or texel units (window).
    pub normalized: bool,
    /// Scaled GL_LINEAR.
    pub linear: bool,
    /// Whether llvmpipe's multiply-adds fuse on this CPU level.
    pub fma: bool,
    /// The sides that are sRGB surfaces (GL_FRAMEBUFFER_SRGB on; [`super::blit_srgb`]).
    pub srgb: super::blit_srgb::SrgbSides,
}

impl Job {
    /// Copies the masked buffers of `s` into `d`.
    pub fn run(&self, s: &Framebuffer, d: &mut Framebuffer, mask: BlitMask) {
        let sc = self.scissor;
        let [bx, by, bw, bh] = self.dst;
        let [sx, sy, sw, sh] = self.src;
        // util_try_blit_via_copy_region's memcpy: unscaled, not mirrored, no scissor, every
        // buffer of the depth-stencil format; otherwise depth takes the blitter's shader.
        let whole = sc == [bx as i64, by as i64, (bx + bw) as i64, (by + bh) as i64];
        // Z32_UNORM to Z32_UNORM with NEAREST is an R32_UINT blit (`lp_blit`): copied too.
        let copy_region = bw == sw && bh == sh && whole && (mask.stencil || s.stencil.is_empty());
        let exact_depth = copy_region || s.depth_format == crate::framebuffer::DepthFormat::Z32;
        let bits = s.depth_format.texel_bits();
        let unscaled = bw == sw.abs() && bh == sh.abs();
        let convert = self.srgb.converts(unscaled);
        let fma = self.fma;
        // Wider than 8 bits on either side: the blitter's float colour (the source texel
        // as the sampler returns it, stored with the destination's output conversion).
        let wide = s.wide.is_some() || d.wide.is_some();
        let write = |d: &mut Framebuffer, px: i64, py: i64, c: Option<Texel>, t: (usize, usize)| {
            let di = py as usize * d.width + px as usize;
            let si = t.1 * s.width + t.0;
            if mask.color {
                match c {
                    Some(Texel::Float(f)) => d.put_float(di, f),
                    Some(Texel::Unorm8(u)) if wide => {
                        d.put_float(di, u.map(|v| v as f32 * (1.0f32 / 255.0)))
                    }
                    Some(Texel::Unorm8(u)) => d.color[di] = d.store_rgba8(u),
                    None if convert => {
                        d.color[di] = d.store_rgba8(self.srgb.texel(s.color[si], fma))
                    }
                    None if wide => d.put_float(di, s.float_at(si)),
                    None => d.color[di] = d.store_rgba8(s.color[si]),
                }
            }
            if mask.depth {
                d.depth[di] = if exact_depth {
                    s.depth[si]
                } else {
                    // The blitter's depth shader: the sampler's float, written as depth.
                    let z = crate::texture::shadow::sample_value(s.depth[si], bits);
                    d.depth_format.quantize(z)
                };
            }
            if mask.stencil && !s.stencil.is_empty() && !d.stencil.is_empty() {
                d.stencil[di] = s.stencil[si];
            }
        };
        let inside = |px: i64, py: i64| px >= sc[0] && px < sc[2] && py >= sc[1] && py < sc[3];
        if unscaled && sw > 0 && sh > 0 && !convert && !wide && (!mask.depth || exact_depth) {
            return self.copy_rows(s, d, mask);
        }
        if unscaled {
            // Texel for texel (llvmpipe's copy or TXF path).
            for j in 0..bh as i64 {
                for i in 0..bw as i64 {
                    let (px, py) = (bx as i64 + i, by as i64 + j);
                    let tx = if sw > 0 {
                        sx as i64 + i
                    } else {
                        sx as i64 - 1 - i
                    };
                    let ty = if sh > 0 {
                        sy as i64 + j
                    } else {
                        sy as i64 - 1 - j
                    };
                    let ok = tx >= 0 && ty >= 0 && tx < s.width as i64 && ty < s.height as i64;
                    if inside(px, py) && ok {
                        write(d, px, py, None, (tx as usize, ty as usize));
                    }
                }
            }
            return;
        }
        let (ws, hs) = (s.width as f32, s.height as f32);
        let (nx, ny) = if self.normalized {
            (ws, hs)
        } else {
            (1.0, 1.0)
        };
        let (dwf, dhf) = (d.width as f32, d.height as f32);
        let vp = Viewport::oriented(
            [0, 0, d.width as i32, d.height as i32],
            [0.0, 1.0],
            d.height,
            false,
        );
        let corner = |x: i32, y: i32, u: i32, v: i32| {
            let clip = [
                x as f32 / dwf * 2.0 - 1.0,
                y as f32 / dhf * 2.0 - 1.0,
                0.0,
                1.0,
            ];
            let mut c = ClipVertex {
                clip,
                win: vp.apply_shader(clip, self.fma),
                ..Default::default()
            };
            c.vary[VARY_TEX] = u as f32 / nx;
            c.vary[VARY_TEX + 1] = v as f32 / ny;
            c
        };
        let v = [
            corner(bx, by, sx, sy),
            corner(bx + bw, by, sx + sw, sy),
            corner(bx + bw, by + bh, sx + sw, sy + sh),
            corner(bx, by + bh, sx, sy + sh),
        ];
        // The blitter's rasterizer state is the rule the window's draws use (measured).
        super::rect::quad_pixels(&v, sc, |tri, px, py| {
            let (u, t) = if self.fma {
                st::<Fused>(tri, px, py)
            } else {
                st::<Unfused>(tri, px, py)
            };
            let nearest = (texel(u * nx, s.width), texel(t * ny, s.height));
            let c = match (self.linear, convert) {
                (true, true) => {
                    let eight_bit = || bilinear(s, u * nx, t * ny);
                    let c = self.srgb.bilinear(s, (u * nx, t * ny), fma, eight_bit);
                    Some(Texel::Unorm8(c))
                }
                (true, false) => Some(match s.wide {
                    Some(_) => Texel::Float(bilinear_float(s, u * nx, t * ny, fma)),
                    None => Texel::Unorm8(bilinear(s, u * nx, t * ny)),
                }),
                _ => None,
            };
            write(d, px, py, c, nearest);
        });
    }
}

impl Job {
    /// An unscaled, unmirrored blit between 8-bit buffers without conversion (depth only
    /// when copied exactly): [`Job::run`]'s texel-for-texel copy a row slice at a time.
    fn copy_rows(&self, s: &Framebuffer, d: &mut Framebuffer, mask: BlitMask) {
        let [x0, y0, x1, y1] = self.scissor;
        let [bx, by, bw, bh] = self.dst.map(|v| v as i64);
        let [sx, sy] = [self.src[0] as i64, self.src[1] as i64];
        // Destination pixels inside the box, the scissor, the destination and a source
        // texel: tx = sx + (px − bx) in [0, s.width), likewise rows.
        let lo = |b: i64, c: i64, o: i64| b.max(c).max(b - o);
        let hi =
            |b: i64, n: i64, c: i64, d: i64, o: i64, sn: i64| (b + n).min(c).min(d).min(b - o + sn);
        let (xa, xb) = (
            lo(bx, x0, sx).max(0),
            hi(bx, bw, x1, d.width as i64, sx, s.width as i64),
        );
        let (ya, yb) = (
            lo(by, y0, sy).max(0),
            hi(by, bh, y1, d.height as i64, sy, s.height as i64),
        );
        if xa >= xb || ya >= yb {
            return;
        }
        let n = (xb - xa) as usize;
        let stencil = mask.stencil && !s.stencil.is_empty() && !d.stencil.is_empty();
        for py in ya..yb {
            let di = py as usize * d.width + xa as usize;
            let si = (py - by + sy) as usize * s.width + (xa - bx + sx) as usize;
            if mask.color {
                let (src, dst) = (&s.color[si..si + n], &mut d.color[di..di + n]);
                if d.format == crate::framebuffer::ColorFormat::Rgba {
                    dst.copy_from_slice(src);
                } else {
                    for (o, &c) in dst.iter_mut().zip(src) {
                        *o = d.format.store_rgba8(c);
                    }
                }
            }
            if mask.depth {
                d.depth[di..di + n].copy_from_slice(&s.depth[si..si + n]);
            }
            if stencil {
                d.stencil[di..di + n].copy_from_slice(&s.stencil[si..si + n]);
            }
        }
    }
}

/// A filtered source colour: llvmpipe's 8-bit filter's result, or the float filter's.
#[derive(Clone, Copy)]
enum Texel {
    /// From an 8-bit source.
    Unorm8([u8; 4]),
    /// From a wide source.
    Float([f32; 4]),
}

/// GL_LINEAR of a wide source at (u, v) in texels, clamped to the edge, in f32: weights
/// `c − 0.5 − floor(c − 0.5)`, `fmuladd(w, b − a, a)` across, then down (llvmpipe's SoA
/// filter, as the float mipmap blit; not compared with llvmpipe yet).
fn bilinear_float(s: &Framebuffer, u: f32, v: f32, fma: bool) -> [f32; 4] {
    let axis = |c: f32, n: usize| {
        let c = c - 0.5;
        let f = c.floor();
        let clamp = |i: i64| i.clamp(0, n as i64 - 1) as usize;
        (clamp(f as i64), clamp(f as i64 + 1), c - f)
    };
    let (x0, x1, wx) = axis(u, s.width);
    let (y0, y1, wy) = axis(v, s.height);
    let at = |x: usize, y: usize| s.float_at(y * s.width + x);
    let lerp = crate::texture::sample::lerpfx4;
    let top = lerp(fma, wx, at(x0, y0), at(x1, y0));
    let bot = lerp(fma, wx, at(x0, y1), at(x1, y1));
    lerp(fma, wy, top, bot)
}

/// The interpolated source coordinates at pixel (px, py).
#[inline]
fn st<M: Madd>(tri: &SetupTriangle, px: i64, py: i64) -> (f32, f32) {
    let (fx, fy) = (px as f32, py as f32);
    (
        eval::<M>(&tri.vary[VARY_TEX], fx, fy),
        eval::<M>(&tri.vary[VARY_TEX + 1], fx, fy),
    )
}

/// GL_NEAREST's texel for coordinate `c` (in texels) of a `n`-texel axis.
#[inline]
fn texel(c: f32, n: usize) -> usize {
    (c.floor().max(0.0) as usize).min(n - 1)
}

/// llvmpipe's 8-bit GL_LINEAR filter at (u, v) in texels, clamped to the edge.
fn bilinear(s: &Framebuffer, u: f32, v: f32) -> [u8; 4] {
    let axis = |c: f32, n: usize| {
        let f = (c * 256.0).round_ties_even() as i64 - 128;
        let i0 = f >> 8;
        let clamp = |i: i64| i.clamp(0, n as i64 - 1) as usize;
        (clamp(i0), clamp(i0 + 1), (f & 255) as i32)
    };
    let (x0, x1, wx) = axis(u, s.width);
    let (y0, y1, wy) = axis(v, s.height);
    let at = |x: usize, y: usize| s.color[y * s.width + x];
    let lerp = |a: [u8; 4], b: [u8; 4], w: i32| -> [u8; 4] {
        std::array::from_fn(|i| {
            (a[i] as i32 + ((w * (b[i] as i32 - a[i] as i32) + 128) >> 8)) as u8
        })
    };
    let top = lerp(at(x0, y0), at(x1, y0), wx);
    let bot = lerp(at(x0, y1), at(x1, y1), wx);
    lerp(top, bot, wy)
}
