//! GL state calls: capabilities, clears, viewport, depth, faces, hints, pixel store,
//! glFlush/glFinish and glGetError.
#![allow(non_snake_case)]

use super::enums::*;
use super::glext_enums::*;
use super::types::*;
use super::{gl_bool, with_ctx, with_ctx_list};
use crate::context::clamp01;
use crate::context::error::{GlError, GlResult};
use crate::context::state::{Cap, CompareFunc, Face, PixelStore, ShadeModel};
use crate::context::Context;

/// glGetError: the first error since the last call, or GL_NO_ERROR.
#[no_mangle]
pub extern "C" fn glGetError() -> GLenum {
    // Between glBegin and glEnd it returns 0 and records GL_INVALID_OPERATION, as Mesa.
    with_ctx(|c| Ok(c.take_error().map_or(GL_NO_ERROR, GlError::to_gl)))
}

/// glEnable.
#[no_mangle]
pub extern "C" fn glEnable(cap: GLenum) {
    with_ctx_list(move |c| enable(c, cap, true))
}

/// glEnable/glDisable. Like Mesa's compatibility profile (and unlike the GL 1.5 spec, which
/// makes them INVALID_ENUM), the client arrays are accepted as glEnableClientState /
/// glDisableClientState: real programs rely on it (README, known differences).
fn enable(c: &mut Context, cap: GLenum, on: bool) -> GlResult<()> {
    if super::arrays::is_client_array(cap) {
        return super::arrays::set_client_array(c, cap, on);
    }
    c.set_cap(Cap::from_gl(cap)?, on)
}

/// glDisable.
#[no_mangle]
pub extern "C" fn glDisable(cap: GLenum) {
    with_ctx_list(move |c| enable(c, cap, false))
}

/// glIsEnabled (also answers the client array states).
#[no_mangle]
pub extern "C" fn glIsEnabled(cap: GLenum) -> GLboolean {
    with_ctx(|c| {
        let a = &c.arrays;
        let on = match cap {
            GL_VERTEX_ARRAY => a.vertex.enabled,
            GL_COLOR_ARRAY => a.color.enabled,
            GL_NORMAL_ARRAY => a.normal.enabled,
            GL_TEXTURE_COORD_ARRAY => a.texcoord[c.state.client_active_texture].enabled,
            GL_EDGE_FLAG_ARRAY => a.edge_flag.enabled,
            GL_INDEX_ARRAY => a.index.enabled,
            GL_SECONDARY_COLOR_ARRAY => a.secondary_color.enabled,
            GL_FOG_COORD_ARRAY => a.fog_coord.enabled,
            _ => c.state.caps.get(Cap::from_gl(cap)?),
        };
        Ok(on as GLboolean)
    })
}

/// glClearColor (clamped to [0,1]).
#[no_mangle]
pub extern "C" fn glClearColor(red: GLclampf, green: GLclampf, blue: GLclampf, alpha: GLclampf) {
    with_ctx_list(move |c| {
        c.state.clear_color = [red, green, blue, alpha].map(|v| clamp01(v as f64) as f32);
        Ok(())
    })
}

/// glClearDepth (clamped to [0,1]).
#[no_mangle]
pub extern "C" fn glClearDepth(depth: GLclampd) {
    with_ctx_list(move |c| {
        c.state.clear_depth = clamp01(depth);
        Ok(())
    })
}

/// glClearStencil.
#[no_mangle]
pub extern "C" fn glClearStencil(s: GLint) {
    with_ctx_list(move |c| {
        c.state.clear_stencil = s;
        Ok(())
    })
}

/// glClear.
#[no_mangle]
pub extern "C" fn glClear(mask: GLbitfield) {
    with_ctx_list(move |c| c.clear(mask))
}

/// glViewport.
#[no_mangle]
pub extern "C" fn glViewport(x: GLint, y: GLint, width: GLsizei, height: GLsizei) {
    with_ctx_list(move |c| c.viewport(x, y, width, height))
}

/// glScissor.
#[no_mangle]
pub extern "C" fn glScissor(x: GLint, y: GLint, width: GLsizei, height: GLsizei) {
    with_ctx_list(move |c| c.scissor(x, y, width, height))
}

/// glDepthRange.
#[no_mangle]
pub extern "C" fn glDepthRange(near_val: GLclampd, far_val: GLclampd) {
    with_ctx_list(move |c| c.depth_range(near_val, far_val))
}

/// glDepthFunc.
#[no_mangle]
pub extern "C" fn glDepthFunc(func: GLenum) {
    with_ctx_list(move |c| {
        let f = CompareFunc::from_gl(func)?;
        c.state.depth_func = f;
        Ok(())
    })
}

/// glDepthMask.
#[no_mangle]
pub extern "C" fn glDepthMask(flag: GLboolean) {
    with_ctx_list(move |c| {
        c.state.depth_mask = gl_bool(flag);
        Ok(())
    })
}

/// glColorMask.
#[no_mangle]
pub extern "C" fn glColorMask(red: GLboolean, green: GLboolean, blue: GLboolean, alpha: GLboolean) {
    with_ctx_list(move |c| {
        c.state.color_mask = [red, green, blue, alpha].map(gl_bool);
        Ok(())
    })
}

/// glShadeModel.
#[no_mangle]
pub extern "C" fn glShadeModel(mode: GLenum) {
    with_ctx_list(move |c| {
        let m = match mode {
            GL_FLAT => ShadeModel::Flat,
            GL_SMOOTH => ShadeModel::Smooth,
            _ => return Err(GlError::InvalidEnum),
        };
        c.state.shade_model = m;
        Ok(())
    })
}

/// glCullFace.
#[no_mangle]
pub extern "C" fn glCullFace(mode: GLenum) {
    with_ctx_list(move |c| {
        let f = Face::from_gl(mode)?;
        c.state.cull_face = f;
        Ok(())
    })
}

/// glFrontFace.
#[no_mangle]
pub extern "C" fn glFrontFace(mode: GLenum) {
    with_ctx_list(move |c| {
        let ccw = match mode {
            GL_CCW => true,
            GL_CW => false,
            _ => return Err(GlError::InvalidEnum),
        };
        c.state.front_ccw = ccw;
        Ok(())
    })
}

/// glHint (stored; the rasterizer ignores hints, as llvmpipe does).
#[no_mangle]
pub extern "C" fn glHint(target: GLenum, mode: GLenum) {
    with_ctx_list(move |c| {
        if !matches!(mode, GL_FASTEST | GL_NICEST | GL_DONT_CARE) {
            return Err(GlError::InvalidEnum);
        }
        let h = &mut c.state.hints;
        let slot = match target {
            GL_PERSPECTIVE_CORRECTION_HINT => &mut h.perspective_correction,
            GL_POINT_SMOOTH_HINT => &mut h.point_smooth,
            GL_LINE_SMOOTH_HINT => &mut h.line_smooth,
            GL_POLYGON_SMOOTH_HINT => &mut h.polygon_smooth,
            GL_FOG_HINT => &mut h.fog,
            GL_GENERATE_MIPMAP_HINT => &mut h.generate_mipmap,
            GL_TEXTURE_COMPRESSION_HINT => &mut h.texture_compression,
            _ => return Err(GlError::InvalidEnum),
        };
        *slot = mode;
        Ok(())
    })
}

/// glFlush: makes the rendering visible in the OSMesa buffer.
#[no_mangle]
pub extern "C" fn glFlush() {
    with_ctx(|c| {
        c.flush();
        Ok(())
    })
}

/// glFinish: as glFlush (rendering is synchronous).
#[no_mangle]
pub extern "C" fn glFinish() {
    glFlush()
}

fn pixel_store(pname: GLenum, value: f64) {
    with_ctx(|c| {
        let (store, which): (&mut PixelStore, GLenum) = match pname {
            GL_PACK_SWAP_BYTES | GL_PACK_LSB_FIRST | GL_PACK_ROW_LENGTH | GL_PACK_SKIP_ROWS
            | GL_PACK_SKIP_PIXELS | GL_PACK_ALIGNMENT | GL_PACK_IMAGE_HEIGHT
            | GL_PACK_SKIP_IMAGES => (&mut c.state.pack, pname),
            GL_UNPACK_SWAP_BYTES
            | GL_UNPACK_LSB_FIRST
            | GL_UNPACK_ROW_LENGTH
            | GL_UNPACK_SKIP_ROWS
            | GL_UNPACK_SKIP_PIXELS
            | GL_UNPACK_ALIGNMENT
            | GL_UNPACK_IMAGE_HEIGHT
            | GL_UNPACK_SKIP_IMAGES => (&mut c.state.unpack, pname),
            _ => return Err(GlError::InvalidEnum),
        };
        let iv = value.round() as i64;
        let int = || -> Result<i32, GlError> {
            if iv < 0 || iv > i32::MAX as i64 {
                Err(GlError::InvalidValue)
            } else {
                Ok(iv as i32)
            }
        };
        match which {
            GL_PACK_SWAP_BYTES | GL_UNPACK_SWAP_BYTES => store.swap_bytes = value != 0.0,
            GL_PACK_LSB_FIRST | GL_UNPACK_LSB_FIRST => store.lsb_first = value != 0.0,
            GL_PACK_ROW_LENGTH | GL_UNPACK_ROW_LENGTH => store.row_length = int()?,
            GL_PACK_SKIP_ROWS | GL_UNPACK_SKIP_ROWS => store.skip_rows = int()?,
            GL_PACK_SKIP_PIXELS | GL_UNPACK_SKIP_PIXELS => store.skip_pixels = int()?,
            GL_PACK_IMAGE_HEIGHT | GL_UNPACK_IMAGE_HEIGHT => store.image_height = int()?,
            GL_PACK_SKIP_IMAGES | GL_UNPACK_SKIP_IMAGES => store.skip_images = int()?,
            _ => {
                let a = int()?;
                if !matches!(a, 1 | 2 | 4 | 8) {
                    return Err(GlError::InvalidValue);
                }
                store.alignment = a;
            }
        }
        Ok(())
    })
}

/// glPixelStorei.
#[no_mangle]
pub extern "C" fn glPixelStorei(pname: GLenum, param: GLint) {
    pixel_store(pname, param as f64);
}

/// glPixelStoref.
#[no_mangle]
pub extern "C" fn glPixelStoref(pname: GLenum, param: GLfloat) {
    pixel_store(pname, param as f64);
}
