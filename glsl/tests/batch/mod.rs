//! Batches one-line test cases into shaders for Mesa (`tests/mesa`) and attributes
//! Mesa's errors back to the cases by line number: a case is accepted when no error
//! names its line. Cases of one version and stage share a shader, many to a shader.
#![allow(dead_code)]

use crate::mesa::{run, Context, Job};
use softgl_glsl::types::{Stage, Version};
use std::collections::BTreeSet;

/// One statement to compile inside `main` of a shader of `version` and `stage`.
#[derive(Clone, Debug)]
pub struct Case {
    /// The shader's version.
    pub version: Version,
    /// The shader's stage (vertex or fragment: Mesa's harness has no geometry shaders).
    pub stage: Stage,
    /// Global declarations the statement needs (`uniform sampler2D s;`), one per line.
    pub globals: Vec<String>,
    /// The statement, on one line.
    pub line: String,
}

/// The context a version is compiled in: the core 3.3 context for core 1.50 and 3.30,
/// a compatibility context otherwise.
pub fn context(v: Version) -> Context {
    if v.number >= 150 && !v.compatibility {
        Context::Core33
    } else {
        Context::Compat
    }
}

fn error_lines(log: &str) -> BTreeSet<usize> {
    log.lines()
        .filter(|l| l.contains(": error:"))
        .filter_map(|l| l.strip_prefix("0:")?.split('(').next()?.parse().ok())
        .collect()
}

/// Compiles every case; returns for each whether Mesa accepted it (None when an error
/// names no case's line, so no case of that shader can be judged) and the log lines of
/// its shader naming its line (or the whole log).
pub fn compile(cases: &[Case], per_shader: usize) -> Vec<(Option<bool>, String)> {
    let mut out = vec![(None, String::new()); cases.len()];
    for ctx in [Context::Compat, Context::Core33] {
        let mut groups: Vec<(Version, Stage, Vec<usize>)> = Vec::new();
        for (i, c) in cases.iter().enumerate() {
            if context(c.version) != ctx {
                continue;
            }
            match groups
                .iter_mut()
                .find(|g| g.0 == c.version && g.1 == c.stage && g.2.len() < per_shader)
            {
                Some(g) => g.2.push(i),
                None => groups.push((c.version, c.stage, vec![i])),
            }
        }
        let mut sources = Vec::new();
        let mut firsts = Vec::new();
        for (version, _, idx) in &groups {
            let globals: BTreeSet<&String> = idx.iter().flat_map(|&i| &cases[i].globals).collect();
            let mut src = format!("{}\n", version.directive());
            for g in &globals {
                src += &format!("{g}\n");
            }
            src += "void main() {\n";
            firsts.push(globals.len() + 3);
            for &i in idx {
                src += &format!("{}\n", cases[i].line);
            }
            src += "}\n";
            sources.push(src);
        }
        let jobs: Vec<Job> = groups
            .iter()
            .zip(&sources)
            .map(|(g, s)| match g.1 {
                Stage::Vertex => Job::Vertex(s),
                _ => Job::Fragment(s),
            })
            .collect();
        if jobs.is_empty() {
            continue;
        }
        let results = run(ctx, &jobs);
        for ((g, first), r) in groups.iter().zip(&firsts).zip(&results) {
            let lines = error_lines(&r.log);
            let stray = lines.iter().any(|&l| l < *first || l >= first + g.2.len());
            for (k, &i) in g.2.iter().enumerate() {
                let line = first + k;
                let mine = format!("0:{line}(");
                let log: String = if stray {
                    r.log.clone()
                } else {
                    r.log
                        .lines()
                        .filter(|l| l.starts_with(&mine))
                        .collect::<Vec<_>>()
                        .join("\n")
                };
                out[i] = ((!stray).then_some(!lines.contains(&line)), log);
            }
        }
    }
    out
}

/// Compiles the cases and returns a report line for each case whose outcome differs
/// from `expect_ok` (empty: all as expected).
pub fn check(cases: &[Case], expect_ok: bool, per_shader: usize) -> Vec<String> {
    compile(cases, per_shader)
        .into_iter()
        .zip(cases)
        .filter(|((ok, _), _)| *ok != Some(expect_ok))
        .map(|((_, log), c)| {
            let log: Vec<&str> = log.lines().take(3).collect();
            let (v, s) = (c.version.directive(), c.stage);
            format!("{v} {s:?}: {}\n    {}", c.line, log.join("\n    "))
        })
        .collect()
}

/// Prints `what` with the number of cases and of those `done`, and fails listing the
/// first 20 of `bad`.
fn report(what: &str, total: usize, done: &str, bad: &[String]) {
    eprintln!("{what}: {total} cases, {} {done}", total - bad.len());
    let first = &bad[..bad.len().min(20)];
    assert!(
        bad.is_empty(),
        "{what}: {} not {done}:\n{}",
        bad.len(),
        first.join("\n")
    );
}

/// Compiles the cases and fails unless each is accepted (`expect_ok`) or rejected.
pub fn expect(what: &str, cases: &[Case], expect_ok: bool, per_shader: usize) {
    let verb = if expect_ok { "accepted" } else { "rejected" };
    report(
        what,
        cases.len(),
        verb,
        &check(cases, expect_ok, per_shader),
    );
}

/// Compiles the cases and fails unless each is rejected with its `want` text among
/// its errors.
pub fn expect_errors(what: &str, cases: &[Case], want: &[String], per_shader: usize) {
    let bad: Vec<String> = compile(cases, per_shader)
        .iter()
        .zip(cases.iter().zip(want))
        .filter(|((ok, log), (_, w))| *ok != Some(false) || !log.contains(w.as_str()))
        .map(|((_, log), (c, w))| {
            let (v, s) = (c.version.directive(), c.stage);
            format!("{v} {s:?}: {}\n    want {w}\n    got {log}", c.line)
        })
        .collect();
    report(what, cases.len(), "with the expected error", &bad);
}

/// Turns a case whose line assigns a value to a variable of type `Z` into a check that
/// Mesa names the value's type `ty`: declares `struct Z`, which nothing converts to,
/// and returns the error Mesa must give.
pub fn names_type(mut case: Case, ty: &impl std::fmt::Display) -> (Case, String) {
    case.globals.push("struct Z { float z; };".into());
    let want = format!("initializer of type {ty} cannot be assigned to variable of type Z");
    (case, want)
}
