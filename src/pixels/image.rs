//! Client images of glDrawPixels and glBitmap as the pipeline draws them: decoded values,
//! row 0 first (the bottom row). The decoding from client memory is GL's unpacking and
//! lives in `context::pack::draw_image`.

/// What a decoded image holds.
#[derive(Clone, Debug, PartialEq)]
pub enum Pixels {
    /// RGBA colours.
    Color(Vec<[f32; 4]>),
    /// Colour indices (GL_COLOR_INDEX).
    Index(Vec<i64>),
    /// Depth values (GL_DEPTH_COMPONENT).
    Depth(Vec<f32>),
    /// Stencil indices (GL_STENCIL_INDEX).
    Stencil(Vec<i64>),
}

/// A decoded `w` x `h` image, row 0 first (the bottom row).
#[derive(Clone, Debug, PartialEq)]
pub struct Image {
    /// Width.
    pub w: usize,
    /// Height.
    pub h: usize,
    /// The values.
    pub pixels: Pixels,
}
