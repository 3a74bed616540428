//! Line, point and polygon rasterization state: glLineWidth, glLineStipple, glPointSize,
//! glPolygonMode, glPolygonOffset, glPolygonStipple, glGetPolygonStipple and glEdgeFlag.
#![allow(non_snake_case)]

use super::types::*;
use super::{gl_bool, with_ctx, with_ctx_list, with_ctx_list_keep};
use crate::context::error::GlError;
use crate::context::raster_state::FillMode;
use crate::context::state::Face;
use crate::context::Context;

/// Stores a line width or point size: GL_INVALID_VALUE unless it is positive.
fn set_size(size: f32, field: fn(&mut Context) -> &mut f32) {
    with_ctx_list_keep(move |c| {
        if size.is_nan() || size <= 0.0 {
            return Err(GlError::InvalidValue);
        }
        *field(c) = size;
        Ok(())
    })
}

/// glLineWidth (GL_INVALID_VALUE for width <= 0; stored unclamped as Mesa does).
#[no_mangle]
pub extern "C" fn glLineWidth(width: GLfloat) {
    set_size(width, |c| &mut c.raster.line.width)
}

/// glLineStipple (the factor is clamped to [1, 256]).
#[no_mangle]
pub extern "C" fn glLineStipple(factor: GLint, pattern: GLushort) {
    with_ctx_list_keep(move |c| {
        c.line_stipple(factor, pattern);
        Ok(())
    })
}

/// glPointSize (GL_INVALID_VALUE for size <= 0; stored unclamped).
#[no_mangle]
pub extern "C" fn glPointSize(size: GLfloat) {
    set_size(size, |c| &mut c.raster.point.size)
}

/// glPolygonMode.
#[no_mangle]
pub extern "C" fn glPolygonMode(face: GLenum, mode: GLenum) {
    with_ctx_list_keep(move |c| {
        let (face, mode) = (Face::from_gl(face)?, FillMode::from_gl(mode)?);
        c.polygon_mode(face, mode);
        Ok(())
    })
}

/// glPolygonOffset.
#[no_mangle]
pub extern "C" fn glPolygonOffset(factor: GLfloat, units: GLfloat) {
    with_ctx_list_keep(move |c| {
        c.polygon_offset(factor, units);
        Ok(())
    })
}

/// glPolygonStipple (honours GL_UNPACK_LSB_FIRST; a NULL mask is ignored).
///
/// # Safety
/// `mask` must be NULL or readable for 128 bytes.
#[no_mangle]
pub unsafe extern "C" fn glPolygonStipple(mask: *const GLubyte) {
    let Some(copy) = super::client::unpack_buffer_bytes(mask as *const GLvoid, None, 128) else {
        return;
    };
    let bytes: Option<[u8; 128]> = match copy {
        Some(b) => b.try_into().ok(),
        // SAFETY: the GL contract makes a non-NULL `mask` point to a 32x32 bitmap (128
        // bytes).
        None => (!mask.is_null()).then(|| unsafe { mask.cast::<[u8; 128]>().read_unaligned() }),
    };
    with_ctx_list(move |c| c.polygon_stipple(bytes.as_ref()))
}

/// glGetPolygonStipple (honours GL_PACK_LSB_FIRST; a NULL mask is ignored).
///
/// # Safety
/// `mask` must be NULL or writable for 128 bytes.
#[no_mangle]
pub unsafe extern "C" fn glGetPolygonStipple(mask: *mut GLubyte) {
    // SAFETY: the GL contract makes a non-NULL `mask` writable for 128 bytes (or a pack
    // buffer takes them).
    with_ctx(|c| unsafe { c.get_polygon_stipple_to(mask) })
}

/// glEdgeFlag.
#[no_mangle]
pub extern "C" fn glEdgeFlag(flag: GLboolean) {
    super::with_ctx_vertex(crate::context::dlist::VertexOp::EdgeFlag(gl_bool(flag)))
}

/// glEdgeFlagv (NULL is ignored).
///
/// # Safety
/// `flag` must be NULL or point to a readable GLboolean.
#[no_mangle]
pub unsafe extern "C" fn glEdgeFlagv(flag: *const GLboolean) {
    if flag.is_null() {
        return;
    }
    // SAFETY: non-NULL and, per the GL contract, points to one GLboolean.
    glEdgeFlag(unsafe { *flag });
}
