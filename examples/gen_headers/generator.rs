//! Generates `include/GL/gl.h`, `include/GL/glext.h` and `include/GL/osmesa.h` from the
//! Rust sources in `src/ffi` with cbindgen.
//!
//! Shared by `examples/gen_headers.rs` (writes the files) and `tests/headers.rs` (checks
//! that the committed files are byte-identical to what this produces).
//!
//! cbindgen turns every Rust item into its C declaration; this module only sorts those
//! declarations into Mesa's header layout: the `GLAPI … GLAPIENTRY` decoration of
//! prototypes, `PFNGL…PROC` typedefs derived from the prototypes, the
//! `GL_GLEXT_PROTOTYPES` guard, per-extension `#ifndef` guards in glext.h, and the hex
//! spelling of integer constants (cbindgen prints them in decimal; the spelling of the
//! Rust source is restored after checking that the values agree).
#![allow(dead_code)] // the example and the test each use a different part of this module

use std::collections::HashMap;
use std::fmt::Write as _;
use std::path::Path;

/// One of the C headers softgl ships.
#[derive(Clone, Copy, PartialEq, Eq, Debug)]
pub enum Header {
    /// `GL/gl.h`: GL 1.0–1.3 types, tokens and functions.
    Gl,
    /// `GL/glext.h`: GL 1.4/1.5 and extension tokens and functions.
    Glext,
    /// `GL/osmesa.h`: the OSMesa API.
    Osmesa,
}

impl Header {
    /// Every header, in the order they are generated.
    pub const ALL: [Header; 3] = [Header::Gl, Header::Glext, Header::Osmesa];

    /// The header's path relative to the crate root.
    pub fn path(self) -> &'static str {
        match self {
            Header::Gl => "include/GL/gl.h",
            Header::Glext => "include/GL/glext.h",
            Header::Osmesa => "include/GL/osmesa.h",
        }
    }
}

/// Which header each file of `src/ffi` feeds. Every new file in `src/ffi` must be added
/// here (or to [`NOT_IN_HEADERS`]); the generator refuses to run otherwise.
///
/// A file contributes all its public constants, type aliases, opaque structs and
/// `#[no_mangle] extern "C"` functions to its header. Keep one header per file: put GL
/// 1.4/1.5 entry points and ARB/EXT aliases of them in files mapped to glext.h, and GL
/// 1.0–1.3 entry points (and GL_ARB_multitexture aliases) in files mapped to gl.h.
pub const SOURCES: &[(&str, Header)] = &[
    ("types.rs", Header::Gl),
    ("enums.rs", Header::Gl),
    ("state.rs", Header::Gl),
    ("matrix.rs", Header::Gl),
    ("immediate.rs", Header::Gl),
    ("arrays.rs", Header::Gl),
    ("draw.rs", Header::Gl),
    ("query.rs", Header::Gl),
    ("fragment.rs", Header::Gl),
    ("textures.rs", Header::Gl),
    ("textures_3d.rs", Header::Gl),
    ("lighting.rs", Header::Gl),
    ("rasterization.rs", Header::Gl),
    ("texgen.rs", Header::Gl),
    ("pixels.rs", Header::Gl),
    ("pixels_draw.rs", Header::Gl),
    ("lists.rs", Header::Gl),
    ("accum.rs", Header::Gl),
    ("feedback.rs", Header::Gl),
    ("eval.rs", Header::Gl),
    ("legacy.rs", Header::Gl),
    ("textures_compressed.rs", Header::Gl),
    ("aliases_gl.rs", Header::Gl),
    ("glext_enums.rs", Header::Glext),
    ("multidraw.rs", Header::Glext),
    ("buffers.rs", Header::Glext),
    ("fragment_ext.rs", Header::Glext),
    ("textures_ext.rs", Header::Glext),
    ("framebuffers.rs", Header::Glext),
    ("lighting_ext.rs", Header::Glext),
    ("arrays_gl14.rs", Header::Glext),
    ("points.rs", Header::Glext),
    ("pixels_ext.rs", Header::Glext),
    ("queries.rs", Header::Glext),
    ("arrays_ext.rs", Header::Glext),
    ("transform_ext.rs", Header::Glext),
    ("aliases_ext.rs", Header::Glext),
    ("osmesa.rs", Header::Osmesa),
];

/// Files of `src/ffi` that declare nothing for C.
pub const NOT_IN_HEADERS: &[&str] = &["mod.rs", "proc_table.rs", "textures_ds.rs"];

/// Typedefs of `types.rs` that Mesa declares in glext.h rather than gl.h.
pub const GLEXT_TYPES: &[&str] = &[
    "GLsizeiptr",
    "GLintptr",
    "GLchar",
    "GLsizeiptrARB",
    "GLintptrARB",
];

/// The gl.h functions for which Mesa's gl.h declares a `PFNGL…PROC` typedef (its GL 1.2
/// and 1.3 sections). Functions ending in `ARB` (GL_ARB_multitexture) get one as well.
/// The list is exact on purpose: programs written against Mesa's headers declare the
/// other PFN types themselves, and a second typedef of the same name breaks C99.
pub const GL_H_PFN: &[&str] = &[
    "glDrawRangeElements",
    "glTexImage3D",
    "glTexSubImage3D",
    "glCopyTexSubImage3D",
    "glActiveTexture",
    "glSampleCoverage",
    "glCompressedTexImage3D",
    "glCompressedTexImage2D",
    "glCompressedTexImage1D",
    "glCompressedTexSubImage3D",
    "glCompressedTexSubImage2D",
    "glCompressedTexSubImage1D",
    "glGetCompressedTexImage",
];

/// Declarations where cbindgen's rendering differs from Mesa's and Mesa's is kept:
/// (cbindgen's line, Mesa's line). Generation fails if cbindgen's line is not produced.
const MESA_SPELLINGS: &[(&str, &str)] = &[
    // Mesa leaves the parameter list unprototyped, so `proc(args)` compiles in C.
    (
        "typedef void (*OSMESAproc)(void);",
        "typedef void (*OSMESAproc)();",
    ),
];

/// The command that regenerates the headers.
pub const REGENERATE: &str = "cargo run --example gen_headers";

/// A C prototype as cbindgen rendered it, split into its parts.
#[derive(Clone, Debug)]
struct Proto {
    /// Return type, e.g. `void` or `const GLubyte *`.
    ret: String,
    /// Function name.
    name: String,
    /// Parameter list without parentheses (`void` when empty).
    args: String,
}

/// What cbindgen produced for one source file.
#[derive(Default, Debug)]
struct Fragment {
    /// `#define` name and value, in source order.
    defines: Vec<(String, String)>,
    /// The feature section (`GL_ARB_shadow`) of each constant in the Rust source: a
    /// constant `GL_<feature> = 1` opens one, the next plain `//` comment closes it.
    sections: HashMap<String, String>,
    /// Typedef name and full line.
    typedefs: Vec<(String, String)>,
    /// Opaque struct declarations (`struct osmesa_context;`).
    structs: Vec<String>,
    /// Function prototypes.
    protos: Vec<Proto>,
}

/// Generates every header: `(path relative to the crate root, contents)`.
pub fn generate(root: &Path) -> Result<Vec<(&'static str, String)>, String> {
    let ffi = root.join("src/ffi");
    check_file_table(&ffi)?;
    let mut parts: HashMap<&str, Fragment> = HashMap::new();
    for &(file, _) in SOURCES {
        parts.insert(file, run_cbindgen(&ffi.join(file))?);
    }
    let for_header = |h: Header| -> Vec<(&str, &Fragment)> {
        SOURCES
            .iter()
            .filter(|(_, hh)| *hh == h)
            .map(|(f, _)| (*f, &parts[f]))
            .collect()
    };
    let mut out = Vec::new();
    let mut used = vec![0; MESA_SPELLINGS.len()];
    for h in Header::ALL {
        let text = match h {
            Header::Gl => gl_h(&for_header(h), &parts)?,
            Header::Glext => glext_h(&for_header(h), &parts)?,
            Header::Osmesa => osmesa_h(&for_header(h))?,
        };
        out.push((h.path(), apply_mesa_spellings(text, &mut used)));
    }
    for ((cbindgen, _), n) in MESA_SPELLINGS.iter().zip(used) {
        if n != 1 {
            return Err(format!(
                "expected cbindgen to render `{cbindgen}` once, found {n}: update MESA_SPELLINGS"
            ));
        }
    }
    Ok(out)
}

/// Fails unless every `.rs` file of `src/ffi` is in exactly one of [`SOURCES`] and
/// [`NOT_IN_HEADERS`], and every listed file exists.
fn check_file_table(ffi: &Path) -> Result<(), String> {
    let mut present = Vec::new();
    let entries = std::fs::read_dir(ffi).map_err(|e| format!("{}: {e}", ffi.display()))?;
    for e in entries.flatten() {
        let name = e.file_name().to_string_lossy().into_owned();
        if name.ends_with(".rs") {
            present.push(name);
        }
    }
    present.sort();
    let mut errors = Vec::new();
    for name in &present {
        let listed = SOURCES.iter().filter(|(f, _)| f == name).count()
            + NOT_IN_HEADERS.iter().filter(|f| *f == name).count();
        if listed != 1 {
            errors.push(format!(
                "src/ffi/{name} is listed {listed} times in SOURCES/NOT_IN_HEADERS of \
                 examples/gen_headers/generator.rs (must be exactly once: add it to the \
                 header it belongs to)"
            ));
        }
    }
    for (f, _) in SOURCES {
        if !present.iter().any(|p| p == f) {
            errors.push(format!("SOURCES lists src/ffi/{f}, which does not exist"));
        }
    }
    if errors.is_empty() {
        Ok(())
    } else {
        Err(errors.join("\n"))
    }
}

/// The cbindgen configuration shared by every file: bare C declarations, one per line.
fn config(include: Vec<String>) -> cbindgen::Config {
    let mut c = cbindgen::Config {
        language: cbindgen::Language::C,
        no_includes: true,
        documentation: false,
        style: cbindgen::Style::Tag,
        usize_is_size_t: true,
        sort_by: cbindgen::SortKey::None,
        line_length: 100_000,
        ..Default::default()
    };
    c.function.args = cbindgen::Layout::Horizontal;
    c.export.include = include;
    c
}

/// Runs cbindgen on one source file and sorts its output lines into a [`Fragment`].
fn run_cbindgen(path: &Path) -> Result<Fragment, String> {
    let source = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    // cbindgen emits only types reachable from functions and constants; name the type
    // aliases and structs of the file so that e.g. types.rs yields its typedefs.
    let include = public_type_names(&source);
    let bindings = cbindgen::Builder::new()
        .with_config(config(include))
        .with_src(path)
        .generate()
        .map_err(|e| format!("cbindgen failed on {}: {e}", path.display()))?;
    let mut bytes = Vec::new();
    bindings.write(&mut bytes);
    let text = String::from_utf8(bytes).map_err(|e| e.to_string())?;
    let literals = const_literals(&source);
    let mut frag = Fragment {
        sections: const_sections(&source),
        ..Default::default()
    };
    for line in text.lines().map(str::trim).filter(|l| !l.is_empty()) {
        if let Some(rest) = line.strip_prefix("#define ") {
            let (name, value) = rest
                .split_once(' ')
                .ok_or_else(|| format!("odd cbindgen #define: {line}"))?;
            let value = restore_literal(name, value.trim(), &literals)?;
            frag.defines.push((name.to_string(), value));
        } else if line.starts_with("typedef ") && line.ends_with(';') {
            frag.typedefs.push((typedef_name(line)?, line.to_string()));
        } else if line.starts_with("struct ") && line.ends_with(';') {
            frag.structs.push(line.to_string());
        } else if line.ends_with(");") && line.contains('(') {
            frag.protos.push(parse_proto(line)?);
        } else {
            return Err(format!(
                "unexpected cbindgen output for {}: {line}",
                path.display()
            ));
        }
    }
    // cbindgen writes constants that use a type of the file after that type; keep the
    // order of the Rust source instead.
    frag.defines.sort_by_key(|(n, _)| {
        literals
            .iter()
            .position(|(ln, _)| ln == n)
            .unwrap_or(usize::MAX)
    });
    Ok(frag)
}

/// Names of `pub type X` and `pub struct X` items in a Rust source.
fn public_type_names(source: &str) -> Vec<String> {
    source
        .lines()
        .filter_map(|l| {
            let l = l.trim_start();
            l.strip_prefix("pub type ")
                .or_else(|| l.strip_prefix("pub struct "))
        })
        .map(|rest| {
            rest.chars()
                .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
                .collect()
        })
        .collect()
}

/// `(name, literal text)` of every one-line `pub const NAME: T = VALUE;` in source order.
fn const_literals(source: &str) -> Vec<(String, String)> {
    source
        .lines()
        .filter_map(|l| {
            let rest = l.trim_start().strip_prefix("pub const ")?;
            let (name, rest) = rest.split_once(':')?;
            let (_, value) = rest.split_once('=')?;
            let value = value.trim().strip_suffix(';')?;
            Some((name.trim().to_string(), value.trim().to_string()))
        })
        .collect()
}

/// Maps each one-line `pub const` to the feature section it is in (see
/// [`Fragment::sections`]); constants outside any section are not listed.
fn const_sections(source: &str) -> HashMap<String, String> {
    let mut out = HashMap::new();
    let mut current: Option<String> = None;
    for line in source.lines().map(str::trim_start) {
        if line.starts_with("//") && !line.starts_with("///") && !line.starts_with("//!") {
            current = None;
        }
        if let Some((name, value)) = const_literals(line).pop() {
            if is_feature_macro(&name) && value == "1" {
                current = Some(name.clone());
            }
            if let Some(section) = &current {
                out.insert(name, section.clone());
            }
        }
    }
    out
}

/// The value of a plain decimal or `0x` integer literal.
fn int_value(lit: &str) -> Option<u64> {
    match lit.strip_prefix("0x").or_else(|| lit.strip_prefix("0X")) {
        Some(hex) => u64::from_str_radix(hex, 16).ok(),
        None => lit.parse().ok(),
    }
}

/// Replaces cbindgen's decimal rendering of an integer constant with the Rust source's
/// spelling (e.g. `0x1400`) when that spelling is a plain literal of the same value.
fn restore_literal(
    name: &str,
    rendered: &str,
    literals: &[(String, String)],
) -> Result<String, String> {
    let Some(value) = int_value(rendered) else {
        return Ok(rendered.to_string()); // a path (`GL_RGBA`) or an expression
    };
    let Some((_, lit)) = literals.iter().find(|(n, _)| n == name) else {
        return Ok(rendered.to_string());
    };
    match int_value(lit) {
        Some(v) if v == value => Ok(lit.clone()),
        Some(v) => Err(format!(
            "{name}: cbindgen rendered {rendered} but the source says {lit} ({v})"
        )),
        None => Ok(rendered.to_string()),
    }
}

/// The name a typedef line declares (`typedef unsigned int GLenum;`,
/// `typedef void (*OSMESAproc)(void);`).
fn typedef_name(line: &str) -> Result<String, String> {
    let ident = |s: &str| -> String {
        s.chars()
            .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
            .collect()
    };
    if let Some(i) = line.find("(*") {
        return Ok(ident(&line[i + 2..]));
    }
    let body = line.trim_end_matches(';');
    let start = body
        .rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .map_or(0, |i| i + 1);
    let name = &body[start..];
    if name.is_empty() {
        Err(format!("cannot find the name of: {line}"))
    } else {
        Ok(name.to_string())
    }
}

/// Splits `RET NAME(ARGS);` into its parts and gives the parameters Mesa's names
/// (`type_` → `type`, `_sharelist` → `sharelist`).
fn parse_proto(line: &str) -> Result<Proto, String> {
    let open = line.find('(').ok_or_else(|| format!("no '(' in {line}"))?;
    let head = line[..open].trim_end();
    let start = head
        .rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .map_or(0, |i| i + 1);
    let name = head[start..].to_string();
    let ret = head[..start].trim_end().to_string();
    let args = line[open + 1..]
        .strip_suffix(");")
        .ok_or_else(|| format!("prototype does not end in ');': {line}"))?;
    if name.is_empty() || ret.is_empty() {
        return Err(format!("cannot parse prototype: {line}"));
    }
    let args = split_args(args)
        .iter()
        .map(|a| mesa_param_name(a))
        .collect::<Vec<_>>()
        .join(", ");
    Ok(Proto { ret, name, args })
}

/// Splits a parameter list at its top-level commas.
fn split_args(args: &str) -> Vec<String> {
    let (mut out, mut cur, mut depth) = (Vec::new(), String::new(), 0i32);
    for c in args.chars() {
        match c {
            '(' => depth += 1,
            ')' => depth -= 1,
            ',' if depth == 0 => {
                out.push(cur.trim().to_string());
                cur.clear();
                continue;
            }
            _ => {}
        }
        cur.push(c);
    }
    out.push(cur.trim().to_string());
    out
}

/// Drops the leading and trailing underscores Rust needs (`_unused`, `type_`) from a
/// parameter's name.
fn mesa_param_name(arg: &str) -> String {
    let start = arg
        .rfind(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .map_or(0, |i| i + 1);
    let (ty, name) = arg.split_at(start);
    let trimmed = name.trim_matches('_');
    if name == "void" || trimmed.is_empty() {
        arg.to_string()
    } else {
        format!("{ty}{trimmed}")
    }
}

/// `RET` followed by a space unless it ends in `*`.
fn ret_sep(ret: &str) -> &'static str {
    if ret.ends_with('*') {
        ""
    } else {
        " "
    }
}

/// `GLAPI RET GLAPIENTRY NAME(ARGS);` with the given calling-convention macro.
fn prototype(p: &Proto, entry: &str, space: &str) -> String {
    format!(
        "GLAPI {}{}{entry} {}{space}({});",
        p.ret,
        ret_sep(&p.ret),
        p.name,
        p.args
    )
}

/// `typedef RET (APIENTRYP PFNGLNAMEPROC) (ARGS);`
fn pfn_typedef(p: &Proto) -> String {
    format!(
        "typedef {}{}(APIENTRYP PFN{}PROC) ({});",
        p.ret,
        ret_sep(&p.ret),
        p.name.to_ascii_uppercase(),
        p.args
    )
}

/// `#define NAME VALUE` with the value aligned like Mesa's headers.
fn define(name: &str, value: &str) -> String {
    format!("#define {name:<40} {value}")
}

/// True for a feature-test macro (`GL_VERSION_1_4`, `GL_ARB_imaging`) rather than a token.
fn is_feature_macro(name: &str) -> bool {
    name.starts_with("GL_VERSION_") || name.bytes().any(|b| b.is_ascii_lowercase())
}

/// The comment every generated header starts with.
fn banner(header: Header, what: &str) -> String {
    format!(
        "/*\n * {} — {what}\n *\n * softgl: a software OpenGL 1.5 implementation with Mesa's OSMesa API.\n *\n \
         * GENERATED FILE, DO NOT EDIT. Produced by cbindgen from the files in src/ffi with\n \
         *   {REGENERATE}\n \
         * (tests/headers.rs fails when this file is stale).\n */\n\n",
        header.path().trim_start_matches("include/"),
    )
}

/// The calling-convention and linkage macros, as Mesa's gl.h defines them on Unix.
const GL_H_MACROS: &str = "\
/*
 * GLAPI, GLAPIENTRY, APIENTRY, APIENTRYP and GLAPIENTRYP, as in Mesa's gl.h.
 */
#if !defined(GLAPI) && ((defined(__GNUC__) && __GNUC__ >= 4) || (defined(__SUNPRO_C) && (__SUNPRO_C >= 0x590)))
#  define GLAPI __attribute__((visibility(\"default\")))
#endif

#ifndef GLAPI
#define GLAPI extern
#endif

#ifndef GLAPIENTRY
#define GLAPIENTRY
#endif

#ifndef APIENTRY
#define APIENTRY GLAPIENTRY
#endif

/* \"P\" suffix to be used for a pointer to a function */
#ifndef APIENTRYP
#define APIENTRYP APIENTRY *
#endif

#ifndef GLAPIENTRYP
#define GLAPIENTRYP GLAPIENTRY *
#endif
";

/// Opens `extern "C"` for C++.
const EXTERN_C_OPEN: &str = "#ifdef __cplusplus\nextern \"C\" {\n#endif\n";
/// Closes `extern "C"` for C++.
const EXTERN_C_CLOSE: &str = "#ifdef __cplusplus\n}\n#endif\n";

/// Appends a `/* comment */` line followed by `lines`, then a blank line.
fn block(out: &mut String, comment: &str, lines: impl IntoIterator<Item = String>) {
    let lines: Vec<String> = lines.into_iter().collect();
    if lines.is_empty() {
        return;
    }
    let _ = writeln!(out, "/* {comment} */");
    for l in lines {
        out.push_str(&l);
        out.push('\n');
    }
    out.push('\n');
}

/// Fails if a fragment of `header` carries something the header has no place for.
fn reject(file: &str, what: &str, present: bool) -> Result<(), String> {
    if present {
        Err(format!(
            "src/ffi/{file} declares {what}, which its header does not take; \
             move it or extend examples/gen_headers/generator.rs"
        ))
    } else {
        Ok(())
    }
}

/// `GL/gl.h`.
fn gl_h(files: &[(&str, &Fragment)], all: &HashMap<&str, Fragment>) -> Result<String, String> {
    let mut out = banner(Header::Gl, "OpenGL 1.0–1.3 (GL 1.4/1.5 are in GL/glext.h)");
    out.push_str("#ifndef __gl_h_\n#define __gl_h_\n\n");
    out.push_str(GL_H_MACROS);
    out.push('\n');
    out.push_str(EXTERN_C_OPEN);
    out.push('\n');
    for (file, f) in files {
        reject(file, "an opaque struct", !f.structs.is_empty())?;
        let typedefs = f
            .typedefs
            .iter()
            .filter(|(n, _)| !GLEXT_TYPES.contains(&n.as_str()))
            .map(|(_, l)| l.clone());
        block(&mut out, &format!("Types: src/ffi/{file}"), typedefs);
        let defines = f.defines.iter().map(|(n, v)| define(n, v));
        block(&mut out, &format!("Tokens: src/ffi/{file}"), defines);
        let protos = f.protos.iter().map(|p| prototype(p, "GLAPIENTRY", ""));
        block(&mut out, &format!("Functions: src/ffi/{file}"), protos);
    }
    let pfns = files
        .iter()
        .flat_map(|(_, f)| &f.protos)
        .filter(|p| GL_H_PFN.contains(&p.name.as_str()) || p.name.ends_with("ARB"))
        .map(pfn_typedef);
    block(
        &mut out,
        "Function-pointer types Mesa's gl.h declares (GL 1.2, 1.3, GL_ARB_multitexture)",
        pfns,
    );
    // Types declared in glext.h must not come from a file of another header by mistake.
    for (file, f) in all {
        if !files.iter().any(|(ff, _)| ff == file) {
            for (n, _) in &f.typedefs {
                if GLEXT_TYPES.contains(&n.as_str()) {
                    return Err(format!("{n} is expected in types.rs, found in {file}"));
                }
            }
        }
    }
    out.push_str(EXTERN_C_CLOSE);
    out.push_str(
        "\n/*\n * As in Mesa, gl.h includes glext.h unless GL_GLEXT_LEGACY is defined.\n */\n\
         #ifndef GL_GLEXT_LEGACY\n#include <GL/glext.h>\n#endif\n\n#endif /* __gl_h_ */\n",
    );
    Ok(out)
}

/// `GL/glext.h`.
fn glext_h(files: &[(&str, &Fragment)], all: &HashMap<&str, Fragment>) -> Result<String, String> {
    let mut out = banner(Header::Glext, "OpenGL 1.4/1.5 and extensions");
    out.push_str(
        "#ifndef __gl_glext_h_\n#define __gl_glext_h_ 1\n\
         /* The include guard of older Mesa glext.h versions. */\n#define __glext_h_ 1\n\n\
         #include <stddef.h>\n\n",
    );
    out.push_str(EXTERN_C_OPEN);
    out.push_str(
        "\n#ifndef APIENTRY\n#define APIENTRY\n#endif\n#ifndef APIENTRYP\n\
         #define APIENTRYP APIENTRY *\n#endif\n#ifndef GLAPI\n#define GLAPI extern\n#endif\n\n",
    );
    // The glext.h types live in types.rs, which belongs to gl.h.
    let ext_types = all
        .get("types.rs")
        .map(|f| {
            f.typedefs
                .iter()
                .filter(|(n, _)| GLEXT_TYPES.contains(&n.as_str()))
                .map(|(_, l)| l.clone())
                .collect::<Vec<_>>()
        })
        .unwrap_or_default();
    block(&mut out, "Types: src/ffi/types.rs", ext_types);
    for (file, f) in files {
        reject(file, "an opaque struct", !f.structs.is_empty())?;
        block(
            &mut out,
            &format!("Types: src/ffi/{file}"),
            f.typedefs.iter().map(|(_, l)| l.clone()),
        );
        if f.defines.is_empty() {
            continue;
        }
        let _ = writeln!(out, "/* Tokens: src/ffi/{file} */");
        // One `#ifndef FEATURE` section per feature of the Rust source, as in Mesa's glext.h.
        let mut open: Option<&String> = None;
        for (n, v) in &f.defines {
            let section = f.sections.get(n);
            if section != open {
                if let Some(prev) = open {
                    let _ = writeln!(out, "#endif /* {prev} */\n");
                }
                if let Some(feature) = section {
                    let _ = writeln!(out, "#ifndef {feature}");
                }
                open = section;
            }
            out.push_str(&define(n, v));
            out.push('\n');
        }
        if let Some(prev) = open {
            let _ = writeln!(out, "#endif /* {prev} */");
        }
        out.push('\n');
    }
    for (file, f) in files {
        block(
            &mut out,
            &format!("Function-pointer types: src/ffi/{file}"),
            f.protos.iter().map(pfn_typedef),
        );
    }
    out.push_str("#ifdef GL_GLEXT_PROTOTYPES\n\n");
    for (file, f) in files {
        block(
            &mut out,
            &format!("Functions: src/ffi/{file}"),
            f.protos.iter().map(|p| prototype(p, "APIENTRY", " ")),
        );
    }
    out.push_str("#endif /* GL_GLEXT_PROTOTYPES */\n\n");
    out.push_str(EXTERN_C_CLOSE);
    out.push_str("\n#endif /* __gl_glext_h_ */\n");
    Ok(out)
}

/// `GL/osmesa.h`.
fn osmesa_h(files: &[(&str, &Fragment)]) -> Result<String, String> {
    let mut out = banner(Header::Osmesa, "the OSMesa off-screen rendering API");
    out.push_str("#ifndef OSMESA_H\n#define OSMESA_H\n\n#include <GL/gl.h>\n\n");
    out.push_str(EXTERN_C_OPEN);
    out.push('\n');
    for (file, f) in files {
        block(
            &mut out,
            &format!("Constants: src/ffi/{file}"),
            f.defines.iter().map(|(n, v)| define(n, v)),
        );
        let types = f
            .structs
            .iter()
            .cloned()
            .chain(f.typedefs.iter().map(|(_, l)| l.clone()));
        block(&mut out, &format!("Types: src/ffi/{file}"), types);
        block(
            &mut out,
            &format!("Functions: src/ffi/{file}"),
            f.protos.iter().map(|p| prototype(p, "GLAPIENTRY", "")),
        );
    }
    out.push_str(EXTERN_C_CLOSE);
    out.push_str("\n#endif /* OSMESA_H */\n");
    Ok(out)
}

/// Replaces cbindgen's rendering by Mesa's for each [`MESA_SPELLINGS`] entry found, and
/// counts the replacements per entry.
fn apply_mesa_spellings(mut text: String, used: &mut [usize]) -> String {
    for (i, (cbindgen, mesa)) in MESA_SPELLINGS.iter().enumerate() {
        used[i] += text.matches(cbindgen).count();
        text = text.replace(cbindgen, mesa);
    }
    text
}
