//! Line, point and polygon rasterization state: glLineWidth, glLineStipple, glPointSize,
//! glPolygonMode, glPolygonOffset, glPolygonStipple, glGetPolygonStipple and glEdgeFlag.
#![allow(non_snake_case)]

use super::types::*;
use super::{gl_bool, with_ctx, with_ctx_list};
use crate::context::error::GlError;
use crate::context::raster_state::FillMode;
use crate::context::state::Face;
use crate::context::Context;

/// Stores a line width or point size: GL_INVALID_VALUE unless it is positive.
fn set_size(size: f32, field: fn(&mut Context) -> &mut f32) {
    with_ctx_list(move |c| {
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
    with_ctx_list(move |c| {
        c.raster.line.stipple_repeat = factor.clamp(1, 256) as u32;
        c.raster.line.stipple_pattern = pattern;
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
    with_ctx_list(move |c| {
        let face = Face::from_gl(face)?;
        let mode = FillMode::from_gl(mode)?;
        let p = &mut c.raster.polygon;
        if face != Face::Back {
            p.mode_front = mode;
        }
        if face != Face::Front {
            p.mode_back = mode;
        }
        Ok(())
    })
}

/// glPolygonOffset.
#[no_mangle]
pub extern "C" fn glPolygonOffset(factor: GLfloat, units: GLfloat) {
    with_ctx_list(move |c| {
        c.raster.polygon.offset_factor = factor;
        c.raster.polygon.offset_units = units;
        Ok(())
    })
}

/// Reads the 32x32 stipple from 128 bytes (rows bottom-up, 4 bytes each).
fn stipple_from_bytes(b: &[u8; 128], lsb_first: bool) -> [u32; 32] {
    std::array::from_fn(|r| {
        let mut row = [b[4 * r], b[4 * r + 1], b[4 * r + 2], b[4 * r + 3]];
        if lsb_first {
            row = row.map(u8::reverse_bits);
        }
        u32::from_be_bytes(row)
    })
}

/// glPolygonStipple (honours GL_UNPACK_LSB_FIRST; a NULL mask is ignored).
///
/// # Safety
/// `mask` must be NULL or readable for 128 bytes.
#[no_mangle]
pub unsafe extern "C" fn glPolygonStipple(mask: *const GLubyte) {
    let bytes: Option<[u8; 128]> = (!mask.is_null()).then(|| {
        let mut b = [0u8; 128];
        // SAFETY: the GL contract makes `mask` point to a 32x32 bitmap (128 bytes); it was
        // checked for NULL.
        unsafe { std::ptr::copy_nonoverlapping(mask, b.as_mut_ptr(), 128) };
        b
    });
    with_ctx_list(move |c| {
        if let Some(b) = bytes {
            c.raster.stipple.0 = stipple_from_bytes(&b, c.state.unpack.lsb_first);
        }
        Ok(())
    })
}

/// glGetPolygonStipple (honours GL_PACK_LSB_FIRST; a NULL mask is ignored).
///
/// # Safety
/// `mask` must be NULL or writable for 128 bytes.
#[no_mangle]
pub unsafe extern "C" fn glGetPolygonStipple(mask: *mut GLubyte) {
    let rows = with_ctx(|c| {
        let lsb = c.state.pack.lsb_first;
        Ok(Some(c.raster.stipple.0.map(|r| {
            let b = r.to_be_bytes();
            if lsb {
                b.map(u8::reverse_bits)
            } else {
                b
            }
        })))
    });
    if let (Some(rows), false) = (rows, mask.is_null()) {
        // SAFETY: the GL contract makes `mask` writable for 128 bytes; checked for NULL.
        unsafe { std::ptr::copy_nonoverlapping(rows.as_ptr().cast::<u8>(), mask, 128) };
    }
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
