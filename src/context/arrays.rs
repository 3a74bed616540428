//! Vertex-array state: client array pointers (glVertexPointer …) and buffer objects
//! (glGenBuffers, glBufferData …). While a buffer is bound to GL_ARRAY_BUFFER, a pointer
//! given to gl*Pointer is an offset into that buffer.

use super::error::{GlError, GlResult};
use super::state::MAX_TEXTURE_UNITS;

/// GL_MAX_VERTEX_ATTRIBS: the generic vertex attributes (16, as Mesa).
pub const MAX_VERTEX_ATTRIBS: usize = 16;
use crate::gl::enums::*;
use crate::gl::types::GLenum;
pub use crate::pipe::{ArrayPointer, DataType};
use std::collections::HashMap;

impl DataType {
    /// Converts a GL type token.
    pub fn from_gl(e: GLenum) -> GlResult<Self> {
        Ok(match e {
            GL_BYTE => Self::Byte,
            GL_UNSIGNED_BYTE => Self::UByte,
            GL_SHORT => Self::Short,
            GL_UNSIGNED_SHORT => Self::UShort,
            GL_INT => Self::Int,
            GL_UNSIGNED_INT => Self::UInt,
            GL_FLOAT => Self::Float,
            GL_DOUBLE => Self::Double,
            _ => return Err(GlError::InvalidEnum),
        })
    }
    /// The GL token.
    pub fn to_gl(self) -> GLenum {
        match self {
            Self::Byte => GL_BYTE,
            Self::UByte => GL_UNSIGNED_BYTE,
            Self::Short => GL_SHORT,
            Self::UShort => GL_UNSIGNED_SHORT,
            Self::Int => GL_INT,
            Self::UInt => GL_UNSIGNED_INT,
            Self::Float => GL_FLOAT,
            Self::Double => GL_DOUBLE,
        }
    }
}
/// A buffer object's store.
#[derive(Clone, Debug, Default)]
pub struct BufferObject {
    /// The bytes.
    pub data: super::store::Store,
    /// GL_BUFFER_USAGE.
    pub usage: GLenum,
    /// GL_BUFFER_ACCESS of the current mapping, if mapped.
    pub mapped: Option<GLenum>,
    /// GL_BUFFER_ACCESS as last requested (GL_READ_WRITE initially).
    pub access: GLenum,
}

/// Which binding point a buffer call names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BufferTarget {
    /// GL_ARRAY_BUFFER
    Array,
    /// GL_ELEMENT_ARRAY_BUFFER
    ElementArray,
    /// GL_PIXEL_PACK_BUFFER (the binding lives in the pack [`super::state::PixelStore`])
    PixelPack,
    /// GL_PIXEL_UNPACK_BUFFER (the binding lives in the unpack pixel store)
    PixelUnpack,
}

impl BufferTarget {
    /// Converts a target token (GL 1.5 and the ARB names share values).
    pub fn from_gl(e: GLenum) -> GlResult<Self> {
        use crate::gl::glext_enums::*;
        match e {
            GL_ARRAY_BUFFER => Ok(Self::Array),
            GL_ELEMENT_ARRAY_BUFFER => Ok(Self::ElementArray),
            GL_PIXEL_PACK_BUFFER => Ok(Self::PixelPack),
            GL_PIXEL_UNPACK_BUFFER => Ok(Self::PixelUnpack),
            _ => Err(GlError::InvalidEnum),
        }
    }
}

/// All vertex-array state of a context.
#[derive(Clone, Debug)]
pub struct ArrayState {
    /// GL_VERTEX_ARRAY.
    pub vertex: ArrayPointer,
    /// GL_COLOR_ARRAY.
    pub color: ArrayPointer,
    /// GL_NORMAL_ARRAY.
    pub normal: ArrayPointer,
    /// GL_TEXTURE_COORD_ARRAY per unit.
    pub texcoord: [ArrayPointer; MAX_TEXTURE_UNITS],
    /// GL_EDGE_FLAG_ARRAY (GLboolean elements).
    pub edge_flag: ArrayPointer,
    /// GL_INDEX_ARRAY (kept for glGet; an RGBA context does not read it).
    pub index: ArrayPointer,
    /// GL_SECONDARY_COLOR_ARRAY.
    pub secondary_color: ArrayPointer,
    /// GL_FOG_COORD_ARRAY.
    pub fog_coord: ArrayPointer,
    /// The generic attribute arrays (glVertexAttribPointer). Fixed function reads only
    /// attribute 0, which stands for the vertex array while enabled.
    pub generic: [ArrayPointer; MAX_VERTEX_ATTRIBS],
    /// GL_ARRAY_BUFFER binding.
    pub array_buffer: u32,
    /// GL_ELEMENT_ARRAY_BUFFER binding.
    pub element_buffer: u32,
    /// Buffer objects by name; a generated but never bound name maps to `None`.
    pub buffers: HashMap<u32, Option<BufferObject>>,
}

impl Default for ArrayState {
    fn default() -> Self {
        ArrayState {
            vertex: ArrayPointer::new(4, DataType::Float),
            color: ArrayPointer::new(4, DataType::Float),
            normal: ArrayPointer::new(3, DataType::Float),
            texcoord: [ArrayPointer::new(4, DataType::Float); MAX_TEXTURE_UNITS],
            edge_flag: ArrayPointer::new(1, DataType::UByte),
            index: ArrayPointer::new(1, DataType::Float),
            secondary_color: ArrayPointer::new(3, DataType::Float),
            fog_coord: ArrayPointer::new(1, DataType::Float),
            generic: [ArrayPointer::new(4, DataType::Float); MAX_VERTEX_ATTRIBS],
            array_buffer: 0,
            element_buffer: 0,
            buffers: HashMap::new(),
        }
    }
}

impl ArrayState {
    /// A copy of every array pointer and buffer binding, without the buffer objects (what
    /// glPushClientAttrib saves).
    pub fn bindings(&mut self) -> ArrayState {
        let buffers = std::mem::take(&mut self.buffers);
        let copy = self.clone();
        self.buffers = buffers;
        copy
    }

    /// The live object named `name`, or GL_INVALID_OPERATION for 0 or a deleted name.
    pub fn object_mut(&mut self, name: u32) -> GlResult<&mut BufferObject> {
        if name == 0 {
            return Err(GlError::InvalidOperation);
        }
        self.buffers
            .get_mut(&name)
            .and_then(|b| b.as_mut())
            .ok_or(GlError::InvalidOperation)
    }

    /// `arr` with the store of its buffer object looked up.
    pub fn input<'a>(&'a self, arr: &'a ArrayPointer) -> crate::pipe::ArrayInput<'a> {
        crate::pipe::ArrayInput {
            arr,
            data: if arr.buffer != 0 {
                self.buffer_data(arr.buffer)
            } else {
                None
            },
        }
    }

    /// The array the positions come from: generic attribute 0 while its array is
    /// enabled (the compatibility profile's aliasing; Mesa's attribute map mode GENERIC0
    /// wins over GL_VERTEX_ARRAY), else GL_VERTEX_ARRAY. A draw without either enabled
    /// draws nothing.
    pub fn position(&self) -> &ArrayPointer {
        if self.generic[0].enabled {
            &self.generic[0]
        } else {
            &self.vertex
        }
    }

    /// Every array with its buffer object looked up: what a draw hands the vertex fetch.
    pub fn inputs(&self) -> crate::pipe::VertexArrays<'_> {
        crate::pipe::VertexArrays {
            vertex: self.input(self.position()),
            color: self.input(&self.color),
            normal: self.input(&self.normal),
            texcoord: std::array::from_fn(|u| self.input(&self.texcoord[u])),
            edge_flag: self.input(&self.edge_flag),
            secondary_color: self.input(&self.secondary_color),
            fog_coord: self.input(&self.fog_coord),
            generic: Some(std::array::from_fn(|k| self.input(&self.generic[k]))),
        }
    }

    /// The store of buffer `name`, if it exists.
    pub fn buffer_data(&self, name: u32) -> Option<&[u8]> {
        self.buffers
            .get(&name)
            .and_then(|b| b.as_ref())
            .map(|b| &b.data[..])
    }

    /// glGenBuffers: `n` unused names (reserved, no object yet).
    pub fn gen_buffers(&mut self, n: usize) -> Vec<u32> {
        let mut out = Vec::with_capacity(n);
        let mut next = 1u32;
        while out.len() < n {
            if let std::collections::hash_map::Entry::Vacant(e) = self.buffers.entry(next) {
                e.insert(None);
                out.push(next);
            }
            next += 1;
        }
        out
    }

    /// glDeleteBuffers for one name: unbinds it everywhere in this context. Arrays that
    /// sourced it become null pointers (never a dangling offset read as an address).
    pub fn delete_buffer(&mut self, name: u32) {
        if name == 0 || self.buffers.remove(&name).is_none() {
            return;
        }
        if self.array_buffer == name {
            self.array_buffer = 0;
        }
        if self.element_buffer == name {
            self.element_buffer = 0;
        }
        for a in self.all_arrays_mut() {
            if a.buffer == name {
                a.buffer = 0;
                a.ptr = 0;
            }
        }
    }

    /// Makes `name` a buffer object if it is not one yet (glBindBuffer's creation of a
    /// name; 0 names none).
    pub fn touch_buffer(&mut self, name: u32) {
        if name != 0 {
            let e = self.buffers.entry(name).or_insert(None);
            if e.is_none() {
                *e = Some(BufferObject {
                    usage: crate::gl::glext_enums::GL_STATIC_DRAW,
                    access: crate::gl::glext_enums::GL_READ_WRITE,
                    ..Default::default()
                });
            }
        }
    }

    fn all_arrays_mut(&mut self) -> impl Iterator<Item = &mut ArrayPointer> {
        [
            &mut self.vertex,
            &mut self.color,
            &mut self.normal,
            &mut self.edge_flag,
            &mut self.index,
            &mut self.secondary_color,
            &mut self.fog_coord,
        ]
        .into_iter()
        .chain(self.texcoord.iter_mut())
        .chain(self.generic.iter_mut())
    }

    /// Every client array (for checks that look at all of them, e.g. mapped buffers).
    pub fn all_arrays(&self) -> impl Iterator<Item = &ArrayPointer> {
        [
            &self.vertex,
            &self.color,
            &self.normal,
            &self.edge_flag,
            &self.secondary_color,
            &self.fog_coord,
        ]
        .into_iter()
        .chain(self.texcoord.iter())
        .chain(self.generic.iter())
    }
}
