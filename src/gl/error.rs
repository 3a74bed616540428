//! GL errors: the values glGetError reports, as a Rust error type for `?`.

use super::enums::*;
use super::types::GLenum;

/// A GL error; the failing call must leave all state unchanged.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GlError {
    /// GL_INVALID_ENUM: an enum argument is not allowed for this call.
    InvalidEnum,
    /// GL_INVALID_VALUE: a numeric argument is out of range.
    InvalidValue,
    /// GL_INVALID_OPERATION: the call is not allowed in the current state.
    InvalidOperation,
    /// GL_STACK_OVERFLOW: a push on a full stack.
    StackOverflow,
    /// GL_STACK_UNDERFLOW: a pop on a stack with one entry.
    StackUnderflow,
    /// GL_OUT_OF_MEMORY: an allocation failed.
    OutOfMemory,
    /// GL_INVALID_FRAMEBUFFER_OPERATION: drawing to or reading from an incomplete
    /// framebuffer object.
    InvalidFramebufferOperation,
}

impl GlError {
    /// The GL enum value glGetError returns for this error.
    pub fn to_gl(self) -> GLenum {
        match self {
            GlError::InvalidEnum => GL_INVALID_ENUM,
            GlError::InvalidValue => GL_INVALID_VALUE,
            GlError::InvalidOperation => GL_INVALID_OPERATION,
            GlError::StackOverflow => GL_STACK_OVERFLOW,
            GlError::StackUnderflow => GL_STACK_UNDERFLOW,
            GlError::OutOfMemory => GL_OUT_OF_MEMORY,
            GlError::InvalidFramebufferOperation => {
                super::glext_enums::GL_INVALID_FRAMEBUFFER_OPERATION
            }
        }
    }
}

/// The result type of every context method that can fail with a GL error.
pub type GlResult<T> = Result<T, GlError>;
