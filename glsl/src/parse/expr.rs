//! Expressions: assignment, `?:` and `,` by recursive descent, the binary operators by
//! precedence climbing over [`BINOPS`], then prefix operators, postfix operators
//! (`[]`, `.`, `++`, `--`, method calls) and primaries (names, literals, calls and
//! constructors, parentheses).

use super::{PResult, Parser};
use crate::ast::{Callee, Expr, ExprKind, UnOp, ASSIGNOPS, BINOPS};
use crate::diag::Pos;
use crate::lex::{Tok, Word};

impl Parser<'_> {
    /// `expression`: assignments separated by commas.
    pub fn expression(&mut self) -> PResult<Expr> {
        let mut e = self.assignment()?;
        while self.is(",") {
            self.bump();
            let r = self.assignment()?;
            let pos = e.pos;
            e = Expr {
                kind: ExprKind::Comma(Box::new(e), Box::new(r)),
                pos,
            };
        }
        Ok(e)
    }

    /// `assignment_expression`: a unary expression and an assignment operator, or a
    /// conditional expression.
    pub fn assignment(&mut self) -> PResult<Expr> {
        self.enter()?;
        let r = self.assignment_inner();
        self.leave();
        r
    }

    fn assignment_inner(&mut self) -> PResult<Expr> {
        let start = self.pos();
        let lhs = self.unary()?;
        let op = match self.peek() {
            Tok::Punct(p) => ASSIGNOPS.iter().find(|(t, _)| t == p),
            _ => None,
        };
        if let Some(&(_, op)) = op {
            self.bump();
            let rhs = self.assignment()?;
            let pos = start;
            return Ok(Expr {
                kind: ExprKind::Assign(op, Box::new(lhs), Box::new(rhs)),
                pos,
            });
        }
        let b = self.binary_from(lhs, start, 1)?;
        self.ternary_from(b, start)
    }

    /// `conditional_expression` (what array sizes and layout values are).
    pub fn conditional(&mut self) -> PResult<Expr> {
        self.enter()?;
        let start = self.pos();
        let r = self.unary().and_then(|u| self.binary_from(u, start, 1));
        let r = r.and_then(|b| self.ternary_from(b, start));
        self.leave();
        r
    }

    fn ternary_from(&mut self, c: Expr, start: Pos) -> PResult<Expr> {
        if !self.is("?") {
            return Ok(c);
        }
        self.bump();
        let a = self.expression()?;
        self.expect(":")?;
        let b = self.assignment()?;
        let pos = start;
        Ok(Expr {
            kind: ExprKind::Ternary(Box::new(c), Box::new(a), Box::new(b)),
            pos,
        })
    }

    fn binary_from(&mut self, mut lhs: Expr, start: Pos, min: u8) -> PResult<Expr> {
        loop {
            let found = match self.peek() {
                Tok::Punct(p) => BINOPS.iter().find(|(t, prec, _)| t == p && *prec >= min),
                _ => None,
            };
            let Some(&(_, prec, op)) = found else {
                return Ok(lhs);
            };
            self.bump();
            let rstart = self.pos();
            let u = self.unary()?;
            let rhs = self.binary_from(u, rstart, prec + 1)?;
            let pos = start;
            lhs = Expr {
                kind: ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)),
                pos,
            };
        }
    }

    /// `unary_expression`.
    pub fn unary(&mut self) -> PResult<Expr> {
        let op = match self.peek() {
            Tok::Punct("+") => Some(UnOp::Plus),
            Tok::Punct("-") => Some(UnOp::Neg),
            Tok::Punct("!") => Some(UnOp::Not),
            Tok::Punct("~") => Some(UnOp::BitNot),
            Tok::Punct("++") => Some(UnOp::PreInc),
            Tok::Punct("--") => Some(UnOp::PreDec),
            _ => None,
        };
        let Some(op) = op else {
            let start = self.pos();
            let p = self.primary()?;
            return self.postfix(p, start);
        };
        let pos = self.bump().pos;
        self.enter()?;
        let e = self.unary();
        self.leave();
        Ok(Expr {
            kind: ExprKind::Unary(op, Box::new(e?)),
            pos,
        })
    }

    fn postfix(&mut self, mut e: Expr, pos: Pos) -> PResult<Expr> {
        loop {
            let kind = match self.peek() {
                Tok::Punct("[") => {
                    self.bump();
                    let i = self.expression()?;
                    self.expect("]")?;
                    ExprKind::Index(Box::new(e), Box::new(i))
                }
                Tok::Punct(".") => {
                    self.bump();
                    let (name, _) = self.ident()?;
                    if self.is("(") {
                        let args = self.call_args()?;
                        ExprKind::Method(Box::new(e), name, args)
                    } else {
                        ExprKind::Field(Box::new(e), name)
                    }
                }
                Tok::Punct("++") => {
                    self.bump();
                    ExprKind::Unary(UnOp::PostInc, Box::new(e))
                }
                Tok::Punct("(") => {
                    let args = self.call_args()?;
                    ExprKind::Call(Callee::Expr(Box::new(e)), args)
                }
                Tok::Punct("--") => {
                    self.bump();
                    ExprKind::Unary(UnOp::PostDec, Box::new(e))
                }
                _ => return Ok(e),
            };
            e = Expr { kind, pos };
        }
    }

    /// `( args )` of a call; `(void)` and `()` give no arguments.
    fn call_args(&mut self) -> PResult<Vec<Expr>> {
        self.expect("(")?;
        let mut args = Vec::new();
        if self.is_word(Word::Void) && self.is_at(1, ")") {
            self.bump();
        } else if !self.is(")") {
            args.push(self.assignment()?);
            while self.is(",") {
                self.bump();
                args.push(self.assignment()?);
            }
        }
        self.expect(")")?;
        Ok(args)
    }

    fn primary(&mut self) -> PResult<Expr> {
        let pos = self.pos();
        let kind = match self.peek() {
            Tok::Int(v) => ExprKind::Int(*v),
            Tok::Uint(v) => ExprKind::Uint(*v),
            Tok::Int64(v) => ExprKind::Int64(*v),
            Tok::Uint64(v) => ExprKind::Uint64(*v),
            Tok::Float(v) => ExprKind::Float(*v),
            Tok::Bool(v) => ExprKind::Bool(*v),
            Tok::Punct("(") => {
                self.bump();
                let e = self.expression()?;
                self.expect(")")?;
                return Ok(e);
            }
            Tok::Ident(n) if !self.types.contains(n) => {
                self.bump();
                let kind = if self.is("(") {
                    ExprKind::Call(Callee::Name(n.clone()), self.call_args()?)
                } else {
                    ExprKind::Ident(n.clone())
                };
                return Ok(Expr { kind, pos });
            }
            Tok::Ident(_) | Tok::Type(_) | Tok::Word(Word::Void | Word::Struct) => {
                let spec = self.type_spec()?;
                if !self.is("(") {
                    return self.fail();
                }
                let args = self.call_args()?;
                ExprKind::Call(Callee::Type(spec), args)
            }
            _ => return self.fail(),
        };
        if !matches!(kind, ExprKind::Call(..)) {
            self.bump();
        }
        Ok(Expr { kind, pos })
    }
}
