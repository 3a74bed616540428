//! Texture-coordinate generation modes and planes, and user clip planes.

#[allow(unused_imports)]
use super::*;

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

/// User clip planes (part of GL_TRANSFORM_BIT; the enables live in the cap bits).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct ClipPlanes {
    /// GL_CLIP_PLANEi in eye space.
    pub eye: [[f32; 4]; MAX_CLIP_PLANES],
    /// GL_CLIP_PLANEi enables as bits.
    pub enabled: u8,
}
