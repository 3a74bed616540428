//! The fixed-function vertex stage, computed as llvmpipe runs Mesa's generated vertex
//! program: matrices and matrix stacks ([`matrix`], with Mesa's inverse in
//! [`mesa_matrix`]), the per-vertex transform into clip and window space ([`transform`],
//! and [`block`] for runs of vertices through a plain stage), lighting ([`lighting`], with
//! gallivm's `pow`/`exp2` in [`gallivm_math`]), texture coordinate generation ([`texgen`]),
//! the fog coordinate and fog factors ([`fog`]), point-size attenuation ([`point_size`])
//! and the evaluators' Bézier arithmetic ([`eval`]).

pub mod block;
pub mod eval;
pub mod fog;
#[cfg(target_arch = "x86_64")]
pub mod gallivm_lanes;
pub mod gallivm_math;
pub mod lighting;
pub mod matrix;
pub mod mesa_matrix;
pub mod point_size;
pub mod texgen;
pub mod transform;
