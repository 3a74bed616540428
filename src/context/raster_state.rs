//! Rasterization state of lines, points and polygons (glLineWidth, glLineStipple,
//! glPointSize, glPolygonMode, glPolygonOffset, glPolygonStipple), one `Clone` struct per
//! glPushAttrib group: [`LineState`] (GL_LINE_BIT), [`PointState`] (GL_POINT_BIT),
//! [`PolygonState`] (GL_POLYGON_BIT) and [`PolygonStipple`] (GL_POLYGON_STIPPLE_BIT). The
//! enables of those groups live in the shared `Caps`.

use super::error::{GlError, GlResult};
use crate::gl::enums::*;
use crate::gl::types::GLenum;
pub use crate::pipe::{
    FillMode, LineState, PointState, PolygonState, PolygonStipple, RasterState, MAX_LINE_WIDTH,
    MAX_POINT_SIZE, SIZE_GRANULARITY,
};

/// A glPointParameter pname.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PointParam {
    /// GL_POINT_SIZE_MIN.
    SizeMin,
    /// GL_POINT_SIZE_MAX.
    SizeMax,
    /// GL_POINT_FADE_THRESHOLD_SIZE.
    FadeThreshold,
    /// GL_POINT_DISTANCE_ATTENUATION (three values).
    DistanceAttenuation,
    /// GL_POINT_SPRITE_COORD_ORIGIN (GL 2.0): GL_LOWER_LEFT or GL_UPPER_LEFT.
    SpriteCoordOrigin,
}

impl PointParam {
    /// Converts a pname (the ARB/EXT tokens share the values).
    pub fn from_gl(e: GLenum) -> GlResult<Self> {
        use crate::gl::glext_enums::*;
        Ok(match e {
            GL_POINT_SIZE_MIN => Self::SizeMin,
            GL_POINT_SIZE_MAX => Self::SizeMax,
            GL_POINT_FADE_THRESHOLD_SIZE => Self::FadeThreshold,
            GL_POINT_DISTANCE_ATTENUATION => Self::DistanceAttenuation,
            super::point_sprite::GL_POINT_SPRITE_COORD_ORIGIN => Self::SpriteCoordOrigin,
            _ => return Err(GlError::InvalidEnum),
        })
    }

    /// How many values the pname takes.
    pub fn count(self) -> usize {
        if self == Self::DistanceAttenuation {
            3
        } else {
            1
        }
    }
}

impl PointState {
    /// glPointParameterfv: negative sizes and thresholds are GL_INVALID_VALUE (NaN passes,
    /// as Mesa's `< 0` test lets it); the attenuation coefficients are not checked; an
    /// origin other than GL_LOWER_LEFT and GL_UPPER_LEFT is GL_INVALID_VALUE (Mesa's
    /// `points.c` converts the float to GLenum).
    pub fn set(&mut self, p: PointParam, v: [f32; 3]) -> GlResult<()> {
        if p == PointParam::SpriteCoordOrigin {
            use crate::gl::glext_enums::{GL_LOWER_LEFT, GL_UPPER_LEFT};
            self.sprite_upper_left = match v[0] as i64 as GLenum {
                GL_UPPER_LEFT => true,
                GL_LOWER_LEFT => false,
                _ => return Err(GlError::InvalidValue),
            };
            return Ok(());
        }
        if p != PointParam::DistanceAttenuation && v[0] < 0.0 {
            return Err(GlError::InvalidValue);
        }
        match p {
            PointParam::SizeMin => self.min_size = v[0],
            PointParam::SizeMax => self.max_size = v[0],
            PointParam::FadeThreshold => self.fade_threshold = v[0],
            PointParam::DistanceAttenuation => self.attenuation = v,
            PointParam::SpriteCoordOrigin => {}
        }
        Ok(())
    }
}
impl FillMode {
    /// Converts GL_POINT/GL_LINE/GL_FILL.
    pub fn from_gl(e: GLenum) -> GlResult<Self> {
        Ok(match e {
            GL_POINT => Self::Point,
            GL_LINE => Self::Line,
            GL_FILL => Self::Fill,
            _ => return Err(GlError::InvalidEnum),
        })
    }
    /// The GL token.
    pub fn to_gl(self) -> GLenum {
        match self {
            Self::Point => GL_POINT,
            Self::Line => GL_LINE,
            Self::Fill => GL_FILL,
        }
    }
}
