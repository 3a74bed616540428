//! Comparisons of softgl's headers with Mesa's (`/usr/include/GL/{gl,glext}.h` of Debian's
//! libgl-dev, which scripts/ensure-deps.sh installs with libosmesa6-dev): a program that
//! compiles against Mesa's headers compiles against ours.

use super::{generator, have, int_defines, lib_dir, read_header, root, run, scratch};
use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;
use std::process::Command;

/// Mesa's headers.
const MESA_GL: &str = "/usr/include/GL/gl.h";
/// Mesa's glext.h.
const MESA_GLEXT: &str = "/usr/include/GL/glext.h";

/// What gl.h leaves out with GL_GLEXT_LEGACY, unlike Mesa's (see `GL_H_TAIL` in
/// examples/gen_headers/generator.rs): GL_OES_EGL_image, an OpenGL ES extension.
const LEGACY_DIFFERENCES: &[&str] = &[
    "GLeglImageOES",
    "PFNGLEGLIMAGETARGETTEXTURE2DOESPROC",
    "PFNGLEGLIMAGETARGETRENDERBUFFERSTORAGEOESPROC",
    "glEGLImageTargetTexture2DOES",
    "glEGLImageTargetRenderbufferStorageOES",
];

/// Names Mesa's headers declare only on Windows (`#if defined(_WIN32)`).
const WINDOWS_ONLY: &[&str] = &["WIN32_LEAN_AND_MEAN", "__WIN32__"];

/// The text of Mesa's gl.h and glext.h, or `None` (with a note) when they are absent.
fn mesa_headers() -> Option<[String; 2]> {
    let read = |p: &str| std::fs::read_to_string(p).ok();
    match (read(MESA_GL), read(MESA_GLEXT)) {
        (Some(gl), Some(glext)) => Some([gl, glext]),
        _ => {
            eprintln!(
                "note: Mesa's gl.h/glext.h absent (run scripts/ensure-deps.sh); check skipped"
            );
            None
        }
    }
}

/// The first C identifier in `s`.
fn ident(s: &str) -> String {
    s.trim_start_matches(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect()
}

/// Every macro, typedef and function name a header's text declares: `#define NAME`,
/// `typedef … NAME;`, `typedef RET (APIENTRYP NAME) (…);` and `GLAPI … NAME (…`, each
/// wherever it appears (whichever `#if` branch).
fn declared_names(text: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for line in text.lines().map(str::trim_start) {
        let name = if let Some(rest) = line.strip_prefix("#define ") {
            ident(rest)
        } else if line.starts_with("typedef ") {
            match (line.find('('), line.find(')')) {
                // A function-pointer type: the name is the last word inside the first ( ).
                (Some(open), Some(close)) if open < close => line[open + 1..close]
                    .rsplit(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                    .next()
                    .unwrap_or("")
                    .to_string(),
                _ => line
                    .trim_end_matches(';')
                    .rsplit(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                    .next()
                    .unwrap_or("")
                    .to_string(),
            }
        } else if line.starts_with("GLAPI ") {
            let head = line.split('(').next().unwrap_or("").trim_end();
            head.rsplit([' ', '*']).next().unwrap_or("").to_string()
        } else {
            continue;
        };
        if !name.is_empty() {
            out.insert(name);
        }
    }
    out
}

/// Every enum, typedef and prototype name of Mesa's gl.h and glext.h is declared by ours.
#[test]
fn every_name_of_mesas_headers_is_declared() {
    let Some(mesa) = mesa_headers() else {
        return;
    };
    let mesa: BTreeSet<String> = mesa.iter().flat_map(|t| declared_names(t)).collect();
    let ours: BTreeSet<String> = [generator::Header::Gl, generator::Header::Glext]
        .into_iter()
        .flat_map(|h| declared_names(&read_header(h)))
        .collect();
    let missing: Vec<&String> = mesa
        .iter()
        .filter(|n| !ours.contains(*n) && !WINDOWS_ONLY.contains(&n.as_str()))
        .collect();
    assert!(
        missing.is_empty(),
        "{} names of Mesa's headers are not declared by ours: {missing:?}",
        missing.len()
    );
    let kinds = |set: &BTreeSet<String>| {
        let pfn = set.iter().filter(|n| n.starts_with("PFN")).count();
        let fns = set.iter().filter(|n| n.starts_with("gl")).count();
        (set.len(), pfn, fns)
    };
    eprintln!(
        "names (all, PFN types, functions): Mesa {:?}, ours {:?}",
        kinds(&mesa),
        kinds(&ours)
    );
}

/// Runs the preprocessor on `#include <GL/gl.h>` (with `defines` first) against our
/// headers or, when `ours` is false, Mesa's; returns its output.
fn preprocess(ours: bool, defines: &str, flags: &[&str]) -> String {
    let dir = scratch("preprocess");
    let src = dir.join(format!("pp_{ours}.c"));
    std::fs::write(&src, format!("{defines}#include <GL/gl.h>\n")).expect("write pp.c");
    let mut cmd = Command::new("cc");
    if ours {
        cmd.arg(format!("-I{}", root().join("include").display()));
    }
    let out = cmd
        .args(["-std=c99", "-E"])
        .args(flags)
        .arg(&src)
        .output()
        .expect("run cc -E");
    assert!(
        out.status.success(),
        "cc -E failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The `GL…`/`gl…`/`PFN…` identifiers of preprocessed code.
fn gl_identifiers(code: &str) -> BTreeSet<String> {
    code.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .filter(|w| w.starts_with("gl") || w.starts_with("GL") || w.starts_with("PFN"))
        .map(str::to_string)
        .collect()
}

/// What a program sees after `#include <GL/gl.h>` is what it sees with Mesa's headers: the
/// same macros with the same values, and the same declared identifiers, with and without
/// GL_GLEXT_PROTOTYPES and GL_GLEXT_LEGACY.
#[test]
fn preprocessed_headers_match_mesas() {
    if !have("cc") || mesa_headers().is_none() {
        return;
    }
    let mut errors = Vec::new();
    for defines in [
        "",
        "#define GL_GLEXT_PROTOTYPES\n",
        "#define GL_GLEXT_LEGACY\n#define GL_GLEXT_PROTOTYPES\n",
    ] {
        let macros = |ours| -> BTreeMap<String, String> {
            preprocess(ours, defines, &["-dM"])
                .lines()
                .filter_map(|l| {
                    let rest = l.strip_prefix("#define ")?;
                    let (name, value) = rest.split_once(' ').unwrap_or((rest, ""));
                    name.starts_with("GL_")
                        .then(|| (name.to_string(), value.trim().to_string()))
                })
                .collect()
        };
        let (mesa, ours) = (macros(false), macros(true));
        for (name, value) in &mesa {
            match ours.get(name) {
                None => errors.push(format!("[{defines:?}] macro {name} missing")),
                Some(v) if int_value(v) != int_value(value) => {
                    errors.push(format!("[{defines:?}] {name} is {v}, Mesa: {value}"))
                }
                Some(_) => {}
            }
        }
        for name in ours.keys().filter(|n| !mesa.contains_key(*n)) {
            errors.push(format!("[{defines:?}] macro {name} is not Mesa's"));
        }
        let (mesa, ours) = (
            gl_identifiers(&preprocess(false, defines, &["-P"])),
            gl_identifiers(&preprocess(true, defines, &["-P"])),
        );
        for name in mesa.symmetric_difference(&ours) {
            if defines.contains("GL_GLEXT_LEGACY") && LEGACY_DIFFERENCES.contains(&name.as_str()) {
                continue;
            }
            let side = if ours.contains(name) {
                "only ours"
            } else {
                "only Mesa's"
            };
            errors.push(format!("[{defines:?}] {name} declared by {side}"));
        }
    }
    assert!(errors.is_empty(), "{}", errors.join("\n"));
}

/// The value of an integer macro (`0x8513`, `1`, `0xFFFFFFFFu`), or its text.
fn int_value(v: &str) -> Result<u64, String> {
    let t = v.trim_end_matches(['u', 'l', 'U', 'L']);
    match t.strip_prefix("0x").or_else(|| t.strip_prefix("0X")) {
        Some(hex) => u64::from_str_radix(hex, 16),
        None => t.parse(),
    }
    .map_err(|_| v.to_string())
}

/// The output of running `exe` (with `LD_LIBRARY_PATH=lib`), which must succeed.
fn run_program(exe: &Path, lib: Option<&Path>) -> String {
    let mut cmd = Command::new(exe);
    if let Some(lib) = lib {
        cmd.env("LD_LIBRARY_PATH", lib);
    }
    let out = cmd
        .output()
        .unwrap_or_else(|e| panic!("run {}: {e}", exe.display()));
    let stdout = String::from_utf8_lossy(&out.stdout).into_owned();
    assert!(
        out.status.success(),
        "{} failed ({}):\n{stdout}{}",
        exe.display(),
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
    stdout
}

/// A program that declares GL 1.3–4.5 and extension functions with glext.h's
/// `PFNGL…PROC` types and loads them with OSMesaGetProcAddress (as glad, VTK and tutorials
/// do) builds against our headers alone, draws through them (an FBO, glClipControl,
/// glBlitFramebuffer, glActiveTexture) and prints what Mesa's OSMesa prints.
#[test]
fn extension_functions_load_through_get_proc_address() {
    if !have("cc") {
        eprintln!("note: no `cc`; check skipped");
        return;
    }
    let src = root().join("tests/headers/ext_procs.c");
    let dir = scratch("ext-procs");
    let lib = lib_dir();
    let exe = dir.join("ext_procs");
    // -H lists every header used: none may come from /usr/include/GL.
    let out = Command::new("cc")
        .arg(format!("-I{}", root().join("include").display()))
        .args(["-H", "-std=c99", "-Wall", "-Werror", "-pedantic"])
        .arg(&src)
        .arg(format!("-L{}", lib.display()))
        .args(["-lsoftgl", "-o"])
        .arg(&exe)
        .output()
        .expect("run cc");
    let log = String::from_utf8_lossy(&out.stderr);
    assert!(out.status.success(), "compiling ext_procs.c failed:\n{log}");
    let system: Vec<&str> = log
        .lines()
        .filter(|l| l.contains("/usr/include/GL/"))
        .collect();
    assert!(system.is_empty(), "Mesa's headers were used: {system:?}");
    let ours = run_program(&exe, Some(&lib));
    for line in [
        "framebuffer status 0x8CD5",
        "window top (16,24): 255 0 0 255",
        "window bottom (16,8): 0 0 255 255",
        "error 0x0000",
    ] {
        assert!(ours.contains(line), "expected `{line}` in:\n{ours}");
    }
    if !Path::new("/usr/include/GL/osmesa.h").exists() {
        eprintln!("note: Mesa's OSMesa absent; output not compared");
        return;
    }
    let mesa_exe = dir.join("ext_procs_mesa");
    run(Command::new("cc")
        .args(["-std=c99", "-Wall"])
        .arg(&src)
        .args(["-lOSMesa", "-o"])
        .arg(&mesa_exe));
    let mesa = run_program(&mesa_exe, None);
    assert_eq!(ours, mesa, "softgl (left) and Mesa's OSMesa (right) differ");
}

#[test]
fn tokens_have_mesa_values() {
    let ours: BTreeMap<String, u64> = [generator::Header::Gl, generator::Header::Glext]
        .into_iter()
        .flat_map(|h| int_defines(&read_header(h)))
        .collect();
    let Ok(mesa_gl) = std::fs::read_to_string("/usr/include/GL/gl.h") else {
        eprintln!("note: /usr/include/GL/gl.h absent; token values not compared with Mesa");
        return;
    };
    let mesa_gl = int_defines(&mesa_gl);
    let mut mesa = mesa_gl.clone();
    match std::fs::read_to_string("/usr/include/GL/glext.h") {
        Ok(t) => mesa.extend(int_defines(&t)),
        Err(_) => eprintln!("note: /usr/include/GL/glext.h absent; glext tokens not compared"),
    }
    let mut errors = Vec::new();
    let mut unknown = Vec::new();
    for (name, v) in &ours {
        match mesa.get(name) {
            Some(m) if m == v => {}
            Some(m) => errors.push(format!("{name} is {v:#X}, Mesa says {m:#X}")),
            None => unknown.push(name.as_str()),
        }
    }
    // Every token of Mesa's gl.h must be there: GLU, GLUT and programs rely on them.
    for (name, v) in &mesa_gl {
        if name.starts_with("GL_") && !ours.contains_key(name) {
            errors.push(format!("{name} ({v:#X}) of Mesa's gl.h is missing"));
        }
    }
    if !unknown.is_empty() {
        eprintln!("note: not in Mesa's headers: {unknown:?}");
    }
    assert!(errors.is_empty(), "{}", errors.join("\n"));
}

#[test]
fn declarations_are_compatible_with_mesas() {
    // Redeclaring each of our prototypes and PFN typedefs after Mesa's headers is an error
    // ("conflicting types") unless the C types agree exactly, const-ness included.
    let mesa = ["/usr/include/GL/gl.h", "/usr/include/GL/osmesa.h"];
    if !have("cc") || !mesa.iter().all(|h| Path::new(h).exists()) {
        eprintln!("note: no `cc` or no Mesa headers; compatibility check skipped");
        return;
    }
    let mut code = String::from("#define GL_GLEXT_PROTOTYPES\n");
    for h in mesa {
        code.push_str(&format!("#include \"{h}\"\n"));
    }
    let mut n = 0;
    for h in generator::Header::ALL {
        for line in read_header(h).lines() {
            if line.starts_with("GLAPI ") || line.starts_with("typedef ") && line.contains("PFN") {
                code.push_str(line);
                code.push('\n');
                n += 1;
            }
        }
    }
    let dir = scratch("mesa-compat");
    let src = dir.join("compat.c");
    std::fs::write(&src, &code).expect("write compat.c");
    run(Command::new("cc")
        .args(["-std=c11", "-fsyntax-only"])
        .arg(&src));
    assert!(n > 100, "only {n} declarations found");
}
