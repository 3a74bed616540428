//! Statements: blocks, `if`/`else` under lane masks, unrolled loops with `break` and
//! `continue`, `return` and `discard`, and the inlining of user functions (see
//! [`super::lower`]'s module doc for the scheme).

use super::lower::{no, Lower, Unsupported, R};
use crate::engine::ir::{Op, Val};
use softgl_glsl::hir::{self, Expr, Stmt, Storage, VarId};
use softgl_glsl::types::Type;

/// The most iterations an unrolled loop may take.
const MAX_UNROLL: usize = 1024;

/// A loop being unrolled: the lanes that left it or skip the rest of this iteration.
#[derive(Default)]
pub(super) struct LoopFrame {
    /// The lanes that left the loop.
    pub(super) broken: Option<Val>,
    /// The lanes that skip the rest of this iteration.
    pub(super) continued: Option<Val>,
    /// Every lane left (an unconditional `break`).
    pub(super) done: bool,
    /// Every lane skips the rest of this iteration.
    pub(super) skip: bool,
}

/// A function being inlined: its return value and the lanes that returned.
#[derive(Default)]
pub(super) struct FnFrame {
    /// The value returned so far (per lane).
    pub(super) ret: Option<Vec<Val>>,
    /// The lanes that returned.
    pub(super) returned: Option<Val>,
    /// Every lane returned.
    pub(super) done: bool,
}

impl Lower<'_> {
    /// The lanes the current code runs for (`None`: every lane).
    pub(super) fn exec(&mut self) -> Option<Val> {
        if self.unmasked {
            return None;
        }
        let f = self.fns.last().and_then(|f| f.returned);
        let (b, c) = self
            .loops
            .last()
            .map_or((None, None), |l| (l.broken, l.continued));
        let key = [self.cond, f, b, c];
        if let Some((k, m)) = self.exec_memo {
            if k == key {
                return m;
            }
        }
        let mut m = self.cond;
        for o in [f, b, c].into_iter().flatten() {
            let ones = self.mask(true);
            let not = self.op(Op::Xor(o, ones));
            m = Some(match m {
                Some(m) => self.op(Op::And(m, not)),
                None => not,
            });
        }
        self.exec_memo = Some((key, m));
        m
    }

    /// Whether the rest of the current block is dead (every lane returned, broke out or
    /// continued).
    fn dead(&self) -> bool {
        self.fns.last().is_some_and(|f| f.done)
            || self.loops.last().is_some_and(|l| l.done || l.skip)
    }

    /// Writes `vals` to the components `idx` of variable `var`, under the current mask.
    pub(super) fn write(&mut self, var: VarId, idx: &[usize], vals: &[Val]) -> R<()> {
        let cur = self.read_var(var)?;
        let mut next = cur.clone();
        let m = self.exec();
        for (&k, &v) in idx.iter().zip(vals) {
            next[k] = match m {
                Some(m) => self.op(Op::Select(m, v, cur[k])),
                None => v,
            };
        }
        self.env.insert(var, next);
        Ok(())
    }

    /// Lowers the statements of a block, in order, until the rest is dead.
    pub(super) fn block(&mut self, stmts: &[Stmt]) -> R<()> {
        for s in stmts {
            if self.dead() {
                break;
            }
            self.stmt(s)?;
        }
        Ok(())
    }

    fn stmt(&mut self, s: &Stmt) -> R<()> {
        match s {
            Stmt::Decl(v, init) => {
                let vals = match init {
                    Some(e) => self.expr(e)?,
                    None => {
                        self.env.remove(v);
                        let z = self.read_var(*v)?;
                        self.env.remove(v);
                        z
                    }
                };
                // A declaration binds (no mask): the variable is new in this scope.
                self.env.insert(*v, vals);
            }
            Stmt::Expr(e) => {
                self.expr(e)?;
            }
            Stmt::Block(b) => self.block(b)?,
            Stmt::If(c, t, e) => self.if_(c, t, e.as_deref())?,
            Stmt::Loop {
                init,
                cond,
                step,
                body,
                test_last,
            } => self.loop_(
                init.as_deref(),
                cond.as_ref(),
                step.as_ref(),
                body,
                *test_last,
            )?,
            Stmt::Break | Stmt::Continue => {
                let m = self.exec();
                let brk = matches!(s, Stmt::Break);
                let Some(lf) = self.loops.last() else {
                    return no("break outside a loop");
                };
                let prev = if brk { lf.broken } else { lf.continued };
                let next = match (m, prev) {
                    (None, _) => None,
                    (Some(m), None) => Some(m),
                    (Some(m), Some(p)) => Some(self.op(Op::Or(m, p))),
                };
                let lf = self.loops.last_mut().unwrap();
                match (next, brk) {
                    (None, true) => lf.done = true,
                    (None, false) => lf.skip = true,
                    (Some(n), true) => lf.broken = Some(n),
                    (Some(n), false) => lf.continued = Some(n),
                }
            }
            Stmt::Return(e) => {
                let vals = match e {
                    Some(e) => Some(self.expr(e)?),
                    None => None,
                };
                let m = self.exec();
                let f = self
                    .fns
                    .last()
                    .ok_or_else(|| Unsupported("return".into()))?;
                let (old, prev) = (f.ret.clone(), f.returned);
                let ret = match (vals, old, m) {
                    (Some(v), Some(o), Some(m)) => Some(
                        v.iter()
                            .zip(&o)
                            .map(|(&a, &b)| self.op(Op::Select(m, a, b)))
                            .collect(),
                    ),
                    (Some(v), _, _) => Some(v),
                    (None, o, _) => o,
                };
                let returned = match (m, prev) {
                    (None, _) => None,
                    (Some(m), None) => Some(m),
                    (Some(m), Some(p)) => Some(self.op(Op::Or(m, p))),
                };
                let f = self.fns.last_mut().unwrap();
                f.ret = ret;
                match returned {
                    None => f.done = true,
                    Some(r) => f.returned = Some(r),
                }
            }
            Stmt::Discard => {
                let keep = match self.exec() {
                    None => self.mask(false),
                    Some(m) => {
                        let ones = self.mask(true);
                        self.op(Op::Xor(m, ones))
                    }
                };
                self.op(Op::Kill(keep));
            }
            Stmt::Switch(..) | Stmt::Case(_) => return no("switch"),
        }
        Ok(())
    }

    fn if_(&mut self, c: &Expr, t: &Stmt, e: Option<&Stmt>) -> R<()> {
        let cv = self.expr(c)?[0];
        if let Some(k) = self.cval(cv) {
            return match (k != 0, e) {
                (true, _) => self.stmt(t),
                (false, Some(e)) => self.stmt(e),
                (false, None) => Ok(()),
            };
        }
        let saved = self.cond;
        let ones = self.mask(true);
        let not = self.op(Op::Xor(cv, ones));
        for (m, s) in [(cv, Some(t)), (not, e)] {
            let Some(s) = s else { continue };
            self.cond = Some(match saved {
                Some(o) => self.op(Op::And(o, m)),
                None => m,
            });
            self.stmt(s)?;
        }
        self.cond = saved;
        Ok(())
    }

    /// Unrolls a loop while its condition folds to a constant. The variables the step
    /// writes (the counters) are read inside the loop as the step computes them for every
    /// lane, so that a `break` in some lanes leaves the condition constant; their values
    /// after the loop are kept per lane, as of each lane's last step.
    fn loop_(
        &mut self,
        init: Option<&Stmt>,
        cond: Option<&Expr>,
        step: Option<&Expr>,
        body: &Stmt,
        test_last: bool,
    ) -> R<()> {
        if let Some(i) = init {
            self.stmt(i)?;
        }
        let mut counters = Vec::new();
        if let Some(s) = step {
            written(s, &mut counters);
        }
        // The loop runs for the lanes that reach it: outer loops' and returns' masks
        // become its condition.
        let saved_cond = self.cond;
        self.cond = self.exec();
        self.loops.push(LoopFrame::default());
        let r = self.unroll(cond, step, body, test_last, &counters);
        self.loops.pop();
        self.cond = saved_cond;
        r
    }

    fn unroll(
        &mut self,
        cond: Option<&Expr>,
        step: Option<&Expr>,
        body: &Stmt,
        test_last: bool,
        counters: &[VarId],
    ) -> R<()> {
        let mut real: Vec<Option<Vec<Val>>> = vec![None; counters.len()];
        let mut n = 0;
        loop {
            if !(test_last && n == 0) {
                if let Some(c) = cond {
                    let cv = self.expr(c)?[0];
                    match self.cval(cv) {
                        Some(0) => break,
                        Some(_) => {}
                        None => return no("a loop whose trip count is not constant"),
                    }
                }
            }
            n += 1;
            if n > MAX_UNROLL {
                return no("a loop of more than 1024 iterations");
            }
            self.stmt(body)?;
            let returned = self.fns.last().is_some_and(|f| f.done);
            let lf = self.loops.last_mut().unwrap();
            if lf.done || returned {
                break;
            }
            lf.skip = false;
            lf.continued = None;
            if let Some(s) = step {
                let m = self.exec();
                let before: Vec<Vec<Val>> = counters
                    .iter()
                    .zip(&real)
                    .map(|(v, r)| r.clone().map_or_else(|| self.read_var(*v), Ok))
                    .collect::<R<_>>()?;
                self.unmasked = true;
                let r = self.expr(s);
                self.unmasked = false;
                r?;
                for (k, v) in counters.iter().enumerate() {
                    let now = self.read_var(*v)?;
                    real[k] = Some(match m {
                        None => now,
                        Some(m) => now
                            .iter()
                            .zip(&before[k])
                            .map(|(&a, &b)| self.op(Op::Select(m, a, b)))
                            .collect(),
                    });
                }
            }
        }
        for (v, r) in counters.iter().zip(real) {
            if let Some(r) = r {
                self.env.insert(*v, r);
            }
        }
        Ok(())
    }

    /// Inlines a call of user function `fid`.
    pub(super) fn call(&mut self, fid: usize, args: &[Expr]) -> R<Vec<Val>> {
        let f = &self.p.functions[fid];
        let Some(body) = f.body.as_ref() else {
            return no(format!("function {} without body", f.name));
        };
        if self.fns.len() > 32 {
            return no("recursion");
        }
        let mut outs = Vec::new();
        for (k, a) in args.iter().enumerate() {
            let pid = f.params[k];
            if matches!(a.ty, Type::Sampler(_)) {
                // A sampler parameter names the caller's sampler (a texture lookup
                // resolves it, `texture`).
                let hir::ExprKind::Var(id) = a.kind else {
                    return no("a sampler argument that is not a variable");
                };
                let root = self.sampler_alias.get(&id).copied().unwrap_or(id);
                self.sampler_alias.insert(pid, root);
                continue;
            }
            let dir = match self.p.vars[pid].storage {
                Storage::Param(d) => d,
                _ => hir::ParamDir::In,
            };
            let v = match dir {
                hir::ParamDir::Out => {
                    self.env.remove(&pid);
                    let z = self.read_var(pid)?;
                    self.env.remove(&pid);
                    z
                }
                _ => self.expr(a)?,
            };
            if dir != hir::ParamDir::In {
                outs.push((pid, a));
            }
            self.env.insert(pid, v);
        }
        // The callee runs for the caller's lanes: its own returns and loops start afresh.
        let saved_cond = self.cond;
        self.cond = self.exec();
        let saved_loops = std::mem::take(&mut self.loops);
        self.fns.push(FnFrame::default());
        let r = self.block(body);
        let frame = self.fns.pop().unwrap();
        self.loops = saved_loops;
        self.cond = saved_cond;
        r?;
        for (pid, a) in outs {
            let v = self.env[&pid].clone();
            self.store(a, &v)?;
        }
        if f.ret == Type::Void {
            return Ok(Vec::new());
        }
        match frame.ret {
            Some(v) => Ok(v),
            None => no(format!("{} returns no value", f.name)),
        }
    }
}

/// The variables an expression assigns to (increments included), by their root.
fn written(e: &Expr, out: &mut Vec<VarId>) {
    use softgl_glsl::hir::ExprKind as K;
    let root = |mut e: &Expr| loop {
        match &e.kind {
            K::Var(v) => return Some(*v),
            K::Swizzle(b, _) | K::Index(b, _) | K::Field(b, _) => e = b,
            _ => return None,
        }
    };
    match &e.kind {
        K::Assign(_, l, r) => {
            out.extend(root(l));
            written(r, out);
        }
        K::Unary(op, a) => {
            use softgl_glsl::ast::UnOp::*;
            if matches!(op, PreInc | PreDec | PostInc | PostDec) {
                out.extend(root(a));
            }
            written(a, out);
        }
        K::Comma(a, b) | K::Binary(_, a, b) => {
            written(a, out);
            written(b, out);
        }
        _ => {}
    }
    out.sort_unstable();
    out.dedup();
}
