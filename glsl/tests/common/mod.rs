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

fn unescape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut it = s.chars();
    while let Some(c) = it.next() {
        if c != '\\' {
            out.push(c);
            continue;
        }
        match it.next() {
            Some('n') => out.push('\n'),
            Some('t') => out.push('\t'),
            Some(other) => out.push(other),
            None => out.push('\\'),
        }
    }
    out
}

/// The error corpus `tests/corpus/errors.txt`: (name, stage, source).
pub fn error_cases() -> Vec<(String, Stage, String)> {
    cases_from("errors.txt")
}

/// The cases of a corpus file in the format of `errors.txt`: (name, stage, source).
pub fn cases_from(file: &str) -> Vec<(String, Stage, String)> {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/corpus")
        .join(file);
    let text = std::fs::read_to_string(path).expect("corpus file");
    text.lines()
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .map(|l| {
            let mut f = l.splitn(3, '\t');
            let (name, stage, src) = (f.next().unwrap(), f.next().unwrap(), f.next().unwrap());
            let stage = if stage == "v" {
                Stage::Vertex
            } else {
                Stage::Fragment
            };
            (name.to_string(), stage, unescape(src))
        })
        .collect()
}

/// The reference jobs for `cases`: `vert` or `frag` of each source by its stage.
pub fn jobs<'a, J>(
    cases: &'a [(String, Stage, String)],
    vert: fn(&'a str) -> J,
    frag: fn(&'a str) -> J,
) -> Vec<J> {
    cases
        .iter()
        .map(|(_, st, src)| match st {
            Stage::Vertex => vert(src),
            _ => frag(src),
        })
        .collect()
}

/// An error line as (position, kind, text).
pub type ErrorLine = (String, String, String);

/// Whether our first error agrees with Mesa's: same line and kind, and the same text
/// (for a syntax error, Mesa's text starts with ours, its `expecting` list aside; for
/// an unsupported `#version`, up to Mesa's longer list of versions).
pub fn agrees(ours: &ErrorLine, theirs: &ErrorLine) -> bool {
    let line = |p: &str| p.split('(').next().unwrap_or("").to_string();
    line(&ours.0) == line(&theirs.0)
        && ours.1 == theirs.1
        && if ours.2.starts_with("syntax error, unexpected ") {
            theirs.2.starts_with(&ours.2)
        } else if ours.2.starts_with("GLSL ") {
            theirs.2.starts_with(&ours.2[..ours.2.len().min(20)])
        } else {
            ours.2 == theirs.2.trim_end()
        }
}

/// A tiny xorshift generator (generated cases must not change from run to run).
pub struct Rng(pub u64);

impl Rng {
    /// The next number.
    pub fn next(&mut self) -> usize {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as usize
    }

    /// A random element of `v`.
    pub fn pick<'a, T>(&mut self, v: &'a [T]) -> &'a T {
        &v[self.next() % v.len()]
    }
}
