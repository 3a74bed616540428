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

/// Compiles the cases, prints `what` with the number of cases and of outcomes as
/// expected (`expect_ok`: accepted, else rejected), and fails listing the first 40
/// cases that came out otherwise.
pub fn expect(what: &str, cases: &[Case], expect_ok: bool, per_shader: usize) {
    let bad = check(cases, expect_ok, per_shader);
    let verb = if expect_ok { "accepted" } else { "rejected" };
    eprintln!(
        "{what}: {} cases, {} {verb}",
        cases.len(),
        cases.len() - bad.len()
    );
    assert!(
        bad.is_empty(),
        "{what}: {} not {verb}:\n{}",
        bad.len(),
        bad[..bad.len().min(40)].join("\n")
    );
}

/// Compiles the cases, each of which must be rejected with its `want` text in its
/// errors; prints `what` with the counts and fails listing the first 20 that were not.
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
    eprintln!(
        "{what}: {} cases, {} with the expected error",
        cases.len(),
        cases.len() - bad.len()
    );
    assert!(
        bad.is_empty(),
        "{what}:\n{}",
        bad[..bad.len().min(20)].join("\n")
    );
}
