//! softglut's GLU against the GLU real programs link: SGI's libGLU (Debian's
//! `libglu1-mesa`), the library Mesa's users pair with `libOSMesa`.
//!
//! The tutorials test (`tests/glut_tutorials.rs`) links softglut on both sides, so a GLU
//! that computes a matrix differently from libGLU passes it unnoticed; these tests catch
//! that:
//!
//! - `glu_reference/matrices.c` runs gluLookAt, gluPerspective, gluOrtho2D, gluPickMatrix
//!   and gluProject on 500 random inputs, once linked with softglut's GLU and once with the
//!   system libGLU, both over Mesa's OSMesa: the matrices and window coordinates must be
//!   bit-identical;
//! - `glu_reference/robot_arm.c`, a lit robot arm over a textured floor seen through
//!   gluPerspective and gluLookAt, drawn by softgl with softglut's GLU must be
//!   byte-identical to Mesa's llvmpipe with libGLU. With a double-precision gluLookAt
//!   (libGLU builds the basis in single precision) 125 pixels of it differed by one step;
//! - `glu_reference/quadrics.c` draws every quadric in every combination of normals,
//!   orientation, draw style and texture coordinates (360 lit, textured frames): each
//!   frame drawn by softgl with softglut's quadrics must be byte-identical to llvmpipe with
//!   libGLU's. Quadrics written from their definitions matched on 78% of a sphere's pixels;
//! - `glu_reference/scale_image.c` runs gluScaleImage between every pair of the seven
//!   basic types on five size pairs: the bytes must equal libGLU's, which scales in 16 bits
//!   (a box filter in f64 on the type's own scale differed by one step in 4% of bytes).
//!
//! Built under `target/glu_reference/`. `CC` picks the C compiler (default `cc`).

use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

#[path = "support/paths.rs"]
mod paths;
#[path = "support/softglut_libs.rs"]
mod softglut_libs;
use paths::root;
use softglut_libs::libs_dir;

/// Which GLU and which GL a program is linked with.
#[derive(Clone, Copy, Debug)]
enum Link {
    /// softglut's GLU (our headers) over Mesa's OSMesa.
    SoftGluOnMesa,
    /// softglut's GLU over softgl (our headers): what a softgl user runs.
    SoftGluOnSoftgl,
    /// The system libGLU over Mesa's OSMesa (system headers): the reference.
    SystemGluOnMesa,
}

/// Compiles `tests/glu_reference/NAME.c` with the given link; returns the binary.
fn build(name: &str, link: Link) -> PathBuf {
    let libs = libs_dir();
    let src = root().join("tests/glu_reference").join(format!("{name}.c"));
    let out =
        softglut_libs::work_dir("glu_reference").join(format!("{name}.{link:?}").to_lowercase());
    let mut cmd = Command::new(std::env::var("CC").unwrap_or_else(|_| "cc".into()));
    cmd.arg(&src)
        .args(["-O1", "-Wall", "-Werror", "-o"])
        .arg(&out);
    let ours = |cmd: &mut Command| {
        cmd.arg(format!("-I{}", root().join("glut/include").display()))
            .arg(format!("-I{}", root().join("include").display()))
            .arg(format!("-L{}", libs.display()))
            .arg("-lsoftglut")
            .arg(format!("-Wl,-rpath,{}", libs.display()));
    };
    match link {
        Link::SoftGluOnMesa => {
            ours(&mut cmd);
            cmd.arg("-lOSMesa");
        }
        Link::SoftGluOnSoftgl => {
            ours(&mut cmd);
            cmd.arg("-lsoftgl");
        }
        Link::SystemGluOnMesa => {
            cmd.args(["-lGLU", "-lOSMesa"]);
        }
    }
    let o = cmd.arg("-lm").output().expect("run cc");
    assert!(
        o.status.success(),
        "compiling {} ({link:?}) failed:\n{}",
        src.display(),
        String::from_utf8_lossy(&o.stderr)
    );
    out
}

/// Runs a binary (llvmpipe pinned to one thread, and its fusing to softgl's level as in
/// src/cpu.rs; softgl ignores both) and returns what it wrote.
fn run(bin: &Path) -> Vec<u8> {
    let out = bin.with_extension("out");
    softglut_libs::run_checked(
        Command::new(bin)
            .arg(&out)
            .env("LP_NUM_THREADS", "1")
            .envs(softgl::cpu::reference_cpu_caps().map(|c| ("GALLIUM_OVERRIDE_CPU_CAPS", c))),
    );
    fs::read(&out).expect("read output")
}

#[test]
fn glu_matrices_equal_system_libglu() {
    let ours = run(&build("matrices", Link::SoftGluOnMesa));
    let reference = run(&build("matrices", Link::SystemGluOnMesa));
    // Each of the 500 records: four 4x4 float matrices, then gluProject's status and
    // window x, y, z.
    const RECORD: usize = 4 * 64 + 4 + 3 * 8;
    assert_eq!(ours.len(), 500 * RECORD);
    assert_eq!(ours.len(), reference.len());
    let names = ["gluLookAt", "gluPerspective", "gluOrtho2D", "gluPickMatrix"];
    let mut differing = [0usize; 5];
    for (a, b) in ours.chunks(RECORD).zip(reference.chunks(RECORD)) {
        for (i, d) in differing.iter_mut().enumerate() {
            let r = if i < 4 {
                i * 64..i * 64 + 64
            } else {
                256..RECORD
            };
            *d += usize::from(a[r.clone()] != b[r]);
        }
    }
    let report: Vec<String> = names
        .iter()
        .chain(["gluProject"].iter())
        .zip(differing)
        .map(|(n, d)| format!("{n}: {d}/500 differ"))
        .collect();
    assert_eq!(differing, [0; 5], "{}", report.join(", "));
}

#[test]
fn robot_arm_through_glu_matches_llvmpipe_with_libglu() {
    let ours = run(&build("robot_arm", Link::SoftGluOnSoftgl));
    let reference = run(&build("robot_arm", Link::SystemGluOnMesa));
    assert_eq!(ours.len(), 640 * 480 * 4);
    assert_eq!(ours.len(), reference.len());
    let differing = ours
        .chunks(4)
        .zip(reference.chunks(4))
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(
        differing, 0,
        "{differing} of 307200 pixels differ from llvmpipe"
    );
}

#[test]
fn quadrics_match_llvmpipe_with_libglu() {
    let ours = run(&build("quadrics", Link::SoftGluOnSoftgl));
    let reference = run(&build("quadrics", Link::SystemGluOnMesa));
    const FRAME: usize = 128 * 128 * 4;
    assert_eq!(ours.len(), 360 * FRAME);
    assert_eq!(ours.len(), reference.len());
    let bad: Vec<String> = ours
        .chunks(FRAME)
        .zip(reference.chunks(FRAME))
        .enumerate()
        .filter_map(|(i, (a, b))| {
            let n = a.chunks(4).zip(b.chunks(4)).filter(|(x, y)| x != y).count();
            (n > 0).then(|| format!("frame {i}: {n} pixels"))
        })
        .collect();
    assert!(
        bad.is_empty(),
        "{} of 360 frames differ: {}",
        bad.len(),
        bad.join(", ")
    );
}

#[test]
fn scale_image_equals_system_libglu() {
    let ours = run(&build("scale_image", Link::SoftGluOnMesa));
    let reference = run(&build("scale_image", Link::SystemGluOnMesa));
    assert_eq!(ours.len(), reference.len());
    assert!(ours.len() > 300_000, "short output: {} bytes", ours.len());
    let differing = ours.iter().zip(&reference).filter(|(a, b)| a != b).count();
    assert_eq!(
        differing, 0,
        "{differing} bytes differ from libGLU's gluScaleImage"
    );
}
