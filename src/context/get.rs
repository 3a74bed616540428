//! glGet*: every queryable state value, with the GL type conversions between boolean,
//! integer, float and double queries (GL 1.5 §6.1.2; normalised values such as colours map
//! [-1,1] onto the integer range, as Mesa does).

use super::error::{GlError, GlResult};
use super::legacy_state::{
    GL_DRAW_BUFFER0, GL_DRAW_BUFFER7, GL_MAX_DRAW_BUFFERS, MAX_DRAW_BUFFERS,
};
use super::state::{Cap, MatrixMode, ShadeModel};
use super::{Context, MAX_VIEWPORT};
use crate::context::pack::tex_format::LISTED;
use crate::fixed_function::matrix::Mat4;
use crate::gl::enums::*;
use crate::gl::glext_enums::*;

/// How a state value is typed, which decides the conversions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// Booleans.
    Bool,
    /// Integers or enums.
    Int,
    /// Unsigned integers (stencil masks): glGetIntegerv clamps them to INT_MAX.
    UInt,
    /// Floats (rounded to the nearest integer for glGetIntegerv).
    Float,
    /// Normalised floats (colours, normals, depth values): scaled for glGetIntegerv.
    Normalized,
}

/// A queried value: up to 16 components.
#[derive(Clone, Copy, Debug)]
pub struct Value {
    /// The type of the state.
    pub kind: Kind,
    /// Components.
    pub vals: [f64; 16],
    /// Number of components.
    pub len: usize,
}

impl Value {
    /// A value of f64 components.
    pub fn from_f64(kind: Kind, v: &[f64]) -> Self {
        Value::new(kind, v)
    }
    /// A value of f32 components.
    pub fn from_f32(kind: Kind, v: &[f32]) -> Self {
        let d: Vec<f64> = v.iter().map(|&x| x as f64).collect();
        Value::new(kind, &d)
    }
    fn new(kind: Kind, v: &[f64]) -> Self {
        let mut vals = [0.0; 16];
        vals[..v.len()].copy_from_slice(v);
        Value {
            kind,
            vals,
            len: v.len(),
        }
    }
    /// Components as booleans.
    pub fn as_bools(&self) -> impl Iterator<Item = bool> + '_ {
        self.vals[..self.len].iter().map(|&v| v != 0.0)
    }
    /// Components as glGetIntegerv returns them.
    pub fn as_ints(&self) -> impl Iterator<Item = i32> + '_ {
        self.vals[..self.len].iter().map(move |&v| match self.kind {
            Kind::Bool | Kind::Int => v as i32,
            Kind::UInt => v.min(i32::MAX as f64) as i32,
            Kind::Float => {
                let r = if v >= 0.0 {
                    (v + 0.5).floor()
                } else {
                    (v - 0.5).ceil()
                };
                r.clamp(i32::MIN as f64, i32::MAX as f64) as i32
            }
            Kind::Normalized => (v * 2147483647.0).clamp(i32::MIN as f64, i32::MAX as f64) as i32,
        })
    }
    /// Components as doubles.
    pub fn as_doubles(&self) -> impl Iterator<Item = f64> + '_ {
        self.vals[..self.len].iter().copied()
    }
}

pub(super) fn b(v: bool) -> Value {
    Value::new(Kind::Bool, &[v as u8 as f64])
}
pub(super) fn i(v: &[i64]) -> Value {
    let f: Vec<f64> = v.iter().map(|&x| x as f64).collect();
    Value::new(Kind::Int, &f)
}
fn u(v: u32) -> Value {
    Value::new(Kind::UInt, &[v as f64])
}
pub(super) fn e(v: u32) -> Value {
    Value::new(Kind::Int, &[v as f64])
}
fn f(v: &[f32]) -> Value {
    let d: Vec<f64> = v.iter().map(|&x| x as f64).collect();
    Value::new(Kind::Float, &d)
}
fn n(v: &[f32]) -> Value {
    let d: Vec<f64> = v.iter().map(|&x| x as f64).collect();
    Value::new(Kind::Normalized, &d)
}
fn m(mat: &Mat4) -> Value {
    f(&mat.0)
}

/// The framebuffer-object bindings and limits, and the draw and read buffers of a bound
/// object.
fn framebuffer_get(c: &Context, pname: u32) -> Option<Value> {
    use super::fbo::{MAX_COLOR_ATTACHMENTS, MAX_RENDERBUFFER_SIZE, MAX_SAMPLES};
    let attachment = |b: Option<usize>| e(b.map_or(GL_NONE, |i| GL_COLOR_ATTACHMENT0 + i as u32));
    Some(match pname {
        GL_DRAW_FRAMEBUFFER_BINDING => i(&[c.fbo.draw as i64]),
        GL_READ_FRAMEBUFFER_BINDING => i(&[c.fbo.read as i64]),
        GL_RENDERBUFFER_BINDING => i(&[c.fbo.renderbuffer as i64]),
        GL_MAX_RENDERBUFFER_SIZE => i(&[MAX_RENDERBUFFER_SIZE as i64]),
        GL_MAX_COLOR_ATTACHMENTS => i(&[MAX_COLOR_ATTACHMENTS as i64]),
        GL_MAX_SAMPLES => i(&[MAX_SAMPLES as i64]),
        GL_FRAMEBUFFER_SRGB_CAPABLE_EXT => i(&[c.fbo.srgb_capable(c.fbo.draw, &c.textures) as i64]),
        GL_MAX_DRAW_BUFFERS => i(&[MAX_DRAW_BUFFERS as i64]),
        GL_DRAW_BUFFER0..=GL_DRAW_BUFFER7 => {
            e(c.draw_buffer_query((pname - GL_DRAW_BUFFER0) as usize)?)
        }
        GL_DRAW_BUFFER => attachment(c.fbo.object(c.fbo.draw)?.draw_buffer),
        GL_READ_BUFFER => attachment(c.fbo.object(c.fbo.read)?.read_buffer),
        _ => return None,
    })
}

/// The side (pack or unpack, front or back) whose list of names holds `pname`, and its
/// position in that list.
fn pick_side<T, const N: usize>(pname: u32, sides: [(&T, [u32; N]); 2]) -> Option<(&T, usize)> {
    sides
        .into_iter()
        .find_map(|(side, names)| Some((side, names.iter().position(|&n| n == pname)?)))
}

/// The stencil state of the front and back faces (references clamped to `stencil_max`).
fn stencil_get(c: &Context, pname: u32, stencil_max: i32) -> Option<Value> {
    let front = [
        GL_STENCIL_FUNC,
        GL_STENCIL_REF,
        GL_STENCIL_VALUE_MASK,
        GL_STENCIL_WRITEMASK,
        GL_STENCIL_FAIL,
        GL_STENCIL_PASS_DEPTH_FAIL,
        GL_STENCIL_PASS_DEPTH_PASS,
    ];
    let back = [
        GL_STENCIL_BACK_FUNC,
        GL_STENCIL_BACK_REF,
        GL_STENCIL_BACK_VALUE_MASK,
        GL_STENCIL_BACK_WRITEMASK,
        GL_STENCIL_BACK_FAIL,
        GL_STENCIL_BACK_PASS_DEPTH_FAIL,
        GL_STENCIL_BACK_PASS_DEPTH_PASS,
    ];
    let f = &c.state.frag;
    let (s, k) = pick_side(pname, [(&f.stencil_front, front), (&f.stencil_back, back)])?;
    Some(match k {
        0 => e(s.func.to_gl()),
        1 => i(&[s.reference.clamp(0, stencil_max) as i64]),
        2 => u(s.value_mask),
        3 => u(s.writemask),
        4 => e(s.fail.to_gl()),
        5 => e(s.zfail.to_gl()),
        _ => e(s.zpass.to_gl()),
    })
}

/// The glPixelStore values: GL_PACK_* and GL_UNPACK_*.
fn pixel_store_get(c: &Context, pname: u32) -> Option<Value> {
    let pack = [
        GL_PACK_SWAP_BYTES,
        GL_PACK_LSB_FIRST,
        GL_PACK_ROW_LENGTH,
        GL_PACK_SKIP_ROWS,
        GL_PACK_SKIP_PIXELS,
        GL_PACK_ALIGNMENT,
        GL_PACK_IMAGE_HEIGHT,
        GL_PACK_SKIP_IMAGES,
    ];
    let unpack = [
        GL_UNPACK_SWAP_BYTES,
        GL_UNPACK_LSB_FIRST,
        GL_UNPACK_ROW_LENGTH,
        GL_UNPACK_SKIP_ROWS,
        GL_UNPACK_SKIP_PIXELS,
        GL_UNPACK_ALIGNMENT,
        GL_UNPACK_IMAGE_HEIGHT,
        GL_UNPACK_SKIP_IMAGES,
    ];
    let (ps, k) = pick_side(pname, [(&c.state.pack, pack), (&c.state.unpack, unpack)])?;
    let ints = [
        ps.row_length,
        ps.skip_rows,
        ps.skip_pixels,
        ps.alignment,
        ps.image_height,
        ps.skip_images,
    ];
    Some(match k {
        0 => b(ps.swap_bytes),
        1 => b(ps.lsb_first),
        _ => i(&[ints[k - 2] as i64]),
    })
}

/// Whether `pname`'s value is read from the draw framebuffer's working copy (an object's
/// buffer bits, the clear colour's clamp, the stencil values' range), which a draw left
/// on the pool holds: glGet waits for that draw first for these, and only these.
pub fn reads_framebuffer(c: &Context, pname: u32) -> bool {
    matches!(
        pname,
        GL_RED_BITS
            | GL_GREEN_BITS
            | GL_BLUE_BITS
            | GL_ALPHA_BITS
            | GL_DEPTH_BITS
            | GL_STENCIL_BITS
            | GL_COLOR_CLEAR_VALUE
    ) || stencil_get(c, pname, 0).is_some()
}

/// The value of `pname`, or GL_INVALID_ENUM.
pub fn get(c: &Context, pname: u32) -> GlResult<Value> {
    let st = &c.state;
    let mx = &c.matrices;
    let (bits, depth_bits, stencil_bits) = c.draw_bits();
    let depth_bits = depth_bits as i64;
    let stencil_max = (1i32 << stencil_bits) - 1;
    let a = &c.arrays;
    let tc = &a.vao.texcoord[st.client_active_texture];
    if let Some(v) = raster_get(c, pname) {
        return Ok(v);
    }
    if let Some(v) = framebuffer_get(c, pname) {
        return Ok(v);
    }
    if let Some(v) = pixel_store_get(c, pname) {
        return Ok(v);
    }
    if let Some(v) = stencil_get(c, pname, stencil_max) {
        return Ok(v);
    }
    if let Some(v) = super::get_shader::shader_get(c, pname) {
        return Ok(v);
    }
    Ok(match pname {
        GL_VIEWPORT => i(&st.viewport.map(|v| v as i64)),
        GL_SCISSOR_BOX => i(&st.scissor.map(|v| v as i64)),
        GL_DEPTH_RANGE => Value::new(Kind::Normalized, &st.depth_range),
        GL_MODELVIEW_MATRIX => m(mx.modelview.top()),
        GL_PROJECTION_MATRIX => m(mx.projection.top()),
        GL_TEXTURE_MATRIX => m(mx.texture[st.active_texture].top()),
        GL_COLOR_MATRIX => m(mx.color.top()),
        GL_TRANSPOSE_MODELVIEW_MATRIX => m(&mx.modelview.top().transpose()),
        GL_TRANSPOSE_PROJECTION_MATRIX => m(&mx.projection.top().transpose()),
        GL_TRANSPOSE_TEXTURE_MATRIX => m(&mx.texture[st.active_texture].top().transpose()),
        GL_TRANSPOSE_COLOR_MATRIX => m(&mx.color.top().transpose()),
        GL_MATRIX_MODE => e(match st.matrix_mode {
            MatrixMode::ModelView => GL_MODELVIEW,
            MatrixMode::Projection => GL_PROJECTION,
            MatrixMode::Texture => GL_TEXTURE,
            MatrixMode::Color => GL_COLOR,
        }),
        GL_MODELVIEW_STACK_DEPTH => i(&[mx.modelview.depth() as i64]),
        GL_PROJECTION_STACK_DEPTH => i(&[mx.projection.depth() as i64]),
        GL_TEXTURE_STACK_DEPTH => i(&[mx.texture[st.active_texture].depth() as i64]),
        GL_COLOR_MATRIX_STACK_DEPTH => i(&[mx.color.depth() as i64]),
        GL_MAX_MODELVIEW_STACK_DEPTH => i(&[mx.modelview.max_depth() as i64]),
        GL_MAX_PROJECTION_STACK_DEPTH => i(&[mx.projection.max_depth() as i64]),
        GL_MAX_TEXTURE_STACK_DEPTH => i(&[mx.texture[0].max_depth() as i64]),
        GL_MAX_COLOR_MATRIX_STACK_DEPTH => i(&[mx.color.max_depth() as i64]),
        GL_MAX_VIEWPORT_DIMS => i(&[MAX_VIEWPORT as i64, MAX_VIEWPORT as i64]),
        GL_MAX_TEXTURE_SIZE => i(&[16384]),
        GL_MAX_3D_TEXTURE_SIZE => i(&[crate::texture::MAX_3D_TEXTURE_SIZE as i64]),
        GL_MAX_CUBE_MAP_TEXTURE_SIZE => i(&[crate::texture::MAX_CUBE_MAP_TEXTURE_SIZE as i64]),
        GL_MAX_LIGHTS => i(&[8]),
        GL_MAX_CLIP_PLANES => i(&[8]),
        GL_MAX_TEXTURE_UNITS => i(&[super::state::MAX_TEXTURE_UNITS as i64]),
        GL_MAX_ATTRIB_STACK_DEPTH | GL_MAX_CLIENT_ATTRIB_STACK_DEPTH => i(&[16]),
        GL_MAX_NAME_STACK_DEPTH => i(&[64]),
        GL_MAX_LIST_NESTING => i(&[super::dlist::MAX_LIST_NESTING as i64]),
        GL_LIST_BASE => i(&[c.lists.base as i64]),
        GL_LIST_INDEX => i(&[c.lists.compiling.as_ref().map_or(0, |k| k.name as i64)]),
        GL_LIST_MODE => e(match c.lists.compile_mode() {
            None => 0,
            Some(false) => GL_COMPILE,
            Some(true) => GL_COMPILE_AND_EXECUTE,
        }),
        GL_ATTRIB_STACK_DEPTH => i(&[c.attrib.server.len() as i64]),
        GL_CLIENT_ATTRIB_STACK_DEPTH => i(&[c.attrib.client.len() as i64]),
        GL_MAX_EVAL_ORDER => i(&[30]),
        GL_SUBPIXEL_BITS => i(&[8]),
        GL_DEPTH_FUNC => e(st.depth_func.to_gl()),
        GL_DEPTH_WRITEMASK => b(st.depth_mask),
        GL_COLOR_WRITEMASK => Value::new(Kind::Bool, &st.color_mask.map(|v| v as u8 as f64)),

        GL_CULL_FACE_MODE => e(st.cull_face.to_gl()),
        GL_BLEND_SRC | GL_BLEND_SRC_RGB => e(st.frag.blend.src_rgb.to_gl()),
        GL_BLEND_DST | GL_BLEND_DST_RGB => e(st.frag.blend.dst_rgb.to_gl()),
        GL_BLEND_SRC_ALPHA => e(st.frag.blend.src_a.to_gl()),
        GL_BLEND_DST_ALPHA => e(st.frag.blend.dst_a.to_gl()),
        GL_BLEND_EQUATION => e(st.frag.blend.eq_rgb.to_gl()),
        GL_BLEND_EQUATION_ALPHA => e(st.frag.blend.eq_a.to_gl()),
        GL_BLEND_COLOR => n(&st.frag.blend.color),
        GL_ALPHA_TEST_FUNC => e(st.frag.alpha_func.to_gl()),
        GL_ALPHA_TEST_REF => n(&[st.frag.alpha_ref.clamp(0.0, 1.0)]),
        GL_LOGIC_OP_MODE => e(st.frag.logic_op.to_gl()),
        GL_FRONT_FACE => e(if st.front_ccw { GL_CCW } else { GL_CW }),
        GL_CLIP_ORIGIN => e(if st.clip_control.upper_left {
            GL_UPPER_LEFT
        } else {
            GL_LOWER_LEFT
        }),
        GL_CLIP_DEPTH_MODE => e(if st.clip_control.zero_to_one {
            GL_ZERO_TO_ONE
        } else {
            GL_NEGATIVE_ONE_TO_ONE
        }),
        GL_SHADE_MODEL => e(if st.shade_model == ShadeModel::Flat {
            GL_FLAT
        } else {
            GL_SMOOTH
        }),
        GL_COLOR_CLEAR_VALUE => n(&c.clear_color_query()),
        GL_DEPTH_CLEAR_VALUE => Value::new(Kind::Normalized, &[st.clear_depth]),
        GL_STENCIL_CLEAR_VALUE => i(&[st.clear_stencil as i64]),
        GL_CURRENT_COLOR => n(&st.current.color),
        GL_CURRENT_SECONDARY_COLOR => n(&st.current.secondary_color),
        GL_CURRENT_NORMAL => n(&st.current.normal),
        GL_CURRENT_TEXTURE_COORDS => f(&st.current.texcoord[st.active_texture]),
        GL_CURRENT_FOG_COORD => f(&[st.current.fog_coord]),
        GL_EDGE_FLAG => b(st.current.edge_flag),
        GL_RED_BITS => i(&[bits[0] as i64]),
        GL_GREEN_BITS => i(&[bits[1] as i64]),
        GL_BLUE_BITS => i(&[bits[2] as i64]),
        GL_ALPHA_BITS => i(&[bits[3] as i64]),
        GL_DEPTH_BITS => i(&[depth_bits]),
        GL_STENCIL_BITS => i(&[stencil_bits as i64]),
        GL_ACCUM_RED_BITS | GL_ACCUM_GREEN_BITS | GL_ACCUM_BLUE_BITS | GL_ACCUM_ALPHA_BITS => {
            i(&[if c.has_accum() { 16 } else { 0 }])
        }
        GL_ACCUM_CLEAR_VALUE => n(&c.accum.attrib.clear_color),
        GL_INDEX_BITS => i(&[0]),
        GL_RGBA_MODE => b(true),
        GL_INDEX_MODE | GL_DOUBLEBUFFER | GL_STEREO => b(false),
        GL_AUX_BUFFERS => i(&[0]),
        GL_DRAW_BUFFER => e(st.legacy.draw_buffer.to_gl()),
        GL_READ_BUFFER => e(st.legacy.read_buffer.to_gl()),
        GL_CURRENT_INDEX => f(&[st.current.index]),
        GL_INDEX_WRITEMASK => i(&[st.legacy.index_mask as i32 as i64]),
        GL_INDEX_CLEAR_VALUE => i(&[st.legacy.clear_index as i32 as i64]),
        GL_SAMPLE_COVERAGE_VALUE => f(&[st.legacy.sample_coverage_value]),
        GL_SAMPLE_COVERAGE_INVERT => b(st.legacy.sample_coverage_invert),
        GL_SAMPLE_BUFFERS => i(&[(c.draw_samples() > 0) as i64]),
        GL_SAMPLES => i(&[c.draw_samples() as i64]),
        // The S3TC formats of Mesa's list (see `context::pack::tex_format::LISTED`).
        GL_NUM_COMPRESSED_TEXTURE_FORMATS => i(&[LISTED.len() as i64]),
        GL_COMPRESSED_TEXTURE_FORMATS => i(&LISTED.map(|f| f as i64)),
        GL_MAP1_GRID_DOMAIN => f(&c.eval.grid1.d),
        GL_MAP1_GRID_SEGMENTS => i(&[c.eval.grid1.n as i64]),
        GL_MAP2_GRID_DOMAIN => {
            let [u, v] = c.eval.grid2;
            f(&[u.d[0], u.d[1], v.d[0], v.d[1]])
        }
        GL_MAP2_GRID_SEGMENTS => i(&[c.eval.grid2[0].n as i64, c.eval.grid2[1].n as i64]),
        GL_INDEX_ARRAY => b(a.vao.index.enabled),
        GL_INDEX_ARRAY_TYPE => e(a.vao.index.ty.to_gl()),
        GL_INDEX_ARRAY_STRIDE => i(&[a.vao.index.stride as i64]),
        GL_INDEX_ARRAY_BUFFER_BINDING => i(&[a.vao.index.buffer as i64]),
        GL_PERSPECTIVE_CORRECTION_HINT => e(st.hints.perspective_correction),
        GL_POINT_SMOOTH_HINT => e(st.hints.point_smooth),
        GL_LINE_SMOOTH_HINT => e(st.hints.line_smooth),
        GL_POLYGON_SMOOTH_HINT => e(st.hints.polygon_smooth),
        GL_FOG_HINT => e(st.hints.fog),
        GL_GENERATE_MIPMAP_HINT => e(st.hints.generate_mipmap),
        GL_TEXTURE_COMPRESSION_HINT => e(st.hints.texture_compression),
        GL_ACTIVE_TEXTURE => e(GL_TEXTURE0 + st.active_texture as u32),
        GL_CLIENT_ACTIVE_TEXTURE => e(GL_TEXTURE0 + st.client_active_texture as u32),
        GL_VERTEX_ARRAY => b(a.vao.vertex.enabled),
        GL_VERTEX_ARRAY_SIZE => i(&[a.vao.vertex.size as i64]),
        GL_VERTEX_ARRAY_TYPE => e(a.vao.vertex.ty.to_gl()),
        GL_VERTEX_ARRAY_STRIDE => i(&[a.vao.vertex.stride as i64]),
        GL_COLOR_ARRAY => b(a.vao.color.enabled),
        GL_COLOR_ARRAY_SIZE => i(&[a.vao.color.size as i64]),
        GL_COLOR_ARRAY_TYPE => e(a.vao.color.ty.to_gl()),
        GL_COLOR_ARRAY_STRIDE => i(&[a.vao.color.stride as i64]),
        GL_NORMAL_ARRAY => b(a.vao.normal.enabled),
        GL_NORMAL_ARRAY_TYPE => e(a.vao.normal.ty.to_gl()),
        GL_NORMAL_ARRAY_STRIDE => i(&[a.vao.normal.stride as i64]),
        GL_TEXTURE_COORD_ARRAY => b(tc.enabled),
        GL_TEXTURE_COORD_ARRAY_SIZE => i(&[tc.size as i64]),
        GL_TEXTURE_COORD_ARRAY_TYPE => e(tc.ty.to_gl()),
        GL_TEXTURE_COORD_ARRAY_STRIDE => i(&[tc.stride as i64]),
        GL_EDGE_FLAG_ARRAY => b(a.vao.edge_flag.enabled),
        GL_EDGE_FLAG_ARRAY_STRIDE => i(&[a.vao.edge_flag.stride as i64]),
        GL_EDGE_FLAG_ARRAY_BUFFER_BINDING => i(&[a.vao.edge_flag.buffer as i64]),
        GL_SECONDARY_COLOR_ARRAY => b(a.vao.secondary_color.enabled),
        GL_SECONDARY_COLOR_ARRAY_SIZE => i(&[a.vao.secondary_color.size as i64]),
        GL_SECONDARY_COLOR_ARRAY_TYPE => e(a.vao.secondary_color.ty.to_gl()),
        GL_SECONDARY_COLOR_ARRAY_STRIDE => i(&[a.vao.secondary_color.stride as i64]),
        GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING => i(&[a.vao.secondary_color.buffer as i64]),
        GL_FOG_COORD_ARRAY => b(a.vao.fog_coord.enabled),
        GL_FOG_COORD_ARRAY_TYPE => e(a.vao.fog_coord.ty.to_gl()),
        GL_FOG_COORD_ARRAY_STRIDE => i(&[a.vao.fog_coord.stride as i64]),
        GL_FOG_COORD_ARRAY_BUFFER_BINDING => i(&[a.vao.fog_coord.buffer as i64]),
        GL_ARRAY_BUFFER_BINDING => i(&[a.array_buffer as i64]),
        GL_ELEMENT_ARRAY_BUFFER_BINDING => i(&[a.vao.element_buffer as i64]),
        GL_VERTEX_ARRAY_BINDING => i(&[a.vao_binding as i64]),
        GL_PRIMITIVE_RESTART => b(a.primitive_restart),
        // Mesa answers the index as a GLint (0xFFFFFFFF reads back as -1).
        GL_PRIMITIVE_RESTART_INDEX => i(&[a.restart_index as i32 as i64]),
        GL_PIXEL_PACK_BUFFER_BINDING => i(&[st.pack.buffer as i64]),
        GL_PIXEL_UNPACK_BUFFER_BINDING => i(&[st.unpack.buffer as i64]),
        GL_VERTEX_ARRAY_BUFFER_BINDING => i(&[a.vao.vertex.buffer as i64]),
        GL_COLOR_ARRAY_BUFFER_BINDING => i(&[a.vao.color.buffer as i64]),
        GL_NORMAL_ARRAY_BUFFER_BINDING => i(&[a.vao.normal.buffer as i64]),
        GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING => i(&[tc.buffer as i64]),
        // texturing (per active unit)
        GL_TEXTURE_BINDING_3D => i(&[c.textures.units[st.active_texture].bound[2] as i64]),
        GL_TEXTURE_BINDING_CUBE_MAP => i(&[c.textures.units[st.active_texture].bound[3] as i64]),
        GL_TEXTURE_BINDING_1D => i(&[c.textures.units[st.active_texture].bound[0] as i64]),
        GL_TEXTURE_BINDING_2D => i(&[c.textures.units[st.active_texture].bound[1] as i64]),
        GL_TEXTURE_3D => b(c.textures.units[st.active_texture].enabled_3d),
        GL_TEXTURE_CUBE_MAP => b(c.textures.units[st.active_texture].enabled_cube),
        GL_TEXTURE_1D => b(c.textures.units[st.active_texture].enabled_1d),
        GL_TEXTURE_2D => b(c.textures.units[st.active_texture].enabled_2d),
        GL_TEXTURE_CUBE_MAP_SEAMLESS => b(c.textures.cube_seamless),
        GL_MAX_TEXTURE_LOD_BIAS => f(&[crate::texture::MAX_LOD_BIAS]),
        GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT => f(&[crate::texture::MAX_ANISOTROPY]),
        GL_LIGHT_MODEL_AMBIENT => n(&c.light.model.ambient),
        GL_LIGHT_MODEL_LOCAL_VIEWER => b(c.light.model.local_viewer),
        GL_LIGHT_MODEL_TWO_SIDE => b(c.light.model.two_side),
        GL_LIGHT_MODEL_COLOR_CONTROL => e(if c.light.model.separate_specular {
            GL_SEPARATE_SPECULAR_COLOR
        } else {
            GL_SINGLE_COLOR
        }),
        GL_COLOR_MATERIAL_FACE => e(c.light.color_material.face.to_gl()),
        GL_COLOR_MATERIAL_PARAMETER => e(c.light.color_material.mode.to_gl()),
        GL_FOG_MODE => e(c.light.fog.mode.to_gl()),
        GL_FOG_DENSITY => f(&[c.light.fog.density]),
        GL_FOG_START => f(&[c.light.fog.start]),
        GL_FOG_END => f(&[c.light.fog.end]),
        GL_FOG_INDEX => f(&[c.light.fog.index]),
        GL_FOG_COLOR => n(&c.light.fog.color),
        GL_FOG_COORD_SRC => e(if c.light.fog.coord_from_attrib {
            GL_FOG_COORD
        } else {
            GL_FRAGMENT_DEPTH
        }),
        _ => {
            let unit = st.active_texture;
            if let Some(v) = super::pixel_state::get(&c.raster_pos, &c.pixel_modes, unit, pname) {
                return v;
            }
            if let Some(v) = c.pixel_maps.get(pname) {
                return Ok(v);
            }
            if let Some(v) = c.feedback.get(pname) {
                return Ok(v);
            }
            match Cap::from_gl(pname) {
                Ok(cap) => b(st.caps.get(cap)),
                Err(_) => return Err(GlError::InvalidEnum),
            }
        }
    })
}

/// The line, point and polygon rasterization values (Mesa's numbers for llvmpipe).
fn raster_get(c: &Context, pname: u32) -> Option<Value> {
    use super::raster_state::{MAX_LINE_WIDTH, MAX_POINT_SIZE, SIZE_GRANULARITY};
    let r = &c.raster;
    Some(match pname {
        GL_LINE_WIDTH => f(&[r.line.width]),
        GL_LINE_WIDTH_RANGE | GL_ALIASED_LINE_WIDTH_RANGE => f(&[1.0, MAX_LINE_WIDTH]),
        GL_LINE_WIDTH_GRANULARITY => f(&[SIZE_GRANULARITY]),
        GL_POINT_SIZE => f(&[r.point.size]),
        GL_POINT_SIZE_MIN => f(&[r.point.min_size]),
        GL_POINT_SIZE_MAX => f(&[r.point.max_size]),
        GL_POINT_FADE_THRESHOLD_SIZE => f(&[r.point.fade_threshold]),
        GL_POINT_DISTANCE_ATTENUATION => f(&r.point.attenuation),
        super::point_sprite::GL_POINT_SPRITE_COORD_ORIGIN => e(if r.point.sprite_upper_left {
            crate::gl::glext_enums::GL_UPPER_LEFT
        } else {
            crate::gl::glext_enums::GL_LOWER_LEFT
        }),
        GL_POINT_SIZE_RANGE | GL_ALIASED_POINT_SIZE_RANGE => f(&[1.0, MAX_POINT_SIZE]),
        GL_POINT_SIZE_GRANULARITY => f(&[SIZE_GRANULARITY]),
        GL_LINE_STIPPLE_PATTERN => i(&[r.line.stipple_pattern as i64]),
        GL_LINE_STIPPLE_REPEAT => i(&[r.line.stipple_repeat as i64]),
        GL_POLYGON_MODE => i(&[
            r.polygon.mode_front.to_gl() as i64,
            r.polygon.mode_back.to_gl() as i64,
        ]),
        GL_POLYGON_OFFSET_FACTOR => f(&[r.polygon.offset_factor]),
        GL_POLYGON_OFFSET_UNITS => f(&[r.polygon.offset_units]),
        _ => return None,
    })
}
