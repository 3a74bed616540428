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
//! inverse trigonometric functions.
//!
//! # In draws
//! [`draw`] runs a program's fragment shader in draws: when the current program has a
//! linked fragment shader and no vertex shader, filled triangles take the fixed-function
//! vertex stage and the shader colours each fragment on the engine (8 lanes), followed by
//! the fixed per-fragment operations (alpha test, depth test, blending, colour mask). The
//! inputs: `gl_Color` (the fixed-function colour, clamped), `gl_TexCoord[0..8]` (each
//! unit's coordinates with its texture matrix and texgen; the vertex stage computes all
//! eight sets when the shader reads `gl_TexCoord`), `gl_FragCoord` (window position,
//! `y` flipped for top-down rows, `z` the depth plane, `w` the interpolated `1/w`), all
//! perspective-correct; uniforms from the program's storage at each draw, passed as run
//! inputs (a glUniform between draws takes effect; the variant cache is keyed by the
//! shader, the plan and the row flip, never by uniform values).
//!
//! Honest refusals: a draw that cannot run its program draws **nothing** and counts it
//! (`SOFTGL_STATS=1`: `program_draws_refused`, `program_tris_refused`), rather than
//! falling back to fixed function and drawing wrong colours. Refused: a program with a
//! vertex shader; a fragment shader that does not lower (texture sampling, derivatives …),
//! reads `gl_FrontFacing`, `gl_SecondaryColor`, `gl_FogFragCoord`, a user varying or a
//! built-in uniform, or has more than 64 uniform components; points, lines, polygons
//! taking the polygon pipeline (unfilled, stippled, offset, two-sided lighting), flat
//! shading and multisampling; triangles whose fragment state the engine does not draw
//! (stencil, logic ops, wide, sRGB or non-RGBA8 targets, Z32 unorm depth). `GL_VERSION`
//! stays 1.5.

mod builtins;
mod control;
pub mod draw;
mod expr;
pub mod lower;

pub use lower::{lower_fragment, lower_fragment_with, Lowered, Options, Slot, Unsupported};
