//! Statements (GLSL chapter 6): scopes of compound statements and loops, conditions
//! that must be scalar `bool`, `break`/`continue` only where they have a target,
//! `discard` only in fragment shaders, `return` against the function's type (no
//! implicit conversion of the value: Mesa rejects `return 1;` in a float function),
//! and `switch` (from 1.30) on a scalar integer with constant, unique `case` labels of
//! the same type.

use super::{fold, Checker, Context};
use crate::ast::{self, Condition, StmtKind as S};
use crate::hir::{Expr, Stmt};
use crate::types::{Scalar, Type};

impl Checker<'_> {
    /// The statements of a block, in the current scope.
    pub(super) fn stmts(&mut self, body: &[ast::Stmt]) -> Vec<Stmt> {
        let mut out = Vec::new();
        for s in body {
            self.stmt(s, &mut out);
        }
        out
    }

    fn scoped(&mut self, s: &ast::Stmt) -> Stmt {
        self.push_scope();
        let mut v = Vec::new();
        self.stmt(s, &mut v);
        self.pop_scope();
        match v.len() {
            1 => v.pop().unwrap_or(Stmt::Block(Vec::new())),
            _ => Stmt::Block(v),
        }
    }

    fn bool_cond(&mut self, e: &ast::Expr, what: &str) -> Option<Expr> {
        let x = self.expr(e)?;
        if x.ty != Type::BOOL {
            self.error(e.pos, format!("{what} must be scalar boolean"));
            return None;
        }
        Some(x)
    }

    fn condition(&mut self, c: &Condition, out: &mut Vec<Stmt>) -> Option<Expr> {
        match c {
            Condition::Expr(e) => self.bool_cond(e, "loop condition"),
            Condition::Decl {
                ty,
                name,
                init,
                pos,
            } => {
                let q = self.quals(&ty.qualifiers, *pos)?;
                let t = self.resolve_type(&ty.spec, &[])?;
                let before = out.len();
                if !self.one_var(&q, t, (name, *pos, Some(init)), ty.spec.pos, out) {
                    return None;
                }
                let id = match out.get(before) {
                    Some(Stmt::Decl(id, _)) => *id,
                    _ => return None,
                };
                if self.vars[id].ty != Type::BOOL {
                    self.error(*pos, "loop condition must be scalar boolean");
                    return None;
                }
                Some(super::expr::node(
                    crate::hir::ExprKind::Var(id),
                    Type::BOOL,
                    *pos,
                ))
            }
        }
    }

    fn stmt(&mut self, s: &ast::Stmt, out: &mut Vec<Stmt>) {
        let pos = s.pos;
        match &s.kind {
            S::Decl(d) => self.decl(d, out),
            S::Expr(None) => {}
            S::Expr(Some(e)) => {
                if let Some(x) = self.expr(e) {
                    out.push(Stmt::Expr(x));
                }
            }
            S::Compound(v) => {
                self.push_scope();
                let b = self.stmts(v);
                self.pop_scope();
                out.push(Stmt::Block(b));
            }
            S::If(c, a, b) => {
                let c = self.bool_cond(c, "if-statement condition");
                let a = self.scoped(a);
                let b = b.as_ref().map(|b| Box::new(self.scoped(b)));
                if let Some(c) = c {
                    out.push(Stmt::If(c, Box::new(a), b));
                }
            }
            S::While(c, body) => {
                self.push_scope();
                let mut init = Vec::new();
                let c = self.condition(c, &mut init);
                let body = self.loop_body(body);
                self.pop_scope();
                if let Some(c) = c {
                    out.push(Stmt::Loop {
                        init: init.pop().map(Box::new),
                        cond: Some(c),
                        step: None,
                        body: Box::new(body),
                        test_last: false,
                    });
                }
            }
            S::DoWhile(body, c) => {
                let body = self.loop_body(body);
                if let Some(c) = self.bool_cond(c, "loop condition") {
                    out.push(Stmt::Loop {
                        init: None,
                        cond: Some(c),
                        step: None,
                        body: Box::new(body),
                        test_last: true,
                    });
                }
            }
            S::For {
                init,
                cond,
                step,
                body,
            } => {
                self.push_scope();
                let mut iv = Vec::new();
                self.stmt(init, &mut iv);
                let c = match cond {
                    Some(c) => self.condition(c, &mut iv),
                    None => None,
                };
                let st = step.as_ref().and_then(|e| self.expr(e));
                let body = self.loop_body(body);
                self.pop_scope();
                out.push(Stmt::Loop {
                    init: match iv.len() {
                        0 => None,
                        1 => iv.pop().map(Box::new),
                        _ => Some(Box::new(Stmt::Block(iv))),
                    },
                    cond: c,
                    step: st,
                    body: Box::new(body),
                    test_last: false,
                });
            }
            S::Break => {
                if self.ctx.loops == 0 && self.ctx.switches == 0 {
                    self.error(pos, "break may only appear in a loop or a switch");
                }
                out.push(Stmt::Break);
            }
            S::Continue => {
                if self.ctx.loops == 0 {
                    self.error(pos, "continue may only appear in a loop");
                }
                out.push(Stmt::Continue);
            }
            S::Discard => {
                if self.stage != crate::types::Stage::Fragment {
                    self.error(pos, "`discard' may only appear in a fragment shader");
                }
                out.push(Stmt::Discard);
            }
            S::Return(e) => self.ret(e.as_ref(), pos, out),
            S::Switch(e, body) => self.switch(e, body, out),
            S::Case(_) | S::Default => {
                // Labels outside a switch are syntax errors the parser reports.
            }
        }
    }

    fn loop_body(&mut self, body: &ast::Stmt) -> Stmt {
        let saved = self.ctx;
        self.ctx = Context {
            loops: saved.loops + 1,
            switches: 0,
        };
        let b = self.scoped(body);
        self.ctx = saved;
        b
    }

    fn ret(&mut self, e: Option<&ast::Expr>, pos: crate::diag::Pos, out: &mut Vec<Stmt>) {
        let Some(f) = self.current else {
            return;
        };
        let (fname, ret) = (
            self.functions[f].name.clone(),
            self.functions[f].ret.clone(),
        );
        match e {
            None => {
                if ret != Type::Void {
                    self.error(
                        pos,
                        format!("`return' with no value, in function {fname} returning non-void"),
                    );
                    return;
                }
                out.push(Stmt::Return(None));
            }
            Some(e) => {
                let Some(x) = self.expr(e) else {
                    return;
                };
                self.returned = true;
                if x.ty != ret {
                    self.error(
                        pos,
                        format!(
                            "`return' with wrong type {}, in function `{fname}' returning {ret}",
                            x.ty
                        ),
                    );
                    return;
                }
                out.push(Stmt::Return(Some(x)));
            }
        }
    }

    fn switch(&mut self, e: &ast::Expr, body: &[ast::Stmt], out: &mut Vec<Stmt>) {
        let Some(x) = self.expr(e) else {
            return;
        };
        if !matches!(x.ty, Type::Scalar(Scalar::Int | Scalar::Uint)) {
            self.error(e.pos, "switch-statement expression must be scalar integer");
            return;
        }
        let saved = self.ctx;
        self.ctx.switches += 1;
        self.push_scope();
        let mut seen: Vec<i64> = Vec::new();
        let mut default = false;
        let mut stmts = Vec::new();
        for s in body {
            match &s.kind {
                S::Case(c) => {
                    let Some(v) = self.expr(c) else {
                        continue;
                    };
                    let Some(k) = v.value.as_ref().and_then(fold::as_int) else {
                        self.error(
                            c.pos,
                            "switch statement case label must be a constant expression",
                        );
                        continue;
                    };
                    if v.ty != x.ty {
                        self.error(c.pos, format!("type mismatch with switch init-expression and case label ({} != {})", v.ty, x.ty));
                        continue;
                    }
                    if seen.contains(&k) {
                        self.error(c.pos, "duplicate case value");
                        continue;
                    }
                    seen.push(k);
                    stmts.push(Stmt::Case(Some(k)));
                }
                S::Default => {
                    if default {
                        self.error(s.pos, "multiple default labels in one switch");
                        continue;
                    }
                    default = true;
                    stmts.push(Stmt::Case(None));
                }
                _ => self.stmt(s, &mut stmts),
            }
        }
        self.pop_scope();
        self.ctx = saved;
        out.push(Stmt::Switch(x, stmts));
    }
}
