//! The engine (issue 42): a small typed IR for per-fragment work and the executor that
//! runs it over 8-pixel chunks. Wired into the general textured walk: when
//! `SOFTGL_ENGINE` gives it the triangle (by default the large ones without an early depth
//! or stencil test whose combiners the hand-written walk interprets:
//! `raster::textured::engine_takes`) and the draw's state lowers ([`ff`]), the rasterizer
//! samples the units as before and hands each triangle's chunk rows with their texels to
//! [`draw::Walk`],
//! which runs the state's program from the per-thread variant [`cache`] (see
//! `docs/engine.md`). The tests check the lowered programs against the hand-written
//! fragment functions for the same states, bytes and counters. Fragment shaders run here
//! too, whatever `SOFTGL_ENGINE` says: `crate::shader::draw` compiles a program's shader
//! with the same per-fragment tail ([`ff::tail`]) and draws its triangles through
//! [`draw::Walk::with_program`], variants in the same [`cache`] ([`cache::Key`]).
//!
//! # Design
//! - **IR** ([`ir`]): SSA values of 8 lanes, typed f32, i32 or mask; arithmetic defined
//!   as llvmpipe's (`fmuladd` fused exactly on fusing levels, `minps`/`maxps` NaN order,
//!   `cvtps2dq` rounding, unorm8 conversions); the fragment interface (plane
//!   interpolation, input streams such as sampled texels, kill, depth test, colour load,
//!   8-bit blending, colour store). Built with [`ir::Builder`], which checks types.
//! - **Executor** ([`exec`]): a stage pipeline of precompiled kernels, the design of
//!   Skia's SkRasterPipeline and tiny-skia, chosen over a JIT from the prototype's
//!   measurements (`docs/engine.md`). Compiling a program is register allocation over a
//!   register file in L1 and one table look-up per operation, microseconds per state, so
//!   a state change costs nothing like an LLVM compile. Each kernel runs its operation
//!   over a *batch* of chunks, so the indirect call is paid once per operation per batch.
//!   A JIT may later compile the same IR behind the same [`exec::Program`] interface for
//!   ALU-heavy shaders (see the numbers below).
//! - **Levels** ([`kernels`]): every kernel body is written once over a lane backend and
//!   compiled per instruction-set level (portable unfused, portable fused under FMA,
//!   AVX2, AVX2+FMA; AVX-512 CPUs run the AVX2+FMA kernels), so the engine fuses exactly
//!   where llvmpipe and today's code do and runs on any x86-64 (and other targets, on the
//!   portable kernels).
//! - **Lowering**: [`ff`] lowers the general textured walk's per-fragment state (every
//!   texture environment and GL_COMBINE on up to 8 units, the colour sum, fog of every
//!   mode, alpha test, depth on Z16/Z24/Z32F, blending, colour mask, RGBA8 store);
//!   [`lower`] is the prototype's state (kept for the executor's tests and benchmark).
//! - **Variants** ([`cache`]): programs keyed by the state the lowering reads (the
//!   fragment plan and the units' combiners), per thread, most recently used first;
//!   `SOFTGL_STATS=1` prints compiles, refused states, hits and compile time.
//!
//! # Numbers
//! Measured by the ignored test in `bench.rs` (AVX2+FMA, 2048 full chunks, medians of
//! 41 alternating rounds, three runs on a shared, loaded 2-core machine; the table is in
//! `docs/engine.md`): MODULATE + depth LESS + "over" blending takes 3.2–3.5 ns per pixel
//! at a batch of 32 chunks against 2.5–3.1 for today's hand-written AVX2 fast path and
//! 1.8–2.2 for straight-line AVX2 code (a JIT's ceiling); with linear fog and the alpha
//! test added, which today only the general per-lane path draws (41–63 ns per pixel),
//! the engine takes 6.1–8.9 and the ceiling 3.5–4.5. One chunk per kernel call costs
//! 3.7 times a batch of 32. Lowering and compiling one state takes 2.3–2.9 µs.
//!
//! # Not covered yet
//! Texture sampling (the texels come from today's samplers as f32 input streams),
//! derivatives and 2×2 quads, stencil, logic ops, colour formats other than RGBA8, Z32
//! unorm depth, multisampling, smooth lines and points, the texture fast path's states
//! (one simple unit without fog, drawn by `raster/textured.rs`'s own walk), lines and
//! points, and per-vertex work.

#[cfg(test)]
mod bench;
pub mod cache;
pub mod draw;
pub mod exec;
pub mod ff;
pub mod ir;
mod kernels;
pub mod lower;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_ff;
#[cfg(test)]
mod tests_loop;
#[cfg(test)]
mod tests_shader;
