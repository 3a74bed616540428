//! glPointParameter{f,fv,i,iv} (GL 1.4, ARB/EXT_point_parameters): the point size
//! clamps, the fade threshold and the distance attenuation. As in Mesa (`points.c`,
//! `dlist.c`), the scalar forms set (value, 0, 0), so glPointParameterf with
//! GL_POINT_DISTANCE_ATTENUATION sets the linear and quadratic terms to 0; and while a
//! display list is being compiled glPointParameteriv keeps only its first value.
#![allow(non_snake_case)]

use super::lighting::read4;
use super::types::*;
use super::{with_ctx_list_keep, with_ctx_raw};
use crate::context::raster_state::PointParam;

/// How many values `pname` takes (an unknown pname reads one and fails later).
fn count(pname: GLenum) -> usize {
    PointParam::from_gl(pname).map_or(1, PointParam::count)
}

/// Records or runs glPointParameterfv(pname, v).
fn point_parameter(pname: GLenum, v: [f32; 3]) {
    with_ctx_list_keep(move |c| {
        let p = PointParam::from_gl(pname)?;
        c.raster.point.set(p, v)
    })
}

/// glPointParameterf.
#[no_mangle]
pub extern "C" fn glPointParameterf(pname: GLenum, param: GLfloat) {
    point_parameter(pname, [param, 0.0, 0.0])
}

/// glPointParameterfv (a null pointer does nothing).
///
/// # Safety
/// `params` must be null or point to as many values as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glPointParameterfv(pname: GLenum, params: *const GLfloat) {
    // SAFETY: the caller promises the values `pname` takes.
    if let Some(p) = unsafe { read4(params, count(pname)) } {
        point_parameter(pname, [p[0], p[1], p[2]])
    }
}

/// glPointParameteri.
#[no_mangle]
pub extern "C" fn glPointParameteri(pname: GLenum, param: GLint) {
    point_parameter(pname, [param as f32, 0.0, 0.0])
}

/// glPointParameteriv (a null pointer does nothing).
///
/// # Safety
/// `params` must be null or point to as many values as `pname` takes.
#[no_mangle]
pub unsafe extern "C" fn glPointParameteriv(pname: GLenum, params: *const GLint) {
    // SAFETY: the caller promises the values `pname` takes.
    let Some(p) = (unsafe { read4(params, count(pname)) }) else {
        return;
    };
    // Mesa's display-list version converts only the first value (for every pname).
    let compiling = with_ctx_raw(|c| Ok(c.lists.compile_mode().is_some()));
    let n = if compiling { 1 } else { 3 };
    let mut v = [0.0f32; 3];
    for (o, &i) in v.iter_mut().zip(&p).take(n) {
        *o = i as f32;
    }
    point_parameter(pname, v)
}
