//! softgl's GLSL front end: shading-language source in, checked program out, for
//! versions 1.10, 1.20, 1.30, 1.40, 1.50 and 3.30 (issue 43).
//!
//! The crate knows nothing of GL state or of the engine: it turns the source strings of
//! a shader into a typed syntax tree, or into an info log worded like Mesa's
//! (`0:LINE(COLUMN): error: ...`). softgl itself lowers the checked tree into the
//! engine's IR. It is its own crate so that it builds and tests in seconds, apart from
//! the rasterizer's long optimised build.
//!
//! The stages, each its own module, every arrow pointing down:
//! 1. the preprocessor (`#version`, macros, conditionals, `#extension`, `#line`);
//! 2. the lexer and the parser, into a syntax tree that keeps source positions;
//! 3. the type checker with each version's built-in functions and variables and its
//!    implicit conversions.
//!
//! Nothing here panics or loops without bound on any input: nesting depth, macro
//! expansion and source length are limited, and the tests feed random input.
//!
//! The reference for what is accepted and how errors read is Mesa's own compiler, run
//! by the integration tests through OSMesa (`tests/mesa/`).
//!
//! [`parse()`] runs stages 1 and 2: [`pp`] (with [`lex`]) and [`parse`](mod@parse) give
//! an [`ast::Shader`] or a [`Log`] whose first error has Mesa's line and wording
//! (`tests/errors.rs`, `tests/mutations.rs` measure it against Mesa).
//!
//! [`compile()`] runs all three: [`check`] turns the syntax tree into the typed tree of
//! [`hir`] (every expression typed, implicit conversions explicit, calls resolved to a
//! built-in signature or a user function, constants folded, l-values marked), or a log
//! whose first error is on Mesa's line, in Mesa's words for nearly all: `tests/check.rs`
//! (330 hand-written cases over 1.10 to 3.30: acceptance and line agree on all),
//! `tests/check_random.rs` (random well-typed expressions, their type-breaking mutants
//! and type mutations of the valid corpus, all compiled by Mesa too) measure it.

pub mod ast;
pub mod builtins;
pub mod check;
pub mod diag;
pub mod hir;
pub mod lex;
pub mod parse;
pub mod pp;
pub mod types;

pub use ast::{Shader, Stage};
pub use diag::Log;

/// The longest source (all strings together) the front end accepts, in bytes.
pub const MAX_SOURCE: usize = 1 << 24;

/// Preprocesses and parses the source strings of one shader (concatenated, as GL does)
/// into its syntax tree, with the info log (warnings, or the errors when the tree is
/// `None`).
pub fn parse_with_log(sources: &[&str], stage: Stage) -> (Option<Shader>, Log) {
    let mut log = Log::default();
    let total: usize = sources.iter().map(|s| s.len()).sum();
    if total > MAX_SOURCE {
        log.error(diag::Pos::new(1, 1), "shader source too long");
        return (None, log);
    }
    let src = sources.concat();
    let out = pp::preprocess(&src, stage.name(), &mut log);
    if log
        .messages
        .iter()
        .any(|m| m.preprocessor && m.severity == diag::Severity::Error)
    {
        return (None, log);
    }
    let mut parse_log = Log::default();
    let mut parser = parse::Parser::new(&out.tokens, stage, &mut parse_log);
    let items = parser.translation_unit();
    let furthest = parser.furthest();
    // The lexer's errors come as Mesa's lexer meets them: before the parser's, and
    // only for the tokens the parser reached.
    for t in out.tokens.iter().take(furthest + 1) {
        if let Some(e) = &t.error {
            log.error(t.pos, e.clone());
        }
    }
    log.messages.extend(parse_log.messages);
    match items {
        Ok(items) if !log.has_errors() => (
            Some(Shader {
                stage,
                version: out.version,
                profile: out.profile,
                extensions: out.extensions,
                pragmas: out.pragmas,
                items,
            }),
            log,
        ),
        _ => (None, log),
    }
}

/// Preprocesses and parses one shader; the error log when it has errors.
pub fn parse(sources: &[&str], stage: Stage) -> Result<Shader, Log> {
    match parse_with_log(sources, stage) {
        (Some(s), _) => Ok(s),
        (None, log) => Err(log),
    }
}

/// Preprocesses, parses and type-checks one shader into its checked tree
/// ([`hir::Program`]), with the info log (warnings, or the errors when there is no
/// tree).
pub fn compile_with_log(sources: &[&str], stage: Stage) -> (Option<hir::Program>, Log) {
    let (tree, mut log) = parse_with_log(sources, stage);
    let Some(tree) = tree else {
        return (None, log);
    };
    let program = check::check(&tree, &mut log);
    (program, log)
}

/// Preprocesses, parses and type-checks one shader; the error log when it has errors.
pub fn compile(sources: &[&str], stage: Stage) -> Result<hir::Program, Log> {
    match compile_with_log(sources, stage) {
        (Some(p), _) => Ok(p),
        (None, log) => Err(log),
    }
}
