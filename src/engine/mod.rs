//! The engine (issue 42, first step): a small typed IR for per-fragment work and the
//! executor that runs it over 8-pixel chunks. Not wired into the draw path yet: the
//! rasterizer still calls the hand-written fragment functions, and the tests here check
//! that programs lowered from the same state give their bytes (see `docs/engine.md`).
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
//! - **Lowering** ([`lower`]): the prototype's fixed-function state (one RGBA8 texture
//!   with MODULATE, linear fog, alpha test, depth, blending, RGBA8 store) into the IR.
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
//! Texture sampling (the texels come from today's sampler as an input stream),
//! derivatives and 2×2 quads, flat shading, stencil, logic ops, colour masks, other
//! colour and depth formats, multisampling, statistics counters, the variant cache and
//! the wiring into the rasterizer.

#[cfg(test)]
mod bench;
pub mod exec;
pub mod ir;
mod kernels;
pub mod lower;
#[cfg(test)]
mod tests;
