//! The 256 KiB-stack test on the release library: see `small_stack/scene.rs`.

#[path = "small_stack/scene.rs"]
mod scene;
