//! Client vertex arrays: gl*Pointer, glEnable/DisableClientState, glInterleavedArrays and
//! glArrayElement. A pointer given while a buffer is bound to GL_ARRAY_BUFFER is an offset.
#![allow(non_snake_case)]

use super::enums::*;
use super::types::*;
use super::with_ctx_keep;
use crate::context::client_arrays::ClientArray;
use crate::context::error::GlError;
use libc::c_void;

/// gl*Pointer: stores the pointer of client array `w` (see
/// [`Context::set_array_pointer`]).
pub(crate) fn set_pointer(
    w: ClientArray,
    size: GLint,
    ty: GLenum,
    stride: GLsizei,
    ptr: *const c_void,
) {
    with_ctx_keep(|c| c.set_array_pointer(w, (size, ty, stride), ptr as usize))
}

/// glVertexPointer.
#[no_mangle]
pub extern "C" fn glVertexPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    set_pointer(ClientArray::Vertex, size, type_, stride, ptr)
}

/// glColorPointer.
#[no_mangle]
pub extern "C" fn glColorPointer(size: GLint, type_: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    set_pointer(ClientArray::Color, size, type_, stride, ptr)
}

/// glTexCoordPointer (for the client-active texture unit).
#[no_mangle]
pub extern "C" fn glTexCoordPointer(
    size: GLint,
    type_: GLenum,
    stride: GLsizei,
    ptr: *const GLvoid,
) {
    set_pointer(ClientArray::TexCoord, size, type_, stride, ptr)
}

/// glEdgeFlagPointer (GLboolean elements).
#[no_mangle]
pub extern "C" fn glEdgeFlagPointer(stride: GLsizei, ptr: *const GLvoid) {
    set_pointer(ClientArray::EdgeFlag, 1, GL_UNSIGNED_BYTE, stride, ptr)
}

/// glIndexPointer (kept for glGet; an RGBA context does not read the index array).
#[no_mangle]
pub extern "C" fn glIndexPointer(type_: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    set_pointer(ClientArray::Index, 1, type_, stride, ptr)
}

/// glNormalPointer.
#[no_mangle]
pub extern "C" fn glNormalPointer(type_: GLenum, stride: GLsizei, ptr: *const GLvoid) {
    set_pointer(ClientArray::Normal, 3, type_, stride, ptr)
}

fn client_state(cap: GLenum, on: bool) {
    with_ctx_keep(|c| c.set_client_array(cap, on))
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

/// glInterleavedArrays: sets and enables the arrays of one of the 14 fixed layouts.
#[no_mangle]
pub extern "C" fn glInterleavedArrays(format: GLenum, stride: GLsizei, pointer: *const GLvoid) {
    with_ctx_keep(|c| c.interleaved_arrays(format, stride, pointer as usize))
}

/// glArrayElement: inside glBegin/glEnd, specifies vertex `i` from the enabled arrays. In a
/// display list the arrays are read at compile time.
#[no_mangle]
pub extern "C" fn glArrayElement(i: GLint) {
    if i < 0 {
        return super::with_ctx_list_anywhere(|_| Err(GlError::InvalidValue));
    }
    super::with_ctx_raw(|c| {
        c.array_element(i as u32);
        Ok(())
    })
}
