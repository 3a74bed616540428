//! softglut's shapes against the real freeglut: `glut_freeglut/shapes.c` draws every
//! GLUT shape (solid and wire, the tea set, the sponge, some in fog, some through a
//! display list) lit, scene by scene, and dumps each scene's pixels. It is built once
//! against the system freeglut 3.4 and run on Mesa's llvmpipe through GLX under a
//! private Xvfb server, and once against softglut on softgl; every scene must be
//! byte-identical. softglut builds its shapes as freeglut does (same vertices, normals,
//! triangles, strips and draw calls), so a GLUT program draws the same pixels with
//! either library.
//!
//! Needs `Xvfb`, freeglut's headers and library (`scripts/ensure-deps.sh` installs
//! both); without them the test says so and passes. Built under `target/glut_freeglut/`.
//! `CC` picks the C compiler (default `cc`).

use std::fs;
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

#[path = "support/paths.rs"]
mod paths;
#[path = "support/softglut_libs.rs"]
mod softglut_libs;
use paths::root;
use softglut_libs::{libs_dir, run_checked, work_dir};

/// Side of each scene, and the number of scenes (as in shapes.c).
const SIZE: usize = 160;
const SCENES: usize = 30;

/// What each scene of shapes.c draws.
const NAMES: [&str; SCENES] = [
    "solid sphere",
    "wire sphere",
    "solid cone",
    "wire cone",
    "solid cylinder",
    "wire cylinder",
    "solid torus",
    "wire torus",
    "solid cube",
    "wire cube",
    "solid dodecahedron",
    "wire dodecahedron",
    "solid icosahedron",
    "wire icosahedron",
    "solid octahedron",
    "solid tetrahedron",
    "wire tetrahedron",
    "solid rhombic dodecahedron",
    "wire rhombic dodecahedron",
    "solid teapot",
    "wire teapot",
    "solid teapot resized",
    "solid teacup",
    "wire teacup",
    "solid teaspoon",
    "solid sponge",
    "wire sponge",
    "sphere and cone in fog",
    "sphere and cone in fog, farther",
    "display list: teapot and cylinder",
];

/// Compiles shapes.c: against the system freeglut and libGL, or softglut and softgl.
fn build(freeglut: bool) -> PathBuf {
    let out = work_dir("glut_freeglut").join(if freeglut {
        "shapes.freeglut"
    } else {
        "shapes.softglut"
    });
    let mut cmd = Command::new(std::env::var("CC").unwrap_or_else(|_| "cc".into()));
    cmd.arg(root().join("tests/glut_freeglut/shapes.c"))
        .args(["-O1", "-Wall", "-Werror", "-o"])
        .arg(&out);
    if freeglut {
        cmd.args(["-lglut", "-lGL"]);
    } else {
        let libs = libs_dir();
        cmd.arg(format!("-I{}", root().join("glut/include").display()))
            .arg(format!("-I{}", root().join("include").display()))
            .arg(format!("-L{}", libs.display()))
            .args(["-lsoftglut", "-lsoftgl"])
            .arg(format!("-Wl,-rpath,{}", libs.display()));
    }
    let o = cmd.arg("-lm").output().expect("run cc");
    assert!(
        o.status.success(),
        "compiling shapes.c (freeglut: {freeglut}) failed:\n{}",
        String::from_utf8_lossy(&o.stderr)
    );
    out
}

/// A private X server, stopped when dropped.
struct Xvfb {
    child: Child,
    display: String,
}

impl Xvfb {
    /// Starts `Xvfb` on a display number it picks itself (`-displayfd`), waiting until
    /// it accepts connections.
    fn start() -> Xvfb {
        let mut child = Command::new("Xvfb")
            .args([
                "-displayfd",
                "1",
                "-screen",
                "0",
                "320x240x24",
                "-nolisten",
                "tcp",
            ])
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("start Xvfb");
        let mut line = String::new();
        let stdout = child.stdout.take().expect("Xvfb stdout");
        BufReader::new(stdout)
            .read_line(&mut line)
            .expect("read Xvfb's display number");
        let n: u32 = line.trim().parse().unwrap_or_else(|_| {
            let _ = child.kill();
            panic!("Xvfb gave no display number: {line:?}")
        });
        Xvfb {
            child,
            display: format!(":{n}"),
        }
    }
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        // SIGTERM first so the server removes its lock file and socket.
        let _ = Command::new("kill")
            .arg(self.child.id().to_string())
            .status();
        let deadline = Instant::now() + Duration::from_secs(5);
        while Instant::now() < deadline {
            if let Ok(Some(_)) = self.child.try_wait() {
                return;
            }
            std::thread::sleep(Duration::from_millis(20));
        }
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Runs a shapes binary; returns every scene's RGBA pixels.
fn run(bin: &Path, envs: &[(&str, String)]) -> Vec<u8> {
    let out = bin.with_extension("raw");
    let _ = fs::remove_file(&out);
    run_checked(
        Command::new(bin)
            .arg(&out)
            .envs(envs.iter().map(|(k, v)| (*k, v.as_str())))
            .env("SOFTGLUT_OUTPUT", work_dir("glut_freeglut").join("frames"))
            .env_remove("SOFTGLUT_SIZE"),
    );
    let px = fs::read(&out).expect("read pixels");
    assert_eq!(px.len(), SCENES * SIZE * SIZE * 4, "{}", bin.display());
    px
}

/// The tools this test needs, or what is missing.
fn missing_tools() -> Option<String> {
    let xvfb = Command::new("Xvfb")
        .arg("-help")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok();
    if !xvfb {
        return Some("Xvfb".into());
    }
    let header = Path::new("/usr/include/GL/freeglut.h");
    (!header.exists()).then(|| "freeglut's headers (libglut-dev)".into())
}

#[test]
fn shapes_are_pixel_identical_to_freeglut() {
    if let Some(what) = missing_tools() {
        eprintln!("note: no {what}; softglut's shapes not compared with freeglut");
        return;
    }
    let (fg_bin, ours_bin) = (build(true), build(false));
    let ours = run(&ours_bin, &[]);
    let x = Xvfb::start();
    let mut envs = vec![
        ("DISPLAY", x.display.clone()),
        ("LIBGL_ALWAYS_SOFTWARE", "1".into()),
        ("GALLIUM_DRIVER", "llvmpipe".into()),
        ("LP_NUM_THREADS", "1".into()),
    ];
    // Pins llvmpipe's fusing to softgl's level (as the OSMesa comparisons do).
    if let Some(c) = softgl::cpu::reference_cpu_caps() {
        envs.push(("GALLIUM_OVERRIDE_CPU_CAPS", c));
    }
    let reference = run(&fg_bin, &envs);
    drop(x);

    let scene = SIZE * SIZE * 4;
    let mut failures = Vec::new();
    for (i, name) in NAMES.iter().enumerate() {
        let (a, b) = (
            &ours[i * scene..(i + 1) * scene],
            &reference[i * scene..(i + 1) * scene],
        );
        let differ = a
            .chunks_exact(4)
            .zip(b.chunks_exact(4))
            .filter(|(p, q)| p[..3] != q[..3])
            .count();
        let drawn = b.chunks_exact(4).filter(|p| p[..3] != b[..3]).count();
        let same = 100.0 * (1.0 - differ as f64 / (SIZE * SIZE) as f64);
        println!("{name:34} {same:7.3}% identical ({differ} pixels differ, {drawn} drawn)");
        assert!(drawn > 200, "{name}: freeglut drew almost nothing");
        if differ > 0 {
            failures.push(format!("{name}: {differ} pixels differ"));
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}
