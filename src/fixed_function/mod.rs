//! The fixed-function vertex stage: matrix stacks and the transform into clip space.
//! (Lighting, texgen and fog arrive with later issues behind the same interface.)

pub mod matrix;
pub mod transform;
