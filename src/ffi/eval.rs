//! Evaluators (gl.h): glMap1/2, glMapGrid1/2, glEvalCoord1/2, glEvalMesh1/2,
//! glEvalPoint1/2 and glGetMap, with Mesa's validation order. glEvalMesh is glBegin, a
//! glEvalCoord per grid point and glEnd, as Mesa's vbo module issues it.
#![allow(non_snake_case)]

use super::client::write_all;
use super::enums::*;
use super::types::*;
use super::{with_ctx, with_ctx_list, with_ctx_list_anywhere};
use crate::context::dlist::VertexOp;
use crate::context::error::{GlError, GlResult};
use crate::context::eval::{Grid, MapKind};
use crate::context::state::Primitive;
use crate::context::Context;
use crate::fixed_function::eval::MAX_ORDER;

/// The map kind and dimensionality (`true` for 2D) of a GL_MAP1_*/GL_MAP2_* target.
fn map_target(target: GLenum) -> Option<(MapKind, bool)> {
    let (base, two) = match target {
        GL_MAP1_COLOR_4..=GL_MAP1_VERTEX_4 => (GL_MAP1_COLOR_4, false),
        GL_MAP2_COLOR_4..=GL_MAP2_VERTEX_4 => (GL_MAP2_COLOR_4, true),
        _ => return None,
    };
    Some((MapKind::ALL[(target - base) as usize], two))
}

/// The control net of a glMap1/glMap2 call: the u and v parameter ranges (no v for
/// glMap1), the strides and orders of u and v (in elements; 0 and 1 for glMap1's v) and
/// the points.
struct Net<T> {
    target: GLenum,
    u: [f32; 2],
    v: Option<[f32; 2]>,
    stride: [GLint; 2],
    order: [GLint; 2],
    points: *const T,
}

/// Reads a control net (`uorder` x `vorder` points of `dim` components, strides in
/// elements) into u-major f32 points, after Mesa's checks.
fn gather<T: Copy + Into<f64>>(net: &Net<T>) -> GlResult<(MapKind, bool, Vec<f32>)> {
    let Net {
        target,
        u,
        v,
        stride: [ustride, vstride],
        order: [uorder, vorder],
        points,
    } = *net;
    let order_ok = |o: GLint| (1..=MAX_ORDER as GLint).contains(&o);
    if u[0] == u[1] || v.is_some_and(|v| v[0] == v[1]) {
        return Err(GlError::InvalidValue);
    }
    if !order_ok(uorder) || !order_ok(vorder) || points.is_null() {
        return Err(GlError::InvalidValue);
    }
    let (kind, two) = map_target(target)
        .filter(|&(_, two)| two == v.is_some())
        .ok_or(GlError::InvalidEnum)?;
    let dim = kind.dim() as GLint;
    if ustride < dim || (v.is_some() && vstride < dim) {
        return Err(GlError::InvalidValue);
    }
    let mut out = Vec::with_capacity((uorder * vorder * dim) as usize);
    for i in 0..uorder as usize {
        for j in 0..vorder as usize {
            let base = i * ustride as usize + j * vstride.max(0) as usize;
            for k in 0..dim as usize {
                // SAFETY: the caller promises the control points glMap describes.
                out.push(unsafe { *points.add(base + k) }.into() as f32);
            }
        }
    }
    Ok((kind, two, out))
}

/// glMap1/glMap2: the control points are read now (a display list keeps this copy);
/// the map is set, or the error raised, when the call runs.
fn map<T: Copy + Into<f64>>(net: Net<T>) {
    let (u, v, [uo, vo]) = (
        net.u,
        net.v.unwrap_or([0.0, 1.0]),
        net.order.map(|o| o as usize),
    );
    match gather(&net) {
        Ok((kind, two, pts)) => with_ctx_list(move |c| {
            if c.state.active_texture != 0 {
                return Err(GlError::InvalidOperation);
            }
            c.set_map(kind, two, u, v, uo, vo, pts.clone())
        }),
        Err(e) => with_ctx_list(move |_| Err(e)),
    }
}

/// glMap1f.
///
/// # Safety
/// `points` must hold `order` points `stride` floats apart.
#[no_mangle]
pub unsafe extern "C" fn glMap1f(
    target: GLenum,
    u1: GLfloat,
    u2: GLfloat,
    stride: GLint,
    order: GLint,
    points: *const GLfloat,
) {
    let (stride, order) = ([stride, 0], [order, 1]);
    map(Net {
        target,
        u: [u1, u2],
        v: None,
        stride,
        order,
        points,
    })
}

/// glMap1d.
///
/// # Safety
/// `points` must hold `order` points `stride` doubles apart.
#[no_mangle]
pub unsafe extern "C" fn glMap1d(
    target: GLenum,
    u1: GLdouble,
    u2: GLdouble,
    stride: GLint,
    order: GLint,
    points: *const GLdouble,
) {
    let (u, stride, order) = ([u1 as f32, u2 as f32], [stride, 0], [order, 1]);
    map(Net {
        target,
        u,
        v: None,
        stride,
        order,
        points,
    })
}

/// glMap2f.
///
/// # Safety
/// `points` must hold the `uorder` x `vorder` net with the given strides.
#[no_mangle]
pub unsafe extern "C" fn glMap2f(
    target: GLenum,
    u1: GLfloat,
    u2: GLfloat,
    ustride: GLint,
    uorder: GLint,
    v1: GLfloat,
    v2: GLfloat,
    vstride: GLint,
    vorder: GLint,
    points: *const GLfloat,
) {
    let (stride, order) = ([ustride, vstride], [uorder, vorder]);
    map(Net {
        target,
        u: [u1, u2],
        v: Some([v1, v2]),
        stride,
        order,
        points,
    })
}

/// glMap2d.
///
/// # Safety
/// `points` must hold the `uorder` x `vorder` net with the given strides.
#[no_mangle]
pub unsafe extern "C" fn glMap2d(
    target: GLenum,
    u1: GLdouble,
    u2: GLdouble,
    ustride: GLint,
    uorder: GLint,
    v1: GLdouble,
    v2: GLdouble,
    vstride: GLint,
    vorder: GLint,
    points: *const GLdouble,
) {
    let (u, v) = ([u1 as f32, u2 as f32], Some([v1 as f32, v2 as f32]));
    let (stride, order) = ([ustride, vstride], [uorder, vorder]);
    map(Net {
        target,
        u,
        v,
        stride,
        order,
        points,
    })
}

/// glMapGrid1f.
#[no_mangle]
pub extern "C" fn glMapGrid1f(un: GLint, u1: GLfloat, u2: GLfloat) {
    with_ctx_list(move |c| c.map_grid(&[Grid { n: un, d: [u1, u2] }]))
}

/// glMapGrid1d.
#[no_mangle]
pub extern "C" fn glMapGrid1d(un: GLint, u1: GLdouble, u2: GLdouble) {
    glMapGrid1f(un, u1 as f32, u2 as f32)
}

/// glMapGrid2f.
#[no_mangle]
pub extern "C" fn glMapGrid2f(
    un: GLint,
    u1: GLfloat,
    u2: GLfloat,
    vn: GLint,
    v1: GLfloat,
    v2: GLfloat,
) {
    with_ctx_list(move |c| c.map_grid(&[Grid { n: un, d: [u1, u2] }, Grid { n: vn, d: [v1, v2] }]))
}

/// glMapGrid2d.
#[no_mangle]
pub extern "C" fn glMapGrid2d(
    un: GLint,
    u1: GLdouble,
    u2: GLdouble,
    vn: GLint,
    v1: GLdouble,
    v2: GLdouble,
) {
    glMapGrid2f(un, u1 as f32, u2 as f32, vn, v1 as f32, v2 as f32)
}

/// glEvalCoord: compiled into display lists as a call (evaluated with the maps current
/// when the list runs, as Mesa's OPCODE_EVAL_C1/C2 do).
fn coord(u: f32, v: Option<f32>) {
    with_ctx_list_anywhere(move |c| {
        c.eval_coord(u, v);
        Ok(())
    })
}

/// glEvalCoord1f.
#[no_mangle]
pub extern "C" fn glEvalCoord1f(u: GLfloat) {
    coord(u, None)
}

/// glEvalCoord1d.
#[no_mangle]
pub extern "C" fn glEvalCoord1d(u: GLdouble) {
    coord(u as f32, None)
}

/// glEvalCoord1fv.
///
/// # Safety
/// `u` must be NULL or point to 1 value.
#[no_mangle]
pub unsafe extern "C" fn glEvalCoord1fv(u: *const GLfloat) {
    if !u.is_null() {
        // SAFETY: non-null; the caller promises one value.
        coord(unsafe { *u }, None)
    }
}

/// glEvalCoord1dv.
///
/// # Safety
/// `u` must be NULL or point to 1 value.
#[no_mangle]
pub unsafe extern "C" fn glEvalCoord1dv(u: *const GLdouble) {
    if !u.is_null() {
        // SAFETY: non-null; the caller promises one value.
        coord(unsafe { *u } as f32, None)
    }
}

/// glEvalCoord2f.
#[no_mangle]
pub extern "C" fn glEvalCoord2f(u: GLfloat, v: GLfloat) {
    coord(u, Some(v))
}

/// glEvalCoord2d.
#[no_mangle]
pub extern "C" fn glEvalCoord2d(u: GLdouble, v: GLdouble) {
    coord(u as f32, Some(v as f32))
}

/// glEvalCoord2fv.
///
/// # Safety
/// `u` must be NULL or point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glEvalCoord2fv(u: *const GLfloat) {
    if !u.is_null() {
        // SAFETY: non-null; the caller promises two values.
        let (a, b) = unsafe { (*u, *u.add(1)) };
        coord(a, Some(b))
    }
}

/// glEvalCoord2dv.
///
/// # Safety
/// `u` must be NULL or point to 2 values.
#[no_mangle]
pub unsafe extern "C" fn glEvalCoord2dv(u: *const GLdouble) {
    if !u.is_null() {
        // SAFETY: non-null; the caller promises two values.
        let (a, b) = unsafe { (*u, *u.add(1)) };
        coord(a as f32, Some(b as f32))
    }
}

/// glEvalPoint1: `u = i * du + u1` with Mesa's `du = (u2 - u1) / n`.
#[no_mangle]
pub extern "C" fn glEvalPoint1(i: GLint) {
    with_ctx_list_anywhere(move |c| {
        c.eval_point1(i);
        Ok(())
    })
}

/// glEvalPoint2.
#[no_mangle]
pub extern "C" fn glEvalPoint2(i: GLint, j: GLint) {
    with_ctx_list_anywhere(move |c| {
        c.eval_point2(i, j);
        Ok(())
    })
}

/// Checks glEvalMesh's mode and state; `Some(grid)` when there is something to draw.
fn mesh_setup(
    c: &Context,
    mode: GLenum,
    allowed: &[GLenum],
    two: bool,
) -> GlResult<Option<[Grid; 2]>> {
    if !allowed.contains(&mode) {
        return Err(GlError::InvalidEnum);
    }
    let grid = if two {
        c.eval.grid2
    } else {
        [c.eval.grid1, c.eval.grid1]
    };
    Ok(c.eval_vertex_enabled(two).then_some(grid))
}

/// One glBegin … glEnd of evaluated points at `coords`.
fn strip(
    c: &mut Context,
    mode: Primitive,
    coords: impl Iterator<Item = (f32, Option<f32>)>,
) -> GlResult<()> {
    c.vertex_op(VertexOp::Begin(mode))?;
    for (u, v) in coords {
        c.eval_coord(u, v);
    }
    c.vertex_op(VertexOp::End)
}

/// glEvalMesh1 on the context: `u` steps by Mesa's stored `du` from `u1 + i1·du`.
fn eval_mesh1(c: &mut Context, mode: GLenum, i1: GLint, i2: GLint) -> GlResult<()> {
    let Some([g, _]) = mesh_setup(c, mode, &[GL_POINT, GL_LINE], false)? else {
        return Ok(());
    };
    let du = g.step();
    let mut u = g.d[0] + i1 as f32 * du;
    let prim = if mode == GL_POINT {
        Primitive::Points
    } else {
        Primitive::LineStrip
    };
    let coords = (i1..=i2).map(|_| {
        let x = u;
        u += du;
        (x, None)
    });
    strip(c, prim, coords)
}

/// glEvalMesh2 on the context (GL_FILL as triangle strips, as Mesa issues it).
fn eval_mesh2(c: &mut Context, mode: GLenum, i: [GLint; 2], j: [GLint; 2]) -> GlResult<()> {
    let Some([gu, gv]) = mesh_setup(c, mode, &[GL_POINT, GL_LINE, GL_FILL], true)? else {
        return Ok(());
    };
    let (du, dv) = (gu.step(), gv.step());
    let u1 = gu.d[0] + i[0] as f32 * du;
    let v1 = gv.d[0] + j[0] as f32 * dv;
    // Row `k` of u values (accumulated as Mesa steps them).
    let us = |n: GLint| {
        let mut u = u1;
        (0..n).map(move |_| {
            let x = u;
            u += du;
            x
        })
    };
    let nu = i[1] - i[0] + 1;
    let mut v = v1;
    match mode {
        GL_POINT => {
            c.vertex_op(VertexOp::Begin(Primitive::Points))?;
            for _ in j[0]..=j[1] {
                for u in us(nu) {
                    c.eval_coord(u, Some(v));
                }
                v += dv;
            }
            c.vertex_op(VertexOp::End)
        }
        GL_LINE => {
            for _ in j[0]..=j[1] {
                strip(c, Primitive::LineStrip, us(nu).map(|u| (u, Some(v))))?;
                v += dv;
            }
            for u in us(nu) {
                let mut v = v1;
                let coords = (j[0]..=j[1]).map(|_| {
                    let x = v;
                    v += dv;
                    (u, Some(x))
                });
                strip(c, Primitive::LineStrip, coords)?;
            }
            Ok(())
        }
        _ => {
            for _ in j[0]..j[1] {
                let coords = us(nu).flat_map(|u| [(u, Some(v)), (u, Some(v + dv))]);
                strip(c, Primitive::TriangleStrip, coords)?;
                v += dv;
            }
            Ok(())
        }
    }
}

/// glEvalMesh1 (GL_POINT or GL_LINE); compiled into display lists as one call.
#[no_mangle]
pub extern "C" fn glEvalMesh1(mode: GLenum, i1: GLint, i2: GLint) {
    with_ctx_list(move |c| eval_mesh1(c, mode, i1, i2))
}

/// glEvalMesh2 (GL_POINT, GL_LINE or GL_FILL); compiled into display lists as one call.
#[no_mangle]
pub extern "C" fn glEvalMesh2(mode: GLenum, i1: GLint, i2: GLint, j1: GLint, j2: GLint) {
    with_ctx_list(move |c| eval_mesh2(c, mode, [i1, i2], [j1, j2]))
}

/// The values glGetMap returns for `query`, as f64.
fn get_map(target: GLenum, query: GLenum) -> Vec<f64> {
    with_ctx(|c| {
        let (kind, two) = map_target(target).ok_or(GlError::InvalidEnum)?;
        let m = c.map(kind, two);
        Ok(match query {
            GL_COEFF => m.points.iter().map(|&p| p as f64).collect(),
            GL_ORDER if two => vec![m.uorder as f64, m.vorder as f64],
            GL_ORDER => vec![m.uorder as f64],
            GL_DOMAIN if two => [m.u[0], m.u[1], m.v[0], m.v[1]].map(f64::from).to_vec(),
            GL_DOMAIN => vec![m.u[0] as f64, m.u[1] as f64],
            _ => return Err(GlError::InvalidEnum),
        })
    })
}

/// glGetMapdv.
///
/// # Safety
/// `v` must be NULL or writable for the values of `query`.
#[no_mangle]
pub unsafe extern "C" fn glGetMapdv(target: GLenum, query: GLenum, v: *mut GLdouble) {
    // SAFETY: the caller promises room for the values.
    unsafe { write_all(v, &get_map(target, query), |x| x) }
}

/// glGetMapfv.
///
/// # Safety
/// `v` must be NULL or writable for the values of `query`.
#[no_mangle]
pub unsafe extern "C" fn glGetMapfv(target: GLenum, query: GLenum, v: *mut GLfloat) {
    // SAFETY: the caller promises room for the values.
    unsafe { write_all(v, &get_map(target, query), |x| x as f32) }
}

/// glGetMapiv (coefficients and domain rounded to the nearest integer).
///
/// # Safety
/// `v` must be NULL or writable for the values of `query`.
#[no_mangle]
pub unsafe extern "C" fn glGetMapiv(target: GLenum, query: GLenum, v: *mut GLint) {
    // Coefficients and domain are rounded to the nearest integer, the order is exact.
    let round = query != GL_ORDER;
    let conv = |x: f64| if round { (x as f32 + 0.5).floor() } else { x as f32 } as GLint;
    // SAFETY: the caller promises room for the values.
    unsafe { write_all(v, &get_map(target, query), conv) }
}
