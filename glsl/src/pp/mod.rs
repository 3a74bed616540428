//! The preprocessor (GLSL 3.30 spec, section 3.3; Mesa's glcpp is the reference for
//! what is accepted and how errors read).
//!
//! Design: [`crate::lex::scan`] cuts the source into lines of tokens; this module walks
//! the lines once, keeping a stack of conditional groups, running directives and
//! expanding macros ([`macros`]) on text lines, and hands every surviving token to
//! [`crate::lex::classify`] with the position Mesa's compiler would give it. That
//! position follows glcpp's output, which the compiler re-lexes: within a line each
//! token's column counts one space for every run of blanks or comment before it, lines
//! keep their numbers (directive and skipped lines stay as empty lines), a block
//! comment's newlines come after its line, and a macro call spanning lines moves the
//! line's text down to the line where the call ends. The preprocessor's own errors use
//! the columns as written.
//!
//! Limits (so no input can make it run long or grow without bound): the conditional
//! stack is at most [`MAX_NESTING`] deep, all macro expansions together may produce at
//! most [`macros::EXPANSION_BUDGET`] tokens, argument pre-expansion nests at most 64
//! deep, and a macro call spans at most [`MAX_CALL_LINES`] lines (a longer one is
//! reported as running into the end of the file).

pub mod expr;
pub mod macros;

use crate::diag::{Log, Pos};
use crate::lex::{classify, scan, split_number, PpKind, PpTok, RawLine, Tok, Token};
use macros::{Macro, Stop};
use std::collections::HashMap;

/// The deepest nesting of `#if` groups.
pub const MAX_NESTING: usize = 256;

/// The most lines a function-like macro's arguments may span (each further line makes
/// the line's expansion run again, so this bounds the work to linear).
pub const MAX_CALL_LINES: usize = 256;

/// The GLSL versions this front end compiles.
pub const VERSIONS: [u32; 6] = [110, 120, 130, 140, 150, 330];

/// The extensions `#extension` knows (others are warned about, or an error with
/// `require`, as in Mesa).
pub const EXTENSIONS: &[&str] = &[
    "GL_ARB_texture_rectangle",
    "GL_ARB_explicit_attrib_location",
    "GL_ARB_uniform_buffer_object",
    "GL_ARB_draw_buffers",
    "GL_ARB_shader_texture_lod",
    "GL_ARB_separate_shader_objects",
    "GL_ARB_fragment_coord_conventions",
    "GL_ARB_draw_instanced",
    "GL_EXT_texture_array",
    "GL_EXT_gpu_shader4",
    "GL_ARB_shader_bit_encoding",
    "GL_ARB_texture_multisample",
];

/// The `#version` line's profile.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Profile {
    /// No profile was named (core from 1.50 on).
    #[default]
    None,
    /// `core`.
    Core,
    /// `compatibility`.
    Compatibility,
}

/// One `#extension` directive.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Extension {
    /// The extension's name (or `all`).
    pub name: String,
    /// `require`, `enable`, `warn` or `disable`.
    pub behavior: String,
    /// Where the directive's name is.
    pub pos: Pos,
}

/// What the preprocessor hands the parser.
#[derive(Clone, Debug, Default)]
pub struct Output {
    /// The `#version` (110 when there is none).
    pub version: u32,
    /// The `#version`'s profile.
    pub profile: Profile,
    /// The tokens, ending with [`Tok::Eof`].
    pub tokens: Vec<Token>,
    /// The `#extension` directives in order.
    pub extensions: Vec<Extension>,
    /// The `#pragma` lines' text.
    pub pragmas: Vec<String>,
}

/// An error already written to the log.
#[derive(Debug)]
pub struct PpError;

#[derive(Clone, Copy, Debug)]
struct Cond {
    /// Where "Unterminated #if" is reported.
    pos: Pos,
    /// The enclosing group is being kept.
    parent: bool,
    /// This branch is being kept.
    taking: bool,
    /// Some branch of this group was kept.
    done: bool,
    /// `#else` was seen.
    else_seen: bool,
}

/// The preprocessor's state while it walks the lines.
pub struct Pp<'a> {
    log: &'a mut Log,
    stage: &'a str,
    macros: HashMap<String, Macro>,
    conds: Vec<Cond>,
    budget: usize,
    out: Output,
    /// Reported line minus scanned line (changed by `#line`).
    line_delta: i64,
    source: u32,
    out_line: u32,
    eof: Pos,
    seen_content: bool,
    version_seen: bool,
    /// Expanding a `#if` line (`defined`'s operand stays unexpanded).
    in_if: bool,
}

fn is_punct(t: Option<&PpTok>, p: &str) -> bool {
    t.is_some_and(|t| t.kind == PpKind::Punct && t.text == p)
}

/// The conditional directive glcpp's lexer finds in a line of a skipped group: after
/// a `#` anywhere in the line it passes over everything up to a directive's name, and
/// takes the line if that is `if`, `ifdef`, `ifndef`, `elif`, `else` or `endif` (so
/// `x #endif`, `# # endif` and `#out ifdef X` count too, `#error … #if` does not).
/// The line is returned as `# NAME rest…`.
fn skipped_conditional(line: &RawLine) -> Option<RawLine> {
    let toks = &line.toks;
    let hash = toks.iter().position(|t| is_punct(Some(t), "#"))?;
    let name = hash
        + 1
        + toks[hash + 1..].iter().position(|t| {
            t.kind == PpKind::Ident && directive::DIRECTIVES.contains(&t.text.as_str())
        })?;
    if !matches!(
        toks[name].text.as_str(),
        "if" | "ifdef" | "ifndef" | "elif" | "else" | "endif"
    ) {
        return None;
    }
    let mut rest = line.clone();
    rest.toks = std::iter::once(toks[hash].clone())
        .chain(toks[name..].iter().cloned())
        .collect();
    Some(rest)
}

/// Preprocesses `src` for a shader of stage `stage` (`vertex`, `fragment`, `geometry`,
/// as Mesa's messages name it), writing errors into `log`.
pub fn preprocess(src: &str, stage: &str, log: &mut Log) -> Output {
    let lines = scan(src, log);
    let mut pp = Pp {
        log,
        stage,
        macros: HashMap::new(),
        conds: Vec::new(),
        budget: macros::EXPANSION_BUDGET,
        out: Output {
            version: 110,
            ..Output::default()
        },
        line_delta: 0,
        source: 0,
        out_line: 1,
        eof: Pos::new(1, 1),
        seen_content: false,
        version_seen: false,
        in_if: false,
    };
    pp.run(&lines);
    if let Some(c) = pp.conds.last() {
        let pos = c.pos;
        pp.log.pp_error(pos, "Unterminated #if\n");
    }
    let eof = pp.eof;
    pp.out.tokens.push(Token {
        tok: Tok::Eof,
        pos: eof,
        error: None,
    });
    pp.out
}

impl Pp<'_> {
    /// A scanned position as the preprocessor reports it (after `#line`).
    fn rpos(&self, p: Pos) -> Pos {
        Pos {
            source: self.source,
            line: (i64::from(p.line) + self.line_delta).clamp(0, u32::MAX as i64) as u32,
            col: p.col,
        }
    }

    fn taking(&self) -> bool {
        self.conds.last().is_none_or(|c| c.taking)
    }

    /// `__LINE__`, `__FILE__`, `__VERSION__` and the profile macros.
    fn builtin_macro(&self, t: &PpTok) -> Option<String> {
        let v = self.out.version;
        let core = v >= 150 && self.out.profile != Profile::Compatibility;
        match t.text.as_str() {
            "__LINE__" => Some(self.rpos(t.pos).line.to_string()),
            "__FILE__" => Some(self.source.to_string()),
            "__VERSION__" => Some(v.to_string()),
            "GL_core_profile" if core => Some("1".into()),
            "GL_compatibility_profile" if self.out.profile == Profile::Compatibility => {
                Some("1".into())
            }
            "GL_FRAGMENT_PRECISION_HIGH" if v >= 130 => Some("1".into()),
            n if EXTENSIONS.contains(&n) => Some("1".into()),
            _ => None,
        }
    }

    /// Whether `t` names a macro for `defined` (`__LINE__` and `__FILE__` are not macros
    /// for Mesa).
    fn defined(&self, t: &PpTok) -> bool {
        self.macros.contains_key(&t.text)
            || (self.builtin_macro(t).is_some() && t.text != "__LINE__" && t.text != "__FILE__")
    }

    fn run(&mut self, lines: &[RawLine]) {
        let mut i = 0;
        while i < lines.len() {
            let line = &lines[i];
            i += 1;
            if !self.taking() {
                if let Some(rest) = skipped_conditional(line) {
                    self.directive(&rest);
                }
                self.end_line(1 + line.extra_newlines, 1);
                continue;
            }
            if is_punct(line.toks.first(), "#") {
                self.directive(line);
                self.end_line(1 + line.extra_newlines, 1);
                continue;
            }
            if line.toks.is_empty() {
                self.end_line(1 + line.extra_newlines, 1);
                continue;
            }
            self.seen_content = true;
            let mut toks = line.toks.clone();
            let mut after = line.extra_newlines;
            let mut joined = 0;
            let mut end = line.end;
            loop {
                match self.expand(toks.clone()) {
                    Ok(v) => {
                        let col = self.emit(&v);
                        self.end_line(1 + after, col);
                        break;
                    }
                    Err(Stop::NeedMore)
                        if i < lines.len()
                            && joined < MAX_CALL_LINES
                            && !is_punct(lines[i].toks.first(), "#") =>
                    {
                        joined += 1;
                        let next = &lines[i];
                        i += 1;
                        after += 1 + next.extra_newlines;
                        end = next.end;
                        let start = toks.len();
                        toks.extend(next.toks.iter().cloned());
                        if let Some(t) = toks.get_mut(start) {
                            t.space = true;
                        }
                    }
                    Err(Stop::NeedMore) => {
                        // The call runs into a directive (glcpp stops at its `#`) or
                        // the end of the text.
                        let (pos, what) = match lines.get(i).and_then(|l| l.toks.first()) {
                            Some(h) if joined < MAX_CALL_LINES => (h.pos, "HASH_TOKEN"),
                            _ => (end, "end of file"),
                        };
                        let pos = self.rpos(pos);
                        self.log
                            .pp_error(pos, format!("syntax error, unexpected {what}"));
                        self.end_line(1 + after, 1);
                        break;
                    }
                    Err(Stop::Failed) => {
                        self.end_line(1 + after, 1);
                        break;
                    }
                }
            }
        }
    }

    /// Ends an output line whose text ended before column `col`.
    fn end_line(&mut self, newlines: u32, col: u32) {
        self.eof = Pos {
            source: self.source,
            line: self.out_line,
            col,
        };
        self.out_line = self.out_line.saturating_add(newlines);
    }

    /// Classifies one token for the compiler, keeping the lexer's error with it.
    fn push_token(&mut self, t: &PpTok, pos: Pos) {
        let mut lexer_log = Log::default();
        let tok = classify(t, self.out.version, pos, &mut lexer_log);
        let error = lexer_log.messages.into_iter().next().map(|m| m.text);
        self.out.tokens.push(Token { tok, pos, error });
    }

    /// Emits one output line's tokens; returns the column after the last.
    fn emit(&mut self, toks: &[PpTok]) -> u32 {
        let mut col = 1u32;
        for t in toks {
            if t.space {
                col = col.saturating_add(1);
            }
            let pos = Pos {
                source: self.source,
                line: self.out_line,
                col,
            };
            if t.kind == PpKind::Punct && t.text == "#" {
                let name = expr::glcpp_name(Some(t));
                let at = self.rpos(t.pos);
                self.log
                    .pp_error(at, format!("syntax error, unexpected {name}"));
            }
            if t.kind == PpKind::Number {
                for (off, len, kind) in split_number(&t.text) {
                    let piece = PpTok {
                        kind,
                        text: t.text[off..off + len].to_string(),
                        pos: t.pos,
                        space: false,
                    };
                    let at = Pos {
                        col: pos.col.saturating_add(off as u32),
                        ..pos
                    };
                    self.push_token(&piece, at);
                }
            } else {
                self.push_token(t, pos);
            }
            col = col.saturating_add(t.text.len() as u32);
        }
        col
    }
}

mod directive;
