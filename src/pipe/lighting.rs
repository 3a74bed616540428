//! Lights, materials, colour material, the light model and fog: the parameter blocks the
//! vertex stage evaluates.

#[allow(unused_imports)]
use super::*;

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

impl Material {
    /// Replaces the terms `t` tracks with `color` (GL_COLOR_MATERIAL).
    #[inline]
    pub fn apply_tracked(&mut self, t: Tracked, color: [f32; 4]) {
        if t.emission {
            self.emission = color;
        }
        if t.ambient {
            self.ambient = color;
        }
        if t.diffuse {
            self.diffuse = color;
        }
        if t.specular {
            self.specular = color;
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

impl Tracked {
    /// Whether any term follows the colour.
    #[inline]
    pub fn any(&self) -> bool {
        self.ambient || self.diffuse || self.emission || self.specular
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

/// `TRANSFORM_POINT(Q, M, P)` (column-major, left to right).
pub fn transform_point(m: &[f32; 16], p: [f32; 4]) -> [f32; 4] {
    std::array::from_fn(|r| m[r] * p[0] + m[4 + r] * p[1] + m[8 + r] * p[2] + m[12 + r] * p[3])
}

/// `TRANSFORM_DIRECTION(TO, DIR, M)`: the upper 3x3 times the direction.
pub fn transform_direction(m: &[f32; 16], d: [f32; 3]) -> [f32; 3] {
    std::array::from_fn(|r| d[0] * m[r] + d[1] * m[4 + r] + d[2] * m[8 + r])
}

impl LightingState {
    /// `_mesa_update_color_material`: copies `color` into the tracked material terms. Mesa
    /// does this whenever the current colour changes while GL_COLOR_MATERIAL is on, when
    /// it is enabled, on glColorMaterial, and before glGetMaterial.
    pub fn sync_color_material(&mut self, color: [f32; 4]) {
        for f in 0..2 {
            self.material[f].apply_tracked(self.color_material.tracked(f), color);
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

/// glColorMaterial state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ColorMaterial {
    /// GL_COLOR_MATERIAL_FACE
    pub face: Face,
    /// GL_COLOR_MATERIAL_PARAMETER
    pub mode: MaterialParam,
}

impl Default for ColorMaterial {
    fn default() -> Self {
        ColorMaterial {
            face: Face::FrontAndBack,
            mode: MaterialParam::AmbientAndDiffuse,
        }
    }
}

impl ColorMaterial {
    /// The tracked terms of face `f` (0 front, 1 back): Mesa's `_ColorMaterialBitmask`.
    pub fn tracked(&self, f: usize) -> Tracked {
        let on = matches!(
            (self.face, f),
            (Face::FrontAndBack, _) | (Face::Front, 0) | (Face::Back, 1)
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
