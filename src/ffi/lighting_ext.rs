//! GL 1.4 vertex attributes of the lighting and fog stages (`GL/glext.h`): the current
//! secondary colour (glSecondaryColor3*) and fog coordinate (glFogCoord*). Integer
//! colours convert as Mesa's vbo module does (`(2c + 1) / (2^n - 1)` for signed types,
//! `c / (2^n - 1)` for unsigned ones); the alpha of the secondary colour is 1.
#![allow(non_snake_case)]

use super::families::vector_fns;
use super::types::*;
use super::with_ctx_vertex;
use crate::context::dlist::VertexOp;

/// Sets the current secondary colour (allowed between glBegin and glEnd).
fn secondary(v: [f32; 3]) {
    with_ctx_vertex(VertexOp::SecondaryColor(v))
}

/// Sets the current fog coordinate (allowed between glBegin and glEnd).
fn fog_coord(f: f32) {
    with_ctx_vertex(VertexOp::FogCoord(f))
}

/// glFogCoordf.
#[no_mangle]
pub extern "C" fn glFogCoordf(coord: GLfloat) {
    fog_coord(coord)
}

/// glFogCoordd.
#[no_mangle]
pub extern "C" fn glFogCoordd(coord: GLdouble) {
    fog_coord(coord as f32)
}

/// glFogCoordfv.
///
/// # Safety
/// `coord` must point to one value.
#[no_mangle]
pub unsafe extern "C" fn glFogCoordfv(coord: *const GLfloat) {
    if !coord.is_null() {
        // SAFETY: the caller promises one readable value.
        fog_coord(unsafe { coord.read_unaligned() })
    }
}

/// glFogCoorddv.
///
/// # Safety
/// `coord` must point to one value.
#[no_mangle]
pub unsafe extern "C" fn glFogCoorddv(coord: *const GLdouble) {
    if !coord.is_null() {
        // SAFETY: the caller promises one readable value.
        fog_coord(unsafe { coord.read_unaligned() } as f32)
    }
}

vector_fns! {
    secondary norm [0.0, 0.0, 0.0] {
        (red, green, blue) glSecondaryColor3b glSecondaryColor3bv GLbyte, glSecondaryColor3s glSecondaryColor3sv GLshort, glSecondaryColor3i glSecondaryColor3iv GLint, glSecondaryColor3f glSecondaryColor3fv GLfloat;
        (red, green, blue) glSecondaryColor3d glSecondaryColor3dv GLdouble, glSecondaryColor3ub glSecondaryColor3ubv GLubyte, glSecondaryColor3us glSecondaryColor3usv GLushort, glSecondaryColor3ui glSecondaryColor3uiv GLuint;
    }
    // GL_EXT_secondary_color's names of the same functions.
    secondary norm [0.0, 0.0, 0.0] {
        (red, green, blue) glSecondaryColor3bEXT glSecondaryColor3bvEXT GLbyte, glSecondaryColor3sEXT glSecondaryColor3svEXT GLshort, glSecondaryColor3iEXT glSecondaryColor3ivEXT GLint, glSecondaryColor3fEXT glSecondaryColor3fvEXT GLfloat;
        (red, green, blue) glSecondaryColor3dEXT glSecondaryColor3dvEXT GLdouble, glSecondaryColor3ubEXT glSecondaryColor3ubvEXT GLubyte, glSecondaryColor3usEXT glSecondaryColor3usvEXT GLushort, glSecondaryColor3uiEXT glSecondaryColor3uivEXT GLuint;
    }
}
