//! Per-fragment vocabulary: compare functions, blend factors and equations, stencil and logic
//! operations, and the per-fragment state block the plan reads.

#[allow(unused_imports)]
use super::*;

/// A comparison function (depth test; later alpha and stencil tests).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CompareFunc {
    /// Never passes.
    Never,
    /// Passes if the incoming value is less.
    Less,
    /// Passes if equal.
    Equal,
    /// Passes if less or equal.
    LEqual,
    /// Passes if greater.
    Greater,
    /// Passes if not equal.
    NotEqual,
    /// Passes if greater or equal.
    GEqual,
    /// Always passes.
    Always,
}

impl CompareFunc {
    /// Every function, in the order of the GL enums (GL_NEVER 0x0200 … GL_ALWAYS 0x0207).
    pub const ALL: [CompareFunc; 8] = [
        CompareFunc::Never,
        CompareFunc::Less,
        CompareFunc::Equal,
        CompareFunc::LEqual,
        CompareFunc::Greater,
        CompareFunc::NotEqual,
        CompareFunc::GEqual,
        CompareFunc::Always,
    ];

    /// Applies the function to `incoming` vs `stored`.
    #[inline(always)]
    pub fn test<T: PartialOrd>(self, incoming: T, stored: T) -> bool {
        match self {
            Self::Never => false,
            Self::Less => incoming < stored,
            Self::Equal => incoming == stored,
            Self::LEqual => incoming <= stored,
            Self::Greater => incoming > stored,
            Self::NotEqual => incoming != stored,
            Self::GEqual => incoming >= stored,
            Self::Always => true,
        }
    }
}

/// A blend factor (glBlendFunc).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[allow(missing_docs)]
pub enum BlendFactor {
    Zero,
    One,
    SrcColor,
    OneMinusSrcColor,
    DstColor,
    OneMinusDstColor,
    SrcAlpha,
    OneMinusSrcAlpha,
    DstAlpha,
    OneMinusDstAlpha,
    ConstantColor,
    OneMinusConstantColor,
    ConstantAlpha,
    OneMinusConstantAlpha,
    SrcAlphaSaturate,
}

/// A blend equation (glBlendEquation).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[allow(missing_docs)]
pub enum BlendEquation {
    Add,
    Subtract,
    ReverseSubtract,
    Min,
    Max,
}

/// glBlendFuncSeparate / glBlendEquationSeparate / glBlendColor state; with `C = [u8; 4]`
/// a draw's blending in 8-bit terms (`fragment::BlendPlan`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlendState<C = [f32; 4]> {
    /// Source factor for RGB.
    pub src_rgb: BlendFactor,
    /// Destination factor for RGB.
    pub dst_rgb: BlendFactor,
    /// Source factor for alpha.
    pub src_a: BlendFactor,
    /// Destination factor for alpha.
    pub dst_a: BlendFactor,
    /// Equation for RGB.
    pub eq_rgb: BlendEquation,
    /// Equation for alpha.
    pub eq_a: BlendEquation,
    /// glBlendColor: in the state as given, clamped to [0,1]; in a plan converted like a
    /// fragment colour.
    pub color: C,
}

impl Default for BlendState {
    fn default() -> Self {
        BlendState {
            src_rgb: BlendFactor::One,
            dst_rgb: BlendFactor::Zero,
            src_a: BlendFactor::One,
            dst_a: BlendFactor::Zero,
            eq_rgb: BlendEquation::Add,
            eq_a: BlendEquation::Add,
            color: [0.0; 4],
        }
    }
}

/// A stencil operation (glStencilOp).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[allow(missing_docs)]
pub enum StencilOp {
    Keep,
    Zero,
    Replace,
    Incr,
    Decr,
    Invert,
    IncrWrap,
    DecrWrap,
}

impl StencilOp {
    /// Applies the operation to stored value `s` with reference `r` (8-bit buffer).
    #[inline(always)]
    pub fn apply(self, s: u8, r: u8) -> u8 {
        match self {
            Self::Keep => s,
            Self::Zero => 0,
            Self::Replace => r,
            Self::Incr => s.saturating_add(1),
            Self::Decr => s.saturating_sub(1),
            Self::Invert => !s,
            Self::IncrWrap => s.wrapping_add(1),
            Self::DecrWrap => s.wrapping_sub(1),
        }
    }
}

/// The stencil state of one face.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StencilFace {
    /// glStencilFunc function.
    pub func: CompareFunc,
    /// Reference value (as given; clamped to the buffer's range when used).
    pub reference: i32,
    /// Comparison mask.
    pub value_mask: u32,
    /// Operation when the stencil test fails.
    pub fail: StencilOp,
    /// Operation when the stencil test passes and the depth test fails.
    pub zfail: StencilOp,
    /// Operation when both pass.
    pub zpass: StencilOp,
    /// glStencilMask.
    pub writemask: u32,
}

impl Default for StencilFace {
    fn default() -> Self {
        StencilFace {
            func: CompareFunc::Always,
            reference: 0,
            // Mesa starts both masks at the 8-bit buffer's all-ones, 0xFF.
            value_mask: 0xFF,
            fail: StencilOp::Keep,
            zfail: StencilOp::Keep,
            zpass: StencilOp::Keep,
            writemask: 0xFF,
        }
    }
}

listed_enum! {
    /// A logic operation (glLogicOp) on 8-bit channels.
    #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
    #[allow(missing_docs)]
    pub enum LogicOp {
        Clear,
        And,
        AndReverse,
        Copy,
        AndInverted,
        Noop,
        Xor,
        Or,
        Nor,
        Equiv,
        Invert,
        OrReverse,
        CopyInverted,
        OrInverted,
        Nand,
        Set,
    }
}

impl LogicOp {
    /// Applies the operation to source `s` and destination `d`.
    #[inline(always)]
    pub fn apply(self, s: u8, d: u8) -> u8 {
        match self {
            Self::Clear => 0,
            Self::And => s & d,
            Self::AndReverse => s & !d,
            Self::Copy => s,
            Self::AndInverted => !s & d,
            Self::Noop => d,
            Self::Xor => s ^ d,
            Self::Or => s | d,
            Self::Nor => !(s | d),
            Self::Equiv => !(s ^ d),
            Self::Invert => !d,
            Self::OrReverse => s | !d,
            Self::CopyInverted => !s,
            Self::OrInverted => !s | d,
            Self::Nand => !(s & d),
            Self::Set => 255,
        }
    }
}

/// All per-fragment operation state other than depth.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FragmentOps {
    /// Blending.
    pub blend: BlendState,
    /// glAlphaFunc function.
    pub alpha_func: CompareFunc,
    /// glAlphaFunc reference, unclamped as given (Mesa clamps when it uses it).
    pub alpha_ref: f32,
    /// Front-face stencil state.
    pub stencil_front: StencilFace,
    /// Back-face stencil state.
    pub stencil_back: StencilFace,
    /// glLogicOp.
    pub logic_op: LogicOp,
}

impl Default for FragmentOps {
    fn default() -> Self {
        FragmentOps {
            blend: BlendState::default(),
            alpha_func: CompareFunc::Always,
            alpha_ref: 0.0,
            stencil_front: StencilFace::default(),
            stencil_back: StencilFace::default(),
            logic_op: LogicOp::Copy,
        }
    }
}
