//! glWindowPos of GL 1.4 (`GL/glext.h`) with the ARB aliases Mesa exports (it exports no MESA ones):
//! window coordinates set the raster position directly (Mesa's `window_pos3f`).
#![allow(non_snake_case)]

use super::families::vector_fns;
use super::types::*;
use super::with_ctx_list;
use crate::context::pixel_ops::raster_pos::window_pos;

fn wp([x, y, z]: [f32; 3]) {
    with_ctx_list(move |c| {
        window_pos(c, x, y, z);
        Ok(())
    })
}

vector_fns! {
    wp cast [0.0, 0.0, 0.0] {
        (x, y) glWindowPos2s glWindowPos2sv GLshort, glWindowPos2i glWindowPos2iv GLint, glWindowPos2f glWindowPos2fv GLfloat, glWindowPos2d glWindowPos2dv GLdouble;
        (x, y, z) glWindowPos3s glWindowPos3sv GLshort, glWindowPos3i glWindowPos3iv GLint, glWindowPos3f glWindowPos3fv GLfloat, glWindowPos3d glWindowPos3dv GLdouble;
    }
    wp cast [0.0, 0.0, 0.0] {
        (x, y) glWindowPos2sARB glWindowPos2svARB GLshort, glWindowPos2iARB glWindowPos2ivARB GLint, glWindowPos2fARB glWindowPos2fvARB GLfloat, glWindowPos2dARB glWindowPos2dvARB GLdouble;
        (x, y, z) glWindowPos3sARB glWindowPos3svARB GLshort, glWindowPos3iARB glWindowPos3ivARB GLint, glWindowPos3fARB glWindowPos3fvARB GLfloat, glWindowPos3dARB glWindowPos3dvARB GLdouble;
    }
}
