//! The fixed-function vertex stage: matrix stacks and the transform into clip space.
//! (Lighting, texgen and fog arrive with later issues behind the same interface.)

pub mod block;
pub mod eval;
pub mod fog;
pub mod gallivm_math;
pub mod lighting;
pub mod matrix;
pub mod mesa_matrix;
pub mod point_size;
pub mod texgen;
pub mod transform;
