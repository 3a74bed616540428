//! The directives: conditionals, `#define`/`#undef`, `#version`, `#extension`, `#line`,
//! `#error` and `#pragma`, with Mesa's messages.

use super::expr::{eval, glcpp_name};
use super::macros::{Macro, Stop};
use super::{Cond, Extension, Pp, Profile, EXTENSIONS, MAX_NESTING, VERSIONS};
use crate::diag::Pos;
use crate::lex::{int_value, PpKind, PpTok, RawLine};

/// The text of a directive's tokens with the blanks between them as written (a
/// comment counts as its width in blanks).
/// The directive names, longest first among those sharing a prefix.
pub(super) const DIRECTIVES: [&str; 13] = [
    "ifndef",
    "ifdef",
    "if",
    "elif",
    "else",
    "endif",
    "error",
    "extension",
    "pragma",
    "version",
    "define",
    "undef",
    "line",
];

fn text_of(toks: &[PpTok]) -> String {
    let mut s = String::new();
    let mut end: Option<Pos> = None;
    for t in toks {
        if let Some(e) = end {
            let gap = if t.pos.line == e.line && t.pos.col > e.col {
                (t.pos.col - e.col) as usize
            } else {
                usize::from(t.space)
            };
            s.extend(std::iter::repeat_n(' ', gap.min(256)));
        }
        s.push_str(&t.text);
        end = Some(Pos::new(t.pos.line, t.pos.col + t.text.len() as u32));
    }
    s
}

impl Pp<'_> {
    /// Runs the directive on `line` (whose first token is `#`).
    pub(super) fn directive(&mut self, line: &RawLine) {
        let hash = self.rpos(line.toks[0].pos);
        let toks = &line.toks[1..];
        let Some(name) = toks.first() else {
            return;
        };
        if name.kind != PpKind::Ident {
            // glcpp: one stray character after `#` is a syntax error at the line's
            // end; anything longer makes a non-directive.
            if self.taking() {
                if toks.len() == 1 && name.text.len() == 1 {
                    let at = self.rpos(line.end);
                    self.log.pp_error(at, "syntax error, unexpected NEWLINE");
                } else {
                    self.log.pp_error(hash, "Illegal non-directive after #");
                }
            }
            return;
        }
        // glcpp matches a directive's name as a prefix: `#defineX 1` defines X.
        let split;
        let (name, args) = match DIRECTIVES
            .iter()
            .find(|d| name.text.len() > d.len() && name.text.starts_with(*d))
            .filter(|_| !DIRECTIVES.contains(&name.text.as_str()))
        {
            Some(d) => {
                let mut head = name.clone();
                head.text = d.to_string();
                let mut tail = name.clone();
                tail.text = name.text[d.len()..].to_string();
                if tail.text.starts_with(|c: char| c.is_ascii_digit()) {
                    tail.kind = PpKind::Int;
                }
                tail.pos.col += d.len() as u32;
                tail.space = false;
                let rest: Vec<PpTok> = std::iter::once(tail)
                    .chain(toks[1..].iter().cloned())
                    .collect();
                split = (head, rest);
                (&split.0, &split.1[..])
            }
            None => (name, &toks[1..]),
        };
        let taking = self.taking();
        match name.text.as_str() {
            "if" | "ifdef" | "ifndef" => {
                if self.conds.len() >= MAX_NESTING {
                    self.log.pp_error(hash, "#if nesting too deep");
                    return;
                }
                let ok = if !taking {
                    false
                } else if name.text == "if" {
                    self.condition(args, line.end, hash, "#if")
                } else {
                    match args.first() {
                        Some(t) if t.kind == PpKind::Ident => {
                            if let Some(x) = args.get(1) {
                                let at = self.rpos(x.pos);
                                self.log.pp_error(at, "extra tokens at end of directive");
                            }
                            self.defined(t) == (name.text == "ifdef")
                        }
                        t => {
                            self.not_identifier(t, line.end);
                            false
                        }
                    }
                };
                // Where Mesa reports the group as unterminated.
                let pos = match (name.text.as_str(), args.first()) {
                    ("if", _) => self.rpos(line.end),
                    ("ifndef", Some(t)) => self.rpos(t.pos),
                    _ => hash,
                };
                self.conds.push(Cond {
                    pos,
                    parent: taking,
                    taking: ok,
                    done: ok,
                    else_seen: false,
                });
            }
            "elif" => {
                let Some(c) = self.conds.last().copied() else {
                    self.log.pp_error(hash, "#elif without #if\n");
                    return;
                };
                if c.else_seen {
                    self.log.pp_error(hash, "#elif after #else");
                    return;
                }
                let ok = if !c.parent || c.done {
                    if args.is_empty() {
                        self.log
                            .pp_warning(hash, "ignoring illegal #elif without expression");
                    }
                    false
                } else {
                    self.condition(args, line.end, hash, "#elif")
                };
                if let Some(c) = self.conds.last_mut() {
                    c.taking = ok;
                    c.done |= ok;
                }
            }
            // Trailing tokens: always an error after `#else`; after `#endif` only where
            // glcpp goes back to reading normally (the group's parent is kept), as Mesa
            // does.
            "else" | "endif"
                if (name.text == "else" || self.conds.last().is_some_and(|c| c.parent))
                    && self.extra_tokens(args, line.end) => {}
            "else" => {
                let Some(c) = self.conds.last_mut() else {
                    self.log.pp_error(hash, "#else without #if\n");
                    return;
                };
                if c.else_seen {
                    self.log.pp_error(hash, "multiple #else");
                    return;
                }
                c.else_seen = true;
                c.taking = c.parent && !c.done;
                c.done = true;
            }
            "endif" => {
                if self.conds.pop().is_none() {
                    self.log.pp_error(hash, "#endif without #if\n");
                }
            }
            _ if !taking => {}
            "define" => self.define(args, hash),
            "undef" if args.len() > 1 => {
                self.extra_tokens(&args[1..], line.end);
            }
            "undef" => match args.first() {
                Some(t) if t.kind == PpKind::Ident => {
                    if t.text.starts_with("GL_") {
                        self.log.pp_error(
                            hash,
                            "Built-in (pre-defined) names beginning with GL_ cannot be undefined.",
                        );
                    } else {
                        self.macros.remove(&t.text);
                    }
                }
                t => self.not_identifier(t, line.end),
            },
            "error" => {
                self.log.pp_error(hash, format!("#error {}", text_of(args)));
            }
            "pragma" => self.out.pragmas.push(text_of(args)),
            "extension" => self.extension(args, line.end),
            "version" => self.version(args, hash, line.end),
            "line" => {
                // glcpp takes `line` as the directive only when blanks follow it.
                let blank = line.end.col > name.pos.col + name.text.len() as u32;
                self.line(args, line.end, hash, blank)
            }
            // One character alone after `#` is a syntax error at the line's end.
            _ if toks.len() == 1 && name.text.len() == 1 => {
                let at = self.rpos(line.end);
                self.log.pp_error(at, "syntax error, unexpected NEWLINE");
            }
            _ => self.log.pp_error(hash, "Illegal non-directive after #"),
        }
        if taking && name.text != "version" {
            self.seen_content = true;
        }
    }

    /// Reports glcpp's syntax error for a directive whose name operand is `t` (or
    /// missing, at the line's end `end`).
    fn not_identifier(&mut self, t: Option<&PpTok>, end: Pos) {
        self.unexpected(t, end, "IDENTIFIER");
    }

    /// Reports glcpp's `syntax error, unexpected T, expecting WHAT` at `t` (or at the
    /// line's end `end` when `t` is missing).
    fn unexpected(&mut self, t: Option<&PpTok>, end: Pos, what: &str) {
        let at = self.rpos(t.map_or(end, |t| t.pos));
        let name = glcpp_name(t);
        self.log.pp_error(
            at,
            format!("syntax error, unexpected {name}, expecting {what}"),
        );
    }

    /// True (after reporting glcpp's error) when `extra` holds tokens a directive does
    /// not take.
    fn extra_tokens(&mut self, extra: &[PpTok], end: Pos) -> bool {
        if extra.is_empty() {
            return false;
        }
        self.unexpected(extra.first(), end, "NEWLINE");
        true
    }

    /// Evaluates a `#if`/`#elif` condition; errors count as false.
    fn condition(&mut self, args: &[PpTok], end: Pos, hash: Pos, what: &str) -> bool {
        if args.is_empty() {
            self.log
                .pp_error(hash, format!("{what} with no expression"));
            return false;
        }
        self.in_if = true;
        let expanded = self.expand(args.to_vec());
        self.in_if = false;
        let args = match expanded {
            Ok(t) => t,
            Err(Stop::NeedMore) => {
                let at = self.rpos(end);
                self.log.pp_error(at, "syntax error, unexpected NEWLINE");
                return false;
            }
            Err(Stop::Failed) => return false,
        };
        let mut toks = Vec::with_capacity(args.len());
        let mut i = 0;
        while i < args.len() {
            let t = &args[i];
            if t.kind == PpKind::Ident && t.text == "defined" {
                let paren = super::is_punct(args.get(i + 1), "(");
                let n = if paren { i + 2 } else { i + 1 };
                let name = args.get(n).filter(|a| a.kind == PpKind::Ident);
                let closed = !paren || super::is_punct(args.get(n + 1), ")");
                let Some(name) = name.filter(|n| closed && n.text != "defined") else {
                    let at = self.rpos(t.pos);
                    self.log
                        .pp_error(at, "\"defined\" not followed by an identifier");
                    return false;
                };
                let mut v = t.clone();
                v.kind = PpKind::Int;
                v.text = if self.defined(name) { "1" } else { "0" }.into();
                toks.push(v);
                i = n + 1 + usize::from(paren);
                continue;
            }
            toks.push(t.clone());
            i += 1;
        }
        let toks = super::expr::glcpp_tokens(toks);
        let (value, error) = eval(&toks, end);
        if let Some((pos, msg)) = error {
            let at = self.rpos(pos);
            self.log.pp_error(at, msg);
        }
        value.is_some_and(|v| v != 0)
    }

    fn define(&mut self, args: &[PpTok], hash: Pos) {
        let name = match args.first() {
            Some(t) if t.kind == PpKind::Ident => t,
            Some(t) => {
                // Mesa quotes the text up to the next blank.
                let word: String = std::iter::once(t)
                    .chain(args[1..].iter().take_while(|a| !a.space))
                    .map(|a| a.text.as_str())
                    .collect();
                let at = self.rpos(t.pos);
                self.log
                    .pp_error(at, format!("#define followed by a non-identifier: {word}"));
                return;
            }
            None => {
                self.log.pp_error(hash, "#define without macro name");
                return;
            }
        };
        let at = self.rpos(name.pos);
        if name.text == "defined" {
            self.log
                .pp_error(at, "\"defined\" cannot be used as a macro name");
            return;
        }
        if name.text.starts_with("GL_") {
            self.log
                .pp_error(at, "Macro names starting with \"GL_\" are reserved.\n");
            return;
        }
        let mut rest = &args[1..];
        let mut params = None;
        if super::is_punct(rest.first(), "(") && !rest[0].space {
            let mut ps: Vec<String> = Vec::new();
            let mut i = 1;
            loop {
                let t = rest.get(i);
                let expect = if ps.is_empty() && i == 1 {
                    if super::is_punct(t, ")") {
                        break;
                    }
                    "expecting IDENTIFIER or ')'"
                } else if super::is_punct(t, ")") {
                    break;
                } else if super::is_punct(t, ",") {
                    i += 1;
                    "expecting IDENTIFIER"
                } else {
                    "expecting ')' or ','"
                };
                match rest.get(i) {
                    Some(p) if p.kind == PpKind::Ident && !expect.contains("','") => {
                        if ps.contains(&p.text) {
                            self.log
                                .pp_error(at, format!("Duplicate macro parameter \"{}\"", p.text));
                            return;
                        }
                        ps.push(p.text.clone());
                        i += 1;
                    }
                    t => {
                        let pos = self.rpos(t.map_or(hash, |t| t.pos));
                        let what = glcpp_name(t);
                        self.log
                            .pp_error(pos, format!("syntax error, unexpected {what}, {expect}"));
                        return;
                    }
                }
            }
            rest = &rest[i + 1..];
            params = Some(ps);
        }
        if let Some(h) = rest
            .iter()
            .find(|t| t.kind == PpKind::Punct && t.text == "#")
        {
            let at = self.rpos(h.pos);
            self.log
                .pp_error(at, "syntax error, unexpected HASH_TOKEN, expecting NEWLINE");
            return;
        }
        let mut body = rest.to_vec();
        if let Some(b) = body.first_mut() {
            b.space = false;
        }
        let m = Macro { params, body };
        if let Some(old) = self.macros.get(&name.text) {
            if !old.same_as(&m) {
                self.log
                    .pp_error(at, format!("Redefinition of macro {}\n", name.text));
            }
            return;
        }
        self.macros.insert(name.text.clone(), m);
    }

    fn version(&mut self, args: &[PpTok], hash: Pos, end: Pos) {
        if self.seen_content || self.version_seen {
            self.log
                .pp_error(hash, "#version must appear on the first line");
            return;
        }
        self.version_seen = true;
        // glcpp's grammar: `#version INTEGER [IDENTIFIER] NEWLINE`.
        let args = &super::expr::glcpp_tokens(args.to_vec())[..];
        let Some(n) = args.first().filter(|t| t.kind == PpKind::Int) else {
            self.unexpected(args.first(), end, "INTEGER_STRING");
            return;
        };
        if args.get(1).is_some_and(|t| t.kind != PpKind::Ident) {
            self.unexpected(args.get(1), end, "IDENTIFIER or NEWLINE");
            return;
        }
        if args.len() > 2 {
            self.unexpected(args.get(2), end, "NEWLINE");
            return;
        }
        let at = self.rpos(n.pos);
        let v = int_value(&n.text).0.unwrap_or(0);
        if !VERSIONS.contains(&v) {
            self.log.error(
                at,
                format!(
                    "GLSL {}.{:02} is not supported. Supported versions are: 1.10, 1.20, \
                     1.30, 1.40, 1.50, and 3.30",
                    v / 100,
                    v % 100
                ),
            );
            self.out.version = if v > 330 { 330 } else { 110 };
        } else {
            self.out.version = v;
        }
        match args.get(1) {
            None => {}
            Some(_) if v < 150 => self.log.error(at, "illegal text following version number"),
            Some(p) if p.text == "core" && args.len() == 2 => self.out.profile = Profile::Core,
            Some(p) if p.text == "compatibility" && args.len() == 2 => {
                self.out.profile = Profile::Compatibility
            }
            Some(p) => self.log.error(
                at,
                format!(
                    "\"{}\" is not a valid shading language profile; if present, it must be \"core\"",
                    p.text
                ),
            ),
        }
    }

    fn extension(&mut self, args: &[PpTok], end: Pos) {
        // Mesa's compiler reads `#extension NAME : BEHAVIOR` in a lexer state where
        // every word is an IDENTIFIER and `:` is COLON.
        let want = |i: usize,
                    kind: PpKind,
                    text: Option<&str>,
                    what: &str|
         -> Result<(), (Pos, String)> {
            match args.get(i) {
                Some(t) if t.kind == kind && text.is_none_or(|x| x == t.text) => Ok(()),
                t => {
                    let name = match t {
                        None => "EOL".to_string(),
                        Some(t) if t.kind == PpKind::Ident => "IDENTIFIER".into(),
                        Some(t) if t.text == ":" => "COLON".into(),
                        Some(t) => crate::lex::mesa_name(
                            &crate::lex::classify(t, 330, t.pos, &mut crate::diag::Log::default()),
                            false,
                            false,
                        ),
                    };
                    Err((
                        t.map_or(end, |t| t.pos),
                        format!("syntax error, unexpected {name}{what}"),
                    ))
                }
            }
        };
        let check = want(0, PpKind::Ident, None, "")
            .and_then(|_| want(1, PpKind::Punct, Some(":"), ", expecting COLON"))
            .and_then(|_| want(2, PpKind::Ident, None, ""));
        if let Err((pos, msg)) = check {
            let at = self.rpos(pos);
            self.log.error(at, msg);
            return;
        }
        let (name, behavior) = (&args[0], &args[2]);
        let (npos, bpos) = (self.rpos(name.pos), self.rpos(behavior.pos));
        let b = behavior.text.as_str();
        if !matches!(b, "require" | "enable" | "warn" | "disable") {
            self.log
                .error(bpos, format!("unknown extension behavior `{b}'"));
            return;
        }
        if name.text == "all" {
            if b == "require" || b == "enable" {
                self.log.error(npos, format!("cannot {b} all extensions"));
            }
        } else if !EXTENSIONS.contains(&name.text.as_str()) {
            let msg = format!(
                "extension `{}' unsupported in {} shader",
                name.text, self.stage
            );
            if b == "require" {
                self.log.error(npos, msg);
            } else if b != "disable" {
                self.log.warning(npos, msg);
            }
        }
        self.out.extensions.push(Extension {
            name: name.text.clone(),
            behavior: b.into(),
            pos: npos,
        });
    }

    fn line(&mut self, args: &[PpTok], end: Pos, hash: Pos, blank: bool) {
        let toks = match self.expand(args.to_vec()) {
            Ok(t) => t,
            Err(_) => return,
        };
        let num = |t: Option<&PpTok>| {
            t.filter(|t| t.kind == PpKind::Int)
                .and_then(|t| int_value(&t.text).0)
        };
        let Some(line) = num(toks.first()) else {
            if toks.is_empty() && blank {
                let at = self.rpos(end);
                self.log.pp_error(at, "syntax error, unexpected NEWLINE");
            } else {
                self.log.pp_error(hash, "Illegal non-directive after #");
            }
            return;
        };
        let source = match toks.get(1) {
            None => self.source,
            Some(_) => match num(toks.get(1)) {
                Some(s) if toks.len() == 2 => s,
                _ => {
                    let at = self.rpos(end);
                    self.log.pp_error(at, "syntax error, unexpected NEWLINE");
                    return;
                }
            },
        };
        // The next scanned line (end.line + 1) is reported as `line`.
        self.line_delta = i64::from(line) - i64::from(end.line) - 1;
        self.source = source;
        self.out_line = line.saturating_sub(1);
    }
}
