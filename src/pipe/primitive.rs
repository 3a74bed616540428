//! Primitives, faces, shading and the current vertex attributes.

#[allow(unused_imports)]
use super::*;

/// glShadeModel.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShadeModel {
    /// Colours come from the provoking vertex.
    Flat,
    /// Colours are interpolated.
    Smooth,
}

/// A polygon face selector (glCullFace).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Face {
    /// Front faces.
    Front,
    /// Back faces.
    Back,
    /// Both.
    FrontAndBack,
}

/// The primitive type of glBegin and the draw calls.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Primitive {
    /// GL_POINTS
    Points,
    /// GL_LINES
    Lines,
    /// GL_LINE_LOOP
    LineLoop,
    /// GL_LINE_STRIP
    LineStrip,
    /// GL_TRIANGLES
    Triangles,
    /// GL_TRIANGLE_STRIP
    TriangleStrip,
    /// GL_TRIANGLE_FAN
    TriangleFan,
    /// GL_QUADS
    Quads,
    /// GL_QUAD_STRIP
    QuadStrip,
    /// GL_POLYGON
    Polygon,
}

/// The current vertex attributes (what glColor/glNormal/glTexCoord set).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurrentAttribs {
    /// GL_CURRENT_COLOR
    pub color: [f32; 4],
    /// GL_CURRENT_SECONDARY_COLOR
    pub secondary_color: [f32; 4],
    /// GL_CURRENT_NORMAL
    pub normal: [f32; 3],
    /// GL_CURRENT_TEXTURE_COORDS per texture unit
    pub texcoord: [[f32; 4]; MAX_TEXTURE_UNITS],
    /// GL_CURRENT_FOG_COORD
    pub fog_coord: f32,
    /// GL_EDGE_FLAG
    pub edge_flag: bool,
    /// GL_CURRENT_INDEX (kept for glGet; an RGBA context draws nothing with it)
    pub index: f32,
}

/// The number of texture units (Mesa's fixed-function count is 8).
pub const MAX_TEXTURE_UNITS: usize = 8;

impl Default for CurrentAttribs {
    fn default() -> Self {
        CurrentAttribs {
            color: [1.0; 4],
            secondary_color: [0.0, 0.0, 0.0, 1.0],
            normal: [0.0, 0.0, 1.0],
            texcoord: [[0.0, 0.0, 0.0, 1.0]; MAX_TEXTURE_UNITS],
            fog_coord: 0.0,
            edge_flag: true,
            index: 1.0,
        }
    }
}
