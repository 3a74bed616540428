//! GLSL shaders on the engine (issue 43 item 2): a checked fragment or vertex shader
//! ([`softgl_glsl::hir`]) lowered into the engine's IR ([`crate::engine::ir`]), so that the
//! stage executor runs it like a lowered fixed-function state.
//!
//! [`lower::lower_fragment`] gives the program, the colour it writes and where its
//! uniforms and varyings go; a caller appends its output stage (pack and store, or the
//! raw bits for a test) and compiles it with [`crate::engine::exec::compile`]. What lowers:
//! float, int and bool scalars, vectors and matrices (one SSA value per component),
//! arithmetic, comparisons, swizzles, constructors, locals, uniforms (hoisted into the
//! program's prologue), `gl_FragCoord`, varyings (perspective-correct planes), `if`/`else`
//! loops under lane masks (`break`, `continue`, `return`; a constant trip count unrolls,
//! any other runs as an engine loop, [`control`]),
//! `discard`, inlined user functions, and the built-in functions of [`builtins`] with
//! llvmpipe's arithmetic. `tests/shader_mesa.rs` draws shaders through Mesa and compares.
//!
//! Texture lookups lower when their coordinates are varyings as read ([`texture`]): the
//! rasterizer samples them with the fixed-function units' samplers before the program
//! runs. Not yet: lookups at coordinates computed in the shader, with bias or LOD,
//! derivatives,
//! `switch`, integer division and shifts, dynamic indexing on the left of `=`, the
//! inverse trigonometric functions.
//!
//! # In draws
//! [`draw`] runs a program's fragment shader in draws and [`vertex_draw`] its vertex
//! shader ([`vertex`] lowers it, same front end and expression lowering). A program's
//! stages each replace their fixed-function counterpart; a missing stage stays fixed
//! function.
//!
//! Fragment shaders colour triangles, lines and points (also those of unfilled
//! polygons, stippled ones through the stipple's coverage, and smooth lines and points
//! with their coverage in alpha, `engine::ff::smooth_colors`) on the engine (8 lanes; 2x2 quads for derivatives and lookups at computed
//! coordinates), followed by the
//! fixed per-fragment operations (alpha test, depth test, blending, colour mask). The
//! inputs: `gl_Color` (the vertex stage's colour, clamped), `gl_TexCoord[0..8]` (each
//! unit's coordinates; the fixed-function stage computes all eight sets with their
//! texture matrices and texgen when the shader reads `gl_TexCoord`), with a vertex shader
//! also `gl_SecondaryColor`, `gl_FogFragCoord` and user varyings (after the texture
//! coordinates among a vertex's varyings), `gl_FragCoord` (window position, `y` flipped
//! for top-down rows, `z` the depth plane, `w` the interpolated `1/w`), all
//! perspective-correct; `gl_FrontFacing` (the triangle's facing as culling and two-sided
//! lighting see it, a word the walk sets per triangle; true for lines and points, except the edges and vertices of an unfilled back face); uniforms from the program's storage at each draw, passed as run
//! inputs (a glUniform between draws takes effect; the variant cache is keyed by the
//! shader, the plan and the row flip, never by uniform values).
//!
//! Vertex shaders run over a draw's vertices 8 at a time on the engine's executor and
//! write the clip position, the colours, the texture coordinates and the user varyings
//! that the rest of the pipeline (clipping, which interpolates every varying, setup, the
//! fragment stage) reads as it reads the fixed-function stage's; their attributes come
//! from glBegin/glEnd, client arrays and buffer objects, generic attributes from their
//! arrays or current values at the link's locations (0 is the position); the built-in
//! matrices are the draw's. Such draws transform every vertex before assembling
//! (no post-transform cache streaming).
//!
//! Honest refusals: a draw that cannot run its program draws **nothing** and counts it
//! (`SOFTGL_STATS=1`: `program_draws_refused`, `program_tris_refused`), rather than
//! falling back to fixed function and drawing wrong colours. Refused: a shader that does
//! not lower (`textureGrad`, texel offsets,
//! `noperspective` inputs, lookups in vertex shaders …); a fragment shader that reads
//! (without a vertex shader) `gl_SecondaryColor`, `gl_FogFragCoord` or a user varying,
//! or has more than 512 uniform components (the light state fits: `gl_LightSource[]` is
//! 232 of them); a shader that reads a built-in uniform the context does not supply
//! (it supplies, in either stage, every matrix with its inverse and transposes,
//! `vertex_draw::MATRIX_UNIFORMS`, and the state uniforms, `vertex_draw::STATE_UNIFORMS`:
//! lights, materials, their products, fog, depth range, clip planes, point parameters,
//! texture environment colours, texgen planes, `gl_NormalScale`); a vertex
//! shader with a
//! non-float or matrix attribute, or reads a generic attribute
//! that glVertexAttrib set between glBegin and glEnd of a batch that could not record it
//! per vertex (memory ran out), or whose varyings leave no room for its back colours or
//! clip vertex; and `texelFetch` of a depth texture. A fragment shader draws into every
//! target and fragment state: logic ops, wide, sRGB and non-RGBA8 targets, Z32 depth
//! and multisampling take the walk's stores and tests after the program
//! (`crate::engine::draw::host_store`).
//! Under GL_VERTEX_PROGRAM_TWO_SIDE back faces take `gl_BackColor` and
//! `gl_BackSecondaryColor` (each only when the shader writes it). `gl_PointSize` sizes points
//! under GL_VERTEX_PROGRAM_POINT_SIZE (unclamped, as llvmpipe takes a vertex's size), and
//! `gl_PointCoord` is replaced across every point, sprite or not (`raster::sprite`).
//! With them the context is GL 2.1: `GL_VERSION` says 2.1 and `GL_SHADING_LANGUAGE_VERSION`
//! 1.20 (`context::get_extra`), and OSMesaCreateContextAttribs gives compatibility 2.1.

mod builtins;
mod control;
pub mod draw;
mod expr;
#[cfg(test)]
mod fuzz;
pub mod lower;
#[cfg(test)]
mod tests_loop;
mod texture;
pub mod vertex;
pub mod vertex_draw;

pub use lower::{lower_fragment, lower_fragment_with, Lowered, Options, Slot, Unsupported};
