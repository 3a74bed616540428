//! The client arrays of GL 1.4 (EXT_secondary_color, EXT_fog_coord):
//! glSecondaryColorPointer and glFogCoordPointer. Their enables, queries and the draw
//! calls that read them live with the other arrays (`arrays.rs`, `draw.rs`).
#![allow(non_snake_case)]

use super::arrays::set_pointer;
use super::types::*;
use crate::context::client_arrays::ClientArray;

/// glSecondaryColorPointer: 3 or 4 components of any integer type (normalised), float
/// or double.
#[no_mangle]
pub extern "C" fn glSecondaryColorPointer(
    size: GLint,
    type_: GLenum,
    stride: GLsizei,
    pointer: *const GLvoid,
) {
    set_pointer(ClientArray::SecondaryColor, size, type_, stride, pointer)
}

/// glFogCoordPointer: one float or double per vertex.
#[no_mangle]
pub extern "C" fn glFogCoordPointer(type_: GLenum, stride: GLsizei, pointer: *const GLvoid) {
    set_pointer(ClientArray::FogCoord, 1, type_, stride, pointer)
}
