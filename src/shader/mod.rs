//! GLSL shaders on the engine (issue 43 item 2): a checked fragment shader
//! ([`softgl_glsl::hir`]) lowered into the engine's IR ([`crate::engine::ir`]), so that the
//! stage executor runs it like a lowered fixed-function state.
//!
//! [`lower::lower_fragment`] gives the program, the colour it writes and where its
//! uniforms and varyings go; a caller appends its output stage (pack and store, or the
//! raw bits for a test) and compiles it with [`crate::engine::exec::compile`]. What lowers:
//! float, int and bool scalars, vectors and matrices (one SSA value per component),
//! arithmetic, comparisons, swizzles, constructors, locals, uniforms (hoisted into the
//! program's prologue), `gl_FragCoord`, varyings (perspective-correct planes), `if`/`else`
//! and loops with a constant trip count under lane masks (`break`, `continue`, `return`),
//! `discard`, inlined user functions, and the built-in functions of [`builtins`] with
//! llvmpipe's arithmetic. `tests/shader_mesa.rs` draws shaders through Mesa and compares.
//!
//! Not yet: texture sampling, derivatives, loops whose trip count is not a constant,
//! `switch`, integer division and shifts, dynamic indexing on the left of `=`, the
//! inverse trigonometric functions, and wiring into draws (it needs program objects).

mod builtins;
mod control;
mod expr;
pub mod lower;

pub use lower::{lower_fragment, Lowered, Slot, Unsupported};
