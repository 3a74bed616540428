//! softgl's GLSL front end: shading-language source in, checked program out, for
//! versions 1.10, 1.20, 1.30, 1.40, 1.50 and 3.30 (issue 43).
//!
//! The crate knows nothing of GL state or of the engine: it turns the source strings of
//! a shader into a typed syntax tree, or into an info log worded like Mesa's
//! (`0:LINE(COLUMN): error: ...`). softgl itself lowers the checked tree into the
//! engine's IR. It is its own crate so that it builds and tests in seconds, apart from
//! the rasterizer's long optimised build.
//!
//! The stages, each its own module, every arrow pointing down:
//! 1. the preprocessor (`#version`, macros, conditionals, `#extension`, `#line`);
//! 2. the lexer and the parser, into a syntax tree that keeps source positions;
//! 3. the type checker with each version's built-in functions and variables and its
//!    implicit conversions.
//!
//! Nothing here panics or loops without bound on any input: nesting depth, macro
//! expansion and source length are limited, and the tests feed random input.
//!
//! The reference for what is accepted and how errors read is Mesa's own compiler, run
//! by the integration tests through OSMesa (`tests/mesa/`).

pub mod builtins;
pub mod types;
