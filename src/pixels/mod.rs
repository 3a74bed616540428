//! Pixel rectangles and the raster position: glRasterPos/glWindowPos ([`raster_pos`],
//! computed in C arithmetic on the CPU, as Mesa's `main/rastpos.c` does for fixed function,
//! not through the vertex program); glDrawPixels, glCopyPixels and glBitmap drawn as Mesa's
//! state tracker draws them ([`draw`]: decoded client images in [`image`], the textured
//! rectangle in [`rect`], the bitmap cache in [`cache`]); and glBlitFramebuffer ([`blit`]).

pub mod blit;
pub mod cache;
pub mod draw;
pub mod image;
pub mod raster_pos;
pub mod rect;
