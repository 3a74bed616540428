//! Shared helpers of the syntax tests: the corpus on disk and the comparison of our
//! info log with Mesa's.
#![allow(dead_code)]

use softgl_glsl::diag::{Log, Severity};
use softgl_glsl::Stage;
use std::path::PathBuf;

/// The files of `tests/corpus/<dir>`, sorted, with their stage (from the extension)
/// and text.
pub fn corpus(dir: &str) -> Vec<(String, Stage, String)> {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/corpus")
        .join(dir);
    let mut files: Vec<_> = std::fs::read_dir(&root)
        .expect("corpus directory")
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    files
        .into_iter()
        .map(|p| {
            let stage = match p.extension().and_then(|e| e.to_str()) {
                Some("vert") => Stage::Vertex,
                Some("frag") => Stage::Fragment,
                other => panic!("unknown stage extension {other:?} of {p:?}"),
            };
            let name = p.file_name().unwrap().to_string_lossy().into_owned();
            (name, stage, std::fs::read_to_string(&p).unwrap())
        })
        .collect()
}

/// The first error line of a Mesa info log: (position, kind, text).
pub fn mesa_first_error(log: &str) -> Option<(String, String, String)> {
    log.lines().find_map(|l| {
        let (pos, rest) = l.split_once(": ")?;
        let (kind, text) = rest.split_once(": ")?;
        kind.ends_with("error")
            .then(|| (pos.to_string(), kind.to_string(), text.to_string()))
    })
}

/// Our first error in the same form.
pub fn our_first_error(log: &Log) -> Option<(String, String, String)> {
    let m = log
        .messages
        .iter()
        .find(|m| m.severity == Severity::Error)?;
    let kind = if m.preprocessor {
        "preprocessor error"
    } else {
        "error"
    };
    Some((
        m.pos.to_string(),
        kind.into(),
        m.text.lines().next().unwrap_or("").trim_end().to_string(),
    ))
}
