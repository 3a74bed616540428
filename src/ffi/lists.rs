//! Display lists (glNewList … glCallLists) and the attribute stacks (glPushAttrib,
//! glPushClientAttrib). glNewList/glEndList/glGenLists/glDeleteLists/glIsList and the client
//! stack execute immediately; glCallList(s), glListBase and glPush/PopAttrib are recorded.
#![allow(non_snake_case)]

use super::enums::*;
use super::types::*;
use super::{with_ctx, with_ctx_list, with_ctx_list_anywhere_keep, with_ctx_list_keep};
use crate::context::error::GlError;

/// glNewList.
#[no_mangle]
pub extern "C" fn glNewList(list: GLuint, mode: GLenum) {
    with_ctx(|c| {
        // Mesa checks the name before the mode.
        if list == 0 {
            return Err(GlError::InvalidValue);
        }
        let execute = match mode {
            GL_COMPILE => false,
            GL_COMPILE_AND_EXECUTE => true,
            _ => return Err(GlError::InvalidEnum),
        };
        c.new_list(list, execute)
    })
}

/// glEndList.
#[no_mangle]
pub extern "C" fn glEndList() {
    with_ctx(|c| c.end_list())
}

/// glCallList.
#[no_mangle]
pub extern "C" fn glCallList(list: GLuint) {
    with_ctx_list_anywhere_keep(move |c| {
        if list == 0 {
            return Err(GlError::InvalidValue);
        }
        c.call_list(list);
        Ok(())
    })
}

/// The size of one name of glCallLists' `type_`, or GL_INVALID_ENUM.
fn name_size(type_: GLenum) -> Result<usize, GlError> {
    Ok(match type_ {
        GL_BYTE | GL_UNSIGNED_BYTE => 1,
        GL_SHORT | GL_UNSIGNED_SHORT | GL_2_BYTES => 2,
        GL_3_BYTES => 3,
        GL_INT | GL_UNSIGNED_INT | GL_FLOAT | GL_4_BYTES => 4,
        _ => return Err(GlError::InvalidEnum),
    })
}

/// Reads the `n` list offsets of glCallLists (before the list base is added), or the
/// error of an unknown `type_`.
///
/// # Safety
/// `lists` must be readable for `n` elements of `type_`.
unsafe fn read_names(n: usize, type_: GLenum, lists: *const GLvoid) -> Result<Vec<u32>, GlError> {
    let size = name_size(type_)?;
    if lists.is_null() || n == 0 {
        return Ok(Vec::new());
    }
    let mut bytes = Vec::new();
    bytes
        .try_reserve_exact(n * size)
        .map_err(|_| GlError::OutOfMemory)?;
    // SAFETY: the caller promises n readable elements of this type.
    bytes.extend_from_slice(unsafe { std::slice::from_raw_parts(lists as *const u8, n * size) });
    Ok(bytes
        .chunks_exact(size)
        .map(|b| match type_ {
            GL_BYTE => b[0] as i8 as u32,
            GL_UNSIGNED_BYTE => b[0] as u32,
            GL_SHORT => i16::from_ne_bytes([b[0], b[1]]) as u32,
            GL_UNSIGNED_SHORT => u16::from_ne_bytes([b[0], b[1]]) as u32,
            GL_INT | GL_UNSIGNED_INT => u32::from_ne_bytes([b[0], b[1], b[2], b[3]]),
            GL_FLOAT => f32::from_ne_bytes([b[0], b[1], b[2], b[3]]) as i32 as u32,
            // GL_2_BYTES, GL_3_BYTES, GL_4_BYTES: big-endian unsigned bytes.
            _ => b.iter().fold(0u32, |acc, &x| (acc << 8) | x as u32),
        })
        .collect())
}

/// glCallLists: calls list `base + name` for each name (names read as `type_`).
///
/// # Safety
/// `lists` must be NULL or readable for `n` elements of `type_`.
#[no_mangle]
pub unsafe extern "C" fn glCallLists(n: GLsizei, type_: GLenum, lists: *const GLvoid) {
    // Mesa checks the type before the count.
    let names = match name_size(type_) {
        Err(e) => Err(e),
        Ok(_) if n < 0 => Err(GlError::InvalidValue),
        // SAFETY: forwarded caller contract.
        Ok(_) => unsafe { read_names(n as usize, type_, lists) },
    };
    with_ctx_list_anywhere_keep(move |c| {
        c.call_lists(names.as_ref().map_err(|e| *e)?);
        Ok(())
    })
}

/// glListBase.
#[no_mangle]
pub extern "C" fn glListBase(base: GLuint) {
    with_ctx_list_keep(move |c| {
        c.lists.base = base;
        Ok(())
    })
}

/// glGenLists.
#[no_mangle]
pub extern "C" fn glGenLists(range: GLsizei) -> GLuint {
    with_ctx(|c| c.gen_lists(range))
}

/// glDeleteLists.
#[no_mangle]
pub extern "C" fn glDeleteLists(list: GLuint, range: GLsizei) {
    with_ctx(|c| c.delete_lists(list, range))
}

/// glIsList.
#[no_mangle]
pub extern "C" fn glIsList(list: GLuint) -> GLboolean {
    with_ctx(|c| Ok(c.is_list(list) as GLboolean))
}

/// glPushAttrib.
#[no_mangle]
pub extern "C" fn glPushAttrib(mask: GLbitfield) {
    with_ctx_list(move |c| c.push_attrib(mask))
}

/// glPopAttrib.
#[no_mangle]
pub extern "C" fn glPopAttrib() {
    with_ctx_list(|c| c.pop_attrib())
}

/// glPushClientAttrib.
#[no_mangle]
pub extern "C" fn glPushClientAttrib(mask: GLbitfield) {
    with_ctx(|c| c.push_client_attrib(mask))
}

/// glPopClientAttrib.
#[no_mangle]
pub extern "C" fn glPopClientAttrib() {
    with_ctx(|c| c.pop_client_attrib())
}
