//! Point sprites (GL 2.0, ARB_point_sprite): the tokens, and glTexEnv/glGetTexEnv of
//! GL_COORD_REPLACE. The enables are [`crate::pipe::Cap::PointSprite`] and
//! [`crate::pipe::Cap::VertexProgramPointSize`]; the origin and the replace bits live in
//! [`crate::pipe::PointState`] (GL_POINT_BIT), as in Mesa's `ctx->Point`.

use super::error::{GlError, GlResult};
use super::Context;
use crate::gl::enums::{GL_FALSE, GL_TRUE};

/// GL_POINT_SPRITE: the enable, and glTexEnv's target for GL_COORD_REPLACE.
pub const GL_POINT_SPRITE: u32 = 0x8861;
/// GL_COORD_REPLACE: a unit's coordinates are replaced across a sprite.
pub const GL_COORD_REPLACE: u32 = 0x8862;
/// GL_POINT_SPRITE_COORD_ORIGIN (glPointParameter).
pub const GL_POINT_SPRITE_COORD_ORIGIN: u32 = 0x8CA0;
/// GL_VERTEX_PROGRAM_POINT_SIZE: the enable of a vertex shader's `gl_PointSize`.
pub const GL_VERTEX_PROGRAM_POINT_SIZE: u32 = 0x8642;
/// GL_VERTEX_PROGRAM_TWO_SIDE: the enable of a vertex shader's back-face colours (kept
/// here with its neighbour token; the draw reads it in `plan`).
pub const GL_VERTEX_PROGRAM_TWO_SIDE: u32 = 0x8643;

impl Context {
    /// glTexEnv(GL_POINT_SPRITE, pname, v): only GL_COORD_REPLACE (else
    /// GL_INVALID_ENUM), GL_TRUE or GL_FALSE (else GL_INVALID_VALUE, after Mesa converts
    /// the value to an integer), for the active unit.
    pub(crate) fn tex_env_point_sprite(&mut self, pname: u32, v: f64) -> GlResult<()> {
        if pname != GL_COORD_REPLACE {
            return Err(GlError::InvalidEnum);
        }
        let on = match v as i64 {
            x if x == GL_TRUE as i64 => true,
            x if x == GL_FALSE as i64 => false,
            _ => return Err(GlError::InvalidValue),
        };
        let bit = 1u8 << self.state.active_texture;
        let p = &mut self.raster.point;
        p.coord_replace = if on {
            p.coord_replace | bit
        } else {
            p.coord_replace & !bit
        };
        Ok(())
    }

    /// glGetTexEnv(GL_POINT_SPRITE, GL_COORD_REPLACE) of the active unit.
    pub(crate) fn get_tex_env_point_sprite(&self, pname: u32) -> GlResult<f64> {
        if pname != GL_COORD_REPLACE {
            return Err(GlError::InvalidEnum);
        }
        Ok(f64::from(
            self.raster.point.coord_replace >> self.state.active_texture & 1,
        ))
    }
}
