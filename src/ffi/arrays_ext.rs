//! EXT_vertex_array's pointer calls (glVertexPointerEXT ...): the core calls with an
//! extra element count, which Mesa ignores and so do we.
#![allow(non_snake_case)]

use super::arrays::{
    glColorPointer, glEdgeFlagPointer, glIndexPointer, glNormalPointer, glTexCoordPointer,
    glVertexPointer,
};
use super::types::*;

/// glIndexPointerEXT (EXT_vertex_array): glIndexPointer; `count` is ignored, as in Mesa.
#[no_mangle]
pub extern "C" fn glIndexPointerEXT(
    type_: GLenum,
    stride: GLsizei,
    _count: GLsizei,
    ptr: *const GLvoid,
) {
    glIndexPointer(type_, stride, ptr)
}

/// glVertexPointerEXT (EXT_vertex_array): glVertexPointer; `count` is ignored.
#[no_mangle]
pub extern "C" fn glVertexPointerEXT(
    size: GLint,
    type_: GLenum,
    stride: GLsizei,
    _count: GLsizei,
    ptr: *const GLvoid,
) {
    glVertexPointer(size, type_, stride, ptr)
}

/// glColorPointerEXT (EXT_vertex_array): glColorPointer; `count` is ignored.
#[no_mangle]
pub extern "C" fn glColorPointerEXT(
    size: GLint,
    type_: GLenum,
    stride: GLsizei,
    _count: GLsizei,
    ptr: *const GLvoid,
) {
    glColorPointer(size, type_, stride, ptr)
}

/// glNormalPointerEXT (EXT_vertex_array): glNormalPointer; `count` is ignored.
#[no_mangle]
pub extern "C" fn glNormalPointerEXT(
    type_: GLenum,
    stride: GLsizei,
    _count: GLsizei,
    ptr: *const GLvoid,
) {
    glNormalPointer(type_, stride, ptr)
}

/// glTexCoordPointerEXT (EXT_vertex_array): glTexCoordPointer; `count` is ignored.
#[no_mangle]
pub extern "C" fn glTexCoordPointerEXT(
    size: GLint,
    type_: GLenum,
    stride: GLsizei,
    _count: GLsizei,
    ptr: *const GLvoid,
) {
    glTexCoordPointer(size, type_, stride, ptr)
}

/// glEdgeFlagPointerEXT (EXT_vertex_array): glEdgeFlagPointer; `count` is ignored.
#[no_mangle]
pub extern "C" fn glEdgeFlagPointerEXT(stride: GLsizei, _count: GLsizei, ptr: *const GLboolean) {
    glEdgeFlagPointer(stride, ptr as *const GLvoid)
}
