//! The GL state as plain data; `Default` is GL's initial state (as Mesa initialises it).
//!
//! GL enums become the Rust enums below at the C boundary (`CompareFunc::from_gl(e)?`), so
//! the pipeline never looks at raw GL values.

use super::error::{GlError, GlResult};
use crate::gl::enums::*;
use crate::gl::glext_enums::*;
use crate::gl::types::GLenum;
pub use crate::pipe::CompareFunc;
pub use crate::pipe::{Cap, Caps};
pub use crate::pipe::{CurrentAttribs, Face, Primitive, ShadeModel, MAX_TEXTURE_UNITS};

impl CompareFunc {
    /// Converts a GL_NEVER..GL_ALWAYS token.
    pub fn from_gl(e: GLenum) -> GlResult<Self> {
        Ok(match e {
            GL_NEVER => Self::Never,
            GL_LESS => Self::Less,
            GL_EQUAL => Self::Equal,
            GL_LEQUAL => Self::LEqual,
            GL_GREATER => Self::Greater,
            GL_NOTEQUAL => Self::NotEqual,
            GL_GEQUAL => Self::GEqual,
            GL_ALWAYS => Self::Always,
            _ => return Err(GlError::InvalidEnum),
        })
    }
    /// The GL token for glGet.
    pub fn to_gl(self) -> GLenum {
        match self {
            Self::Never => GL_NEVER,
            Self::Less => GL_LESS,
            Self::Equal => GL_EQUAL,
            Self::LEqual => GL_LEQUAL,
            Self::Greater => GL_GREATER,
            Self::NotEqual => GL_NOTEQUAL,
            Self::GEqual => GL_GEQUAL,
            Self::Always => GL_ALWAYS,
        }
    }
}
impl Face {
    /// Converts GL_FRONT/GL_BACK/GL_FRONT_AND_BACK.
    pub fn from_gl(e: GLenum) -> GlResult<Self> {
        Ok(match e {
            GL_FRONT => Self::Front,
            GL_BACK => Self::Back,
            GL_FRONT_AND_BACK => Self::FrontAndBack,
            _ => return Err(GlError::InvalidEnum),
        })
    }
    /// The GL token.
    pub fn to_gl(self) -> GLenum {
        match self {
            Self::Front => GL_FRONT,
            Self::Back => GL_BACK,
            Self::FrontAndBack => GL_FRONT_AND_BACK,
        }
    }
}
impl Primitive {
    /// Converts GL_POINTS..GL_POLYGON.
    pub fn from_gl(e: GLenum) -> GlResult<Self> {
        Ok(match e {
            GL_POINTS => Self::Points,
            GL_LINES => Self::Lines,
            GL_LINE_LOOP => Self::LineLoop,
            GL_LINE_STRIP => Self::LineStrip,
            GL_TRIANGLES => Self::Triangles,
            GL_TRIANGLE_STRIP => Self::TriangleStrip,
            GL_TRIANGLE_FAN => Self::TriangleFan,
            GL_QUADS => Self::Quads,
            GL_QUAD_STRIP => Self::QuadStrip,
            GL_POLYGON => Self::Polygon,
            _ => return Err(GlError::InvalidEnum),
        })
    }
}
/// Which matrix stack glMatrixMode selects.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MatrixMode {
    /// GL_MODELVIEW
    ModelView,
    /// GL_PROJECTION
    Projection,
    /// GL_TEXTURE (of the active texture unit)
    Texture,
    /// GL_COLOR (ARB_imaging colour matrix)
    Color,
}

/// Every [`Cap`] with its GL token, in declaration order (index = `Cap as usize`).
pub const CAPS: &[(Cap, GLenum)] = &[
    (Cap::AlphaTest, GL_ALPHA_TEST),
    (Cap::AutoNormal, GL_AUTO_NORMAL),
    (Cap::Blend, GL_BLEND),
    (Cap::ColorLogicOp, GL_COLOR_LOGIC_OP),
    (Cap::ColorMaterial, GL_COLOR_MATERIAL),
    (Cap::ColorSum, GL_COLOR_SUM),
    (Cap::CullFace, GL_CULL_FACE),
    (Cap::DepthTest, GL_DEPTH_TEST),
    (Cap::Dither, GL_DITHER),
    (Cap::Fog, GL_FOG),
    (
        Cap::FramebufferSrgb,
        crate::gl::glext_enums::GL_FRAMEBUFFER_SRGB,
    ),
    (Cap::Lighting, GL_LIGHTING),
    (Cap::LineSmooth, GL_LINE_SMOOTH),
    (Cap::LineStipple, GL_LINE_STIPPLE),
    (Cap::IndexLogicOp, GL_INDEX_LOGIC_OP),
    (Cap::Multisample, GL_MULTISAMPLE),
    (Cap::Normalize, GL_NORMALIZE),
    (Cap::PointSmooth, GL_POINT_SMOOTH),
    (Cap::PointSprite, super::point_sprite::GL_POINT_SPRITE),
    (
        Cap::VertexProgramPointSize,
        super::point_sprite::GL_VERTEX_PROGRAM_POINT_SIZE,
    ),
    (
        Cap::VertexProgramTwoSide,
        super::point_sprite::GL_VERTEX_PROGRAM_TWO_SIDE,
    ),
    (Cap::PolygonOffsetFill, GL_POLYGON_OFFSET_FILL),
    (Cap::PolygonOffsetLine, GL_POLYGON_OFFSET_LINE),
    (Cap::PolygonOffsetPoint, GL_POLYGON_OFFSET_POINT),
    (Cap::PolygonSmooth, GL_POLYGON_SMOOTH),
    (Cap::PolygonStipple, GL_POLYGON_STIPPLE),
    (Cap::RescaleNormal, GL_RESCALE_NORMAL),
    (Cap::SampleAlphaToCoverage, GL_SAMPLE_ALPHA_TO_COVERAGE),
    (Cap::SampleAlphaToOne, GL_SAMPLE_ALPHA_TO_ONE),
    (Cap::SampleCoverage, GL_SAMPLE_COVERAGE),
    (Cap::ScissorTest, GL_SCISSOR_TEST),
    (Cap::StencilTest, GL_STENCIL_TEST),
    (Cap::Texture1D, GL_TEXTURE_1D),
    (Cap::Texture2D, GL_TEXTURE_2D),
    (Cap::Texture3D, GL_TEXTURE_3D),
    (Cap::TextureCubeMap, GL_TEXTURE_CUBE_MAP),
    (Cap::TexGenS, GL_TEXTURE_GEN_S),
    (Cap::TexGenT, GL_TEXTURE_GEN_T),
    (Cap::TexGenR, GL_TEXTURE_GEN_R),
    (Cap::TexGenQ, GL_TEXTURE_GEN_Q),
    (Cap::Map1Color4, GL_MAP1_COLOR_4),
    (Cap::Map1Index, GL_MAP1_INDEX),
    (Cap::Map1Normal, GL_MAP1_NORMAL),
    (Cap::Map1TexCoord1, GL_MAP1_TEXTURE_COORD_1),
    (Cap::Map1TexCoord2, GL_MAP1_TEXTURE_COORD_2),
    (Cap::Map1TexCoord3, GL_MAP1_TEXTURE_COORD_3),
    (Cap::Map1TexCoord4, GL_MAP1_TEXTURE_COORD_4),
    (Cap::Map1Vertex3, GL_MAP1_VERTEX_3),
    (Cap::Map1Vertex4, GL_MAP1_VERTEX_4),
    (Cap::Map2Color4, GL_MAP2_COLOR_4),
    (Cap::Map2Index, GL_MAP2_INDEX),
    (Cap::Map2Normal, GL_MAP2_NORMAL),
    (Cap::Map2TexCoord1, GL_MAP2_TEXTURE_COORD_1),
    (Cap::Map2TexCoord2, GL_MAP2_TEXTURE_COORD_2),
    (Cap::Map2TexCoord3, GL_MAP2_TEXTURE_COORD_3),
    (Cap::Map2TexCoord4, GL_MAP2_TEXTURE_COORD_4),
    (Cap::Map2Vertex3, GL_MAP2_VERTEX_3),
    (Cap::Map2Vertex4, GL_MAP2_VERTEX_4),
    (Cap::ClipPlane0, GL_CLIP_PLANE0),
    (Cap::ClipPlane1, GL_CLIP_PLANE1),
    (Cap::ClipPlane2, GL_CLIP_PLANE2),
    (Cap::ClipPlane3, GL_CLIP_PLANE3),
    (Cap::ClipPlane4, GL_CLIP_PLANE4),
    (Cap::ClipPlane5, GL_CLIP_PLANE5),
    (Cap::ClipPlane6, GL_CLIP_PLANE0 + 6),
    (Cap::ClipPlane7, GL_CLIP_PLANE0 + 7),
    (Cap::Light0, GL_LIGHT0),
    (Cap::Light1, GL_LIGHT1),
    (Cap::Light2, GL_LIGHT2),
    (Cap::Light3, GL_LIGHT3),
    (Cap::Light4, GL_LIGHT4),
    (Cap::Light5, GL_LIGHT5),
    (Cap::Light6, GL_LIGHT6),
    (Cap::Light7, GL_LIGHT7),
];

// The token table names every capability, in order.
const _: () = assert!(CAPS.len() == crate::pipe::CAP_COUNT);

/// The index `i` of the token `first + i` of a family of `count` (GL_LIGHTi,
/// GL_CLIP_PLANEi, GL_TEXTUREi); any other token is GL_INVALID_ENUM.
pub fn token_index(e: GLenum, first: GLenum, count: usize) -> GlResult<usize> {
    let i = e.wrapping_sub(first) as usize;
    if i < count {
        Ok(i)
    } else {
        Err(GlError::InvalidEnum)
    }
}

impl Cap {
    /// Converts a glEnable token.
    pub fn from_gl(e: GLenum) -> GlResult<Self> {
        CAPS.iter()
            .find(|(_, g)| *g == e)
            .map(|(c, _)| *c)
            .ok_or(GlError::InvalidEnum)
    }
}

/// The pixel-store parameters of one direction (pack or unpack).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelStore {
    /// GL_*_SWAP_BYTES
    pub swap_bytes: bool,
    /// GL_*_LSB_FIRST
    pub lsb_first: bool,
    /// GL_*_ROW_LENGTH (0 = the image width)
    pub row_length: i32,
    /// GL_*_SKIP_ROWS
    pub skip_rows: i32,
    /// GL_*_SKIP_PIXELS
    pub skip_pixels: i32,
    /// GL_*_ALIGNMENT (1, 2, 4 or 8)
    pub alignment: i32,
    /// GL_*_IMAGE_HEIGHT
    pub image_height: i32,
    /// GL_*_SKIP_IMAGES
    pub skip_images: i32,
    /// The buffer object bound to GL_PIXEL_PACK_BUFFER or GL_PIXEL_UNPACK_BUFFER (0 for
    /// none): a pixel command's pointer is then an offset into its store. Kept here, as
    /// Mesa does, so that glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT) saves it.
    pub buffer: u32,
}

impl Default for PixelStore {
    fn default() -> Self {
        PixelStore {
            swap_bytes: false,
            lsb_first: false,
            row_length: 0,
            skip_rows: 0,
            skip_pixels: 0,
            alignment: 4,
            image_height: 0,
            skip_images: 0,
            buffer: 0,
        }
    }
}

/// The hints of glHint, stored as given (llvmpipe ignores them).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub struct Hints {
    pub perspective_correction: GLenum,
    pub point_smooth: GLenum,
    pub line_smooth: GLenum,
    pub polygon_smooth: GLenum,
    pub fog: GLenum,
    pub generate_mipmap: GLenum,
    pub texture_compression: GLenum,
    pub fragment_shader_derivative: GLenum,
}

impl Default for Hints {
    fn default() -> Self {
        Hints {
            perspective_correction: GL_DONT_CARE,
            point_smooth: GL_DONT_CARE,
            line_smooth: GL_DONT_CARE,
            polygon_smooth: GL_DONT_CARE,
            fog: GL_DONT_CARE,
            generate_mipmap: GL_DONT_CARE,
            texture_compression: GL_DONT_CARE,
            fragment_shader_derivative: GL_DONT_CARE,
        }
    }
}

/// The whole fixed-function state that is not an object or a matrix stack.
#[derive(Clone, Debug)]
pub struct State {
    /// glEnable bits.
    pub caps: Caps,
    /// glClearColor, as given (ARB_color_buffer_float: float colour buffers clear to it
    /// unclamped; fixed-point ones clamp when packing, and glGet clamps for them).
    pub clear_color: [f32; 4],
    /// glClearDepth (clamped to [0,1]).
    pub clear_depth: f64,
    /// glClearStencil.
    pub clear_stencil: i32,
    /// glViewport x, y, width, height.
    pub viewport: [i32; 4],
    /// glDepthRange near, far (clamped to [0,1]).
    pub depth_range: [f64; 2],
    /// glClipControl: GL_UPPER_LEFT origin and GL_ZERO_TO_ONE depth mode (part of
    /// GL_TRANSFORM_BIT).
    pub clip_control: crate::geometry::ClipConvention,
    /// glDepthFunc.
    pub depth_func: CompareFunc,
    /// glDepthMask.
    pub depth_mask: bool,
    /// glColorMask r, g, b, a.
    pub color_mask: [bool; 4],
    /// Blending, alpha test, stencil and logic op.
    pub frag: super::fragment_state::FragmentOps,
    /// glScissor x, y, width, height.
    pub scissor: [i32; 4],
    /// glShadeModel.
    pub shade_model: ShadeModel,
    /// glCullFace.
    pub cull_face: Face,
    /// glFrontFace: true for GL_CCW.
    pub front_ccw: bool,
    /// glHint values.
    pub hints: Hints,
    /// glPixelStore for glReadPixels.
    pub pack: PixelStore,
    /// glPixelStore for uploads.
    pub unpack: PixelStore,
    /// Current vertex attributes.
    pub current: CurrentAttribs,
    /// glMatrixMode.
    pub matrix_mode: MatrixMode,
    /// glActiveTexture, as an index.
    pub active_texture: usize,
    /// glClientActiveTexture, as an index.
    pub client_active_texture: usize,
    /// Colour-index, sample-coverage and draw/read-buffer values.
    pub legacy: super::legacy_state::LegacyState,
}

impl State {
    /// The colour channels drawing writes: glColorMask, or none when glDrawBuffer is
    /// GL_NONE.
    pub fn color_write_mask(&self) -> [bool; 4] {
        if self.legacy.draws_color() {
            self.color_mask
        } else {
            [false; 4]
        }
    }
}

impl Default for State {
    fn default() -> Self {
        State {
            caps: Caps::default(),
            clear_color: [0.0; 4],
            clear_depth: 1.0,
            clear_stencil: 0,
            viewport: [0; 4],
            depth_range: [0.0, 1.0],
            clip_control: Default::default(),
            depth_func: CompareFunc::Less,
            depth_mask: true,
            color_mask: [true; 4],
            frag: Default::default(),
            scissor: [0; 4],
            shade_model: ShadeModel::Smooth,
            cull_face: Face::Back,
            front_ccw: true,
            hints: Hints::default(),
            pack: PixelStore::default(),
            unpack: PixelStore::default(),
            current: CurrentAttribs::default(),
            matrix_mode: MatrixMode::ModelView,
            active_texture: 0,
            client_active_texture: 0,
            legacy: Default::default(),
        }
    }
}
