//! [`Combine::apply`] on eight fragments at once: the combiner's one implementation
//! (generic over [`Lane`]) on AVX2 registers, one per channel. The same f32 operations
//! in the same order (separate multiplies and adds, `fsat` as `maxps` with 0 then `minps`
//! with 1, which is NaN → 0 and −0 → +0 like [`super::sat`]). The general textured walk
//! ([`crate::fragment::simd_gen`]) runs every unit's environment through it, whatever the
//! mode, the combiner functions or the number of units.

#![cfg(target_arch = "x86_64")]

use super::{Combine, Inputs, Lane};
use crate::simd::F32x8;

/// Four channels (RGBA) of eight fragments.
pub type Vec4 = [F32x8; 4];

/// What eight fragments' combiner reads (see [`Inputs`]).
pub type Inputs8<'t> = Inputs<'t, F32x8>;

impl Lane for F32x8 {
    #[inline(always)]
    unsafe fn splat(v: f32) -> Self {
        // SAFETY: the caller's AVX2 context.
        unsafe { F32x8::splat(v) }
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        F32x8::add(self, o)
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        F32x8::sub(self, o)
    }
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        F32x8::mul(self, o)
    }
    #[inline(always)]
    fn sat(self) -> Self {
        // SAFETY: AVX2 as `self` proves.
        let (zero, one) = unsafe { (F32x8::zero(), F32x8::splat(1.0)) };
        self.max(zero).min(one)
    }
}

impl Combine {
    /// [`Combine::apply`] on eight fragments.
    ///
    /// # Safety
    /// Must be called from a function compiled with AVX2.
    #[inline(always)]
    pub unsafe fn apply8(&self, inp: &Inputs8<'_>) -> Vec4 {
        // SAFETY: forwarded from the caller.
        unsafe { self.apply_lanes(inp) }
    }
}

#[cfg(test)]
mod tests {
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
        for round in 0..4000 {
            let mut c = super::super::tests::random_combine(&mut pick);
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
