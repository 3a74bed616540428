//! glDrawBuffer and glReadBuffer: of the window, or of the bound framebuffer object.

use super::fbo_api::object_buffer;
use super::legacy_state::ColorBuffer;
use super::{Context, GlResult};
use crate::gl::types::*;

impl Context {
    /// glDrawBuffer: GL_NONE turns colour writes off; every name of the single front-left
    /// buffer (front, back, left, front-and-back) draws into it, as Mesa's OSMesa does.
    pub(crate) fn draw_buffer(&mut self, mode: GLenum) -> GlResult<()> {
        if self.fbo.draw != 0 {
            let b = object_buffer(mode)?;
            return self.fbo_edit(|c| {
                let name = c.fbo.draw;
                if let Some(f) = c.fbo.object_mut(name) {
                    f.draw_buffer = b;
                }
                Ok(())
            });
        }
        self.state.legacy.draw_buffer = ColorBuffer::from_gl(mode)?;
        Ok(())
    }

    /// glReadBuffer: GL_NONE makes colour reads GL_INVALID_OPERATION.
    pub(crate) fn read_buffer(&mut self, mode: GLenum) -> GlResult<()> {
        let read = self.fbo.read;
        if let Some(f) = self.fbo.object_mut(read) {
            f.read_buffer = object_buffer(mode)?;
            return Ok(());
        }
        self.state.legacy.read_buffer = ColorBuffer::from_gl(mode)?;
        Ok(())
    }
}
