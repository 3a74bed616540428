//! glDrawPixels, glCopyPixels and glBitmap as Mesa's state tracker runs them on llvmpipe
//! (`st_cb_drawpixels.c`, `st_cb_bitmap.c`): a textured quad ([`super::rect`]) whose
//! fragments go through the per-fragment operations. This module draws the quad from
//! plain values; `context::pixel_ops` reads the state and calls it.
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

use super::rect::{rasterize, Dest, Fragments, Quad};
use crate::fixed_function::fog::FogPlan;
use crate::fragment::span::{unorm8, LANES};
use crate::fragment::FragPlan;
use crate::framebuffer::Framebuffer;
use crate::stats::Stats;
use crate::texture::UnitPlan;

/// The fixed-function colour computation of pixel-rectangle fragments.
pub struct Shader<'a> {
    units: Vec<(UnitPlan<'a>, [f32; 4])>,
    /// Every unit's texel in unit order, for crossbar sources (fixed for the draw).
    texels: Vec<[f32; 4]>,
    fog: Option<FogPlan>,
}

impl<'a> Shader<'a> {
    /// The shader of the enabled units (each with the current texture coordinates, which
    /// every fragment samples alike) and the fog, if enabled.
    pub fn new(units: Vec<(UnitPlan<'a>, [f32; 4])>, fog: Option<FogPlan>) -> Self {
        let units: Vec<_> = units
            .into_iter()
            .map(|(p, tc)| {
                let r = 1.0f32 / tc[3];
                let (s, t) = (tc[0] * r, tc[1] * r);
                let lod = p.quad_lod([s; 4], [t; 4]);
                let texel = p.sample_one(s, t, lod);
                (p, texel)
            })
            .collect();
        let texels = units.iter().map(|(_, tex)| *tex).collect();
        Shader { units, texels, fog }
    }

    /// The shader's output colour of a fragment with primary colour `primary` (before the
    /// target's conversion).
    pub fn shade(&self, primary: [f32; 4]) -> [f32; 4] {
        let mut prev = primary;
        for (u, tex) in &self.units {
            prev = u.env.apply(primary, *tex, prev, &self.texels);
        }
        if let Some(f) = &self.fog {
            prev = f.apply(prev, f.factor(0.0));
        }
        prev
    }
}

/// What the fragments of a rectangle carry.
pub enum Source<'a> {
    /// Shader output colours per texel.
    Color(&'a [[f32; 4]]),
    /// One colour; only texels that are set draw.
    Mask(&'a [bool], [f32; 4]),
    /// Depth per texel, one colour.
    Depth(&'a [f32], [f32; 4]),
    /// Stencil values per texel.
    Stencil(&'a [u8]),
}

/// Buffers a pixel rectangle's colours are converted into, kept by the context from one
/// rectangle to the next: allocating them per glDrawPixels cost a page fault per 4 KiB
/// each time (glibc hands blocks this size back to the kernel on free), a fifth of the
/// pushattrib_pixels benchmark's frame.
#[derive(Clone, Debug, Default)]
pub struct Scratch {
    /// Shaded colours of the image's texels ([`shade_colors`]).
    pub colors: Vec<[f32; 4]>,
    /// Their unorm8 conversion ([`run`]).
    pub c8: Vec<[u8; 4]>,
}

impl Scratch {
    /// Bytes a buffer keeps between rectangles; a bigger one is freed after its use.
    pub const KEEP_BYTES: usize = 4 << 20;

    /// Frees whatever grew past [`Scratch::KEEP_BYTES`].
    pub fn trim(&mut self) {
        if self.colors.capacity() * 16 > Self::KEEP_BYTES {
            self.colors = Vec::new();
        }
        if self.c8.capacity() * 4 > Self::KEEP_BYTES {
            self.c8 = Vec::new();
        }
    }
}

/// Where and how a rectangle's fragments land.
pub struct Target<'a> {
    /// The draw buffer.
    pub fb: &'a mut Framebuffer,
    /// The per-fragment operations.
    pub plan: &'a FragPlan,
    /// The draw buffer ∩ scissor, `[x0, y0, x1, y1)` in memory rows.
    pub region: [i64; 4],
    /// The stencil write mask (stencil images).
    pub stencil_mask: u8,
    /// Whether llvmpipe's multiply-adds fuse on this CPU level.
    pub fma: bool,
    /// Counters.
    pub stats: &'a mut Stats,
    /// Room for the unorm8 colours.
    pub c8: &'a mut Vec<[u8; 4]>,
}

/// Rasterises the quad `q` and runs its fragments of `src` into `t`.
pub fn run(t: Target<'_>, q: &Quad, src: Source<'_>) {
    let fb = t.fb;
    fb.uniform_color = None;
    let d = Dest {
        fb_w: fb.width,
        fb_h: fb.height,
        region: t.region,
        fma: t.fma,
        y_flip: fb.y_flip,
    };
    if let Source::Stencil(vals) = src {
        let fw = fb.width;
        if fb.stencil.is_empty() {
            return;
        }
        let stencil_mask = t.stencil_mask;
        rasterize(q, &d, |_, py, x, texels| {
            let row = &mut fb.stencil[py * fw + x..py * fw + x + texels.len()];
            for (s, &k) in row.iter_mut().zip(texels) {
                *s = (*s & !stencil_mask) | (vals[k] & stencil_mask);
            }
        });
        return;
    }
    let mut frags = Fragments::new(t.plan, fb.target(), t.stats);
    let narrow = frags.target.wide.is_none();
    match src {
        // The unorm8 conversion of each texel's colour, once per texel, not per pixel.
        Source::Color(c) if narrow => {
            let c8 = t.c8;
            c8.clear();
            c8.extend(c.iter().map(|p| p.map(unorm8)));
            rasterize(q, &d, |t, py, x, texels| {
                for (i, k) in texels.chunks(LANES).enumerate() {
                    frags.put_chunk8(t, py, x + i * LANES, |l| k.get(l).map(|&k| c8[k]));
                }
            })
        }
        Source::Mask(m, c) if narrow => {
            let c8 = c.map(unorm8);
            rasterize(q, &d, |t, py, x, texels| {
                for (i, k) in texels.chunks(LANES).enumerate() {
                    if k.iter().any(|&k| m[k]) {
                        frags.put_chunk8(t, py, x + i * LANES, |l| {
                            k.get(l).and_then(|&k| m[k].then_some(c8))
                        });
                    }
                }
            })
        }
        Source::Color(c) => rasterize(q, &d, |t, py, x, texels| {
            for (i, k) in texels.chunks(LANES).enumerate() {
                frags.put_chunk(t, py, x + i * LANES, |l| k.get(l).map(|&k| c[k]));
            }
        }),
        Source::Mask(m, c) => rasterize(q, &d, |t, py, x, texels| {
            for (i, k) in texels.chunks(LANES).enumerate() {
                frags.put_chunk(t, py, x + i * LANES, |l| {
                    k.get(l).and_then(|&k| m[k].then_some(c))
                });
            }
        }),
        Source::Depth(z, c) => rasterize(q, &d, |t, py, x, texels| {
            for (i, &k) in texels.iter().enumerate() {
                frags.put(t, x + i, py, c, Some(z[k]))
            }
        }),
        Source::Stencil(_) => {}
    }
}

/// Colour texels (`w` wide, in the temporary texture's row order) through the
/// pixel-transfer operations and the fragment shader: `scale_bias` (when active), then
/// `map_rg` (GL_MAP_COLOR's red and green lookups, when active), into `out`.
///
/// GL_MAP_COLOR as Mesa 22.3 runs it (`nir_lower_drawpixels.c`): red and green are looked
/// up in the pixel-map texture, but the second lookup, meant for blue and alpha, carries no
/// texture source and so samples texture 0, the image itself: blue and alpha become the
/// red and green of the image texel at (b, a), NEAREST with CLAMP_TO_EDGE.
pub fn shade_colors(
    sh: &Shader<'_>,
    texels: &[[f32; 4]],
    w: usize,
    scale_bias: Option<&dyn Fn([f32; 4]) -> [f32; 4]>,
    map_rg: Option<&dyn Fn([f32; 4]) -> [f32; 2]>,
    out: &mut Vec<[f32; 4]>,
) {
    let h = texels.len() / w.max(1);
    let nearest = |c: f32, n: usize| {
        (c.clamp(-1.0, 2.0) * n as f32)
            .floor()
            .clamp(0.0, (n - 1) as f32) as usize
    };
    out.clear();
    out.extend(texels.iter().map(|&c| {
        let mut c = c;
        if let Some(sb) = scale_bias {
            c = sb(c);
        }
        if let Some(map) = map_rg {
            let [r, g] = map(c);
            let texel = texels[nearest(c[3], h) * w + nearest(c[2], w)];
            c = [r, g, texel[0], texel[1]];
        }
        sh.shade(c)
    }));
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

/// The source rectangle of a glCopyPixels: `w` x `h` pixels at (x, y) in GL window
/// coordinates of a `fw` x `fh` buffer; pixels outside it read as zero.
#[derive(Clone, Copy, Debug)]
pub struct CopySource {
    /// Lower-left corner.
    pub x: i32,
    /// Lower-left corner.
    pub y: i32,
    /// Width.
    pub w: usize,
    /// Height.
    pub h: usize,
    /// Buffer width.
    pub fw: i64,
    /// Buffer height.
    pub fh: i64,
    /// The buffer's rows run top-down in memory.
    pub y_flip: bool,
}

impl CopySource {
    /// The memory row of GL row `y`.
    fn row(&self, y: i64) -> i64 {
        if self.y_flip {
            self.fh - 1 - y
        } else {
            y
        }
    }

    /// The buffer index of source pixel (i, j), bottom row first, or `None` outside.
    pub fn index(&self, i: usize, j: usize) -> Option<usize> {
        let (x, y) = (self.x as i64 + i as i64, self.y as i64 + j as i64);
        (x >= 0 && y >= 0 && x < self.fw && y < self.fh)
            .then(|| (self.row(y) * self.fw + x) as usize)
    }

    /// Whether the source overlaps the destination rectangle at (dx, dy).
    pub fn overlaps(&self, dx: i32, dy: i32) -> bool {
        let (w, h) = (self.w as i64, self.h as i64);
        let (ax0, ay0, ax1, ay1) = (
            self.x as i64,
            self.y as i64,
            self.x as i64 + w,
            self.y as i64 + h,
        );
        let (bx0, by0, bx1, by1) = (dx as i64, dy as i64, dx as i64 + w, dy as i64 + h);
        ax0 < bx1 && bx0 < ax1 && ay0 < by1 && by0 < ay1
    }

    /// The unscaled colour copy to (dx, dy) inside `region` (Mesa's blit path).
    pub fn blit(&self, fb: &mut Framebuffer, dx: i32, dy: i32, region: [i64; 4], kind: CopyKind) {
        fb.resolve();
        fb.uniform_color = None;
        let fw = self.fw;
        for j in 0..self.h {
            for i in 0..self.w {
                let Some(s) = self.index(i, j) else { continue };
                let gy = dy as i64 + j as i64;
                let yd = self.row(gy);
                let x = dx as i64 + i as i64;
                if x < region[0] || x >= region[2] || yd < region[1] || yd >= region[3] {
                    continue;
                }
                let d = (yd * fw + x) as usize;
                match kind {
                    CopyKind::Color => match fb.wide {
                        // The blit copies the stored value at full precision.
                        Some(k) => {
                            let v = fb.wide_at(s);
                            fb.wide_color[d] = v;
                            fb.color[d] = k.mirror(v);
                        }
                        None => fb.color[d] = fb.color[s],
                    },
                    CopyKind::Depth => fb.depth[d] = fb.depth[s],
                    CopyKind::Stencil | CopyKind::DepthStencil => fb.stencil[d] = fb.stencil[s],
                }
            }
        }
    }

    /// The source index of texel `k` of Mesa's temporary texture, which is y-down (top
    /// source row first) and sampled with t flipped.
    fn texel_index(&self, k: usize) -> Option<usize> {
        let (i, j) = (k % self.w, k / self.w);
        self.index(i, self.h - 1 - j)
    }

    /// The colour texels of the copy, as floats ([`Framebuffer::float_at`]: a wide
    /// buffer's at full precision).
    pub fn colors(&self, fb: &Framebuffer) -> Vec<[f32; 4]> {
        (0..self.w * self.h)
            .map(|k| self.texel_index(k).map_or([0.0; 4], |s| fb.float_at(s)))
            .collect()
    }

    /// The depth texels of the copy.
    pub fn depths(&self, fb: &Framebuffer) -> Vec<f32> {
        let f = fb.depth_format;
        (0..self.w * self.h)
            .map(|k| {
                self.texel_index(k)
                    .map_or(0.0, |s| f.sample_float(fb.depth_at(s)))
            })
            .collect()
    }

    /// The stencil texels of the copy.
    pub fn stencils(&self, fb: &Framebuffer) -> Vec<u8> {
        (0..self.w * self.h)
            .map(|k| self.texel_index(k).map_or(0, |s| fb.stencil[s]))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::Scratch;

    /// Buffers up to [`Scratch::KEEP_BYTES`] stay for the next rectangle; bigger ones go.
    #[test]
    fn scratch_keeps_small_buffers_and_frees_big_ones() {
        let mut s = Scratch::default();
        s.colors.reserve(1000);
        s.c8.reserve(1000);
        s.trim();
        assert!(s.colors.capacity() >= 1000 && s.c8.capacity() >= 1000);
        s.colors.reserve(Scratch::KEEP_BYTES / 16 + 1);
        s.c8.reserve(Scratch::KEEP_BYTES / 4 + 1);
        s.trim();
        assert_eq!((s.colors.capacity(), s.c8.capacity()), (0, 0));
    }
}
