//! The attribute stacks: glPushAttrib/glPopAttrib and glPushClientAttrib/glPopClientAttrib.
//!
//! A push takes a snapshot of the plain state sub-structs (cheap `Clone`s of data, no
//! texel or buffer storage) together with the mask; a pop copies back, group by group, the
//! members of the groups in the mask. Each group is one restore function below listing its
//! members one per line, so a new piece of state joins a group by adding one line there
//! (the snapshot already holds every field of `State` and `LightingState`).
//!
//! Stack depths are Mesa's (`MAX_ATTRIB_STACK_DEPTH`, `MAX_CLIENT_ATTRIB_STACK_DEPTH`: 16).

use super::arrays::ArrayPointer;
use super::error::{GlError, GlResult};
use super::lighting_state::LightingState;
use super::state::{Cap, PixelStore, State, CAPS, MAX_TEXTURE_UNITS};
use super::Context;
use crate::gl::enums::*;
use crate::texture::{SamplerParams, TexUnit};

/// GL_MAX_ATTRIB_STACK_DEPTH (Mesa's value).
pub const MAX_ATTRIB_STACK_DEPTH: usize = 16;
/// GL_MAX_CLIENT_ATTRIB_STACK_DEPTH (Mesa's value).
pub const MAX_CLIENT_ATTRIB_STACK_DEPTH: usize = 16;

/// GL_MULTISAMPLE_BIT (part of GL_ALL_ATTRIB_BITS).
const MULTISAMPLE_BIT: u32 = 0x2000_0000;

/// One glPushAttrib entry.
pub struct AttribFrame {
    /// The groups pushed.
    mask: u32,
    /// Plain state.
    state: Box<State>,
    /// Lights, materials and fog.
    light: Box<LightingState>,
    /// Texture units.
    units: Box<[TexUnit; MAX_TEXTURE_UNITS]>,
    /// Sampler parameters of the texture bound to each unit and target, by name.
    tex_params: Vec<[(u32, SamplerParams); crate::texture::NUM_TARGETS]>,
    /// glListBase.
    list_base: u32,
    /// Line, point, polygon and polygon-stipple state.
    raster: super::raster_state::RasterState,
    /// Texture coordinate generation per unit.
    texgen: Box<super::texgen_state::TexGenState>,
    /// User clip planes and their enables.
    clip_planes: super::texgen_state::ClipPlanes,
    /// The current raster position.
    raster_pos: super::pixel_state::RasterPos,
    /// Pixel zoom.
    pixel_modes: super::pixel_state::PixelModes,
    /// The accumulation clear value.
    accum: super::accum::AccumAttrib,
    /// glMapGrid1 and glMapGrid2.
    grids: (super::eval::Grid, [super::eval::Grid; 2]),
}

/// The vertex-array part of a glPushClientAttrib entry.
#[derive(Clone)]
struct ClientArrays {
    vertex: ArrayPointer,
    color: ArrayPointer,
    normal: ArrayPointer,
    texcoord: [ArrayPointer; MAX_TEXTURE_UNITS],
    edge_flag: ArrayPointer,
    index: ArrayPointer,
    secondary_color: ArrayPointer,
    fog_coord: ArrayPointer,
    array_buffer: u32,
    element_buffer: u32,
    client_active_texture: usize,
}

/// One glPushClientAttrib entry.
pub struct ClientFrame {
    /// The groups pushed.
    mask: u32,
    /// glPixelStore pack and unpack state.
    pixel: (PixelStore, PixelStore),
    /// Vertex arrays.
    arrays: Box<ClientArrays>,
}

/// Both attribute stacks of a context.
#[derive(Default)]
pub struct AttribStacks {
    /// glPushAttrib entries.
    pub server: Vec<AttribFrame>,
    /// glPushClientAttrib entries.
    pub client: Vec<ClientFrame>,
}

/// Copies the enable bits `caps` from the snapshot.
fn caps(c: &mut Context, s: &AttribFrame, caps: &[Cap]) {
    for &cap in caps {
        c.state.caps.set(cap, s.state.caps.get(cap));
    }
}

/// Makes the GL_TEXTURE_1D/2D enable bits mirror the active unit again.
fn sync_texture_caps(c: &mut Context) {
    let u = &c.textures.units[c.state.active_texture];
    let (e1, e2, e3, ec) = (u.enabled_1d, u.enabled_2d, u.enabled_3d, u.enabled_cube);
    c.state.caps.set(Cap::Texture1D, e1);
    c.state.caps.set(Cap::Texture2D, e2);
    c.state.caps.set(Cap::Texture3D, e3);
    c.state.caps.set(Cap::TextureCubeMap, ec);
}

fn current(c: &mut Context, s: &AttribFrame) {
    c.state.current = s.state.current;
    c.raster_pos = s.raster_pos;
}

fn point(c: &mut Context, s: &AttribFrame) {
    caps(c, s, &[Cap::PointSmooth]);
    c.raster.point = s.raster.point;
    // missing: size min/max, fade threshold, distance attenuation (glPointParameter not
    // implemented)
}

fn line(c: &mut Context, s: &AttribFrame) {
    caps(c, s, &[Cap::LineSmooth, Cap::LineStipple]);
    c.raster.line = s.raster.line;
}

fn polygon(c: &mut Context, s: &AttribFrame) {
    caps(
        c,
        s,
        &[
            Cap::CullFace,
            Cap::PolygonSmooth,
            Cap::PolygonStipple,
            Cap::PolygonOffsetFill,
            Cap::PolygonOffsetLine,
            Cap::PolygonOffsetPoint,
        ],
    );
    c.state.cull_face = s.state.cull_face;
    c.state.front_ccw = s.state.front_ccw;
    c.raster.polygon = s.raster.polygon;
}

fn polygon_stipple(c: &mut Context, s: &AttribFrame) {
    c.raster.stipple = s.raster.stipple;
}

fn pixel_mode(c: &mut Context, s: &AttribFrame) {
    c.pixel_modes = s.pixel_modes;
    c.state.legacy.read_buffer = s.state.legacy.read_buffer;
    // pixel maps belong to no group
}

fn lighting(c: &mut Context, s: &AttribFrame) {
    let mut list = vec![Cap::Lighting, Cap::ColorMaterial];
    list.extend((0..8).map(|i| CAPS[Cap::Light0 as usize + i].0));
    caps(c, s, &list);
    c.state.shade_model = s.state.shade_model;
    c.light.lights = s.light.lights;
    c.light.model = s.light.model;
    c.light.material = s.light.material;
    c.light.color_material = s.light.color_material;
}

fn fog(c: &mut Context, s: &AttribFrame) {
    caps(c, s, &[Cap::Fog]);
    c.light.fog = s.light.fog;
}

fn depth_buffer(c: &mut Context, s: &AttribFrame) {
    caps(c, s, &[Cap::DepthTest]);
    c.state.depth_func = s.state.depth_func;
    c.state.clear_depth = s.state.clear_depth;
    c.state.depth_mask = s.state.depth_mask;
}

fn accum_buffer(c: &mut Context, s: &AttribFrame) {
    c.accum.attrib = s.accum;
}

fn stencil_buffer(c: &mut Context, s: &AttribFrame) {
    caps(c, s, &[Cap::StencilTest]);
    c.state.clear_stencil = s.state.clear_stencil;
    c.state.frag.stencil_front = s.state.frag.stencil_front;
    c.state.frag.stencil_back = s.state.frag.stencil_back;
}

fn viewport(c: &mut Context, s: &AttribFrame) {
    c.state.viewport = s.state.viewport;
    c.state.depth_range = s.state.depth_range;
}

fn transform(c: &mut Context, s: &AttribFrame) {
    let mut list = vec![Cap::Normalize, Cap::RescaleNormal];
    list.extend([
        Cap::ClipPlane0,
        Cap::ClipPlane1,
        Cap::ClipPlane2,
        Cap::ClipPlane3,
        Cap::ClipPlane4,
        Cap::ClipPlane5,
        Cap::ClipPlane6,
        Cap::ClipPlane7,
    ]);
    caps(c, s, &list);
    c.state.matrix_mode = s.state.matrix_mode;
    // The plane equations and their enable bits (which mirror the caps above).
    c.clip_planes = s.clip_planes;
    // glClipControl (Mesa's attrib.c restores it with the transform group).
    c.state.clip_control = s.state.clip_control;
}

fn enable(c: &mut Context, s: &AttribFrame) {
    c.state.caps = s.state.caps.clone();
    for (u, saved) in c.textures.units.iter_mut().zip(s.units.iter()) {
        u.enabled_1d = saved.enabled_1d;
        u.enabled_2d = saved.enabled_2d;
        u.enabled_3d = saved.enabled_3d;
        u.enabled_cube = saved.enabled_cube;
    }
    sync_texture_caps(c);
    c.clip_planes.enabled = s.clip_planes.enabled;
    for (u, saved) in c.texgen.units.iter_mut().zip(s.texgen.units.iter()) {
        u.enabled = saved.enabled;
    }
    c.sync_texgen_caps();
}

fn color_buffer(c: &mut Context, s: &AttribFrame) {
    caps(
        c,
        s,
        &[
            Cap::AlphaTest,
            Cap::Blend,
            Cap::Dither,
            Cap::ColorLogicOp,
            Cap::IndexLogicOp,
        ],
    );
    c.state.frag.alpha_func = s.state.frag.alpha_func;
    c.state.frag.alpha_ref = s.state.frag.alpha_ref;
    c.state.frag.blend = s.state.frag.blend;
    c.state.frag.logic_op = s.state.frag.logic_op;
    c.state.color_mask = s.state.color_mask;
    c.state.clear_color = s.state.clear_color;
    c.state.legacy.draw_buffer = s.state.legacy.draw_buffer;
    c.state.legacy.index_mask = s.state.legacy.index_mask;
    c.state.legacy.clear_index = s.state.legacy.clear_index;
}

fn hint(c: &mut Context, s: &AttribFrame) {
    c.state.hints = s.state.hints;
}

fn eval(c: &mut Context, s: &AttribFrame) {
    let maps: Vec<Cap> = CAPS
        .iter()
        .map(|&(cap, _)| cap)
        .filter(|&cap| {
            (Cap::Map1Color4 as usize..=Cap::Map2Vertex4 as usize).contains(&(cap as usize))
        })
        .chain([Cap::AutoNormal])
        .collect();
    caps(c, s, &maps);
    c.eval.grid1 = s.grids.0;
    c.eval.grid2 = s.grids.1;
}

fn list(c: &mut Context, s: &AttribFrame) {
    c.lists.base = s.list_base;
}

fn texture(c: &mut Context, s: &AttribFrame) {
    for (i, saved) in s.units.iter().enumerate() {
        c.textures.units[i] = saved.clone();
        for (t, (name, params)) in s.tex_params[i].iter().enumerate() {
            // A texture deleted since the push stays deleted: its unit binds the default.
            let obj = if *name == 0 {
                Some(&mut c.textures.defaults[t])
            } else {
                c.textures.objects.get_mut(name)
            };
            match obj {
                Some(o) => o.params = *params,
                None => c.textures.units[i].bound[t] = 0,
            }
        }
    }
    c.state.active_texture = s.state.active_texture;
    caps(
        c,
        s,
        &[
            Cap::Texture3D,
            Cap::TextureCubeMap,
            Cap::TexGenS,
            Cap::TexGenT,
            Cap::TexGenR,
            Cap::TexGenQ,
        ],
    );
    sync_texture_caps(c);
    c.texgen = (*s.texgen).clone();
    c.sync_texgen_caps();
}

fn scissor(c: &mut Context, s: &AttribFrame) {
    caps(c, s, &[Cap::ScissorTest]);
    c.state.scissor = s.state.scissor;
}

fn multisample(c: &mut Context, s: &AttribFrame) {
    caps(
        c,
        s,
        &[
            Cap::Multisample,
            Cap::SampleAlphaToCoverage,
            Cap::SampleAlphaToOne,
            Cap::SampleCoverage,
        ],
    );
    c.state.legacy.sample_coverage_value = s.state.legacy.sample_coverage_value;
    c.state.legacy.sample_coverage_invert = s.state.legacy.sample_coverage_invert;
}

/// A group's restore function.
type Restore = fn(&mut Context, &AttribFrame);

/// The groups in the order a pop restores them.
const GROUPS: &[(u32, Restore)] = &[
    (GL_ACCUM_BUFFER_BIT, accum_buffer),
    (GL_COLOR_BUFFER_BIT, color_buffer),
    (GL_CURRENT_BIT, current),
    (GL_DEPTH_BUFFER_BIT, depth_buffer),
    (GL_ENABLE_BIT, enable),
    (GL_EVAL_BIT, eval),
    (GL_FOG_BIT, fog),
    (GL_HINT_BIT, hint),
    (GL_LIGHTING_BIT, lighting),
    (GL_LINE_BIT, line),
    (GL_LIST_BIT, list),
    (GL_PIXEL_MODE_BIT, pixel_mode),
    (GL_POINT_BIT, point),
    (GL_POLYGON_BIT, polygon),
    (GL_POLYGON_STIPPLE_BIT, polygon_stipple),
    (GL_SCISSOR_BIT, scissor),
    (GL_STENCIL_BUFFER_BIT, stencil_buffer),
    (GL_TEXTURE_BIT, texture),
    (GL_TRANSFORM_BIT, transform),
    (GL_VIEWPORT_BIT, viewport),
    (MULTISAMPLE_BIT, multisample),
];

impl Context {
    /// glPushAttrib.
    pub fn push_attrib(&mut self, mask: u32) -> GlResult<()> {
        if self.attrib.server.len() >= MAX_ATTRIB_STACK_DEPTH {
            return Err(GlError::StackOverflow);
        }
        let tx = &self.textures;
        let tex_params = tx
            .units
            .iter()
            .map(|u| {
                std::array::from_fn(|t| {
                    let name = u.bound[t];
                    let obj = if name == 0 {
                        Some(&tx.defaults[t])
                    } else {
                        tx.objects.get(&name)
                    };
                    (name, obj.map(|o| o.params).unwrap_or_default())
                })
            })
            .collect();
        self.attrib.server.push(AttribFrame {
            mask,
            state: Box::new(self.state.clone()),
            light: Box::new(self.light.clone()),
            units: Box::new(tx.units.clone()),
            tex_params,
            list_base: self.lists.base,
            raster: self.raster,
            texgen: Box::new(self.texgen.clone()),
            clip_planes: self.clip_planes,
            raster_pos: self.raster_pos,
            pixel_modes: self.pixel_modes,
            accum: self.accum.attrib,
            grids: (self.eval.grid1, self.eval.grid2),
        });
        Ok(())
    }

    /// glPopAttrib.
    pub fn pop_attrib(&mut self) -> GlResult<()> {
        let Some(frame) = self.attrib.server.pop() else {
            return Err(GlError::StackUnderflow);
        };
        for &(bit, restore) in GROUPS {
            if frame.mask & bit != 0 {
                restore(self, &frame);
            }
        }
        Ok(())
    }

    /// glPushClientAttrib.
    pub fn push_client_attrib(&mut self, mask: u32) -> GlResult<()> {
        if self.attrib.client.len() >= MAX_CLIENT_ATTRIB_STACK_DEPTH {
            return Err(GlError::StackOverflow);
        }
        let a = &self.arrays;
        self.attrib.client.push(ClientFrame {
            mask,
            pixel: (self.state.pack, self.state.unpack),
            arrays: Box::new(ClientArrays {
                vertex: a.vertex,
                color: a.color,
                normal: a.normal,
                texcoord: a.texcoord,
                edge_flag: a.edge_flag,
                index: a.index,
                secondary_color: a.secondary_color,
                fog_coord: a.fog_coord,
                array_buffer: a.array_buffer,
                element_buffer: a.element_buffer,
                client_active_texture: self.state.client_active_texture,
            }),
        });
        Ok(())
    }

    /// glPopClientAttrib.
    pub fn pop_client_attrib(&mut self) -> GlResult<()> {
        let Some(f) = self.attrib.client.pop() else {
            return Err(GlError::StackUnderflow);
        };
        if f.mask & GL_CLIENT_PIXEL_STORE_BIT != 0 {
            (self.state.pack, self.state.unpack) = f.pixel;
        }
        if f.mask & GL_CLIENT_VERTEX_ARRAY_BIT != 0 {
            let s = *f.arrays;
            let a = &mut self.arrays;
            a.vertex = s.vertex;
            a.color = s.color;
            a.normal = s.normal;
            a.texcoord = s.texcoord;
            a.edge_flag = s.edge_flag;
            a.index = s.index;
            a.secondary_color = s.secondary_color;
            a.fog_coord = s.fog_coord;
            // A buffer deleted since the push is not revived.
            let live = |a: &super::arrays::ArrayState, n: u32| n == 0 || a.buffers.contains_key(&n);
            if live(a, s.array_buffer) {
                a.array_buffer = s.array_buffer;
            }
            if live(a, s.element_buffer) {
                a.element_buffer = s.element_buffer;
            }
            self.state.client_active_texture = s.client_active_texture;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::Visual;
    use crate::framebuffer::{ColorFormat, DepthFormat};

    #[test]
    fn pop_restores_only_the_pushed_groups_and_the_stack_is_bounded() {
        let mut c = Context::new(Visual {
            format: ColorFormat::Rgba,
            depth: DepthFormat::None,
            stencil: false,
            accum_bits: 0,
        });
        c.push_attrib(GL_DEPTH_BUFFER_BIT).unwrap();
        c.state.depth_mask = false;
        c.state.clear_color = [1.0; 4];
        c.set_cap(Cap::DepthTest, true).unwrap();
        c.pop_attrib().unwrap();
        assert!(c.state.depth_mask && !c.state.caps.get(Cap::DepthTest));
        assert_eq!(c.state.clear_color, [1.0; 4]);
        assert_eq!(c.pop_attrib(), Err(GlError::StackUnderflow));
        for _ in 0..MAX_ATTRIB_STACK_DEPTH {
            c.push_attrib(GL_ALL_ATTRIB_BITS).unwrap();
        }
        assert_eq!(c.push_attrib(0), Err(GlError::StackOverflow));
    }
}
