//! The enable bits of glEnable/glDisable as plain data: which capability, and the set.
//! Their GL tokens (`CAPS`, `Cap::from_gl`) stay with the state.

/// The capabilities of glEnable/glDisable/glIsEnabled that GL 1.5 defines, and GL 2.0's
/// point sprite and vertex program enables.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
#[allow(missing_docs)]
pub enum Cap {
    AlphaTest,
    AutoNormal,
    Blend,
    ColorLogicOp,
    ColorMaterial,
    ColorSum,
    CullFace,
    DepthTest,
    Dither,
    Fog,
    /// GL_FRAMEBUFFER_SRGB (ARB/EXT_framebuffer_sRGB): sRGB colour buffers encode writes.
    FramebufferSrgb,
    Lighting,
    LineSmooth,
    LineStipple,
    IndexLogicOp,
    Multisample,
    Normalize,
    PointSmooth,
    /// GL_POINT_SPRITE (GL 2.0, ARB_point_sprite): points are squares with the
    /// fill rule, and units with GL_COORD_REPLACE get coordinates across them.
    PointSprite,
    /// GL_VERTEX_PROGRAM_POINT_SIZE (GL 2.0): a vertex shader's `gl_PointSize` sizes points.
    VertexProgramPointSize,
    /// GL_VERTEX_PROGRAM_TWO_SIDE (GL 2.0): back-facing triangles take a vertex shader's
    /// `gl_BackColor` and `gl_BackSecondaryColor`.
    VertexProgramTwoSide,
    PolygonOffsetFill,
    PolygonOffsetLine,
    PolygonOffsetPoint,
    PolygonSmooth,
    PolygonStipple,
    RescaleNormal,
    SampleAlphaToCoverage,
    SampleAlphaToOne,
    SampleCoverage,
    ScissorTest,
    StencilTest,
    Texture1D,
    Texture2D,
    Texture3D,
    TextureCubeMap,
    TexGenS,
    TexGenT,
    TexGenR,
    TexGenQ,
    Map1Color4,
    Map1Index,
    Map1Normal,
    Map1TexCoord1,
    Map1TexCoord2,
    Map1TexCoord3,
    Map1TexCoord4,
    Map1Vertex3,
    Map1Vertex4,
    Map2Color4,
    Map2Index,
    Map2Normal,
    Map2TexCoord1,
    Map2TexCoord2,
    Map2TexCoord3,
    Map2TexCoord4,
    Map2Vertex3,
    Map2Vertex4,
    ClipPlane0,
    ClipPlane1,
    ClipPlane2,
    ClipPlane3,
    ClipPlane4,
    ClipPlane5,
    ClipPlane6,
    ClipPlane7,
    Light0,
    Light1,
    Light2,
    Light3,
    Light4,
    Light5,
    Light6,
    Light7,
}

/// How many [`Cap`]s there are.
pub const CAP_COUNT: usize = Cap::Light7 as usize + 1;

/// The enable bits, indexed by [`Cap`].
#[derive(Clone, Debug)]
pub struct Caps([bool; CAP_COUNT]);

impl Default for Caps {
    fn default() -> Self {
        let mut c = Caps([false; CAP_COUNT]);
        // Mesa's initial state: dithering and multisampling are on (both have no effect).
        c.set(Cap::Dither, true);
        c.set(Cap::Multisample, true);
        c
    }
}

impl Caps {
    /// Whether `cap` is enabled.
    #[inline]
    pub fn get(&self, cap: Cap) -> bool {
        self.0[cap as usize]
    }
    /// Enables or disables `cap`.
    pub fn set(&mut self, cap: Cap, on: bool) {
        self.0[cap as usize] = on;
    }
}
