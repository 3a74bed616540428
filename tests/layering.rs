//! The import rules of the crate's layers (issue 41), checked on the source text.
//!
//! The layers, top to bottom, and what each may name:
//! - `ffi` (the C boundary): anything below it.
//! - `context` (the GL state machine): everything but `ffi`.
//! - `plan` (state values → pipeline values, once per draw): the pipeline and the leaves,
//!   never `context` or `ffi`.
//! - the pipeline (`engine`, `geometry`, `fixed_function`, `raster`, `fragment`, `texture`, `pixels`,
//!   `framebuffer`, and `render`, which runs a plan through them): other pipeline modules
//!   and the leaves, never `context`, `plan`, `ffi`
//!   or `gl` (the pipeline never sees a GL token).
//! - the leaves (`pipe`, `gl`, `simd`, `cpu`, `stats`, `tuning`, `memory`): one another
//!   at most, never a layer above.
//!
//! A file's module is its first path component under `src/`; every `crate::NAME`, every
//! `use crate::{NAME, …}` group and every `super::` chain that climbs to the crate root is
//! an edge. Doc comments and ordinary comments are skipped.

#[path = "../tools/ffi_expand.rs"]
mod ffi_expand;

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The modules of each layer.
const FFI: &[&str] = &["ffi"];
const STATE: &[&str] = &["context"];
const PLAN: &[&str] = &["plan"];
const PIPELINE: &[&str] = &[
    "engine",
    "geometry",
    "fixed_function",
    "raster",
    "fragment",
    "texture",
    "pixels",
    "framebuffer",
    "render",
    "shader",
];
const LEAVES: &[&str] = &["pipe", "gl", "simd", "cpu", "stats", "tuning", "memory"];

/// Modules that are neither code of the library nor a layer (test helpers).
const IGNORED: &[&str] = &["lib", "test_rng"];

/// What module `from` may not name.
fn forbidden(from: &str) -> Vec<&'static str> {
    let above_pipeline = [FFI, STATE, PLAN].concat();
    if FFI.contains(&from) {
        Vec::new()
    } else if STATE.contains(&from) {
        FFI.to_vec()
    } else if PLAN.contains(&from) {
        [FFI, STATE].concat()
    } else if PIPELINE.contains(&from) {
        [above_pipeline.as_slice(), &["gl"]].concat()
    } else if LEAVES.contains(&from) {
        [above_pipeline.as_slice(), PIPELINE].concat()
    } else {
        Vec::new()
    }
}

/// Every `.rs` file below `dir`.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for e in std::fs::read_dir(dir).expect("read src").flatten() {
        let p = e.path();
        if p.is_dir() {
            rust_files(&p, out);
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
}

/// The module path of a file below `src/` (`src/a/b.rs` → `["a", "b"]`, `mod.rs` → its folder).
fn module_path(rel: &Path) -> Vec<String> {
    let mut parts: Vec<String> = rel
        .iter()
        .map(|c| c.to_string_lossy().trim_end_matches(".rs").to_string())
        .collect();
    if parts.last().is_some_and(|l| l == "mod") {
        parts.pop();
    }
    parts
}

/// The crate-root modules one source text names.
fn named_modules(text: &str, module: &[String]) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    for line in text.lines() {
        let code = line.split("//").next().unwrap_or("");
        let mut rest = code;
        while let Some(i) = rest.find("crate::") {
            let after = &rest[i + "crate::".len()..];
            if let Some(group) = after.strip_prefix('{') {
                // `crate::{a::X, b}`: the first component of each item of the group
                // (a group spread over several lines is caught line by line below).
                for item in group.split(',') {
                    let name: String = item
                        .trim()
                        .chars()
                        .take_while(|c| c.is_alphanumeric() || *c == '_')
                        .collect();
                    if !name.is_empty() {
                        out.insert(name);
                    }
                }
            } else {
                let name: String = after
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                if !name.is_empty() {
                    out.insert(name);
                }
            }
            rest = &after[1.min(after.len())..];
        }
        // `super::super::x`: climbs from the file's module; reaching the root names `x`.
        let mut rest = code;
        while let Some(i) = rest.find("super::") {
            let mut s = &rest[i..];
            let mut up = 0;
            while let Some(t) = s.strip_prefix("super::") {
                up += 1;
                s = t;
            }
            // A file `a/b.rs` is module a::b: one `super` is `a`, two are the root.
            if up >= module.len() {
                let name: String = s
                    .chars()
                    .take_while(|c| c.is_alphanumeric() || *c == '_')
                    .collect();
                if !name.is_empty() {
                    out.insert(name);
                }
            }
            rest = &rest[i + "super::".len() * up..];
        }
    }
    out
}

/// Lines inside a multi-line `use crate::{` group name their first path component too.
fn grouped_use_modules(text: &str) -> BTreeSet<String> {
    let mut out = BTreeSet::new();
    let mut depth = 0usize;
    for line in text.lines() {
        let code = line.split("//").next().unwrap_or("").trim();
        if depth == 0 {
            if code.starts_with("use crate::{") || code.starts_with("pub use crate::{") {
                depth = code.matches('{').count()
                    - code.matches('}').count().min(code.matches('{').count());
            }
            continue;
        }
        if depth == 1 {
            let name: String = code
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if !name.is_empty() {
                out.insert(name);
            }
        }
        depth += code.matches('{').count();
        depth = depth.saturating_sub(code.matches('}').count());
    }
    out
}

/// The import graph of `src/`: module → (named module → first file naming it).
fn graph() -> BTreeMap<String, BTreeMap<String, String>> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    files.sort();
    let tops: BTreeSet<String> = files
        .iter()
        .map(|f| module_path(f.strip_prefix(&src).unwrap())[0].clone())
        .collect();
    let mut g: BTreeMap<String, BTreeMap<String, String>> = BTreeMap::new();
    for f in &files {
        let rel = f.strip_prefix(&src).unwrap();
        let module = module_path(rel);
        let from = module[0].clone();
        if IGNORED.contains(&from.as_str()) {
            continue;
        }
        let text = std::fs::read_to_string(f).unwrap();
        let mut names = named_modules(&text, &module);
        names.extend(grouped_use_modules(&text));
        for to in names {
            if to != from && tops.contains(&to) && !IGNORED.contains(&to.as_str()) {
                g.entry(from.clone())
                    .or_default()
                    .entry(to)
                    .or_insert_with(|| rel.display().to_string());
            }
        }
    }
    g
}

#[test]
fn every_import_points_down() {
    let g = graph();
    let mut errors = Vec::new();
    for (from, tos) in &g {
        for (to, file) in tos {
            if forbidden(from).contains(&to.as_str()) {
                errors.push(format!("src/{file}: `{from}` may not import `{to}`"));
            }
        }
    }
    let listing: Vec<String> = g
        .iter()
        .map(|(f, t)| format!("{f} -> {}", t.keys().cloned().collect::<Vec<_>>().join(" ")))
        .collect();
    assert!(
        errors.is_empty(),
        "{} forbidden imports:\n{}\n\nthe graph:\n{}",
        errors.len(),
        errors.join("\n"),
        listing.join("\n")
    );
}

#[test]
fn every_module_has_a_layer() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut unknown = BTreeSet::new();
    for f in &files {
        let top = module_path(f.strip_prefix(&src).unwrap())[0].clone();
        let known = [FFI, STATE, PLAN, PIPELINE, LEAVES, IGNORED]
            .iter()
            .any(|l| l.contains(&top.as_str()));
        if !known {
            unknown.insert(top);
        }
    }
    assert!(
        unknown.is_empty(),
        "modules without a layer in tests/layering.rs: {unknown:?}"
    );
}

/// The checker itself sees the edges it must: a `super` chain to the root, a grouped use
/// spread over lines, and a plain path; comments do not count.
#[test]
fn the_parser_finds_edges() {
    let m = vec!["raster".to_string(), "lines".to_string()];
    let text = "use super::super::context::state::State;\n\
                // crate::ffi in a comment\n\
                let x = crate::gl::enums::GL_FLOAT;\n\
                use super::prims;\n";
    let names = named_modules(text, &m);
    assert!(names.contains("context"), "{names:?}");
    assert!(names.contains("gl"), "{names:?}");
    assert!(!names.contains("ffi"), "{names:?}");
    assert!(!names.contains("prims"), "{names:?}");
    let grouped = grouped_use_modules("use crate::{\n    context::Context,\n    pipe::Face,\n};\n");
    assert_eq!(
        grouped,
        ["context", "pipe"].iter().map(|s| s.to_string()).collect()
    );
}

/// Intrinsics and inline assembly live only in `src/simd/`: every other module reaches the
/// CPU's vector instructions through its wide types.
#[test]
fn intrinsics_only_in_simd() {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("src");
    let mut files = Vec::new();
    rust_files(&src, &mut files);
    let mut found = Vec::new();
    for f in &files {
        let rel = f.strip_prefix(&src).unwrap();
        if rel.starts_with("simd") {
            continue;
        }
        let text = std::fs::read_to_string(f).unwrap();
        for (n, line) in text.lines().enumerate() {
            let code = line.split("//").next().unwrap_or("");
            if code.contains("std::arch") || code.contains("core::arch") || code.contains("_mm") {
                found.push(format!("src/{}:{}: {}", rel.display(), n + 1, line.trim()));
            }
        }
    }
    assert!(
        found.is_empty(),
        "intrinsics outside src/simd:\n{}",
        found.join("\n")
    );
}

/// The most non-blank, non-comment lines an `extern "C"` body may have: enough to read
/// pointer arguments, convert, make the call and write results back.
const MAX_BODY_LINES: usize = 12;

/// The functions through which a C entry point reaches the context (`src/ffi/mod.rs` and
/// the record-or-execute helpers). Every other `extern "C"` function's name counts too (a
/// body that forwards to another entry point).
const CONTEXT_ENTRIES: &[&str] = &[
    "with_ctx",
    "with_ctx_raw",
    "with_ctx_anywhere",
    "with_ctx_list",
    "with_ctx_list_anywhere",
    "with_ctx_vertex",
    "listable_draw",
    "image_command",
];

/// Bodies allowed to break the rules of [`ffi_bodies_only_convert`], with the reason.
const BODY_EXCEPTIONS: &[(&str, &str)] = &[];

/// `line` without its `//` comment and the text of its string literals (`""` stays).
fn code_of(line: &str) -> String {
    let mut out = String::new();
    let mut in_str = false;
    let mut prev = ' ';
    let mut chars = line.chars().peekable();
    while let Some(ch) = chars.next() {
        if !in_str && ch == '/' && chars.peek() == Some(&'/') {
            break;
        }
        if ch == '"' && prev != '\\' {
            in_str = !in_str;
            out.push(ch);
        } else if !in_str {
            out.push(ch);
        }
        prev = ch;
    }
    out
}

/// The identifiers of a code line.
fn words(code: &str) -> impl Iterator<Item = &str> {
    code.split(|c: char| !(c.is_alphanumeric() || c == '_'))
        .filter(|w| !w.is_empty())
}

/// Every `extern "C" fn` of a source text: (name, line number, code lines of its body).
fn extern_bodies(text: &str) -> Vec<(String, usize, Vec<String>)> {
    let lines: Vec<String> = text.lines().map(code_of).collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let Some(at) = lines[i].find("extern \"\" fn ") else {
            i += 1;
            continue;
        };
        let name: String = lines[i][at + "extern \"\" fn ".len()..]
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_')
            .collect();
        // The body: from the first `{` after the parameters to its matching `}`.
        let (mut depth, mut started, mut parens) = (0i32, false, 0i32);
        let mut body = Vec::new();
        let start = i;
        'outer: while i < lines.len() {
            let mut cur = String::new();
            for ch in lines[i].chars() {
                match ch {
                    '(' => parens += 1,
                    ')' => parens -= 1,
                    '{' if parens == 0 => {
                        depth += 1;
                        if !started {
                            started = true;
                            continue;
                        }
                    }
                    '}' if started => {
                        depth -= 1;
                        if depth == 0 {
                            if !cur.trim().is_empty() {
                                body.push(cur);
                            }
                            break 'outer;
                        }
                    }
                    _ => {}
                }
                if started {
                    cur.push(ch);
                }
            }
            if started && !cur.trim().is_empty() {
                body.push(cur);
            }
            i += 1;
        }
        out.push((name, start + 1, body));
        i += 1;
    }
    out
}

/// What is wrong with one `extern "C"` body: a loop, too many lines, or more than one way
/// into the context. Early `return`s through an entry (an argument error raised, the
/// display-list form of a command: at most two) and the pair of closures of a
/// record-or-execute helper (`listable_draw`, or a `compiling_list()` branch) do not count
/// as further calls.
fn body_violations(name: &str, body: &[String], externs: &BTreeSet<String>) -> Vec<String> {
    let mut v = Vec::new();
    let all: Vec<&str> = body.iter().flat_map(|l| words(l)).collect();
    for kw in ["for", "while", "loop"] {
        if all.contains(&kw) {
            v.push(format!("a `{kw}` loop"));
        }
    }
    if body.len() > MAX_BODY_LINES {
        v.push(format!("{} lines (at most {MAX_BODY_LINES})", body.len()));
    }
    let is_entry = |w: &str| CONTEXT_ENTRIES.contains(&w) || (externs.contains(w) && w != name);
    let (mut calls, mut returns) = (0, 0);
    for line in body {
        let n = words(line).filter(|w| is_entry(w)).count();
        if line.contains("return ") {
            returns += n;
        } else {
            calls += n;
        }
    }
    if calls > 1 || returns > 2 {
        v.push(format!(
            "{calls} calls into the context (+{returns} in a return)"
        ));
    }
    let paired = all.contains(&"listable_draw") || all.contains(&"compiling_list");
    let touches: usize = body
        .iter()
        .map(|l| {
            let b = l.as_bytes();
            (0..b.len())
                .filter(|&i| {
                    (b[i..].starts_with(b"c.") || b[i..].starts_with(b"ctx."))
                        && (i == 0 || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'_'))
                })
                .count()
        })
        .sum();
    if touches > if paired { 2 } else { 1 } {
        v.push(format!("{touches} uses of the context"));
    }
    v
}

/// The `extern "C"` functions of `src/ffi`: each body.
fn ffi_bodies() -> Vec<(String, String, usize, Vec<String>)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/ffi");
    let mut files = Vec::new();
    rust_files(&dir, &mut files);
    files.sort();
    let mut out = Vec::new();
    for f in files {
        // Macro families expand to their declarations (empty bodies): their names count
        // as entry points, and the macros' own bodies are one expression each.
        let text = ffi_expand::expand(&std::fs::read_to_string(&f).unwrap());
        let rel = f.strip_prefix(&dir).unwrap().display().to_string();
        for (name, line, body) in extern_bodies(&text) {
            out.push((rel.clone(), name, line, body));
        }
    }
    out
}

/// Issue 41: every `extern "C"` body only converts — reads its pointer arguments,
/// converts, makes one call into the context and lets the wrapper record the error. The
/// logic (loops, validation, state decisions, multi-step sequences) lives below `ffi`.
#[test]
fn ffi_bodies_only_convert() {
    let bodies = ffi_bodies();
    assert!(
        bodies.len() > 300,
        "found only {} extern bodies",
        bodies.len()
    );
    let externs: BTreeSet<String> = bodies.iter().map(|b| b.1.clone()).collect();
    let mut errors = Vec::new();
    for (file, name, line, body) in &bodies {
        if BODY_EXCEPTIONS.iter().any(|(n, _)| n == name) {
            continue;
        }
        for v in body_violations(name, body, &externs) {
            errors.push(format!("src/ffi/{file}:{line} {name}: {v}"));
        }
    }
    assert!(
        errors.is_empty(),
        "{} extern \"C\" bodies do more than convert and call:\n{}",
        errors.len(),
        errors.join("\n")
    );
}

/// The body checker sees what it must: a loop, a long body, two calls into the context,
/// two uses of `c`; and accepts a record-or-execute pair and an early error return.
#[test]
fn the_body_checker_finds_logic() {
    let text = r#"
/// doc: for while loop in a comment
#[no_mangle]
pub unsafe extern "C" fn glBad(n: GLsizei, p: *const GLuint) {
    for i in 0..n {
        with_ctx(|c| c.thing(i));
    }
}
pub extern "C" fn glTwo(a: GLenum) {
    with_ctx(|c| c.one(a));
    with_ctx_list(move |c| c.two(a))
}
pub extern "C" fn glTouch(a: GLenum) {
    with_ctx(|c| { c.state.x = c.other(a); Ok(()) })
}
pub extern "C" fn glFine(a: GLenum, n: GLint) {
    if n < 0 {
        return with_ctx_list(|_| Err(GlError::InvalidValue));
    }
    if a == 0 && compiling_list() {
        return with_ctx_list(move |c| c.vector(a, n));
    }
    with_ctx_list(move |c| c.scalar(a, n))
}
pub extern "C" fn glForward(a: GLenum) {
    glFine(a, 0)
}
"#;
    let bodies = extern_bodies(text);
    let names: BTreeSet<String> = bodies.iter().map(|b| b.0.clone()).collect();
    assert_eq!(names.len(), 5, "{bodies:?}");
    let found: BTreeMap<String, Vec<String>> = bodies
        .iter()
        .map(|(n, _, b)| (n.clone(), body_violations(n, b, &names)))
        .collect();
    assert_eq!(found["glBad"], ["a `for` loop"], "{found:?}");
    assert!(found["glTwo"][0].contains("2 calls"), "{found:?}");
    assert_eq!(found["glTouch"], ["2 uses of the context"], "{found:?}");
    assert!(found["glFine"].is_empty(), "{found:?}");
    assert!(found["glForward"].is_empty(), "{found:?}");
    let long = format!(
        "pub extern \"C\" fn glLong() {{\n{}}}\n",
        "    let x = 1;\n".repeat(13)
    );
    let b = extern_bodies(&long);
    assert_eq!(body_violations("glLong", &b[0].2, &names).len(), 1, "{b:?}");
}
