//! softgl as a binary drop-in for Mesa's `libOSMesa.so.8`, and its pkg-config files.
//!
//! `scripts/install.sh PREFIX` is run once (with `SOFTGL_LIB` naming the freshest
//! `libsoftgl.so`, chosen as in `tests/osmesa_compare.rs`) into
//! `target/dropin/<profile>/prefix`. Then:
//!
//! - a C scene compiled against the system headers with `-lOSMesa` runs once on Mesa
//!   and once with `LD_LIBRARY_PATH=PREFIX/lib/osmesa`; the drop-in run must load the
//!   installed softgl (`LD_DEBUG=libs`, `ldd`, `/proc/self/maps`, `dladdr`) and write
//!   exactly the bytes of the same scene linked with `-lsoftgl`;
//! - `pkg-config --cflags --libs softgl` (and `osmesa`) build programs that link to
//!   the installed library;
//! - a program using the system libGLU (gluPerspective, gluLookAt) run through the
//!   drop-in must have libGLU's gl* calls bound to softgl, and draw what the same
//!   program linked with `-lsoftgl` draws;
//! - the GL 1.0–2.1 entry points Mesa's libOSMesa exports and softgl does not are
//!   exactly `docs/missing-entry-points.txt` (also written to
//!   `target/dropin/missing-exports.txt`).
//!
//! Everything is built under `target/dropin/`. `CC` picks the C compiler (default `cc`).

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::sync::OnceLock;
use std::time::SystemTime;

// ---------------------------------------------------------------------------
// Paths

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// `target/<profile>`: the test executable lives in `target/<profile>/deps/`.
fn profile_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("current_exe");
    exe.parent()
        .and_then(Path::parent)
        .expect("profile folder")
        .to_path_buf()
}

fn target_dir() -> PathBuf {
    profile_dir()
        .parent()
        .map(Path::to_path_buf)
        .unwrap_or_else(|| root().join("target"))
}

fn mtime(p: &Path) -> Option<SystemTime> {
    fs::metadata(p).and_then(|m| m.modified()).ok()
}

/// The freshest `libsoftgl.so`: `SOFTGL_LIB_DIR`, else the newer of
/// `target/<profile>/` (`cargo build`) and `target/<profile>/deps/` (`cargo test`).
fn fresh_lib() -> PathBuf {
    if let Some(d) = std::env::var_os("SOFTGL_LIB_DIR") {
        return PathBuf::from(d).join("libsoftgl.so");
    }
    let profile = profile_dir();
    let up = profile.join("libsoftgl.so");
    let dep = profile.join("deps").join("libsoftgl.so");
    match (mtime(&up), mtime(&dep)) {
        (Some(u), Some(d)) if d > u => dep,
        (None, Some(_)) => dep,
        _ => up,
    }
}

/// `target/dropin/`: sources, binaries and outputs of these tests.
fn work_dir() -> PathBuf {
    let d = target_dir().join("dropin");
    fs::create_dir_all(&d).expect("mkdir target/dropin");
    d
}

fn canon(p: &Path) -> PathBuf {
    fs::canonicalize(p).unwrap_or_else(|e| panic!("canonicalize {}: {e}", p.display()))
}

// ---------------------------------------------------------------------------
// Running things

fn show(cmd: &Command, out: &Output) -> String {
    format!(
        "{cmd:?}\nstatus: {}\nstdout:\n{}\nstderr:\n{}",
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

/// Runs `cmd`, panicking with its output unless it succeeds.
fn check(mut cmd: Command) -> Output {
    let out = cmd
        .output()
        .unwrap_or_else(|e| panic!("could not run {cmd:?}: {e}"));
    assert!(out.status.success(), "command failed: {}", show(&cmd, &out));
    out
}

fn stdout(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).into_owned()
}

fn have(program: &str) -> bool {
    Command::new(program)
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

/// Mesa's OSMesa (headers, library) and a C compiler, installed if missing.
fn ensure_reference() {
    static DONE: OnceLock<()> = OnceLock::new();
    DONE.get_or_init(|| {
        if !Path::new("/usr/include/GL/osmesa.h").exists() {
            let _ = Command::new("bash")
                .arg(root().join("scripts/ensure-deps.sh"))
                .status();
        }
        assert!(
            Path::new("/usr/include/GL/osmesa.h").exists(),
            "Mesa's OSMesa (libosmesa6-dev) is missing; run scripts/ensure-deps.sh"
        );
    });
}

/// The install prefix, filled once per test run by `bash scripts/install.sh PREFIX`.
fn prefix() -> &'static Path {
    static PREFIX: OnceLock<PathBuf> = OnceLock::new();
    PREFIX.get_or_init(|| {
        ensure_reference();
        let lib = fresh_lib();
        assert!(
            lib.exists(),
            "{} does not exist: build the library first (cargo build --release)",
            lib.display()
        );
        let profile = profile_dir();
        let profile = profile.file_name().unwrap_or_default().to_string_lossy();
        let prefix = work_dir().join(profile.as_ref()).join("prefix");
        let _ = fs::remove_dir_all(&prefix);
        let mut cmd = Command::new("bash");
        cmd.arg(root().join("scripts/install.sh"))
            .arg(&prefix)
            .env("SOFTGL_LIB", &lib)
            .current_dir(work_dir());
        check(cmd);
        canon(&prefix)
    })
}

fn dropin_dir() -> PathBuf {
    prefix().join("lib/osmesa")
}

fn cc() -> Command {
    Command::new(std::env::var("CC").unwrap_or_else(|_| "cc".to_owned()))
}

/// Writes an embedded C source to `target/dropin/NAME.c` and returns its path.
fn write_source(name: &str, text: &str) -> PathBuf {
    let path = work_dir().join(format!("{name}.c"));
    let tmp = path.with_extension(format!("c.{}", std::process::id()));
    fs::write(&tmp, text).expect("write C source");
    fs::rename(&tmp, &path).expect("rename C source");
    path
}

/// How a test program is compiled and linked.
enum Link<'a> {
    /// System headers, `-lOSMesa` (Mesa's, as any OSMesa program is built).
    SystemOsmesa,
    /// Installed softgl headers and `-lsoftgl` with an rpath to the install.
    Softgl,
    /// Flags printed by `pkg-config --cflags --libs NAME` for the install.
    PkgConfig(&'a str),
}

fn pkg_config(args: &[&str]) -> String {
    let mut cmd = Command::new("pkg-config");
    cmd.args(args)
        .env("PKG_CONFIG_PATH", prefix().join("lib/pkgconfig"));
    stdout(&check(cmd)).trim().to_owned()
}

/// Compiles `source` into `target/dropin/BIN` with `extra` libraries after the GL one.
fn compile(source: &Path, bin: &str, link: Link, extra: &[&str]) -> PathBuf {
    let out = work_dir().join(bin);
    let mut cmd = cc();
    cmd.arg("-O1")
        .arg("-Wall")
        .arg(format!("-I{}", root().join("c_tests").display()));
    match link {
        Link::SystemOsmesa => {
            cmd.arg(source)
                .arg("-o")
                .arg(&out)
                .args(extra)
                .arg("-lOSMesa");
        }
        Link::Softgl => {
            let lib = prefix().join("lib");
            cmd.arg(format!("-I{}", prefix().join("include").display()))
                .arg(source)
                .arg("-o")
                .arg(&out)
                .args(extra)
                .arg(format!("-L{}", lib.display()))
                .arg("-lsoftgl")
                .arg(format!("-Wl,-rpath,{}", lib.display()));
        }
        Link::PkgConfig(name) => {
            let flags = pkg_config(&["--cflags", "--libs", name]);
            cmd.arg(source)
                .arg("-o")
                .arg(&out)
                .args(extra)
                .args(flags.split_whitespace());
        }
    }
    cmd.arg("-lm").arg("-ldl");
    check(cmd);
    out
}

/// How a test program is run.
#[derive(Clone, Copy)]
enum Via {
    /// As built: Mesa for `-lOSMesa` binaries (llvmpipe, one thread).
    AsBuilt,
    /// With the drop-in folder first in `LD_LIBRARY_PATH`.
    Dropin,
}

fn command(bin: &Path, via: Via) -> Command {
    let mut cmd = Command::new(bin);
    cmd.current_dir(work_dir())
        .env("GALLIUM_DRIVER", "llvmpipe")
        .env("LP_NUM_THREADS", "1")
        .env_remove("LD_PRELOAD");
    match via {
        Via::AsBuilt => cmd.env_remove("LD_LIBRARY_PATH"),
        Via::Dropin => cmd.env("LD_LIBRARY_PATH", dropin_dir()),
    };
    cmd
}

/// Runs a scene binary (argv[1] = output file) and returns the output bytes and stderr.
fn run_scene(bin: &Path, via: Via, tag: &str, env: &[(&str, &str)]) -> (Vec<u8>, String) {
    let out_file = work_dir().join(format!(
        "{}.{tag}.out",
        bin.file_name().unwrap().to_string_lossy()
    ));
    let _ = fs::remove_file(&out_file);
    let mut cmd = command(bin, via);
    cmd.arg(&out_file).envs(env.iter().copied());
    let out = check(cmd);
    let bytes = fs::read(&out_file)
        .unwrap_or_else(|e| panic!("{} wrote no {}: {e}", bin.display(), out_file.display()));
    (bytes, String::from_utf8_lossy(&out.stderr).into_owned())
}

/// `ldd BIN` (with the drop-in folder in `LD_LIBRARY_PATH` for `Via::Dropin`): the
/// resolved path of each NEEDED name.
fn ldd(bin: &Path, via: Via) -> BTreeMap<String, String> {
    let mut cmd = Command::new("ldd");
    cmd.arg(bin);
    match via {
        Via::AsBuilt => cmd.env_remove("LD_LIBRARY_PATH"),
        Via::Dropin => cmd.env("LD_LIBRARY_PATH", dropin_dir()),
    };
    stdout(&check(cmd))
        .lines()
        .filter_map(|l| {
            let (name, rest) = l.trim().split_once(" => ")?;
            let path = rest.split(" (").next()?.trim();
            Some((name.to_owned(), path.to_owned()))
        })
        .collect()
}

// ---------------------------------------------------------------------------
// Tests

/// install.sh lays out the library, the drop-in, the headers and the .pc files with
/// the absolute prefix.
#[test]
fn install_layout() {
    let p = prefix();
    let lib = p.join("lib/libsoftgl.so");
    assert_eq!(
        fs::read(&lib).expect("installed libsoftgl.so"),
        fs::read(fresh_lib()).expect("built libsoftgl.so"),
        "the installed libsoftgl.so is not the freshest build"
    );
    let so8 = dropin_dir().join("libOSMesa.so.8");
    assert_eq!(canon(&so8), canon(&lib), "libOSMesa.so.8 must be softgl");
    let script = fs::read_to_string(dropin_dir().join("libOSMesa.so")).expect("libOSMesa.so");
    assert!(script.contains("INPUT(-l:libOSMesa.so.8)"), "{script}");
    for h in ["gl.h", "glext.h", "osmesa.h"] {
        assert_eq!(
            fs::read(p.join("include/GL").join(h)).expect("installed header"),
            fs::read(root().join("include/GL").join(h)).expect("header"),
            "include/GL/{h}"
        );
    }
    for pc in ["softgl", "osmesa"] {
        let text = fs::read_to_string(p.join(format!("lib/pkgconfig/{pc}.pc"))).expect("pc");
        assert!(
            text.contains(&format!("prefix={}\n", p.display())),
            "{pc}.pc lacks the absolute prefix:\n{text}"
        );
        assert!(!text.contains('@'), "{pc}.pc has an unsubstituted token");
    }
    // The loader finds NEEDED entries by file name, so softgl needs no SONAME; and
    // without one, programs linked with -lsoftgl need "libsoftgl.so".
    let mut cmd = Command::new("readelf");
    cmd.arg("-d").arg(&lib);
    let dynamic = stdout(&check(cmd));
    assert!(
        !dynamic.contains("(SONAME)"),
        "libsoftgl.so got a SONAME; check the drop-in and -lsoftgl NEEDED names:\n{dynamic}"
    );
}

/// An OSMesa scene built against Mesa (system headers, -lOSMesa) renders with softgl
/// when the drop-in folder comes first in LD_LIBRARY_PATH, byte for byte as the scene
/// linked directly with -lsoftgl.
#[test]
fn mesa_binary_runs_on_dropin() {
    let source = root().join("c_tests/smooth_triangles.c");
    let mesa_bin = compile(&source, "smooth_triangles.mesa", Link::SystemOsmesa, &[]);
    let softgl_bin = compile(&source, "smooth_triangles.softgl", Link::Softgl, &[]);

    // The binary needs libOSMesa.so.8, which ldd resolves to the drop-in.
    let system = ldd(&mesa_bin, Via::AsBuilt);
    let dropped = ldd(&mesa_bin, Via::Dropin);
    let so8 = dropin_dir().join("libOSMesa.so.8");
    assert_eq!(
        dropped.get("libOSMesa.so.8").map(PathBuf::from),
        Some(so8.clone()),
        "ldd with LD_LIBRARY_PATH: {dropped:?}"
    );
    assert_ne!(system.get("libOSMesa.so.8"), dropped.get("libOSMesa.so.8"));

    let (mesa_out, _) = run_scene(&mesa_bin, Via::AsBuilt, "mesa", &[]);
    // LD_DEBUG=libs: the loader reports each library it initialises, in this very run.
    let (dropin_out, log) = run_scene(&mesa_bin, Via::Dropin, "dropin", &[("LD_DEBUG", "libs")]);
    let inits: Vec<&str> = log
        .lines()
        .filter_map(|l| l.split_once("calling init: ").map(|(_, p)| p.trim()))
        .collect();
    assert!(
        inits.iter().any(|p| Path::new(p) == so8),
        "the drop-in run did not initialise {}: {inits:?}",
        so8.display()
    );
    assert!(
        !inits
            .iter()
            .any(|p| p.contains("libOSMesa") && Path::new(p) != so8),
        "the drop-in run also loaded Mesa's libOSMesa: {inits:?}"
    );
    let (softgl_out, _) = run_scene(&softgl_bin, Via::AsBuilt, "softgl", &[]);
    assert!(
        dropin_out == softgl_out,
        "the drop-in run differs from the -lsoftgl build of the same scene"
    );
    println!(
        "smooth_triangles: drop-in == -lsoftgl ({} bytes); Mesa run {}",
        dropin_out.len(),
        if mesa_out == dropin_out {
            "identical too"
        } else {
            "differs"
        }
    );
}

/// A probe built against Mesa: which file really provides OSMesa and GL, seen from
/// inside the process (/proc/self/maps, dladdr) and by glGetString(GL_RENDERER).
const PROBE_C: &str = r#"
#define _GNU_SOURCE
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void where(const char *what, void *fn)
{
    Dl_info info;
    if (dladdr(fn, &info) && info.dli_fname)
        printf("dladdr %s %s\n", what, info.dli_fname);
}

int main(void)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    unsigned char *buf = malloc(16 * 16 * 4);
    char line[4096];
    FILE *maps;
    if (!ctx || !buf || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 16, 16))
        return 2;
    printf("renderer %s\n", (const char *)glGetString(GL_RENDERER));
    where("OSMesaCreateContextExt", (void *)OSMesaCreateContextExt);
    where("glBegin", (void *)glBegin);
    maps = fopen("/proc/self/maps", "r");
    if (!maps)
        return 3;
    while (fgets(line, sizeof line, maps)) {
        char *path = strchr(line, '/');
        if (path && (strstr(path, "OSMesa") || strstr(path, "softgl")))
            printf("map %s", path);
    }
    fclose(maps);
    OSMesaDestroyContext(ctx);
    return 0;
}
"#;

fn probe(bin: &Path, via: Via) -> (String, BTreeSet<PathBuf>, BTreeMap<String, PathBuf>) {
    let out = stdout(&check(command(bin, via)));
    let mut renderer = String::new();
    let mut maps = BTreeSet::new();
    let mut dl = BTreeMap::new();
    for l in out.lines() {
        if let Some(r) = l.strip_prefix("renderer ") {
            renderer = r.to_owned();
        } else if let Some(m) = l.strip_prefix("map ") {
            maps.insert(PathBuf::from(m.trim()));
        } else if let Some(d) = l.strip_prefix("dladdr ") {
            if let Some((f, p)) = d.split_once(' ') {
                dl.insert(f.to_owned(), PathBuf::from(p));
            }
        }
    }
    (renderer, maps, dl)
}

/// Seen from inside the process, the drop-in run maps softgl's file and not Mesa's.
#[test]
fn dropin_maps_softgl() {
    let src = write_source("probe", PROBE_C);
    let bin = compile(&src, "probe.mesa", Link::SystemOsmesa, &[]);
    let softgl_file = canon(&prefix().join("lib/libsoftgl.so"));
    let so8 = dropin_dir().join("libOSMesa.so.8");

    let (renderer, maps, _) = probe(&bin, Via::AsBuilt);
    assert!(!renderer.contains("softgl"), "Mesa run: {renderer}");
    assert!(
        !maps.contains(&softgl_file),
        "Mesa run maps softgl: {maps:?}"
    );

    let (renderer, maps, dl) = probe(&bin, Via::Dropin);
    assert_eq!(renderer, "softgl software rasterizer");
    // The kernel names the mapped file by its real path (the symlink's target).
    assert_eq!(
        maps,
        BTreeSet::from([softgl_file.clone()]),
        "the drop-in run must map softgl's file only"
    );
    for f in ["OSMesaCreateContextExt", "glBegin"] {
        assert_eq!(dl.get(f), Some(&so8), "dladdr({f}): {dl:?}");
    }

    // pkg-config osmesa builds link like Mesa's (NEEDED libOSMesa.so.8) against our
    // headers, and run on softgl through the drop-in folder.
    let bin = compile(&src, "probe.osmesa-pc", Link::PkgConfig("osmesa"), &[]);
    let mut cmd = Command::new("readelf");
    cmd.arg("-d").arg(&bin);
    let dynamic = stdout(&check(cmd));
    assert!(
        dynamic.contains("[libOSMesa.so.8]"),
        "pkg-config osmesa: NEEDED is not libOSMesa.so.8:\n{dynamic}"
    );
    let (renderer, maps, _) = probe(&bin, Via::Dropin);
    assert_eq!(renderer, "softgl software rasterizer");
    assert_eq!(maps, BTreeSet::from([softgl_file]));
    assert_eq!(
        pkg_config(&["--variable=libdir", "osmesa"]),
        dropin_dir().display().to_string()
    );
}

/// `cc prog.c $(pkg-config --cflags --libs softgl)` links to the installed libsoftgl.so
/// and draws the same bytes as the directly linked build.
#[test]
fn pkg_config_softgl() {
    if !have("pkg-config") {
        eprintln!("pkg_config_softgl: skipped, pkg-config is not installed");
        return;
    }
    let p = prefix();
    assert_eq!(
        pkg_config(&["--cflags", "softgl"]),
        format!("-I{}", p.join("include").display())
    );
    let source = root().join("c_tests/smooth_triangles.c");
    let bin = compile(
        &source,
        "smooth_triangles.pc",
        Link::PkgConfig("softgl"),
        &[],
    );
    let libs = ldd(&bin, Via::AsBuilt);
    assert_eq!(
        libs.get("libsoftgl.so").map(PathBuf::from),
        Some(p.join("lib/libsoftgl.so")),
        "ldd: {libs:?}"
    );
    assert!(!libs.contains_key("libOSMesa.so.8"), "ldd: {libs:?}");
    let direct = compile(&source, "smooth_triangles.softgl-pc", Link::Softgl, &[]);
    let (a, _) = run_scene(&bin, Via::AsBuilt, "pc", &[]);
    let (b, _) = run_scene(&direct, Via::AsBuilt, "softgl", &[]);
    assert!(a == b, "pkg-config build and -lsoftgl build differ");
}

/// A scene using the system libGLU for its matrices, written in the c_tests protocol.
const GLU_C: &str = r#"
#include <GL/gl.h>
#include <GL/glu.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 160
#define H 120

static void face(float r, float g, float b, const float *v)
{
    int i;
    for (i = 0; i < 4; i++) {
        glColor3f(r * (0.6f + 0.1f * i), g, b * (1.0f - 0.15f * i));
        glVertex3fv(v + 3 * i);
    }
}

int main(int argc, char **argv)
{
    static const float cube[6][12] = {
        {-1, -1, 1, 1, -1, 1, 1, 1, 1, -1, 1, 1},
        {1, -1, -1, -1, -1, -1, -1, 1, -1, 1, 1, -1},
        {1, -1, 1, 1, -1, -1, 1, 1, -1, 1, 1, 1},
        {-1, -1, -1, -1, -1, 1, -1, 1, 1, -1, 1, -1},
        {-1, 1, 1, 1, 1, 1, 1, 1, -1, -1, 1, -1},
        {-1, -1, -1, 1, -1, -1, 1, -1, 1, -1, -1, 1},
    };
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    GLdouble m[16];
    GLint err;
    char text[2048];
    int i, n = 0;
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    glClearColor(0.05f, 0.07f, 0.11f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    gluPerspective(47.3, (double)W / H, 0.71, 23.0);
    glGetDoublev(GL_PROJECTION_MATRIX, m);
    for (i = 0; i < 16; i++)
        n += snprintf(text + n, sizeof text - n, "%.17g ", m[i]);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    gluLookAt(3.1, 2.3, 4.7, 0.13, -0.21, 0.07, 0.0, 1.0, 0.0);
    glRotatef(17.0f, 0.3f, 1.0f, 0.1f);
    glGetDoublev(GL_MODELVIEW_MATRIX, m);
    n += snprintf(text + n, sizeof text - n, "\n");
    for (i = 0; i < 16; i++)
        n += snprintf(text + n, sizeof text - n, "%.17g ", m[i]);
    glBegin(GL_QUADS);
    for (i = 0; i < 6; i++)
        face((i + 1) / 6.0f, (i % 3) / 2.0f, 1.0f - i / 7.0f, cube[i]);
    glEnd();
    glFinish();
    err = glGetError();
    n += snprintf(text + n, sizeof text - n, "\nerror %d\n", (int)err);
    sgl_text(out, "matrices", "%s", text);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
"#;

/// libGLU's gl* calls bind to softgl through the drop-in, and the scene equals the
/// `-lsoftgl` build. With LD_BIND_NOW every libGLU import is bound at start-up, so the
/// log also names the GL functions libGLU needs that softgl does not export (they bind
/// to libGLU's own NEEDED libOpenGL.so.0 instead: no-ops without a GLX/EGL context).
#[test]
fn glu_binds_to_dropin() {
    if !Path::new("/usr/include/GL/glu.h").exists() {
        eprintln!("glu_binds_to_dropin: skipped, libglu1-mesa-dev is not installed");
        return;
    }
    let src = write_source("glu_scene", GLU_C);
    let mesa_bin = compile(&src, "glu_scene.mesa", Link::SystemOsmesa, &["-lGLU"]);
    let softgl_bin = compile(&src, "glu_scene.softgl", Link::Softgl, &["-lGLU"]);
    let so8 = dropin_dir().join("libOSMesa.so.8");

    let (dropin_out, log) = run_scene(
        &mesa_bin,
        Via::Dropin,
        "dropin",
        &[("LD_DEBUG", "bindings"), ("LD_BIND_NOW", "1")],
    );
    // "binding file /…/libGLU.so.1 [0] to /…/libOSMesa.so.8 [0]: normal symbol `glFoo'"
    let mut glu_binds: BTreeMap<String, String> = BTreeMap::new();
    for l in log.lines() {
        let Some((_, rest)) = l.split_once("binding file ") else {
            continue;
        };
        let Some((from, rest)) = rest.split_once(" [") else {
            continue;
        };
        if !from.contains("libGLU.so") {
            continue;
        }
        let (Some((_, to)), Some((_, sym))) = (rest.split_once(" to "), rest.split_once('`'))
        else {
            continue;
        };
        let to = to.split(" [").next().unwrap_or_default();
        let sym = sym.trim_end_matches('\'');
        if sym.starts_with("gl") && !sym.starts_with("glu") {
            glu_binds.insert(sym.to_owned(), to.to_owned());
        }
    }
    assert!(
        !glu_binds.is_empty(),
        "no libGLU gl* bindings in the LD_DEBUG log:\n{log}"
    );
    let exported = softgl_exports();
    let mut elsewhere = Vec::new();
    for (sym, to) in &glu_binds {
        if Path::new(to) == so8 {
            continue;
        }
        assert!(
            !exported.contains(sym),
            "libGLU's {sym} bound to {to} although softgl exports it"
        );
        elsewhere.push(format!("{sym} -> {to}"));
    }
    for sym in [
        "glMultMatrixd",
        "glMultMatrixf",
        "glTranslated",
        "glLoadIdentity",
    ] {
        if let Some(to) = glu_binds.get(sym) {
            assert_eq!(Path::new(to), so8, "libGLU's {sym}");
        }
    }
    assert!(
        ["glMultMatrixd", "glMultMatrixf"]
            .iter()
            .any(|s| glu_binds.get(*s).is_some_and(|t| Path::new(t) == so8)),
        "gluPerspective's glMultMatrix* does not bind to the drop-in: {glu_binds:?}"
    );
    println!(
        "libGLU: {} gl* imports, {} bound to the drop-in; not exported by softgl: {}",
        glu_binds.len(),
        glu_binds.len() - elsewhere.len(),
        if elsewhere.is_empty() {
            "none".to_owned()
        } else {
            elsewhere.join(", ")
        }
    );

    let (softgl_out, _) = run_scene(&softgl_bin, Via::AsBuilt, "softgl", &[]);
    assert!(
        dropin_out == softgl_out,
        "the GLU scene through the drop-in differs from its -lsoftgl build"
    );
    let (mesa_out, _) = run_scene(&mesa_bin, Via::AsBuilt, "mesa", &[]);
    println!(
        "glu_scene: drop-in == -lsoftgl; Mesa run {}",
        if mesa_out == dropin_out {
            "identical too"
        } else {
            "differs"
        }
    );
}

// ---------------------------------------------------------------------------
// Exports compared with Mesa's libOSMesa

fn defined_dynamic_symbols(lib: &Path) -> BTreeSet<String> {
    let mut cmd = Command::new("nm");
    cmd.arg("-D").arg("--defined-only").arg(lib);
    stdout(&check(cmd))
        .lines()
        .filter_map(|l| l.split_whitespace().nth(2).map(str::to_owned))
        .collect()
}

fn softgl_exports() -> BTreeSet<String> {
    defined_dynamic_symbols(&prefix().join("lib/libsoftgl.so"))
}

/// Names following `marker` (e.g. "GLAPIENTRY ") that start with "gl".
fn declared(text: &str, marker: &str) -> BTreeSet<String> {
    text.split(marker)
        .skip(1)
        .filter_map(|rest| {
            let name: String = rest
                .trim_start()
                .chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect();
            name.starts_with("gl").then_some(name)
        })
        .collect()
}

/// GL 1.0–2.1 entry points of Mesa's headers: `GL/gl.h` before its extension part,
/// and the GL_VERSION_1_2 … 2_1 sections of `GL/glext.h`.
fn gl21_names() -> BTreeSet<String> {
    let gl = fs::read_to_string("/usr/include/GL/gl.h").expect("/usr/include/GL/gl.h");
    let core = gl.split("#ifndef GL_ARB_multitexture").next().unwrap_or("");
    let ext = fs::read_to_string("/usr/include/GL/glext.h").expect("/usr/include/GL/glext.h");
    let start = ext
        .find("#ifndef GL_VERSION_1_2")
        .expect("glext.h: GL_VERSION_1_2");
    let end = ext
        .find("#ifndef GL_VERSION_3_0")
        .expect("glext.h: GL_VERSION_3_0");
    let mut names = declared(core, "GLAPIENTRY ");
    names.extend(declared(&ext[start..end], "APIENTRY "));
    names
}

/// The ARB/EXT/... names Mesa's libOSMesa exports for the GL 1.0–2.1 functions in `names`
/// (glActiveTextureARB, glBindBufferARB …), except `glIsProgramARB` and
/// `glGetProgramivARB`: those are GL_ARB_vertex_program's (assembly programs, which softgl
/// does not implement or advertise), not names of GL 2.0's glIsProgram and glGetProgramiv.
fn promoted_aliases(names: &BTreeSet<String>, mesa: &BTreeSet<String>) -> BTreeSet<String> {
    const SUFFIXES: [&str; 8] = ["ARB", "EXT", "MESA", "SGIS", "NV", "ATI", "IBM", "SGI"];
    mesa.iter()
        .filter(|m| !matches!(m.as_str(), "glIsProgramARB" | "glGetProgramivARB"))
        .filter(|m| {
            SUFFIXES
                .iter()
                .any(|s| m.strip_suffix(s).is_some_and(|core| names.contains(core)))
        })
        .cloned()
        .collect()
}

/// The GL 1.0–2.1 functions Mesa's libOSMesa exports, and their ARB/EXT aliases, that
/// softgl does not export must be exactly the committed list
/// `docs/missing-entry-points.txt` (an unchanged binary calling one fails to load on the
/// drop-in): adding a function without updating the list fails, and so does a list that
/// claims more than is missing. The list is also written to
/// `target/dropin/missing-exports.txt`.
#[test]
fn exports_compared_with_mesa() {
    let mesa_lib = Path::new("/usr/lib/x86_64-linux-gnu/libOSMesa.so.8");
    ensure_reference();
    assert!(mesa_lib.exists(), "{} not found", mesa_lib.display());
    let names = gl21_names();
    assert!(
        names.len() > 400,
        "header parsing found only {}",
        names.len()
    );
    let mesa = defined_dynamic_symbols(mesa_lib);
    let ours = softgl_exports();
    let mut wanted: BTreeSet<String> = names
        .iter()
        .filter(|n| mesa.contains(*n))
        .cloned()
        .collect();
    let aliases = promoted_aliases(&names, &mesa);
    assert!(aliases.contains("glActiveTextureARB") && aliases.contains("glBindBufferARB"));
    wanted.extend(aliases);
    let missing: Vec<&str> = wanted
        .iter()
        .filter(|n| !ours.contains(*n))
        .map(|s| s.as_str())
        .collect();
    let report = format!(
        "{} of the {} GL 1.0-2.1 entry points and ARB/EXT aliases Mesa's libOSMesa exports are not exported by softgl:\n{}\n",
        missing.len(),
        wanted.len(),
        missing.join("\n")
    );
    fs::write(work_dir().join("missing-exports.txt"), &report).expect("write report");
    println!("{report}");
    let listed = fs::read_to_string(root().join("docs/missing-entry-points.txt"))
        .expect("docs/missing-entry-points.txt");
    let listed: Vec<&str> = listed
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .collect();
    assert_eq!(
        listed, missing,
        "docs/missing-entry-points.txt disagrees with the exports (left: the file, right: \
         what is missing now); update the file"
    );
}

/// Every `gl*` function softgl exports resolves through OSMesaGetProcAddress, to the
/// same function (checked by name lookup in the proc table the build script generates).
#[test]
fn every_export_resolves_through_get_proc_address() {
    let ours = softgl_exports();
    let gl: Vec<&String> = ours.iter().filter(|n| n.starts_with("gl")).collect();
    assert!(gl.len() > 300, "only {} gl exports", gl.len());
    let unresolved: Vec<&&String> = gl
        .iter()
        .filter(|n| {
            let c = std::ffi::CString::new(n.as_str()).unwrap();
            // SAFETY: a NUL-terminated name.
            unsafe { softgl::ffi::osmesa::OSMesaGetProcAddress(c.as_ptr()) }.is_none()
        })
        .collect();
    assert!(unresolved.is_empty(), "not resolvable: {unresolved:?}");
}

/// `src/ffi/aliases_gl.rs` and `aliases_ext.rs` are what `tools/gen_aliases.py` makes of
/// today's core functions: a new core entry point whose Mesa alias is not exported fails
/// here.
#[test]
fn aliases_are_fresh() {
    let out = Command::new("python3")
        .arg(root().join("tools/gen_aliases.py"))
        .arg("--check")
        .output()
        .expect("python3");
    assert!(
        out.status.success(),
        "run `python3 tools/gen_aliases.py` and regenerate the headers: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The functions Mesa's headers declare for extension `ext` (its `#ifndef ext` section in
/// `GL/gl.h` or `GL/glext.h`).
fn extension_functions(ext: &str) -> BTreeSet<String> {
    let mut names = BTreeSet::new();
    for h in ["/usr/include/GL/gl.h", "/usr/include/GL/glext.h"] {
        let text = fs::read_to_string(h).expect(h);
        let open = format!("#ifndef {ext}\n");
        let mut rest = text.as_str();
        while let Some(i) = rest.find(&open) {
            let body = &rest[i + open.len()..];
            let end = body
                .find(&format!("#endif /* {ext} */"))
                .unwrap_or(body.len());
            names.extend(declared(&body[..end], "APIENTRY "));
            rest = &body[end..];
        }
    }
    names
}

/// Every extension GL_EXTENSIONS advertises has all its entry points (as Mesa's headers
/// declare them) resolvable through OSMesaGetProcAddress.
#[test]
fn advertised_extensions_resolve() {
    let exts = softgl::ffi::query::EXTENSIONS.trim_end_matches('\0');
    let mut checked = 0;
    let mut unresolved = Vec::new();
    for ext in exts.split_whitespace() {
        for f in extension_functions(ext) {
            checked += 1;
            let c = std::ffi::CString::new(f.as_str()).unwrap();
            // SAFETY: a NUL-terminated name.
            if unsafe { softgl::ffi::osmesa::OSMesaGetProcAddress(c.as_ptr()) }.is_none() {
                unresolved.push(format!("{ext}: {f}"));
            }
        }
    }
    assert!(
        checked > 20,
        "only {checked} entry points found in the headers"
    );
    assert!(
        unresolved.is_empty(),
        "advertised but missing: {unresolved:#?}"
    );
    // The extensions issue 8 requires (each must also pass the check above), among them
    // the GL 1.4 vertex extras whose entry points the loop resolves: glPointParameter*ARB,
    // glFogCoord*EXT with glFogCoordPointerEXT, glSecondaryColor*EXT with
    // glSecondaryColorPointerEXT.
    let required = [
        "GL_ARB_multitexture",
        "GL_ARB_vertex_buffer_object",
        "GL_ARB_occlusion_query",
        "GL_ARB_texture_cube_map",
        "GL_ARB_texture_env_combine",
        "GL_ARB_depth_texture",
        "GL_ARB_shadow",
        "GL_ARB_point_parameters",
        "GL_ARB_window_pos",
        "GL_EXT_blend_minmax",
        "GL_EXT_blend_subtract",
        "GL_EXT_blend_func_separate",
        "GL_EXT_blend_color",
        "GL_EXT_fog_coord",
        "GL_EXT_secondary_color",
        "GL_EXT_stencil_wrap",
        "GL_EXT_texture_lod_bias",
        "GL_EXT_texture_filter_anisotropic",
        "GL_SGIS_generate_mipmap",
        "GL_NV_blend_square",
    ];
    let advertised: BTreeSet<&str> = exts.split_whitespace().collect();
    let missing: Vec<&str> = required
        .into_iter()
        .filter(|e| !advertised.contains(e))
        .collect();
    assert!(missing.is_empty(), "not advertised: {missing:?}");
    for ext in [
        "GL_ARB_point_parameters",
        "GL_EXT_fog_coord",
        "GL_EXT_secondary_color",
    ] {
        assert!(
            !extension_functions(ext).is_empty(),
            "{ext} declares no functions in Mesa's headers"
        );
    }
}
