//! Per-fragment operation state as data: blending, alpha test, stencil and logic op, with
//! the GL token conversions done once at the boundary.

use super::error::{GlError, GlResult};
use super::state::CompareFunc;
use crate::ffi::enums::*;
use crate::ffi::glext_enums::*;
use crate::ffi::types::GLenum;

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

const FACTORS: &[(BlendFactor, GLenum)] = &[
    (BlendFactor::Zero, GL_ZERO),
    (BlendFactor::One, GL_ONE),
    (BlendFactor::SrcColor, GL_SRC_COLOR),
    (BlendFactor::OneMinusSrcColor, GL_ONE_MINUS_SRC_COLOR),
    (BlendFactor::DstColor, GL_DST_COLOR),
    (BlendFactor::OneMinusDstColor, GL_ONE_MINUS_DST_COLOR),
    (BlendFactor::SrcAlpha, GL_SRC_ALPHA),
    (BlendFactor::OneMinusSrcAlpha, GL_ONE_MINUS_SRC_ALPHA),
    (BlendFactor::DstAlpha, GL_DST_ALPHA),
    (BlendFactor::OneMinusDstAlpha, GL_ONE_MINUS_DST_ALPHA),
    (BlendFactor::ConstantColor, GL_CONSTANT_COLOR),
    (
        BlendFactor::OneMinusConstantColor,
        GL_ONE_MINUS_CONSTANT_COLOR,
    ),
    (BlendFactor::ConstantAlpha, GL_CONSTANT_ALPHA),
    (
        BlendFactor::OneMinusConstantAlpha,
        GL_ONE_MINUS_CONSTANT_ALPHA,
    ),
    (BlendFactor::SrcAlphaSaturate, GL_SRC_ALPHA_SATURATE),
];

impl BlendFactor {
    /// Converts a factor token (GL 1.4 allows every factor as source and destination).
    pub fn from_gl(e: GLenum) -> GlResult<Self> {
        FACTORS
            .iter()
            .find(|(_, g)| *g == e)
            .map(|(f, _)| *f)
            .ok_or(GlError::InvalidEnum)
    }
    /// The GL token.
    pub fn to_gl(self) -> GLenum {
        FACTORS
            .iter()
            .find(|(f, _)| *f == self)
            .map_or(GL_ZERO, |(_, g)| *g)
    }
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

impl BlendEquation {
    /// Converts an equation token.
    pub fn from_gl(e: GLenum) -> GlResult<Self> {
        Ok(match e {
            GL_FUNC_ADD => Self::Add,
            GL_FUNC_SUBTRACT => Self::Subtract,
            GL_FUNC_REVERSE_SUBTRACT => Self::ReverseSubtract,
            GL_MIN => Self::Min,
            GL_MAX => Self::Max,
            _ => return Err(GlError::InvalidEnum),
        })
    }
    /// The GL token.
    pub fn to_gl(self) -> GLenum {
        match self {
            Self::Add => GL_FUNC_ADD,
            Self::Subtract => GL_FUNC_SUBTRACT,
            Self::ReverseSubtract => GL_FUNC_REVERSE_SUBTRACT,
            Self::Min => GL_MIN,
            Self::Max => GL_MAX,
        }
    }
}

/// glBlendFuncSeparate / glBlendEquationSeparate / glBlendColor state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BlendState {
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
    /// glBlendColor (clamped to [0,1]).
    pub color: [f32; 4],
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
    /// Converts an operation token.
    pub fn from_gl(e: GLenum) -> GlResult<Self> {
        Ok(match e {
            GL_KEEP => Self::Keep,
            GL_ZERO => Self::Zero,
            GL_REPLACE => Self::Replace,
            GL_INCR => Self::Incr,
            GL_DECR => Self::Decr,
            GL_INVERT => Self::Invert,
            GL_INCR_WRAP => Self::IncrWrap,
            GL_DECR_WRAP => Self::DecrWrap,
            _ => return Err(GlError::InvalidEnum),
        })
    }
    /// The GL token.
    pub fn to_gl(self) -> GLenum {
        match self {
            Self::Keep => GL_KEEP,
            Self::Zero => GL_ZERO,
            Self::Replace => GL_REPLACE,
            Self::Incr => GL_INCR,
            Self::Decr => GL_DECR,
            Self::Invert => GL_INVERT,
            Self::IncrWrap => GL_INCR_WRAP,
            Self::DecrWrap => GL_DECR_WRAP,
        }
    }
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

impl LogicOp {
    /// Converts a token (GL_CLEAR..GL_SET are 0x1500..0x150F in this order).
    pub fn from_gl(e: GLenum) -> GlResult<Self> {
        use LogicOp::*;
        const ALL: [LogicOp; 16] = [
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
        ];
        e.checked_sub(GL_CLEAR)
            .and_then(|i| ALL.get(i as usize).copied())
            .ok_or(GlError::InvalidEnum)
    }
    /// The GL token.
    pub fn to_gl(self) -> GLenum {
        GL_CLEAR + self as GLenum
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stencil_ops_saturate_and_wrap() {
        assert_eq!(StencilOp::Incr.apply(255, 0), 255);
        assert_eq!(StencilOp::IncrWrap.apply(255, 0), 0);
        assert_eq!(StencilOp::Decr.apply(0, 0), 0);
        assert_eq!(StencilOp::DecrWrap.apply(0, 0), 255);
        assert_eq!(StencilOp::Invert.apply(0x0F, 0), 0xF0);
        assert_eq!(StencilOp::Replace.apply(3, 9), 9);
    }

    #[test]
    fn logic_op_tokens_round_trip() {
        for e in GL_CLEAR..=GL_SET {
            assert_eq!(LogicOp::from_gl(e).unwrap().to_gl(), e);
        }
        assert!(LogicOp::from_gl(GL_SET + 1).is_err());
        assert_eq!(
            LogicOp::from_gl(GL_XOR).unwrap().apply(0b1100, 0b1010),
            0b0110
        );
    }
}
