//! Occlusion queries (GL 1.5, glext.h): glGenQueries … glGetQueryObjectuiv and their ARB
//! aliases. Only GL_SAMPLES_PASSED is a query target in GL 1.5.
#![allow(non_snake_case)]

use super::client::write_all;
use super::families::c_fns;
use super::glext_enums::*;
use super::types::*;
use super::{non_negative, with_ctx, with_ctx_list};
use crate::context::error::{GlError, GlResult};

/// GL_SAMPLES_PASSED, or GL_INVALID_ENUM.
fn samples_target(target: GLenum) -> GlResult<()> {
    if target == GL_SAMPLES_PASSED {
        Ok(())
    } else {
        Err(GlError::InvalidEnum)
    }
}

/// glGenQueries.
///
/// # Safety
/// `ids` must be NULL or writable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glGenQueries(n: GLsizei, ids: *mut GLuint) {
    let names: Vec<GLuint> = with_ctx(|c| {
        let n = non_negative(n)?;
        // Mesa makes no names when there is nowhere to put them.
        c.gen_queries(if ids.is_null() { 0 } else { n })
    });
    // SAFETY: the caller promises room for n names.
    unsafe { write_all(ids, &names, |x| x) }
}

/// glDeleteQueries.
///
/// # Safety
/// `ids` must be NULL or readable for `n` names.
#[no_mangle]
pub unsafe extern "C" fn glDeleteQueries(n: GLsizei, ids: *const GLuint) {
    let names: Vec<GLuint> = match usize::try_from(n) {
        // SAFETY: the caller promises n readable names.
        Ok(len) if !ids.is_null() => unsafe { std::slice::from_raw_parts(ids, len) }.to_vec(),
        _ => Vec::new(),
    };
    with_ctx(move |c| {
        non_negative(n)?;
        c.delete_queries(&names)
    })
}

/// glIsQuery.
#[no_mangle]
pub extern "C" fn glIsQuery(id: GLuint) -> GLboolean {
    with_ctx(|c| c.is_query(id)) as GLboolean
}

/// glBeginQuery.
#[no_mangle]
pub extern "C" fn glBeginQuery(target: GLenum, id: GLuint) {
    with_ctx_list(move |c| {
        samples_target(target)?;
        c.begin_query(id)
    })
}

/// glEndQuery.
#[no_mangle]
pub extern "C" fn glEndQuery(target: GLenum) {
    with_ctx_list(move |c| {
        samples_target(target)?;
        c.end_query()
    })
}

/// glGetQueryiv: GL_CURRENT_QUERY and GL_QUERY_COUNTER_BITS (64, as llvmpipe).
///
/// # Safety
/// `params` must be NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn glGetQueryiv(target: GLenum, pname: GLenum, params: *mut GLint) {
    let v: Option<GLint> = with_ctx(|c| {
        samples_target(target)?;
        Ok(Some(match pname {
            GL_CURRENT_QUERY => c.queries.active.map_or(0, |a| a.0 as GLint),
            GL_QUERY_COUNTER_BITS => 64,
            _ => return Err(GlError::InvalidEnum),
        }))
    });
    if let (Some(v), false) = (v, params.is_null()) {
        // SAFETY: checked non-null; the caller promises it is writable.
        unsafe { *params = v };
    }
}

/// GL_QUERY_RESULT or GL_QUERY_RESULT_AVAILABLE of query `id`.
fn query_object(id: GLuint, pname: GLenum) -> Option<u64> {
    with_ctx(|c| {
        let r = c.query_result(id)?;
        match pname {
            GL_QUERY_RESULT => Ok(Some(r)),
            GL_QUERY_RESULT_AVAILABLE => Ok(Some(1)),
            _ => Err(GlError::InvalidEnum),
        }
    })
}

/// glGetQueryObjectiv (results above INT_MAX read as INT_MAX).
///
/// # Safety
/// `params` must be NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn glGetQueryObjectiv(id: GLuint, pname: GLenum, params: *mut GLint) {
    if let (Some(v), false) = (query_object(id, pname), params.is_null()) {
        // SAFETY: checked non-null; the caller promises it is writable.
        unsafe { *params = v.min(GLint::MAX as u64) as GLint };
    }
}

/// glGetQueryObjectuiv (results above UINT_MAX read as UINT_MAX).
///
/// # Safety
/// `params` must be NULL or writable.
#[no_mangle]
pub unsafe extern "C" fn glGetQueryObjectuiv(id: GLuint, pname: GLenum, params: *mut GLuint) {
    if let (Some(v), false) = (query_object(id, pname), params.is_null()) {
        // SAFETY: checked non-null; the caller promises it is writable.
        unsafe { *params = v.min(GLuint::MAX as u64) as GLuint };
    }
}

c_fns! {
    unsafe fn glGenQueriesARB(n: GLsizei, ids: *mut GLuint) = queries::glGenQueries;
    unsafe fn glDeleteQueriesARB(n: GLsizei, ids: *const GLuint) = queries::glDeleteQueries;
    safe fn glIsQueryARB(id: GLuint) -> GLboolean = queries::glIsQuery;
    safe fn glBeginQueryARB(target: GLenum, id: GLuint) = queries::glBeginQuery;
    safe fn glEndQueryARB(target: GLenum) = queries::glEndQuery;
    unsafe fn glGetQueryivARB(target: GLenum, pname: GLenum, params: *mut GLint) = queries::glGetQueryiv;
    unsafe fn glGetQueryObjectivARB(id: GLuint, pname: GLenum, params: *mut GLint) = queries::glGetQueryObjectiv;
    unsafe fn glGetQueryObjectuivARB(id: GLuint, pname: GLenum, params: *mut GLuint) = queries::glGetQueryObjectuiv;
}
