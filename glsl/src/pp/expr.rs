//! `#if` and `#elif` expressions: `defined`, then macro expansion, then C's integer
//! operators evaluated in 64 bits with wrapping arithmetic, by precedence climbing.
//!
//! As in Mesa, a name left after expansion counts as 0, `?:` is not allowed, and a
//! syntax error names glcpp's token (`NEWLINE`, `IDENTIFIER`, `INTEGER_STRING`, …) at
//! the end of the line.

use crate::diag::Pos;
use crate::lex::{int_value, PpKind, PpTok};

/// How glcpp's grammar names a token in its syntax errors.
pub fn glcpp_name(t: Option<&PpTok>) -> String {
    let Some(t) = t else {
        return "NEWLINE".into();
    };
    match t.kind {
        PpKind::Ident if t.text == "defined" => "DEFINED".into(),
        PpKind::Ident => "IDENTIFIER".into(),
        PpKind::Int => "INTEGER_STRING".into(),
        PpKind::Float | PpKind::Number | PpKind::Other => "OTHER".into(),
        PpKind::Punct => match t.text.as_str() {
            "==" => "EQUAL",
            "!=" => "NOT_EQUAL",
            "<=" => "LESS_OR_EQUAL",
            ">=" => "GREATER_OR_EQUAL",
            "<<" => "LEFT_SHIFT",
            ">>" => "RIGHT_SHIFT",
            "&&" => "AND",
            "||" => "OR",
            "##" => "PASTE",
            "++" => "PLUS_PLUS",
            "--" => "MINUS_MINUS",
            "#" => "HASH_TOKEN",
            p if p.len() == 1 && "()[]{},+-*/%<>&^|!~=.;".contains(p) => return format!("'{p}'"),
            _ => "OTHER",
        }
        .into(),
    }
}

/// glcpp's operators of more than one character; the scanner's others (`+=`, `^^`,
/// `<<=`, …) are several tokens to glcpp.
const GLCPP_OPS: [&str; 11] = [
    "<<", ">>", "<=", ">=", "==", "!=", "&&", "||", "++", "--", "##",
];

/// Re-cuts a `#if` line's tokens as glcpp's lexer does: the operators it does not
/// have split into their characters.
pub fn glcpp_tokens(toks: Vec<PpTok>) -> Vec<PpTok> {
    let mut out: Vec<PpTok> = Vec::with_capacity(toks.len());
    for t in toks {
        if t.kind == PpKind::Punct && t.text.len() > 1 && !GLCPP_OPS.contains(&t.text.as_str()) {
            let mut rest = t.text.as_str();
            let mut col = t.pos.col;
            while !rest.is_empty() {
                let n = GLCPP_OPS
                    .iter()
                    .find(|o| rest.starts_with(*o))
                    .map_or(1, |o| o.len());
                let mut piece = t.clone();
                piece.text = rest[..n].to_string();
                piece.pos.col = col;
                piece.space = t.space && col == t.pos.col;
                out.push(piece);
                rest = &rest[n..];
                col += n as u32;
            }
            continue;
        }
        out.push(t);
    }
    out
}

/// An evaluation error: where and what.
pub type EvalError = (Pos, String);

/// Evaluates the expanded tokens of a `#if`; `end` is the position of the line's end.
/// Returns the value (`None` after a syntax error) and the first error. As in Mesa, a
/// division by zero is an error but the evaluation goes on with 0 for it, so
/// `1 || 1 / 0` still holds.
pub fn eval(toks: &[PpTok], end: Pos) -> (Option<i64>, Option<EvalError>) {
    let mut e = Eval {
        toks,
        i: 0,
        end,
        depth: 0,
        error: None,
    };
    let v = e.binary(0).and_then(|v| {
        if e.i < toks.len() {
            Err(e.unexpected())
        } else {
            Ok(v)
        }
    });
    match v {
        Ok(v) => (Some(v), e.error),
        Err(err) => (None, e.error.or(Some(err))),
    }
}

struct Eval<'a> {
    toks: &'a [PpTok],
    i: usize,
    end: Pos,
    depth: u32,
    /// The first division by zero.
    error: Option<EvalError>,
}

const LEVELS: &[&[&str]] = &[
    &["||"],
    &["&&"],
    &["|"],
    &["^"],
    &["&"],
    &["==", "!="],
    &["<", ">", "<=", ">="],
    &["<<", ">>"],
    &["+", "-"],
    &["*", "/", "%"],
];

impl Eval<'_> {
    fn peek(&self) -> Option<&PpTok> {
        self.toks.get(self.i)
    }

    /// glcpp parses a `#if` line after expanding it, so its syntax errors point at the
    /// line's end whichever token they name.
    fn unexpected(&self) -> EvalError {
        let t = self.peek();
        (
            self.end,
            format!("syntax error, unexpected {}", glcpp_name(t)),
        )
    }

    fn is_op(&self, op: &str) -> bool {
        self.peek()
            .is_some_and(|t| t.kind == PpKind::Punct && t.text == op)
    }

    fn binary(&mut self, level: usize) -> Result<i64, EvalError> {
        if level == LEVELS.len() {
            return self.unary(0);
        }
        let mut l = self.binary(level + 1)?;
        while let Some(op) = LEVELS[level].iter().find(|o| self.is_op(o)) {
            self.i += 1;
            let r = self.binary(level + 1)?;
            l = match *op {
                "||" => i64::from(l != 0 || r != 0),
                "&&" => i64::from(l != 0 && r != 0),
                "|" => l | r,
                "^" => l ^ r,
                "&" => l & r,
                "==" => i64::from(l == r),
                "!=" => i64::from(l != r),
                "<" => i64::from(l < r),
                ">" => i64::from(l > r),
                "<=" => i64::from(l <= r),
                ">=" => i64::from(l >= r),
                "<<" => l.wrapping_shl(r as u32),
                ">>" => l.wrapping_shr(r as u32),
                "+" => l.wrapping_add(r),
                "-" => l.wrapping_sub(r),
                "*" => l.wrapping_mul(r),
                "/" | "%" if r == 0 => {
                    let msg = if *op == "/" {
                        "division by 0 in preprocessor directive"
                    } else {
                        "zero modulus in preprocessor directive"
                    };
                    self.error.get_or_insert((self.end, msg.into()));
                    0
                }
                "/" => l.wrapping_div(r),
                _ => l.wrapping_rem(r),
            };
        }
        Ok(l)
    }

    fn unary(&mut self, depth: u32) -> Result<i64, EvalError> {
        if depth > 256 {
            return Err(self.unexpected());
        }
        let Some(t) = self.peek() else {
            return Err(self.unexpected());
        };
        match (t.kind, t.text.as_str()) {
            (PpKind::Punct, "+" | "-" | "~" | "!") => {
                let op = t.text.clone();
                self.i += 1;
                let v = self.unary(depth + 1)?;
                Ok(match op.as_str() {
                    "+" => v,
                    "-" => v.wrapping_neg(),
                    "~" => !v,
                    _ => i64::from(v == 0),
                })
            }
            (PpKind::Punct, "(") => {
                self.i += 1;
                self.depth += 1;
                if self.depth > 256 {
                    return Err(self.unexpected());
                }
                let v = self.binary(0)?;
                self.depth -= 1;
                if !self.is_op(")") {
                    return Err(self.unexpected());
                }
                self.i += 1;
                Ok(v)
            }
            (PpKind::Int, _) => {
                let v = int_value(&t.text).0.map_or(i64::MAX, i64::from);
                self.i += 1;
                Ok(v)
            }
            (PpKind::Ident, n) if n != "defined" => {
                self.i += 1;
                Ok(0)
            }
            _ => Err(self.unexpected()),
        }
    }
}
