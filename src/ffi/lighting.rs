//! Lighting and fog calls of GL 1.0–1.3 (`GL/gl.h`): glLight, glLightModel, glMaterial,
//! glColorMaterial, glFog and their queries. Integer colours convert with Mesa's
//! `INT_TO_FLOAT`; integer scalars convert directly; queries of colours as integers use
//! `FLOAT_TO_INT`, as Mesa's `light.c` and `fog.c` do.
#![allow(non_snake_case)]

use super::enums::*;
use super::families::c_fns;
use super::types::*;
use super::{with_ctx, with_ctx_list_keep};
use crate::context::lighting_state::{float_to_int, int_to_float};
use crate::context::state::Cap;
use crate::context::Context;

/// Reads `n` values from a GL pointer argument, padding to 4 with zeros.
///
/// # Safety
/// `p` must be null or readable for `n` values.
pub(crate) unsafe fn read4<T: Copy + Default>(p: *const T, n: usize) -> Option<[T; 4]> {
    if p.is_null() {
        return None;
    }
    let mut out = [T::default(); 4];
    for (i, o) in out.iter_mut().enumerate().take(n) {
        // SAFETY: the caller guarantees `n` readable values.
        *o = unsafe { p.add(i).read_unaligned() };
    }
    Some(out)
}

/// How many values a glLight pname takes (0 for an unknown pname).
fn light_count(pname: GLenum) -> usize {
    match pname {
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_POSITION => 4,
        GL_SPOT_DIRECTION => 3,
        GL_SPOT_EXPONENT
        | GL_SPOT_CUTOFF
        | GL_CONSTANT_ATTENUATION
        | GL_LINEAR_ATTENUATION
        | GL_QUADRATIC_ATTENUATION => 1,
        _ => 0,
    }
}

/// How many values a glMaterial pname takes.
fn material_count(pname: GLenum) -> usize {
    match pname {
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE => 4,
        GL_COLOR_INDEXES => 3,
        GL_SHININESS => 1,
        _ => 0,
    }
}

/// How many values a glLightModel pname takes.
fn light_model_count(pname: GLenum) -> usize {
    if pname == GL_LIGHT_MODEL_AMBIENT {
        4
    } else {
        1
    }
}

/// How many values a glFog pname takes.
fn fog_count(pname: GLenum) -> usize {
    if pname == GL_FOG_COLOR {
        4
    } else {
        1
    }
}

fn is_color(pname: GLenum) -> bool {
    matches!(
        pname,
        GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR | GL_EMISSION | GL_AMBIENT_AND_DIFFUSE
    )
}

fn light(light: GLenum, pname: GLenum, p: [f32; 4]) {
    with_ctx_list_keep(move |c| {
        let mv = c.matrices.modelview.top().0;
        c.light.set_light(light, pname, &p, &mv)
    })
}

fn light_model(pname: GLenum, p: [f32; 4]) {
    with_ctx_list_keep(move |c| c.light.set_light_model(pname, &p))
}

fn material(face: GLenum, pname: GLenum, p: [f32; 4]) {
    // glMaterial is allowed between glBegin and glEnd.
    super::with_ctx_list_anywhere_keep(move |c| {
        let cm = c.state.caps.get(Cap::ColorMaterial);
        c.material_changing();
        c.light.set_material(face, pname, &p, cm)
    })
}

fn fog(pname: GLenum, p: [f32; 4]) {
    with_ctx_list_keep(move |c| c.light.set_fog(pname, &p))
}

/// Copies the current colour into the tracked material terms when GL_COLOR_MATERIAL is on
/// (what Mesa's FLUSH_CURRENT does before material queries).
pub(crate) fn sync_color_material(c: &mut Context) {
    if c.state.caps.get(Cap::ColorMaterial) {
        let col = c.state.current.color;
        c.light.sync_color_material(col);
    }
}

/// Reads the integer form of a parameter vector: colours (`color`) with Mesa's
/// `INT_TO_FLOAT`, other values directly.
///
/// # Safety
/// As [`read4`].
unsafe fn read4i(p: *const GLint, n: usize, color: bool) -> Option<[f32; 4]> {
    // SAFETY: forwarded caller contract.
    let p = unsafe { read4(p, n) }?;
    Some(if color {
        p.map(int_to_float)
    } else {
        p.map(|v| v as f32)
    })
}

/// A scalar parameter as the parameter vector the setters take.
fn one(param: f32) -> [f32; 4] {
    [param, 0.0, 0.0, 0.0]
}

/// Writes the values of a glGet*v query, converted by `f`, to `params` (nothing when the
/// query failed or `params` is null).
///
/// # Safety
/// `params` must be null or writable for `v.len()` values.
unsafe fn write_all<T>(params: *mut T, v: Option<Vec<f32>>, f: impl Fn(f32) -> T) {
    let Some(v) = v else { return };
    if params.is_null() {
        return;
    }
    for (i, x) in v.into_iter().enumerate() {
        // SAFETY: the caller promises room for the values.
        unsafe { params.add(i).write_unaligned(f(x)) };
    }
}

/// Shared by glGetLightfv/iv: the values, or an error.
fn get_light(light_: GLenum, pname: GLenum) -> Option<Vec<f32>> {
    with_ctx(|c| c.light.get_light(light_, pname).map(Some))
}

/// glGetLightiv's conversion: colours with Mesa's `FLOAT_TO_INT`, other values truncated.
fn light_int(pname: GLenum) -> impl Fn(f32) -> GLint {
    let color = matches!(pname, GL_AMBIENT | GL_DIFFUSE | GL_SPECULAR);
    move |x| if color { float_to_int(x) } else { x as i32 }
}

/// Shared by glGetMaterialfv/iv.
fn get_material(face: GLenum, pname: GLenum) -> Option<Vec<f32>> {
    with_ctx(|c| {
        sync_color_material(c);
        c.light.get_material(face, pname).map(Some)
    })
}

/// glGetMaterialiv's conversion: colours with Mesa's `FLOAT_TO_INT`, other values rounded
/// (`lroundf`).
fn material_int(pname: GLenum) -> impl Fn(f32) -> GLint {
    let color = is_color(pname);
    move |x| {
        if color {
            float_to_int(x)
        } else {
            x.round() as i32
        }
    }
}

// glLight, glLightModel and glMaterial: the vector forms read as many values as `pname`
// takes.
c_fns! {
    safe fn glLightf(light_: GLenum, pname: GLenum, param: GLfloat) => light(light_, pname, one(param));
    safe fn glLighti(light_: GLenum, pname: GLenum, param: GLint) => light(light_, pname, one(param as f32));
    unsafe fn glLightfv(light_: GLenum, pname: GLenum, params: *const GLfloat) => if let Some(p) = read4(params, light_count(pname)) { light(light_, pname, p) };
    unsafe fn glLightiv(light_: GLenum, pname: GLenum, params: *const GLint) => if let Some(p) = read4i(params, light_count(pname), is_color(pname)) { light(light_, pname, p) };
    unsafe fn glGetLightfv(light_: GLenum, pname: GLenum, params: *mut GLfloat) => write_all(params, get_light(light_, pname), |x| x);
    unsafe fn glGetLightiv(light_: GLenum, pname: GLenum, params: *mut GLint) => write_all(params, get_light(light_, pname), light_int(pname));
    safe fn glLightModelf(pname: GLenum, param: GLfloat) => light_model(pname, one(param));
    safe fn glLightModeli(pname: GLenum, param: GLint) => light_model(pname, one(param as f32));
    unsafe fn glLightModelfv(pname: GLenum, params: *const GLfloat) => if let Some(p) = read4(params, light_model_count(pname)) { light_model(pname, p) };
    unsafe fn glLightModeliv(pname: GLenum, params: *const GLint) => if let Some(p) = read4i(params, light_model_count(pname), pname == GL_LIGHT_MODEL_AMBIENT) { light_model(pname, p) };
    safe fn glMaterialf(face: GLenum, pname: GLenum, param: GLfloat) => material(face, pname, one(param));
    safe fn glMateriali(face: GLenum, pname: GLenum, param: GLint) => material(face, pname, one(param as f32));
    unsafe fn glMaterialfv(face: GLenum, pname: GLenum, params: *const GLfloat) => if let Some(p) = read4(params, material_count(pname)) { material(face, pname, p) };
    unsafe fn glMaterialiv(face: GLenum, pname: GLenum, params: *const GLint) => if let Some(p) = read4i(params, material_count(pname), is_color(pname)) { material(face, pname, p) };
    unsafe fn glGetMaterialfv(face: GLenum, pname: GLenum, params: *mut GLfloat) => write_all(params, get_material(face, pname), |x| x);
    unsafe fn glGetMaterialiv(face: GLenum, pname: GLenum, params: *mut GLint) => write_all(params, get_material(face, pname), material_int(pname));
}

/// glColorMaterial.
#[no_mangle]
pub extern "C" fn glColorMaterial(face: GLenum, mode: GLenum) {
    with_ctx_list_keep(move |c| {
        c.light.set_color_material(face, mode)?;
        sync_color_material(c);
        Ok(())
    })
}

// glFog: the vector forms read as many values as `pname` takes.
c_fns! {
    safe fn glFogf(pname: GLenum, param: GLfloat) => fog(pname, one(param));
    safe fn glFogi(pname: GLenum, param: GLint) => fog(pname, one(param as f32));
    unsafe fn glFogfv(pname: GLenum, params: *const GLfloat) => if let Some(p) = read4(params, fog_count(pname)) { fog(pname, p) };
    unsafe fn glFogiv(pname: GLenum, params: *const GLint) => if let Some(p) = read4i(params, fog_count(pname), pname == GL_FOG_COLOR) { fog(pname, p) };
}
