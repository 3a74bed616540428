//! softglut: the GLUT API (freeglut's names, signatures and values) and GLU for
//! headless programs.
//!
//! Each window is an OSMesa context (RGBA, 24-bit depth, 8-bit stencil) rendering into
//! memory. `glutMainLoop` calls reshape once, then display for a fixed number of
//! frames and writes every frame as a PNG file; the GLUT clock advances by a fixed step
//! per frame, so every run writes identical files. The variables that configure a run
//! are read by [`config::Config::from_env`] (`SOFTGLUT_FRAMES`, `SOFTGLUT_OUTPUT`,
//! `SOFTGLUT_SIZE`, `SOFTGLUT_KEYS`, `SOFTGLUT_STEP_MS`).
//!
//! GL and OSMesa are called through undefined symbols (see [`gl`]), so the program's
//! link line decides which GL runs: `-lsoftglut -lsoftgl` or `-lsoftglut -lOSMesa`.

// The exported functions are C entry points: they take C's raw pointers by contract
// (documented per function, checked for NULL) and cannot be `unsafe fn` for C callers.
#![allow(clippy::not_unsafe_ptr_arg_deref)]

pub mod config;
pub mod font;
pub mod gl;
pub mod glu;
pub mod menu;
pub mod mipmap;
pub mod nurbs;
pub mod quadric;
pub mod shapes;
pub mod teapot;
pub mod tess;
pub mod window;
