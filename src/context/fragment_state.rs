//! Per-fragment operation state as data: blending, alpha test, stencil and logic op, with
//! the GL token conversions done once at the boundary.

use super::error::{GlError, GlResult};
use crate::gl::enums::*;
use crate::gl::glext_enums::*;
use crate::gl::types::GLenum;
pub use crate::pipe::{
    BlendEquation, BlendFactor, BlendState, FragmentOps, LogicOp, StencilFace, StencilOp,
};

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
}
impl LogicOp {
    /// Converts a token (GL_CLEAR..GL_SET are 0x1500..0x150F in this order).
    pub fn from_gl(e: GLenum) -> GlResult<Self> {
        e.checked_sub(GL_CLEAR)
            .and_then(|i| LogicOp::ALL.get(i as usize).copied())
            .ok_or(GlError::InvalidEnum)
    }
    /// The GL token.
    pub fn to_gl(self) -> GLenum {
        GL_CLEAR + self as GLenum
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
