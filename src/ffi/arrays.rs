//! Client vertex arrays: gl*Pointer, glEnable/DisableClientState, glInterleavedArrays and
//! glArrayElement. A pointer given while a buffer is bound to GL_ARRAY_BUFFER is an offset.
#![allow(non_snake_case)]

use super::enums::*;
use super::glext_enums::*;
use super::types::*;
use super::with_ctx;
use crate::context::arrays::{ArrayPointer, DataType};
use crate::context::error::{GlError, GlResult};
use crate::context::Context;
use libc::c_void;

/// Which client array a call names.
#[derive(Clone, Copy)]
pub(crate) enum Which {
    Vertex,
    Color,
    Normal,
    TexCoord,
    EdgeFlag,
    Index,
    SecondaryColor,
    FogCoord,
}

fn array_mut(c: &mut Context, w: Which) -> &mut ArrayPointer {
    match w {
        Which::Vertex => &mut c.arrays.vertex,
        Which::Color => &mut c.arrays.color,
        Which::Normal => &mut c.arrays.normal,
        Which::TexCoord => &mut c.arrays.texcoord[c.state.client_active_texture],
        Which::EdgeFlag => &mut c.arrays.edge_flag,
        Which::Index => &mut c.arrays.index,
        Which::SecondaryColor => &mut c.arrays.secondary_color,
        Which::FogCoord => &mut c.arrays.fog_coord,
    }
}

/// gl*Pointer: validates as Mesa does (inside glBegin/glEnd its dispatch table answers
/// GL_INVALID_OPERATION; then the stride, the type and the size, in that order) and
/// stores the pointer. Mesa 22.3 still stores a negative stride after reporting it; we
/// keep the old state, as GL requires.
pub(crate) fn set_pointer(w: Which, size: GLint, ty: GLenum, stride: GLsizei, ptr: *const c_void) {
    with_ctx(|c| {
        if stride < 0 {
            return Err(GlError::InvalidValue);
        }
        let t = DataType::from_gl(ty)?;
        let type_ok = match w {
            Which::Vertex | Which::TexCoord => matches!(
                t,
                DataType::Short | DataType::Int | DataType::Float | DataType::Double
            ),
            Which::Normal => matches!(
                t,
                DataType::Byte
                    | DataType::Short
                    | DataType::Int
                    | DataType::Float
                    | DataType::Double
            ),
            Which::Color | Which::SecondaryColor => true,
            Which::EdgeFlag => t == DataType::UByte,
            Which::Index => matches!(
                t,
                DataType::UByte
                    | DataType::Short
                    | DataType::Int
                    | DataType::Float
                    | DataType::Double
            ),
            Which::FogCoord => matches!(t, DataType::Float | DataType::Double),
        };
        if !type_ok {
            return Err(GlError::InvalidEnum);
        }
        let size_ok = match w {
            Which::Vertex => (2..=4).contains(&size),
            Which::Color | Which::SecondaryColor => (3..=4).contains(&size),
            Which::TexCoord => (1..=4).contains(&size),
            Which::Normal => size == 3,
            Which::EdgeFlag | Which::Index | Which::FogCoord => size == 1,
        };
        if !size_ok {
            return Err(GlError::InvalidValue);
        }
        let buffer = c.arrays.array_buffer;
        let a = array_mut(c, w);
        a.size = size;
        a.ty = t;
        a.stride = stride;
        a.ptr = ptr as usize;
        a.buffer = buffer;
        Ok(())
    })
}

/// glVertexPointer.
#[no_mangle]
pub extern "C" fn glVertexPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    set_pointer(Which::Vertex, size, type_, stride, ptr)
}

/// glColorPointer.
#[no_mangle]
pub extern "C" fn glColorPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    set_pointer(Which::Color, size, type_, stride, ptr)
}

/// glTexCoordPointer (for the client-active texture unit).
#[no_mangle]
pub extern "C" fn glTexCoordPointer(
    size: GLint,
    type_: GLenum,
    stride: GLsizei,
    ptr: *const GLvoid,
) {
    set_pointer(Which::TexCoord, size, type_, stride, ptr)
}

/// glEdgeFlagPointer (GLboolean elements).
#[no_mangle]
pub extern "C" fn glEdgeFlagPointer(stride: GLsizei, ptr: *const GLvoid) {
    set_pointer(Which::EdgeFlag, 1, GL_UNSIGNED_BYTE, stride, ptr)
}

/// glIndexPointer (kept for glGet; an RGBA context does not read the index array).
#[no_mangle]
pub extern "C" fn glIndexPointer(type_: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    set_pointer(Which::Index, 1, type_, stride, ptr)
}

/// glNormalPointer.
#[no_mangle]
pub extern "C" fn glNormalPointer(type_: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    set_pointer(Which::Normal, 3, type_, stride, ptr)
}

fn client_state(cap: GLenum, on: bool) {
    with_ctx(|c| set_client_array(c, cap, on))
}

/// The client array `cap` names, if any.
fn client_array(cap: GLenum) -> Option<Which> {
    Some(match cap {
        GL_VERTEX_ARRAY => Which::Vertex,
        GL_COLOR_ARRAY => Which::Color,
        GL_NORMAL_ARRAY => Which::Normal,
        GL_TEXTURE_COORD_ARRAY => Which::TexCoord,
        GL_EDGE_FLAG_ARRAY => Which::EdgeFlag,
        // Kept for glGet; an RGBA context does not read the index array.
        GL_INDEX_ARRAY => Which::Index,
        GL_SECONDARY_COLOR_ARRAY => Which::SecondaryColor,
        GL_FOG_COORD_ARRAY => Which::FogCoord,
        _ => return None,
    })
}

/// Whether `cap` names a client array (then glEnable/glDisable treat it as
/// glEnableClientState/glDisableClientState, as Mesa's compatibility profile does).
pub(crate) fn is_client_array(cap: GLenum) -> bool {
    client_array(cap).is_some()
}

/// Whether the client array `cap` names is enabled (None when `cap` names none).
pub(crate) fn client_array_enabled(c: &mut Context, cap: GLenum) -> Option<bool> {
    client_array(cap).map(|w| array_mut(c, w).enabled)
}

/// glEnableClientState/glDisableClientState on the context.
pub(crate) fn set_client_array(c: &mut Context, cap: GLenum, on: bool) -> GlResult<()> {
    let w = client_array(cap).ok_or(GlError::InvalidEnum)?;
    array_mut(c, w).enabled = on;
    Ok(())
}

/// glEnableClientState.
#[no_mangle]
pub extern "C" fn glEnableClientState(cap: GLenum) {
    client_state(cap, true)
}

/// glDisableClientState.
#[no_mangle]
pub extern "C" fn glDisableClientState(cap: GLenum) {
    client_state(cap, false)
}

/// (tex size, colour size, colour type, normal?, vertex size, colour/normal/vertex offsets,
/// stride) of one glInterleavedArrays format.
type Layout = (i32, i32, GLenum, bool, i32, i32, i32, i32, i32);

/// glInterleavedArrays: sets and enables the arrays of one of the 14 fixed layouts.
#[no_mangle]
pub extern "C" fn glInterleavedArrays(format: GLenum, stride: GLsizei, pointer: *const GLvoid) {
    const F: i32 = 4;
    const C: i32 = 4;
    // (tex size, colour size, colour type, normal?, vertex size, colour off, normal off, vertex off, stride)
    let layout: Option<Layout> = match format {
        GL_V2F => Some((0, 0, 0, false, 2, 0, 0, 0, 2 * F)),
        GL_V3F => Some((0, 0, 0, false, 3, 0, 0, 0, 3 * F)),
        GL_C4UB_V2F => Some((0, 4, GL_UNSIGNED_BYTE, false, 2, 0, 0, C, C + 2 * F)),
        GL_C4UB_V3F => Some((0, 4, GL_UNSIGNED_BYTE, false, 3, 0, 0, C, C + 3 * F)),
        GL_C3F_V3F => Some((0, 3, GL_FLOAT, false, 3, 0, 0, 3 * F, 6 * F)),
        GL_N3F_V3F => Some((0, 0, 0, true, 3, 0, 0, 3 * F, 6 * F)),
        GL_C4F_N3F_V3F => Some((0, 4, GL_FLOAT, true, 3, 0, 4 * F, 7 * F, 10 * F)),
        GL_T2F_V3F => Some((2, 0, 0, false, 3, 0, 0, 2 * F, 5 * F)),
        GL_T4F_V4F => Some((4, 0, 0, false, 4, 0, 0, 4 * F, 8 * F)),
        GL_T2F_C4UB_V3F => Some((
            2,
            4,
            GL_UNSIGNED_BYTE,
            false,
            3,
            2 * F,
            0,
            C + 2 * F,
            C + 5 * F,
        )),
        GL_T2F_C3F_V3F => Some((2, 3, GL_FLOAT, false, 3, 2 * F, 0, 5 * F, 8 * F)),
        GL_T2F_N3F_V3F => Some((2, 0, 0, true, 3, 0, 2 * F, 5 * F, 8 * F)),
        GL_T2F_C4F_N3F_V3F => Some((2, 4, GL_FLOAT, true, 3, 2 * F, 6 * F, 9 * F, 12 * F)),
        GL_T4F_C4F_N3F_V4F => Some((4, 4, GL_FLOAT, true, 4, 4 * F, 8 * F, 11 * F, 15 * F)),
        _ => None,
    };
    if !super::outside_begin_end() {
        return;
    }
    let Some((tc, cc, ctype, norm, vc, pc, pn, pv, s)) = layout else {
        with_ctx(|_| Err::<(), _>(GlError::InvalidEnum));
        return;
    };
    if stride < 0 {
        with_ctx(|_| Err::<(), _>(GlError::InvalidValue));
        return;
    }
    let stride = if stride == 0 { s } else { stride };
    let base = pointer as usize;
    let at = |off: i32| (base + off as usize) as *const c_void;
    client_state(GL_EDGE_FLAG_ARRAY, false);
    client_state(GL_INDEX_ARRAY, false);
    client_state(GL_TEXTURE_COORD_ARRAY, tc > 0);
    if tc > 0 {
        glTexCoordPointer(tc, GL_FLOAT, stride, at(0));
    }
    client_state(GL_COLOR_ARRAY, cc > 0);
    if cc > 0 {
        glColorPointer(cc, ctype, stride, at(pc));
    }
    client_state(GL_NORMAL_ARRAY, norm);
    if norm {
        glNormalPointer(GL_FLOAT, stride, at(pn));
    }
    client_state(GL_VERTEX_ARRAY, true);
    glVertexPointer(vc, GL_FLOAT, stride, at(pv));
}

/// glArrayElement: inside glBegin/glEnd, specifies vertex `i` from the enabled arrays. In a
/// display list the arrays are read at compile time.
#[no_mangle]
pub extern "C" fn glArrayElement(i: GLint) {
    if i < 0 {
        return super::with_ctx_list_anywhere(|_| Err(GlError::InvalidValue));
    }
    let ops = super::with_ctx_raw(|c| {
        let mut ops = Vec::new();
        c.array_element_ops(i as u32, &mut ops);
        Ok(ops)
    });
    for op in ops {
        super::with_ctx_vertex(op);
    }
}
