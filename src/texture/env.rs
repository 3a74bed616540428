//! The fixed-function texture environment (GL 1.5 §3.8.13, ARB_texture_env_combine,
//! _crossbar, _dot3) computed as Mesa's generated fragment shader does
//! (docs/llvmpipe-rules.md §10.2).
//!
//! [`TexEnv`] is the GL state of one unit as Rust enums. [`Combine::derive`] turns it into
//! Mesa's combiner form once per draw: legacy modes become combiner states exactly as
//! `calculate_derived_texenv` (`mesa/main/texstate.c`) builds them, so REPLACE on an ALPHA
//! texture is REPLACE(PREVIOUS) for RGB and so on. [`Combine::apply`] then evaluates the
//! combiner like `emit_texenv`/`emit_combine` (`ff_fragment_shader.cpp`): f32 arithmetic
//! with separate multiplies and adds, INTERPOLATE as `s0·s2 + s1·(1 − s2)`, saturation only
//! for ADD, ADD_SIGNED, SUBTRACT and DOT3 (and after a scale, which then saturates all four
//! channels). The evaluation is written once, generic over the [`Lane`] it computes in:
//! `f32` for one fragment, eight fragments' AVX2 lanes in [`vec8`].
//!
//! Two of NIR's algebraic rewrites change the rounding and are reproduced: ADD_SIGNED
//! becomes `(arg0 + −0.5) + arg1` (or `(0.5 − x) + arg1` when arg0 is `1 − x`) unless CSE
//! has shared its sums (`Combine::add_signed_reassociates`), and INTERPOLATE's `1 − arg2`
//! with arg2 = `1 − x` is x. Checked against llvmpipe on all two-argument operand/source/
//! scale combinations of ADD, ADD_SIGNED, SUBTRACT, INTERPOLATE and MODULATE on one unit;
//! a few two-unit chains where PREVIOUS feeds ADD_SIGNED still round differently.

/// GL_TEXTURE_ENV_MODE.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EnvMode {
    /// GL_REPLACE.
    Replace,
    /// GL_MODULATE.
    Modulate,
    /// GL_DECAL.
    Decal,
    /// GL_BLEND.
    Blend,
    /// GL_ADD.
    Add,
    /// GL_COMBINE.
    Combine,
}

/// GL_COMBINE_RGB / GL_COMBINE_ALPHA function.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CombineFn {
    /// Arg0.
    Replace,
    /// Arg0·Arg1.
    Modulate,
    /// Arg0 + Arg1.
    Add,
    /// Arg0 + Arg1 − 0.5.
    AddSigned,
    /// Arg0·Arg2 + Arg1·(1 − Arg2).
    Interpolate,
    /// Arg0 − Arg1.
    Subtract,
    /// 4·((r0−.5)(r1−.5) + …) into RGB (RGB only).
    Dot3Rgb,
    /// The same into RGBA (RGB only).
    Dot3Rgba,
}

impl CombineFn {
    #[inline(always)]
    fn num_args(self) -> usize {
        match self {
            CombineFn::Replace => 1,
            CombineFn::Interpolate => 3,
            _ => 2,
        }
    }
    #[inline(always)]
    fn saturates(self) -> bool {
        !matches!(
            self,
            CombineFn::Replace | CombineFn::Modulate | CombineFn::Interpolate
        )
    }
}

/// GL_SOURCEn_RGB / GL_SOURCEn_ALPHA.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Source {
    /// GL_TEXTURE: this unit's texture.
    Texture,
    /// GL_TEXTUREn (crossbar).
    TextureN(u8),
    /// GL_CONSTANT: the env colour.
    Constant,
    /// GL_PRIMARY_COLOR: the fragment's primary colour.
    PrimaryColor,
    /// GL_PREVIOUS: the previous unit's result.
    Previous,
}

/// GL_OPERANDn_RGB / GL_OPERANDn_ALPHA.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Operand {
    /// GL_SRC_COLOR.
    SrcColor,
    /// GL_ONE_MINUS_SRC_COLOR.
    OneMinusSrcColor,
    /// GL_SRC_ALPHA.
    SrcAlpha,
    /// GL_ONE_MINUS_SRC_ALPHA.
    OneMinusSrcAlpha,
}

/// The GL texture-environment state of one unit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexEnv {
    /// GL_TEXTURE_ENV_MODE.
    pub mode: EnvMode,
    /// GL_COMBINE_RGB.
    pub combine_rgb: CombineFn,
    /// GL_COMBINE_ALPHA.
    pub combine_alpha: CombineFn,
    /// GL_SOURCE0..2_RGB.
    pub source_rgb: [Source; 3],
    /// GL_SOURCE0..2_ALPHA.
    pub source_alpha: [Source; 3],
    /// GL_OPERAND0..2_RGB.
    pub operand_rgb: [Operand; 3],
    /// GL_OPERAND0..2_ALPHA.
    pub operand_alpha: [Operand; 3],
    /// GL_RGB_SCALE (1, 2 or 4).
    pub rgb_scale: f32,
    /// GL_ALPHA_SCALE (1, 2 or 4).
    pub alpha_scale: f32,
    /// GL_TEXTURE_ENV_COLOR (clamped to [0,1]).
    pub color: [f32; 4],
}

impl Default for TexEnv {
    fn default() -> Self {
        TexEnv {
            mode: EnvMode::Modulate,
            combine_rgb: CombineFn::Modulate,
            combine_alpha: CombineFn::Modulate,
            source_rgb: [Source::Texture, Source::Previous, Source::Constant],
            source_alpha: [Source::Texture, Source::Previous, Source::Constant],
            operand_rgb: [Operand::SrcColor, Operand::SrcColor, Operand::SrcAlpha],
            operand_alpha: [Operand::SrcAlpha; 3],
            rgb_scale: 1.0,
            alpha_scale: 1.0,
            color: [0.0; 4],
        }
    }
}

/// One combiner argument.
pub type Arg = (Source, Operand);

/// The derived combiner of a unit (Mesa's `_CurrentCombine`), evaluated per fragment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Combine {
    /// RGB function.
    pub mode_rgb: CombineFn,
    /// Alpha function.
    pub mode_a: CombineFn,
    /// RGB arguments.
    pub args_rgb: [Arg; 3],
    /// Alpha arguments.
    pub args_a: [Arg; 3],
    /// RGB scale factor (1, 2, 4).
    pub scale_rgb: f32,
    /// Alpha scale factor (1, 2, 4).
    pub scale_a: f32,
    /// The env colour.
    pub color: [f32; 4],
    /// `emit_texenv` builds one vec4 combine for RGB and alpha (equal functions and
    /// Mesa's `args_match` on the sources as set, before [`Combine::canonicalise`]).
    pub one_vec4: bool,
    /// [`Combine::add_signed_reassociates`] of RGB and alpha, kept up to date by
    /// `derive` and `canonicalise` so that `apply` does not work it out per fragment.
    pub reassoc: (bool, bool),
    /// Whether a source reads another unit's texel (GL_TEXTUREn after
    /// [`Combine::canonicalise`]): `apply` then needs every active unit's texel.
    pub crossbar: bool,
    /// The combiner as a [`Simple`] one when it is (kept up to date by `derive` and
    /// `canonicalise`, like `reassoc`): `apply` then skips the general evaluation.
    pub simple: Option<Simple>,
}

/// A combiner whose RGB and alpha functions are each REPLACE or MODULATE of plain
/// operands (GL_SRC_COLOR for RGB, GL_SRC_ALPHA for alpha) of sources other than
/// GL_TEXTUREn, without a scale: no saturation, no reassociation, and per channel the
/// general evaluation is `v0[c]` or `v0[c]·v1[c]`, which this form computes directly.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Simple {
    /// RGB: the sources of arg0 and arg1 (`None` for REPLACE).
    pub rgb: (Source, Option<Source>),
    /// Alpha: the same.
    pub a: (Source, Option<Source>),
}

impl Simple {
    /// The simple form of `c`, if it has one.
    fn of(c: &Combine) -> Option<Simple> {
        if c.scale_rgb != 1.0 || c.scale_a != 1.0 || c.crossbar {
            return None;
        }
        let side = |f: CombineFn, args: &[Arg; 3], op: Operand| {
            let plain = |a: Arg| (a.1 == op && !matches!(a.0, Source::TextureN(_))).then_some(a.0);
            match f {
                CombineFn::Replace => Some((plain(args[0])?, None)),
                CombineFn::Modulate => Some((plain(args[0])?, Some(plain(args[1])?))),
                _ => None,
            }
        };
        Some(Simple {
            rgb: side(c.mode_rgb, &c.args_rgb, Operand::SrcColor)?,
            a: side(c.mode_a, &c.args_a, Operand::SrcAlpha)?,
        })
    }
}

/// The crossbar slot of a unit that is not active: past any texel list, so it reads zero.
pub const NO_SLOT: u8 = u8::MAX;

impl Combine {
    /// Whether the alpha this combiner computes can read a texel: an alpha argument of
    /// GL_TEXTURE or GL_TEXTUREn or, for DOT3_RGBA (whose alpha is the RGB dot product),
    /// such an RGB argument. Every other alpha reads only the alpha channels of its own
    /// arguments (`eval::apply_general`, `apply_simple`). Where no unit's does, a draw's
    /// alpha test can run before its units are sampled (`fragment::simd_gen::alpha_early`).
    pub fn alpha_reads_texels(&self) -> bool {
        let tex = |a: &Arg| matches!(a.0, Source::Texture | Source::TextureN(_));
        if self.mode_rgb == CombineFn::Dot3Rgba {
            self.args_rgb[..2].iter().any(tex)
        } else {
            self.args_a[..self.mode_a.num_args()].iter().any(tex)
        }
    }

    /// Mesa's `args_match` and equal functions: RGB and alpha are one vec4 combine.
    fn compute_one_vec4(&self) -> bool {
        self.mode_rgb == self.mode_a
            && (0..self.mode_rgb.num_args()).all(|i| {
                let (rs, ro) = self.args_rgb[i];
                let (as_, ao) = self.args_a[i];
                rs == as_
                    && match ao {
                        Operand::SrcAlpha => matches!(ro, Operand::SrcColor | Operand::SrcAlpha),
                        _ => matches!(ro, Operand::OneMinusSrcColor | Operand::OneMinusSrcAlpha),
                    }
            })
    }

    /// Mesa's combiner form of `env` for a texture of base format `base`.
    pub fn derive(env: &TexEnv, base: super::BaseFormat) -> Combine {
        use super::BaseFormat as B;
        use CombineFn as F;
        use Source as S;
        let zip = |s: [Source; 3], o: [Operand; 3]| [(s[0], o[0]), (s[1], o[1]), (s[2], o[2])];
        if env.mode == EnvMode::Combine {
            return Combine::with(
                (env.combine_rgb, env.combine_alpha),
                (
                    zip(env.source_rgb, env.operand_rgb),
                    zip(env.source_alpha, env.operand_alpha),
                ),
                (env.rgb_scale, env.alpha_scale),
                env.color,
            );
        }
        let base = base.env_base();
        let d = TexEnv::default();
        let mut src_rgb = d.source_rgb;
        let mut src_a = d.source_alpha;
        let mut op_rgb = d.operand_rgb;
        let mut op_a = d.operand_alpha;
        match base {
            B::Alpha => src_rgb[0] = S::Previous,
            B::Luminance | B::Rgb => src_a[0] = S::Previous,
            _ => {}
        }
        let (mut mode_rgb, mut mode_a);
        match env.mode {
            EnvMode::Replace | EnvMode::Modulate => {
                let m = if env.mode == EnvMode::Replace {
                    F::Replace
                } else {
                    F::Modulate
                };
                mode_rgb = if src_rgb[0] == S::Previous {
                    F::Replace
                } else {
                    m
                };
                mode_a = if src_a[0] == S::Previous {
                    F::Replace
                } else {
                    m
                };
            }
            EnvMode::Decal => {
                mode_rgb = F::Interpolate;
                mode_a = F::Replace;
                src_a[0] = S::Previous;
                match base {
                    B::Alpha | B::Luminance | B::LuminanceAlpha | B::Intensity => {
                        src_rgb[0] = S::Previous
                    }
                    B::Rgb => mode_rgb = F::Replace,
                    B::Rgba => src_rgb[2] = S::Texture,
                    // a depth texture reaches the environment as its depth mode's format;
                    // red and green ones as RGB (`env_base`)
                    B::Depth | B::Red | B::Rg => {}
                }
            }
            EnvMode::Blend => {
                mode_rgb = F::Interpolate;
                mode_a = F::Modulate;
                if base == B::Alpha {
                    mode_rgb = F::Replace;
                } else {
                    if base == B::Intensity {
                        mode_a = F::Interpolate;
                        src_a[0] = S::Constant;
                        op_a[2] = Operand::SrcAlpha;
                    }
                    src_rgb[2] = S::Texture;
                    src_a[2] = S::Texture;
                    src_rgb[0] = S::Constant;
                    op_rgb[2] = Operand::SrcColor;
                }
            }
            EnvMode::Add | EnvMode::Combine => {
                mode_rgb = if src_rgb[0] == S::Previous {
                    F::Replace
                } else {
                    F::Add
                };
                mode_a = if base == B::Intensity {
                    F::Add
                } else if src_a[0] == S::Previous {
                    F::Replace
                } else {
                    F::Modulate
                };
            }
        }
        if src_rgb[0] == S::Previous {
            mode_rgb = F::Replace;
        }
        if src_a[0] == S::Previous {
            mode_a = F::Replace;
        }
        Combine::with(
            (mode_rgb, mode_a),
            (zip(src_rgb, op_rgb), zip(src_a, op_a)),
            (1.0, 1.0),
            env.color,
        )
    }

    /// The combiner of functions `modes` on arguments `args` (RGB, alpha each) with
    /// scales `scales` and env colour `color`, its derived fields worked out.
    fn with(
        modes: (CombineFn, CombineFn),
        args: ([Arg; 3], [Arg; 3]),
        scales: (f32, f32),
        color: [f32; 4],
    ) -> Combine {
        let mut c = Combine {
            mode_rgb: modes.0,
            mode_a: modes.1,
            args_rgb: args.0,
            args_a: args.1,
            scale_rgb: scales.0,
            scale_a: scales.1,
            color,
            one_vec4: false,
            reassoc: (true, true),
            crossbar: false,
            simple: None,
        };
        c.one_vec4 = c.compute_one_vec4();
        c.refresh();
        c
    }

    /// Recomputes the fields derived from the others (`reassoc`, `simple`).
    fn refresh(&mut self) {
        self.reassoc = self.add_signed_reassociates();
        self.simple = Simple::of(self);
    }

    /// Whether NIR reassociates the ADD_SIGNED of RGB and of alpha (see [`add_signed`]).
    ///
    /// llvmpipe's NIR is scalar, and the rule wants both the inner `arg0 + arg1` and the
    /// outer `+ -0.5` used once after CSE. A per-channel (vector) ADD_SIGNED always
    /// qualifies. When both RGB arguments are alpha operands, the RGB function is one
    /// scalar; if the alpha function's first two arguments are the same two scalars (in
    /// any order), CSE merges the two:
    /// - ADD_SIGNED with ADD: the ADD's sum is the ADD_SIGNED's inner sum, used twice;
    /// - ADD_SIGNED with ADD_SIGNED: one value. `emit_texenv` saturates it (when that
    ///   side has no scale) and then multiplies by the scale (a scale of 1 folds away,
    ///   `fsat(fsat(x))` is `fsat(x)`), so its users are `fsat(v)` and/or `v·scale`:
    ///   two different users keep it as it is. With one vec4 combine (equal functions
    ///   and `args_match`) the RGB saturation decides for alpha too.
    pub fn add_signed_reassociates(&self) -> (bool, bool) {
        use CombineFn as F;
        let alpha_op = |o: Operand| matches!(o, Operand::SrcAlpha | Operand::OneMinusSrcAlpha);
        let [r0, r1, _] = self.args_rgb;
        let [a0, a1, _] = self.args_a;
        let shared = matches!(self.mode_rgb, F::AddSigned | F::Add)
            && matches!(self.mode_a, F::AddSigned | F::Add)
            && alpha_op(r0.1)
            && alpha_op(r1.1)
            && ((r0 == a0 && r1 == a1) || (r0 == a1 && r1 == a0));
        if !shared {
            return (true, true);
        }
        if self.mode_rgb != self.mode_a {
            return (false, false);
        }
        let rgb_sat = self.scale_rgb == 1.0;
        let a_sat = if self.one_vec4 {
            rgb_sat
        } else {
            self.scale_a == 1.0
        };
        // the user of v: None = fsat(v), Some(s) = v·s
        let user = |sat: bool, scale: f32| (!sat && scale != 1.0).then_some(scale);
        let ok = user(rgb_sat, self.scale_rgb) == user(a_sat, self.scale_a);
        (ok, ok)
    }

    /// Sources as the generated shader sees them on unit `unit`: GL_TEXTUREn of the
    /// unit's own number is its GL_TEXTURE, and GL_PREVIOUS is the primary colour when
    /// no earlier unit is enabled (`prev_is_primary`). The values are the same either
    /// way; this only matters where identical expressions merge (ADD_SIGNED).
    ///
    /// Every other GL_TEXTUREn (crossbar) is renumbered by `slot`: the unit's place among
    /// the draw's active units, whose texels [`Combine::apply`] receives in that order,
    /// or `None` for a unit that is not active (disabled or incomplete), which Mesa's
    /// generated shader reads as zero (`load_texture`'s `dummy_tex`); it becomes
    /// [`NO_SLOT`], past any list.
    pub fn canonicalise(
        &mut self,
        unit: usize,
        prev_is_primary: bool,
        slot: impl Fn(usize) -> Option<usize>,
    ) {
        for args in [&mut self.args_rgb, &mut self.args_a] {
            for a in args.iter_mut() {
                match a.0 {
                    Source::TextureN(n) if n as usize == unit => a.0 = Source::Texture,
                    Source::TextureN(n) => {
                        let k = slot(n as usize).map_or(NO_SLOT, |k| k as u8);
                        a.0 = Source::TextureN(k);
                        self.crossbar = true;
                    }
                    Source::Previous if prev_is_primary => a.0 = Source::PrimaryColor,
                    _ => {}
                }
            }
        }
        self.refresh();
    }
}

mod eval;
pub use eval::{sat, Inputs, Lane};

#[cfg(test)]
pub(crate) mod tests;
#[cfg(target_arch = "x86_64")]
pub mod vec8;
