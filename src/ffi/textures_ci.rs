//! GL_COLOR_INDEX texture images are unpacked by the state machine: see
//! `context/texture_ci.rs`. This C-boundary module has no entry points of its own.
