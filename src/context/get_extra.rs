//! glGetString's strings and glGetPointerv's pointers.

use super::{Context, GlError, GlResult};
use crate::gl::enums::*;
use crate::gl::glext_enums::{
    GL_FOG_COORD_ARRAY_POINTER, GL_SECONDARY_COLOR_ARRAY_POINTER, GL_SHADING_LANGUAGE_VERSION,
};
use crate::gl::types::*;

/// The extensions that work, as GL_EXTENSIONS lists them (NUL-terminated for C).
pub const EXTENSIONS: &str = concat!(
    "GL_ARB_clip_control GL_ARB_depth_buffer_float GL_ARB_depth_texture GL_ARB_multitexture GL_ARB_occlusion_query GL_ARB_shadow ",
    "GL_ARB_texture_border_clamp GL_ARB_texture_cube_map GL_EXT_texture3D ",
    "GL_EXT_texture_cube_map GL_ARB_framebuffer_object GL_EXT_framebuffer_object ",
    "GL_EXT_framebuffer_blit GL_EXT_packed_depth_stencil ",
    "GL_ARB_seamless_cube_map ",
    "GL_ARB_texture_env_add GL_ARB_window_pos GL_ARB_point_parameters GL_ARB_point_sprite ",
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
    "GL_EXT_texture_compression_latc GL_EXT_texture_sRGB ",
    "GL_ARB_framebuffer_sRGB GL_EXT_framebuffer_sRGB ",
    "GL_ARB_half_float_pixel GL_ARB_texture_float GL_ARB_texture_rg ",
    "GL_ARB_pixel_buffer_object GL_EXT_pixel_buffer_object ",
    "GL_ARB_shader_objects GL_ARB_vertex_shader GL_ARB_fragment_shader ",
    "GL_ARB_shading_language_100 GL_ARB_draw_buffers GL_ARB_texture_non_power_of_two ",
    "GL_ARB_vertex_array_object GL_ARB_draw_elements_base_vertex ",
    "GL_ARB_draw_instanced GL_ARB_instanced_arrays\0"
);

/// glGetString: vendor, renderer, version ("2.1 …", the compatibility profile of GL 2.1),
/// the shading language version ("1.20", GL 2.1's; the compiler also takes the
/// `#version 130` … `330` shaders it lowers) and the extension list, each NUL-terminated.
pub(crate) fn gl_string(name: GLenum) -> GlResult<&'static [u8]> {
    Ok(match name {
        GL_VENDOR => b"softgl\0",
        GL_RENDERER => b"softgl software rasterizer\0",
        GL_VERSION => concat!("2.1 softgl ", env!("CARGO_PKG_VERSION"), "\0").as_bytes(),
        GL_SHADING_LANGUAGE_VERSION => b"1.20\0",
        GL_EXTENSIONS => EXTENSIONS.as_bytes(),
        _ => return Err(GlError::InvalidEnum),
    })
}

impl Context {
    /// glGetPointerv: the address a client array, the feedback or the selection buffer
    /// was given.
    pub(crate) fn get_pointer(&self, pname: GLenum) -> GlResult<usize> {
        let a = &self.arrays;
        Ok(match pname {
            GL_VERTEX_ARRAY_POINTER => a.vao.vertex.ptr,
            GL_COLOR_ARRAY_POINTER => a.vao.color.ptr,
            GL_NORMAL_ARRAY_POINTER => a.vao.normal.ptr,
            GL_TEXTURE_COORD_ARRAY_POINTER => a.vao.texcoord[self.state.client_active_texture].ptr,
            GL_FEEDBACK_BUFFER_POINTER => self.feedback.fb_buffer,
            GL_SELECTION_BUFFER_POINTER => self.feedback.sel_buffer,
            GL_EDGE_FLAG_ARRAY_POINTER => a.vao.edge_flag.ptr,
            GL_INDEX_ARRAY_POINTER => a.vao.index.ptr,
            GL_SECONDARY_COLOR_ARRAY_POINTER => a.vao.secondary_color.ptr,
            GL_FOG_COORD_ARRAY_POINTER => a.vao.fog_coord.ptr,
            _ => return Err(GlError::InvalidEnum),
        })
    }
}
