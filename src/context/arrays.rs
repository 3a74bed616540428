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

/// The state a vertex array object holds (GL 3.0 §2.10, ARB_vertex_array_object): every
/// array's pointer, format and enable, and the GL_ELEMENT_ARRAY_BUFFER binding. Object 0
/// is the compatibility profile's default object.
#[derive(Clone, Debug)]
pub struct VertexArrayObject {
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
    /// GL_VERTEX_ATTRIB_ARRAY_DIVISOR per generic attribute (0: one element per vertex;
    /// n: one per n instances).
    pub divisor: [u32; MAX_VERTEX_ATTRIBS],
    /// GL_ELEMENT_ARRAY_BUFFER binding.
    pub element_buffer: u32,
}

impl Default for VertexArrayObject {
    fn default() -> Self {
        VertexArrayObject {
            vertex: ArrayPointer::new(4, DataType::Float),
            color: ArrayPointer::new(4, DataType::Float),
            normal: ArrayPointer::new(3, DataType::Float),
            texcoord: [ArrayPointer::new(4, DataType::Float); MAX_TEXTURE_UNITS],
            edge_flag: ArrayPointer::new(1, DataType::UByte),
            index: ArrayPointer::new(1, DataType::Float),
            secondary_color: ArrayPointer::new(3, DataType::Float),
            fog_coord: ArrayPointer::new(1, DataType::Float),
            generic: [ArrayPointer::new(4, DataType::Float); MAX_VERTEX_ATTRIBS],
            divisor: [0; MAX_VERTEX_ATTRIBS],
            element_buffer: 0,
        }
    }
}

/// All vertex-array state of a context: the bound vertex array object's state, the other
/// objects, the GL_ARRAY_BUFFER binding (context state, not an object's) and the buffer
/// objects.
#[derive(Clone, Debug, Default)]
pub struct ArrayState {
    /// The bound vertex array object's state (the object is moved here while bound).
    pub vao: VertexArrayObject,
    /// GL_VERTEX_ARRAY_BINDING: the bound object's name (0: the default object).
    pub vao_binding: u32,
    /// The vertex array objects not bound, by name: `None` for a generated name never
    /// bound; the default object (0) is here while another is bound.
    pub vaos: HashMap<u32, Option<Box<VertexArrayObject>>>,
    /// GL_ARRAY_BUFFER binding.
    pub array_buffer: u32,
    /// GL_PRIMITIVE_RESTART (GL 3.1): an element equal to `restart_index` ends the
    /// primitive and starts a new one in glDrawElements and its relatives.
    pub primitive_restart: bool,
    /// GL_PRIMITIVE_RESTART_INDEX.
    pub restart_index: u32,
    /// Buffer objects by name; a generated but never bound name maps to `None`.
    pub buffers: HashMap<u32, Option<BufferObject>>,
}

impl ArrayState {
    /// A copy of every array pointer and buffer binding, with the bound vertex array
    /// object's name, without the buffer objects and the other vertex array objects (what
    /// glPushClientAttrib saves).
    pub fn bindings(&mut self) -> ArrayState {
        let buffers = std::mem::take(&mut self.buffers);
        let vaos = std::mem::take(&mut self.vaos);
        let copy = self.clone();
        self.buffers = buffers;
        self.vaos = vaos;
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
        let v = &self.vao;
        if v.generic[0].enabled {
            &v.generic[0]
        } else {
            &v.vertex
        }
    }

    /// Every array with its buffer object looked up: what a draw hands the vertex fetch.
    pub fn inputs(&self) -> crate::pipe::VertexArrays<'_> {
        let v = &self.vao;
        crate::pipe::VertexArrays {
            vertex: self.input(self.position()),
            color: self.input(&v.color),
            normal: self.input(&v.normal),
            texcoord: std::array::from_fn(|u| self.input(&v.texcoord[u])),
            edge_flag: self.input(&v.edge_flag),
            secondary_color: self.input(&v.secondary_color),
            fog_coord: self.input(&v.fog_coord),
            generic: Some(std::array::from_fn(|k| self.input(&v.generic[k]))),
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

    /// glDeleteBuffers for one name: unbinds it everywhere in this context, in every
    /// vertex array object (not only the bound one, as GL 3.0 says: an object keeps no
    /// orphaned store, so a name made again later is never read through an old pointer).
    /// Arrays that sourced it become null pointers (never a dangling offset read as an
    /// address).
    pub fn delete_buffer(&mut self, name: u32) {
        if name == 0 || self.buffers.remove(&name).is_none() {
            return;
        }
        if self.array_buffer == name {
            self.array_buffer = 0;
        }
        let stored = self.vaos.values_mut().flatten().map(|b| &mut **b);
        for v in std::iter::once(&mut self.vao).chain(stored) {
            v.unbind_buffer(name);
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

    /// Every client array of the bound object (for checks that look at all of them,
    /// e.g. mapped buffers).
    pub fn all_arrays(&self) -> impl Iterator<Item = &ArrayPointer> {
        self.vao.all_arrays()
    }

    /// Whether `name` names a vertex array object (bound or not, generated or made).
    pub fn vao_exists(&self, name: u32) -> bool {
        name == 0 || name == self.vao_binding || self.vaos.contains_key(&name)
    }

    /// glGenVertexArrays: `n` unused names (reserved; the object is made by its first
    /// bind). Names in use by this context's objects are skipped.
    pub fn gen_vertex_arrays(&mut self, n: usize) -> Vec<u32> {
        let mut out = Vec::with_capacity(n);
        let mut next = 1u32;
        while out.len() < n {
            if next != self.vao_binding && !self.vaos.contains_key(&next) {
                self.vaos.insert(next, None);
                out.push(next);
            }
            next += 1;
        }
        out
    }

    /// glBindVertexArray: the bound object is stored under its name and `name`'s moved in
    /// (made on its first bind). GL_INVALID_OPERATION for a name never generated or
    /// deleted; nothing changes then.
    pub fn bind_vertex_array(&mut self, name: u32) -> GlResult<()> {
        if !self.vao_exists(name) {
            return Err(GlError::InvalidOperation);
        }
        if name == self.vao_binding {
            return Ok(());
        }
        let next = self.vaos.remove(&name).flatten().unwrap_or_default();
        let old = std::mem::replace(&mut self.vao, *next);
        self.vaos.insert(self.vao_binding, Some(Box::new(old)));
        self.vao_binding = name;
        Ok(())
    }

    /// glDeleteVertexArrays: each of `names` as [`Self::delete_vertex_array`].
    pub fn delete_vertex_arrays(&mut self, names: &[u32]) {
        for &name in names {
            self.delete_vertex_array(name);
        }
    }

    /// glDeleteVertexArrays for one name: a bound object is unbound first (the binding
    /// reverts to 0); 0 and unused names are ignored.
    pub fn delete_vertex_array(&mut self, name: u32) {
        if name == 0 || !self.vao_exists(name) {
            return;
        }
        if name == self.vao_binding {
            // Object 0 always exists, so the bind cannot fail.
            let _ = self.bind_vertex_array(0);
        }
        self.vaos.remove(&name);
    }

    /// glIsVertexArray: whether `name` is an object that has been bound (a generated name
    /// is not one until then, as in Mesa).
    pub fn is_vertex_array(&self, name: u32) -> bool {
        name != 0 && (name == self.vao_binding || matches!(self.vaos.get(&name), Some(Some(_))))
    }
}

impl VertexArrayObject {
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

    /// Unbinds buffer `name` from the element binding and every array that sources it.
    fn unbind_buffer(&mut self, name: u32) {
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
}
