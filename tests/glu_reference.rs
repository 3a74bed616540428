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
//! - the NURBS programs (`glu_reference/nurbs_*.c`) are linked with softglut's GLU and
//!   with libGLU, both over Mesa's OSMesa, so that only GLU differs; see each test for
//!   which frames are pixel-identical and the tolerance of the others.
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
            cmd.args(["-Wl,--allow-shlib-undefined", "-lOSMesa"]);
        }
        Link::SoftGluOnSoftgl => {
            ours(&mut cmd);
            cmd.arg("-lsoftgl");
        }
        Link::SystemGluOnMesa => {
            cmd.args(["-Wl,--allow-shlib-undefined", "-lGLU", "-lOSMesa"]);
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
/// src/simd/cpu.rs; softgl ignores both) and returns what it wrote.
fn run(bin: &Path) -> Vec<u8> {
    // NAME.<link>.out: the two builds of a program must not share one output file.
    let mut out = bin.as_os_str().to_owned();
    out.push(".out");
    let out = PathBuf::from(out);
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

/// Differing pixels per `size`×`size` RGBA frame of two outputs.
fn frame_diffs(ours: &[u8], reference: &[u8], size: usize) -> Vec<usize> {
    let frame = size * size * 4;
    assert_eq!(ours.len(), reference.len());
    assert_eq!(ours.len() % frame, 0);
    ours.chunks(frame)
        .zip(reference.chunks(frame))
        .map(|(a, b)| a.chunks(4).zip(b.chunks(4)).filter(|(x, y)| x != y).count())
        .collect()
}

/// Runs a NURBS program with softglut's GLU and with libGLU (both over Mesa) and
/// checks each frame's differing pixels against its bound (0: identical).
fn nurbs_frames_within(name: &str, bounds: &[usize]) {
    let ours = run(&build(name, Link::SoftGluOnMesa));
    let reference = run(&build(name, Link::SystemGluOnMesa));
    let diffs = frame_diffs(&ours, &reference, 200);
    assert_eq!(diffs.len(), bounds.len(), "{name}: frame count");
    let total = (diffs.len() * 200 * 200) as f64;
    let same = 100.0 * (total - diffs.iter().sum::<usize>() as f64) / total;
    let over: Vec<String> = diffs
        .iter()
        .zip(bounds)
        .enumerate()
        .filter(|(_, (d, b))| d > b)
        .map(|(i, (d, b))| format!("frame {i}: {d} pixels differ (bound {b})"))
        .collect();
    assert!(
        over.is_empty(),
        "{name}: {same:.3}% of pixels identical; {}",
        over.join(", ")
    );
}

/// `nurbs_curve.c`: cubic Bézier, uniform cubic B-spline and a nonuniform quadratic with
/// a colour map, under path length (tolerance 50, 10, 3, and after a rotation),
/// domain distance (U_STEP 7, 40) and parametric error: every pixel equals libGLU's.
/// Curves are drawn as libGLU draws them: one glMap1f/glMapGrid1f/glEvalMesh1 per
/// Bézier segment with SGI's step count, in single precision.
#[test]
fn nurbs_curves_equal_libglu() {
    nurbs_frames_within("nurbs_curve", &[0; 7]);
}

/// `nurbs_surface.c` (the Red Book's surface.c with extras): the two domain-distance
/// frames (filled and GLU_OUTLINE_POLYGON) are pixel-identical, since libGLU draws
/// untrimmed domain-distance surfaces with one glEvalMesh2 per patch as softglut does.
/// Under path length libGLU runs every surface through its trimming tessellator (strips
/// and fans over its own sample points) while softglut uses a glEvalMesh2 grid with
/// SGI's per-patch step sizes: the same shape, sampled as densely, but other triangles
/// and so other Gouraud shading and outlines. A GL_MAP2_NORMAL map (domain distance) is
/// identical too; with colour and texture maps 39 pixels of an outline differ: softglut
/// cuts a map that spans several of the vertex map's patches into Bézier pieces in
/// double precision, libGLU in single, so piece colours differ in the last bits.
/// Measured: 93.3% of all pixels identical; the bounds are the measured counts plus
/// about 10%.
#[test]
fn nurbs_surfaces_match_libglu() {
    nurbs_frames_within(
        "nurbs_surface",
        &[8200, 4500, 850, 1900, 8100, 5600, 850, 5400, 0, 0, 0, 60],
    );
}

/// `nurbs_trim.c` (the Red Book's trim.c, a rational circular hole, GLU_OUTLINE_PATCH):
/// softglut triangulates the trimmed domain on the patch's evaluation grid (cells cut
/// by the trim polylines go through the polygon tessellator) where libGLU uses its own
/// monotone tessellation, so shading differs along triangle edges. Measured: 95.0% of
/// all pixels identical (70% of the surfaces' own pixels); bounds are measured + ~10%.
#[test]
fn nurbs_trimmed_surfaces_match_libglu() {
    nurbs_frames_within("nurbs_trim", &[3500, 3100, 20]);
}

/// `nurbs_circle.c`: the rational circle (GL_MAP1_VERTEX_4) is pixel-identical under
/// path length and domain distance; the rational half cylinder (GL_MAP2_VERTEX_4,
/// path length) differs as the surfaces above do. Measured 90.9% identical.
#[test]
fn nurbs_rational_match_libglu() {
    nurbs_frames_within("nurbs_circle", &[0, 0, 7000, 9100]);
}

/// `nurbs_errors.c`: the codes the GLU_NURBS_ERROR callback receives for bad knot
/// vectors, orders and misnested calls (including SGI's implicit begin/end recovery),
/// property defaults and values read back, and gluErrorString for all 37 NURBS errors
/// are the same text as with libGLU.
#[test]
fn nurbs_errors_equal_libglu() {
    let ours = run(&build("nurbs_errors", Link::SoftGluOnMesa));
    let reference = run(&build("nurbs_errors", Link::SystemGluOnMesa));
    assert!(reference.len() > 1000, "short reference output");
    assert_eq!(
        String::from_utf8_lossy(&ours),
        String::from_utf8_lossy(&reference)
    );
}

/// `nurbs_hostile.c`: NaN/infinite points and knots, bad knot vectors, orders from -2 to
/// 30, negative and huge counts and strides, NULL arrays, unknown types, misnested
/// calls, self-crossing and degenerate trims and absurd properties, in both NURBS
/// modes, on softgl: the program finishes (a Rust panic would abort it) and the
/// errors reach the callback.
#[test]
fn nurbs_hostile_input_never_panics() {
    let out = run(&build("nurbs_hostile", Link::SoftGluOnSoftgl));
    let text = String::from_utf8_lossy(&out);
    let errors: usize = text
        .split_whitespace()
        .next()
        .and_then(|w| w.parse().ok())
        .unwrap_or_else(|| panic!("unexpected output: {text}"));
    assert!(errors > 100, "only {errors} errors reported: {text}");
}
