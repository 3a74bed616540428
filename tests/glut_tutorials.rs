//! softglut (the `glut/` workspace member): GLUT tutorials run headless.
//!
//! - `libsoftglut.so` is built with cargo (same profile as this test);
//! - every program in `tutorials/` is compiled twice against the same GLUT library,
//!   once linked with `-lsoftgl`, once with Mesa's `-lOSMesa`; both run with the same
//!   `SOFTGLUT_*` settings (frames, keys) and their PNG frames are compared pixel by
//!   pixel (`TUTORIALS` gives each one's frame count, keys and allowed difference);
//! - the softgl build runs twice and must write byte-identical files;
//! - the GLU tutorials (`glu: true`: the tessellator ones) are also linked with SGI's
//!   libGLU ahead of softglut (`-lGLU -lsoftglut -lOSMesa`, Debian's libglu1-mesa):
//!   softglut's GLU on Mesa must draw the same pixels and print the same lines
//!   (errors, properties) as SGI's GLU on Mesa;
//! - `scripts/install.sh` installs GLUT, and `cc prog.c $(pkg-config --cflags --libs
//!   softgl-glut)` builds an unchanged tutorial that writes the configured frames;
//! - the hand-written headers `glut/include/GL/{glut,freeglut,glu}.h` declare exactly
//!   what `libsoftglut.so` exports, with freeglut's and GLU's values, and compile as
//!   C89 and C++.
//!
//! Everything is built under `target/glut/`. `SOFTGLUT_TEST_SAVE=1` keeps a side-by-side
//! diff picture for every differing frame in `target/glut/diff/`.

mod glut_common;

use glut_common::*;
use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

/// One tutorial run: program, frames, keys fed, and the allowed difference.
struct Tutorial {
    name: &'static str,
    frames: u32,
    keys: &'static str,
    /// Largest allowed channel difference against Mesa (0: bit-identical).
    max_diff: u8,
    /// Also compared with the program linked with SGI's libGLU (on Mesa).
    glu: bool,
    /// Pixels per frame allowed beyond `max_diff` on softgl (known GL differences).
    odd_pixels: usize,
}

/// The tutorials and how they are driven. Every one is bit-identical to OSMesa but for
/// the `odd_pixels` noted.
const TUTORIALS: &[Tutorial] = &[
    Tutorial {
        name: "cube",
        frames: 6,
        keys: "1:UP,2:RIGHT,3:+,4:l,5:s",
        max_diff: 0,
        glu: false,
        odd_pixels: 0,
    },
    Tutorial {
        name: "texture",
        frames: 6,
        keys: "3:m",
        max_diff: 0,
        glu: false,
        odd_pixels: 0,
    },
    Tutorial {
        name: "fog",
        frames: 6,
        keys: "2:f,3:+,4:f,5:-",
        max_diff: 0,
        glu: false,
        odd_pixels: 0,
    },
    Tutorial {
        name: "blend",
        frames: 6,
        keys: "2:a,3:b,4:b,5:A",
        max_diff: 0,
        glu: false,
        odd_pixels: 0,
    },
    Tutorial {
        name: "robot",
        frames: 6,
        keys: "1:s,1:s,2:e,2:e,3:f,4:r,5:E",
        max_diff: 0,
        glu: false,
        odd_pixels: 0,
    },
    // Every winding rule filled, then boundary-only loops and edge-flagged lines.
    Tutorial {
        name: "tess",
        frames: 8,
        keys: "1:w,2:w,3:w,4:w,5:m,6:w,7:m",
        max_diff: 0,
        glu: true,
        odd_pixels: 0,
    },
    Tutorial {
        name: "tesswind",
        frames: 10,
        keys: "1:w,2:w,3:w,4:w,5:b,6:w,7:w,8:w,9:w",
        max_diff: 0,
        glu: true,
        odd_pixels: 0,
    },
    Tutorial {
        name: "tessmisc",
        frames: 3,
        keys: "1:e,2:e",
        max_diff: 0,
        glu: true,
        odd_pixels: 0,
    },
    // Random self-intersecting polygons: filled, boundary-only, edge-flagged lines.
    // Frame 11 has a sliver triangle (area ~2e-4 px²) drawn in GL_LINE mode: Mesa's
    // draw module drops it as zero-area, softgl draws its one flagged edge (2 pixels,
    // one of them also lit by a neighbour). SGI's GLU and softglut's emit the same
    // pixels on Mesa; this is softgl against Mesa only.
    // Shared edges, touching holes, T-junctions, overlaps, zero area, repeats.
    Tutorial {
        name: "tessdegen",
        frames: 15,
        keys: "",
        max_diff: 0,
        glu: true,
        odd_pixels: 0,
    },
    // GLUT_ACCUM: motion blur through the accumulation buffer.
    Tutorial {
        name: "accum",
        frames: 4,
        keys: "1:j,2:r,3:j",
        max_diff: 0,
        glu: false,
        odd_pixels: 0,
    },
    Tutorial {
        name: "tessrand",
        frames: 15,
        keys: "",
        max_diff: 0,
        glu: true,
        odd_pixels: 1,
    },
];

/// Runs a tutorial binary into a fresh folder; returns the sorted PNG paths.
fn run(bin: &Path, t: &Tutorial, out: &Path) -> Vec<PathBuf> {
    run_with_stdout(bin, t, out).0
}

/// [`run`], also returning what the program printed.
fn run_with_stdout(bin: &Path, t: &Tutorial, out: &Path) -> (Vec<PathBuf>, String) {
    let _ = fs::remove_dir_all(out);
    let o = Command::new(bin)
        .env("SOFTGLUT_FRAMES", t.frames.to_string())
        .env("SOFTGLUT_OUTPUT", out)
        .env("SOFTGLUT_KEYS", t.keys)
        .env("LP_NUM_THREADS", "1")
        // Pins llvmpipe's fusing to softgl's level (softgl ignores the variable).
        .envs(softgl::cpu::reference_cpu_caps().map(|c| ("GALLIUM_OVERRIDE_CPU_CAPS", c)))
        .env_remove("SOFTGLUT_SIZE")
        .env_remove("SOFTGLUT_STEP_MS")
        .output()
        .expect("run tutorial");
    assert!(
        o.status.success(),
        "{} exited with {}:\n{}",
        bin.display(),
        o.status,
        String::from_utf8_lossy(&o.stderr)
    );
    let mut files: Vec<PathBuf> = fs::read_dir(out)
        .expect("output folder")
        .flatten()
        .map(|e| e.path())
        .collect();
    files.sort();
    (files, String::from_utf8_lossy(&o.stdout).into_owned())
}

/// (% identical pixels, largest channel difference) between two PNG files.
fn compare(a: &Path, b: &Path) -> (f64, u8) {
    let (pct, max, _) = compare_count(a, b, 0);
    (pct, max)
}

/// [`compare`], plus the number of pixels differing by more than `tolerance`.
fn compare_count(a: &Path, b: &Path, tolerance: u8) -> (f64, u8, usize) {
    let ia = image::open(a).expect("decode png").to_rgb8();
    let ib = image::open(b).expect("decode png").to_rgb8();
    assert_eq!(ia.dimensions(), ib.dimensions(), "{}", a.display());
    let mut same = 0usize;
    let mut over = 0usize;
    let mut max = 0u8;
    for (pa, pb) in ia.pixels().zip(ib.pixels()) {
        let d = (0..3).map(|c| pa[c].abs_diff(pb[c])).max().unwrap_or(0);
        same += usize::from(d == 0);
        over += usize::from(d > tolerance);
        max = max.max(d);
    }
    let total = ia.pixels().len().max(1);
    (100.0 * same as f64 / total as f64, max, over)
}

fn tutorial_test(t: &Tutorial) {
    if !Path::new("/usr/include/GL/osmesa.h").exists() {
        eprintln!("{}: skipped, Mesa's OSMesa is not installed", t.name);
        return;
    }
    let dir = work_dir().join("out").join(t.name);
    let sg = compile(t.name, Gl::Softgl);
    let mesa = compile(t.name, Gl::Osmesa);
    let a = run(&sg, t, &dir.join("softgl"));
    let a2 = run(&sg, t, &dir.join("softgl.again"));
    let b = run(&mesa, t, &dir.join("osmesa"));
    let names = |v: &[PathBuf]| -> Vec<String> {
        v.iter()
            .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
            .collect()
    };
    let want: Vec<String> = (0..t.frames).map(|f| format!("frame_{f:04}.png")).collect();
    assert_eq!(names(&a), want, "{}: softgl frames", t.name);
    assert_eq!(names(&b), want, "{}: OSMesa frames", t.name);
    assert_eq!(names(&a2), want, "{}: second run frames", t.name);
    for (x, y) in a.iter().zip(&a2) {
        assert!(
            fs::read(x).unwrap() == fs::read(y).unwrap(),
            "{}: two runs differ in {}",
            t.name,
            x.display()
        );
    }
    let mut failures = Vec::new();
    for (x, y) in a.iter().zip(&b) {
        let (pct, max, over) = compare_count(x, y, t.max_diff);
        let frame = x.file_name().unwrap().to_string_lossy();
        println!("{:8} {frame}: {pct:8.4}% identical, max diff {max}", t.name);
        if over > t.odd_pixels {
            failures.push(format!("{frame}: {pct:.4}% identical, max diff {max}"));
        }
    }
    assert!(
        failures.is_empty(),
        "{} differs from OSMesa beyond max diff {}:\n{}",
        t.name,
        t.max_diff,
        failures.join("\n")
    );
    if t.glu {
        compare_with_sgi_glu(t, &dir);
    }
}

/// softglut's GLU against SGI's libGLU, both on Mesa: same pixels, same output.
fn compare_with_sgi_glu(t: &Tutorial, dir: &Path) {
    if !Path::new("/usr/include/GL/glu.h").exists() {
        eprintln!(
            "{}: SGI libGLU comparison skipped (no libglu1-mesa-dev)",
            t.name
        );
        return;
    }
    let (ours, ours_out) =
        run_with_stdout(&compile(t.name, Gl::Osmesa), t, &dir.join("osmesa.glu"));
    let (sgi, sgi_out) = run_with_stdout(&compile(t.name, Gl::SgiGlu), t, &dir.join("sgi-glu"));
    assert_eq!(ours.len(), sgi.len(), "{}: frame counts", t.name);
    let mut failures = Vec::new();
    for (x, y) in ours.iter().zip(&sgi) {
        let (pct, max) = compare(x, y);
        let frame = x.file_name().unwrap().to_string_lossy();
        println!(
            "{:8} {frame}: {pct:8.4}% identical to SGI's GLU, max diff {max}",
            t.name
        );
        if max > 0 {
            failures.push(format!("{frame}: {pct:.4}% identical, max diff {max}"));
        }
    }
    assert!(
        failures.is_empty(),
        "{}: softglut's GLU draws differently from SGI's libGLU:\n{}",
        t.name,
        failures.join("\n")
    );
    assert_eq!(
        ours_out, sgi_out,
        "{}: printed output differs from SGI's GLU",
        t.name
    );
}

#[test]
fn tutorial_cube() {
    tutorial_test(&TUTORIALS[0]);
}

#[test]
fn tutorial_texture() {
    tutorial_test(&TUTORIALS[1]);
}

#[test]
fn tutorial_fog() {
    tutorial_test(&TUTORIALS[2]);
}

#[test]
fn tutorial_blend() {
    tutorial_test(&TUTORIALS[3]);
}

#[test]
fn tutorial_robot() {
    tutorial_test(&TUTORIALS[4]);
}

#[test]
fn tutorial_tess() {
    tutorial_test(&TUTORIALS[5]);
}

#[test]
fn tutorial_tesswind() {
    tutorial_test(&TUTORIALS[6]);
}

#[test]
fn tutorial_tessmisc() {
    tutorial_test(&TUTORIALS[7]);
}

#[test]
fn tutorial_tessdegen() {
    tutorial_test(&TUTORIALS[8]);
}

#[test]
fn tutorial_accum() {
    tutorial_test(&TUTORIALS[9]);
}

#[test]
fn tutorial_tessrand() {
    tutorial_test(&TUTORIALS[10]);
}

#[test]
fn every_tutorial_is_in_the_table() {
    let mut on_disk: Vec<String> = fs::read_dir(root().join("tutorials"))
        .expect("tutorials/")
        .flatten()
        .filter_map(|e| {
            let p = e.path();
            (p.extension()? == "c").then(|| p.file_stem().unwrap().to_string_lossy().into())
        })
        .collect();
    on_disk.sort();
    let mut listed: Vec<String> = TUTORIALS.iter().map(|t| t.name.to_string()).collect();
    listed.sort();
    assert_eq!(on_disk, listed);
}

/// The environment overrides: window size, step, frame count; glutLeaveMainLoop via
/// Esc is not used (the tutorials exit(0) there), so frames stop at the count.
#[test]
fn size_override_and_frame_count() {
    let sg = compile("cube", Gl::Softgl);
    let out = work_dir().join("out").join("size");
    let _ = fs::remove_dir_all(&out);
    let status = Command::new(&sg)
        .env("SOFTGLUT_FRAMES", "3")
        .env("SOFTGLUT_OUTPUT", &out)
        .env("SOFTGLUT_SIZE", "64x48")
        .env("SOFTGLUT_STEP_MS", "100")
        .status()
        .expect("run cube");
    assert!(status.success());
    let mut files: Vec<_> = fs::read_dir(&out)
        .unwrap()
        .flatten()
        .map(|e| e.path())
        .collect();
    files.sort();
    assert_eq!(files.len(), 3);
    let img = image::open(&files[0]).unwrap();
    assert_eq!((img.width(), img.height()), (64, 48));
    // Esc calls exit(0) in the tutorial: the frames before it are written.
    let out2 = work_dir().join("out").join("esc");
    let _ = fs::remove_dir_all(&out2);
    let status = Command::new(&sg)
        .env("SOFTGLUT_FRAMES", "10")
        .env("SOFTGLUT_OUTPUT", &out2)
        .env("SOFTGLUT_KEYS", "2:ESC")
        .status()
        .expect("run cube");
    assert!(status.success());
    assert_eq!(fs::read_dir(&out2).unwrap().count(), 2);
}

fn have(tool: &str) -> bool {
    Command::new(tool)
        .arg("--version")
        .output()
        .map(|o| o.status.success())
        .unwrap_or(false)
}

/// `install.sh` + `pkg-config --cflags --libs softgl-glut` build an unchanged tutorial.
#[test]
fn pkg_config_builds_a_tutorial() {
    if !have("pkg-config") {
        eprintln!("pkg_config_builds_a_tutorial: skipped, no pkg-config");
        return;
    }
    let glut = glut_dir();
    let prefix = work_dir().join("prefix");
    let status = Command::new("bash")
        .arg(root().join("scripts/install.sh"))
        .arg(&prefix)
        .env("SOFTGL_LIB", softgl_dir().join("libsoftgl.so"))
        .env("SOFTGLUT_LIB", glut.join("libsoftglut.so"))
        .status()
        .expect("run install.sh");
    assert!(status.success(), "install.sh failed");
    let pc = Command::new("pkg-config")
        .args(["--cflags", "--libs", "softgl-glut"])
        .env("PKG_CONFIG_PATH", prefix.join("lib/pkgconfig"))
        .output()
        .expect("pkg-config");
    assert!(pc.status.success(), "pkg-config softgl-glut failed");
    let flags = String::from_utf8(pc.stdout).unwrap();
    let bin_dir = work_dir().join("bin");
    fs::create_dir_all(&bin_dir).expect("mkdir bin");
    let bin = bin_dir.join("robot.pkgconfig");
    let status = Command::new(cc())
        .arg(root().join("tutorials/robot.c"))
        .arg("-o")
        .arg(&bin)
        .args(flags.split_whitespace())
        .status()
        .expect("cc");
    assert!(
        status.success(),
        "cc tutorials/robot.c $(pkg-config ...) failed"
    );
    let t = Tutorial {
        name: "robot",
        frames: 2,
        keys: "1:s",
        max_diff: 0,
        glu: false,
        odd_pixels: 0,
    };
    let files = run(&bin, &t, &work_dir().join("out").join("pkgconfig"));
    assert_eq!(files.len(), 2);
    // The installed GLUT draws what the build-tree GLUT draws.
    let tree = run(
        &compile("robot", Gl::Softgl),
        &t,
        &work_dir().join("out/pkgconfig.tree"),
    );
    for (x, y) in files.iter().zip(&tree) {
        assert!(
            fs::read(x).unwrap() == fs::read(y).unwrap(),
            "{}",
            x.display()
        );
    }
}

// ---------------------------------------------------------------------------
// Headers

/// Functions declared (`GLUTAPI`/`GLUAPI` prototypes) in the hand-written headers.
fn declared() -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for h in ["glut.h", "freeglut.h", "glu.h"] {
        let text = fs::read_to_string(root().join("glut/include/GL").join(h)).expect("header");
        for line in text.lines() {
            let Some(rest) = line
                .strip_prefix("GLUTAPI ")
                .or(line.strip_prefix("GLUAPI "))
            else {
                continue;
            };
            // Prototypes only (the font handles are data: `GLUTAPI void *name;`).
            let Some((head, _)) = rest.split_once('(') else {
                continue;
            };
            let name = head
                .rsplit([' ', '*'])
                .next()
                .unwrap_or("")
                .trim_end_matches(';');
            assert!(out.insert(name.to_string()), "{name} declared twice");
        }
    }
    out
}

/// `#define NAME VALUE` pairs with integer values.
fn int_defines(text: &str) -> BTreeMap<String, i64> {
    let mut out = BTreeMap::new();
    for line in text.lines() {
        let mut w = line.split_whitespace();
        if w.next() != Some("#define") {
            continue;
        }
        let (Some(n), Some(v)) = (w.next(), w.next()) else {
            continue;
        };
        let v = match v.strip_prefix("0x") {
            Some(h) => i64::from_str_radix(h, 16).ok(),
            None => v.parse().ok(),
        };
        if let Some(v) = v {
            out.insert(n.to_string(), v);
        }
    }
    out
}

#[test]
fn headers_match_the_library_and_freeglut() {
    let lib = glut_dir().join("libsoftglut.so");
    let nm = Command::new("nm")
        .args(["-D", "--defined-only"])
        .arg(&lib)
        .output()
        .expect("run nm");
    assert!(nm.status.success());
    let text = String::from_utf8_lossy(&nm.stdout);
    let mut functions = BTreeSet::new();
    let mut data = BTreeSet::new();
    for l in text.lines() {
        let f: Vec<&str> = l.split_whitespace().collect();
        if f.len() == 3 && (f[2].starts_with("glut") || f[2].starts_with("glu")) {
            if f[1] == "T" {
                functions.insert(f[2].to_string());
            } else {
                data.insert(f[2].to_string());
            }
        }
    }
    let decl = declared();
    let undeclared: Vec<_> = functions.difference(&decl).collect();
    let missing: Vec<_> = decl.difference(&functions).collect();
    assert!(
        undeclared.is_empty(),
        "exported, not declared: {undeclared:?}"
    );
    assert!(missing.is_empty(), "declared, not exported: {missing:?}");
    let glut_h = fs::read_to_string(root().join("glut/include/GL/glut.h")).unwrap();
    for sym in &data {
        assert!(
            glut_h.contains(&format!("GLUTAPI void *{sym};")),
            "font symbol {sym} not declared"
        );
    }
    // Values: every GLUT_/GLU_ constant equals the system freeglut's / GLU's.
    let mut ours = BTreeMap::new();
    for h in ["glut.h", "freeglut.h", "glu.h"] {
        ours.extend(int_defines(
            &fs::read_to_string(root().join("glut/include/GL").join(h)).unwrap(),
        ));
    }
    let mut reference = BTreeMap::new();
    for h in ["freeglut_std.h", "freeglut_ext.h", "glu.h"] {
        if let Ok(t) = fs::read_to_string(Path::new("/usr/include/GL").join(h)) {
            reference.extend(int_defines(&t));
        }
    }
    if reference.is_empty() {
        eprintln!("note: no system freeglut/GLU headers; values unchecked");
    }
    let mut checked = 0;
    for (name, v) in &ours {
        if let Some(r) = reference.get(name) {
            assert_eq!(v, r, "{name}");
            checked += 1;
        }
    }
    println!("{checked} constants equal to freeglut's/GLU's");
}

#[test]
fn headers_compile_as_c89_and_cpp() {
    let dir = work_dir().join("hdr");
    fs::create_dir_all(&dir).unwrap();
    let src = dir.join("h.c");
    fs::write(
        &src,
        "#include <GL/freeglut.h>\n#include <GL/glu.h>\n\
         int main(void) { void *f = GLUT_STROKE_ROMAN; return f == GLUT_BITMAP_8_BY_13; }\n",
    )
    .unwrap();
    let inc = [
        format!("-I{}", root().join("glut/include").display()),
        format!("-I{}", root().join("include").display()),
    ];
    let o = Command::new(cc())
        .args(&inc)
        .args(["-std=c89", "-pedantic", "-Wall", "-Werror", "-fsyntax-only"])
        .arg(&src)
        .output()
        .expect("cc");
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    if have("c++") {
        let o = Command::new("c++")
            .args(&inc)
            .args(["-Wall", "-Werror", "-fsyntax-only", "-x", "c++"])
            .arg(&src)
            .output()
            .expect("c++");
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    }
}

/// Compiles and runs a C snippet against softglut and the chosen GL; returns the first
/// frame (RGB).
fn run_snippet(name: &'static str, code: &str, gl: Gl) -> image::RgbImage {
    let dir = work_dir().join("snippets");
    fs::create_dir_all(&dir).unwrap();
    let src = dir.join(format!("{name}.c"));
    fs::write(&src, code).unwrap();
    let bin = build(&src, &dir.join(format!("{name}.{gl:?}").to_lowercase()), gl);
    let t = Tutorial {
        name,
        frames: 1,
        keys: "",
        max_diff: 0,
        glu: false,
        odd_pixels: 0,
    };
    let files = run(&bin, &t, &dir.join(format!("{name}.{gl:?}.out")));
    image::open(&files[0]).unwrap().to_rgb8()
}

/// Bitmap fonts go through glBitmap, found with OSMesaGetProcAddress: the text softgl
/// draws is the text Mesa draws, pixel for pixel (Mesa's bitmap cache included: the
/// glyphs are drawn at glFlush).
#[test]
fn bitmap_font_uses_glbitmap_when_the_gl_has_it() {
    if !Path::new("/usr/include/GL/osmesa.h").exists() {
        return;
    }
    let text = |raster: &str| {
        format!(
            "#include <GL/freeglut.h>\n\
             static void display(void) {{\n\
               glClear(GL_COLOR_BUFFER_BIT);\n\
               glMatrixMode(GL_PROJECTION); glLoadIdentity(); gluOrtho2D(0, 64, 0, 32);\n\
               glColor3f(1, 1, 1);\n\
               {raster}\n\
               glutBitmapString(GLUT_BITMAP_9_BY_15, (const unsigned char *)\"HI\");\n\
               if (glutBitmapLength(GLUT_BITMAP_9_BY_15, (const unsigned char *)\"HI\") != 18) glClearColor(1, 0, 0, 1);\n\
               if (glutBitmapHeight(GLUT_BITMAP_8_BY_13) != 13) glClearColor(1, 0, 0, 1);\n\
               glFlush();\n\
             }}\n\
             int main(int c, char **v) {{ glutInit(&c, v); glutInitWindowSize(64, 32);\n\
               glutCreateWindow(\"t\"); glutDisplayFunc(display); glutMainLoop(); return 0; }}\n"
        )
    };
    let code = text("glRasterPos2i(4, 8);");
    let mesa = run_snippet("bitmap", &code, Gl::Osmesa);
    let lit = mesa.pixels().filter(|p| p[0] == 255 && p[1] == 255).count();
    assert!(lit > 20, "Mesa drew {lit} text pixels");
    let sg = run_snippet("bitmap_softgl", &code, Gl::Softgl);
    let diff = sg
        .pixels()
        .zip(mesa.pixels())
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(
        diff, 0,
        "softgl's bitmap text differs from Mesa's in {diff} pixels"
    );
}
