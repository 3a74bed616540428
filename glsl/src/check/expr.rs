//! Expressions (GLSL chapter 5): names, literals, fields and swizzles (5.5, 5.6),
//! indexing with constant bounds checks (5.7), calls with overload resolution against
//! the built-in tables and user functions (6.1), `.length()` (from 1.20),
//! assignments (5.8) and the ternary and comma operators. The operators' typing is in
//! `ops`, constructors in `construct`.
//!
//! Mesa's behaviour followed: swizzles of scalars are an error in these versions; a
//! user function named like a built-in hides the built-ins of that name from 1.20
//! (in 1.10 it adds an overload); `out`/`inout` arguments must be l-values and not
//! read-only; constant indices are checked against the array, vector or matrix size.

use super::{fold, Checker, Symbol};
use crate::ast::{self, Callee, ExprKind as A};
use crate::builtins;
use crate::diag::Pos;
use crate::hir::{Const, Expr, ExprKind, ParamDir, Storage, Value, VarId};
use crate::types::{Scalar, Type};

/// A new expression node of type `ty` at `pos`, not an l-value, not constant.
pub(super) fn node(kind: ExprKind, ty: Type, pos: Pos) -> Expr {
    Expr {
        kind,
        ty,
        pos,
        lvalue: false,
        value: None,
    }
}

/// The variable an l-value expression designates (through fields, indices and
/// swizzles).
pub(super) fn root_var(e: &Expr) -> Option<VarId> {
    let mut e = e;
    loop {
        match &e.kind {
            ExprKind::Var(v) => return Some(*v),
            ExprKind::Index(b, _) | ExprKind::Field(b, _) | ExprKind::Swizzle(b, _) => e = b,
            _ => return None,
        }
    }
}

/// The component indices of a swizzle, if `s` is a valid one for `n` components.
fn swizzle(s: &str, n: u8) -> Option<Vec<u8>> {
    const SETS: [&str; 3] = ["xyzw", "rgba", "stpq"];
    if s.is_empty() || s.len() > 4 {
        return None;
    }
    let first = s.chars().next()?;
    let set = SETS.iter().find(|set| set.contains(first))?;
    s.chars()
        .map(|c| set.find(c).map(|i| i as u8).filter(|i| *i < n))
        .collect()
}

impl Checker<'_> {
    /// Checks an expression; `None` after reporting an error.
    pub(super) fn expr(&mut self, e: &ast::Expr) -> Option<Expr> {
        if !self.enter(e.pos) {
            self.leave();
            return None;
        }
        let r = self.expr_inner(e);
        self.leave();
        r
    }

    fn expr_inner(&mut self, e: &ast::Expr) -> Option<Expr> {
        let pos = e.pos;
        let lit = |v: Value, ty: Type| {
            Some(Expr {
                kind: ExprKind::Literal,
                ty,
                pos,
                lvalue: false,
                value: Some(Const::Scalars(vec![v])),
            })
        };
        match &e.kind {
            A::Ident(n) => self.ident(n, pos),
            A::Int(v) => lit(Value::Int(*v as i32), Type::INT),
            A::Uint(v) => lit(Value::Uint(*v), Type::UINT),
            A::Float(f) => lit(Value::Float(*f as f32), Type::FLOAT),
            A::Bool(b) => lit(Value::Bool(*b), Type::BOOL),
            A::Int64(_) | A::Uint64(_) => {
                self.error(pos, "64-bit integers require GL_ARB_gpu_shader_int64");
                None
            }
            A::Unary(op, x) => {
                let x = self.expr(x)?;
                self.unary(*op, x, pos)
            }
            A::Binary(op, a, b) => {
                let a = self.expr(a)?;
                let b = self.expr(b)?;
                self.binary(*op, a, b, pos)
            }
            A::Assign(op, l, r) => {
                let l = self.expr(l)?;
                let r = self.expr(r)?;
                self.assign(*op, l, r, pos)
            }
            A::Ternary(c, a, b) => {
                let c = self.expr(c)?;
                if c.ty != Type::BOOL {
                    self.error(c.pos, "condition of `?:' must be scalar boolean");
                    return None;
                }
                let a = self.expr(a)?;
                let b = self.expr(b)?;
                let (a, b) = match (
                    self.convert(a.clone(), &b.ty),
                    self.convert(b.clone(), &a.ty),
                ) {
                    (Some(a2), _) if a2.ty == b.ty => (a2, b),
                    (_, Some(b2)) if b2.ty == a.ty => (a, b2),
                    _ => {
                        self.error(
                            pos,
                            "second and third operands of ?: operator must have matching types",
                        );
                        return None;
                    }
                };
                let value = match (&c.value, &a.value, &b.value) {
                    (Some(Const::Scalars(v)), Some(x), Some(y)) => {
                        Some(if v.first() == Some(&Value::Bool(true)) {
                            x.clone()
                        } else {
                            y.clone()
                        })
                    }
                    _ => None,
                };
                let ty = a.ty.clone();
                let mut n = node(
                    ExprKind::Ternary(Box::new(c), Box::new(a), Box::new(b)),
                    ty,
                    pos,
                );
                n.value = value;
                Some(n)
            }
            A::Comma(a, b) => {
                let a = self.expr(a)?;
                let b = self.expr(b)?;
                let ty = b.ty.clone();
                Some(node(ExprKind::Comma(Box::new(a), Box::new(b)), ty, pos))
            }
            A::Index(a, i) => {
                let a = self.expr(a)?;
                let i = self.expr(i)?;
                self.index(a, i, pos)
            }
            A::Field(a, name) => {
                let a = self.expr(a)?;
                self.field(a, name, pos)
            }
            A::Call(callee, args) => self.call(callee, args, pos),
            A::InitList(_) => {
                self.error(
                    pos,
                    "initializer lists require GLSL 4.20 or GL_ARB_shading_language_420pack",
                );
                None
            }
            A::Method(a, name, args) => {
                let a = self.expr(a)?;
                if !self.require(
                    120,
                    pos,
                    "methods not supported",
                    "GLSL 1.20 or GLSL ES 3.00",
                ) {
                    return None;
                }
                if name != "length" {
                    self.error(pos, format!("unknown method: `{name}'"));
                    return None;
                }
                if !args.is_empty() {
                    self.error(pos, "length method takes no arguments");
                    return None;
                }
                match &a.ty {
                    Type::Array(_, Some(n)) => {
                        let n = *n as i32;
                        let mut x = node(ExprKind::Length(Box::new(a)), Type::INT, pos);
                        x.value = Some(Const::Scalars(vec![Value::Int(n)]));
                        Some(x)
                    }
                    Type::Array(_, None) => {
                        self.error(pos, "length called on unsized array");
                        None
                    }
                    _ => {
                        self.error(pos, "length method called on non-array");
                        None
                    }
                }
            }
        }
    }

    fn ident(&mut self, n: &str, pos: Pos) -> Option<Expr> {
        match self.lookup(n) {
            Some(Symbol::Var(v)) => {
                let var = &self.vars[v];
                let const_var = var.storage == Storage::Const
                    || var.storage == Storage::Builtin(builtins::variables::Kind::Constant);
                Some(Expr {
                    kind: ExprKind::Var(v),
                    ty: var.ty.clone(),
                    pos,
                    lvalue: !const_var,
                    value: if const_var { var.value.clone() } else { None },
                })
            }
            _ => {
                self.error(pos, format!("`{n}' undeclared"));
                None
            }
        }
    }

    fn index(&mut self, a: Expr, i: Expr, pos: Pos) -> Option<Expr> {
        let (what, len, elem) = match &a.ty {
            Type::Array(e, n) => ("array", *n, (**e).clone()),
            Type::Vector(s, n) => ("vector", Some(*n as u32), Type::Scalar(*s)),
            Type::Matrix { cols, rows } => (
                "matrix",
                Some(*cols as u32),
                Type::vec(Scalar::Float, *rows),
            ),
            _ => {
                self.error(
                    pos,
                    "cannot dereference non-array / non-matrix / non-vector",
                );
                return None;
            }
        };
        if !matches!(i.ty, Type::Scalar(Scalar::Int | Scalar::Uint)) {
            self.error(i.pos, format!("{what} index must be integer type"));
            return None;
        }
        let k = i.value.as_ref().and_then(fold::as_int);
        if let Some(k) = k {
            if k < 0 {
                self.error(pos, "error index must be >= 0");
                return None;
            }
            if let Some(n) = len {
                if k >= n as i64 {
                    self.error(pos, format!("{what} index must be < {n}"));
                    return None;
                }
            }
        }
        let value = match (&a.value, k) {
            (Some(c), Some(k)) => fold::index(c, &a.ty, k),
            _ => None,
        };
        let lvalue = a.lvalue;
        let mut x = node(ExprKind::Index(Box::new(a), Box::new(i)), elem, pos);
        x.lvalue = lvalue;
        x.value = value;
        Some(x)
    }

    fn field(&mut self, a: Expr, name: &str, pos: Pos) -> Option<Expr> {
        match &a.ty {
            Type::Struct(s) => {
                let Some(k) = s.members.iter().position(|m| m.name == name) else {
                    self.error(pos, format!("cannot access field `{name}' of structure"));
                    return None;
                };
                let ty = s.members[k].ty.clone();
                let value = match &a.value {
                    Some(Const::Aggregate(v)) => v.get(k).cloned(),
                    _ => None,
                };
                let lvalue = a.lvalue;
                let mut x = node(ExprKind::Field(Box::new(a), k), ty, pos);
                x.lvalue = lvalue;
                x.value = value;
                Some(x)
            }
            Type::Vector(s, n) => {
                let Some(idx) = swizzle(name, *n) else {
                    self.error(pos, format!("invalid swizzle / mask `{name}'"));
                    return None;
                };
                let repeated = (1..idx.len()).any(|i| idx[..i].contains(&idx[i]));
                let ty = Type::vec(*s, idx.len() as u8);
                let value = a.value.as_ref().and_then(|c| fold::swizzle(c, &idx));
                let lvalue = a.lvalue && !repeated;
                let mut x = node(ExprKind::Swizzle(Box::new(a), idx), ty, pos);
                x.lvalue = lvalue;
                x.value = value;
                Some(x)
            }
            _ => {
                self.error(
                    pos,
                    format!("cannot access field `{name}' of non-structure / non-vector"),
                );
                None
            }
        }
    }

    /// `x` converted implicitly to `to` (itself when the types are equal), or `None`
    /// when the version has no such conversion. Constants are converted too.
    pub(super) fn convert(&self, x: Expr, to: &Type) -> Option<Expr> {
        if &x.ty == to {
            return Some(x);
        }
        if !x.ty.converts_to(to, self.version) {
            return None;
        }
        let value = x
            .value
            .as_ref()
            .and_then(|c| fold::convert_all(c, to.scalar().unwrap_or(Scalar::Float)));
        let pos = x.pos;
        let mut n = node(ExprKind::Convert(Box::new(x)), to.clone(), pos);
        n.value = value;
        Some(n)
    }

    /// `x` converted for assignment to a variable of type `to`; the found type when
    /// it does not convert. Mesa converts int to float for an assignment from 1.20.
    pub(super) fn assign_convert(&self, x: Expr, to: &Type) -> Result<Expr, Type> {
        // Mesa reports the type after its attempted conversion to the target's base
        // type (an int converts to a float of the same shape from 1.20).
        let ty = match (&x.ty, to.scalar()) {
            (Type::Scalar(Scalar::Int | Scalar::Uint), Some(Scalar::Float))
                if self.at_least(120) =>
            {
                Type::FLOAT
            }
            (Type::Vector(Scalar::Int | Scalar::Uint, n), Some(Scalar::Float))
                if self.at_least(120) =>
            {
                Type::Vector(Scalar::Float, *n)
            }
            (t, _) => t.clone(),
        };
        // An unsized array takes the initializer's size.
        if let (Type::Array(e, None), Type::Array(f, Some(_))) = (to, &ty) {
            if e == f {
                return Ok(x);
            }
        }
        self.convert(x, to).ok_or(ty)
    }

    fn assign(&mut self, op: Option<ast::BinOp>, l: Expr, r: Expr, pos: Pos) -> Option<Expr> {
        // Mesa types a compound assignment's operation before it checks the target,
        // and names the operator with its `=` (`LHS of `^=' must be an integer`).
        if op.is_none() && !self.assignable(&l, pos) {
            return None;
        }
        let r = match op {
            None => r,
            Some(op) => {
                self.compound = true;
                let v = self.binary(op, l.clone(), r, pos);
                self.compound = false;
                let v = v?;
                if !self.assignable(&l, pos) {
                    return None;
                }
                if v.ty != l.ty {
                    self.error(
                        pos,
                        format!("could not implicitly convert {} to {}", v.ty, l.ty),
                    );
                    return None;
                }
                match v.kind {
                    ExprKind::Binary(_, _, r) => *r,
                    _ => return None,
                }
            }
        };
        if matches!(l.ty, Type::Array(..)) && !self.at_least(120) {
            let vt = self.version_text();
            self.error(
                pos,
                format!(
                    "whole array assignment forbidden in {vt} (GLSL 1.20 or GLSL ES 3.00 required)"
                ),
            );
            return None;
        }
        let r = if op.is_some() {
            r
        } else {
            match self.assign_convert(r, &l.ty) {
                Ok(r) => r,
                Err(found) => {
                    self.error(
                        pos,
                        format!(
                            "value of type {found} cannot be assigned to variable of type {}",
                            l.ty
                        ),
                    );
                    return None;
                }
            }
        };
        let ty = l.ty.clone();
        Some(node(
            ExprKind::Assign(op, Box::new(l), Box::new(r)),
            ty,
            pos,
        ))
    }

    /// Whether `l` may be assigned to; reports Mesa's error when not.
    pub(super) fn assignable(&mut self, l: &Expr, pos: Pos) -> bool {
        if let Some(v) = root_var(l) {
            if self.vars[v].read_only
                || self.vars[v].storage == Storage::Const
                || !is_writable_builtin(&self.vars[v])
            {
                let n = self.vars[v].name.clone();
                self.error(pos, format!("assignment to read-only variable '{n}'"));
                return false;
            }
        }
        if !l.lvalue {
            self.error(l.pos, "non-lvalue in assignment");
            return false;
        }
        if let Some(v) = root_var(l) {
            self.note_write(v);
        }
        true
    }

    fn call(&mut self, callee: &Callee, args: &[ast::Expr], pos: Pos) -> Option<Expr> {
        let name = match callee {
            Callee::Type(spec) => {
                let ty = self.resolve_type(spec, &[])?;
                let args = self.args(args)?;
                return self.construct(ty, args, pos);
            }
            Callee::Expr(_) => {
                self.error(pos, "function name is not an identifier");
                return None;
            }
            Callee::Name(n) => n,
        };
        if let Some(st) = self.struct_named(name) {
            let args = self.args(args)?;
            return self.construct(Type::Struct(st), args, pos);
        }
        let args = self.args(args)?;
        let types: Vec<Type> = args.iter().map(|a| a.ty.clone()).collect();
        let users = match self.lookup(name) {
            Some(Symbol::Functions(f)) => f,
            Some(_) => {
                // A variable hides the functions of that name.
                self.error(pos, format!("no function with name '{name}'"));
                return None;
            }
            None => Vec::new(),
        };
        // A user function: exact match first, then through conversions.
        let user_match = |c: &Checker, exact: bool| -> Vec<usize> {
            users
                .iter()
                .copied()
                .filter(|f| {
                    let ps = &c.functions[*f].params;
                    ps.len() == types.len()
                        && ps.iter().zip(&types).all(|(p, t)| {
                            let pt = &c.vars[*p].ty;
                            if exact {
                                pt == t
                            } else {
                                match c.vars[*p].storage {
                                    Storage::Param(ParamDir::Out) => pt.converts_to(t, c.version),
                                    Storage::Param(ParamDir::Inout) => pt == t,
                                    _ => t.converts_to(pt, c.version),
                                }
                            }
                        })
                })
                .collect()
        };
        // Several through conversions: the one at least as exact as every other in
        // each parameter and more in one (GLSL 4.00, as Mesa does); none is an error.
        let found_user = user_match(self, true).first().copied().or_else(|| {
            let fits = user_match(self, false);
            let exact = |f: usize, i: usize| self.vars[self.functions[f].params[i]].ty == types[i];
            let better = |a: usize, b: usize| {
                (0..types.len()).all(|i| exact(a, i) || !exact(b, i))
                    && (0..types.len()).any(|i| exact(a, i) && !exact(b, i))
            };
            match fits.as_slice() {
                [f] => Some(*f),
                _ => fits
                    .iter()
                    .copied()
                    .find(|&a| fits.iter().all(|&b| a == b || better(a, b))),
            }
        });
        let hide_builtins = !users.is_empty() && self.at_least(120);
        let builtin = if hide_builtins || found_user.is_some() {
            None
        } else {
            match builtins::resolve(name, &types, self.version, self.stage, &self.exts) {
                Ok(f) => Some(f),
                Err(builtins::Unresolved::NoFunction) if users.is_empty() => {
                    self.error(pos, format!("no function with name '{name}'"));
                    return None;
                }
                Err(_) => None,
            }
        };
        let sig = format!(
            "{name}({})",
            types
                .iter()
                .map(|t| t.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        );
        if let Some(f) = builtin {
            if let Some(a) = f
                .params
                .iter()
                .zip(&args)
                .find_map(|(p, a)| (p.constant && a.value.is_none()).then_some(a))
            {
                // Mesa names the parameter; the tables' constant parameters are the
                // texel offsets.
                self.error(a.pos, "parameter `in offset' must be a constant expression");
                return None;
            }
            let args = self.bind_args(
                args,
                f.params
                    .iter()
                    .map(|p| {
                        (
                            p.ty.clone(),
                            if p.out { ParamDir::Out } else { ParamDir::In },
                            String::new(),
                        )
                    })
                    .collect(),
                pos,
            )?;
            let consts: Option<Vec<&Const>> = args.iter().map(|a| a.value.as_ref()).collect();
            let value = consts.and_then(|c| fold::builtin(name, &c, &f.ret));
            let mut x = node(ExprKind::Builtin(f, args), f.ret.clone(), pos);
            x.value = value;
            return Some(x);
        }
        let Some(fid) = found_user else {
            self.error(
                pos,
                format!("no matching function for call to `{sig}'; candidates are:"),
            );
            return None;
        };
        let params: Vec<(Type, ParamDir, String)> = self.functions[fid]
            .params
            .iter()
            .map(|p| {
                let v = &self.vars[*p];
                let dir = match v.storage {
                    Storage::Param(d) => d,
                    _ => ParamDir::In,
                };
                (v.ty.clone(), dir, v.name.clone())
            })
            .collect();
        let args = self.bind_args(args, params, pos)?;
        if let Some(cur) = self.current {
            self.calls.push((cur, fid));
        }
        let ret = self.functions[fid].ret.clone();
        Some(node(ExprKind::Call(fid, args), ret, pos))
    }

    fn args(&mut self, args: &[ast::Expr]) -> Option<Vec<Expr>> {
        args.iter().map(|a| self.expr(a)).collect()
    }

    /// Converts `in` arguments to the parameter types and checks that `out` and
    /// `inout` arguments are writable l-values.
    fn bind_args(
        &mut self,
        args: Vec<Expr>,
        params: Vec<(Type, ParamDir, String)>,
        _pos: Pos,
    ) -> Option<Vec<Expr>> {
        let mut out = Vec::with_capacity(args.len());
        for (a, (ty, dir, name)) in args.into_iter().zip(params) {
            if dir == ParamDir::In {
                out.push(self.convert(a.clone(), &ty).unwrap_or(a));
                continue;
            }
            let d = if dir == ParamDir::Out { "out" } else { "inout" };
            if !a.lvalue {
                self.error(
                    a.pos,
                    format!("function parameter '{d} {name}' is not an lvalue"),
                );
                return None;
            }
            if let Some(v) = root_var(&a) {
                if self.vars[v].read_only || !is_writable_builtin(&self.vars[v]) {
                    let n = self.vars[v].name.clone();
                    self.error(a.pos, format!("function parameter '{d} {name}' references the read-only variable '{n}'"));
                    return None;
                }
            }
            out.push(a);
        }
        Some(out)
    }
}

/// False for the built-in variables a shader may not write (inputs, uniforms,
/// constants).
fn is_writable_builtin(v: &crate::hir::Var) -> bool {
    match v.storage {
        Storage::Builtin(k) => k == builtins::variables::Kind::Output,
        _ => true,
    }
}
