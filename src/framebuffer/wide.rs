//! The wide colour plane: colour buffers of more than 8 bits per channel (OSMesa
//! GL_UNSIGNED_SHORT and GL_FLOAT buffers, GL_RGBA16/16F/32F renderbuffers), kept at the
//! precision llvmpipe stores them in (docs/llvmpipe-rules.md §23).
//!
//! A wide framebuffer keeps its 8-bit plane as well, as a *mirror*: whatever writes the
//! wide plane writes [`WideKind::mirror8`] of the value into the 8-bit plane too. A path
//! that only knew 8-bit colour would write just the 8-bit plane (the pixel rectangles,
//! blits, resolves, copies and accumulation all write the wide plane, through
//! [`super::Framebuffer::put_float`] or directly); a pixel whose 8-bit value no longer is
//! the mirror of its wide value was last written by such a path, and reads as that 8-bit
//! value
//! ([`super::Framebuffer::wide_at`], [`super::samples::PlaneRows::wide_at`]).

use super::float_to_ubyte;
#[cfg(target_arch = "x86_64")]
use crate::simd::{F32x8, I32x8};

/// The precision of a colour buffer wider than 8 bits. The plane holds every channel as
/// an f32: see each variant for what that f32 is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WideKind {
    /// R16G16B16A16_UNORM (R16G16B16_UNORM): the channel's integer, 0..=65535.
    Unorm16,
    /// R16G16B16A16_FLOAT: the half float's value (converted toward zero).
    Float16,
    /// R32G32B32A32_FLOAT: the float.
    Float32,
}

#[cfg(target_arch = "x86_64")]
impl WideKind {
    /// [`WideKind::mirror8`] of each lane (stored channel values) as an integer 0..=255:
    /// clamped with `max(f, 0)` (NaN gives 0) and `min(1)`, then `·255` and `vcvtps2dq`
    /// (ties to even), the scalar function's operations. Shared by the 8-lane store
    /// (channel-major lanes) and the AVX2 copy-out (pixel-major lanes).
    ///
    /// # Safety
    /// AVX2 context.
    #[inline(always)]
    pub unsafe fn mirror8_lanes(self, v: F32x8) -> I32x8 {
        // SAFETY: the caller's AVX2 context.
        unsafe {
            let f = match self {
                WideKind::Unorm16 => v.mul(F32x8::splat(1.0 / 65535.0f32)),
                _ => v,
            };
            let sat = f.max(F32x8::zero()).min(F32x8::splat(1.0));
            sat.mul(F32x8::splat(255.0)).to_i32()
        }
    }

    /// [`WideKind::from_u8`] of each lane (8-bit channel values 0..=255).
    ///
    /// # Safety
    /// AVX2 context.
    #[inline(always)]
    pub unsafe fn from_u8_lanes(self, c: I32x8) -> F32x8 {
        // SAFETY: the caller's AVX2 context.
        unsafe {
            let scale = match self {
                WideKind::Unorm16 => 257.0,
                _ => 1.0 / 255.0f32,
            };
            c.to_f32().mul(F32x8::splat(scale))
        }
    }
}

impl WideKind {
    /// Bits per channel (glGet(GL_RED_BITS …)).
    pub fn bits(self) -> i32 {
        match self {
            WideKind::Unorm16 | WideKind::Float16 => 16,
            WideKind::Float32 => 32,
        }
    }

    /// Whether the buffer stores floats (colours are not clamped: GL_CLAMP_FRAGMENT_COLOR
    /// is FIXED_ONLY).
    pub fn is_float(self) -> bool {
        self != WideKind::Unorm16
    }

    /// The stored form of 1.0 (the alpha of a buffer without alpha).
    #[inline(always)]
    pub fn one(self) -> f32 {
        match self {
            WideKind::Unorm16 => 65535.0,
            _ => 1.0,
        }
    }

    /// A shader's output channel as llvmpipe stores it: unorm16 clamps to [0, 1] (NaN
    /// gives 0) and converts with `lp_build_clamped_float_to_unsigned_norm`
    /// (`c·(65535/65536) + 128`, the low 16 mantissa bits); floats are not clamped, half
    /// floats are converted toward zero ([`f16_round`]).
    #[inline(always)]
    pub fn from_shader(self, c: f32) -> f32 {
        match self {
            WideKind::Unorm16 => unorm16(c) as f32,
            WideKind::Float16 => f16_round(c),
            WideKind::Float32 => c,
        }
    }

    /// A glClear value as gallium's fast clear packs it (`util_pack_color_union`, the
    /// generated format packers): unorm16 is `util_iround(clamp(c)·65535)`, which on
    /// x86-64 is `(int)(f32(c·65535) + 0.5)` (two f32 roundings, then truncation: halves
    /// round up); floats are stored as they are, half floats toward zero.
    pub fn from_clear(self, c: f32) -> f32 {
        match self {
            WideKind::Unorm16 => {
                let c = if c > 0.0 { c.min(1.0) } else { 0.0 };
                ((c * 65535.0f32) + 0.5f32).trunc()
            }
            WideKind::Float16 => f16_round(c),
            WideKind::Float32 => c,
        }
    }

    /// A stored channel as a float (glReadPixels of GL_FLOAT, blits, the user's float
    /// buffer): unorm16 is `q · f32(1/65535)`, as gallium's format unpacking does.
    #[inline(always)]
    pub fn to_float(self, v: f32) -> f32 {
        match self {
            WideKind::Unorm16 => v * (1.0 / 65535.0f32),
            _ => v,
        }
    }

    /// A stored channel as a 16-bit unsigned integer (glReadPixels of GL_UNSIGNED_SHORT,
    /// the user's 16-bit buffer).
    pub fn to_u16(self, v: f32) -> u16 {
        match self {
            WideKind::Unorm16 => v as u16,
            _ => {
                let c = if v > 0.0 { v.min(1.0) } else { 0.0 };
                (c * 65535.0).round_ties_even() as u16
            }
        }
    }

    /// The 8-bit plane's mirror of a stored channel.
    #[inline(always)]
    pub fn mirror8(self, v: f32) -> u8 {
        float_to_ubyte(self.to_float(v))
    }

    /// The 8-bit mirror of a stored pixel.
    #[inline(always)]
    pub fn mirror(self, v: [f32; 4]) -> [u8; 4] {
        v.map(|c| self.mirror8(c))
    }

    /// The stored value of an 8-bit pixel written by a path that only knows 8 bits.
    #[inline]
    pub fn from_u8(self, c: [u8; 4]) -> [f32; 4] {
        match self {
            WideKind::Unorm16 => c.map(|v| v as f32 * 257.0),
            _ => c.map(|v| v as f32 * (1.0 / 255.0f32)),
        }
    }
}

/// Float to unorm16 as llvmpipe's shader output does: clamp to [0,1] (NaN gives 0), then
/// `c·(65535/65536) + 2^7` in f32 (round to nearest even) and the low 16 mantissa bits.
#[inline(always)]
pub fn unorm16(c: f32) -> u16 {
    let c = if c > 0.0 { c } else { 0.0 };
    let c = if c < 1.0 { c } else { 1.0 };
    (c * (65535.0f32 / 65536.0f32) + 128.0f32).to_bits() as u16
}

/// `x` converted to a half float as llvmpipe's store does (`lp_build_float_to_half`:
/// F16C's `vcvtps2ph` with rounding mode 3, toward zero): finite values above the
/// largest half (65504) give 65504, infinities and NaN stay, small values become half
/// denormals or ±0.
pub fn f16_round(x: f32) -> f32 {
    if !x.is_finite() {
        return x;
    }
    let a = x.abs();
    if a >= 65504.0 {
        return 65504.0f32.copysign(x);
    }
    // Half keeps 11 significant bits down to 2^-14; below, a fixed step of 2^-24.
    let step = if a < 2.0f32.powi(-14) {
        2.0f32.powi(-24)
    } else {
        // The exponent of `a`, then the step of 11 significant bits at that exponent.
        let e = ((a.to_bits() >> 23) as i32) - 127;
        2.0f32.powi(e - 10)
    };
    // Exact: `a / step` is a power-of-two scaling, and its truncation is the half's.
    ((a / step).trunc() * step).copysign(x)
}

impl super::Framebuffer {
    /// Colour pixel `i` (y-down row-major) as a sampler or the blitter reads it, as RGBA
    /// float: a wide buffer's stored value ([`WideKind::to_float`]), an 8-bit one's
    /// `u · f32(1/255)` (`lp_build_unsigned_norm_to_float`).
    #[inline]
    pub fn float_at(&self, i: usize) -> [f32; 4] {
        match self.wide {
            Some(k) => self.wide_at(i).map(|v| k.to_float(v)),
            None => self.color_at(i).map(|u| u as f32 * (1.0f32 / 255.0)),
        }
    }

    /// Stores the shader output `c` at colour pixel `i` (y-down row-major), converted as
    /// llvmpipe's fragment output is for the buffer's format: a wide buffer's
    /// [`WideKind::from_shader`] (with its 8-bit mirror), an 8-bit buffer's clamped
    /// `round_half_even(c·255)`. Buffers without alpha store 1.
    #[inline]
    pub fn put_float(&mut self, i: usize, c: [f32; 4]) {
        match self.wide {
            Some(k) => {
                let mut v = c.map(|x| k.from_shader(x));
                if !self.format.has_alpha() {
                    v[3] = k.one();
                }
                self.wide_color[i] = v;
                self.color[i] = k.mirror(v);
            }
            None => self.color[i] = self.store_rgba8(c.map(float_to_ubyte)),
        }
    }
}

impl super::Target<'_> {
    /// Stored wide colour of pixel `j` of the band (its recorded clears written): as
    /// [`super::Framebuffer::wide_at`].
    #[inline]
    pub fn wide_at(&self, j: usize) -> [f32; 4] {
        let k = self.wide.expect("a wide target");
        let (w, c8) = (self.wide_color[j], self.color[j]);
        if k.mirror(w) == c8 {
            w
        } else {
            k.from_u8(c8)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unorm16_ends_and_midpoints() {
        assert_eq!(unorm16(0.0), 0);
        assert_eq!(unorm16(1.0), 65535);
        assert_eq!(unorm16(2.0), 65535);
        assert_eq!(unorm16(-1.0), 0);
        assert_eq!(unorm16(f32::NAN), 0);
        assert_eq!(unorm16(0.5), 32768);
        for q in [1u16, 100, 32767, 65534] {
            assert_eq!(unorm16(q as f32 / 65535.0), q);
        }
    }

    #[test]
    fn unorm16_round_trips_and_clear_rounding() {
        // A stored unorm16 read as float and converted back is itself (blits are exact).
        for q in 0..=65535u16 {
            assert_eq!(unorm16(WideKind::Unorm16.to_float(q as f32)), q);
        }
        // The fast clear rounds halves up (util_iround): f32(0.3·65535) is 19660.5.
        assert_eq!(WideKind::Unorm16.from_clear(0.3), 19661.0);
        assert_eq!(WideKind::Unorm16.from_clear(1.5), 65535.0);
        assert_eq!(WideKind::Unorm16.from_clear(-0.25), 0.0);
        assert_eq!(WideKind::Float32.from_clear(-0.25), -0.25);
    }

    #[test]
    fn half_rounding() {
        assert_eq!(f16_round(1.0), 1.0);
        assert_eq!(f16_round(65504.0), 65504.0);
        assert_eq!(f16_round(65519.0), 65504.0);
        assert_eq!(f16_round(1e9), 65504.0);
        assert_eq!(f16_round(f32::INFINITY), f32::INFINITY);
        // Toward zero: 1 + 3·2^-11 lies between 1 + 2^-10 and 1 + 2^-9.
        assert_eq!(
            f16_round(1.0 + 3.0 * 2.0f32.powi(-11)),
            1.0 + 2.0f32.powi(-10)
        );
        assert_eq!(f16_round(2.0f32.powi(-25)), 0.0);
        assert_eq!(f16_round(-0.1), -0.099975586);
        for k in 0..1024u32 {
            let v = 1.0 + k as f32 / 1024.0;
            assert_eq!(f16_round(v), v);
        }
    }
}
