//! Texture coordinate generation (glTexGen) and user clip plane (glClipPlane) state, with
//! Mesa's initial values (`main/texgen.c`, `main/clip.c`, `main/texstate.c`).
//!
//! Eye planes and clip planes are stored in eye space: the plane given by the application
//! is multiplied by the inverse of the modelview current at the time of the call
//! (`_mesa_transform_vector`, a row vector times Mesa's f32 inverse, left to right).
//! Both structs are plain `Clone` data so glPushAttrib (GL_TEXTURE_BIT, GL_TRANSFORM_BIT)
//! can save and restore them whole.

use super::error::{GlError, GlResult};
pub use crate::fixed_function::matrix::plane_times_inverse;
use crate::fixed_function::matrix::MatrixStack;
use crate::gl::enums::*;
use crate::gl::types::GLenum;
pub use crate::pipe::{ClipPlanes, TexGenMode, TexGenState, TexGenUnit, MAX_CLIP_PLANES};

impl TexGenMode {
    /// Converts a mode token for coordinate `coord` (0..4 = S, T, R, Q), with Mesa's
    /// per-coordinate restrictions.
    pub fn from_gl(e: GLenum, coord: usize) -> GlResult<Self> {
        Ok(match e {
            GL_OBJECT_LINEAR => Self::ObjectLinear,
            GL_EYE_LINEAR => Self::EyeLinear,
            GL_SPHERE_MAP if coord < 2 => Self::SphereMap,
            GL_REFLECTION_MAP if coord < 3 => Self::ReflectionMap,
            GL_NORMAL_MAP if coord < 3 => Self::NormalMap,
            _ => return Err(GlError::InvalidEnum),
        })
    }
    /// The GL token.
    pub fn to_gl(self) -> GLenum {
        match self {
            Self::ObjectLinear => GL_OBJECT_LINEAR,
            Self::EyeLinear => GL_EYE_LINEAR,
            Self::SphereMap => GL_SPHERE_MAP,
            Self::ReflectionMap => GL_REFLECTION_MAP,
            Self::NormalMap => GL_NORMAL_MAP,
        }
    }
}
/// The index (0..4) of GL_S, GL_T, GL_R or GL_Q.
pub fn coord_index(coord: GLenum) -> GlResult<usize> {
    match coord {
        GL_S => Ok(0),
        GL_T => Ok(1),
        GL_R => Ok(2),
        GL_Q => Ok(3),
        _ => Err(GlError::InvalidEnum),
    }
}

impl TexGenState {
    /// glTexGenfv on `unit` (values already converted to f32 as Mesa does).
    pub fn set(
        &mut self,
        unit: usize,
        coord: GLenum,
        pname: GLenum,
        params: [f32; 4],
        modelview: &MatrixStack,
    ) -> GlResult<()> {
        let c = coord_index(coord)?;
        let u = &mut self.units[unit];
        match pname {
            GL_TEXTURE_GEN_MODE => u.mode[c] = TexGenMode::from_gl(params[0] as i32 as GLenum, c)?,
            GL_OBJECT_PLANE => u.object_plane[c] = params,
            GL_EYE_PLANE => u.eye_plane[c] = plane_times_inverse(modelview, params),
            _ => return Err(GlError::InvalidEnum),
        }
        Ok(())
    }

    /// glGetTexGen*: the mode as one value or a plane as four.
    pub fn get(&self, unit: usize, coord: GLenum, pname: GLenum) -> GlResult<([f64; 4], usize)> {
        let c = coord_index(coord)?;
        let u = &self.units[unit];
        let w = |p: [f32; 4]| (p.map(|v| v as f64), 4);
        Ok(match pname {
            GL_TEXTURE_GEN_MODE => ([u.mode[c].to_gl() as f64, 0.0, 0.0, 0.0], 1),
            GL_OBJECT_PLANE => w(u.object_plane[c]),
            GL_EYE_PLANE => w(u.eye_plane[c]),
            _ => return Err(GlError::InvalidEnum),
        })
    }
}
impl ClipPlanes {
    /// The index of GL_CLIP_PLANEi.
    pub fn index(plane: GLenum) -> GlResult<usize> {
        super::state::token_index(plane, GL_CLIP_PLANE0, MAX_CLIP_PLANES)
    }
}
