//! Pixel-transfer state (glPixelTransfer, part of GL_PIXEL_MODE_BIT) and the pixel maps
//! (glPixelMap, in no attribute group), with Mesa's initial values and rules
//! (`main/pixel.c`, `main/pixeltransfer.c`).
//!
//! Numbers: colour maps store values clamped to [0, 1]; index maps store the values as
//! given; a lookup of colour `c` in a map of `n` entries reads entry
//! `round_half_even(clamp(c, 0, 1) · (n − 1))` on the CPU paths (Mesa's `_mesa_map_rgba`:
//! glReadPixels), while glDrawPixels/glCopyPixels look the red and green maps up in a
//! texture ([`PixelMaps::map_rg_texture`]; Mesa 22.3's blue and alpha lookup reads the
//! image instead, see `pixels::draw`).

use super::error::{GlError, GlResult};
use super::get::{Kind, Value};
use crate::gl::enums::*;

/// Mesa's MAX_PIXEL_MAP_TABLE.
pub const MAX_PIXEL_MAP_TABLE: usize = 256;

/// glPixelTransfer state (GL_PIXEL_MODE_BIT).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelTransfer {
    /// GL_RED/GREEN/BLUE/ALPHA_SCALE.
    pub scale: [f32; 4],
    /// GL_RED/GREEN/BLUE/ALPHA_BIAS.
    pub bias: [f32; 4],
    /// GL_DEPTH_SCALE.
    pub depth_scale: f32,
    /// GL_DEPTH_BIAS.
    pub depth_bias: f32,
    /// GL_MAP_COLOR.
    pub map_color: bool,
    /// GL_MAP_STENCIL.
    pub map_stencil: bool,
    /// GL_INDEX_SHIFT.
    pub index_shift: i32,
    /// GL_INDEX_OFFSET.
    pub index_offset: i32,
}

impl Default for PixelTransfer {
    fn default() -> Self {
        PixelTransfer {
            scale: [1.0; 4],
            bias: [0.0; 4],
            depth_scale: 1.0,
            depth_bias: 0.0,
            map_color: false,
            map_stencil: false,
            index_shift: 0,
            index_offset: 0,
        }
    }
}

impl PixelTransfer {
    /// Whether colour scale or bias is not the identity.
    pub fn scale_bias(&self) -> bool {
        self.scale != [1.0; 4] || self.bias != [0.0; 4]
    }

    /// Sets one parameter (glPixelTransferf); GL_INVALID_ENUM for unknown names.
    pub fn set(&mut self, pname: u32, v: f32) -> GlResult<()> {
        let chan = |p: u32| -> Option<(bool, usize)> {
            Some(match p {
                GL_RED_SCALE => (true, 0),
                GL_GREEN_SCALE => (true, 1),
                GL_BLUE_SCALE => (true, 2),
                GL_ALPHA_SCALE => (true, 3),
                GL_RED_BIAS => (false, 0),
                GL_GREEN_BIAS => (false, 1),
                GL_BLUE_BIAS => (false, 2),
                GL_ALPHA_BIAS => (false, 3),
                _ => return None,
            })
        };
        match pname {
            GL_MAP_COLOR => self.map_color = v != 0.0,
            GL_MAP_STENCIL => self.map_stencil = v != 0.0,
            GL_INDEX_SHIFT => self.index_shift = v as i32,
            GL_INDEX_OFFSET => self.index_offset = v as i32,
            GL_DEPTH_SCALE => self.depth_scale = v,
            GL_DEPTH_BIAS => self.depth_bias = v,
            p => match chan(p) {
                Some((true, c)) => self.scale[c] = v,
                Some((false, c)) => self.bias[c] = v,
                None => return Err(GlError::InvalidEnum),
            },
        }
        Ok(())
    }

    /// glGet of a transfer parameter, or `None` for other names.
    pub fn get(&self, pname: u32) -> Option<Value> {
        let f = |v: f32| Value::from_f32(Kind::Float, &[v]);
        let i = |v: i32| Value::from_f32(Kind::Int, &[v as f32]);
        Some(match pname {
            GL_MAP_COLOR => Value::from_f32(Kind::Bool, &[self.map_color as u8 as f32]),
            GL_MAP_STENCIL => Value::from_f32(Kind::Bool, &[self.map_stencil as u8 as f32]),
            GL_INDEX_SHIFT => i(self.index_shift),
            GL_INDEX_OFFSET => i(self.index_offset),
            GL_DEPTH_SCALE => f(self.depth_scale),
            GL_DEPTH_BIAS => f(self.depth_bias),
            GL_RED_SCALE => f(self.scale[0]),
            GL_GREEN_SCALE => f(self.scale[1]),
            GL_BLUE_SCALE => f(self.scale[2]),
            GL_ALPHA_SCALE => f(self.scale[3]),
            GL_RED_BIAS => f(self.bias[0]),
            GL_GREEN_BIAS => f(self.bias[1]),
            GL_BLUE_BIAS => f(self.bias[2]),
            GL_ALPHA_BIAS => f(self.bias[3]),
            _ => return None,
        })
    }

    /// `c · scale + bias` per channel (separate multiply and add, as Mesa's C and shader
    /// code compute it).
    #[inline]
    pub fn apply_scale_bias(&self, c: [f32; 4]) -> [f32; 4] {
        std::array::from_fn(|i| c[i] * self.scale[i] + self.bias[i])
    }

    /// GL_DEPTH_SCALE and GL_DEPTH_BIAS, or `None` when they are the identity.
    pub fn depth_scale_bias(&self) -> Option<(f32, f32)> {
        (self.depth_scale != 1.0 || self.depth_bias != 0.0)
            .then_some((self.depth_scale, self.depth_bias))
    }

    /// Depth scale and bias, clamped to [0,1].
    #[inline]
    pub fn apply_depth(&self, z: f32) -> f32 {
        (z * self.depth_scale + self.depth_bias).clamp(0.0, 1.0)
    }
}

/// The ten pixel maps, indexed by `pname - GL_PIXEL_MAP_I_TO_I`.
#[derive(Clone, Debug, PartialEq)]
pub struct PixelMaps {
    /// Values of each map (at least one entry each).
    pub maps: [Vec<f32>; 10],
}

impl Default for PixelMaps {
    fn default() -> Self {
        PixelMaps {
            maps: std::array::from_fn(|_| vec![0.0]),
        }
    }
}

/// The map index of a GL_PIXEL_MAP_* name.
pub fn map_index(pname: u32) -> GlResult<usize> {
    if (GL_PIXEL_MAP_I_TO_I..=GL_PIXEL_MAP_A_TO_A).contains(&pname) {
        Ok((pname - GL_PIXEL_MAP_I_TO_I) as usize)
    } else {
        Err(GlError::InvalidEnum)
    }
}

/// Whether map `i` holds indices (I_TO_I, S_TO_S) rather than colours.
pub fn is_index_map(i: usize) -> bool {
    i < 2
}

impl PixelMaps {
    /// glPixelMap with values already converted to floats: the size must be 1..=256 and a
    /// power of two for the maps indexed by colour or stencil indices (I_TO_*, S_TO_S).
    pub fn set(&mut self, pname: u32, values: &[f32]) -> GlResult<()> {
        let i = map_index(pname)?;
        let n = values.len();
        if !(1..=MAX_PIXEL_MAP_TABLE).contains(&n) {
            return Err(GlError::InvalidValue);
        }
        let indexed = i < 6; // I_TO_I, S_TO_S, I_TO_R/G/B/A
        if indexed && !n.is_power_of_two() {
            return Err(GlError::InvalidValue);
        }
        self.maps[i] = if is_index_map(i) {
            values.to_vec()
        } else {
            values.iter().map(|v| v.clamp(0.0, 1.0)).collect()
        };
        Ok(())
    }

    /// Looks colour `c` up in the R/G/B/A_TO_* maps (channel `ch`).
    #[inline]
    pub fn map_color(&self, ch: usize, c: f32) -> f32 {
        let m = &self.maps[6 + ch];
        let n = (m.len() - 1) as f32;
        let i = (c.clamp(0.0, 1.0) * n).round_ties_even() as usize;
        m[i.min(m.len() - 1)]
    }

    /// Maps a colour through the four colour maps.
    pub fn map_rgba(&self, c: [f32; 4]) -> [f32; 4] {
        std::array::from_fn(|ch| self.map_color(ch, c[ch]))
    }

    /// Maps red and green as llvmpipe's glDrawPixels/glCopyPixels shader does
    /// (`nir_lower_drawpixels.c`, `st_atom_pixeltransfer.c`): the maps live in a 256×256
    /// RGBA8 texture whose entry j holds `map[j·n/256]` packed with gallium's
    /// `float_to_ubyte`, sampled NEAREST with CLAMP_TO_EDGE at the colour itself (entry
    /// `clamp(floor(c·256), 0, 255)`), and read back as `u·f32(1/255)`. (Blue and alpha are
    /// not looked up in the maps by Mesa 22.3: see `pixels::draw`.)
    pub fn map_rg_texture(&self, c: [f32; 4]) -> [f32; 2] {
        std::array::from_fn(|ch| {
            let m = &self.maps[6 + ch];
            let j = (c[ch].clamp(-1.0, 2.0) * 256.0).floor().clamp(0.0, 255.0) as usize;
            let u = crate::framebuffer::clear_float_to_ubyte(m[j * m.len() / 256]);
            u as f32 * (1.0f32 / 255.0)
        })
    }

    /// Looks stencil index `s` up in S_TO_S (masked by the table size).
    pub fn map_stencil(&self, s: i64) -> i64 {
        let m = &self.maps[1];
        m[(s as usize) & (m.len() - 1)] as i64
    }

    /// GL_PIXEL_MAP_*_SIZE, or `None` for other names.
    pub fn get(&self, pname: u32) -> Option<Value> {
        if (GL_PIXEL_MAP_I_TO_I_SIZE..=GL_PIXEL_MAP_A_TO_A_SIZE).contains(&pname) {
            let n = self.maps[(pname - GL_PIXEL_MAP_I_TO_I_SIZE) as usize].len();
            return Some(Value::from_f32(Kind::Int, &[n as f32]));
        }
        if pname == GL_MAX_PIXEL_MAP_TABLE {
            return Some(Value::from_f32(Kind::Int, &[MAX_PIXEL_MAP_TABLE as f32]));
        }
        None
    }
}

/// Applies index shift and offset, then (with GL_MAP_STENCIL) the S_TO_S map, to a stencil
/// index (Mesa's `_mesa_apply_stencil_transfer_ops`).
pub fn stencil_transfer(t: &PixelTransfer, maps: &PixelMaps, s: i64) -> i64 {
    let mut s = s;
    if t.index_shift != 0 || t.index_offset != 0 {
        s = if t.index_shift > 0 {
            s << t.index_shift.min(31)
        } else {
            s >> (-t.index_shift).min(31)
        } + t.index_offset as i64;
    }
    if t.map_stencil {
        s = maps.map_stencil(s);
    }
    s
}
