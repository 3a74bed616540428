//! Raster position and pixel rectangles of `GL/gl.h`: glRasterPos*, glPixelZoom.
//! Arguments convert to f32 as Mesa's `rastpos.c` does; vector forms read their values
//! before anything else.
#![allow(non_snake_case)]

use super::families::vector_fns;
use super::types::*;
use super::with_ctx_list;
use crate::context::pixel_ops::raster_pos::raster_pos;

fn rp(v: [f32; 4]) {
    with_ctx_list(move |c| {
        raster_pos(c, v);
        Ok(())
    })
}

vector_fns! {
    rp cast [0.0, 0.0, 0.0, 1.0] {
        (x, y) glRasterPos2s glRasterPos2sv GLshort, glRasterPos2i glRasterPos2iv GLint, glRasterPos2f glRasterPos2fv GLfloat, glRasterPos2d glRasterPos2dv GLdouble;
        (x, y, z) glRasterPos3s glRasterPos3sv GLshort, glRasterPos3i glRasterPos3iv GLint, glRasterPos3f glRasterPos3fv GLfloat, glRasterPos3d glRasterPos3dv GLdouble;
        (x, y, z, w) glRasterPos4s glRasterPos4sv GLshort, glRasterPos4i glRasterPos4iv GLint, glRasterPos4f glRasterPos4fv GLfloat, glRasterPos4d glRasterPos4dv GLdouble;
    }
}

/// glPixelZoom.
#[no_mangle]
pub extern "C" fn glPixelZoom(xfactor: GLfloat, yfactor: GLfloat) {
    with_ctx_list(move |c| {
        c.pixel_zoom(xfactor, yfactor);
        Ok(())
    })
}
