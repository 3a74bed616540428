//! The OSMesa user buffer as the state machine sees it: the buffer OSMesaMakeCurrent binds,
//! its OSMesaPixelStore parameters, and the depth copy OSMesaGetDepthBuffer hands out.
//! The C boundary (`ffi/osmesa.rs`) owns the handles and the buffer formats; it changes
//! these fields only through the methods here.

use super::{Context, GlError, GlResult};
use crate::framebuffer::{ColorFormat, DepthFormat};
use crate::gl::types::*;

/// What OSMesaGetDepthBuffer reports: width, height, bytes per value and the copy's
/// address.
pub type DepthBufferView = (GLint, GLint, GLint, *mut std::ffi::c_void);

impl Context {
    /// OSMesaMakeCurrent's binding of `width` x `height` pixels at `ptr` of component type
    /// `ty`, laid out as `format`: sizes the window framebuffer (cleared again when the
    /// type changed) and makes it the target of the glFlush/glFinish copy.
    pub(crate) fn attach_user_buffer(
        &mut self,
        format: ColorFormat,
        ptr: usize,
        ty: GLenum,
        (width, height): (usize, usize),
    ) {
        self.visual.format = format;
        let retyped = self.target.ty != ty;
        self.bind_framebuffer(width, height, retyped);
        self.target.ptr = ptr;
        self.target.ty = ty;
        self.target.width = width;
        self.target.height = height;
        // 16-bit and float buffers are rendered at their own precision.
        let kind = super::wide_type(ty).map(|t| t.kind());
        self.with_window(|c| {
            if let Some(fb) = c.fb.as_mut().filter(|fb| fb.wide != kind) {
                fb.set_wide(kind);
            }
        });
    }

    /// OSMESA_ROW_LENGTH: the user buffer's row length in pixels (0 = its width).
    pub(crate) fn set_user_row_length(&mut self, value: GLint) -> GlResult<()> {
        if value < 0 {
            return Err(GlError::InvalidValue);
        }
        self.target.row_length = value;
        Ok(())
    }

    /// OSMESA_Y_UP: whether row 0 of the user buffer is the bottom row.
    pub(crate) fn set_user_y_up(&mut self, y_up: bool) {
        self.target.y_up = y_up;
    }

    /// OSMesaGetDepthBuffer: the window's depth buffer as a copy kept in the context
    /// (made on first request, refreshed at each flush); `None` without a depth buffer.
    pub(crate) fn depth_buffer_view(&mut self) -> Option<DepthBufferView> {
        self.settle_draws();
        let fb = self.window_fb()?;
        if fb.depth_format == DepthFormat::None {
            return None;
        }
        let (w, h) = (fb.width as GLint, fb.height as GLint);
        let bpv = if fb.depth_format == DepthFormat::Z16 {
            2
        } else {
            4
        };
        if self.depth_copy.is_none() {
            self.depth_copy = Some(self.depth_snapshot());
        }
        let p = self
            .depth_copy
            .as_mut()
            .map_or(std::ptr::null_mut(), |v| v.as_mut_ptr() as *mut _);
        Some((w, h, bpv, p))
    }
}
