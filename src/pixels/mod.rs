//! Pixel rectangles and the raster position: glRasterPos/glWindowPos (computed in C
//! arithmetic on the CPU, as Mesa's `main/rastpos.c` does for fixed function, not through
//! the vertex program) and, later, glDrawPixels, glBitmap and glCopyPixels.

pub mod blit;
pub mod cache;
pub mod draw;
pub mod image;
pub mod raster_pos;
pub mod rect;
