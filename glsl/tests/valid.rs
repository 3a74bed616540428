//! The valid corpus (`tests/corpus/valid`): realistic shaders of every version that
//! Mesa accepts. We must accept each, and the tree printed back as GLSL must be
//! accepted by Mesa too and parse to the same tree (compared by its printed text).

mod common;
mod mesa;

use mesa::{run, Context, Job};
use softgl_glsl::ast::print;
use softgl_glsl::{parse_with_log, Stage};

fn job(stage: Stage, src: &str) -> Job<'_> {
    match stage {
        Stage::Vertex => Job::Vertex(src),
        _ => Job::Fragment(src),
    }
}

/// A 3.3 core context compiles `#version 150` and `330` without `compatibility`.
fn core_too(src: &str) -> bool {
    (src.contains("#version 150") || src.contains("#version 330")) && !src.contains("compatibility")
}

#[test]
fn valid_corpus_parses_and_round_trips() {
    let corpus = common::corpus("valid");
    assert!(corpus.len() >= 25, "corpus has {} shaders", corpus.len());
    let mut printed = Vec::new();
    let mut versions = std::collections::BTreeMap::new();
    for (name, stage, src) in &corpus {
        let (tree, log) = parse_with_log(&[src], *stage);
        let tree = tree.unwrap_or_else(|| panic!("{name} rejected:\n{log}"));
        *versions.entry(tree.version).or_insert(0) += 1;
        let text = print::shader(&tree);
        let (again, log2) = parse_with_log(&[&text], *stage);
        let again = again.unwrap_or_else(|| panic!("{name} printed is rejected:\n{log2}\n{text}"));
        assert_eq!(
            print::shader(&again),
            text,
            "{name}: the round trip changed the tree"
        );
        assert_eq!(again.items.len(), tree.items.len(), "{name}");
        printed.push(text);
    }
    for ctx in [Context::Compat, Context::Core33] {
        let mut jobs = Vec::new();
        let mut names = Vec::new();
        for ((name, stage, src), text) in corpus.iter().zip(&printed) {
            if ctx == Context::Core33 && !core_too(src) {
                continue;
            }
            jobs.push(job(*stage, src));
            jobs.push(job(*stage, text));
            names.push(name.as_str());
        }
        let out = run(ctx, &jobs);
        for (i, name) in names.iter().enumerate() {
            assert!(
                out[2 * i].ok,
                "{ctx:?}: Mesa rejects {name}: {}",
                out[2 * i].log
            );
            assert!(
                out[2 * i + 1].ok,
                "{ctx:?}: Mesa rejects {name} as we print it: {}\n{}",
                out[2 * i + 1].log,
                printed[corpus.iter().position(|c| c.0 == *name).unwrap()]
            );
        }
        println!(
            "{ctx:?}: Mesa accepts {} shaders and their printed trees",
            names.len()
        );
    }
    println!("{} valid shaders by version: {versions:?}", corpus.len());
}
