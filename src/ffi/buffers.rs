//! Buffer objects (GL 1.5, `GL/glext.h`): names, binding, data store, mapping and queries.
#![allow(non_snake_case)]

use super::enums::*;
use super::glext_enums::*;
use super::types::*;
use super::{non_negative, with_ctx};
use crate::context::arrays::BufferTarget;
use crate::context::error::GlError;
use crate::context::store::Store;
use libc::c_void;

/// glGenBuffers.
///
/// # Safety
/// `buffers` must be writable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenBuffers(n: GLsizei, buffers: *mut GLuint) {
    with_ctx(|c| {
        let n = non_negative(n)?;
        if !buffers.is_null() && n != 0 {
            let names = c.arrays.gen_buffers(n);
            // SAFETY: the caller promises room for n names.
            unsafe { std::ptr::copy_nonoverlapping(names.as_ptr(), buffers, names.len()) };
        }
        Ok(())
    })
}

/// glDeleteBuffers (unknown names and 0 are ignored).
///
/// # Safety
/// `buffers` must be readable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteBuffers(n: GLsizei, buffers: *const GLuint) {
    with_ctx(|c| {
        let n = non_negative(n)?;
        if !buffers.is_null() {
            // SAFETY: the caller promises n readable names.
            let names = unsafe { std::slice::from_raw_parts(buffers, n) };
            names.iter().for_each(|&name| c.arrays.delete_buffer(name));
        }
        Ok(())
    })
}

/// glIsBuffer: true for a name that has been bound at least once and not deleted.
#[no_mangle]
pub extern "C" fn glIsBuffer(buffer: GLuint) -> GLboolean {
    with_ctx(|c| Ok(c.arrays.buffers.get(&buffer).is_some_and(|b| b.is_some()) as GLboolean))
}

/// glBindBuffer.
#[no_mangle]
pub extern "C" fn glBindBuffer(target: GLenum, buffer: GLuint) {
    with_ctx(|c| {
        let t = BufferTarget::from_gl(target)?;
        c.arrays.bind_buffer(t, buffer);
        Ok(())
    })
}

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

/// glBufferData: replaces the store of the bound buffer (GL_OUT_OF_MEMORY when it cannot be
/// allocated, leaving the old store).
///
/// # Safety
/// `data` must be NULL or readable for `size` bytes.
#[no_mangle]
pub unsafe extern "C" fn glBufferData(
    target: GLenum,
    size: GLsizeiptr,
    data: *const GLvoid,
    usage: GLenum,
) {
    with_ctx(|c| {
        let t = BufferTarget::from_gl(target)?;
        if size < 0 {
            return Err(GlError::InvalidValue);
        }
        if !valid_usage(usage) {
            return Err(GlError::InvalidEnum);
        }
        let b = c.arrays.bound_mut(t)?;
        let size = size as usize;
        let store = if data.is_null() {
            Store::zeroed(size)
        } else {
            // SAFETY: the caller promises `size` readable bytes at `data`.
            Store::copy_of(unsafe { std::slice::from_raw_parts(data as *const u8, size) })
        };
        b.data = store.map_err(|_| GlError::OutOfMemory)?;
        b.usage = usage;
        b.mapped = None;
        Ok(())
    })
}

/// glBufferSubData and glGetBufferSubData: `copy` gets the bytes they name in the buffer
/// bound to `target`, after their checks (in Mesa's order), unless there is nothing to copy.
fn copy_sub_range(
    target: GLenum,
    offset: GLintptr,
    size: GLsizeiptr,
    null: bool,
    copy: impl FnOnce(&mut [u8]),
) {
    with_ctx(|c| {
        let b = c.arrays.bound_mut(BufferTarget::from_gl(target)?)?;
        if offset < 0 || size < 0 || (offset as usize).saturating_add(size as usize) > b.data.len()
        {
            return Err(GlError::InvalidValue);
        }
        if b.mapped.is_some() {
            return Err(GlError::InvalidOperation);
        }
        if size != 0 && !null {
            copy(&mut b.data[offset as usize..offset as usize + size as usize]);
        }
        Ok(())
    })
}

/// glBufferSubData.
///
/// # Safety
/// `data` must be readable for `size` bytes.
#[no_mangle]
pub unsafe extern "C" fn glBufferSubData(
    target: GLenum,
    offset: GLintptr,
    size: GLsizeiptr,
    data: *const GLvoid,
) {
    copy_sub_range(target, offset, size, data.is_null(), |dst| {
        // SAFETY: the caller promises `size` readable bytes; the range was checked.
        dst.copy_from_slice(unsafe { std::slice::from_raw_parts(data as *const u8, dst.len()) })
    })
}

/// glGetBufferSubData.
///
/// # Safety
/// `data` must be writable for `size` bytes.
#[no_mangle]
pub unsafe extern "C" fn glGetBufferSubData(
    target: GLenum,
    offset: GLintptr,
    size: GLsizeiptr,
    data: *mut GLvoid,
) {
    copy_sub_range(target, offset, size, data.is_null(), |src| {
        // SAFETY: the caller promises `size` writable bytes; the range was checked.
        unsafe { std::ptr::copy_nonoverlapping(src.as_ptr(), data as *mut u8, src.len()) }
    })
}

/// glMapBuffer: a pointer to the bound buffer's store until glUnmapBuffer.
#[no_mangle]
pub extern "C" fn glMapBuffer(target: GLenum, access: GLenum) -> *mut GLvoid {
    with_ctx(|c| {
        let t = BufferTarget::from_gl(target)?;
        if !matches!(access, GL_READ_ONLY | GL_WRITE_ONLY | GL_READ_WRITE) {
            return Err(GlError::InvalidEnum);
        }
        let b = c.arrays.bound_mut(t)?;
        if b.mapped.is_some() {
            return Err(GlError::InvalidOperation);
        }
        b.mapped = Some(access);
        b.access = access;
        Ok(MapPtr(b.data.as_mut_ptr() as *mut c_void))
    })
    .0
}

/// A pointer with a null default (for `with_ctx`).
struct MapPtr(*mut c_void);
impl Default for MapPtr {
    fn default() -> Self {
        MapPtr(std::ptr::null_mut())
    }
}

/// glUnmapBuffer.
#[no_mangle]
pub extern "C" fn glUnmapBuffer(target: GLenum) -> GLboolean {
    with_ctx(|c| {
        let t = BufferTarget::from_gl(target)?;
        let b = c.arrays.bound_mut(t)?;
        if b.mapped.take().is_none() {
            return Err(GlError::InvalidOperation);
        }
        Ok(GL_TRUE as GLboolean)
    })
}

/// glGetBufferParameteriv.
///
/// # Safety
/// `params` must be writable.
#[no_mangle]
pub unsafe extern "C" fn glGetBufferParameteriv(target: GLenum, pname: GLenum, params: *mut GLint) {
    with_ctx(|c| {
        let t = BufferTarget::from_gl(target)?;
        let b = c.arrays.bound_mut(t)?;
        let v = match pname {
            GL_BUFFER_SIZE => b.data.len().min(i32::MAX as usize) as GLint,
            GL_BUFFER_USAGE => b.usage as GLint,
            GL_BUFFER_ACCESS => b.access as GLint,
            GL_BUFFER_MAPPED => b.mapped.is_some() as GLint,
            _ => return Err(GlError::InvalidEnum),
        };
        if !params.is_null() {
            // SAFETY: checked non-null; the caller promises it is writable.
            unsafe { *params = v };
        }
        Ok(())
    })
}

/// glGetBufferPointerv: the mapped pointer (NULL when not mapped).
///
/// # Safety
/// `params` must be writable.
#[no_mangle]
pub unsafe extern "C" fn glGetBufferPointerv(
    target: GLenum,
    pname: GLenum,
    params: *mut *mut GLvoid,
) {
    with_ctx(|c| {
        let t = BufferTarget::from_gl(target)?;
        if pname != GL_BUFFER_MAP_POINTER {
            return Err(GlError::InvalidEnum);
        }
        let b = c.arrays.bound_mut(t)?;
        let p = if b.mapped.is_some() {
            b.data.as_mut_ptr() as *mut c_void
        } else {
            std::ptr::null_mut()
        };
        if !params.is_null() {
            // SAFETY: checked non-null; the caller promises it is writable.
            unsafe { *params = p };
        }
        Ok(())
    })
}
