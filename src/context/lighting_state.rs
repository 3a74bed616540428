//! Lighting, material, colour-material and fog state (glLight, glLightModel, glMaterial,
//! glColorMaterial, glFog), with Mesa's initial values (`main/light.c`, `main/fog.c`).
//!
//! Setters validate first and change nothing on error. Light positions and spot
//! directions are stored in eye space, transformed by the modelview at the time of the
//! call (the caller passes it in), exactly as Mesa's `_mesa_Lightfv` does.

use super::error::{GlError, GlResult};
use crate::gl::enums::*;
use crate::gl::glext_enums::*;
use crate::gl::types::GLenum;
pub use crate::pipe::{
    transform_direction, transform_point, ColorMaterial, Face, FogMode, FogState, Light,
    LightModel, LightingState, Material, MaterialParam, Tracked, MAX_EXPONENT, MAX_LIGHTS,
};

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
/// The faces a glMaterial call names.
fn faces(face: GLenum) -> GlResult<&'static [usize]> {
    Ok(match face {
        GL_FRONT => &[0],
        GL_BACK => &[1],
        GL_FRONT_AND_BACK => &[0, 1],
        _ => return Err(GlError::InvalidEnum),
    })
}

impl LightingState {
    /// The index of GL_LIGHTi.
    pub fn light_index(light: GLenum) -> GlResult<usize> {
        super::state::token_index(light, GL_LIGHT0, MAX_LIGHTS)
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
        let face = Face::from_gl(face)?;
        self.color_material = ColorMaterial { face, mode };
        Ok(())
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
