//! Symbol interposition: a program that defines a `gl*` function of its own must not
//! replace softgl's. `interposition/wrapper.c` defines `glFinish`, asks
//! `OSMesaGetProcAddress("glFinish")`, clears to red and calls the pointer; softgl (linked
//! `-Bsymbolic`, see `build.rs`) must hand out and run its own glFinish, which fills the
//! user buffer, exactly as Mesa's libOSMesa does (checked against it when installed).

use std::path::{Path, PathBuf};
use std::process::Command;

/// What the program prints when the library binds its own symbols.
const EXPECTED: &str = "proc_is_program_s 0 program_calls 0 pixel 255";

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Compiles the wrapper program with `args` and returns its output line.
fn run(name: &str, args: &[String]) -> String {
    let dir = root().join("target").join("interposition");
    std::fs::create_dir_all(&dir).unwrap();
    let bin = dir.join(name);
    let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
    let src = root().join("tests/interposition/wrapper.c");
    let o = Command::new(cc)
        .arg(&src)
        .arg("-o")
        .arg(&bin)
        .args(args)
        .output()
        .expect("run the C compiler");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // cargo test puts target/<profile> on LD_LIBRARY_PATH, which would win over the rpath.
    let o = Command::new(&bin)
        .env_remove("LD_LIBRARY_PATH")
        .env("GALLIUM_DRIVER", "llvmpipe")
        .output()
        .expect("run the program");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    String::from_utf8_lossy(&o.stdout).trim().to_string()
}

#[test]
fn a_programs_own_gl_function_does_not_replace_softgls() {
    let lib = std::env::var("SOFTGL_LIB_DIR")
        .map(PathBuf::from)
        .unwrap_or_else(|_| root().join("target").join("release"));
    assert!(
        lib.join("libsoftgl.so").exists(),
        "{} has no libsoftgl.so",
        lib.display()
    );
    let ours = run(
        "wrapper.softgl",
        &[
            format!("-I{}", root().join("include").display()),
            format!("-L{}", lib.display()),
            "-lsoftgl".into(),
            format!("-Wl,-rpath,{}", lib.display()),
        ],
    );
    assert_eq!(ours, EXPECTED);
    if Path::new("/usr/include/GL/osmesa.h").exists() {
        let mesa = run("wrapper.osmesa", &["-lOSMesa".into()]);
        assert_eq!(mesa, EXPECTED, "Mesa itself behaves otherwise");
    }
}
