//! glBlitFramebuffer's colour conversions with GL_FRAMEBUFFER_SRGB on (docs/fbo-rules.md
//! §5.3). Mesa gives the blit the source and destination surfaces in their sRGB formats
//! while the enable is on (`_mesa_update_renderbuffer_surface`), so llvmpipe's blitter
//! samples an sRGB source through its decode (`lp_build_srgb_to_linear`; GL_LINEAR filters
//! the decoded floats on the float path) and writes an sRGB destination through the
//! shader's encode ([`srgb::shader_value`]); a linear destination gets
//! `round_half_even(c·255)`. Two sRGB surfaces of one format copied texel for texel are
//! a plain copy (`util_try_blit_via_copy_region`), as are blits with the enable off.

use crate::framebuffer::{float_to_ubyte, srgb, Framebuffer};
use crate::texture::sample::INV_255;

/// Which sides of a blit are sRGB-encoded surfaces (the enable on and an sRGB image).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SrgbSides {
    /// The source is decoded when sampled.
    pub src: bool,
    /// The destination encodes what it is given.
    pub dst: bool,
}

impl SrgbSides {
    /// Whether a blit of these sides converts colours (`unscaled`: texel for texel).
    pub fn converts(self, unscaled: bool) -> bool {
        (self.src || self.dst) && !(unscaled && self.src && self.dst)
    }

    /// A source texel as the blitter's shader sees it.
    #[inline]
    fn to_float(self, t: [u8; 4], fma: bool) -> [f32; 4] {
        if self.src {
            crate::texture::srgb::to_float(t, srgb::table(fma))
        } else {
            t.map(|v| v as f32 * INV_255)
        }
    }

    /// The shader's colour `c` as the destination stores it.
    #[inline]
    fn store(self, c: [f32; 4], fma: bool) -> [u8; 4] {
        if self.dst {
            srgb::shader_value(c, fma)
        } else {
            c.map(float_to_ubyte)
        }
    }

    /// The converted colour of source texel `t` (GL_NEAREST or unscaled).
    pub fn texel(self, t: [u8; 4], fma: bool) -> [u8; 4] {
        self.store(self.to_float(t, fma), fma)
    }

    /// The converted GL_LINEAR sample at (u, v) in texels; `eight_bit` is the 8-bit
    /// filter a linear source takes (llvmpipe's AoS path).
    pub fn bilinear(
        self,
        s: &Framebuffer,
        (u, v): (f32, f32),
        fma: bool,
        eight_bit: impl Fn() -> [u8; 4],
    ) -> [u8; 4] {
        if !self.src {
            return self.texel(eight_bit(), fma);
        }
        // The float path: coordinate − 0.5, floor and fraction, taps clamped to the edge,
        // `fmuladd(w, b − a, a)` across, then down.
        let axis = |c: f32, n: usize| {
            let c = c.clamp(0.0, n as f32) - 0.5;
            let f = c.floor();
            let i = f as i64;
            let clamp = |i: i64| i.clamp(0, n as i64 - 1) as usize;
            (clamp(i), clamp(i + 1), c - f)
        };
        let (x0, x1, wx) = axis(u, s.width);
        let (y0, y1, wy) = axis(v, s.height);
        let at = |x: usize, y: usize| self.to_float(s.color[y * s.width + x], fma);
        let lerp = |w: f32, a: [f32; 4], b: [f32; 4]| -> [f32; 4] {
            std::array::from_fn(|i| {
                if fma {
                    w.mul_add(b[i] - a[i], a[i])
                } else {
                    w * (b[i] - a[i]) + a[i]
                }
            })
        };
        let top = lerp(wx, at(x0, y0), at(x1, y0));
        let bot = lerp(wx, at(x0, y1), at(x1, y1));
        self.store(lerp(wy, top, bot), fma)
    }

    /// The multisample resolve (`util_make_fs_msaa_resolve`) of `planes` into the
    /// destination's stored form: the four samples as the shader sees them, summed in
    /// sample order in f32, times 0.25.
    pub fn resolve(self, planes: &[Framebuffer], fma: bool) -> Framebuffer {
        let mut out = planes[0].clone();
        for (i, px) in out.color.iter_mut().enumerate() {
            let mut sum = [0.0f32; 4];
            for p in planes {
                let s = self.to_float(p.color[i], fma);
                for (a, v) in sum.iter_mut().zip(s) {
                    *a += v;
                }
            }
            *px = self.store(sum.map(|v| v * 0.25), fma);
        }
        out
    }
}
