//! The texture state's GL side: texture-environment enums from and to GL tokens, and
//! glBindTexture's rule on a texture object's target.

use crate::gl::enums::*;
use crate::gl::error::{GlError, GlResult};
use crate::texture::env::{CombineFn, EnvMode, Operand, Source};
use crate::texture::{Target, TextureObject, TextureState};

impl EnvMode {
    /// From a GL enum.
    pub fn from_gl(e: u32) -> Option<EnvMode> {
        Some(match e {
            GL_REPLACE => EnvMode::Replace,
            GL_MODULATE => EnvMode::Modulate,
            GL_DECAL => EnvMode::Decal,
            GL_BLEND => EnvMode::Blend,
            GL_ADD => EnvMode::Add,
            GL_COMBINE => EnvMode::Combine,
            _ => return None,
        })
    }
    /// To the GL enum.
    pub fn to_gl(self) -> u32 {
        match self {
            EnvMode::Replace => GL_REPLACE,
            EnvMode::Modulate => GL_MODULATE,
            EnvMode::Decal => GL_DECAL,
            EnvMode::Blend => GL_BLEND,
            EnvMode::Add => GL_ADD,
            EnvMode::Combine => GL_COMBINE,
        }
    }
}

impl CombineFn {
    /// From a GL enum; the DOT3 functions only for RGB.
    pub fn from_gl(e: u32, rgb: bool) -> Option<CombineFn> {
        Some(match e {
            GL_REPLACE => CombineFn::Replace,
            GL_MODULATE => CombineFn::Modulate,
            GL_ADD => CombineFn::Add,
            GL_ADD_SIGNED => CombineFn::AddSigned,
            GL_INTERPOLATE => CombineFn::Interpolate,
            GL_SUBTRACT => CombineFn::Subtract,
            GL_DOT3_RGB if rgb => CombineFn::Dot3Rgb,
            GL_DOT3_RGBA if rgb => CombineFn::Dot3Rgba,
            _ => return None,
        })
    }
    /// To the GL enum.
    pub fn to_gl(self) -> u32 {
        match self {
            CombineFn::Replace => GL_REPLACE,
            CombineFn::Modulate => GL_MODULATE,
            CombineFn::Add => GL_ADD,
            CombineFn::AddSigned => GL_ADD_SIGNED,
            CombineFn::Interpolate => GL_INTERPOLATE,
            CombineFn::Subtract => GL_SUBTRACT,
            CombineFn::Dot3Rgb => GL_DOT3_RGB,
            CombineFn::Dot3Rgba => GL_DOT3_RGBA,
        }
    }
}

impl Source {
    /// From a GL enum (`units` = number of texture units for GL_TEXTUREn).
    pub fn from_gl(e: u32, units: usize) -> Option<Source> {
        Some(match e {
            GL_TEXTURE => Source::Texture,
            GL_CONSTANT => Source::Constant,
            GL_PRIMARY_COLOR => Source::PrimaryColor,
            GL_PREVIOUS => Source::Previous,
            _ if e >= GL_TEXTURE0 && ((e - GL_TEXTURE0) as usize) < units => {
                Source::TextureN((e - GL_TEXTURE0) as u8)
            }
            _ => return None,
        })
    }
    /// To the GL enum.
    pub fn to_gl(self) -> u32 {
        match self {
            Source::Texture => GL_TEXTURE,
            Source::TextureN(n) => GL_TEXTURE0 + n as u32,
            Source::Constant => GL_CONSTANT,
            Source::PrimaryColor => GL_PRIMARY_COLOR,
            Source::Previous => GL_PREVIOUS,
        }
    }
}

impl Operand {
    /// From a GL enum; alpha operands may only be the alpha ones.
    pub fn from_gl(e: u32, alpha: bool) -> Option<Operand> {
        Some(match e {
            GL_SRC_COLOR if !alpha => Operand::SrcColor,
            GL_ONE_MINUS_SRC_COLOR if !alpha => Operand::OneMinusSrcColor,
            GL_SRC_ALPHA => Operand::SrcAlpha,
            GL_ONE_MINUS_SRC_ALPHA => Operand::OneMinusSrcAlpha,
            _ => return None,
        })
    }
    /// To the GL enum.
    pub fn to_gl(self) -> u32 {
        match self {
            Operand::SrcColor => GL_SRC_COLOR,
            Operand::OneMinusSrcColor => GL_ONE_MINUS_SRC_COLOR,
            Operand::SrcAlpha => GL_SRC_ALPHA,
            Operand::OneMinusSrcAlpha => GL_ONE_MINUS_SRC_ALPHA,
        }
    }
}

impl TextureState {
    /// glBindTexture on `unit`.
    pub fn bind(&mut self, unit: usize, target: Target, name: u32) -> GlResult<()> {
        if name != 0 {
            match self.objects.get(&name).map(|o| o.target) {
                Some(Some(t)) if t != target => return Err(GlError::InvalidOperation),
                Some(Some(_)) => {}
                Some(None) => {
                    *self.objects.get_mut(&name).expect("present") =
                        TextureObject::new(Some(target));
                }
                None => {
                    self.objects.insert(name, TextureObject::new(Some(target)));
                }
            }
        }
        self.units[unit].bound[target.index()] = name;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bind_target_mismatch_and_delete_unbinds() {
        let mut ts = TextureState::default();
        let n = ts.gen(2);
        assert!(!ts.is_texture(n[0]));
        ts.bind(0, Target::Tex2D, n[0]).unwrap();
        assert!(ts.is_texture(n[0]));
        assert_eq!(
            ts.bind(1, Target::Tex1D, n[0]),
            Err(GlError::InvalidOperation)
        );
        ts.bind(3, Target::Tex2D, n[0]).unwrap();
        ts.delete(&[n[0]]);
        assert_eq!(ts.units[0].bound[1], 0);
        assert_eq!(ts.units[3].bound[1], 0);
        assert!(!ts.is_texture(n[0]));
    }
}
