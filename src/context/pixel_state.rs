//! Raster position state (glRasterPos, glWindowPos) and pixel-rectangle modes
//! (glPixelZoom), with Mesa's initial values (`main/context.c`, `main/pixel.c`).
//!
//! [`RasterPos`] belongs to GL_CURRENT_BIT and [`PixelModes`] to GL_PIXEL_MODE_BIT; both
//! are plain `Clone` data for glPushAttrib.

use super::error::GlResult;
use super::get::Value;
use super::state::MAX_TEXTURE_UNITS;
use crate::gl::enums::*;

/// GL_CURRENT_RASTER_SECONDARY_COLOR (GL 3.0 compatibility token, not in gl.h).
pub const GL_CURRENT_RASTER_SECONDARY_COLOR: u32 = 0x845F;

/// The current raster position and the attributes latched with it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterPos {
    /// Window x, y (GL y-up), z in [0,1], and the clip w.
    pub pos: [f32; 4],
    /// GL_CURRENT_RASTER_POSITION_VALID
    pub valid: bool,
    /// GL_CURRENT_RASTER_COLOR
    pub color: [f32; 4],
    /// GL_CURRENT_RASTER_SECONDARY_COLOR
    pub secondary: [f32; 4],
    /// GL_CURRENT_RASTER_DISTANCE
    pub distance: f32,
    /// GL_CURRENT_RASTER_TEXTURE_COORDS per texture unit.
    pub texcoords: [[f32; 4]; MAX_TEXTURE_UNITS],
}

impl Default for RasterPos {
    fn default() -> Self {
        RasterPos {
            pos: [0.0, 0.0, 0.0, 1.0],
            valid: true,
            color: [1.0; 4],
            secondary: [0.0, 0.0, 0.0, 1.0],
            distance: 0.0,
            texcoords: [[0.0, 0.0, 0.0, 1.0]; MAX_TEXTURE_UNITS],
        }
    }
}

/// Pixel-rectangle modes (GL_PIXEL_MODE_BIT).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelModes {
    /// GL_ZOOM_X, GL_ZOOM_Y
    pub zoom: [f32; 2],
    /// glPixelTransfer state.
    pub transfer: super::pixel_transfer::PixelTransfer,
}

impl Default for PixelModes {
    fn default() -> Self {
        PixelModes {
            zoom: [1.0, 1.0],
            transfer: Default::default(),
        }
    }
}

/// The raster and pixel-mode values of glGet*, or `None` for other names.
pub fn get(rp: &RasterPos, pm: &PixelModes, unit: usize, pname: u32) -> Option<GlResult<Value>> {
    use super::get::Kind;
    let f = |v: &[f32]| Value::from_f32(Kind::Float, v);
    let n = |v: &[f32]| Value::from_f32(Kind::Normalized, v);
    Some(Ok(match pname {
        GL_CURRENT_RASTER_POSITION => f(&rp.pos),
        GL_CURRENT_RASTER_POSITION_VALID => Value::from_f32(Kind::Bool, &[rp.valid as u8 as f32]),
        GL_CURRENT_RASTER_COLOR => n(&rp.color),
        GL_CURRENT_RASTER_SECONDARY_COLOR => n(&rp.secondary),
        GL_CURRENT_RASTER_DISTANCE => f(&[rp.distance]),
        GL_CURRENT_RASTER_TEXTURE_COORDS => f(&rp.texcoords[unit]),
        GL_CURRENT_RASTER_INDEX => f(&[1.0]),
        GL_ZOOM_X => f(&[pm.zoom[0]]),
        GL_ZOOM_Y => f(&[pm.zoom[1]]),
        _ => return pm.transfer.get(pname).map(Ok),
    }))
}
