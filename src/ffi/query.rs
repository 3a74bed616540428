//! Queries: glGet{Boolean,Integer,Float,Double}v, glGetString, glGetPointerv and
//! glReadPixels.
#![allow(non_snake_case)]

use super::enums::*;
use super::types::*;
use super::with_ctx;
use crate::context::error::GlError;
use crate::context::get::get;
use crate::context::pack::read::read_pixels;
use libc::c_void;

/// Writes the value of `pname` through `out` using `conv`.
fn get_into<T>(
    pname: GLenum,
    out: *mut T,
    conv: impl Fn(&crate::context::get::Value, &mut dyn FnMut(usize, T)),
) {
    with_ctx(|c| {
        let v = get(c, pname)?;
        if out.is_null() {
            return Ok(());
        }
        conv(&v, &mut |i, x| {
            // SAFETY: the program promises room for the value's components, as GL requires.
            unsafe { *out.add(i) = x }
        });
        Ok(())
    })
}

/// glGetBooleanv.
///
/// # Safety
/// `params` must be writable for the value's components.
#[no_mangle]
pub unsafe extern "C" fn glGetBooleanv(pname: GLenum, params: *mut GLboolean) {
    get_into(pname, params, |v, put| {
        v.as_bools()
            .enumerate()
            .for_each(|(i, x)| put(i, x as GLboolean))
    })
}

/// glGetIntegerv.
///
/// # Safety
/// `params` must be writable for the value's components.
#[no_mangle]
pub unsafe extern "C" fn glGetIntegerv(pname: GLenum, params: *mut GLint) {
    get_into(pname, params, |v, put| {
        v.as_ints().enumerate().for_each(|(i, x)| put(i, x))
    })
}

/// glGetFloatv.
///
/// # Safety
/// `params` must be writable for the value's components.
#[no_mangle]
pub unsafe extern "C" fn glGetFloatv(pname: GLenum, params: *mut GLfloat) {
    get_into(pname, params, |v, put| {
        v.as_doubles()
            .enumerate()
            .for_each(|(i, x)| put(i, x as f32))
    })
}

/// glGetDoublev.
///
/// # Safety
/// `params` must be writable for the value's components.
#[no_mangle]
pub unsafe extern "C" fn glGetDoublev(pname: GLenum, params: *mut GLdouble) {
    get_into(pname, params, |v, put| {
        v.as_doubles().enumerate().for_each(|(i, x)| put(i, x))
    })
}

/// The extensions that work, as GL_EXTENSIONS lists them (NUL-terminated for C).
pub const EXTENSIONS: &str = concat!(
    "GL_ARB_clip_control GL_ARB_depth_buffer_float GL_ARB_depth_texture GL_ARB_multitexture GL_ARB_occlusion_query GL_ARB_shadow ",
    "GL_ARB_texture_border_clamp GL_ARB_texture_cube_map GL_EXT_texture3D ",
    "GL_EXT_texture_cube_map GL_ARB_framebuffer_object GL_EXT_framebuffer_object ",
    "GL_EXT_framebuffer_blit GL_EXT_packed_depth_stencil ",
    "GL_ARB_texture_env_add GL_ARB_window_pos GL_ARB_point_parameters ",
    "GL_ARB_texture_env_combine GL_ARB_texture_env_crossbar GL_ARB_texture_env_dot3 ",
    "GL_ARB_texture_mirrored_repeat GL_ARB_transpose_matrix GL_ARB_vertex_buffer_object ",
    "GL_EXT_bgra GL_EXT_blend_color GL_EXT_blend_equation_separate ",
    "GL_EXT_blend_func_separate GL_EXT_blend_minmax GL_EXT_blend_subtract ",
    "GL_EXT_draw_range_elements GL_EXT_multi_draw_arrays GL_EXT_rescale_normal ",
    "GL_EXT_fog_coord GL_EXT_point_parameters GL_EXT_secondary_color ",
    "GL_EXT_separate_specular_color GL_EXT_stencil_wrap GL_EXT_texture_env_add ",
    "GL_EXT_texture_env_combine GL_EXT_texture_filter_anisotropic GL_EXT_texture_lod_bias ",
    "GL_EXT_vertex_array ",
    "GL_NV_blend_square GL_SGIS_generate_mipmap GL_SGIS_texture_edge_clamp ",
    "GL_SGIS_texture_lod GL_ARB_texture_compression GL_EXT_texture_compression_s3tc ",
    "GL_ARB_texture_compression_rgtc GL_EXT_texture_compression_rgtc ",
    "GL_EXT_texture_compression_latc GL_EXT_texture_sRGB\0"
);

/// glGetString: vendor, renderer, version ("1.5 …") and the extension list.
#[no_mangle]
pub extern "C" fn glGetString(name: GLenum) -> *const GLubyte {
    // Without a current context, and between glBegin and glEnd, GL calls return 0 (Mesa).
    if !super::outside_begin_end() {
        return std::ptr::null();
    }
    let s: &'static [u8] = match name {
        GL_VENDOR => b"softgl\0",
        GL_RENDERER => b"softgl software rasterizer\0",
        GL_VERSION => concat!("1.5 softgl ", env!("CARGO_PKG_VERSION"), "\0").as_bytes(),
        GL_EXTENSIONS => EXTENSIONS.as_bytes(),
        _ => {
            with_ctx(|_| Err::<(), _>(GlError::InvalidEnum));
            return std::ptr::null();
        }
    };
    s.as_ptr()
}

/// glGetPointerv: the client array pointers.
///
/// # Safety
/// `params` must be writable.
#[no_mangle]
pub unsafe extern "C" fn glGetPointerv(pname: GLenum, params: *mut *mut GLvoid) {
    with_ctx(|c| {
        let a = &c.arrays;
        let p = match pname {
            GL_VERTEX_ARRAY_POINTER => a.vertex.ptr,
            GL_COLOR_ARRAY_POINTER => a.color.ptr,
            GL_NORMAL_ARRAY_POINTER => a.normal.ptr,
            GL_TEXTURE_COORD_ARRAY_POINTER => a.texcoord[c.state.client_active_texture].ptr,
            GL_FEEDBACK_BUFFER_POINTER => c.feedback.fb_buffer,
            GL_SELECTION_BUFFER_POINTER => c.feedback.sel_buffer,
            GL_EDGE_FLAG_ARRAY_POINTER => a.edge_flag.ptr,
            GL_INDEX_ARRAY_POINTER => a.index.ptr,
            super::glext_enums::GL_SECONDARY_COLOR_ARRAY_POINTER => a.secondary_color.ptr,
            super::glext_enums::GL_FOG_COORD_ARRAY_POINTER => a.fog_coord.ptr,
            _ => return Err(GlError::InvalidEnum),
        };
        if !params.is_null() {
            // SAFETY: checked non-null; the caller promises it is writable.
            unsafe { *params = p as *mut c_void };
        }
        Ok(())
    })
}

/// glReadPixels: reads a rectangle of the framebuffer (bottom row first) with the pack
/// parameters; pixels outside the framebuffer are left unwritten.
///
/// # Safety
/// `pixels` must be writable for the packed image.
#[no_mangle]
pub unsafe extern "C" fn glReadPixels(
    x: GLint,
    y: GLint,
    width: GLsizei,
    height: GLsizei,
    format: GLenum,
    type_: GLenum,
    pixels: *mut GLvoid,
) {
    with_ctx(|c| {
        let out = pixels as *mut u8;
        // SAFETY: the program promises room for the packed image, as GL requires.
        unsafe { read_pixels(c, x, y, width, height, format, type_, out) }
    })
}
