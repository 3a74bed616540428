//! Pixel rectangles in the pipeline: the textured quad of glDrawPixels, glCopyPixels and
//! glBitmap with its zoom and per-fragment operations ([`rect`], [`draw`]), the decoded
//! client images they draw ([`image`]) and glBlitFramebuffer's clipping, resolve and copy
//! ([`blit`], [`resolve`]). Colour and bitmap fragments run 8 at a time in AVX2 registers where
//! the level has it ([`simd`]). Everything here takes plain values; reading the GL state (raster position,
//! pixel transfer, the bitmap cache) is `context::pixel_ops`'s work, and decoding client
//! memory `context::pack`'s.

pub mod blit;
pub mod blit_srgb;
pub mod draw;
pub mod image;
pub mod rect;
pub mod resolve;
pub mod simd;
