//! The lexer: source text into preprocessing tokens, and preprocessing tokens into the
//! language's tokens for one GLSL version.
//!
//! Two lexers, as in Mesa, where glcpp writes its tokens' text out and the compiler's
//! lexer reads it again. [`scan`] cuts the source as glcpp does: a number is a
//! preprocessing number (`[.]?[0-9]([._a-zA-Z0-9]|[eEpP][-+])*`), an integer when one
//! of glcpp's integer patterns covers all of it and a [`PpKind::Number`] otherwise, so
//! that macros, `##` and `#if` see what glcpp sees. When the preprocessor hands the
//! tokens on, [`split_number`] cuts each such number with the compiler's rules (longest
//! of decimal `[1-9][0-9]*`, octal `0[0-7]*`, hex `0x…`, with a `u`, `l` or `ul`
//! suffix, and floats with `f` or `lf`), so `09` is `0` then `9` and `0x` is `0` then
//! `x`, as Mesa reads them. Before scanning, line continuations are removed and the
//! newlines they held are put back after the next newline (Mesa's
//! `remove_line_continuations`), and a block comment's newlines are likewise counted and
//! emitted after its line, so later lines keep their numbers.
//!
//! Words become keywords, basic type names, reserved words (an error) or identifiers by
//! the tables in [`classify`], measured against Mesa 22.3 for each version.

use crate::diag::{Log, Pos};

mod token;
pub use token::*;

/// What a preprocessing token is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PpKind {
    /// A word.
    Ident,
    /// An integer literal (decimal, octal or hex, maybe with `u`).
    Int,
    /// A floating-point literal (only in the pieces of a [`PpKind::Number`]).
    Float,
    /// A preprocessing number that is not one of glcpp's integers (`1.5`, `0x`,
    /// `3flat`): the compiler's lexer cuts it up again ([`split_number`]).
    Number,
    /// An operator or punctuator, `#` and `##` included.
    Punct,
    /// A character that starts no token (`@`, `$`, `"`, `\`, non-ASCII bytes).
    Other,
}

/// A preprocessing token with its position in the source as written.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PpTok {
    /// The kind.
    pub kind: PpKind,
    /// The text as written.
    pub text: String,
    /// Where it starts (after continuation removal), 1-based.
    pub pos: Pos,
    /// True when blanks or a comment came before it on its line.
    pub space: bool,
}

/// One source line, cut into tokens.
#[derive(Clone, Debug, Default)]
pub struct RawLine {
    /// The tokens of the line.
    pub toks: Vec<PpTok>,
    /// The position of the newline ending it (or of the end of the text).
    pub end: Pos,
    /// Newlines inside block comments and continuations, emitted after this line.
    pub extra_newlines: u32,
}

/// The operators and punctuators, longest first where one is a prefix of another.
pub(crate) const PUNCTS: [&str; 47] = [
    "<<=", ">>=", "++", "--", "<<", ">>", "<=", ">=", "==", "!=", "&&", "||", "^^", "*=", "/=",
    "+=", "-=", "%=", "&=", "^=", "|=", "##", "(", ")", "[", "]", "{", "}", ".", ",", ":", ";",
    "=", "+", "-", "!", "~", "*", "/", "%", "<", ">", "|", "^", "&", "?", "#",
];

/// Removes line continuations, putting their newlines back after the next newline.
fn join_continuations(src: &str) -> Vec<u8> {
    let b = src.as_bytes();
    let mut out = Vec::with_capacity(b.len());
    let mut pending = 0usize;
    let mut i = 0;
    while i < b.len() {
        if b[i] == b'\\' && b.get(i + 1) == Some(&b'\n') {
            pending += 1;
            i += 2;
            continue;
        }
        if b[i] == b'\\' && b.get(i + 1) == Some(&b'\r') && b.get(i + 2) == Some(&b'\n') {
            pending += 1;
            i += 3;
            continue;
        }
        out.push(b[i]);
        if b[i] == b'\n' {
            out.extend(std::iter::repeat_n(b'\n', pending));
            pending = 0;
        }
        i += 1;
    }
    out
}

fn digits(b: &[u8], i: usize, f: fn(u8) -> bool) -> usize {
    b[i.min(b.len())..].iter().take_while(|&&c| f(c)).count()
}

fn exponent(b: &[u8], i: usize) -> usize {
    if !matches!(b.get(i), Some(b'e' | b'E')) {
        return 0;
    }
    let sign = usize::from(matches!(b.get(i + 1), Some(b'+' | b'-')));
    let d = digits(b, i + 1 + sign, |c| c.is_ascii_digit());
    if d == 0 {
        0
    } else {
        1 + sign + d
    }
}

/// The length and kind of the number at `b[i]` (a digit, or `.` and a digit).
fn number(b: &[u8], i: usize) -> (usize, PpKind) {
    let suffix = |at: usize, set: &[u8]| usize::from(b.get(at).is_some_and(|c| set.contains(c)));
    // Mesa's integer suffixes: `u`, `l` (64-bit), `ul`; its float ones: `f`, `lf`.
    let int_suffix = |at: usize| match (b.get(at), b.get(at + 1)) {
        (Some(b'u'), Some(b'l')) | (Some(b'U'), Some(b'L')) => 2,
        (Some(b'u' | b'U' | b'l' | b'L'), _) => 1,
        _ => 0,
    };
    let float_suffix = |at: usize| match (b.get(at), b.get(at + 1)) {
        (Some(b'l'), Some(b'f')) | (Some(b'L'), Some(b'F')) => 2,
        _ => suffix(at, b"fF"),
    };
    let mut best = (0, PpKind::Int);
    if b[i] == b'.' {
        let f = digits(b, i + 1, |c| c.is_ascii_digit());
        let mut n = 1 + f;
        n += exponent(b, i + n);
        n += float_suffix(i + n);
        return (n, PpKind::Float);
    }
    let d = digits(b, i, |c| c.is_ascii_digit());
    if b[i] == b'0' && matches!(b.get(i + 1), Some(b'x' | b'X')) {
        let h = digits(b, i + 2, |c| c.is_ascii_hexdigit());
        if h > 0 {
            let n = 2 + h;
            best = (n + int_suffix(i + n), PpKind::Int);
        }
    }
    let int = if b[i] == b'0' {
        1 + digits(b, i + 1, |c| (b'0'..=b'7').contains(&c))
    } else {
        d
    };
    let int = int + int_suffix(i + int);
    if int > best.0 {
        best = (int, PpKind::Int);
    }
    let mut float = 0;
    if b.get(i + d) == Some(&b'.') {
        let f = digits(b, i + d + 1, |c| c.is_ascii_digit());
        float = d + 1 + f;
        float += exponent(b, i + float);
    } else {
        let e = exponent(b, i + d);
        if e > 0 {
            float = d + e;
        }
    }
    if float > 0 {
        float += float_suffix(i + float);
        if float > best.0 {
            best = (float, PpKind::Float);
        }
    }
    best
}

/// The length and kind of glcpp's preprocessing number at `b[i]`:
/// `[.]?[0-9]([._a-zA-Z0-9]|[eEpP][-+])*`, an integer (`INTEGER_STRING`) when one of
/// the integer patterns (decimal, octal, hex, with an optional `u`) covers all of it.
fn pp_number(b: &[u8], i: usize) -> (usize, PpKind) {
    let mut n = usize::from(b[i] == b'.') + 1;
    while let Some(&c) = b.get(i + n) {
        if matches!(c, b'e' | b'E' | b'p' | b'P') && matches!(b.get(i + n + 1), Some(b'+' | b'-')) {
            n += 2;
        } else if c.is_ascii_alphanumeric() || c == b'_' || c == b'.' {
            n += 1;
        } else {
            break;
        }
    }
    let t = &b[i..i + n];
    let body = t
        .strip_suffix(b"u")
        .or_else(|| t.strip_suffix(b"U"))
        .unwrap_or(t);
    let int = match body {
        [b'0', b'x' | b'X', hex @ ..] => !hex.is_empty() && hex.iter().all(u8::is_ascii_hexdigit),
        [b'0', oct @ ..] => oct.iter().all(|c| (b'0'..=b'7').contains(c)),
        [b'1'..=b'9', dec @ ..] => dec.iter().all(u8::is_ascii_digit),
        _ => false,
    };
    (n, if int { PpKind::Int } else { PpKind::Number })
}

/// Cuts a preprocessing number into the compiler's tokens (Mesa's lexer reads glcpp's
/// output again): the offset, length and kind of each piece, in order.
pub fn split_number(text: &str) -> Vec<(usize, usize, PpKind)> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        let (n, kind) =
            if c.is_ascii_digit() || (c == b'.' && b.get(i + 1).is_some_and(u8::is_ascii_digit)) {
                number(b, i)
            } else if c.is_ascii_alphabetic() || c == b'_' {
                (
                    digits(b, i, |c| c.is_ascii_alphanumeric() || c == b'_'),
                    PpKind::Ident,
                )
            } else {
                (1, PpKind::Punct)
            };
        let n = n.max(1);
        out.push((i, n, kind));
        i += n;
    }
    out
}

/// Cuts `src` into lines of preprocessing tokens. An unterminated block comment is an
/// error (Mesa's "Unterminated comment").
pub fn scan(src: &str, log: &mut Log) -> Vec<RawLine> {
    let b = join_continuations(src);
    let mut lines = Vec::new();
    let mut cur = RawLine::default();
    let (mut line, mut col) = (1u32, 1u32);
    let mut space = false;
    let mut i = 0;
    while i < b.len() {
        let c = b[i];
        let pos = Pos::new(line, col);
        if c == b'\n' {
            cur.end = pos;
            lines.push(std::mem::take(&mut cur));
            line += 1;
            col = 1;
            i += 1;
            space = false;
            continue;
        }
        if matches!(c, b' ' | b'\t' | b'\r' | 0x0b | 0x0c) {
            space = true;
            i += 1;
            col += 1;
            continue;
        }
        if c == b'/' && b.get(i + 1) == Some(&b'/') {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
                col += 1;
            }
            space = true;
            continue;
        }
        if c == b'/' && b.get(i + 1) == Some(&b'*') {
            i += 2;
            col += 2;
            let mut chunk = Pos::new(line, col);
            loop {
                if i >= b.len() {
                    log.pp_error(chunk, "Unterminated comment");
                    cur.end = Pos::new(line, col);
                    lines.push(cur);
                    return lines;
                }
                if b[i] == b'*' && b.get(i + 1) == Some(&b'/') {
                    i += 2;
                    col += 2;
                    break;
                }
                if b[i] == b'\n' {
                    cur.extra_newlines += 1;
                    line += 1;
                    col = 1;
                } else {
                    if i == 0 || b[i - 1] == b'\n' || (b[i] == b'*') != (b[i - 1] == b'*') {
                        chunk = Pos::new(line, col);
                    }
                    col += 1;
                }
                i += 1;
            }
            space = true;
            continue;
        }
        let (n, kind) = if c.is_ascii_alphabetic() || c == b'_' {
            (
                digits(&b, i, |c| c.is_ascii_alphanumeric() || c == b'_'),
                PpKind::Ident,
            )
        } else if c.is_ascii_digit() || (c == b'.' && b.get(i + 1).is_some_and(u8::is_ascii_digit))
        {
            pp_number(&b, i)
        } else if let Some(p) = PUNCTS.iter().find(|p| b[i..].starts_with(p.as_bytes())) {
            (p.len(), PpKind::Punct)
        } else {
            (1, PpKind::Other)
        };
        cur.toks.push(PpTok {
            kind,
            text: String::from_utf8_lossy(&b[i..i + n]).into_owned(),
            pos,
            space,
        });
        space = false;
        i += n;
        col += n as u32;
    }
    if !cur.toks.is_empty() || cur.extra_newlines > 0 || lines.is_empty() {
        cur.end = Pos::new(line, col);
        lines.push(cur);
    }
    lines
}
