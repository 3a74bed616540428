//! softgl: a software OpenGL 1.5 implementation with Mesa's OSMesa API.
//!
//! # The layers
//!
//! A GL call travels down through five layers, and no module imports one above it
//! (`tests/layering.rs` fails on an upward `use`):
//!
//! 1. **The C boundary**, [`ffi`]: the `extern "C"` entry points with the Khronos names and
//!    types. Each reads its pointers, converts the raw values through [`gl`], makes one call
//!    on the thread's current [`context::Context`] and records the error for glGetError.
//! 2. **The state machine**, [`context`]: GL's semantics. Every command is validated and
//!    applied here (texture specification, framebuffer objects, display lists, queries,
//!    pixel packing), with Mesa's error codes and error order. A command that fails changes
//!    nothing.
//! 3. **The plan**, [`plan`]: once per draw, the context gathers references to its
//!    parameter blocks and [`plan::build`] makes the only translation from the state's
//!    values to the pipeline's: which vertex stages run, how primitives are assembled,
//!    which fragment operations and texture units are live. The plan is what the engine of
//!    a later stage compiles.
//! 4. **The pipeline**, in the order a vertex meets it ([`render`] runs a plan through
//!    it): [`geometry`] fetches, assembles
//!    and clips, [`fixed_function`] transforms, lights, fogs and generates texture
//!    coordinates, [`raster`] walks the covered pixels (in bands, on a thread pool),
//!    [`fragment`] runs the per-fragment operations, [`texture`] samples, [`pixels`] draws
//!    pixel rectangles and bitmaps, and [`framebuffer`] holds the colour, depth and stencil
//!    storage. The pipeline never sees a GL token or the GL state.
//! 5. **The leaves**: [`pipe`] (the vocabulary the plan and the pipeline share: compare
//!    functions, blend factors, primitives, limits, parameter blocks), [`gl`] (tokens, C
//!    types, [`gl::error::GlError`]), [`simd`] (the only home of intrinsics, and CPU
//!    detection in [`simd::cpu`]), [`tuning`]
//!    (every `SOFTGL_*` knob, read once), [`stats`] and [`memory`].
//!
//! # The reference
//!
//! The arithmetic follows Mesa's llvmpipe, which the C scenes in `c_tests/` compare against
//! pixel by pixel, so that images are bit-identical. The rules followed are written down in
//! `docs/llvmpipe-rules.md` (cited in module docs as "docs/llvmpipe-rules.md §n") and, for
//! framebuffer objects, blits and multisampling, in `docs/fbo-rules.md`.

#![deny(unsafe_op_in_unsafe_fn)]
#![deny(clippy::undocumented_unsafe_blocks)]

pub mod context;
pub mod engine;
/// CPU detection at its first path: [`simd::cpu`].
pub use simd::cpu;
pub mod ffi;
pub mod fixed_function;
pub mod fragment;
pub mod framebuffer;
pub mod geometry;
pub mod gl;
pub mod memory;
pub mod pipe;
pub mod pixels;
pub mod plan;
pub mod raster;
pub mod render;
pub mod shader;
pub mod simd;
pub mod stats;
#[cfg(test)]
mod test_rng;

pub mod texture;
pub mod tuning;
