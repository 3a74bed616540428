//! Small pieces of state outside the other groups: the colour-index values an RGBA
//! context keeps without drawing with them (glIndexMask, glClearIndex; the current index
//! is a current attribute), glSampleCoverage's value and invert flag (used when drawing
//! into a 4x multisample framebuffer object with GL_SAMPLE_COVERAGE on), and the draw and
//! read buffer selection of the single-buffered OSMesa window (a framebuffer object keeps
//! its own, [`super::fbo`]).

use super::error::{GlError, GlResult};
use crate::gl::enums::*;

/// GL_MAX_DRAW_BUFFERS (llvmpipe's `PIPE_MAX_COLOR_BUFS`).
pub const MAX_DRAW_BUFFERS: usize = 8;
/// GL_MAX_DRAW_BUFFERS (GL 2.0; not in the generated enums).
pub const GL_MAX_DRAW_BUFFERS: u32 = 0x8824;
/// GL_DRAW_BUFFER0: GL_DRAW_BUFFERi is `GL_DRAW_BUFFER0 + i`.
pub const GL_DRAW_BUFFER0: u32 = 0x8825;
/// GL_DRAW_BUFFER7, the last of the eight.
pub const GL_DRAW_BUFFER7: u32 = 0x882C;
/// The draw buffers after draw buffer 0.
pub const MORE_DRAW_BUFFERS: usize = MAX_DRAW_BUFFERS - 1;

/// A colour buffer named by glDrawBuffer / glReadBuffer, among those an OSMesa
/// framebuffer accepts (it has one, front-left, colour buffer; Mesa also accepts the
/// names that include it through "back", and draws into the single buffer).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorBuffer {
    /// GL_NONE: nothing is drawn (or read).
    None,
    /// GL_FRONT.
    Front,
    /// GL_BACK.
    Back,
    /// GL_LEFT.
    Left,
    /// GL_FRONT_LEFT.
    FrontLeft,
    /// GL_BACK_LEFT.
    BackLeft,
    /// GL_FRONT_AND_BACK.
    FrontAndBack,
}

impl ColorBuffer {
    /// Converts a glDrawBuffer/glReadBuffer argument: GL_INVALID_ENUM for a name that is
    /// no colour buffer, GL_INVALID_OPERATION for a buffer the framebuffer does not have
    /// (right, aux), as Mesa's `draw_buffer_enum_to_bitmask` and supported-mask check do.
    pub fn from_gl(e: u32) -> GlResult<ColorBuffer> {
        Ok(match e {
            GL_NONE => ColorBuffer::None,
            GL_FRONT => ColorBuffer::Front,
            GL_BACK => ColorBuffer::Back,
            GL_LEFT => ColorBuffer::Left,
            GL_FRONT_LEFT => ColorBuffer::FrontLeft,
            GL_BACK_LEFT => ColorBuffer::BackLeft,
            GL_FRONT_AND_BACK => ColorBuffer::FrontAndBack,
            GL_RIGHT | GL_FRONT_RIGHT | GL_BACK_RIGHT => return Err(GlError::InvalidOperation),
            _ if (GL_AUX0..GL_AUX0 + 4).contains(&e) => return Err(GlError::InvalidOperation),
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// The GL enum glGet returns.
    pub fn to_gl(self) -> u32 {
        match self {
            ColorBuffer::None => GL_NONE,
            ColorBuffer::Front => GL_FRONT,
            ColorBuffer::Back => GL_BACK,
            ColorBuffer::Left => GL_LEFT,
            ColorBuffer::FrontLeft => GL_FRONT_LEFT,
            ColorBuffer::BackLeft => GL_BACK_LEFT,
            ColorBuffer::FrontAndBack => GL_FRONT_AND_BACK,
        }
    }
}

/// The values of this module, one field per GL value.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LegacyState {
    /// glIndexMask (GL_INDEX_WRITEMASK), all ones initially.
    pub index_mask: u32,
    /// glClearIndex (GL_INDEX_CLEAR_VALUE), stored as Mesa does: truncated to an integer.
    pub clear_index: u32,
    /// glSampleCoverage value, clamped to [0, 1].
    pub sample_coverage_value: f32,
    /// glSampleCoverage invert flag.
    pub sample_coverage_invert: bool,
    /// glDrawBuffer (draw buffer 0 of glDrawBuffers).
    pub draw_buffer: ColorBuffer,
    /// Draw buffers 1.. of glDrawBuffers (GL_NONE after glDrawBuffer). The window has one
    /// colour buffer: these only answer GL_DRAW_BUFFERi.
    pub more_draw: [ColorBuffer; MORE_DRAW_BUFFERS],
    /// glReadBuffer.
    pub read_buffer: ColorBuffer,
}

impl Default for LegacyState {
    fn default() -> Self {
        LegacyState {
            index_mask: u32::MAX,
            clear_index: 0,
            sample_coverage_value: 1.0,
            sample_coverage_invert: false,
            draw_buffer: ColorBuffer::Front,
            more_draw: [ColorBuffer::None; MORE_DRAW_BUFFERS],
            read_buffer: ColorBuffer::Front,
        }
    }
}

impl LegacyState {
    /// glClearIndex: Mesa keeps `(GLuint) c`.
    pub fn set_clear_index(&mut self, c: f32) {
        // An in-range value truncates as the C cast does; `as` saturates the rest (a
        // negative or NaN value gives 0, where the C cast is undefined).
        self.clear_index = c as u32;
    }

    /// glSampleCoverage.
    pub fn set_sample_coverage(&mut self, value: f32, invert: bool) {
        self.sample_coverage_value = if value.is_nan() {
            0.0
        } else {
            value.clamp(0.0, 1.0)
        };
        self.sample_coverage_invert = invert;
    }

    /// Whether drawing writes colour at all (glDrawBuffer(GL_NONE) turns it off).
    pub fn draws_color(&self) -> bool {
        self.draw_buffer != ColorBuffer::None
    }

    /// Whether glReadPixels, glCopyPixels and glCopyTex* have a colour buffer to read.
    pub fn reads_color(&self) -> bool {
        self.read_buffer != ColorBuffer::None
    }
}
