//! Per-fragment work: interpolation of the varyings and the fragment operations in GL
//! order (alpha test, stencil, depth, blend or logic op, colour mask), specialised per draw
//! by a small [`FragPlan`] that the plan derives from the GL state once per draw
//! (in `plan/fragment.rs`).
//!
//! Numbers (docs/llvmpipe-rules.md §7, §8, §12, §13): every attribute is a plane evaluated per
//! pixel as `fmuladd(dady, py, fmuladd(dadx, px, a0))`; perspective attributes are
//! multiplied by `1 / w_plane`; z is clamped to [0, 1] and quantised with round-half-even;
//! colours are clamped to [0, 1] and converted with `round_half_even(c * 255)`; the alpha
//! test compares 8-bit integers; blending is 8-bit fixed point with
//! `mul(a, b) = (t + (t >> 8) + 128) >> 8`, `t = a·b`.

pub mod blend;
pub mod multisample;
pub mod simd;
pub mod simd_gen;
pub mod simd_plane;
pub mod simd_tex;
pub mod simd_wide;
pub mod span;
pub mod srgb;
pub mod wide;

use crate::framebuffer::DepthFormat;
use crate::pipe::{BlendState, CompareFunc, LogicOp, StencilFace, StencilOp};

/// What the fragment stage does for one draw, derived once from the state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FragPlan {
    /// The depth test, when enabled and a depth buffer exists.
    pub depth: Option<DepthPlan>,
    /// Flat shading: the colour is the provoking vertex's.
    pub flat: bool,
    /// glColorMask.
    pub color_mask: [bool; 4],
    /// Whether the host fuses multiply-adds.
    pub fma: bool,
    /// The alpha test: function and the 8-bit reference.
    pub alpha: Option<(CompareFunc, u8)>,
    /// The stencil test, when enabled and a stencil buffer exists.
    pub stencil: Option<StencilPlan>,
    /// Blending (None when disabled, or replaced by a logic op).
    pub blend: Option<BlendPlan>,
    /// The logic op, when GL_COLOR_LOGIC_OP is on and it is not COPY.
    pub logic: Option<LogicOp>,
    /// GL_SEPARATE_SPECULAR_COLOR: the secondary colour is added after texturing.
    pub separate_specular: bool,
    /// Fog, when GL_FOG is on.
    pub fog: Option<crate::fixed_function::fog::FogPlan>,
    /// An occlusion query is active: count the samples that pass (general path only).
    pub count_samples: bool,
    /// Antialiased lines or points: the coverage multiplied into alpha (general path).
    pub smooth: Option<crate::raster::smooth::Smooth>,
    /// A one-pass 4x multisample triangle draw ([`MsPass`]).
    pub ms: Option<MsPass>,
    /// glBlendColor as floats, for blending into wide buffers ([`wide`]).
    pub blend_color: [f32; 4],
    /// The colour buffer is sRGB and GL_FRAMEBUFFER_SRGB is on: writes are encoded and
    /// blending is done in linear space ([`srgb`]; general path only).
    pub srgb: bool,
    /// A fragment shader replaces the colour stages (texturing, colour sum, fog): the
    /// triangles are drawn through the engine by [`crate::shader::draw`].
    pub shader: Option<crate::shader::draw::ShaderRef>,
    /// Bit k − 1: draw buffer k ≥ 1 has a colour buffer
    /// ([`crate::framebuffer::Framebuffer::more_colors`]); drawn by the engine only.
    pub more_buffers: u8,
}

/// A 4x multisample triangle draw, rasterised once for the four samples
/// ([`crate::raster::multisample`]) and shaded once per pixel ([`multisample`]): a pixel
/// is shaded when any of its sample points is inside, colour and every other attribute
/// evaluated at the pixel centre `(x + 0.5, y + 0.5)`; then each covered sample s in turn
/// gets the alpha-to-coverage test, stencil, depth evaluated at its sample point
/// `(x + sx, y + sy)`, blending and the write, in plane s. Each value is
/// `fmuladd(dady, y', fmuladd(dadx, x', a0))` with `a0` at the pixel's corner (llvmpipe's
/// `attribs_update_simple` with `coverage_samples > 1`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MsPass {
    /// The samples drawn, bit s for sample s: glSampleCoverage's mask (a sample it leaves
    /// out is not drawn at all).
    pub mask: u8,
    /// GL_SAMPLE_ALPHA_TO_COVERAGE: sample s is kept only where the shaded (float) alpha
    /// is above `s · 0.25` (llvmpipe's `lp_build_sample_alpha_to_coverage`, no dither).
    pub alpha_to_coverage: bool,
}

impl MsPass {
    /// The sample point of sample `s` (0..4, llvmpipe's order) inside the pixel, as
    /// fractions (x, y) of a pixel (exact in f32).
    #[inline(always)]
    pub fn pos(s: usize) -> [f32; 2] {
        let [x, y] = crate::geometry::setup::SAMPLE_POS[s];
        [x as f32 / 256.0, y as f32 / 256.0]
    }

    /// The alpha the shaded alpha must exceed for sample `s` to be kept.
    #[inline(always)]
    pub fn coverage_threshold(s: usize) -> f32 {
        s as f32 * 0.25
    }
}

/// The depth test of a draw.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DepthPlan {
    /// glDepthFunc.
    pub func: CompareFunc,
    /// glDepthMask.
    pub write: bool,
    /// Buffer layout.
    pub format: DepthFormat,
}

/// One face's stencil test and updates, with the reference clamped to 8 bits.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StencilFacePlan {
    /// Function.
    pub func: CompareFunc,
    /// `ref & mask`.
    pub masked_ref: u8,
    /// The reference (for REPLACE).
    pub reference: u8,
    /// Comparison mask.
    pub mask: u8,
    /// Operation on stencil fail.
    pub fail: StencilOp,
    /// Operation on depth fail.
    pub zfail: StencilOp,
    /// Operation on pass.
    pub zpass: StencilOp,
    /// Write mask.
    pub write: u8,
}

impl StencilFacePlan {
    /// The plan of one face's stencil state.
    pub fn new(f: &StencilFace) -> Self {
        let reference = f.reference.clamp(0, 255) as u8;
        let mask = (f.value_mask & 0xFF) as u8;
        StencilFacePlan {
            func: f.func,
            masked_ref: reference & mask,
            reference,
            mask,
            fail: f.fail,
            zfail: f.zfail,
            zpass: f.zpass,
            write: (f.writemask & 0xFF) as u8,
        }
    }
    /// Whether stencil value `s` passes.
    #[inline(always)]
    pub fn test(&self, s: u8) -> bool {
        self.func.test(self.masked_ref, s & self.mask)
    }
    /// The stored value after `op`, through the write mask.
    #[inline(always)]
    pub fn update(&self, op: StencilOp, s: u8) -> u8 {
        (s & !self.write) | (op.apply(s, self.reference) & self.write)
    }
}

/// The stencil state of a draw.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StencilPlan {
    /// For front-facing primitives (and lines/points).
    pub front: StencilFacePlan,
    /// For back-facing triangles.
    pub back: StencilFacePlan,
}

/// Blending of a draw, in 8-bit terms: the factors and equations, and the constant colour
/// converted like a fragment colour.
pub type BlendPlan = BlendState<[u8; 4]>;

impl FragPlan {
    /// Whether fragments of this plan can change anything.
    pub fn writes_anything(&self) -> bool {
        self.color_mask.iter().any(|&m| m)
            || self.depth.is_some_and(|d| d.write)
            || self
                .stencil
                .is_some_and(|s| s.front.write != 0 || s.back.write != 0)
            || self.count_samples
    }

    /// Whether the plan needs the general fragment path (alpha test, stencil, blending or a
    /// logic op); otherwise the plain depth-and-write path runs.
    pub fn needs_full_path(&self) -> bool {
        self.alpha.is_some()
            || self.stencil.is_some()
            || self.blend.is_some()
            || self.logic.is_some()
            || self.separate_specular
            || self.fog.is_some()
            || self.count_samples
            || self.smooth.is_some()
            || self.ms.is_some()
            || self.srgb
    }
}
