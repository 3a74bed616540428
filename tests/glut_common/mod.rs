//! Shared by the softglut integration tests (tests/glut_tutorials.rs,
//! tests/glut_reference.rs): where things are, building `libsoftglut.so`, and
//! compiling C programs against it with softgl, Mesa's OSMesa, or SGI's libGLU.

#![allow(dead_code)]

use std::collections::BTreeMap;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::{Mutex, OnceLock};
use std::time::SystemTime;

#[path = "../support/paths.rs"]
mod paths;
pub use paths::{profile_dir, root};

/// A file's modification time.
pub fn mtime(p: &Path) -> Option<SystemTime> {
    fs::metadata(p).and_then(|m| m.modified()).ok()
}

/// The freshest `libsoftgl.so` folder: `SOFTGL_LIB_DIR`, else the newer of
/// `target/<profile>/` and `target/<profile>/deps/` (as in tests/osmesa_compare.rs).
pub fn softgl_dir() -> PathBuf {
    if let Some(d) = std::env::var_os("SOFTGL_LIB_DIR") {
        return PathBuf::from(d);
    }
    let profile = profile_dir();
    let up = profile.join("libsoftgl.so");
    let dep = profile.join("deps").join("libsoftgl.so");
    match (mtime(&up), mtime(&dep)) {
        (Some(u), Some(d)) if d > u => profile.join("deps"),
        (None, Some(_)) => profile.join("deps"),
        _ => profile,
    }
}

/// Builds `libsoftglut.so` once (cargo, this test's profile); returns its folder. The
/// whole workspace, as `scripts/test.sh` builds it: `-p softglut` alone resolves other
/// features and rebuilt softglut (about 25 s in a fresh clone) over the workspace's.
pub fn glut_dir() -> &'static Path {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let profile = profile_dir();
        let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".into());
        let mut cmd = Command::new(cargo);
        cmd.current_dir(root()).args(["build", "--workspace"]);
        if profile.file_name().and_then(|n| n.to_str()) == Some("release") {
            cmd.arg("--release");
        }
        let target = profile.parent().expect("target dir");
        cmd.env("CARGO_TARGET_DIR", target);
        let status = cmd.status().expect("run cargo build -p softglut");
        assert!(status.success(), "cargo build -p softglut failed");
        assert!(profile.join("libsoftglut.so").exists());
        profile
    })
}

/// `target/glut/`.
pub fn work_dir() -> PathBuf {
    let d = profile_dir()
        .parent()
        .map(|t| t.join("glut"))
        .unwrap_or_else(|| root().join("target/glut"));
    fs::create_dir_all(&d).expect("mkdir target/glut");
    d
}

/// The C compiler (`CC`, default `cc`).
pub fn cc() -> String {
    std::env::var("CC").unwrap_or_else(|_| "cc".into())
}

/// Which GL a tutorial is linked with.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Gl {
    Softgl,
    Osmesa,
    /// Mesa's OSMesa with SGI's libGLU linked ahead of softglut (its glu* win).
    SgiGlu,
}

/// Compiles `tutorials/NAME.c` against softglut and the chosen GL, once per test run
/// (tests running in parallel share the binary instead of rewriting it).
pub fn compile(name: &str, gl: Gl) -> PathBuf {
    static BUILT: Mutex<BTreeMap<String, PathBuf>> = Mutex::new(BTreeMap::new());
    let mut built = BUILT.lock().unwrap_or_else(|e| e.into_inner());
    let key = format!("{name}.{gl:?}").to_lowercase();
    if let Some(p) = built.get(&key) {
        return p.clone();
    }
    let bin = work_dir().join("bin");
    fs::create_dir_all(&bin).expect("mkdir bin");
    let src = root().join("tutorials").join(format!("{name}.c"));
    let out = build(&src, &bin.join(&key), gl);
    built.insert(key, out.clone());
    out
}

/// Compiles a C file against softglut and the chosen GL into `out`.
pub fn build(src: &Path, out: &Path, gl: Gl) -> PathBuf {
    let glut = glut_dir();
    let mut cmd = Command::new(cc());
    cmd.arg(src)
        .args(["-O1", "-Wall", "-Werror", "-o"])
        .arg(out)
        .arg(format!("-I{}", root().join("glut/include").display()));
    if gl == Gl::SgiGlu {
        cmd.args(["-Wl,--no-as-needed", "-lGLU"]);
    }
    cmd.arg(format!("-L{}", glut.display())).arg("-lsoftglut");
    match gl {
        Gl::Softgl => {
            let sg = softgl_dir();
            cmd.arg(format!("-I{}", root().join("include").display()))
                .arg(format!("-L{}", sg.display()))
                .arg("-lsoftgl")
                .arg(format!("-Wl,-rpath,{}:{}", glut.display(), sg.display()));
        }
        Gl::Osmesa | Gl::SgiGlu => {
            cmd.args(["-Wl,--allow-shlib-undefined", "-lOSMesa"])
                .arg(format!("-Wl,-rpath,{}", glut.display()));
        }
    }
    let o = cmd.arg("-lm").output().expect("run cc");
    assert!(
        o.status.success(),
        "compiling {} for {gl:?} failed:\n{}",
        src.display(),
        String::from_utf8_lossy(&o.stderr)
    );
    out.to_path_buf()
}

/// Whether `program` is on PATH.
pub fn have_program(program: &str) -> bool {
    std::env::var_os("PATH")
        .map(|p| std::env::split_paths(&p).any(|d| d.join(program).is_file()))
        .unwrap_or(false)
}
