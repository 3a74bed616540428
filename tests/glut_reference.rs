//! softglut against the reference libraries, on things the tutorials do not show:
//!
//! - the SGI-GLU build of a tutorial really binds glu* to SGI's libGLU;
//! - `tests/glu/mipmaps.c` (gluBuild*Mipmaps, gluBuild*MipmapLevels, gluUnProject4,
//!   gluCheckExtension) prints the same with softglut's GLU as with SGI's libGLU, both
//!   on Mesa's OSMesa;
//! - `tests/glu/menus.c` (menu ids and state, context requests, GLUT_MULTISAMPLE and
//!   GLUT_ACCUM) prints the same with softglut as with the system freeglut under Xvfb.
//!
//! Each test is skipped (with a note) when its reference is not installed.

mod glut_common;

use glut_common::*;
use std::fs;
use std::path::Path;
use std::process::Command;

/// The SGI-GLU build really calls SGI's libGLU (not softglut's glu*).
#[test]
fn sgi_glu_build_binds_glu_to_libglu() {
    if !Path::new("/usr/include/GL/glu.h").exists()
        || !Path::new("/usr/include/GL/osmesa.h").exists()
    {
        return;
    }
    let bin = compile("tess", Gl::SgiGlu);
    let out = work_dir().join("out/tess.bindings");
    let _ = fs::remove_dir_all(&out);
    let o = Command::new(&bin)
        .env("SOFTGLUT_FRAMES", "1")
        .env("SOFTGLUT_OUTPUT", &out)
        .env("LD_DEBUG", "bindings")
        .output()
        .expect("run tess");
    assert!(o.status.success());
    let log = String::from_utf8_lossy(&o.stderr);
    let bound: Vec<&str> = log
        .lines()
        .filter(|l| l.contains("normal symbol `gluTessVertex'") && l.contains("tess.sgiglu"))
        .collect();
    assert!(!bound.is_empty(), "no binding of gluTessVertex in the log");
    assert!(
        bound.iter().all(|l| l.contains("libGLU.so")),
        "gluTessVertex not bound to libGLU: {bound:?}"
    );
}

/// `tests/glu/mipmaps.c` (mipmap builders, gluUnProject4, gluCheckExtension) prints
/// the same with softglut's GLU as with SGI's libGLU, both on Mesa.
#[test]
fn glu_mipmaps_match_sgi() {
    if !Path::new("/usr/include/GL/glu.h").exists()
        || !Path::new("/usr/include/GL/osmesa.h").exists()
    {
        return;
    }
    let src = root().join("tests/glu/mipmaps.c");
    let bin = work_dir().join("bin");
    fs::create_dir_all(&bin).expect("mkdir bin");
    let print = |gl: Gl| {
        let exe = build(
            &src,
            &bin.join(format!("mipmaps.{gl:?}").to_lowercase()),
            gl,
        );
        let o = Command::new(&exe).output().expect("run mipmaps");
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        String::from_utf8(o.stdout).expect("utf-8")
    };
    let (ours, sgi) = (print(Gl::Osmesa), print(Gl::SgiGlu));
    assert!(sgi.lines().count() > 100, "{sgi}");
    for (a, b) in ours.lines().zip(sgi.lines()) {
        assert_eq!(a, b, "softglut (left) against SGI's GLU (right)");
    }
    assert_eq!(ours.lines().count(), sgi.lines().count());
}

/// `tests/glu/menus.c` (menu ids and state, context requests, options) prints the
/// same with softglut as with the system freeglut run under Xvfb.
#[test]
fn glut_menus_match_freeglut() {
    let freeglut = Path::new("/usr/include/GL/freeglut.h").exists();
    if !freeglut || !have_program("xvfb-run") || !Path::new("/usr/include/GL/osmesa.h").exists() {
        eprintln!("glut_menus_match_freeglut: skipped (needs freeglut3-dev, xvfb, OSMesa)");
        return;
    }
    let src = root().join("tests/glu/menus.c");
    let bin = work_dir().join("bin");
    fs::create_dir_all(&bin).expect("mkdir bin");
    let ours = build(&src, &bin.join("menus.softglut"), Gl::Osmesa);
    let theirs = bin.join("menus.freeglut");
    let o = Command::new(cc())
        .arg(&src)
        .args(["-O1", "-Wall", "-Werror", "-o"])
        .arg(&theirs)
        .args(["-Wl,--allow-shlib-undefined", "-lglut", "-lGL"])
        .output()
        .expect("cc");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let run = |cmd: &mut Command| {
        let o = cmd.output().expect("run menus");
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        String::from_utf8(o.stdout).expect("utf-8")
    };
    let a = run(&mut Command::new(&ours));
    let b = run(Command::new("xvfb-run").arg("-a").arg(&theirs));
    assert!(b.lines().count() > 15, "{b}");
    assert_eq!(a, b, "softglut (left) against freeglut (right)");
}
