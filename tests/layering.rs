//! The import rules of the crate's layers (issue 41), checked on the source text.
//!
//! The layers, top to bottom, and what each may name:
//! - `ffi` (the C boundary): anything below it.
//! - `context` (the GL state machine): everything but `ffi`.
//! - `plan` (state values → pipeline values, once per draw): the pipeline and the leaves,
//!   never `context` or `ffi`.
//! - the pipeline (`geometry`, `fixed_function`, `raster`, `fragment`, `texture`, `pixels`,
//!   `framebuffer`, and `render`, which runs a plan through them): other pipeline modules
//!   and the leaves, never `context`, `plan`, `ffi`
//!   or `gl` (the pipeline never sees a GL token).
//! - the leaves (`pipe`, `gl`, `simd`, `cpu`, `stats`, `tuning`, `memory`): one another
//!   at most, never a layer above.
//!
//! A file's module is its first path component under `src/`; every `crate::NAME`, every
//! `use crate::{NAME, …}` group and every `super::` chain that climbs to the crate root is
//! an edge. Doc comments and ordinary comments are skipped.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The modules of each layer.
const FFI: &[&str] = &["ffi"];
const STATE: &[&str] = &["context"];
const PLAN: &[&str] = &["plan"];
const PIPELINE: &[&str] = &[
    "geometry",
    "fixed_function",
    "raster",
    "fragment",
    "texture",
    "pixels",
    "framebuffer",
    "render",
];
const LEAVES: &[&str] = &["pipe", "gl", "simd", "cpu", "stats", "tuning", "memory"];

/// Modules that are neither code of the library nor a layer (test helpers).
const IGNORED: &[&str] = &["lib", "test_rng", "small_stack", "softgl"];

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
