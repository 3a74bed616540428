//! A draw's vertex arrays as the vertex fetch reads them: each array's layout with the
//! bytes of its buffer object, looked up once per draw by the state.

use super::{ArrayPointer, MAX_TEXTURE_UNITS};

/// One vertex array: its layout and, for an array in a buffer object, the store's bytes.
#[derive(Clone, Copy, Debug)]
pub struct ArrayInput<'a> {
    /// Enabled flag, element size, type, stride, and the pointer (an offset into the
    /// buffer object when `arr.buffer != 0`).
    pub arr: &'a ArrayPointer,
    /// The buffer object's bytes when `arr.buffer != 0` (`None` when that buffer is gone);
    /// `None` for client memory.
    pub data: Option<&'a [u8]>,
}

/// Every vertex array of a draw.
#[derive(Clone, Copy, Debug)]
pub struct VertexArrays<'a> {
    /// GL_VERTEX_ARRAY.
    pub vertex: ArrayInput<'a>,
    /// GL_COLOR_ARRAY.
    pub color: ArrayInput<'a>,
    /// GL_NORMAL_ARRAY.
    pub normal: ArrayInput<'a>,
    /// GL_TEXTURE_COORD_ARRAY per unit.
    pub texcoord: [ArrayInput<'a>; MAX_TEXTURE_UNITS],
    /// GL_EDGE_FLAG_ARRAY.
    pub edge_flag: ArrayInput<'a>,
    /// GL_SECONDARY_COLOR_ARRAY.
    pub secondary_color: ArrayInput<'a>,
    /// GL_FOG_COORD_ARRAY.
    pub fog_coord: ArrayInput<'a>,
    /// The generic attribute arrays (glVertexAttribPointer), which only a vertex shader
    /// reads (`None`: none given).
    pub generic: Option<[ArrayInput<'a>; MAX_GENERIC]>,
}

/// The generic vertex attributes (GL_MAX_VERTEX_ATTRIBS).
pub const MAX_GENERIC: usize = 16;
