//! softgl: a software OpenGL 1.5 implementation with Mesa's OSMesa API.
//!
//! A GL call enters at the C boundary ([`ffi`]), which validates and converts raw GL values
//! into Rust types and calls a safe method of the thread's current [`context::Context`]. The
//! context is the GL state machine: plain state data, named objects (buffers) and the
//! [`framebuffer`] the OSMesa user buffer is copied from on glFlush/glFinish.
//!
//! A draw call flows through the stages in lecture order: [`geometry::fetch`] reads vertices
//! (immediate mode, client arrays, buffer objects), [`fixed_function`] transforms them into
//! clip space, [`geometry::assemble`] builds triangles in llvmpipe's vertex order,
//! [`geometry::clip`] clips them homogeneously, [`geometry::setup`] snaps them to 1/256 pixel
//! and builds integer edge functions and float plane equations, [`raster`] walks the covered
//! pixels and [`fragment`] runs the per-fragment operations chosen by a per-draw plan.
//!
//! The arithmetic follows Mesa's llvmpipe (the reference the C tests compare against) so
//! that images are bit-identical. The rules followed are written down in `docs/llvmpipe-rules.md`
//! (cited in module docs as "llvmpipe-rules §n") and, for framebuffer objects, blits and
//! multisampling, in `docs/fbo-rules.md`.

#![deny(unsafe_op_in_unsafe_fn)]
#![deny(clippy::undocumented_unsafe_blocks)]

pub mod context;
/// CPU detection at its first path: [`simd::cpu`].
pub use simd::cpu;
pub mod draw;
pub mod ffi;
pub mod fixed_function;
pub mod fragment;
pub mod framebuffer;
pub mod geometry;
pub mod memory;
pub mod pixels;
pub mod raster;
pub mod simd;
pub mod stats;
#[cfg(test)]
mod test_rng;

/// The library by its own name, so that test files shared with `tests/` compile here too.
#[cfg(test)]
extern crate self as softgl;
/// The 256 KiB-stack test in the unit profile (unoptimised): `tests/small_stack/scene.rs`.
#[cfg(test)]
#[path = "../tests/small_stack/scene.rs"]
mod small_stack;
pub mod texture;
