//! Buffer objects (GL 1.5): the data store, mapping and queries of the buffer bound to a
//! target, with Mesa's checks in Mesa's order.

use super::arrays::{BufferObject, BufferTarget};
use super::store::Store;
use super::{Context, GlError, GlResult};
use crate::gl::glext_enums::*;
use crate::gl::types::*;

/// Whether `usage` is one of the nine GL_{STREAM,STATIC,DYNAMIC}_{DRAW,READ,COPY}.
fn valid_usage(usage: GLenum) -> bool {
    matches!(
        usage,
        GL_STREAM_DRAW
            | GL_STREAM_READ
            | GL_STREAM_COPY
            | GL_STATIC_DRAW
            | GL_STATIC_READ
            | GL_STATIC_COPY
            | GL_DYNAMIC_DRAW
            | GL_DYNAMIC_READ
            | GL_DYNAMIC_COPY
    )
}

impl Context {
    /// The binding `target` names: the arrays' two, or the pack and unpack pixel stores'.
    fn buffer_binding_mut(&mut self, target: BufferTarget) -> &mut u32 {
        match target {
            BufferTarget::Array => &mut self.arrays.array_buffer,
            BufferTarget::ElementArray => &mut self.arrays.vao.element_buffer,
            BufferTarget::PixelPack => &mut self.state.pack.buffer,
            BufferTarget::PixelUnpack => &mut self.state.unpack.buffer,
        }
    }

    /// glBindBuffer: binds `name` (0 unbinds), creating the object on its first bind.
    pub(crate) fn bind_buffer(&mut self, target: BufferTarget, name: u32) {
        self.arrays.touch_buffer(name);
        *self.buffer_binding_mut(target) = name;
    }

    /// The object bound to `target`, or GL_INVALID_OPERATION when none is.
    pub(crate) fn bound_buffer_mut(&mut self, target: BufferTarget) -> GlResult<&mut BufferObject> {
        let name = *self.buffer_binding_mut(target);
        self.arrays.object_mut(name)
    }

    /// glGenBuffers: `n` new names (none for 0).
    pub(crate) fn gen_buffer_names(&mut self, n: usize) -> Vec<GLuint> {
        if n == 0 {
            return Vec::new();
        }
        self.arrays.gen_buffers(n)
    }

    /// glDeleteBuffers (unknown names and 0 are ignored).
    pub(crate) fn delete_buffers(&mut self, names: &[GLuint]) {
        for &name in names {
            self.arrays.delete_buffer(name);
            for ps in [&mut self.state.pack, &mut self.state.unpack] {
                if ps.buffer == name {
                    ps.buffer = 0;
                }
            }
        }
    }

    /// glBufferData: replaces the store of the bound buffer (GL_OUT_OF_MEMORY when it
    /// cannot be allocated, leaving the old store); zeroed when `data` is null.
    ///
    /// # Safety
    /// `data` must be null or readable for `size` bytes (read after the checks pass).
    pub(crate) unsafe fn buffer_data(
        &mut self,
        target: GLenum,
        size: GLsizeiptr,
        data: *const u8,
        usage: GLenum,
    ) -> GlResult<()> {
        let t = BufferTarget::from_gl(target)?;
        if size < 0 {
            return Err(GlError::InvalidValue);
        }
        if !valid_usage(usage) {
            return Err(GlError::InvalidEnum);
        }
        let b = self.bound_buffer_mut(t)?;
        let size = size as usize;
        let store = if data.is_null() {
            Store::zeroed(size)
        } else {
            // SAFETY: the caller promises `size` readable bytes at `data`.
            Store::copy_of(unsafe { std::slice::from_raw_parts(data, size) })
        };
        b.data = store.map_err(|_| GlError::OutOfMemory)?;
        b.usage = usage;
        b.mapped = None;
        Ok(())
    }

    /// The bytes glBufferSubData/glGetBufferSubData name in the buffer bound to `target`,
    /// after their checks (in Mesa's order); `None` when there is nothing to copy (an
    /// empty range, or a null client pointer).
    pub(crate) fn buffer_sub_range(
        &mut self,
        target: GLenum,
        (offset, size): (GLintptr, GLsizeiptr),
        null: bool,
    ) -> GlResult<Option<&mut [u8]>> {
        let b = self.bound_buffer_mut(BufferTarget::from_gl(target)?)?;
        if offset < 0 || size < 0 || (offset as usize).saturating_add(size as usize) > b.data.len()
        {
            return Err(GlError::InvalidValue);
        }
        if b.mapped.is_some() {
            return Err(GlError::InvalidOperation);
        }
        if size == 0 || null {
            return Ok(None);
        }
        Ok(Some(
            &mut b.data[offset as usize..offset as usize + size as usize],
        ))
    }

    /// glMapBuffer: the address of the bound buffer's store, mapped until glUnmapBuffer.
    pub(crate) fn map_buffer(&mut self, target: GLenum, access: GLenum) -> GlResult<usize> {
        let t = BufferTarget::from_gl(target)?;
        if !matches!(access, GL_READ_ONLY | GL_WRITE_ONLY | GL_READ_WRITE) {
            return Err(GlError::InvalidEnum);
        }
        let b = self.bound_buffer_mut(t)?;
        if b.mapped.is_some() {
            return Err(GlError::InvalidOperation);
        }
        b.mapped = Some(access);
        b.access = access;
        Ok(b.data.as_mut_ptr() as usize)
    }

    /// glGetBufferParameteriv's value.
    pub(crate) fn get_buffer_parameter(
        &mut self,
        target: GLenum,
        pname: GLenum,
    ) -> GlResult<GLint> {
        let t = BufferTarget::from_gl(target)?;
        let b = self.bound_buffer_mut(t)?;
        Ok(match pname {
            GL_BUFFER_SIZE => b.data.len().min(i32::MAX as usize) as GLint,
            GL_BUFFER_USAGE => b.usage as GLint,
            GL_BUFFER_ACCESS => b.access as GLint,
            GL_BUFFER_MAPPED => b.mapped.is_some() as GLint,
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// glGetBufferPointerv: the address of the mapped store (0 when not mapped).
    pub(crate) fn get_buffer_pointer(&mut self, target: GLenum, pname: GLenum) -> GlResult<usize> {
        let t = BufferTarget::from_gl(target)?;
        if pname != GL_BUFFER_MAP_POINTER {
            return Err(GlError::InvalidEnum);
        }
        let b = self.bound_buffer_mut(t)?;
        Ok(if b.mapped.is_some() {
            b.data.as_mut_ptr() as usize
        } else {
            0
        })
    }
}
