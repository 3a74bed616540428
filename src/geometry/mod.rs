//! Geometry: vertex fetch ([`fetch`], and where a draw's vertices come from with the
//! post-transform cache, [`source`]), primitive assembly ([`assemble`]), homogeneous
//! clipping ([`clip`]), the draw module's cull, offset and unfilled stages ([`unfilled`]),
//! triangle setup ([`setup`], eight at a time in [`setup8`]), the primitive stages of
//! feedback and selection ([`feedback`]), and trivial rejection from positions alone,
//! before the rest of the vertex stage ([`reject`]), whole runs of a display list's
//! positions at a time where their boxes allow ([`boxes`]).
//!
//! Vertices travel as [`ClipVertex`]: clip-space position, window position (x, y in
//! y-down raster space, z, 1/w) and up to [`MAX_VARY`] floats of varyings (colour first).

pub mod assemble;
pub mod boxes;
pub mod clip;
pub mod feedback;
pub mod fetch;
pub mod reject;
pub mod setup;
pub mod setup8;
pub mod source;
pub mod stored;
pub mod unfilled;

/// The number of varying floats a vertex carries: primary colour (0..4), secondary colour
/// (4..8), the fog coordinate (8), the texture coordinates (s, t, r, q) of each enabled
/// unit from [`VARY_TEX`], compacted, and with two-sided lighting the back colours (8
/// floats) after the last texture unit.
pub const MAX_VARY: usize = VARY_TEX + 4 * crate::pipe::MAX_TEXTURE_UNITS + 8;

/// Where the secondary (specular) colour starts among the varyings.
pub const VARY_SPEC: usize = 4;
/// The fog coordinate's varying.
pub const VARY_FOG: usize = 8;
/// Where the first enabled texture unit's coordinates start among the varyings.
pub const VARY_TEX: usize = 12;

/// A vertex after the vertex stage: what clipping, setup and interpolation read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClipVertex {
    /// Clip-space position.
    pub clip: [f32; 4],
    /// Window position: x, y (y-down raster space), z in [0,1] before clamping, and 1/w.
    pub win: [f32; 4],
    /// Clip mask: bit 0 x>w, 1 x<-w, 2 y>w, 3 y<-w, 4 z<-w (z<0 under
    /// GL_ZERO_TO_ONE), 5 z>w (llvmpipe's order),
    /// bits 6.. the user clip planes.
    pub mask: ClipMask,
    /// Varyings: [0..4] primary colour, [4..8] secondary colour, then texture coordinates.
    pub vary: [f32; MAX_VARY],
    /// The attenuated point size (GL_POINT_DISTANCE_ATTENUATION), when the vertex stage
    /// writes one.
    pub psize: f32,
}

impl Default for ClipVertex {
    fn default() -> Self {
        ClipVertex {
            clip: [0.0; 4],
            win: [0.0; 4],
            mask: 0,
            vary: [0.0; MAX_VARY],
            psize: 1.0,
        }
    }
}

/// The clip-space conventions of GL_ARB_clip_control, as plain flags.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ClipConvention {
    /// GL_UPPER_LEFT origin: clip-space y points down the window (the viewport's y scale
    /// is negated, front faces and the horizontal-edge fill rule swap).
    pub upper_left: bool,
    /// GL_ZERO_TO_ONE depth: the near plane is `z >= 0` (gallium's `clip_halfz`) and the
    /// viewport maps z in [0, 1] to [n, f].
    pub zero_to_one: bool,
}

/// The viewport transform as llvmpipe's vertex stage holds it (y flipped for the
/// bottom-up OSMesa buffer, so window y is in y-down raster space).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Viewport {
    /// x, y, z scale.
    pub scale: [f32; 3],
    /// x, y, z translate.
    pub translate: [f32; 3],
    /// Whether the near clip plane is `z >= 0` instead of `z >= -w` (GL_ZERO_TO_ONE: the
    /// draw module's `clip_halfz`). It travels with the transform because the clip mask,
    /// the clipper and the z mapping all follow it.
    pub halfz: bool,
}

impl Viewport {
    /// Builds the transform from glViewport/glDepthRange and the framebuffer height, for
    /// the y-down window.
    pub fn new(vp: [i32; 4], depth_range: [f64; 2], fb_height: usize) -> Self {
        Viewport::oriented(vp, depth_range, fb_height, true)
    }

    /// As [`Viewport::new`]; `flip` false gives the unflipped transform llvmpipe uses for
    /// framebuffer objects (window y = GL y).
    pub fn oriented(vp: [i32; 4], depth_range: [f64; 2], fb_height: usize, flip: bool) -> Self {
        Viewport::with_convention(vp, depth_range, fb_height, flip, ClipConvention::default())
    }

    /// As [`Viewport::oriented`] under the clip-control convention `cc`, as Mesa's
    /// `_mesa_get_viewport_xform` and `st_update_viewport` build it: the GL transform has
    /// y scale `±0.5f·h` (negative for GL_UPPER_LEFT) and translate `0.5f·h + y`; the
    /// window buffer then negates the scale and takes `fb_height − translate`. z is
    /// `0.5·(f−n)`, `0.5·(n+f)` in double for GL_NEGATIVE_ONE_TO_ONE, `f−n`, `n` for
    /// GL_ZERO_TO_ONE, each rounded to f32.
    pub fn with_convention(
        vp: [i32; 4],
        depth_range: [f64; 2],
        fb_height: usize,
        flip: bool,
        cc: ClipConvention,
    ) -> Self {
        let (x, y, w, h) = (vp[0] as f32, vp[1] as f32, vp[2] as f32, vp[3] as f32);
        let (n, f) = (depth_range[0], depth_range[1]);
        let half_h = 0.5f32 * h;
        let gl_sy = if cc.upper_left { -half_h } else { half_h };
        let (sy, ty) = if flip {
            (-gl_sy, fb_height as f32 - (half_h + y))
        } else {
            (gl_sy, half_h + y)
        };
        let (sz, tz) = if cc.zero_to_one {
            ((f - n) as f32, n as f32)
        } else {
            ((0.5 * (f - n)) as f32, (0.5 * (n + f)) as f32)
        };
        Viewport {
            scale: [0.5 * w, sy, sz],
            translate: [0.5 * w + x, ty, tz],
            halfz: cc.zero_to_one,
        }
    }

    /// Window coordinates of an unclipped vertex, as llvmpipe's vertex shader computes them:
    /// `fmuladd(clip * (1/w), scale, translate)`, fused where the CPU has FMA.
    #[inline]
    pub fn apply_shader(&self, clip: [f32; 4], fma: bool) -> [f32; 4] {
        let inv_w = 1.0f32 / clip[3];
        let mut out = [0f32; 4];
        for i in 0..3 {
            out[i] = madd(clip[i] * inv_w, self.scale[i], self.translate[i], fma);
        }
        out[3] = inv_w;
        out
    }

    /// Window coordinates of a vertex made by the clipper (plain C arithmetic, never fused).
    #[inline]
    pub fn apply_clipper(&self, clip: [f32; 4]) -> [f32; 4] {
        let oow = 1.0f32 / clip[3];
        let mut out = [0f32; 4];
        for i in 0..3 {
            out[i] = clip[i] * oow * self.scale[i] + self.translate[i];
        }
        out[3] = oow;
        out
    }
}

/// `a * b + c`, fused (one rounding) when `fma`, else two roundings: llvmpipe's
/// `llvm.fmuladd`, whose fusing depends on the host CPU.
#[inline(always)]
pub fn madd(a: f32, b: f32, c: f32, fma: bool) -> f32 {
    if fma {
        crate::simd::mul_add_fused(a, b, c)
    } else {
        a * b + c
    }
}

/// `v` rounded to the nearest integer, ties to even (`f32::round_ties_even`), without a
/// call into libm on CPUs without SSE4.1: adding and subtracting 2^23 rounds in the
/// default rounding mode; values of 2^23 and more (and NaN, infinities) are returned as
/// they are, already integral.
#[inline(always)]
pub fn round_even(v: f32) -> f32 {
    const BIG: f32 = 8_388_608.0;
    if v.abs() < BIG {
        let c = BIG.copysign(v);
        (v + c) - c
    } else {
        v
    }
}

/// Whether this CPU fuses multiply-adds (then llvmpipe does too).
pub fn cpu_has_fma() -> bool {
    crate::cpu::isa().fused()
}

/// A vertex's clip mask: the six view-volume bits, then one bit per user clip plane.
pub type ClipMask = u16;

/// The user clip-plane bits of a clip-space position, as llvmpipe's vertex stage tests
/// them: `0 > ((a·x ⊕ b·y) ⊕ c·z) ⊕ d·w` where ⊕ is `fmuladd` (fused on FMA hosts), so a
/// NaN distance sets no bit. `planes` are clip-space planes, `enabled` their bits.
#[inline]
pub fn user_clip_mask(c: [f32; 4], planes: &[[f32; 4]; 8], enabled: u8, fma: bool) -> ClipMask {
    let mut mask = 0;
    let mut bits = enabled;
    while bits != 0 {
        let i = bits.trailing_zeros() as usize;
        bits &= bits - 1;
        let p = planes[i];
        let mut sum = p[0] * c[0];
        for k in 1..4 {
            sum = madd(p[k], c[k], sum, fma);
        }
        if 0.0 > sum {
            mask |= 1 << (6 + i);
        }
    }
    mask
}

/// The clip mask of a clip-space position (strict tests: on the plane is inside). The
/// tests are written negated so that a NaN coordinate counts as outside (the clipper then
/// drops the primitive); for every non-NaN input they equal the plain `x > w` tests.
/// `halfz` (GL_ZERO_TO_ONE) moves the near plane to `z >= 0`, as the draw module's
/// `clip_halfz` mask does (`0 > z`).
#[inline]
#[allow(clippy::neg_cmp_op_on_partial_ord)] // deliberate: NaN must count as outside
pub fn clip_mask(c: [f32; 4], halfz: bool) -> ClipMask {
    let [x, y, z, w] = c;
    let near = if halfz { z } else { z + w };
    ((!(x <= w)) as u8
        | ((!(x + w >= 0.0)) as u8) << 1
        | ((!(y <= w)) as u8) << 2
        | ((!(y + w >= 0.0)) as u8) << 3
        | ((!(near >= 0.0)) as u8) << 4
        | ((!(z <= w)) as u8) << 5) as ClipMask
}

#[cfg(test)]
mod tests {
    use super::madd;

    #[test]
    fn fused_madd_rounds_once_like_mul_add() {
        let mut rng = crate::test_rng::xorshift32(0x1234_5678);
        let mut next = || {
            let x = rng();
            f32::from_bits((x & 0x3fff_ffff) | 0x3000_0000) * if x & 1 == 0 { 1.0 } else { -1.0 }
        };
        for _ in 0..100_000 {
            let (a, b, c) = (next(), next(), next());
            let want = a.mul_add(b, c);
            assert_eq!(madd(a, b, c, true).to_bits(), want.to_bits(), "{a} {b} {c}");
            assert_eq!(madd(a, b, c, false).to_bits(), (a * b + c).to_bits());
        }
        // A case where fusing changes the result.
        let a = 1.0 + 2.0 * f32::EPSILON;
        assert_eq!(madd(a, a, -1.0, true), a.mul_add(a, -1.0));
        assert_ne!(madd(a, a, -1.0, true), madd(a, a, -1.0, false));
    }
}
