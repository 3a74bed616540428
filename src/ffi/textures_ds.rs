//! Packed depth-stencil texture images are handled by the state machine: see
//! `context/texture_ds.rs`. This C-boundary module has no entry points of its own.
