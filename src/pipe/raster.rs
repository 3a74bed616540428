//! Line, point and polygon rasterization parameters and their limits.

#[allow(unused_imports)]
use super::*;

/// Mesa's implementation limits for llvmpipe (`PIPE_CAPF_MAX_LINE_WIDTH`,
/// `PIPE_CAPF_MAX_POINT_SIZE` = 255, granularity 0.1).
pub const MAX_LINE_WIDTH: f32 = 255.0;

/// Largest point size (aliased and smooth).
pub const MAX_POINT_SIZE: f32 = 255.0;

/// GL_LINE_WIDTH_GRANULARITY and GL_POINT_SIZE_GRANULARITY.
pub const SIZE_GRANULARITY: f32 = 0.1;

/// GL_LINE_BIT state (besides the GL_LINE_SMOOTH / GL_LINE_STIPPLE enables).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LineState {
    /// glLineWidth as given (clamped only when drawing).
    pub width: f32,
    /// glLineStipple pattern.
    pub stipple_pattern: u16,
    /// glLineStipple factor, clamped to [1, 256].
    pub stipple_repeat: u32,
}

impl Default for LineState {
    fn default() -> Self {
        LineState {
            width: 1.0,
            stipple_pattern: 0xffff,
            stipple_repeat: 1,
        }
    }
}

/// GL_POINT_BIT state (besides the GL_POINT_SMOOTH enable).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointState {
    /// glPointSize as given.
    pub size: f32,
    /// GL_POINT_SIZE_MIN (glPointParameter).
    pub min_size: f32,
    /// GL_POINT_SIZE_MAX.
    pub max_size: f32,
    /// GL_POINT_FADE_THRESHOLD_SIZE (stored and queried; llvmpipe does not fade).
    pub fade_threshold: f32,
    /// GL_POINT_DISTANCE_ATTENUATION: constant, linear and quadratic coefficients.
    pub attenuation: [f32; 3],
    /// GL_POINT_SPRITE_COORD_ORIGIN is GL_UPPER_LEFT (the default): a sprite's `t` is 0
    /// at its top.
    pub sprite_upper_left: bool,
    /// GL_COORD_REPLACE of each texture unit (bit `u` for unit `u`), set with
    /// glTexEnv(GL_POINT_SPRITE, …) and kept with the point state, as Mesa does.
    pub coord_replace: u8,
}

impl Default for PointState {
    fn default() -> Self {
        PointState {
            size: 1.0,
            min_size: 0.0,
            max_size: MAX_POINT_SIZE,
            fade_threshold: 1.0,
            attenuation: [1.0, 0.0, 0.0],
            sprite_upper_left: true,
            coord_replace: 0,
        }
    }
}

impl PointState {
    /// Whether the size is attenuated per vertex (Mesa's `Point._Attenuated`).
    pub fn attenuated(&self) -> bool {
        self.attenuation != [1.0, 0.0, 0.0]
    }

    /// The size llvmpipe rasterizes without attenuation: glPointSize clamped to
    /// [GL_POINT_SIZE_MIN, GL_POINT_SIZE_MAX] by Mesa's `CLAMP` macro (the minimum is
    /// tested first, so an inverted range still gives one of its ends).
    pub fn clamped_size(&self) -> f32 {
        if self.size < self.min_size {
            self.min_size
        } else if self.size > self.max_size {
            self.max_size
        } else {
            self.size
        }
    }
}

/// glPolygonMode's mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FillMode {
    /// Vertices as points.
    Point,
    /// Edges as lines.
    Line,
    /// Filled.
    Fill,
}

/// GL_POLYGON_BIT state owned here (cull face and front face stay in `State`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PolygonState {
    /// glPolygonMode for front faces.
    pub mode_front: FillMode,
    /// glPolygonMode for back faces.
    pub mode_back: FillMode,
    /// glPolygonOffset factor.
    pub offset_factor: f32,
    /// glPolygonOffset units.
    pub offset_units: f32,
}

impl Default for PolygonState {
    fn default() -> Self {
        PolygonState {
            mode_front: FillMode::Fill,
            mode_back: FillMode::Fill,
            offset_factor: 0.0,
            offset_units: 0.0,
        }
    }
}

/// GL_POLYGON_STIPPLE_BIT: the 32x32 pattern, one `u32` per row from the bottom, bit 31 =
/// leftmost pixel (the first byte's most significant bit).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PolygonStipple(pub [u32; 32]);

impl Default for PolygonStipple {
    fn default() -> Self {
        PolygonStipple([u32::MAX; 32])
    }
}

impl PolygonStipple {
    /// Whether window pixel (x, y) (GL y-up) passes the stipple.
    #[inline]
    pub fn passes(&self, x: i64, y: i64) -> bool {
        let row = self.0[(y & 31) as usize];
        row & (0x8000_0000u32 >> (x & 31)) != 0
    }

    /// [`Self::passes`] for the 8 pixels `x..x + 8` of row `y`, as bits (bit i: pixel
    /// `x + i`): the pattern's row reversed (its most significant bit is column 0) and
    /// rotated to `x`.
    #[inline]
    pub fn passes8(&self, x: i64, y: i64) -> u32 {
        let row = self.0[(y & 31) as usize].reverse_bits();
        row.rotate_right((x & 31) as u32) & 0xFF
    }
}

/// All of this module's state, as `Context::raster`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RasterState {
    /// Lines.
    pub line: LineState,
    /// Points.
    pub point: PointState,
    /// Polygon modes and offset.
    pub polygon: PolygonState,
    /// Polygon stipple pattern.
    pub stipple: PolygonStipple,
}

#[cfg(test)]
mod tests {
    use super::PolygonStipple;

    /// [`PolygonStipple::passes8`] gives [`PolygonStipple::passes`] for each of its
    /// pixels, at every alignment and across the pattern's wrap, negative x included.
    #[test]
    fn passes8_matches_passes() {
        let mut seed = 0x9E37_79B9u32;
        let mut p = PolygonStipple([0; 32]);
        for row in p.0.iter_mut() {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            *row = seed;
        }
        for y in -3..40 {
            for x in -40..80 {
                let bits = p.passes8(x, y);
                for i in 0..8 {
                    assert_eq!(
                        bits >> i & 1 == 1,
                        p.passes(x + i, y),
                        "x {x} y {y} lane {i}"
                    );
                }
            }
        }
    }
}
