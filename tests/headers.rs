//! Checks the committed C headers `include/GL/{gl,glext,osmesa}.h`: they are what
//! `cargo run --example gen_headers` produces (glext.h via `tools/gen_glext.py` from the
//! Khronos registry), they compile as C89, C99 and C++, they declare every exported
//! function with the C signature of its Rust definition, they declare every name Mesa's
//! headers declare, with Mesa's token values, and `libsoftgl.so` exports every function
//! gl.h and osmesa.h declare. The comparisons with Mesa's headers are in `headers/mesa.rs`.

#[path = "../examples/gen_headers/generator.rs"]
mod generator;
#[path = "headers/mesa.rs"]
mod mesa;

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::Command;

/// The crate root.
fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// The text of a committed header.
fn read_header(h: generator::Header) -> String {
    let path = root().join(h.path());
    std::fs::read_to_string(&path).unwrap_or_else(|e| {
        panic!(
            "{}: {e}\nheaders are missing: run `{}`",
            path.display(),
            generator::REGENERATE
        )
    })
}

/// Names of the functions a header declares (`GLAPI … NAME(…);` lines).
fn declared_functions(text: &str) -> Vec<String> {
    text.lines()
        .filter(|l| l.starts_with("GLAPI ") && l.ends_with(");"))
        .map(|l| {
            let head = l[..l.find('(').expect("prototype has '('")].trim_end();
            head.rsplit([' ', '*']).next().unwrap_or("").to_string()
        })
        .collect()
}

/// `#define NAME VALUE` pairs whose value is a plain integer literal.
fn int_defines(text: &str) -> BTreeMap<String, u64> {
    let mut out = BTreeMap::new();
    for line in text.lines() {
        let mut words = line.split_whitespace();
        if words.next() != Some("#define") {
            continue;
        }
        let (Some(name), Some(value)) = (words.next(), words.next()) else {
            continue;
        };
        let parsed = match value
            .strip_prefix("0x")
            .or_else(|| value.strip_prefix("0X"))
        {
            Some(hex) => u64::from_str_radix(hex, 16).ok(),
            None => value.parse().ok(),
        };
        if let Some(v) = parsed {
            out.insert(name.to_string(), v);
        }
    }
    out
}

/// Every `#[no_mangle]` function of `src/ffi`, with the file that defines it.
fn no_mangle_functions() -> Vec<(String, String)> {
    let dir = root().join("src/ffi");
    let mut out = Vec::new();
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .expect("src/ffi")
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "rs"))
        .collect();
    files.sort();
    for path in files {
        let text = std::fs::read_to_string(&path).expect("read src/ffi file");
        let text = generator::ffi_expand::expand(&text);
        let file = path.file_name().unwrap().to_string_lossy().into_owned();
        let mut pending = false;
        for line in text.lines().map(str::trim) {
            if line == "#[no_mangle]" || line == "#[unsafe(no_mangle)]" {
                pending = true;
            } else if pending && !line.starts_with("#[") && !line.starts_with("//") {
                pending = false;
                let name = line
                    .split_once("fn ")
                    .map(|(_, rest)| {
                        rest.chars()
                            .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                            .collect::<String>()
                    })
                    .unwrap_or_else(|| panic!("{file}: #[no_mangle] on a non-function: {line}"));
                // Empty for the `$name` of a macro definition (src/ffi/families.rs).
                if !name.is_empty() {
                    out.push((name, file.clone()));
                }
            }
        }
    }
    out
}

/// True when `program` can be run.
fn have(program: &str) -> bool {
    Command::new(program)
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success())
}

/// Runs a command and panics with its output when it fails.
fn run(cmd: &mut Command) {
    let out = cmd
        .output()
        .unwrap_or_else(|e| panic!("cannot run {cmd:?}: {e}"));
    assert!(
        out.status.success(),
        "{cmd:?} failed:\n{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}

/// The directory holding the `libsoftgl.so` of this build. Integration tests run from
/// `target/<profile>/deps/`, where cargo writes the cdylib while building the library for
/// the test (it copies it up to `target/<profile>/` only for `cargo build`, so that copy
/// may be stale or absent).
fn lib_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("current_exe");
    let deps = exe.parent().expect("test binary has a directory");
    let profile = deps.parent().unwrap_or(deps);
    if deps.join("libsoftgl.so").exists() || !profile.join("libsoftgl.so").exists() {
        deps.to_path_buf()
    } else {
        profile.to_path_buf()
    }
}

/// A scratch directory for compiler output.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("headers-{name}"));
    std::fs::create_dir_all(&dir).expect("create scratch dir");
    dir
}

#[test]
fn headers_are_up_to_date() {
    let generated = generator::generate(&root()).unwrap_or_else(|e| panic!("{e}"));
    let mut stale = Vec::new();
    // glext.h comes from gl.xml (Debian's khronos-api, installed by scripts/ensure-deps.sh).
    let check = Command::new("python3")
        .arg(root().join(generator::GLEXT_TOOL))
        .arg("--check")
        .output()
        .unwrap_or_else(|e| panic!("python3 {}: {e}", generator::GLEXT_TOOL));
    if !check.status.success() {
        stale.push(
            String::from_utf8_lossy(&check.stderr)
                .trim_end()
                .to_string(),
        );
    }
    for (path, text) in &generated {
        let committed = std::fs::read_to_string(root().join(path)).unwrap_or_default();
        if committed != *text {
            let line = committed
                .lines()
                .zip(text.lines())
                .position(|(a, b)| a != b)
                .unwrap_or_else(|| committed.lines().count().min(text.lines().count()));
            stale.push(format!("{path} (first difference at line {})", line + 1));
        }
    }
    assert!(
        stale.is_empty(),
        "headers are stale: run `{}`\n  {}",
        generator::REGENERATE,
        stale.join("\n  ")
    );
}

/// A program written for Mesa's headers: types, tokens, prototypes, PFN types and macros
/// of all three headers. C89-clean.
const SAMPLE_C: &str = r#"
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <stdlib.h>

#if !defined(GL_VERSION_1_1) || !defined(GL_VERSION_1_2) || !defined(GL_VERSION_1_3)
#error "GL_VERSION_1_1..1_3 must be defined by gl.h"
#endif
#if !defined(GL_VERSION_1_4) || !defined(GL_VERSION_1_5) || !defined(GL_ARB_vertex_buffer_object)
#error "GL_VERSION_1_4, GL_VERSION_1_5 and GL_ARB_vertex_buffer_object must be defined by glext.h"
#endif
#if !defined(GLAPI) || !defined(GLAPIENTRY) || !defined(APIENTRY) || !defined(APIENTRYP) || !defined(GLAPIENTRYP)
#error "calling-convention macros missing"
#endif
#if GL_ALL_ATTRIB_BITS != 0xFFFFFFFF || GL_CLIENT_ALL_ATTRIB_BITS != 0xFFFFFFFF
#error "GL_ALL_ATTRIB_BITS"
#endif
#if OSMESA_MAJOR_VERSION != 11 || OSMESA_RGBA != GL_RGBA
#error "OSMesa constants"
#endif

/* Sizes and signedness of the Khronos types (negative array size on failure). */
typedef char check_sizeiptr[sizeof(GLsizeiptr) == sizeof(void *) ? 1 : -1];
typedef char check_intptr[sizeof(GLintptr) == sizeof(void *) ? 1 : -1];
typedef char check_sizeiptr_signed[(GLsizeiptr)-1 < 0 ? 1 : -1];
typedef char check_byte[(GLbyte)-1 < 0 && sizeof(GLbyte) == 1 ? 1 : -1];
typedef char check_boolean[(GLboolean)-1 > 0 && sizeof(GLboolean) == 1 ? 1 : -1];
typedef char check_enum[sizeof(GLenum) == 4 && (GLenum)-1 > 0 ? 1 : -1];
typedef char check_double[sizeof(GLclampd) == 8 ? 1 : -1];

typedef void (GLAPIENTRYP my_enable_proc)(GLenum cap);
typedef void (APIENTRY *my_clear_proc)(GLbitfield mask);

static GLuint make_buffer(void)
{
    static const GLfloat data[6] = { 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 1.0f };
    GLuint b = 0;
    PFNGLBINDBUFFERPROC bind = glBindBuffer;
    PFNGLBUFFERDATAPROC upload = glBufferData;
    PFNGLMAPBUFFERPROC map = glMapBuffer;
    GLvoid *p;
    GLintptr offset = 0;
    glGenBuffers(1, &b);
    bind(GL_ARRAY_BUFFER, b);
    upload(GL_ARRAY_BUFFER, (GLsizeiptr)sizeof data, data, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, offset, (GLsizeiptr)sizeof(GLfloat), data);
    p = map(GL_ARRAY_BUFFER, GL_READ_ONLY);
    if (p != NULL)
        glUnmapBuffer(GL_ARRAY_BUFFER);
    return b;
}

int main(void)
{
    const GLint w = 8, h = 8;
    GLubyte *buf = (GLubyte *)malloc((size_t)(w * h * 4));
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    OSMESAproc proc = OSMesaGetProcAddress("glBegin");
    PFNGLDRAWRANGEELEMENTSPROC draw_range = glDrawRangeElements;
    my_enable_proc enable = glEnable;
    my_clear_proc clear = glClear;
    static const GLushort indices[3] = { 0, 1, 2 };
    const GLubyte *version;
    GLint width = 0, err;
    GLuint vbo;
    GLint first[1] = { 0 };
    GLsizei count[1] = { 3 };
    if (ctx == NULL || buf == NULL || proc == NULL)
        return 2;
    if (!OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, w, h))
        return 3;
    OSMesaPixelStore(OSMESA_Y_UP, 1);
    version = glGetString(GL_VERSION);
    if (version == NULL)
        return 4;
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, 1.0, 0.0, 1.0, -1.0, 1.0);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    enable(GL_DEPTH_TEST);
    clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    glColor3ub(255, 0, 0);
    glVertex2f(0.0f, 0.0f);
    glVertex2f(1.0f, 0.0f);
    glVertex2f(0.0f, 1.0f);
    glEnd();
    vbo = make_buffer();
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, (const GLvoid *)0);
    glMultiDrawArrays(GL_TRIANGLES, first, count, 1);
    draw_range(GL_TRIANGLES, 0, 2, 3, GL_UNSIGNED_SHORT, (const GLvoid *)0);
    glDisableClientState(GL_VERTEX_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDeleteBuffers(1, &vbo);
    glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_SHORT, indices);
    glFinish();
    OSMesaGetIntegerv(OSMESA_WIDTH, &width);
    err = (GLint)glGetError();
    OSMesaDestroyContext(ctx);
    free(buf);
    if (width != w)
        return 5;
    return err == GL_NO_ERROR ? 0 : 6;
}
"#;

#[test]
fn headers_compile_as_c89_c99_and_cpp_and_link() {
    if !have("cc") {
        eprintln!("note: no `cc`; C compile checks skipped");
        return;
    }
    let dir = scratch("compile");
    let src = dir.join("sample.c");
    std::fs::write(&src, SAMPLE_C).expect("write sample.c");
    let include = root().join("include");
    for std in ["c89", "c99", "c11"] {
        run(Command::new("cc")
            .arg(format!("-I{}", include.display()))
            .args(["-Wall", "-Wextra", "-Werror", "-pedantic"])
            .arg(format!("-std={std}"))
            .arg("-c")
            .arg(&src)
            .arg("-o")
            .arg(dir.join(format!("sample-{std}.o"))));
    }
    if have("c++") {
        run(Command::new("c++")
            .arg(format!("-I{}", include.display()))
            .args([
                "-Wall",
                "-Werror",
                "-pedantic",
                "-x",
                "c++",
                "-fsyntax-only",
            ])
            .arg(&src));
    } else {
        eprintln!("note: no `c++`; C++ check skipped");
    }
    // Link the C99 object against libsoftgl.so and run it: every call resolves and works.
    let lib_dir = lib_dir();
    assert!(
        lib_dir.join("libsoftgl.so").exists(),
        "no libsoftgl.so in {}",
        lib_dir.display()
    );
    let exe = dir.join("sample");
    run(Command::new("cc")
        .arg(dir.join("sample-c99.o"))
        .arg(format!("-L{}", lib_dir.display()))
        .arg("-lsoftgl")
        .arg("-o")
        .arg(&exe));
    let status = Command::new(&exe)
        .env("LD_LIBRARY_PATH", &lib_dir)
        .status()
        .expect("run sample");
    assert!(status.success(), "sample program failed: {status}");
}

#[test]
fn system_glu_and_glut_headers_compile_against_our_gl_h() {
    if !have("cc") {
        eprintln!("note: no `cc`; GLU/GLUT check skipped");
        return;
    }
    let include = root().join("include");
    let mut cases = Vec::new();
    for (hdr, code) in [
        ("/usr/include/GL/glu.h", "#include <GL/glu.h>\nint main(void) { gluPerspective(45.0, 1.0, 0.1, 10.0); return (int)gluErrorString(GLU_INVALID_ENUM)[0]; }\n"),
        ("/usr/include/GL/glut.h", "#include <GL/glu.h>\n#include <GL/glut.h>\nint main(void) { glutSolidTeapot(1.0); return 0; }\n"),
        // gl.h without its glext.h, then Mesa's own glext.h (nice to have).
        ("/usr/include/GL/glext.h", "#define GL_GLEXT_LEGACY\n#define GL_GLEXT_PROTOTYPES\n#include <GL/gl.h>\n#include \"/usr/include/GL/glext.h\"\nint main(void) { PFNGLBINDBUFFERPROC p = glBindBuffer; p(GL_ARRAY_BUFFER, 0); return 0; }\n"),
        // gl.h (with our glext.h), then Mesa's glext.h: skipped by the shared guard.
        ("/usr/include/GL/glext.h", "#include <GL/gl.h>\n#include \"/usr/include/GL/glext.h\"\nint main(void) { return GL_ARRAY_BUFFER == 0x8892 ? 0 : 1; }\n"),
    ] {
        if Path::new(hdr).exists() {
            cases.push(code);
        } else {
            eprintln!("note: {hdr} absent; its check skipped");
        }
    }
    let dir = scratch("system");
    for (i, code) in cases.iter().enumerate() {
        let src = dir.join(format!("case{i}.c"));
        std::fs::write(&src, code).expect("write case");
        // -H lists the headers used: ours must be the gl.h that glu.h includes.
        let out = Command::new("cc")
            .arg(format!("-I{}", include.display()))
            .args([
                "-H",
                "-Wall",
                "-Werror",
                "-pedantic",
                "-std=c99",
                "-fsyntax-only",
            ])
            .arg(&src)
            .output()
            .expect("run cc");
        let log = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "case {i} failed:\n{code}\n{log}");
        let ours = include.join("GL/gl.h");
        assert!(
            log.lines()
                .any(|l| l.trim_start_matches(['.', ' ']) == ours.to_string_lossy()),
            "case {i} did not use our gl.h:\n{log}"
        );
    }
}

/// The functions `libsoftgl.so` defines (`nm -D`), or `None` without `nm`.
fn library_exports() -> Option<BTreeSet<String>> {
    if !have("nm") {
        eprintln!("note: no `nm`; export check skipped");
        return None;
    }
    let lib = lib_dir().join("libsoftgl.so");
    assert!(
        lib.exists(),
        "{} not found (cargo builds the cdylib for integration tests)",
        lib.display()
    );
    let out = Command::new("nm")
        .args(["-D", "--defined-only"])
        .arg(&lib)
        .output()
        .expect("run nm");
    assert!(out.status.success(), "nm failed on {}", lib.display());
    Some(
        String::from_utf8_lossy(&out.stdout)
            .lines()
            .filter_map(|l| {
                let mut w = l.split_whitespace().rev();
                let name = w.next()?;
                let kind = w.next()?;
                (kind == "T" || kind == "W").then(|| name.to_string())
            })
            .collect(),
    )
}

/// The headers whose functions softgl defines (glext.h declares every function of the
/// registry, as Mesa's does, most of which softgl does not implement).
const EXPORTING_HEADERS: [generator::Header; 2] =
    [generator::Header::Gl, generator::Header::Osmesa];

/// Every exported function is declared by a header; gl.h and osmesa.h declare each of
/// their functions once, and only functions `src/ffi` defines (but for the few of Mesa's
/// gl.h that softgl does not implement).
#[test]
fn every_ffi_function_is_declared() {
    let mut declared: BTreeMap<String, Vec<&str>> = BTreeMap::new();
    for h in generator::Header::ALL {
        for name in declared_functions(&read_header(h)) {
            declared.entry(name).or_default().push(h.path());
        }
    }
    let mut errors = Vec::new();
    let exported = no_mangle_functions();
    let names: BTreeSet<&str> = exported.iter().map(|(n, _)| n.as_str()).collect();
    for (name, file) in &exported {
        if !declared.contains_key(name) {
            errors.push(format!("{name} (src/ffi/{file}) is declared in no header"));
        }
    }
    for h in EXPORTING_HEADERS {
        let mut seen = BTreeSet::new();
        for name in declared_functions(&read_header(h)) {
            if !seen.insert(name.clone()) {
                errors.push(format!("{name} is declared twice in {}", h.path()));
            }
            if !names.contains(name.as_str()) && !generator::GL_H_UNEXPORTED.contains(&&*name) {
                errors.push(format!(
                    "{name} is declared in {} but no #[no_mangle] fn defines it",
                    h.path()
                ));
            }
        }
    }
    assert!(
        errors.is_empty(),
        "{}\n(if src/ffi changed, run `{}`)",
        errors.join("\n"),
        generator::REGENERATE
    );
}

/// What cbindgen makes of `src/ffi` agrees with the headers: every exported function
/// redeclared after them with the C signature of its Rust definition (a mismatch is a
/// "conflicting types" error), every integer constant of `src/ffi` defined with the same
/// value, and the typedefs of `types.rs` naming the same types.
#[test]
fn rust_items_match_their_declarations() {
    if !have("cc") {
        eprintln!("note: no `cc`; Rust/C declaration check skipped");
        return;
    }
    let decls = generator::rust_declarations(&root()).unwrap_or_else(|e| panic!("{e}"));
    let mut code =
        String::from("#define GL_GLEXT_PROTOTYPES\n#include <GL/gl.h>\n#include <GL/osmesa.h>\n");
    // The GL types (osmesa.h keeps Mesa's unprototyped OSMESAproc, see MESA_SPELLINGS).
    for (_, line) in decls.typedefs.iter().filter(|(f, _)| *f == "types.rs") {
        code.push_str(line);
        code.push('\n');
    }
    for (file, _, proto) in &decls.functions {
        code.push_str(&format!("/* src/ffi/{file} */ {proto}\n"));
    }
    for (file, name, value) in &decls.constants {
        code.push_str(&format!(
            "#if !defined({name}) || {name} != {value}\n\
             #error \"{name} is {value} in src/ffi/{file}: not so in the headers\"\n#endif\n"
        ));
    }
    let dir = scratch("rust-decls");
    let src = dir.join("rust_decls.c");
    std::fs::write(&src, &code).expect("write rust_decls.c");
    run(Command::new("cc")
        .arg(format!("-I{}", root().join("include").display()))
        .args(["-std=c11", "-fsyntax-only", "-Werror"])
        .arg(&src));
    assert!(
        decls.functions.len() > 300 && decls.constants.len() > 500,
        "only {} functions and {} constants rendered",
        decls.functions.len(),
        decls.constants.len()
    );
}

/// `libsoftgl.so` exports every function of `src/ffi` and every function gl.h and osmesa.h
/// declare (but [`generator::GL_H_UNEXPORTED`]).
#[test]
fn library_exports_every_declared_function() {
    let Some(exported) = library_exports() else {
        return;
    };
    let mut missing = Vec::new();
    for h in EXPORTING_HEADERS {
        for name in declared_functions(&read_header(h)) {
            if !exported.contains(&name) && !generator::GL_H_UNEXPORTED.contains(&&*name) {
                missing.push(format!("{name} ({})", h.path()));
            }
        }
    }
    for (name, file) in no_mangle_functions() {
        if !exported.contains(&name) {
            missing.push(format!("{name} (src/ffi/{file})"));
        }
    }
    assert!(
        missing.is_empty(),
        "libsoftgl.so does not export:\n{}",
        missing.join("\n")
    );
}
