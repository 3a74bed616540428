//! The attribute stacks: glPushAttrib/glPopAttrib and glPushClientAttrib/glPopClientAttrib.
//!
//! A push takes a snapshot of the plain state sub-structs (cheap `Clone`s of data, no
//! texel or buffer storage) together with the mask; a pop copies back, group by group, the
//! members of the groups in the mask. Each group is one entry of `GROUPS` listing its
//! members one per line, so a new piece of state joins a group by adding one line there
//! (the snapshot already holds every field of `State` and `LightingState`); which group
//! restores each enable bit is `cap_group`.
//!
//! Stack depths are Mesa's (`MAX_ATTRIB_STACK_DEPTH`, `MAX_CLIENT_ATTRIB_STACK_DEPTH`: 16).

use super::arrays::ArrayState;
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
struct ClientArrays {
    /// Every array pointer and buffer binding, without the buffer objects
    /// ([`ArrayState::bindings`]).
    arrays: ArrayState,
    /// glClientActiveTexture.
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

/// The group whose pop restores the enable bit `cap` besides GL_ENABLE_BIT (which restores
/// them all), or 0 for none: GL_TEXTURE_1D/2D follow the units' enables instead
/// ([`sync_texture_caps`]), and GL_COLOR_SUM belongs to no group here.
fn cap_group(cap: Cap) -> u32 {
    use Cap::*;
    let within = |first: Cap, last: Cap| (first as usize..=last as usize).contains(&(cap as usize));
    match cap {
        AlphaTest | Blend | Dither | ColorLogicOp | IndexLogicOp => GL_COLOR_BUFFER_BIT,
        // Mesa saves GL_FRAMEBUFFER_SRGB with the colour-buffer group too (measured)
        FramebufferSrgb => GL_COLOR_BUFFER_BIT,
        _ if within(Map1Color4, Map2Vertex4) => GL_EVAL_BIT,
        AutoNormal => GL_EVAL_BIT,
        Lighting | ColorMaterial => GL_LIGHTING_BIT,
        _ if within(Light0, Light7) => GL_LIGHTING_BIT,
        Normalize | RescaleNormal => GL_TRANSFORM_BIT,
        _ if within(ClipPlane0, ClipPlane7) => GL_TRANSFORM_BIT,
        CullFace | PolygonSmooth | PolygonStipple => GL_POLYGON_BIT,
        PolygonOffsetFill | PolygonOffsetLine | PolygonOffsetPoint => GL_POLYGON_BIT,
        Multisample | SampleAlphaToCoverage | SampleAlphaToOne | SampleCoverage => MULTISAMPLE_BIT,
        Texture3D | TextureCubeMap | TexGenS | TexGenT | TexGenR | TexGenQ => GL_TEXTURE_BIT,
        LineSmooth | LineStipple => GL_LINE_BIT,
        // Mesa keeps GL_POINT_SPRITE in its point group (`ctx->Point.PointSprite`).
        PointSmooth | PointSprite => GL_POINT_BIT,
        DepthTest => GL_DEPTH_BUFFER_BIT,
        StencilTest => GL_STENCIL_BUFFER_BIT,
        ScissorTest => GL_SCISSOR_BIT,
        Fog => GL_FOG_BIT,
        _ => 0,
    }
}

/// Copies from the snapshot the enable bits that group `bit` restores.
fn caps(c: &mut Context, s: &AttribFrame, bit: u32) {
    for &(cap, _) in CAPS.iter().filter(|&&(cap, _)| cap_group(cap) == bit) {
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
    sync_texture_caps(c);
    c.texgen = (*s.texgen).clone();
    c.sync_texgen_caps();
}

/// A group's restore function (after its enable bits).
type Restore = fn(&mut Context, &AttribFrame);

/// The groups in the order a pop restores them: each first gets back its enable bits
/// ([`cap_group`]), then what it copies back, one member a line.
const GROUPS: &[(u32, Restore)] = &[
    (GL_ACCUM_BUFFER_BIT, |c, s| c.accum.attrib = s.accum),
    (GL_COLOR_BUFFER_BIT, |c, s| {
        c.state.frag.alpha_func = s.state.frag.alpha_func;
        c.state.frag.alpha_ref = s.state.frag.alpha_ref;
        c.state.frag.blend = s.state.frag.blend;
        c.state.frag.logic_op = s.state.frag.logic_op;
        c.state.color_mask = s.state.color_mask;
        c.state.clear_color = s.state.clear_color;
        c.state.legacy.draw_buffer = s.state.legacy.draw_buffer;
        c.state.legacy.more_draw = s.state.legacy.more_draw;
        c.state.legacy.index_mask = s.state.legacy.index_mask;
        c.state.legacy.clear_index = s.state.legacy.clear_index;
    }),
    (GL_CURRENT_BIT, |c, s| {
        c.state.current = s.state.current;
        c.raster_pos = s.raster_pos;
    }),
    (GL_DEPTH_BUFFER_BIT, |c, s| {
        c.state.depth_func = s.state.depth_func;
        c.state.clear_depth = s.state.clear_depth;
        c.state.depth_mask = s.state.depth_mask;
    }),
    (GL_ENABLE_BIT, enable),
    (GL_EVAL_BIT, |c, s| (c.eval.grid1, c.eval.grid2) = s.grids),
    (GL_FOG_BIT, |c, s| c.light.fog = s.light.fog),
    // Mesa 22.3's glPopAttrib leaves GL 2.0's derivative hint as it is (scene
    // gl21_context); the spec's GL_HINT_BIT holds every hint.
    (GL_HINT_BIT, |c, s| {
        let derivative = c.state.hints.fragment_shader_derivative;
        c.state.hints = s.state.hints;
        c.state.hints.fragment_shader_derivative = derivative;
    }),
    (GL_LIGHTING_BIT, |c, s| {
        c.state.shade_model = s.state.shade_model;
        c.light.lights = s.light.lights;
        c.light.model = s.light.model;
        c.light.material = s.light.material;
        c.light.color_material = s.light.color_material;
    }),
    (GL_LINE_BIT, |c, s| c.raster.line = s.raster.line),
    (GL_LIST_BIT, |c, s| c.lists.base = s.list_base),
    (GL_PIXEL_MODE_BIT, |c, s| {
        c.pixel_modes = s.pixel_modes;
        c.state.legacy.read_buffer = s.state.legacy.read_buffer;
        // pixel maps belong to no group
    }),
    // missing: size min/max, fade threshold, distance attenuation (glPointParameter not
    // implemented)
    (GL_POINT_BIT, |c, s| c.raster.point = s.raster.point),
    (GL_POLYGON_BIT, |c, s| {
        c.state.cull_face = s.state.cull_face;
        c.state.front_ccw = s.state.front_ccw;
        c.raster.polygon = s.raster.polygon;
    }),
    (GL_POLYGON_STIPPLE_BIT, |c, s| {
        c.raster.stipple = s.raster.stipple
    }),
    (GL_SCISSOR_BIT, |c, s| c.state.scissor = s.state.scissor),
    (GL_STENCIL_BUFFER_BIT, |c, s| {
        c.state.clear_stencil = s.state.clear_stencil;
        c.state.frag.stencil_front = s.state.frag.stencil_front;
        c.state.frag.stencil_back = s.state.frag.stencil_back;
    }),
    (GL_TEXTURE_BIT, texture),
    (GL_TRANSFORM_BIT, |c, s| {
        c.state.matrix_mode = s.state.matrix_mode;
        // The plane equations and their enable bits (which mirror the caps).
        c.clip_planes = s.clip_planes;
        // glClipControl (Mesa's attrib.c restores it with the transform group).
        c.state.clip_control = s.state.clip_control;
    }),
    (GL_VIEWPORT_BIT, |c, s| {
        c.state.viewport = s.state.viewport;
        c.state.depth_range = s.state.depth_range;
    }),
    (MULTISAMPLE_BIT, |c, s| {
        c.state.legacy.sample_coverage_value = s.state.legacy.sample_coverage_value;
        c.state.legacy.sample_coverage_invert = s.state.legacy.sample_coverage_invert;
    }),
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
                caps(self, &frame, bit);
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
        self.attrib.client.push(ClientFrame {
            mask,
            pixel: (self.state.pack, self.state.unpack),
            arrays: Box::new(ClientArrays {
                arrays: self.arrays.bindings(),
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
            let (mut pack, mut unpack) = f.pixel;
            // As for the array buffers below: a buffer deleted since the push is not revived.
            for (saved, now) in [
                (&mut pack, self.state.pack),
                (&mut unpack, self.state.unpack),
            ] {
                if saved.buffer != 0 && !self.arrays.buffers.contains_key(&saved.buffer) {
                    saved.buffer = now.buffer;
                }
            }
            (self.state.pack, self.state.unpack) = (pack, unpack);
        }
        if f.mask & GL_CLIENT_VERTEX_ARRAY_BIT != 0 {
            let ClientArrays {
                arrays: mut saved,
                client_active_texture,
            } = *f.arrays;
            let a = &mut self.arrays;
            // A buffer deleted since the push is not revived: the binding stays as it is.
            for (name, now) in [
                (&mut saved.array_buffer, a.array_buffer),
                (&mut saved.vao.element_buffer, a.vao.element_buffer),
            ] {
                if *name != 0 && !a.buffers.contains_key(&*name) {
                    *name = now;
                }
            }
            a.array_buffer = saved.array_buffer;
            // The saved vertex array object is bound again with its saved state, unless it
            // was deleted since the push (then the binding and the objects stay as they
            // are).
            if a.vao_exists(saved.vao_binding) {
                a.bind_vertex_array(saved.vao_binding)?;
                a.vao = saved.vao;
            }
            self.state.client_active_texture = client_active_texture;
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
