//! Statements: compound, selection (`if`, `switch` with `case`/`default` labels),
//! iteration (`while`, `do`, `for` with a declaration), jumps, declarations and
//! expression statements.

use super::{PResult, Parser};
use crate::ast::{Condition, Decl, External, FullType, Stmt, StmtKind};
use crate::lex::{Tok, Word};

impl Parser<'_> {
    /// Statements up to and including the closing `}`.
    pub fn statements_until_brace(&mut self) -> PResult<Vec<Stmt>> {
        let mut body = Vec::new();
        while !self.is("}") {
            body.push(self.statement()?);
        }
        self.bump();
        Ok(body)
    }

    /// True when the statement here is a declaration: a qualifier, `precision`, or a
    /// type not followed by `(` (a constructor call) after its dimensions.
    fn at_declaration(&self) -> bool {
        if self.at_qualifier() || self.is_word(Word::Precision) || self.is_word(Word::Struct) {
            return true;
        }
        if !self.at_type(0) {
            return false;
        }
        let mut n = 1;
        let mut depth = 0usize;
        loop {
            match &self.tok_at(n).tok {
                Tok::Punct("[") => depth += 1,
                Tok::Punct("]") if depth > 0 => depth -= 1,
                Tok::Punct("(") if depth == 0 => return false,
                Tok::Eof => return true,
                _ if depth == 0 => return true,
                _ => {}
            }
            n += 1;
        }
    }

    fn decl_stmt(&mut self) -> PResult<Decl> {
        match self.declaration(false)? {
            External::Decl(d) => Ok(d),
            External::Function(_) => self.fail(),
        }
    }

    /// One statement.
    pub fn statement(&mut self) -> PResult<Stmt> {
        self.enter()?;
        let r = self.statement_inner();
        self.leave();
        r
    }

    fn paren_expr(&mut self) -> PResult<crate::ast::Expr> {
        self.expect("(")?;
        let e = self.expression()?;
        self.expect(")")?;
        Ok(e)
    }

    fn condition(&mut self) -> PResult<Condition> {
        if !self.at_declaration() {
            return Ok(Condition::Expr(self.expression()?));
        }
        let qualifiers = self.qualifiers()?;
        let spec = self.type_spec()?;
        let (name, pos) = self.ident()?;
        self.expect("=")?;
        let init = self.assignment()?;
        Ok(Condition::Decl {
            ty: FullType { qualifiers, spec },
            name,
            init,
            pos,
        })
    }

    fn statement_inner(&mut self) -> PResult<Stmt> {
        let pos = self.pos();
        let simple = |s: &mut Self, kind: StmtKind| -> PResult<StmtKind> {
            s.bump();
            s.expect(";")?;
            Ok(kind)
        };
        let kind = match self.peek() {
            Tok::Punct("{") => {
                self.bump();
                self.push_scope();
                let body = self.statements_until_brace();
                self.pop_scope();
                StmtKind::Compound(body?)
            }
            Tok::Punct(";") => {
                self.bump();
                StmtKind::Expr(None)
            }
            Tok::Word(Word::If) => {
                self.bump();
                let c = self.paren_expr()?;
                let then = self.statement()?;
                let els = if self.is_word(Word::Else) {
                    self.bump();
                    Some(Box::new(self.statement()?))
                } else {
                    None
                };
                StmtKind::If(c, Box::new(then), els)
            }
            Tok::Word(Word::Switch) => {
                self.bump();
                let e = self.paren_expr()?;
                self.expect("{")?;
                self.push_scope();
                let body = self.switch_body();
                self.pop_scope();
                StmtKind::Switch(e, body?)
            }
            Tok::Word(Word::While) => {
                self.bump();
                self.expect("(")?;
                let c = self.condition()?;
                self.expect(")")?;
                StmtKind::While(c, Box::new(self.statement()?))
            }
            Tok::Word(Word::Do) => {
                self.bump();
                let body = self.statement()?;
                if !self.is_word(Word::While) {
                    return self.fail();
                }
                self.bump();
                let c = self.paren_expr()?;
                self.expect(";")?;
                StmtKind::DoWhile(Box::new(body), c)
            }
            Tok::Word(Word::For) => self.for_stmt()?,
            Tok::Word(Word::Break) => simple(self, StmtKind::Break)?,
            Tok::Word(Word::Continue) => simple(self, StmtKind::Continue)?,
            Tok::Word(Word::Discard) => simple(self, StmtKind::Discard)?,
            Tok::Word(Word::Return) => {
                self.bump();
                let e = if self.is(";") {
                    None
                } else {
                    Some(self.expression()?)
                };
                self.expect(";")?;
                StmtKind::Return(e)
            }
            _ if self.at_declaration() => StmtKind::Decl(self.decl_stmt()?),
            _ => {
                let e = self.expression()?;
                self.expect(";")?;
                StmtKind::Expr(Some(e))
            }
        };
        Ok(Stmt { kind, pos })
    }

    /// A switch body after its `{`: groups of `case e:`/`default:` labels, each group
    /// followed by at least one statement (Mesa's `case_statement_list`).
    fn switch_body(&mut self) -> PResult<Vec<Stmt>> {
        let mut body = Vec::new();
        let mut after_label = false;
        loop {
            let pos = self.pos();
            let kind = match self.peek() {
                Tok::Punct("}") if !after_label => {
                    self.bump();
                    return Ok(body);
                }
                Tok::Word(Word::Case) => {
                    self.bump();
                    let e = self.expression()?;
                    self.expect(":")?;
                    StmtKind::Case(e)
                }
                Tok::Word(Word::Default) => {
                    self.bump();
                    self.expect(":")?;
                    StmtKind::Default
                }
                _ if body.is_empty() || matches!(self.peek(), Tok::Punct("}")) => {
                    return self.fail()
                }
                _ => {
                    after_label = false;
                    body.push(self.statement()?);
                    continue;
                }
            };
            after_label = true;
            body.push(Stmt { kind, pos });
        }
    }

    fn for_stmt(&mut self) -> PResult<StmtKind> {
        self.bump();
        self.expect("(")?;
        // No scope of its own for names: Mesa's parser still knows a `for` loop's
        // variable after the loop (it only changes how syntax errors name it).
        self.for_rest()
    }

    fn for_rest(&mut self) -> PResult<StmtKind> {
        let ipos = self.pos();
        let init = if self.is(";") {
            self.bump();
            StmtKind::Expr(None)
        } else if self.at_declaration() {
            StmtKind::Decl(self.decl_stmt()?)
        } else {
            let e = self.expression()?;
            self.expect(";")?;
            StmtKind::Expr(Some(e))
        };
        let cond = if self.is(";") {
            None
        } else {
            Some(self.condition()?)
        };
        self.expect(";")?;
        let step = if self.is(")") {
            None
        } else {
            Some(self.expression()?)
        };
        self.expect(")")?;
        let body = self.statement()?;
        Ok(StmtKind::For {
            init: Box::new(Stmt {
                kind: init,
                pos: ipos,
            }),
            cond,
            step,
            body: Box::new(body),
        })
    }
}
