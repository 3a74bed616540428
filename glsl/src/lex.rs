//! The lexer: source text into preprocessing tokens, and preprocessing tokens into the
//! language's tokens for one GLSL version.
//!
//! One scanner serves both stages, as in Mesa where glcpp passes its tokens' text on to
//! the compiler's lexer: numbers are scanned with the language's own rules (longest of
//! decimal `[1-9][0-9]*`, octal `0[0-7]*`, hex `0x…`, each with an optional `u`, and
//! floats with an optional `f`), so `09` is the two tokens `0` and `9` and `0x` is `0`
//! then `x`, as Mesa reads them. Before scanning, line continuations are removed and the
//! newlines they held are put back after the next newline (Mesa's
//! `remove_line_continuations`), and a block comment's newlines are likewise counted and
//! emitted after its line, so later lines keep their numbers.
//!
//! Words become keywords, basic type names, reserved words (an error) or identifiers by
//! the tables in [`classify`], measured against Mesa 22.3 for each version.

use crate::diag::{Log, Pos};

/// What a preprocessing token is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PpKind {
    /// A word.
    Ident,
    /// An integer literal (decimal, octal or hex, maybe with `u`).
    Int,
    /// A floating-point literal.
    Float,
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

const PUNCTS: [&str; 47] = [
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
            number(&b, i)
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

/// A keyword of the language (each is its own token in Mesa's grammar).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[allow(missing_docs)]
pub enum Word {
    Attribute,
    Const,
    Uniform,
    Varying,
    Layout,
    Centroid,
    Flat,
    Smooth,
    Noperspective,
    Invariant,
    Break,
    Continue,
    Do,
    For,
    While,
    Switch,
    Case,
    Default,
    If,
    Else,
    In,
    Out,
    Inout,
    Void,
    Discard,
    Return,
    Struct,
    Precision,
    Lowp,
    Mediump,
    Highp,
    RowMajor,
    Packed,
}

impl Word {
    /// The word as written.
    pub fn text(self) -> &'static str {
        use Word::*;
        match self {
            Attribute => "attribute",
            Const => "const",
            Uniform => "uniform",
            Varying => "varying",
            Layout => "layout",
            Centroid => "centroid",
            Flat => "flat",
            Smooth => "smooth",
            Noperspective => "noperspective",
            Invariant => "invariant",
            Break => "break",
            Continue => "continue",
            Do => "do",
            For => "for",
            While => "while",
            Switch => "switch",
            Case => "case",
            Default => "default",
            If => "if",
            Else => "else",
            In => "in",
            Out => "out",
            Inout => "inout",
            Void => "void",
            Discard => "discard",
            Return => "return",
            Struct => "struct",
            Precision => "precision",
            Lowp => "lowp",
            Mediump => "mediump",
            Highp => "highp",
            RowMajor => "row_major",
            Packed => "packed",
        }
    }

    /// The token's name in Mesa's grammar, as its syntax errors print it.
    pub fn mesa_name(self) -> &'static str {
        use Word::*;
        match self {
            Const => "CONST_TOK",
            Layout => "LAYOUT_TOK",
            In => "IN_TOK",
            Out => "OUT_TOK",
            Inout => "INOUT_TOK",
            Void => "VOID_TOK",
            Packed => "PACKED_TOK",
            Attribute => "ATTRIBUTE",
            Uniform => "UNIFORM",
            Varying => "VARYING",
            Centroid => "CENTROID",
            Flat => "FLAT",
            Smooth => "SMOOTH",
            Noperspective => "NOPERSPECTIVE",
            Invariant => "INVARIANT",
            Break => "BREAK",
            Continue => "CONTINUE",
            Do => "DO",
            For => "FOR",
            While => "WHILE",
            Switch => "SWITCH",
            Case => "CASE",
            Default => "DEFAULT",
            If => "IF",
            Else => "ELSE",
            Discard => "DISCARD",
            Return => "RETURN",
            Struct => "STRUCT",
            Precision => "PRECISION",
            Lowp => "LOWP",
            Mediump => "MEDIUMP",
            Highp => "HIGHP",
            RowMajor => "ROW_MAJOR",
        }
    }
}

/// A token of the language.
#[derive(Clone, Debug, PartialEq)]
pub enum Tok {
    /// A name that is no keyword in this version.
    Ident(String),
    /// A keyword.
    Word(Word),
    /// A basic type's name (`float`, `mat4x3`, `sampler2D`, …).
    Type(String),
    /// A signed integer literal (its value wrapped to 32 bits).
    Int(u32),
    /// An unsigned integer literal (`u` suffix).
    Uint(u32),
    /// A 64-bit integer literal (`l` suffix; Mesa lexes it in every version).
    Int64(u64),
    /// A 64-bit unsigned integer literal (`ul` suffix).
    Uint64(u64),
    /// A floating-point literal.
    Float(f64),
    /// `true` or `false`.
    Bool(bool),
    /// An operator or punctuator.
    Punct(&'static str),
    /// A reserved word (already reported) or a double literal (`1.0lf`): Mesa's
    /// `ERROR_TOK`.
    Reserved(String),
    /// A character that starts no token (Mesa's "invalid token").
    Invalid(String),
    /// The end of the text.
    Eof,
}

/// A language token and where Mesa's compiler would report it.
#[derive(Clone, Debug, PartialEq)]
pub struct Token {
    /// The token.
    pub tok: Tok,
    /// Its position in the preprocessed text.
    pub pos: Pos,
    /// The lexer's error about it (a reserved word, a literal out of range). Mesa's
    /// lexer reports it when the parser reads the token, so it is logged only if the
    /// parse gets that far.
    pub error: Option<String>,
}

/// The basic type names and the first version that has each (as Mesa lexes them).
const TYPES: &[(&str, u32)] = &[
    ("float", 110),
    ("int", 110),
    ("bool", 110),
    ("vec2", 110),
    ("vec3", 110),
    ("vec4", 110),
    ("ivec2", 110),
    ("ivec3", 110),
    ("ivec4", 110),
    ("bvec2", 110),
    ("bvec3", 110),
    ("bvec4", 110),
    ("mat2", 110),
    ("mat3", 110),
    ("mat4", 110),
    ("sampler1D", 110),
    ("sampler2D", 110),
    ("sampler3D", 110),
    ("samplerCube", 110),
    ("sampler1DShadow", 110),
    ("sampler2DShadow", 110),
    ("sampler2DRect", 110),
    ("sampler2DRectShadow", 110),
    ("mat2x2", 120),
    ("mat2x3", 120),
    ("mat2x4", 120),
    ("mat3x2", 120),
    ("mat3x3", 120),
    ("mat3x4", 120),
    ("mat4x2", 120),
    ("mat4x3", 120),
    ("mat4x4", 120),
    ("uint", 130),
    ("uvec2", 130),
    ("uvec3", 130),
    ("uvec4", 130),
    ("double", 130),
    ("samplerCubeShadow", 130),
    ("sampler1DArray", 130),
    ("sampler2DArray", 130),
    ("sampler1DArrayShadow", 130),
    ("sampler2DArrayShadow", 130),
    ("isampler1D", 130),
    ("isampler2D", 130),
    ("isampler3D", 130),
    ("isamplerCube", 130),
    ("isampler1DArray", 130),
    ("isampler2DArray", 130),
    ("usampler1D", 130),
    ("usampler2D", 130),
    ("usampler3D", 130),
    ("usamplerCube", 130),
    ("usampler1DArray", 130),
    ("usampler2DArray", 130),
    ("isampler2DRect", 140),
    ("usampler2DRect", 140),
    ("samplerBuffer", 140),
    ("isamplerBuffer", 140),
    ("usamplerBuffer", 140),
    ("sampler2DMS", 150),
    ("isampler2DMS", 150),
    ("usampler2DMS", 150),
    ("sampler2DMSArray", 150),
    ("isampler2DMSArray", 150),
    ("usampler2DMSArray", 150),
];

/// Words reserved in every version.
const RESERVED: &[&str] = &[
    "volatile",
    "asm",
    "class",
    "union",
    "enum",
    "typedef",
    "template",
    "this",
    "goto",
    "inline",
    "noinline",
    "public",
    "static",
    "extern",
    "external",
    "interface",
    "long",
    "short",
    "half",
    "fixed",
    "unsigned",
    "input",
    "output",
    "hvec2",
    "hvec3",
    "hvec4",
    "fvec2",
    "fvec3",
    "fvec4",
    "sampler3DRect",
    "sizeof",
    "cast",
    "namespace",
    "using",
    "dvec2",
    "dvec3",
    "dvec4",
    "dmat2",
    "dmat3",
    "dmat4",
    "dmat2x2",
    "dmat2x3",
    "dmat2x4",
    "dmat3x2",
    "dmat3x3",
    "dmat3x4",
    "dmat4x2",
    "dmat4x3",
    "dmat4x4",
];

/// Words reserved from 1.30 on.
const RESERVED_130: &[&str] = &[
    "common",
    "partition",
    "active",
    "superp",
    "filter",
    "image1D",
    "image2D",
    "image3D",
    "imageCube",
    "iimage1D",
    "iimage2D",
    "iimage3D",
    "iimageCube",
    "uimage1D",
    "uimage2D",
    "uimage3D",
    "uimageCube",
    "image1DArray",
    "image2DArray",
    "iimage1DArray",
    "iimage2DArray",
    "uimage1DArray",
    "uimage2DArray",
    "imageBuffer",
    "iimageBuffer",
    "uimageBuffer",
    "image2DMS",
    "iimage2DMS",
    "uimage2DMS",
    "image2DMSArray",
    "iimage2DMSArray",
    "uimage2DMSArray",
];

fn keyword(w: &str, version: u32) -> Option<Word> {
    use Word::*;
    let (word, since) = match w {
        "attribute" => (Attribute, 110),
        "const" => (Const, 110),
        "uniform" => (Uniform, 110),
        "varying" => (Varying, 110),
        "break" => (Break, 110),
        "continue" => (Continue, 110),
        "do" => (Do, 110),
        "for" => (For, 110),
        "while" => (While, 110),
        "if" => (If, 110),
        "else" => (Else, 110),
        "in" => (In, 110),
        "out" => (Out, 110),
        "inout" => (Inout, 110),
        "void" => (Void, 110),
        "discard" => (Discard, 110),
        "return" => (Return, 110),
        "struct" => (Struct, 110),
        "centroid" => (Centroid, 120),
        "invariant" => (Invariant, 120),
        "flat" => (Flat, 130),
        "smooth" => (Smooth, 130),
        "noperspective" => (Noperspective, 130),
        "switch" => (Switch, 130),
        "case" => (Case, 130),
        "default" => (Default, 130),
        "precision" => (Precision, 130),
        "lowp" => (Lowp, 130),
        "mediump" => (Mediump, 130),
        "highp" => (Highp, 130),
        "layout" => (Layout, 140),
        "row_major" => (RowMajor, 140),
        "packed" => (Packed, 140),
        _ => return None,
    };
    (version >= since).then_some(word)
}

fn reserved(w: &str, version: u32) -> bool {
    RESERVED.contains(&w)
        || (version >= 130 && RESERVED_130.contains(&w))
        || (version < 130 && matches!(w, "switch" | "default"))
        || (version < 140 && w == "packed")
        || (version == 120 && matches!(w, "lowp" | "mediump" | "highp" | "precision"))
        || (version == 130 && matches!(w, "samplerBuffer" | "row_major"))
}

/// Parses an integer literal's text: its value (`None` beyond 64 bits), whether it is
/// unsigned (`u`) and whether it is 64-bit (`l`).
pub fn int_literal(text: &str) -> (Option<u64>, bool, bool) {
    let t = text.trim_end_matches(['u', 'U', 'l', 'L']);
    let suffix = &text[t.len()..];
    let unsigned = suffix.contains(['u', 'U']);
    let long = suffix.contains(['l', 'L']);
    let v = if let Some(h) = t.strip_prefix("0x").or_else(|| t.strip_prefix("0X")) {
        u64::from_str_radix(h, 16)
    } else if t.len() > 1 && t.starts_with('0') {
        u64::from_str_radix(&t[1..], 8)
    } else {
        t.parse::<u64>()
    };
    (v.ok(), unsigned, long)
}

/// Parses a 32-bit integer literal's text into its value (`None` when it exceeds 32
/// bits) and whether it has the `u` suffix.
pub fn int_value(text: &str) -> (Option<u32>, bool) {
    let (v, unsigned, _) = int_literal(text);
    (v.and_then(|v| u32::try_from(v).ok()), unsigned)
}

/// Turns a preprocessing token into the language token of `version`, reporting reserved
/// words and out-of-range literals into `log` at `pos`.
pub fn classify(t: &PpTok, version: u32, pos: Pos, log: &mut Log) -> Tok {
    match t.kind {
        PpKind::Ident => {
            let w = t.text.as_str();
            if w == "true" || w == "false" {
                return Tok::Bool(w == "true");
            }
            if let Some(k) = keyword(w, version) {
                return Tok::Word(k);
            }
            if TYPES.iter().any(|&(n, v)| n == w && version >= v) {
                return Tok::Type(t.text.clone());
            }
            if reserved(w, version) {
                log.error(pos, format!("illegal use of reserved word `{w}'"));
                return Tok::Reserved(t.text.clone());
            }
            Tok::Ident(t.text.clone())
        }
        PpKind::Int if int_literal(&t.text).2 => match int_literal(&t.text) {
            (Some(v), false, _) => Tok::Int64(v),
            (Some(v), true, _) => Tok::Uint64(v),
            (None, ..) => {
                log.error(pos, format!("literal value `{}' out of range", t.text));
                Tok::Int64(u64::MAX)
            }
        },
        PpKind::Float if t.text.ends_with("lf") || t.text.ends_with("LF") => {
            Tok::Reserved(t.text.clone())
        }
        PpKind::Int => match int_value(&t.text) {
            (Some(v), false) => Tok::Int(v),
            (Some(v), true) => Tok::Uint(v),
            (None, u) => {
                log.error(pos, format!("literal value `{}' out of range", t.text));
                if u {
                    Tok::Uint(u32::MAX)
                } else {
                    Tok::Int(u32::MAX)
                }
            }
        },
        PpKind::Float => Tok::Float(
            t.text
                .trim_end_matches(['f', 'F'])
                .parse::<f64>()
                .unwrap_or(0.0),
        ),
        PpKind::Punct => match PUNCTS.iter().find(|p| **p == t.text) {
            Some(p) if *p != "#" && *p != "##" => Tok::Punct(p),
            _ => Tok::Invalid(t.text.clone()),
        },
        PpKind::Other => Tok::Invalid(t.text.clone()),
    }
}

/// How Mesa's syntax errors name a token (`NEW_IDENTIFIER`, `'}'`, `ADD_ASSIGN`, …).
/// `known` says whether an identifier names something declared (`IDENTIFIER`) and
/// `is_type` whether it names a struct (`TYPE_IDENTIFIER`).
pub fn mesa_name(t: &Tok, known: bool, is_type: bool) -> String {
    match t {
        Tok::Ident(_) if is_type => "TYPE_IDENTIFIER".into(),
        Tok::Ident(_) if known => "IDENTIFIER".into(),
        Tok::Ident(_) => "NEW_IDENTIFIER".into(),
        Tok::Word(w) => w.mesa_name().into(),
        Tok::Type(_) => "BASIC_TYPE_TOK".into(),
        Tok::Int(_) => "INTCONSTANT".into(),
        Tok::Uint(_) => "UINTCONSTANT".into(),
        Tok::Int64(_) => "INT64CONSTANT".into(),
        Tok::Uint64(_) => "UINT64CONSTANT".into(),
        Tok::Float(_) => "FLOATCONSTANT".into(),
        Tok::Bool(_) => "BOOLCONSTANT".into(),
        Tok::Reserved(_) => "ERROR_TOK".into(),
        Tok::Invalid(_) => "invalid token".into(),
        Tok::Eof => "end of file".into(),
        Tok::Punct(p) => match *p {
            "<<=" => "LEFT_ASSIGN",
            ">>=" => "RIGHT_ASSIGN",
            "++" => "INC_OP",
            "--" => "DEC_OP",
            "<<" => "LEFT_OP",
            ">>" => "RIGHT_OP",
            "<=" => "LE_OP",
            ">=" => "GE_OP",
            "==" => "EQ_OP",
            "!=" => "NE_OP",
            "&&" => "AND_OP",
            "||" => "OR_OP",
            "^^" => "XOR_OP",
            "*=" => "MUL_ASSIGN",
            "/=" => "DIV_ASSIGN",
            "+=" => "ADD_ASSIGN",
            "-=" => "SUB_ASSIGN",
            "%=" => "MOD_ASSIGN",
            "&=" => "AND_ASSIGN",
            "^=" => "XOR_ASSIGN",
            "|=" => "OR_ASSIGN",
            "." => "DOT_TOK",
            p => return format!("'{p}'"),
        }
        .into(),
    }
}
