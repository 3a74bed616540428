//! The reference compiler for the tests: Mesa's GLSL compiler, run through OSMesa by the
//! C program `mesa_ref.c` beside this file (built here on first use with `cc -lOSMesa`;
//! `scripts/ensure-deps.sh` installs Debian's `libosmesa6-dev`).
//!
//! Every shader of one [`run`] call goes through one process and one context, so a
//! corpus of hundreds of shaders costs a fraction of a second.
#![allow(dead_code)]

use std::io::{BufRead, BufReader, Read, Write};
use std::path::PathBuf;
use std::process::{Command, Stdio};
use std::sync::OnceLock;

/// The context the shaders are compiled in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Context {
    /// A compatibility profile context (Mesa's llvmpipe gives its highest compatibility
    /// version, so `#version` alone decides the language: 1.10 to 1.30 and beyond).
    Compat,
    /// A 3.3 core profile context (`#version 150` and `330`, core rules).
    Core33,
}

/// One record sent to Mesa.
#[derive(Clone, Copy, Debug)]
pub enum Job<'a> {
    /// Compile a vertex shader.
    Vertex(&'a str),
    /// Compile a fragment shader.
    Fragment(&'a str),
    /// Link the shaders compiled since the previous link (failed ones included).
    Link,
}

/// What Mesa said about one record.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Outcome {
    /// The compile (or link) status.
    pub ok: bool,
    /// The info log, as `glGet*InfoLog` returned it.
    pub log: String,
}

fn binary() -> &'static PathBuf {
    static BIN: OnceLock<PathBuf> = OnceLock::new();
    BIN.get_or_init(|| {
        let dir = PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
        let out = dir.join("mesa_ref");
        let src = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("tests/mesa/mesa_ref.c");
        let cc = std::env::var("CC").unwrap_or_else(|_| "cc".into());
        let status = Command::new(cc)
            .args(["-O1", "-o"])
            .arg(&out)
            .arg(&src)
            .arg("-lOSMesa")
            .status()
            .expect("run the C compiler");
        assert!(
            status.success(),
            "building mesa_ref.c failed (is libosmesa6-dev installed?)"
        );
        out
    })
}

/// Runs `jobs` through Mesa in one context of kind `ctx`, in order.
pub fn run(ctx: Context, jobs: &[Job<'_>]) -> Vec<Outcome> {
    let args: &[&str] = match ctx {
        Context::Compat => &["compat", "3", "0"],
        Context::Core33 => &["core", "3", "3"],
    };
    let mut child = Command::new(binary())
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .expect("start mesa_ref");
    let mut input = Vec::new();
    for j in jobs {
        let (stage, src) = match j {
            Job::Vertex(s) => ("vert", *s),
            Job::Fragment(s) => ("frag", *s),
            Job::Link => ("link", ""),
        };
        input.extend_from_slice(format!("{stage} {}\n", src.len()).as_bytes());
        input.extend_from_slice(src.as_bytes());
    }
    let mut stdin = child.stdin.take().unwrap();
    let writer = std::thread::spawn(move || stdin.write_all(&input));
    let mut out = BufReader::new(child.stdout.take().unwrap());
    let mut outcomes = Vec::with_capacity(jobs.len());
    for _ in jobs {
        let mut head = String::new();
        out.read_line(&mut head).expect("read mesa_ref");
        let mut it = head.split_whitespace();
        let ok = it.next().expect("mesa_ref answered") == "1";
        let n: usize = it.next().unwrap().parse().unwrap();
        let mut log = vec![0; n + 1];
        out.read_exact(&mut log).unwrap();
        log.pop();
        outcomes.push(Outcome {
            ok,
            log: String::from_utf8_lossy(&log).into_owned(),
        });
    }
    writer.join().unwrap().unwrap();
    assert!(child.wait().unwrap().success(), "mesa_ref failed");
    outcomes
}

/// Mesa's verdict on each case (name, stage, source): accepted, and the info log. A
/// `#version 150` or `330` shader without `compatibility` goes to a 3.3 core context,
/// the others to a compatibility one.
pub fn verdicts(cases: &[(String, softgl_glsl::Stage, String)]) -> Vec<(bool, String)> {
    let core = |s: &str| {
        (s.contains("#version 150") || s.contains("#version 330")) && !s.contains("compatibility")
    };
    let mut out = vec![(false, String::new()); cases.len()];
    for ctx in [Context::Compat, Context::Core33] {
        let idx: Vec<usize> = (0..cases.len())
            .filter(|i| core(&cases[*i].2) == (ctx == Context::Core33))
            .collect();
        let jobs: Vec<Job> = idx
            .iter()
            .map(|i| match cases[*i].1 {
                softgl_glsl::Stage::Vertex => Job::Vertex(&cases[*i].2),
                _ => Job::Fragment(&cases[*i].2),
            })
            .collect();
        for (i, o) in idx.iter().zip(run(ctx, &jobs)) {
            out[*i] = (o.ok, o.log);
        }
    }
    out
}
