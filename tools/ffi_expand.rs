//! Rewrites the family macro invocations of a `src/ffi` file (`vector_fns! { … }` and
//! `c_fns! { … }`, see `src/ffi/families.rs`) into the plain declarations they
//! generate, `#[no_mangle] pub extern "C" fn NAME(PARAMS) {}`, in place and in order.
//!
//! The tools that read `src/ffi` as text see macro-generated functions through this one
//! function: build.rs (the OSMesaGetProcAddress table), the header generator (cbindgen,
//! which does not expand macros, reads the expanded text), tests/headers.rs and
//! tests/robust_common. tools/gen_aliases.py mirrors it in Python. Each of them includes
//! this file with `#[path]`, so it depends on nothing but `std`.
#![allow(dead_code)] // every includer uses a part

/// `source` with every family invocation replaced by the functions it generates; text
/// without invocations comes back unchanged.
pub fn expand(source: &str) -> String {
    let mut out = String::with_capacity(source.len());
    // The line reader of the invocation being expanded.
    let mut family: Option<fn(&str, &mut String)> = None;
    for line in source.lines() {
        let t = line.trim();
        match family {
            None if t == "vector_fns! {" => family = Some(vector_line),
            None if t == "c_fns! {" => family = Some(c_line),
            None => {
                out.push_str(line);
                out.push('\n');
            }
            Some(_) if line == "}" => family = None,
            Some(read) => read(t, &mut out),
        }
    }
    out
}

/// One exported declaration.
fn declare(out: &mut String, unsafe_: bool, name: &str, params: &str, ret: &str) {
    let kw = if unsafe_ {
        "pub unsafe extern"
    } else {
        "pub extern"
    };
    out.push_str(&format!(
        "#[no_mangle]\n{kw} \"C\" fn {name}({params}){ret} {{}}\n"
    ));
}

/// `(p, q) glXs glXsv GLshort, glXi glXiv GLint;`: for each entry the scalar function
/// (one `p: T` per name) and the vector one (`v: *const T`); `(target: GLenum; p, q)`
/// puts `target: GLenum` first in both. Other lines (a family
/// header `sink conv [defaults] {`, its `}`, comments) declare nothing.
fn vector_line(t: &str, out: &mut String) {
    let Some(rest) = t.strip_prefix('(') else {
        return;
    };
    let (names, entries) = rest.split_once(')').expect("vector_fns!: `(params)`");
    // `(target: GLenum; s, t)`: parameters before the `;` lead both forms unchanged.
    let (fixed, names) = match names.split_once(';') {
        Some((f, n)) => (format!("{}, ", f.trim()), n),
        None => (String::new(), names),
    };
    let names: Vec<&str> = names.split(',').map(str::trim).collect();
    let entries = entries
        .trim()
        .strip_suffix(';')
        .expect("vector_fns!: line ends in ';'");
    for entry in entries.split(',') {
        let words: Vec<&str> = entry.split_whitespace().collect();
        let [scalar, vector, ty] = words[..] else {
            panic!("vector_fns!: `scalar vector type` expected, found `{entry}`");
        };
        let params: Vec<String> = names.iter().map(|p| format!("{p}: {ty}")).collect();
        declare(
            out,
            false,
            scalar,
            &format!("{fixed}{}", params.join(", ")),
            "",
        );
        declare(out, true, vector, &format!("{fixed}v: *const {ty}"), "");
    }
}

/// `safe fn NAME(PARAMS) -> RET = module::core;` or `… => EXPR;` (or `unsafe fn …`).
/// Other lines (`///` docs) declare nothing.
fn c_line(t: &str, out: &mut String) {
    let (unsafe_, rest) = match (t.strip_prefix("safe fn "), t.strip_prefix("unsafe fn ")) {
        (Some(rest), _) => (false, rest),
        (_, Some(rest)) => (true, rest),
        _ => return,
    };
    let open = rest.find('(').expect("c_fns!: `(`");
    let close = open + rest[open..].find(')').expect("c_fns!: `)`");
    let (ret, _) = rest[close + 1..]
        .split_once('=')
        .expect("c_fns!: `=` or `=>`");
    let ret = match ret.trim() {
        "" => String::new(),
        r => format!(" {r}"),
    };
    declare(out, unsafe_, &rest[..open], &rest[open + 1..close], &ret);
}
