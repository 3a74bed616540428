//! GL 2.0's generic vertex attributes under fixed function: glVertexAttrib*,
//! glVertexAttribPointer, glEnable/DisableVertexAttribArray and their queries.
//!
//! The compatibility profile's rules, as Mesa applies them (GL 2.0 §2.7, Mesa's
//! `is_vertex_position` and attribute map mode): generic attribute 0 is the vertex
//! position only while it is given between glBegin and glEnd (there glVertexAttrib*(0, …)
//! emits a vertex, as glVertex does); outside it sets attribute 0's current value, which
//! glGetVertexAttrib cannot read (GL_INVALID_OPERATION). An enabled attribute-0 array is
//! the vertex array, and wins over GL_VERTEX_ARRAY ([`super::arrays::ArrayState::position`]).
//! Attributes 1–15 are stored and queried; fixed function reads none of them. Set between
//! glBegin and glEnd they are recorded per vertex from that call on (the vertices before
//! it keep the value they were given with), as Mesa's vbo module records them, and a
//! vertex shader reads each vertex's own.

use super::arrays::{DataType, MAX_VERTEX_ATTRIBS};
use super::dlist::VertexOp;
use super::{Context, GlError, GlResult};
use crate::gl::glext_enums::{
    GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, GL_VERTEX_ATTRIB_ARRAY_DIVISOR,
    GL_VERTEX_ATTRIB_ARRAY_INTEGER,
};
use crate::gl::types::GLenum;

/// GL_VERTEX_ATTRIB_ARRAY_ENABLED.
pub const GL_VERTEX_ATTRIB_ARRAY_ENABLED: GLenum = 0x8622;
/// GL_VERTEX_ATTRIB_ARRAY_SIZE.
pub const GL_VERTEX_ATTRIB_ARRAY_SIZE: GLenum = 0x8623;
/// GL_VERTEX_ATTRIB_ARRAY_STRIDE.
pub const GL_VERTEX_ATTRIB_ARRAY_STRIDE: GLenum = 0x8624;
/// GL_VERTEX_ATTRIB_ARRAY_TYPE.
pub const GL_VERTEX_ATTRIB_ARRAY_TYPE: GLenum = 0x8625;
/// GL_CURRENT_VERTEX_ATTRIB.
pub const GL_CURRENT_VERTEX_ATTRIB: GLenum = 0x8626;
/// GL_VERTEX_ATTRIB_ARRAY_POINTER.
pub const GL_VERTEX_ATTRIB_ARRAY_POINTER: GLenum = 0x8645;
/// GL_MAX_VERTEX_ATTRIBS.
pub const GL_MAX_VERTEX_ATTRIBS: GLenum = 0x8869;
/// GL_VERTEX_ATTRIB_ARRAY_NORMALIZED.
pub const GL_VERTEX_ATTRIB_ARRAY_NORMALIZED: GLenum = 0x886A;

/// A generic attribute's current value before any glVertexAttrib (0, 0, 0, 1).
pub const GENERIC_DEFAULT: [f32; 4] = [0.0, 0.0, 0.0, 1.0];

/// `index` as an attribute slot, or GL_INVALID_VALUE when it is >= GL_MAX_VERTEX_ATTRIBS.
fn slot(index: u32) -> GlResult<usize> {
    let i = index as usize;
    if i < MAX_VERTEX_ATTRIBS {
        Ok(i)
    } else {
        Err(GlError::InvalidValue)
    }
}

/// One value of glGetVertexAttrib: up to four numbers, in the type the query asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum AttribValue {
    /// An integer (enable flag, size, stride, type token, normalized flag, buffer name).
    Int(i64),
    /// GL_CURRENT_VERTEX_ATTRIB's four components.
    Floats([f32; 4]),
}

impl Context {
    /// glVertexAttrib*: a vertex between glBegin and glEnd for attribute 0, else the
    /// attribute's current value (recorded as a state command in a display list).
    ///
    /// A deferred glBegin/glEnd batch is drawn first (its vertex shader reads the value
    /// at draw time). Inside glBegin/glEnd the batch starts recording each vertex's
    /// generic attributes ([`super::immediate::Immediate::generic_inside`]).
    pub(crate) fn vertex_attrib(&mut self, index: u32, v: [f32; 4]) -> GlResult<()> {
        let i = slot(index)?;
        let inside = match self.lists.compile_mode() {
            Some(_) => self.lists.compiling_inside_begin(),
            None => self.immediate.active.is_some(),
        };
        if i == 0 && inside {
            return self.vertex_command(VertexOp::Vertex(v));
        }
        match self.lists.compile_mode() {
            None => self.set_generic(i, v),
            Some(execute) => {
                self.lists.push_call(Box::new(move |c: &mut Context| {
                    c.set_generic(i, v);
                    Ok(())
                }));
                if execute {
                    self.set_generic(i, v);
                }
            }
        }
        Ok(())
    }

    /// Sets generic attribute `i`'s current value, marking or drawing the batch in
    /// progress (see [`Context::vertex_attrib`]).
    fn set_generic(&mut self, i: usize, v: [f32; 4]) {
        if self.immediate.active.is_some() {
            self.immediate.generic_inside = true;
            // Out of memory leaves the record short: the batch is refused by a vertex
            // shader that reads it.
            let _ = self.immediate.verts.track_generic(&self.generic_current);
        } else {
            self.flush_pending();
        }
        self.generic_current[i] = v;
    }

    /// glVertexAttribPointer: `ptr` is an offset into the GL_ARRAY_BUFFER while one is
    /// bound. Mesa's checks in its order: the index, then those of
    /// [`Context::store_array_pointer`] (the stride, the type, the size).
    pub(crate) fn vertex_attrib_pointer(
        &mut self,
        index: u32,
        (size, ty, normalized, stride): (i32, GLenum, bool, i32),
        ptr: usize,
    ) -> GlResult<()> {
        let i = slot(index)?;
        let checks = (|_: DataType| true, (1..=4).contains(&size));
        let format = (size, ty, stride);
        let a = self.store_array_pointer(|c| &mut c.arrays.vao.generic[i], format, ptr, checks)?;
        a.normalized = normalized;
        a.integer = false;
        Ok(())
    }

    /// glVertexAttribIPointer (GL 3.0): as [`Context::vertex_attrib_pointer`] for an
    /// integer array, whose type must be an integer one (GL_INVALID_ENUM otherwise).
    pub(crate) fn vertex_attrib_ipointer(
        &mut self,
        index: u32,
        (size, ty, stride): (i32, GLenum, i32),
        ptr: usize,
    ) -> GlResult<()> {
        let i = slot(index)?;
        let int = |t: DataType| !matches!(t, DataType::Float | DataType::Double);
        let checks = (int, (1..=4).contains(&size));
        let format = (size, ty, stride);
        let a = self.store_array_pointer(|c| &mut c.arrays.vao.generic[i], format, ptr, checks)?;
        a.normalized = false;
        a.integer = true;
        Ok(())
    }

    /// glVertexAttribDivisor (ARB_instanced_arrays): attribute `index` advances once per
    /// `divisor` instances (0: once per vertex); GL_INVALID_VALUE for an index at or
    /// past GL_MAX_VERTEX_ATTRIBS.
    pub(crate) fn vertex_attrib_divisor(&mut self, index: u32, divisor: u32) -> GlResult<()> {
        self.arrays.vao.divisor[slot(index)?] = divisor;
        Ok(())
    }

    /// glEnableVertexAttribArray / glDisableVertexAttribArray.
    pub(crate) fn set_vertex_attrib_array(&mut self, index: u32, on: bool) -> GlResult<()> {
        self.arrays.vao.generic[slot(index)?].enabled = on;
        Ok(())
    }

    /// glGetVertexAttrib{f,d,i}v: the value of `pname` for attribute `index`.
    pub(crate) fn get_vertex_attrib(&self, index: u32, pname: GLenum) -> GlResult<AttribValue> {
        let i = slot(index)?;
        let a = &self.arrays.vao.generic[i];
        Ok(AttribValue::Int(match pname {
            GL_VERTEX_ATTRIB_ARRAY_ENABLED => a.enabled as i64,
            GL_VERTEX_ATTRIB_ARRAY_SIZE => a.size as i64,
            GL_VERTEX_ATTRIB_ARRAY_STRIDE => a.stride as i64,
            GL_VERTEX_ATTRIB_ARRAY_TYPE => a.ty.to_gl() as i64,
            GL_VERTEX_ATTRIB_ARRAY_NORMALIZED => a.normalized as i64,
            GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING => a.buffer as i64,
            GL_VERTEX_ATTRIB_ARRAY_DIVISOR => self.arrays.vao.divisor[i] as i64,
            GL_VERTEX_ATTRIB_ARRAY_INTEGER => a.integer as i64,
            GL_CURRENT_VERTEX_ATTRIB => {
                // Attribute 0 aliases the vertex position: it has no readable value.
                if i == 0 {
                    return Err(GlError::InvalidOperation);
                }
                return Ok(AttribValue::Floats(self.generic_current[i]));
            }
            _ => return Err(GlError::InvalidEnum),
        }))
    }

    /// glGetVertexAttribPointerv: the pointer (or buffer offset) of attribute `index`.
    pub(crate) fn get_vertex_attrib_pointer(&self, index: u32, pname: GLenum) -> GlResult<usize> {
        let i = slot(index)?;
        if pname != GL_VERTEX_ATTRIB_ARRAY_POINTER {
            return Err(GlError::InvalidEnum);
        }
        Ok(self.arrays.vao.generic[i].ptr)
    }
}
