//! Texture parameters and environments (GL 1.5 §3.8.4, §3.8.13): glTexParameter,
//! glGetTexParameter, glGetTexLevelParameter, glTexEnv and glGetTexEnv, validated and
//! applied to the bound texture object or the active texture unit; and the texture
//! objects and units themselves (glGenTextures, glBindTexture, glActiveTexture …).

use super::fbo::Attachment;
use super::state::{token_index, Cap, MAX_TEXTURE_UNITS};
use super::texture_spec::{bind_target, check_level, image_target};
use super::{Context, GlError, GlResult};
use crate::context::pack::depth as shadow;
use crate::gl::enums::*;
use crate::gl::glext_enums::*;
use crate::gl::types::*;
use crate::texture::env::{CombineFn, EnvMode, Operand, Source};
use crate::texture::shadow::{CompareFunc, DepthMode, ShadowParams};
use crate::texture::{BaseFormat, Filter, MipFilter, Target, Wrap, MAX_ANISOTROPY};

/// GL_DEPTH_TEXTURE_MODE.
fn shadow_parameter(p: &mut ShadowParams, pname: GLenum, e: GLenum) -> GlResult<()> {
    match pname {
        GL_TEXTURE_COMPARE_MODE => {
            p.compare = match e {
                GL_NONE => false,
                GL_COMPARE_R_TO_TEXTURE => true,
                _ => return Err(GlError::InvalidEnum),
            }
        }
        GL_TEXTURE_COMPARE_FUNC => {
            p.func = match e {
                GL_NEVER => CompareFunc::Never,
                GL_LESS => CompareFunc::Less,
                GL_EQUAL => CompareFunc::Equal,
                GL_LEQUAL => CompareFunc::Lequal,
                GL_GREATER => CompareFunc::Greater,
                GL_NOTEQUAL => CompareFunc::Notequal,
                GL_GEQUAL => CompareFunc::Gequal,
                GL_ALWAYS => CompareFunc::Always,
                _ => return Err(GlError::InvalidEnum),
            }
        }
        _ => {
            p.depth_mode = match e {
                GL_LUMINANCE => DepthMode::Luminance,
                GL_INTENSITY => DepthMode::Intensity,
                GL_ALPHA => DepthMode::Alpha,
                GL_RED => DepthMode::Red,
                _ => return Err(GlError::InvalidEnum),
            }
        }
    }
    Ok(())
}

/// glGetTexParameter of the comparison state.
fn get_shadow_parameter(p: &ShadowParams, pname: GLenum) -> GLenum {
    match pname {
        GL_TEXTURE_COMPARE_MODE if p.compare => GL_COMPARE_R_TO_TEXTURE,
        GL_TEXTURE_COMPARE_MODE => GL_NONE,
        GL_TEXTURE_COMPARE_FUNC => match p.func {
            CompareFunc::Never => GL_NEVER,
            CompareFunc::Less => GL_LESS,
            CompareFunc::Equal => GL_EQUAL,
            CompareFunc::Lequal => GL_LEQUAL,
            CompareFunc::Greater => GL_GREATER,
            CompareFunc::Notequal => GL_NOTEQUAL,
            CompareFunc::Gequal => GL_GEQUAL,
            CompareFunc::Always => GL_ALWAYS,
        },
        _ => match p.depth_mode {
            DepthMode::Luminance => GL_LUMINANCE,
            DepthMode::Intensity => GL_INTENSITY,
            DepthMode::Alpha => GL_ALPHA,
            DepthMode::Red => GL_RED,
        },
    }
}

/// A GL_TEXTURE_WRAP_* value.
fn wrap_from_gl(v: u32) -> GlResult<Wrap> {
    Ok(match v {
        GL_REPEAT => Wrap::Repeat,
        GL_CLAMP => Wrap::Clamp,
        GL_CLAMP_TO_EDGE => Wrap::ClampToEdge,
        GL_CLAMP_TO_BORDER => Wrap::ClampToBorder,
        GL_MIRRORED_REPEAT => Wrap::MirroredRepeat,
        _ => return Err(GlError::InvalidEnum),
    })
}

/// The token of a wrap mode.
fn wrap_to_gl(w: Wrap) -> u32 {
    match w {
        Wrap::Repeat => GL_REPEAT,
        Wrap::Clamp => GL_CLAMP,
        Wrap::ClampToEdge => GL_CLAMP_TO_EDGE,
        Wrap::ClampToBorder => GL_CLAMP_TO_BORDER,
        Wrap::MirroredRepeat => GL_MIRRORED_REPEAT,
    }
}

/// The GL_TEXTURE_MIN_FILTER token of a filter and mipmap filter.
fn min_filter_to_gl(f: Filter, m: MipFilter) -> u32 {
    match (f, m) {
        (Filter::Nearest, MipFilter::None) => GL_NEAREST,
        (Filter::Linear, MipFilter::None) => GL_LINEAR,
        (Filter::Nearest, MipFilter::Nearest) => GL_NEAREST_MIPMAP_NEAREST,
        (Filter::Linear, MipFilter::Nearest) => GL_LINEAR_MIPMAP_NEAREST,
        (Filter::Nearest, MipFilter::Linear) => GL_NEAREST_MIPMAP_LINEAR,
        (Filter::Linear, MipFilter::Linear) => GL_LINEAR_MIPMAP_LINEAR,
    }
}

/// A GL_TEXTURE_BORDER_COLOR or GL_TEXTURE_ENV_COLOR value: four components clamped to
/// [0, 1], integers (`ints`) normalised first; fewer than four values are GL_INVALID_ENUM.
fn color_param(v: &[f64], ints: bool) -> GlResult<[f32; 4]> {
    if v.len() < 4 {
        return Err(GlError::InvalidEnum);
    }
    Ok(std::array::from_fn(|i| {
        let x = if ints {
            (2.0 * v[i] + 1.0) / 4294967295.0
        } else {
            v[i]
        };
        crate::context::clamp01(x) as f32
    }))
}

/// GL_RGB_SCALE / GL_ALPHA_SCALE: 1, 2 or 4 (GL_INVALID_VALUE otherwise).
fn scale_from(v: f64) -> GlResult<f32> {
    if v == 1.0 || v == 2.0 || v == 4.0 {
        Ok(v as f32)
    } else {
        Err(GlError::InvalidValue)
    }
}

impl Context {
    /// glTexParameter*: `v` holds the values as floats; `ints` says they came from an integer
    /// call (GL_TEXTURE_BORDER_COLOR is then normalised).
    pub(crate) fn tex_parameter(
        &mut self,
        target: GLenum,
        pname: GLenum,
        v: &[f64],
        ints: bool,
    ) -> GlResult<()> {
        let t = bind_target(target)?;
        let mut p = self.tex_object(t, false).params;
        let e = v[0] as i64 as u32;
        match pname {
            GL_TEXTURE_MIN_FILTER => {
                (p.min_filter, p.mip_filter) = match e {
                    GL_NEAREST => (Filter::Nearest, MipFilter::None),
                    GL_LINEAR => (Filter::Linear, MipFilter::None),
                    GL_NEAREST_MIPMAP_NEAREST => (Filter::Nearest, MipFilter::Nearest),
                    GL_LINEAR_MIPMAP_NEAREST => (Filter::Linear, MipFilter::Nearest),
                    GL_NEAREST_MIPMAP_LINEAR => (Filter::Nearest, MipFilter::Linear),
                    GL_LINEAR_MIPMAP_LINEAR => (Filter::Linear, MipFilter::Linear),
                    _ => return Err(GlError::InvalidEnum),
                }
            }
            GL_TEXTURE_MAG_FILTER => {
                p.mag_filter = match e {
                    GL_NEAREST => Filter::Nearest,
                    GL_LINEAR => Filter::Linear,
                    _ => return Err(GlError::InvalidEnum),
                }
            }
            GL_TEXTURE_WRAP_S => p.wrap_s = wrap_from_gl(e)?,
            GL_TEXTURE_WRAP_T => p.wrap_t = wrap_from_gl(e)?,
            GL_TEXTURE_WRAP_R => p.wrap_r = wrap_from_gl(e)?,
            GL_TEXTURE_BORDER_COLOR => {
                p.border_color = color_param(v, ints)?;
            }
            GL_TEXTURE_MIN_LOD => p.min_lod = v[0] as f32,
            GL_TEXTURE_MAX_LOD => p.max_lod = v[0] as f32,
            GL_TEXTURE_BASE_LEVEL => {
                if v[0] < 0.0 {
                    return Err(GlError::InvalidValue);
                }
                p.base_level = v[0] as i32;
            }
            GL_TEXTURE_MAX_LEVEL => {
                if v[0] < 0.0 {
                    return Err(GlError::InvalidValue);
                }
                p.max_level = v[0] as i32;
            }
            GL_TEXTURE_LOD_BIAS => p.lod_bias = v[0] as f32,
            GL_GENERATE_MIPMAP => p.generate_mipmap = v[0] != 0.0,
            GL_TEXTURE_MAX_ANISOTROPY_EXT => {
                if v[0] < 1.0 {
                    return Err(GlError::InvalidValue);
                }
                p.max_anisotropy = (v[0] as f32).min(MAX_ANISOTROPY);
            }
            GL_TEXTURE_PRIORITY => p.priority = crate::context::clamp01(v[0]) as f32,
            GL_TEXTURE_COMPARE_MODE | GL_TEXTURE_COMPARE_FUNC | GL_DEPTH_TEXTURE_MODE => {
                shadow_parameter(&mut p.shadow, pname, e)?
            }
            _ => return Err(GlError::InvalidEnum),
        }
        self.tex_object_mut(t, false).params = p;
        Ok(())
    }

    /// glGetTexParameter: the values, and whether they are normalised colours.
    pub(crate) fn get_tex_parameter(
        &self,
        target: GLenum,
        pname: GLenum,
    ) -> GlResult<(Vec<f64>, bool)> {
        let t = bind_target(target)?;
        let p = &self.tex_object(t, false).params;
        let one = |x: f64| Ok((vec![x], false));
        match pname {
            GL_TEXTURE_MIN_FILTER => one(min_filter_to_gl(p.min_filter, p.mip_filter) as f64),
            GL_TEXTURE_MAG_FILTER => one(match p.mag_filter {
                Filter::Nearest => GL_NEAREST,
                Filter::Linear => GL_LINEAR,
            } as f64),
            GL_TEXTURE_WRAP_S => one(wrap_to_gl(p.wrap_s) as f64),
            GL_TEXTURE_WRAP_T => one(wrap_to_gl(p.wrap_t) as f64),
            GL_TEXTURE_WRAP_R => one(wrap_to_gl(p.wrap_r) as f64),
            GL_TEXTURE_BORDER_COLOR => Ok((p.border_color.map(|x| x as f64).to_vec(), true)),
            GL_TEXTURE_MIN_LOD => one(p.min_lod as f64),
            GL_TEXTURE_MAX_LOD => one(p.max_lod as f64),
            GL_TEXTURE_BASE_LEVEL => one(p.base_level as f64),
            GL_TEXTURE_MAX_LEVEL => one(p.max_level as f64),
            GL_TEXTURE_LOD_BIAS => one(p.lod_bias as f64),
            GL_GENERATE_MIPMAP => one(p.generate_mipmap as u8 as f64),
            GL_TEXTURE_MAX_ANISOTROPY_EXT => one(p.max_anisotropy as f64),
            GL_TEXTURE_PRIORITY => one(p.priority as f64),
            GL_TEXTURE_RESIDENT => one(1.0),
            GL_TEXTURE_COMPARE_MODE | GL_TEXTURE_COMPARE_FUNC | GL_DEPTH_TEXTURE_MODE => {
                one(get_shadow_parameter(&p.shadow, pname) as f64)
            }
            _ => Err(GlError::InvalidEnum),
        }
    }

    /// glGetTexLevelParameter of a level of the bound texture or a proxy.
    pub(crate) fn get_tex_level_parameter(
        &self,
        target: GLenum,
        level: GLint,
        pname: GLenum,
    ) -> GlResult<f64> {
        let (t, proxy, face) = image_target(target)?;
        let level = check_level(level)?;
        let obj = self.tex_object(t, proxy);
        let img = obj.face_levels(face).get(level).and_then(|l| l.as_ref());
        let depth = if t == Target::Tex3D {
            obj.depths[level]
        } else {
            1
        };
        // the sizes of the storage format Mesa chose (upload::choose_storage)
        let is_depth = img.is_some_and(|i| i.base == BaseFormat::Depth);
        let compressed =
            img.and_then(|i| crate::context::pack::tex_format::compressed_info(i.internal_format));
        let size = |k: usize| img.filter(|_| !is_depth).map_or(0, |i| i.storage.sizes[k]) as f64;
        Ok(match pname {
            GL_TEXTURE_WIDTH => img.map_or(0, |i| i.width) as f64,
            GL_TEXTURE_HEIGHT => img.map_or(0, |i| i.height) as f64,
            GL_TEXTURE_DEPTH => img.map_or(0, |_| depth) as f64,
            GL_TEXTURE_BORDER => 0.0,
            // Mesa reports GL_RGBA for a level that was never specified
            GL_TEXTURE_INTERNAL_FORMAT => img.map_or(GL_RGBA, |i| i.internal_format) as f64,
            GL_TEXTURE_RED_SIZE => size(0),
            GL_TEXTURE_GREEN_SIZE => size(1),
            GL_TEXTURE_BLUE_SIZE => size(2),
            GL_TEXTURE_ALPHA_SIZE => size(3),
            GL_TEXTURE_LUMINANCE_SIZE => size(4),
            GL_TEXTURE_INTENSITY_SIZE => size(5),
            GL_TEXTURE_COMPRESSED => compressed.is_some() as u8 as f64,
            // Mesa: GL_INVALID_OPERATION unless the image is compressed and not a proxy
            GL_TEXTURE_COMPRESSED_IMAGE_SIZE => match (compressed, img) {
                (Some(f), Some(i)) if !proxy => {
                    f.image_size(i.width as i32, i.height as i32) as f64
                }
                _ => return Err(GlError::InvalidOperation),
            },
            GL_TEXTURE_DEPTH_SIZE => img
                .filter(|_| is_depth)
                .map_or(0, |i| shadow::depth_size(i.storage.depth_bits()))
                as f64,
            GL_TEXTURE_RED_TYPE..=GL_TEXTURE_DEPTH_TYPE => {
                img.map_or(0, |i| super::texture_get::channel_type(i, pname)) as f64
            }
            GL_TEXTURE_STENCIL_SIZE => img
                .filter(|i| shadow::is_depth_stencil(i.internal_format))
                .map_or(0, |_| 8) as f64,
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// glTexEnv*: `v` holds the values (4 for GL_TEXTURE_ENV_COLOR); `ints` normalises colours.
    pub(crate) fn tex_env(
        &mut self,
        target: GLenum,
        pname: GLenum,
        v: &[f64],
        ints: bool,
    ) -> GlResult<()> {
        let unit = self.state.active_texture;
        match target {
            GL_TEXTURE_FILTER_CONTROL => {
                if pname != GL_TEXTURE_LOD_BIAS {
                    return Err(GlError::InvalidEnum);
                }
                self.textures.units[unit].lod_bias = v[0] as f32;
                return Ok(());
            }
            super::point_sprite::GL_POINT_SPRITE => return self.tex_env_point_sprite(pname, v[0]),
            GL_TEXTURE_ENV => {}
            _ => return Err(GlError::InvalidEnum),
        }
        let mut env = self.textures.units[unit].env;
        let e = v[0] as i64 as u32;
        let idx = |base: u32| (pname - base) as usize;
        // The token `e` as each kind of value; one it does not name is GL_INVALID_ENUM.
        let combine = |rgb| CombineFn::from_gl(e, rgb).ok_or(GlError::InvalidEnum);
        let source = || Source::from_gl(e, MAX_TEXTURE_UNITS).ok_or(GlError::InvalidEnum);
        let operand = |alpha| Operand::from_gl(e, alpha).ok_or(GlError::InvalidEnum);
        match pname {
            GL_TEXTURE_ENV_MODE => env.mode = EnvMode::from_gl(e).ok_or(GlError::InvalidEnum)?,
            GL_TEXTURE_ENV_COLOR => env.color = color_param(v, ints)?,
            GL_COMBINE_RGB => env.combine_rgb = combine(true)?,
            GL_COMBINE_ALPHA => env.combine_alpha = combine(false)?,
            GL_SOURCE0_RGB..=GL_SOURCE2_RGB => env.source_rgb[idx(GL_SOURCE0_RGB)] = source()?,
            GL_SOURCE0_ALPHA..=GL_SOURCE2_ALPHA => {
                env.source_alpha[idx(GL_SOURCE0_ALPHA)] = source()?
            }
            GL_OPERAND0_RGB..=GL_OPERAND2_RGB => {
                env.operand_rgb[idx(GL_OPERAND0_RGB)] = operand(false)?
            }
            GL_OPERAND0_ALPHA..=GL_OPERAND2_ALPHA => {
                env.operand_alpha[idx(GL_OPERAND0_ALPHA)] = operand(true)?
            }
            GL_RGB_SCALE => env.rgb_scale = scale_from(v[0])?,
            GL_ALPHA_SCALE => env.alpha_scale = scale_from(v[0])?,
            _ => return Err(GlError::InvalidEnum),
        }
        self.textures.units[unit].env = env;
        Ok(())
    }

    /// glGetTexEnv: the values, and whether they are normalised colours.
    pub(crate) fn get_tex_env(&self, target: GLenum, pname: GLenum) -> GlResult<(Vec<f64>, bool)> {
        let u = &self.textures.units[self.state.active_texture];
        let one = |x: u32| Ok((vec![x as f64], false));
        match target {
            GL_TEXTURE_FILTER_CONTROL if pname == GL_TEXTURE_LOD_BIAS => {
                return Ok((vec![u.lod_bias as f64], false))
            }
            super::point_sprite::GL_POINT_SPRITE => {
                return Ok((vec![self.get_tex_env_point_sprite(pname)?], false))
            }
            GL_TEXTURE_ENV => {}
            _ => return Err(GlError::InvalidEnum),
        }
        let env = &u.env;
        let idx = |base: u32| (pname - base) as usize;
        match pname {
            GL_TEXTURE_ENV_MODE => one(env.mode.to_gl()),
            GL_TEXTURE_ENV_COLOR => Ok((env.color.map(|x| x as f64).to_vec(), true)),
            GL_COMBINE_RGB => one(env.combine_rgb.to_gl()),
            GL_COMBINE_ALPHA => one(env.combine_alpha.to_gl()),
            GL_SOURCE0_RGB..=GL_SOURCE2_RGB => one(env.source_rgb[idx(GL_SOURCE0_RGB)].to_gl()),
            GL_SOURCE0_ALPHA..=GL_SOURCE2_ALPHA => {
                one(env.source_alpha[idx(GL_SOURCE0_ALPHA)].to_gl())
            }
            GL_OPERAND0_RGB..=GL_OPERAND2_RGB => one(env.operand_rgb[idx(GL_OPERAND0_RGB)].to_gl()),
            GL_OPERAND0_ALPHA..=GL_OPERAND2_ALPHA => {
                one(env.operand_alpha[idx(GL_OPERAND0_ALPHA)].to_gl())
            }
            GL_RGB_SCALE => Ok((vec![env.rgb_scale as f64], false)),
            GL_ALPHA_SCALE => Ok((vec![env.alpha_scale as f64], false)),
            _ => Err(GlError::InvalidEnum),
        }
    }

    /// glTexParameterf/glTexParameteri outside a display list: one value, so
    /// GL_TEXTURE_BORDER_COLOR is GL_INVALID_ENUM.
    pub(crate) fn tex_parameter_scalar(
        &mut self,
        target: GLenum,
        pname: GLenum,
        v: f64,
    ) -> GlResult<()> {
        if pname == GL_TEXTURE_BORDER_COLOR {
            return Err(GlError::InvalidEnum);
        }
        self.tex_parameter(target, pname, &[v], false)
    }

    /// glTexEnvf/glTexEnvi: one value, so GL_TEXTURE_ENV_COLOR is GL_INVALID_ENUM.
    pub(crate) fn tex_env_scalar(&mut self, target: GLenum, pname: GLenum, v: f64) -> GlResult<()> {
        if pname == GL_TEXTURE_ENV_COLOR {
            return Err(GlError::InvalidEnum);
        }
        self.tex_env(target, pname, &[v], false)
    }

    /// glGenTextures: fills `names` with unused names.
    pub(crate) fn gen_textures(&mut self, names: &mut [GLuint]) {
        let fresh = self.textures.gen(names.len());
        for (dst, name) in names.iter_mut().zip(fresh) {
            *dst = name;
        }
    }

    /// glDeleteTextures: framebuffer attachments and bindings of deleted names revert to
    /// none and 0.
    pub(crate) fn delete_textures(&mut self, names: &[GLuint]) {
        for &name in names {
            self.fbo_touch(name);
            self.fbo.touch_texture(name);
        }
        self.detach_bound(|a| matches!(a, Attachment::Texture(t) if names.contains(&t.name)));
        self.textures.delete(names);
    }

    /// glBindTexture on the active unit (a name first bound to another target:
    /// GL_INVALID_OPERATION).
    pub(crate) fn bind_texture(&mut self, target: GLenum, texture: GLuint) -> GlResult<()> {
        let t = bind_target(target)?;
        let unit = self.state.active_texture;
        self.textures.bind(unit, t, texture)
    }

    /// glActiveTexture (GL_TEXTUREi, i < GL_MAX_TEXTURE_UNITS). `state.caps` for the texture
    /// targets and texgen follow the unit.
    pub(crate) fn active_texture(&mut self, texture: GLenum) -> GlResult<()> {
        let u = token_index(texture, GL_TEXTURE0, MAX_TEXTURE_UNITS)?;
        self.state.active_texture = u;
        let unit = &self.textures.units[u];
        let (e1, e2) = (unit.enabled_1d, unit.enabled_2d);
        let (e3, ec) = (unit.enabled_3d, unit.enabled_cube);
        self.state.caps.set(Cap::Texture1D, e1);
        self.state.caps.set(Cap::Texture2D, e2);
        self.state.caps.set(Cap::Texture3D, e3);
        self.state.caps.set(Cap::TextureCubeMap, ec);
        self.sync_texgen_caps();
        Ok(())
    }

    /// glClientActiveTexture.
    pub(crate) fn client_active_texture(&mut self, texture: GLenum) -> GlResult<()> {
        self.state.client_active_texture = token_index(texture, GL_TEXTURE0, MAX_TEXTURE_UNITS)?;
        Ok(())
    }

    /// glPrioritizeTextures: priorities are stored (clamped to [0, 1]); unknown names are
    /// skipped.
    pub(crate) fn prioritize_textures(&mut self, names: &[GLuint], priorities: &[GLclampf]) {
        for (&name, &p) in names.iter().zip(priorities) {
            if let Some(o) = self.textures.objects.get_mut(&name) {
                o.params.priority = super::clamp01(p as f64) as f32;
            }
        }
    }

    /// glAreTexturesResident: software textures are always resident; 0 or an unknown name
    /// is GL_INVALID_VALUE.
    pub(crate) fn are_textures_resident(&self, names: &[GLuint]) -> GlResult<()> {
        if names.iter().any(|&t| !self.textures.is_texture(t)) {
            return Err(GlError::InvalidValue);
        }
        Ok(())
    }
}
