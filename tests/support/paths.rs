//! Paths shared by the integration tests that build C programs: the repository root and
//! the cargo profile folder the test executable runs from.

use std::path::{Path, PathBuf};

/// The repository root (the softgl crate's manifest folder).
pub fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// `target/<profile>`: the test executable lives in `target/<profile>/deps/`.
pub fn profile_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("current_exe");
    exe.parent()
        .and_then(Path::parent)
        .expect("profile folder")
        .to_path_buf()
}
