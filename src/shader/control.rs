//! Statements: blocks, `if`/`else` under lane masks, unrolled loops with `break` and
//! `continue`, `return` and `discard`, and the inlining of user functions (see
//! [`super::lower`]'s module doc for the scheme).

use super::lower::{no, Lower, Unsupported, R};
use crate::engine::ir::{Op, Ty, Val};
use softgl_glsl::hir::{self, Expr, Stmt, Storage, VarId};
use softgl_glsl::types::{Scalar, Type};

/// The most iterations an unrolled loop may take.
const MAX_UNROLL: usize = 1024;

/// Why a loop is not unrolled: its condition does not fold to a constant.
const NOT_CONSTANT: &str = "a loop whose trip count is not constant";
/// Why a loop is not unrolled: it runs more than [`MAX_UNROLL`] times.
const TOO_LONG: &str = "a loop of more than 1024 iterations";
/// The most mutable variables a shader's loops may carry (each takes a register slot).
const MAX_VARS: u16 = 4096;

/// A loop being unrolled: the lanes that left it or skip the rest of this iteration.
#[derive(Clone, Default)]
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
#[derive(Clone, Default)]
pub(super) struct FnFrame {
    /// The value returned so far (per lane).
    pub(super) ret: Option<Vec<Val>>,
    /// The lanes that returned.
    pub(super) returned: Option<Val>,
    /// Every lane returned.
    pub(super) done: bool,
    /// The scalars of the function's return value (empty for `void` and `main`): a loop
    /// that carries [`FnFrame::ret`] across iterations before any `return` starts it at
    /// zeros of these.
    pub(super) ret_scalars: Vec<Scalar>,
}

/// The mutable variables a loop carries an enclosing function's returns in: the lanes
/// that returned, and each component of the value returned with its type.
struct RetCarry {
    returned: u16,
    value: Vec<(u16, Ty)>,
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
    /// after the loop are kept per lane, as of each lane's last step. A loop whose
    /// condition does not fold, or that runs more than [`MAX_UNROLL`] times, is lowered
    /// again from the same point as a loop ([`Lower::dynamic_loop`]).
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
        let before = self.clone();
        self.loops.push(LoopFrame::default());
        let r = self.unroll(cond, step, body, test_last, &counters);
        self.loops.pop();
        let r = match r {
            Err(Unsupported(why)) if why == NOT_CONSTANT || why == TOO_LONG => {
                *self = before;
                self.dynamic_loop(cond, step, body, test_last)
            }
            r => r,
        };
        self.cond = saved_cond;
        r
    }

    /// Lowers a loop as a loop ([`Op::LoopBegin`] … [`Op::LoopEnd`]): the variables the
    /// loop may write ([`writes_stmt`]) live in mutable variables across iterations
    /// (stored on entry and at the end of each iteration, loaded at the start of each
    /// and after the loop), and so does the mask of the lanes that left it; the body
    /// runs again while a lane that reached the loop has not left it. Every write is
    /// selected under the lane mask as in straight code, so the lanes that left keep
    /// their values. The enclosing function's returns are carried the same way
    /// ([`RetCarry`]): a lane that returns leaves the loop, and its value is selected
    /// into the function's as in straight code.
    fn dynamic_loop(
        &mut self,
        cond: Option<&Expr>,
        step: Option<&Expr>,
        body: &Stmt,
        test_last: bool,
    ) -> R<()> {
        let (mut vars, mut seen) = (Vec::new(), Vec::new());
        writes_stmt(self.p, body, &mut vars, &mut seen);
        for e in cond.iter().chain(step.iter()) {
            writes_expr(self.p, e, &mut vars, &mut seen);
        }
        vars.sort_unstable();
        vars.dedup();
        let mut carried = Vec::new();
        // What cannot be written (uniforms, inputs, constants, samplers) is not carried.
        vars.retain(|&v| {
            let var = &self.p.vars[v];
            !matches!(var.storage, Storage::Uniform | Storage::In | Storage::Const)
                && !matches!(var.ty, Type::Sampler(_))
        });
        for v in vars {
            let vals = self.read_var(v)?;
            let slots = self.stored(vals)?;
            carried.push((v, slots));
        }
        let broken_var = self.new_var()?;
        let none = self.mask(false);
        self.op(Op::VarStore(broken_var, none));
        let ret = self.carry_returns()?;
        let id = self.loop_count;
        self.loop_count = id
            .checked_add(1)
            .ok_or_else(|| Unsupported("too many loops".into()))?;
        self.op(Op::LoopBegin(id));
        self.exec_memo = None;
        self.load_carried(&carried);
        self.load_returns(ret.as_ref());
        let broken = self.op(Op::VarLoad(broken_var, Ty::Mask));
        self.loops.push(LoopFrame {
            broken: Some(broken),
            ..LoopFrame::default()
        });
        if let (false, Some(c)) = (test_last, cond) {
            self.leave_unless(c)?;
        }
        self.stmt(body)?;
        if let Some(lf) = self.loops.last_mut() {
            lf.continued = None;
            lf.skip = false;
        }
        if let Some(s) = step {
            self.expr(s)?;
        }
        if let (true, Some(c)) = (test_last, cond) {
            self.leave_unless(c)?;
        }
        self.store_returns(ret.as_ref());
        for (v, slots) in &carried {
            let vals = self.read_var(*v)?;
            for (&(id, _), &x) in slots.iter().zip(&vals) {
                self.op(Op::VarStore(id, x));
            }
        }
        let left = self.loops.last().and_then(|l| l.broken).unwrap_or(none);
        self.op(Op::VarStore(broken_var, left));
        let running = match self.exec() {
            Some(m) => m,
            None => self.mask(true),
        };
        self.op(Op::LoopEnd(id, running));
        self.loops.pop();
        self.exec_memo = None;
        self.load_carried(&carried);
        self.load_returns(ret.as_ref());
        Ok(())
    }

    /// The mutable variables of the enclosing function's returns, set to their values
    /// before the loop (`None` outside a function frame).
    fn carry_returns(&mut self) -> R<Option<RetCarry>> {
        let Some(f) = self.fns.last() else {
            return Ok(None);
        };
        let (returned, value, sc) = (f.returned, f.ret.clone(), f.ret_scalars.clone());
        let returned = match returned {
            Some(r) => r,
            None => self.mask(false),
        };
        let value = match value {
            Some(v) => v,
            None => sc
                .iter()
                .map(|s| match s {
                    Scalar::Float => self.f32(0.0),
                    Scalar::Int | Scalar::Uint => self.i32(0),
                    Scalar::Bool => self.mask(false),
                })
                .collect(),
        };
        let rv = self.new_var()?;
        self.op(Op::VarStore(rv, returned));
        Ok(Some(RetCarry {
            returned: rv,
            value: self.stored(value)?,
        }))
    }

    /// New mutable variables holding `vals`, each with its type.
    fn stored(&mut self, vals: Vec<Val>) -> R<Vec<(u16, Ty)>> {
        let mut slots = Vec::new();
        for x in vals {
            let Some(ty) = self.b.ty(x) else {
                return no("a carried value without a type");
            };
            let id = self.new_var()?;
            self.op(Op::VarStore(id, x));
            slots.push((id, ty));
        }
        Ok(slots)
    }

    /// The function frame's returns read back from `ret`'s variables.
    fn load_returns(&mut self, ret: Option<&RetCarry>) {
        let Some(ret) = ret else { return };
        let returned = self.op(Op::VarLoad(ret.returned, Ty::Mask));
        let value: Vec<Val> = ret
            .value
            .iter()
            .map(|&(id, ty)| self.op(Op::VarLoad(id, ty)))
            .collect();
        if let Some(f) = self.fns.last_mut() {
            f.returned = Some(returned);
            f.done = false;
            if !value.is_empty() {
                f.ret = Some(value);
            }
        }
        self.exec_memo = None;
    }

    /// The function frame's returns stored into `ret`'s variables (every lane when the
    /// frame says all returned).
    fn store_returns(&mut self, ret: Option<&RetCarry>) {
        let Some(ret) = ret else { return };
        let Some(f) = self.fns.last() else { return };
        let (done, returned, value) = (f.done, f.returned, f.ret.clone());
        let returned = match (done, returned) {
            (false, Some(r)) => r,
            _ => self.mask(true),
        };
        self.op(Op::VarStore(ret.returned, returned));
        for (&(id, _), x) in ret.value.iter().zip(value.unwrap_or_default()) {
            self.op(Op::VarStore(id, x));
        }
    }

    /// The lanes running where condition `c` is false leave the loop being lowered.
    fn leave_unless(&mut self, c: &Expr) -> R<()> {
        let cv = self.expr(c)?[0];
        let m = self.exec();
        let ones = self.mask(true);
        let not = self.op(Op::Xor(cv, ones));
        let leave = match m {
            Some(m) => self.op(Op::And(m, not)),
            None => not,
        };
        let prev = self.loops.last().and_then(|l| l.broken);
        let broken = match prev {
            Some(b) => self.op(Op::Or(b, leave)),
            None => leave,
        };
        if let Some(lf) = self.loops.last_mut() {
            lf.broken = Some(broken);
        }
        Ok(())
    }

    /// Binds each variable of `carried` to loads of its mutable variables.
    fn load_carried(&mut self, carried: &[(VarId, Vec<(u16, Ty)>)]) {
        for (v, slots) in carried {
            let vals = slots
                .iter()
                .map(|&(id, ty)| self.op(Op::VarLoad(id, ty)))
                .collect();
            self.env.insert(*v, vals);
        }
    }

    /// A new mutable variable.
    fn new_var(&mut self) -> R<u16> {
        let id = self.var_count;
        if id >= MAX_VARS {
            return no("too many loop variables");
        }
        self.var_count += 1;
        Ok(id)
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
                        None => return no(NOT_CONSTANT),
                    }
                }
            }
            n += 1;
            if n > MAX_UNROLL {
                return no(TOO_LONG);
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
        let mut ret_scalars = Vec::new();
        if f.ret != Type::Void {
            super::lower::scalars(&f.ret, &mut ret_scalars)?;
        }
        self.fns.push(FnFrame {
            ret_scalars,
            ..FnFrame::default()
        });
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

/// The variable an lvalue names (the array, struct or vector it is part of).
fn root(mut e: &Expr) -> Option<VarId> {
    use softgl_glsl::hir::ExprKind as K;
    loop {
        match &e.kind {
            K::Var(v) => return Some(*v),
            K::Swizzle(b, _) | K::Index(b, _) | K::Field(b, _) => e = b,
            _ => return None,
        }
    }
}

/// The variables an expression assigns to (increments included), by their root.
fn written(e: &Expr, out: &mut Vec<VarId>) {
    use softgl_glsl::hir::ExprKind as K;
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

/// The variables statement `s` may write (assignments, increments, arguments of user
/// calls, and what the called functions write), added to `out`: the values a loop
/// carries from one iteration to the next. `seen` keeps each called function to one
/// visit.
fn writes_stmt(p: &hir::Program, s: &Stmt, out: &mut Vec<VarId>, seen: &mut Vec<usize>) {
    match s {
        Stmt::Decl(_, Some(e)) | Stmt::Expr(e) | Stmt::Return(Some(e)) => {
            writes_expr(p, e, out, seen)
        }
        Stmt::Block(b) | Stmt::Switch(_, b) => {
            if let Stmt::Switch(e, _) = s {
                writes_expr(p, e, out, seen);
            }
            for t in b {
                writes_stmt(p, t, out, seen);
            }
        }
        Stmt::If(c, t, e) => {
            writes_expr(p, c, out, seen);
            writes_stmt(p, t, out, seen);
            if let Some(e) = e {
                writes_stmt(p, e, out, seen);
            }
        }
        Stmt::Loop {
            init,
            cond,
            step,
            body,
            ..
        } => {
            if let Some(i) = init {
                writes_stmt(p, i, out, seen);
            }
            for e in cond.iter().chain(step) {
                writes_expr(p, e, out, seen);
            }
            writes_stmt(p, body, out, seen);
        }
        _ => {}
    }
}

/// [`writes_stmt`] for an expression.
fn writes_expr(p: &hir::Program, e: &Expr, out: &mut Vec<VarId>, seen: &mut Vec<usize>) {
    use softgl_glsl::hir::ExprKind as K;
    match &e.kind {
        K::Assign(_, l, r) => {
            out.extend(root(l));
            writes_expr(p, l, out, seen);
            writes_expr(p, r, out, seen);
        }
        K::Unary(op, a) => {
            use softgl_glsl::ast::UnOp::*;
            if matches!(op, PreInc | PreDec | PostInc | PostDec) {
                out.extend(root(a));
            }
            writes_expr(p, a, out, seen);
        }
        K::Binary(_, a, b) | K::Comma(a, b) | K::Index(a, b) => {
            writes_expr(p, a, out, seen);
            writes_expr(p, b, out, seen);
        }
        K::Ternary(a, b, c) => {
            for x in [a, b, c] {
                writes_expr(p, x, out, seen);
            }
        }
        K::Field(a, _) | K::Swizzle(a, _) | K::Convert(a) | K::Length(a) => {
            writes_expr(p, a, out, seen)
        }
        K::Construct(args) => {
            for a in args {
                writes_expr(p, a, out, seen);
            }
        }
        K::Builtin(_, args) => {
            // `out` parameters of built-ins (modf, frexp …)
            for a in args {
                out.extend(root(a));
                writes_expr(p, a, out, seen);
            }
        }
        K::Call(f, args) => {
            for a in args {
                out.extend(root(a));
                writes_expr(p, a, out, seen);
            }
            if !seen.contains(f) {
                seen.push(*f);
                for s in p.functions[*f].body.iter().flatten() {
                    writes_stmt(p, s, out, seen);
                }
            }
        }
        K::Var(_) | K::Literal => {}
    }
}
