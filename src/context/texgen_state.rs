//! Texture coordinate generation (glTexGen) and user clip plane (glClipPlane) state, with
//! Mesa's initial values (`main/texgen.c`, `main/clip.c`, `main/texstate.c`).
//!
//! Eye planes and clip planes are stored in eye space: the plane given by the application
//! is multiplied by the inverse of the modelview current at the time of the call
//! (`_mesa_transform_vector`, a row vector times Mesa's f32 inverse, left to right).
//! Both structs are plain `Clone` data so glPushAttrib (GL_TEXTURE_BIT, GL_TRANSFORM_BIT)
//! can save and restore them whole.

use super::error::{GlError, GlResult};
use super::state::MAX_TEXTURE_UNITS;
use crate::ffi::enums::*;
use crate::ffi::types::GLenum;
use crate::fixed_function::matrix::MatrixStack;

/// GL_MAX_CLIP_PLANES (Mesa's `MaxClipPlanes` for llvmpipe).
pub const MAX_CLIP_PLANES: usize = 8;

/// A texture-coordinate generation function (GL_TEXTURE_GEN_MODE).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TexGenMode {
    /// GL_OBJECT_LINEAR: `dot(object position, object plane)`.
    ObjectLinear,
    /// GL_EYE_LINEAR: `dot(eye position, eye plane)`.
    EyeLinear,
    /// GL_SPHERE_MAP (S and T only).
    SphereMap,
    /// GL_REFLECTION_MAP (S, T and R).
    ReflectionMap,
    /// GL_NORMAL_MAP (S, T and R).
    NormalMap,
}

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
    /// Whether the mode reads eye coordinates (Mesa's `TEXGEN_NEED_EYE_COORD`).
    pub fn needs_eye(self) -> bool {
        self != Self::ObjectLinear
    }
}

/// The texgen state of one texture unit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TexGenUnit {
    /// GL_TEXTURE_GEN_S/T/R/Q enables as bits 0..4.
    pub enabled: u8,
    /// The mode of S, T, R, Q.
    pub mode: [TexGenMode; 4],
    /// GL_OBJECT_PLANE of S, T, R, Q.
    pub object_plane: [[f32; 4]; 4],
    /// GL_EYE_PLANE of S, T, R, Q (in eye space).
    pub eye_plane: [[f32; 4]; 4],
}

impl Default for TexGenUnit {
    fn default() -> Self {
        let planes = [
            [1.0, 0.0, 0.0, 0.0],
            [0.0, 1.0, 0.0, 0.0],
            [0.0; 4],
            [0.0; 4],
        ];
        TexGenUnit {
            enabled: 0,
            mode: [TexGenMode::EyeLinear; 4],
            object_plane: planes,
            eye_plane: planes,
        }
    }
}

/// glTexGen state of every texture unit (part of GL_TEXTURE_BIT).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TexGenState {
    /// Per texture unit.
    pub units: [TexGenUnit; MAX_TEXTURE_UNITS],
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

/// Plane `p` times the inverse of the stack's top matrix (Mesa's
/// `_mesa_transform_vector(u, p, inv)`): object to eye space with the modelview, eye to
/// clip space with the projection.
pub fn plane_times_inverse(modelview: &MatrixStack, p: [f32; 4]) -> [f32; 4] {
    let mut flags = modelview.top_flags();
    let m = flags.inverse(&modelview.top().0);
    std::array::from_fn(|i| {
        p[0] * m[i * 4] + p[1] * m[i * 4 + 1] + p[2] * m[i * 4 + 2] + p[3] * m[i * 4 + 3]
    })
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

/// User clip planes (part of GL_TRANSFORM_BIT; the enables live in the cap bits).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ClipPlanes {
    /// GL_CLIP_PLANEi in eye space.
    pub eye: [[f32; 4]; MAX_CLIP_PLANES],
    /// GL_CLIP_PLANEi enables as bits.
    pub enabled: u8,
}

impl ClipPlanes {
    /// The index of GL_CLIP_PLANEi.
    pub fn index(plane: GLenum) -> GlResult<usize> {
        let i = plane.wrapping_sub(GL_CLIP_PLANE0) as usize;
        if i < MAX_CLIP_PLANES {
            Ok(i)
        } else {
            Err(GlError::InvalidEnum)
        }
    }
}
