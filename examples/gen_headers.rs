//! Regenerates `include/GL/{gl,osmesa}.h` from `src/ffi` with cbindgen, then
//! `include/GL/glext.h` from the Khronos registry with `tools/gen_glext.py`:
//! `cargo run --example gen_headers`. `tests/headers.rs` fails when they are stale.

#[path = "gen_headers/generator.rs"]
mod generator;

use std::path::Path;

fn main() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let headers = match generator::generate(root) {
        Ok(h) => h,
        Err(e) => {
            eprintln!("gen_headers: {e}");
            std::process::exit(1);
        }
    };
    for (path, text) in headers {
        let full = root.join(path);
        if std::fs::read_to_string(&full).ok().as_deref() == Some(text.as_str()) {
            println!("unchanged {path}");
            continue;
        }
        if let Some(dir) = full.parent() {
            std::fs::create_dir_all(dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display()));
        }
        std::fs::write(&full, text).unwrap_or_else(|e| panic!("{}: {e}", full.display()));
        println!("wrote {path}");
    }
    let status = std::process::Command::new("python3")
        .arg(root.join(generator::GLEXT_TOOL))
        .status()
        .unwrap_or_else(|e| panic!("python3 {}: {e}", generator::GLEXT_TOOL));
    if !status.success() {
        eprintln!("gen_headers: {} failed", generator::GLEXT_TOOL);
        std::process::exit(1);
    }
}
