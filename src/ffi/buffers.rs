//! Buffer objects (GL 1.5, `GL/glext.h`): names, binding, data store, mapping and queries.
#![allow(non_snake_case)]

use super::client::{read_vec, write_all, write_one};
use super::enums::*;
use super::types::*;
use super::{non_negative, with_ctx};
use crate::context::arrays::BufferTarget;
use crate::context::error::GlError;
use libc::c_void;

/// glGenBuffers.
///
/// # Safety
/// `buffers` must be writable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenBuffers(n: GLsizei, buffers: *mut GLuint) {
    with_ctx(|c| {
        let n = non_negative(n)?;
        let n = if buffers.is_null() { 0 } else { n };
        // SAFETY: the caller promises room for n names.
        unsafe { write_all(buffers, &c.gen_buffer_names(n), |x| x) };
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
        // SAFETY: the caller promises n readable names.
        c.delete_buffers(&unsafe { read_vec(buffers, non_negative(n)?) });
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
    super::with_ctx_keep(|c| {
        let t = BufferTarget::from_gl(target)?;
        c.bind_buffer(t, buffer);
        Ok(())
    })
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
    // SAFETY: forwarded caller contract (read after the checks).
    with_ctx(|c| unsafe { c.buffer_data(target, size, data as *const u8, usage) })
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
        if let Some(range) = c.buffer_sub_range(target, (offset, size), null)? {
            copy(range);
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
    with_ctx(|c| c.map_buffer(target, access)) as *mut GLvoid
}

/// glUnmapBuffer.
#[no_mangle]
pub extern "C" fn glUnmapBuffer(target: GLenum) -> GLboolean {
    with_ctx(|c| {
        let t = BufferTarget::from_gl(target)?;
        let b = c.bound_buffer_mut(t)?;
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
        let v = c.get_buffer_parameter(target, pname)?;
        // SAFETY: the caller promises a writable value.
        unsafe { write_one(params, v) };
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
        let p = c.get_buffer_pointer(target, pname)? as *mut c_void;
        // SAFETY: the caller promises a writable value.
        unsafe { write_one(params, p) };
        Ok(())
    })
}
