//! The evaluation of a derived combiner ([`Combine::apply`]), written once over the
//! [`Lane`] it computes in: one fragment's `f32`, or eight fragments' AVX2 lanes
//! ([`super::vec8`]). See [`super`] for the arithmetic and the rewrites it reproduces.

use super::{Arg, Combine, CombineFn, Operand, Simple, Source};

/// The values the combiner computes with: one fragment's `f32` ([`Combine::apply`]), or
/// eight fragments' lanes ([`vec8`], `F32x8`). The combiner is written once over this
/// trait, so that both evaluate the same f32 operations in the same order.
pub trait Lane: Copy {
    /// `v` in every lane.
    ///
    /// # Safety
    /// The lane type's instruction set (AVX2 for eight lanes).
    unsafe fn splat(v: f32) -> Self;
    /// `self + o`.
    fn add(self, o: Self) -> Self;
    /// `self − o`.
    fn sub(self, o: Self) -> Self;
    /// `self · o`.
    fn mul(self, o: Self) -> Self;
    /// llvmpipe's `fsat` ([`sat`]: clamp to [0, 1], NaN → 0, −0 → +0).
    fn sat(self) -> Self;
}

impl Lane for f32 {
    #[inline(always)]
    unsafe fn splat(v: f32) -> Self {
        v
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        self + o
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        self - o
    }
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        self * o
    }
    #[inline(always)]
    fn sat(self) -> Self {
        sat(self)
    }
}

/// What the combiner reads, in lanes `L`: the primary colour, this unit's texel, the
/// previous unit's result and every active unit's texel (crossbar).
#[derive(Clone, Copy)]
pub struct Inputs<'t, L> {
    /// The primary colour.
    pub frag: [L; 4],
    /// This unit's texture values.
    pub tex: [L; 4],
    /// The previous unit's result (the primary colour on the first unit).
    pub prev: [L; 4],
    /// Every active unit's texture values in slot order (read by GL_TEXTUREn sources).
    pub textures: &'t [[L; 4]],
}

impl Combine {
    /// Evaluates the combiner. `textures` holds every active unit's texture value, in the
    /// order of [`Combine::canonicalise`]'s slots, for GL_TEXTUREn sources (only read
    /// when `crossbar`; missing entries read as zero, as Mesa's shader does for disabled
    /// units).
    ///
    /// Every helper is `#[inline(always)]` (no closures): a closure left out of line
    /// is called per channel and loses the caller's target features.
    #[inline(always)]
    pub fn apply(
        &self,
        frag: [f32; 4],
        tex: [f32; 4],
        prev: [f32; 4],
        textures: &[[f32; 4]],
    ) -> [f32; 4] {
        let inp = Inputs {
            frag,
            tex,
            prev,
            textures,
        };
        // SAFETY: f32 lanes need no instruction set.
        unsafe { self.apply_lanes(&inp) }
    }

    /// [`Combine::apply`] on lanes `L`.
    ///
    /// # Safety
    /// `L`'s instruction set ([`Lane::splat`]).
    #[inline(always)]
    pub(super) unsafe fn apply_lanes<L: Lane>(&self, inp: &Inputs<'_, L>) -> [L; 4] {
        // SAFETY: forwarded from the caller.
        unsafe {
            if let Some(sm) = &self.simple {
                return self.apply_simple(sm, inp);
            }
            self.apply_general(inp)
        }
    }

    /// [`Combine::apply`] of a [`Simple`] combiner: the same products.
    #[inline(always)]
    unsafe fn apply_simple<L: Lane>(&self, sm: &Simple, inp: &Inputs<'_, L>) -> [L; 4] {
        // SAFETY: the caller's instruction set for `L`.
        unsafe {
            let r0 = self.value(sm.rgb.0, inp);
            let a0 = self.value(sm.a.0, inp)[3];
            let mut out = [r0[0], r0[1], r0[2], a0];
            if let Some(s1) = sm.rgb.1 {
                let r1 = self.value(s1, inp);
                for c in 0..3 {
                    out[c] = out[c].mul(r1[c]);
                }
            }
            if let Some(s1) = sm.a.1 {
                out[3] = out[3].mul(self.value(s1, inp)[3]);
            }
            out
        }
    }

    /// The value of source `s`.
    #[inline(always)]
    unsafe fn value<L: Lane>(&self, s: Source, inp: &Inputs<'_, L>) -> [L; 4] {
        // SAFETY: the caller's instruction set for `L`.
        unsafe {
            match s {
                Source::Texture => inp.tex,
                Source::TextureN(n) => match inp.textures.get(n as usize) {
                    Some(v) => *v,
                    None => [L::splat(0.0); 4],
                },
                Source::Constant => {
                    let k = &self.color;
                    [
                        L::splat(k[0]),
                        L::splat(k[1]),
                        L::splat(k[2]),
                        L::splat(k[3]),
                    ]
                }
                Source::PrimaryColor => inp.frag,
                Source::Previous => inp.prev,
            }
        }
    }

    /// Channel `ch` of argument `a`.
    #[inline(always)]
    unsafe fn arg<L: Lane>(&self, a: Arg, ch: usize, inp: &Inputs<'_, L>) -> L {
        // SAFETY: the caller's instruction set for `L`.
        unsafe {
            let v = self.value(a.0, inp);
            match a.1 {
                Operand::SrcColor => v[ch],
                Operand::OneMinusSrcColor => L::splat(1.0).sub(v[ch]),
                Operand::SrcAlpha => v[3],
                Operand::OneMinusSrcAlpha => L::splat(1.0).sub(v[3]),
            }
        }
    }

    /// The value x of a ONE_MINUS operand (its argument is `1 − x`).
    #[inline(always)]
    unsafe fn minus_of<L: Lane>(&self, a: Arg, ch: usize, inp: &Inputs<'_, L>) -> Option<L> {
        // SAFETY: the caller's instruction set for `L`.
        let v = unsafe { self.value(a.0, inp) };
        match a.1 {
            Operand::OneMinusSrcColor => Some(v[ch]),
            Operand::OneMinusSrcAlpha => Some(v[3]),
            _ => None,
        }
    }

    /// Function `f` of `args` on channel `ch`, before saturation and scale.
    #[inline(always)]
    unsafe fn eval<L: Lane>(
        &self,
        f: CombineFn,
        args: &[Arg; 3],
        ch: usize,
        reassoc: bool,
        inp: &Inputs<'_, L>,
    ) -> L {
        // SAFETY: the caller's instruction set for `L`.
        unsafe {
            let mut a = [L::splat(0.0); 3];
            for (i, ai) in a.iter_mut().enumerate().take(f.num_args()) {
                *ai = self.arg(args[i], ch, inp);
            }
            match f {
                CombineFn::AddSigned if reassoc => {
                    add_signed(a[0], a[1], self.minus_of(args[0], ch, inp))
                }
                // `1 − arg2` with arg2 = `1 − x` folds to x (`#a + −(b + #c)` →
                // `(#a − #c) + −b`, then `0 + x` → x).
                CombineFn::Interpolate => match self.minus_of(args[2], ch, inp) {
                    Some(x) => a[0].mul(a[2]).add(a[1].mul(x)),
                    None => combine(f, a),
                },
                _ => combine(f, a),
            }
        }
    }

    /// [`Combine::apply`] of any combiner.
    #[inline(always)]
    unsafe fn apply_general<L: Lane>(&self, inp: &Inputs<'_, L>) -> [L; 4] {
        // SAFETY: the caller's instruction set for `L`.
        unsafe {
            let (reassoc_rgb, reassoc_a) = self.reassoc;
            let shift = self.scale_rgb != 1.0 || self.scale_a != 1.0;
            let mut out = [L::splat(0.0); 4];
            let dot3 = matches!(self.mode_rgb, CombineFn::Dot3Rgb | CombineFn::Dot3Rgba);
            if dot3 {
                let (two, m1) = (L::splat(2.0), L::splat(-1.0));
                let mut t0 = [L::splat(0.0); 3];
                let mut t1 = [L::splat(0.0); 3];
                for c in 0..3 {
                    t0[c] = self.arg(self.args_rgb[0], c, inp).mul(two).add(m1);
                    t1[c] = self.arg(self.args_rgb[1], c, inp).mul(two).add(m1);
                }
                let mut d = t0[0].mul(t1[0]).add(t0[1].mul(t1[1])).add(t0[2].mul(t1[2]));
                if self.scale_rgb == 1.0 {
                    d = d.sat();
                }
                out[0] = d;
                out[1] = d;
                out[2] = d;
                if self.mode_rgb == CombineFn::Dot3Rgba {
                    out[3] = d;
                }
            } else {
                for (c, o) in out.iter_mut().enumerate().take(3) {
                    let mut v = self.eval(self.mode_rgb, &self.args_rgb, c, reassoc_rgb, inp);
                    if !shift && self.mode_rgb.saturates() {
                        v = v.sat();
                    }
                    *o = v;
                }
            }
            if self.mode_rgb != CombineFn::Dot3Rgba {
                let mut v = self.eval(self.mode_a, &self.args_a, 3, reassoc_a, inp);
                if !shift && self.mode_a.saturates() {
                    v = v.sat();
                }
                out[3] = v;
            }
            if shift {
                let (srgb, sa) = (L::splat(self.scale_rgb), L::splat(self.scale_a));
                for o in out.iter_mut().take(3) {
                    *o = o.mul(srgb).sat();
                }
                out[3] = out[3].mul(sa).sat();
            }
            out
        }
    }
}

/// Clamp to [0,1], NaN → 0 (llvmpipe's fsat).
#[inline(always)]
pub fn sat(v: f32) -> f32 {
    if v > 0.0 {
        v.min(1.0)
    } else {
        0.0
    }
}

/// ADD_SIGNED as llvmpipe evaluates Mesa's `(arg0 + arg1) + -0.5`.
///
/// NIR's `nir_opt_algebraic` rewrites it before llvmpipe sees it: "propagate constants up
/// addition chains", `(a + b) + #c → (a + #c) + b` (a, b not constants, both adds used
/// once; the first match keeps the operand order, so the constant goes to arg0), gives
/// `(arg0 + -0.5) + arg1`. When arg0 is a ONE_MINUS operand, `1 − x` is `1 + (−x)`, and
/// the constant-reassociation rule `#a + (b + #c) → (#a + #c) + b` folds it further into
/// `(0.5 − x) + arg1`. `minus0` is that x.
///
/// # Safety
/// `L`'s instruction set.
#[inline(always)]
unsafe fn add_signed<L: Lane>(a0: L, a1: L, minus0: Option<L>) -> L {
    // SAFETY: the caller's instruction set for `L`.
    unsafe {
        match minus0 {
            Some(x) => L::splat(0.5).sub(x).add(a1),
            None => a0.add(L::splat(-0.5)).add(a1),
        }
    }
}

/// Function `f` of the arguments `a` (DOT3 is the caller's).
///
/// # Safety
/// `L`'s instruction set.
#[inline(always)]
unsafe fn combine<L: Lane>(f: CombineFn, a: [L; 3]) -> L {
    // SAFETY: the caller's instruction set for `L`.
    unsafe {
        match f {
            CombineFn::Replace => a[0],
            CombineFn::Modulate => a[0].mul(a[1]),
            CombineFn::Add => a[0].add(a[1]),
            CombineFn::AddSigned => a[0].add(a[1]).add(L::splat(-0.5)),
            CombineFn::Interpolate => a[0].mul(a[2]).add(a[1].mul(L::splat(1.0).sub(a[2]))),
            CombineFn::Subtract => a[0].sub(a[1]),
            CombineFn::Dot3Rgb | CombineFn::Dot3Rgba => unreachable!("handled by the caller"),
        }
    }
}
