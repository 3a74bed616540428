//! Building softglut for the tests that link C programs with it (needs the `paths`
//! support module at the test's root).

use crate::paths::{profile_dir, root};
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

/// Builds `libsoftglut.so` and `libsoftgl.so` once (this test's profile); returns the
/// folder holding both.
pub fn libs_dir() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let profile = profile_dir();
        let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
        let mut cmd = Command::new(cargo);
        cmd.current_dir(root())
            .args(["build", "-p", "softglut", "-p", "softgl", "--lib"]);
        if profile.file_name().and_then(|n| n.to_str()) == Some("release") {
            cmd.arg("--release");
        }
        cmd.env("CARGO_TARGET_DIR", profile.parent().expect("target dir"));
        let status = cmd.status().expect("run cargo build");
        assert!(status.success(), "cargo build -p softglut -p softgl failed");
        profile
    })
}

/// `target/NAME/` (created), next to the profile folder.
pub fn work_dir(name: &str) -> PathBuf {
    let d = profile_dir().with_file_name(name);
    fs::create_dir_all(&d).unwrap_or_else(|e| panic!("mkdir {}: {e}", d.display()));
    d
}

/// Runs a test program; panics with its status and stderr unless it succeeds.
pub fn run_checked(cmd: &mut Command) -> std::process::Output {
    let o = cmd.output().expect("run test program");
    let what = cmd.get_program().to_string_lossy().into_owned();
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        o.status.success(),
        "{what} exited with {}:\n{err}",
        o.status
    );
    o
}
