//! Generates the OSMesaGetProcAddress table: every `#[no_mangle] extern "C" fn` in
//! `src/ffi/*.rs`, so the table can never miss an exported function. Functions generated
//! by the family macros of `src/ffi/families.rs` are read from their invocations
//! (`tools/ffi_expand.rs`).

#[path = "tools/ffi_expand.rs"]
mod ffi_expand;

use std::fmt::Write as _;
use std::path::Path;

fn main() {
    // Bind the library's references to its own exported functions inside the library, as
    // Mesa links libOSMesa (-Bsymbolic): a program that defines a `gl*` function of its own
    // (a wrapper named glFinish, say) must not replace softgl's in OSMesaGetProcAddress or
    // in softgl's own calls (tests/interposition.rs).
    if std::env::var("CARGO_CFG_TARGET_OS").as_deref() == Ok("linux") {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-Bsymbolic");
    }
    let dir = Path::new("src/ffi");
    println!("cargo:rerun-if-changed=src/ffi");
    println!("cargo:rerun-if-changed=tools/ffi_expand.rs");
    let mut entries: Vec<(String, String)> = Vec::new();
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .expect("src/ffi")
        .flatten()
        .map(|e| e.path())
        .collect();
    files.sort();
    for path in files {
        if path.extension().and_then(|e| e.to_str()) != Some("rs") {
            continue;
        }
        let module = path
            .file_stem()
            .and_then(|s| s.to_str())
            .unwrap_or_default()
            .to_string();
        println!("cargo:rerun-if-changed={}", path.display());
        let text = ffi_expand::expand(&std::fs::read_to_string(&path).expect("read ffi source"));
        let mut no_mangle = false;
        for line in text.lines() {
            let t = line.trim();
            if t.starts_with("#[no_mangle]") {
                no_mangle = true;
                continue;
            }
            if no_mangle {
                if t.starts_with("#[") || t.starts_with("///") || t.starts_with("//") {
                    continue;
                }
                no_mangle = false;
                let rest = t
                    .strip_prefix("pub unsafe extern \"C\" fn ")
                    .or_else(|| t.strip_prefix("pub extern \"C\" fn "));
                if let Some(rest) = rest {
                    let name: String = rest
                        .chars()
                        .take_while(|c| c.is_alphanumeric() || *c == '_')
                        .collect();
                    // Empty for the `$name` of a macro definition (src/ffi/families.rs).
                    if !name.is_empty() {
                        entries.push((name, module.clone()));
                    }
                }
            }
        }
    }
    entries.sort();
    entries.dedup_by(|a, b| a.0 == b.0);
    let mut out = String::from("/// Every exported function, sorted by name.\npub const PROCS: &[(&[u8], *const ())] = &[\n");
    for (name, module) in &entries {
        writeln!(
            out,
            "    (b\"{name}\", crate::ffi::{module}::{name} as *const ()),"
        )
        .unwrap();
    }
    out.push_str("];\n");
    let dest = Path::new(&std::env::var("OUT_DIR").expect("OUT_DIR")).join("proc_table.rs");
    std::fs::write(dest, out).expect("write proc table");
}
