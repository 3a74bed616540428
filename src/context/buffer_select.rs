//! glDrawBuffer, glDrawBuffers and glReadBuffer: of the window, or of the bound
//! framebuffer object. glDrawBuffers checks its list as Mesa's `draw_buffers` does (in
//! its order, the first failure reported and nothing changed): a name of several
//! buffers (GL_FRONT, GL_BACK, GL_LEFT, GL_RIGHT, GL_FRONT_AND_BACK) or no buffer name
//! is GL_INVALID_ENUM; a buffer the framebuffer lacks (a window name for an object,
//! GL_COLOR_ATTACHMENTi past the eight draw buffers, a colour attachment or a right or
//! aux buffer for the window) and a repeated buffer are GL_INVALID_OPERATION.

use super::fbo_api::object_buffer;
use super::legacy_state::{ColorBuffer, MAX_DRAW_BUFFERS, MORE_DRAW_BUFFERS};
use super::{Context, GlError, GlResult};
use crate::gl::enums::*;
use crate::gl::glext_enums::{GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT31};
use crate::gl::types::*;

/// One glDrawBuffers entry of the window: its buffer (`None` for GL_NONE).
fn window_entry(b: GLenum) -> GlResult<Option<ColorBuffer>> {
    match b {
        GL_NONE => Ok(None),
        GL_FRONT | GL_BACK | GL_LEFT | GL_RIGHT | GL_FRONT_AND_BACK => Err(GlError::InvalidEnum),
        GL_COLOR_ATTACHMENT0..=GL_COLOR_ATTACHMENT31 => Err(GlError::InvalidOperation),
        _ => ColorBuffer::from_gl(b).map(Some),
    }
}

/// One glDrawBuffers entry of a framebuffer object: its colour attachment (`None` for
/// GL_NONE).
fn object_entry(b: GLenum) -> GlResult<Option<usize>> {
    match b {
        GL_FRONT | GL_BACK | GL_LEFT | GL_RIGHT | GL_FRONT_AND_BACK => Err(GlError::InvalidEnum),
        GL_COLOR_ATTACHMENT0..=GL_COLOR_ATTACHMENT31 => {
            let i = (b - GL_COLOR_ATTACHMENT0) as usize;
            match i < MAX_DRAW_BUFFERS {
                true => Ok(Some(i)),
                false => Err(GlError::InvalidOperation),
            }
        }
        _ => object_buffer(b),
    }
}

/// Fails with GL_INVALID_OPERATION when a buffer other than GL_NONE repeats in `list`.
fn distinct<T: PartialEq>(list: &[Option<T>]) -> GlResult<()> {
    for (k, a) in list.iter().enumerate() {
        if a.is_some() && list[..k].contains(a) {
            return Err(GlError::InvalidOperation);
        }
    }
    Ok(())
}

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
                    f.more_draw = [None; MORE_DRAW_BUFFERS];
                }
                Ok(())
            });
        }
        self.state.legacy.draw_buffer = ColorBuffer::from_gl(mode)?;
        self.state.legacy.more_draw = [ColorBuffer::None; MORE_DRAW_BUFFERS];
        Ok(())
    }

    /// glDrawBuffers: draw buffer i of the draw framebuffer becomes `bufs[i]`, the
    /// buffers past the list GL_NONE.
    pub(crate) fn draw_buffers(&mut self, bufs: &[GLenum]) -> GlResult<()> {
        if bufs.len() > MAX_DRAW_BUFFERS {
            return Err(GlError::InvalidValue);
        }
        if self.fbo.draw != 0 {
            let mut list = [None; MAX_DRAW_BUFFERS];
            for (k, &b) in bufs.iter().enumerate() {
                list[k] = object_entry(b)?;
                distinct(&list[..=k])?;
            }
            return self.fbo_edit(|c| {
                let name = c.fbo.draw;
                if let Some(f) = c.fbo.object_mut(name) {
                    f.draw_buffer = list[0];
                    f.more_draw.copy_from_slice(&list[1..]);
                }
                Ok(())
            });
        }
        let mut list = [None; MAX_DRAW_BUFFERS];
        for (k, &b) in bufs.iter().enumerate() {
            list[k] = window_entry(b)?;
            distinct(&list[..=k])?;
        }
        let legacy = &mut self.state.legacy;
        legacy.draw_buffer = list[0].unwrap_or(ColorBuffer::None);
        for (m, l) in legacy.more_draw.iter_mut().zip(&list[1..]) {
            *m = l.unwrap_or(ColorBuffer::None);
        }
        Ok(())
    }

    /// GL_DRAW_BUFFERi of the draw framebuffer (`i` < GL_MAX_DRAW_BUFFERS).
    pub(crate) fn draw_buffer_query(&self, i: usize) -> Option<GLenum> {
        let attachment = |b: Option<usize>| b.map_or(GL_NONE, |i| GL_COLOR_ATTACHMENT0 + i as u32);
        if let Some(f) = self.fbo.object(self.fbo.draw) {
            return Some(match i {
                0 => attachment(f.draw_buffer),
                _ => attachment(*f.more_draw.get(i - 1)?),
            });
        }
        let l = &self.state.legacy;
        Some(match i {
            0 => l.draw_buffer.to_gl(),
            _ => l.more_draw.get(i - 1)?.to_gl(),
        })
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
