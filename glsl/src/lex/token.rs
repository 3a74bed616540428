//! The language's tokens: keywords, basic type names and reserved words per version
//! (measured against Mesa 22.3), literals, and how Mesa's syntax errors name each.

use super::{PpKind, PpTok, PUNCTS};
use crate::diag::{Log, Pos};

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
        // The preprocessor splits these ([`super::split_number`]) before classifying.
        PpKind::Number | PpKind::Other => Tok::Invalid(t.text.clone()),
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
