//! Lighting, material, colour-material and fog state (glLight, glLightModel, glMaterial,
//! glColorMaterial, glFog), with Mesa's initial values (`main/light.c`, `main/fog.c`).
//!
//! Setters validate first and change nothing on error. Light positions and spot
//! directions are stored in eye space, transformed by the modelview at the time of the
//! call (the caller passes it in), exactly as Mesa's `_mesa_Lightfv` does.

use super::error::{GlError, GlResult};
use crate::ffi::enums::*;
use crate::ffi::glext_enums::*;
use crate::ffi::types::GLenum;

/// The number of lights (GL_MAX_LIGHTS).
pub const MAX_LIGHTS: usize = 8;
/// Mesa's `MaxSpotExponent` and `MaxShininess`.
pub const MAX_EXPONENT: f32 = 128.0;

/// One light source (`gl_light_uniforms`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Light {
    /// GL_AMBIENT
    pub ambient: [f32; 4],
    /// GL_DIFFUSE
    pub diffuse: [f32; 4],
    /// GL_SPECULAR
    pub specular: [f32; 4],
    /// GL_POSITION in eye space.
    pub position: [f32; 4],
    /// GL_SPOT_DIRECTION in eye space.
    pub spot_direction: [f32; 3],
    /// GL_SPOT_EXPONENT
    pub spot_exponent: f32,
    /// GL_SPOT_CUTOFF (degrees)
    pub spot_cutoff: f32,
    /// `_CosCutoff`: `cosf(cutoff·π/180)` clamped at 0.
    pub cos_cutoff: f32,
    /// GL_CONSTANT/LINEAR/QUADRATIC_ATTENUATION
    pub attenuation: [f32; 3],
}

impl Light {
    /// The initial state of light `n` (light 0 has white diffuse and specular).
    pub fn new(n: usize) -> Light {
        let white = if n == 0 { 1.0 } else { 0.0 };
        Light {
            ambient: [0.0, 0.0, 0.0, 1.0],
            diffuse: [white, white, white, 1.0],
            specular: [white, white, white, 1.0],
            position: [0.0, 0.0, 1.0, 0.0],
            spot_direction: [0.0, 0.0, -1.0],
            spot_exponent: 0.0,
            spot_cutoff: 180.0,
            cos_cutoff: 0.0,
            attenuation: [1.0, 0.0, 0.0],
        }
    }
}

/// A material (`gl_material`, one face).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// GL_AMBIENT
    pub ambient: [f32; 4],
    /// GL_DIFFUSE
    pub diffuse: [f32; 4],
    /// GL_SPECULAR
    pub specular: [f32; 4],
    /// GL_EMISSION
    pub emission: [f32; 4],
    /// GL_SHININESS
    pub shininess: f32,
    /// GL_COLOR_INDEXES (stored, unused in RGBA mode)
    pub indexes: [f32; 3],
}

impl Default for Material {
    fn default() -> Self {
        Material {
            ambient: [0.2, 0.2, 0.2, 1.0],
            diffuse: [0.8, 0.8, 0.8, 1.0],
            specular: [0.0, 0.0, 0.0, 1.0],
            emission: [0.0, 0.0, 0.0, 1.0],
            shininess: 0.0,
            indexes: [0.0, 1.0, 1.0],
        }
    }
}

/// A material property that glColorMaterial can track.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MaterialParam {
    /// GL_EMISSION
    Emission,
    /// GL_AMBIENT
    Ambient,
    /// GL_DIFFUSE
    Diffuse,
    /// GL_SPECULAR
    Specular,
    /// GL_AMBIENT_AND_DIFFUSE
    AmbientAndDiffuse,
}

impl MaterialParam {
    /// Converts a glColorMaterial mode.
    pub fn from_gl(e: GLenum) -> GlResult<Self> {
        Ok(match e {
            GL_EMISSION => Self::Emission,
            GL_AMBIENT => Self::Ambient,
            GL_DIFFUSE => Self::Diffuse,
            GL_SPECULAR => Self::Specular,
            GL_AMBIENT_AND_DIFFUSE => Self::AmbientAndDiffuse,
            _ => return Err(GlError::InvalidEnum),
        })
    }
    /// The GL token.
    pub fn to_gl(self) -> GLenum {
        match self {
            Self::Emission => GL_EMISSION,
            Self::Ambient => GL_AMBIENT,
            Self::Diffuse => GL_DIFFUSE,
            Self::Specular => GL_SPECULAR,
            Self::AmbientAndDiffuse => GL_AMBIENT_AND_DIFFUSE,
        }
    }
}

/// Which material terms follow the vertex colour (per face: [front, back]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Tracked {
    /// Emission follows the colour.
    pub emission: bool,
    /// Ambient follows the colour.
    pub ambient: bool,
    /// Diffuse follows the colour.
    pub diffuse: bool,
    /// Specular follows the colour.
    pub specular: bool,
}

/// glColorMaterial state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ColorMaterial {
    /// GL_COLOR_MATERIAL_FACE
    pub face: GLenum,
    /// GL_COLOR_MATERIAL_PARAMETER
    pub mode: MaterialParam,
}

impl Default for ColorMaterial {
    fn default() -> Self {
        ColorMaterial {
            face: GL_FRONT_AND_BACK,
            mode: MaterialParam::AmbientAndDiffuse,
        }
    }
}

impl ColorMaterial {
    /// The tracked terms of face `f` (0 front, 1 back): Mesa's `_ColorMaterialBitmask`.
    pub fn tracked(&self, f: usize) -> Tracked {
        let on = matches!(
            (self.face, f),
            (GL_FRONT_AND_BACK, _) | (GL_FRONT, 0) | (GL_BACK, 1)
        );
        if !on {
            return Tracked::default();
        }
        let m = self.mode;
        Tracked {
            emission: m == MaterialParam::Emission,
            ambient: matches!(m, MaterialParam::Ambient | MaterialParam::AmbientAndDiffuse),
            diffuse: matches!(m, MaterialParam::Diffuse | MaterialParam::AmbientAndDiffuse),
            specular: m == MaterialParam::Specular,
        }
    }
}

/// glLightModel state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightModel {
    /// GL_LIGHT_MODEL_AMBIENT
    pub ambient: [f32; 4],
    /// GL_LIGHT_MODEL_LOCAL_VIEWER
    pub local_viewer: bool,
    /// GL_LIGHT_MODEL_TWO_SIDE
    pub two_side: bool,
    /// GL_LIGHT_MODEL_COLOR_CONTROL == GL_SEPARATE_SPECULAR_COLOR
    pub separate_specular: bool,
}

impl Default for LightModel {
    fn default() -> Self {
        LightModel {
            ambient: [0.2, 0.2, 0.2, 1.0],
            local_viewer: false,
            two_side: false,
            separate_specular: false,
        }
    }
}

/// GL_FOG_MODE.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FogMode {
    /// GL_LINEAR
    Linear,
    /// GL_EXP
    Exp,
    /// GL_EXP2
    Exp2,
}

impl FogMode {
    /// The GL token.
    pub fn to_gl(self) -> GLenum {
        match self {
            Self::Linear => GL_LINEAR,
            Self::Exp => GL_EXP,
            Self::Exp2 => GL_EXP2,
        }
    }
}

/// glFog state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FogState {
    /// GL_FOG_MODE
    pub mode: FogMode,
    /// GL_FOG_DENSITY
    pub density: f32,
    /// GL_FOG_START
    pub start: f32,
    /// GL_FOG_END
    pub end: f32,
    /// GL_FOG_COLOR, clamped to [0,1] (what the shader uses and glGet returns).
    pub color: [f32; 4],
    /// GL_FOG_INDEX
    pub index: f32,
    /// GL_FOG_COORD_SRC is GL_FOG_COORD (otherwise GL_FRAGMENT_DEPTH).
    pub coord_from_attrib: bool,
}

impl Default for FogState {
    fn default() -> Self {
        FogState {
            mode: FogMode::Exp,
            density: 1.0,
            start: 0.0,
            end: 1.0,
            color: [0.0; 4],
            index: 0.0,
            coord_from_attrib: false,
        }
    }
}

/// All lighting and fog state.
#[derive(Clone, Debug, PartialEq)]
pub struct LightingState {
    /// GL_LIGHT0..7
    pub lights: [Light; MAX_LIGHTS],
    /// glLightModel
    pub model: LightModel,
    /// Front (0) and back (1) materials.
    pub material: [Material; 2],
    /// glColorMaterial
    pub color_material: ColorMaterial,
    /// glFog
    pub fog: FogState,
}

impl Default for LightingState {
    fn default() -> Self {
        LightingState {
            lights: std::array::from_fn(Light::new),
            model: LightModel::default(),
            material: [Material::default(); 2],
            color_material: ColorMaterial::default(),
            fog: FogState::default(),
        }
    }
}

/// The faces a glMaterial call names.
fn faces(face: GLenum) -> GlResult<&'static [usize]> {
    Ok(match face {
        GL_FRONT => &[0],
        GL_BACK => &[1],
        GL_FRONT_AND_BACK => &[0, 1],
        _ => return Err(GlError::InvalidEnum),
    })
}

/// `TRANSFORM_POINT(Q, M, P)` (column-major, left to right).
pub fn transform_point(m: &[f32; 16], p: [f32; 4]) -> [f32; 4] {
    std::array::from_fn(|r| m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r] * p[3])
}

/// `TRANSFORM_DIRECTION(TO, DIR, M)`: the upper 3x3 times the direction.
pub fn transform_direction(m: &[f32; 16], d: [f32; 3]) -> [f32; 3] {
    std::array::from_fn(|r| d[0] * m[r] + d[1] * m[4 + r] + d[2] * m[8 + r])
}

impl LightingState {
    /// The index of GL_LIGHTi.
    pub fn light_index(light: GLenum) -> GlResult<usize> {
        let i = light.wrapping_sub(GL_LIGHT0) as usize;
        if i < MAX_LIGHTS {
            Ok(i)
        } else {
            Err(GlError::InvalidEnum)
        }
    }

    /// glLightfv with Mesa's validation; `modelview` is the current modelview matrix.
    pub fn set_light(
        &mut self,
        light: GLenum,
        pname: GLenum,
        p: &[f32; 4],
        modelview: &[f32; 16],
    ) -> GlResult<()> {
        let i = Self::light_index(light)?;
        let l = &mut self.lights[i];
        match pname {
            GL_AMBIENT => l.ambient = *p,
            GL_DIFFUSE => l.diffuse = *p,
            GL_SPECULAR => l.specular = *p,
            GL_POSITION => l.position = transform_point(modelview, *p),
            GL_SPOT_DIRECTION => {
                l.spot_direction = transform_direction(modelview, [p[0], p[1], p[2]])
            }
            GL_SPOT_EXPONENT => {
                if p[0] < 0.0 || p[0] > MAX_EXPONENT {
                    return Err(GlError::InvalidValue);
                }
                l.spot_exponent = p[0];
            }
            GL_SPOT_CUTOFF => {
                let c = p[0];
                // Mesa's test, NaN passing as in Mesa.
                #[allow(clippy::manual_range_contains)]
                let bad = (c < 0.0 || c > 90.0) && c != 180.0;
                if bad {
                    return Err(GlError::InvalidValue);
                }
                l.spot_cutoff = c;
                let cos = ((c as f64 * std::f64::consts::PI / 180.0) as f32).cos();
                l.cos_cutoff = if cos < 0.0 { 0.0 } else { cos };
            }
            GL_CONSTANT_ATTENUATION | GL_LINEAR_ATTENUATION | GL_QUADRATIC_ATTENUATION => {
                if p[0] < 0.0 {
                    return Err(GlError::InvalidValue);
                }
                l.attenuation[(pname - GL_CONSTANT_ATTENUATION) as usize] = p[0];
            }
            _ => return Err(GlError::InvalidEnum),
        }
        Ok(())
    }

    /// glGetLightfv: up to 4 values.
    pub fn get_light(&self, light: GLenum, pname: GLenum) -> GlResult<Vec<f32>> {
        let l = &self.lights[Self::light_index(light)?];
        Ok(match pname {
            GL_AMBIENT => l.ambient.to_vec(),
            GL_DIFFUSE => l.diffuse.to_vec(),
            GL_SPECULAR => l.specular.to_vec(),
            GL_POSITION => l.position.to_vec(),
            GL_SPOT_DIRECTION => l.spot_direction.to_vec(),
            GL_SPOT_EXPONENT => vec![l.spot_exponent],
            GL_SPOT_CUTOFF => vec![l.spot_cutoff],
            GL_CONSTANT_ATTENUATION => vec![l.attenuation[0]],
            GL_LINEAR_ATTENUATION => vec![l.attenuation[1]],
            GL_QUADRATIC_ATTENUATION => vec![l.attenuation[2]],
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// glLightModelfv.
    pub fn set_light_model(&mut self, pname: GLenum, p: &[f32; 4]) -> GlResult<()> {
        match pname {
            GL_LIGHT_MODEL_AMBIENT => self.model.ambient = *p,
            GL_LIGHT_MODEL_LOCAL_VIEWER => self.model.local_viewer = p[0] != 0.0,
            GL_LIGHT_MODEL_TWO_SIDE => self.model.two_side = p[0] != 0.0,
            GL_LIGHT_MODEL_COLOR_CONTROL => {
                self.model.separate_specular = if p[0] == GL_SINGLE_COLOR as f32 {
                    false
                } else if p[0] == GL_SEPARATE_SPECULAR_COLOR as f32 {
                    true
                } else {
                    return Err(GlError::InvalidEnum);
                }
            }
            _ => return Err(GlError::InvalidEnum),
        }
        Ok(())
    }

    /// glMaterialfv. Terms that glColorMaterial currently tracks are left alone
    /// (`cm_enabled` is GL_COLOR_MATERIAL), as Mesa does.
    pub fn set_material(
        &mut self,
        face: GLenum,
        pname: GLenum,
        p: &[f32; 4],
        cm_enabled: bool,
    ) -> GlResult<()> {
        let fs = faces(face)?;
        if !matches!(
            pname,
            GL_EMISSION
                | GL_AMBIENT
                | GL_DIFFUSE
                | GL_SPECULAR
                | GL_SHININESS
                | GL_COLOR_INDEXES
                | GL_AMBIENT_AND_DIFFUSE
        ) {
            return Err(GlError::InvalidEnum);
        }
        if pname == GL_SHININESS && (p[0] < 0.0 || p[0] > MAX_EXPONENT) {
            return Err(GlError::InvalidValue);
        }
        for &f in fs {
            let t = if cm_enabled {
                self.color_material.tracked(f)
            } else {
                Tracked::default()
            };
            let m = &mut self.material[f];
            match pname {
                GL_EMISSION if !t.emission => m.emission = *p,
                GL_AMBIENT if !t.ambient => m.ambient = *p,
                GL_DIFFUSE if !t.diffuse => m.diffuse = *p,
                GL_SPECULAR if !t.specular => m.specular = *p,
                GL_SHININESS => m.shininess = p[0],
                GL_COLOR_INDEXES => m.indexes = [p[0], p[1], p[2]],
                GL_AMBIENT_AND_DIFFUSE => {
                    if !t.ambient {
                        m.ambient = *p;
                    }
                    if !t.diffuse {
                        m.diffuse = *p;
                    }
                }
                _ => {}
            }
        }
        Ok(())
    }

    /// glGetMaterialfv (GL_FRONT or GL_BACK only).
    pub fn get_material(&self, face: GLenum, pname: GLenum) -> GlResult<Vec<f32>> {
        let m = &self.material[match face {
            GL_FRONT => 0,
            GL_BACK => 1,
            _ => return Err(GlError::InvalidEnum),
        }];
        Ok(match pname {
            GL_AMBIENT => m.ambient.to_vec(),
            GL_DIFFUSE => m.diffuse.to_vec(),
            GL_SPECULAR => m.specular.to_vec(),
            GL_EMISSION => m.emission.to_vec(),
            GL_SHININESS => vec![m.shininess],
            GL_COLOR_INDEXES => m.indexes.to_vec(),
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// glColorMaterial (validation only; the caller then syncs the material when enabled).
    pub fn set_color_material(&mut self, face: GLenum, mode: GLenum) -> GlResult<()> {
        let mode = MaterialParam::from_gl(mode)?;
        faces(face)?;
        self.color_material = ColorMaterial { face, mode };
        Ok(())
    }

    /// `_mesa_update_color_material`: copies `color` into the tracked material terms. Mesa
    /// does this whenever the current colour changes while GL_COLOR_MATERIAL is on, when
    /// it is enabled, on glColorMaterial, and before glGetMaterial.
    pub fn sync_color_material(&mut self, color: [f32; 4]) {
        for f in 0..2 {
            let t = self.color_material.tracked(f);
            let m = &mut self.material[f];
            if t.emission {
                m.emission = color;
            }
            if t.ambient {
                m.ambient = color;
            }
            if t.diffuse {
                m.diffuse = color;
            }
            if t.specular {
                m.specular = color;
            }
        }
    }

    /// glFogfv.
    pub fn set_fog(&mut self, pname: GLenum, p: &[f32; 4]) -> GlResult<()> {
        let f = &mut self.fog;
        match pname {
            GL_FOG_MODE => {
                f.mode = match p[0] as i32 as GLenum {
                    GL_LINEAR => FogMode::Linear,
                    GL_EXP => FogMode::Exp,
                    GL_EXP2 => FogMode::Exp2,
                    _ => return Err(GlError::InvalidEnum),
                }
            }
            GL_FOG_DENSITY => {
                if p[0] < 0.0 {
                    return Err(GlError::InvalidValue);
                }
                f.density = p[0];
            }
            GL_FOG_START => f.start = p[0],
            GL_FOG_END => f.end = p[0],
            GL_FOG_INDEX => f.index = p[0],
            GL_FOG_COLOR => f.color = p.map(|v| v.clamp(0.0, 1.0)),
            GL_FOG_COORD_SRC => {
                f.coord_from_attrib = match p[0] as i32 as GLenum {
                    GL_FOG_COORD => true,
                    GL_FRAGMENT_DEPTH => false,
                    _ => return Err(GlError::InvalidEnum),
                }
            }
            _ => return Err(GlError::InvalidEnum),
        }
        Ok(())
    }
}

/// Mesa's `INT_TO_FLOAT`: `(2i + 1) / (2^32 - 2)`, with the sum in f32 and the scale in
/// double.
pub fn int_to_float(i: i32) -> f32 {
    let t = 2.0f32 * i as f32 + 1.0f32;
    (t as f64 * (1.0f32 as f64 / 4294967294.0)) as f32
}

/// Mesa's `FLOAT_TO_INT`: `(GLint)(2147483647.0 · x)`.
pub fn float_to_int(x: f32) -> i32 {
    (2147483647.0f64 * x as f64) as i32
}
