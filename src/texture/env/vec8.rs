//! [`Combine::apply`] on eight fragments at once: the same f32 operations in the same
//! order (separate multiplies and adds, `fsat` as `maxps` with 0 then `minps` with 1,
//! which is NaN → 0 and −0 → +0 like [`super::sat`]), one AVX2 register per channel.
//! The general textured walk ([`crate::fragment::simd_gen`]) runs every unit's
//! environment through it, whatever the mode, the combiner functions or the number of
//! units.

#![cfg(target_arch = "x86_64")]

use super::{Arg, Combine, CombineFn, Operand, Simple, Source};
use crate::simd::F32x8;

/// Four channels (RGBA) of eight fragments.
pub type Vec4 = [F32x8; 4];

/// What eight fragments' combiner reads: the primary colour, this unit's texels, the
/// previous unit's result and every active unit's texels (crossbar).
#[derive(Clone, Copy)]
pub struct Inputs8<'t> {
    /// The primary colour.
    pub frag: Vec4,
    /// This unit's texture values.
    pub tex: Vec4,
    /// The previous unit's result (the primary colour on the first unit).
    pub prev: Vec4,
    /// Every active unit's texture values in slot order (read by GL_TEXTUREn sources).
    pub textures: &'t [Vec4],
}

/// `fsat` on eight lanes.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn sat8(v: F32x8) -> F32x8 {
    // SAFETY: the caller's AVX2 context.
    unsafe { v.max(F32x8::zero()).min(F32x8::splat(1.0)) }
}

/// `1 − v` on eight lanes.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn one_minus(v: F32x8) -> F32x8 {
    // SAFETY: the caller's AVX2 context.
    unsafe { F32x8::splat(1.0).sub(v) }
}

impl Combine {
    /// [`Combine::apply`] on eight fragments.
    ///
    /// # Safety
    /// Must be called from a function compiled with AVX2.
    #[inline(always)]
    pub unsafe fn apply8(&self, inp: &Inputs8<'_>) -> Vec4 {
        // SAFETY: forwarded from the caller.
        unsafe {
            if let Some(sm) = &self.simple {
                return self.apply_simple8(sm, inp);
            }
            self.apply_general8(inp)
        }
    }

    /// [`Combine::apply_simple`] on eight fragments.
    #[inline(always)]
    unsafe fn apply_simple8(&self, sm: &Simple, inp: &Inputs8<'_>) -> Vec4 {
        // SAFETY: the caller's AVX2 context.
        unsafe {
            let r0 = self.value8(sm.rgb.0, inp);
            let a0 = self.value8(sm.a.0, inp)[3];
            let mut out = [r0[0], r0[1], r0[2], a0];
            if let Some(s1) = sm.rgb.1 {
                let r1 = self.value8(s1, inp);
                for c in 0..3 {
                    out[c] = out[c].mul(r1[c]);
                }
            }
            if let Some(s1) = sm.a.1 {
                out[3] = out[3].mul(self.value8(s1, inp)[3]);
            }
            out
        }
    }

    /// The value of source `s`.
    #[inline(always)]
    unsafe fn value8(&self, s: Source, inp: &Inputs8<'_>) -> Vec4 {
        // SAFETY: the caller's AVX2 context.
        unsafe {
            match s {
                Source::Texture => inp.tex,
                Source::TextureN(n) => inp
                    .textures
                    .get(n as usize)
                    .copied()
                    .unwrap_or([F32x8::zero(); 4]),
                Source::Constant => {
                    let k = &self.color;
                    [
                        F32x8::splat(k[0]),
                        F32x8::splat(k[1]),
                        F32x8::splat(k[2]),
                        F32x8::splat(k[3]),
                    ]
                }
                Source::PrimaryColor => inp.frag,
                Source::Previous => inp.prev,
            }
        }
    }

    /// Channel `ch` of argument `a`.
    #[inline(always)]
    unsafe fn arg8(&self, a: Arg, ch: usize, inp: &Inputs8<'_>) -> F32x8 {
        // SAFETY: the caller's AVX2 context.
        unsafe {
            let v = self.value8(a.0, inp);
            match a.1 {
                Operand::SrcColor => v[ch],
                Operand::OneMinusSrcColor => one_minus(v[ch]),
                Operand::SrcAlpha => v[3],
                Operand::OneMinusSrcAlpha => one_minus(v[3]),
            }
        }
    }

    /// The value x of a ONE_MINUS operand (its argument is `1 − x`).
    #[inline(always)]
    unsafe fn minus_of8(&self, a: Arg, ch: usize, inp: &Inputs8<'_>) -> Option<F32x8> {
        // SAFETY: the caller's AVX2 context.
        let v = unsafe { self.value8(a.0, inp) };
        match a.1 {
            Operand::OneMinusSrcColor => Some(v[ch]),
            Operand::OneMinusSrcAlpha => Some(v[3]),
            _ => None,
        }
    }

    /// [`Combine::eval`] on eight fragments.
    #[inline(always)]
    unsafe fn eval8(
        &self,
        f: CombineFn,
        args: &[Arg; 3],
        ch: usize,
        reassoc: bool,
        inp: &Inputs8<'_>,
    ) -> F32x8 {
        // SAFETY: the caller's AVX2 context.
        unsafe {
            let mut a = [F32x8::zero(); 3];
            for (i, ai) in a.iter_mut().enumerate().take(f.num_args()) {
                *ai = self.arg8(args[i], ch, inp);
            }
            match f {
                CombineFn::AddSigned if reassoc => match self.minus_of8(args[0], ch, inp) {
                    // (0.5 + −x) + arg1
                    Some(x) => F32x8::splat(0.5).sub(x).add(a[1]),
                    // (arg0 + −0.5) + arg1
                    None => a[0].sub(F32x8::splat(0.5)).add(a[1]),
                },
                CombineFn::Interpolate => match self.minus_of8(args[2], ch, inp) {
                    Some(x) => a[0].mul(a[2]).add(a[1].mul(x)),
                    None => combine8(f, a),
                },
                _ => combine8(f, a),
            }
        }
    }

    /// [`Combine::apply_general`] on eight fragments.
    #[inline(always)]
    unsafe fn apply_general8(&self, inp: &Inputs8<'_>) -> Vec4 {
        // SAFETY: the caller's AVX2 context.
        unsafe {
            let (reassoc_rgb, reassoc_a) = self.reassoc;
            let shift = self.scale_rgb != 1.0 || self.scale_a != 1.0;
            let mut out = [F32x8::zero(); 4];
            let dot3 = matches!(self.mode_rgb, CombineFn::Dot3Rgb | CombineFn::Dot3Rgba);
            if dot3 {
                let (two, m1) = (F32x8::splat(2.0), F32x8::splat(1.0));
                let mut t0 = [F32x8::zero(); 3];
                let mut t1 = [F32x8::zero(); 3];
                for c in 0..3 {
                    t0[c] = self.arg8(self.args_rgb[0], c, inp).mul(two).sub(m1);
                    t1[c] = self.arg8(self.args_rgb[1], c, inp).mul(two).sub(m1);
                }
                let mut d = t0[0].mul(t1[0]).add(t0[1].mul(t1[1])).add(t0[2].mul(t1[2]));
                if self.scale_rgb == 1.0 {
                    d = sat8(d);
                }
                out[0] = d;
                out[1] = d;
                out[2] = d;
                if self.mode_rgb == CombineFn::Dot3Rgba {
                    out[3] = d;
                }
            } else {
                for (c, o) in out.iter_mut().enumerate().take(3) {
                    let mut v = self.eval8(self.mode_rgb, &self.args_rgb, c, reassoc_rgb, inp);
                    if !shift && self.mode_rgb.saturates() {
                        v = sat8(v);
                    }
                    *o = v;
                }
            }
            if self.mode_rgb != CombineFn::Dot3Rgba {
                let mut v = self.eval8(self.mode_a, &self.args_a, 3, reassoc_a, inp);
                if !shift && self.mode_a.saturates() {
                    v = sat8(v);
                }
                out[3] = v;
            }
            if shift {
                let (srgb, sa) = (F32x8::splat(self.scale_rgb), F32x8::splat(self.scale_a));
                for o in out.iter_mut().take(3) {
                    *o = sat8(o.mul(srgb));
                }
                out[3] = sat8(out[3].mul(sa));
            }
            out
        }
    }
}

/// [`super::combine`] on eight fragments.
///
/// # Safety
/// AVX2 context.
#[inline(always)]
unsafe fn combine8(f: CombineFn, a: [F32x8; 3]) -> F32x8 {
    // SAFETY: the caller's AVX2 context.
    unsafe {
        match f {
            CombineFn::Replace => a[0],
            CombineFn::Modulate => a[0].mul(a[1]),
            CombineFn::Add => a[0].add(a[1]),
            CombineFn::AddSigned => a[0].add(a[1]).sub(F32x8::splat(0.5)),
            CombineFn::Interpolate => a[0].mul(a[2]).add(a[1].mul(one_minus(a[2]))),
            CombineFn::Subtract => a[0].sub(a[1]),
            CombineFn::Dot3Rgb | CombineFn::Dot3Rgba => unreachable!("handled by the caller"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::super::BaseFormat;
    use super::super::{EnvMode, TexEnv};
    use super::*;

    /// `apply8` of eight lanes, on a CPU with AVX2.
    #[target_feature(enable = "avx2")]
    unsafe fn apply8_lanes(
        c: &Combine,
        frag: &[[f32; 4]; 8],
        tex: &[[f32; 4]; 8],
        prev: &[[f32; 4]; 8],
        textures: &[[[f32; 4]; 8]],
    ) -> [[f32; 4]; 8] {
        // SAFETY: AVX2 (this function's feature); every array is 8 lanes.
        unsafe {
            let soa = |v: &[[f32; 4]; 8], ch: usize| {
                let mut a = [0f32; 8];
                for i in 0..8 {
                    a[i] = v[i][ch];
                }
                a
            };
            let vec = |v: &[[f32; 4]; 8]| -> Vec4 {
                let mut o = [F32x8::zero(); 4];
                for (ch, o) in o.iter_mut().enumerate() {
                    *o = F32x8::load(soa(v, ch).as_ptr());
                }
                o
            };
            let texs: Vec<Vec4> = textures.iter().map(vec).collect();
            let out = c.apply8(&Inputs8 {
                frag: vec(frag),
                tex: vec(tex),
                prev: vec(prev),
                textures: &texs,
            });
            let mut r = [[0f32; 4]; 8];
            for (ch, o) in out.iter().enumerate() {
                let a = o.to_array();
                for i in 0..8 {
                    r[i][ch] = a[i];
                }
            }
            r
        }
    }

    /// Every lane of `apply8` is bit for bit `apply` of that lane, over random legacy
    /// modes and combiner states (functions, sources with the crossbar, operands, scales)
    /// and inputs that include 0, 1, −0, out-of-range values and NaN.
    #[test]
    fn apply8_is_apply_per_lane() {
        if !crate::cpu::isa().avx2() {
            return;
        }
        let mut next = crate::test_rng::xorshift32(0x5e17_0054);
        let mut pick = |n: u32| (next() % n) as usize;
        let specials = [0.0, 1.0, -0.0, 0.5, 1.5, -0.25, f32::NAN, 0.999_999_9];
        use CombineFn as F;
        let fns = [
            F::Replace,
            F::Modulate,
            F::Add,
            F::AddSigned,
            F::Interpolate,
            F::Subtract,
            F::Dot3Rgb,
            F::Dot3Rgba,
        ];
        let ops = [
            Operand::SrcColor,
            Operand::OneMinusSrcColor,
            Operand::SrcAlpha,
            Operand::OneMinusSrcAlpha,
        ];
        let modes = [
            EnvMode::Replace,
            EnvMode::Modulate,
            EnvMode::Decal,
            EnvMode::Blend,
            EnvMode::Add,
            EnvMode::Combine,
        ];
        let bases = [
            BaseFormat::Alpha,
            BaseFormat::Luminance,
            BaseFormat::LuminanceAlpha,
            BaseFormat::Intensity,
            BaseFormat::Rgb,
            BaseFormat::Rgba,
        ];
        for round in 0..4000 {
            let src = |pick: &mut dyn FnMut(u32) -> usize| match pick(6) {
                0 => Source::Texture,
                1 => Source::TextureN(pick(3) as u8),
                2 => Source::Constant,
                3 => Source::PrimaryColor,
                _ => Source::Previous,
            };
            let scales = [1.0, 2.0, 4.0];
            let env = TexEnv {
                mode: modes[pick(6)],
                combine_rgb: fns[pick(8)],
                combine_alpha: fns[pick(6)],
                source_rgb: [src(&mut pick), src(&mut pick), src(&mut pick)],
                source_alpha: [src(&mut pick), src(&mut pick), src(&mut pick)],
                operand_rgb: [ops[pick(4)], ops[pick(4)], ops[pick(4)]],
                operand_alpha: [ops[2 + pick(2)], ops[2 + pick(2)], ops[2 + pick(2)]],
                rgb_scale: scales[pick(3)],
                alpha_scale: scales[pick(3)],
                color: [0.25, 0.5, 0.75, 0.125],
            };
            let mut c = Combine::derive(&env, bases[pick(6)]);
            let unit = pick(3);
            c.canonicalise(unit, round % 2 == 0, |n| (n < 2).then_some(n));
            let val = |pick: &mut dyn FnMut(u32) -> usize| {
                let mut v = [[0f32; 4]; 8];
                for l in v.iter_mut() {
                    for x in l.iter_mut() {
                        *x = if pick(4) == 0 {
                            specials[pick(8)]
                        } else {
                            pick(1 << 16) as f32 / 65535.0
                        };
                    }
                }
                v
            };
            let (frag, tex, prev) = (val(&mut pick), val(&mut pick), val(&mut pick));
            let textures = [val(&mut pick), val(&mut pick)];
            // SAFETY: AVX2 was detected above.
            let got = unsafe { apply8_lanes(&c, &frag, &tex, &prev, &textures) };
            for i in 0..8 {
                let all = [textures[0][i], textures[1][i]];
                let want = c.apply(frag[i], tex[i], prev[i], &all);
                for ch in 0..4 {
                    let (g, w) = (got[i][ch], want[ch]);
                    assert!(
                        g.to_bits() == w.to_bits() || (g.is_nan() && w.is_nan()),
                        "{c:?} lane {i} ch {ch}: {g} instead of {w}"
                    );
                }
            }
        }
    }
}
