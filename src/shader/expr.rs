//! Expressions: variables, operators, swizzles, indexing, constructors, conversions and
//! calls, each lowered to one value per scalar component.

use super::builtins;
use super::lower::{no, size, Lower, Unsupported, R, TEX_COORDS};
use crate::engine::ir::{FCmp, IOp, Op, Un, Val};
use softgl_glsl::ast::{BinOp, UnOp};
use softgl_glsl::hir::{Expr, ExprKind, VarId};
use softgl_glsl::types::{Scalar, Type};

impl Lower<'_> {
    /// Lowers an expression to its components.
    pub(super) fn expr(&mut self, e: &Expr) -> R<Vec<Val>> {
        self.depth += 1;
        if self.depth > 200 {
            return no("expressions nested too deeply");
        }
        let r = self.expr_inner(e);
        self.depth -= 1;
        r
    }

    fn expr_inner(&mut self, e: &Expr) -> R<Vec<Val>> {
        if let (Some(c), false) = (&e.value, matches!(e.kind, ExprKind::Assign(..))) {
            if !matches!(e.ty, Type::Struct(_)) {
                return self.constant(c, &e.ty);
            }
        }
        match &e.kind {
            ExprKind::Var(id) => self.read_var(*id),
            ExprKind::Literal => no("a literal without value"),
            ExprKind::Unary(op, a) => self.unary(*op, a, e),
            ExprKind::Binary(op, a, b) => {
                let (x, y) = (self.expr(a)?, self.expr(b)?);
                self.binary(*op, &x, &a.ty, &y, &b.ty, &e.ty)
            }
            ExprKind::Assign(op, l, r) => {
                let rv = self.expr(r)?;
                let v = match op {
                    None => rv,
                    Some(op) => {
                        let lv = self.expr(l)?;
                        self.binary(*op, &lv, &l.ty, &rv, &r.ty, &l.ty)?
                    }
                };
                self.store(l, &v)?;
                Ok(v)
            }
            ExprKind::Ternary(c, a, b) => {
                let cv = self.expr(c)?[0];
                if let Some(k) = self.cval(cv) {
                    return self.expr(if k != 0 { a } else { b });
                }
                let (x, y) = (self.expr(a)?, self.expr(b)?);
                Ok(x.iter()
                    .zip(&y)
                    .map(|(&p, &q)| self.op(Op::Select(cv, p, q)))
                    .collect())
            }
            ExprKind::Comma(a, b) => {
                self.expr(a)?;
                self.expr(b)
            }
            ExprKind::Index(base, idx) => {
                let bv = self.expr(base)?;
                let iv = self.expr(idx)?[0];
                let stride = element_size(&base.ty)?;
                match self.cval(iv) {
                    Some(k) => {
                        let k = k as i32 as usize;
                        if (k + 1) * stride > bv.len() {
                            return no("an index out of range");
                        }
                        Ok(bv[k * stride..(k + 1) * stride].to_vec())
                    }
                    None => self.dynamic_index(&bv, stride, iv),
                }
            }
            ExprKind::Field(base, k) => {
                let bv = self.expr(base)?;
                let (off, n) = field_range(&base.ty, *k)?;
                Ok(bv[off..off + n].to_vec())
            }
            ExprKind::Swizzle(base, comps) => {
                let bv = self.expr(base)?;
                Ok(comps.iter().map(|&c| bv[c as usize]).collect())
            }
            ExprKind::Convert(a) => {
                let v = self.expr(a)?;
                let to = e.ty.scalar().unwrap_or(Scalar::Float);
                let from = a.ty.scalar().unwrap_or(Scalar::Float);
                Ok(v.iter().map(|&x| self.convert(x, from, to)).collect())
            }
            ExprKind::Construct(args) => self.construct(&e.ty, args),
            ExprKind::Builtin(f, args)
                if args
                    .first()
                    .is_some_and(|a| matches!(a.ty, Type::Sampler(_))) =>
            {
                self.texture(&f.name, args, &e.ty)
            }
            ExprKind::Builtin(f, args) => {
                let mut vals = Vec::new();
                for a in args {
                    vals.push(self.expr(a)?);
                }
                builtins::call(self, &f.name, args, &vals, &e.ty)
            }
            ExprKind::Call(fid, args) => self.call(*fid, args),
            ExprKind::Length(_) => no("length() of an unsized array"),
        }
    }

    /// Element `iv` (not constant) of `bv` in elements of `stride` components: a chain of
    /// selects over the elements.
    fn dynamic_index(&mut self, bv: &[Val], stride: usize, iv: Val) -> R<Vec<Val>> {
        let n = bv.len() / stride;
        let mut out = bv[..stride].to_vec();
        for k in 1..n {
            let kv = self.i32(k as i32);
            let m = self.op(Op::SCmp(FCmp::Eq, iv, kv));
            for (c, o) in out.iter_mut().enumerate() {
                *o = self.op(Op::Select(m, bv[k * stride + c], *o));
            }
        }
        Ok(out)
    }

    /// Writes `v` to the l-value `l`.
    pub(super) fn store(&mut self, l: &Expr, v: &[Val]) -> R<()> {
        let (var, idx) = self.place(l)?;
        self.write(var, &idx, v)
    }

    /// The variable and component indices an l-value names.
    fn place(&mut self, l: &Expr) -> R<(VarId, Vec<usize>)> {
        match &l.kind {
            ExprKind::Var(id) => {
                // `gl_TexCoord[]` is unsized: it has TEX_COORDS elements (as `read_var`).
                let n = match &l.ty {
                    Type::Array(t, None) if self.p.vars[*id].name == "gl_TexCoord" => {
                        size(t)? * TEX_COORDS as usize
                    }
                    ty => size(ty)?,
                };
                Ok((*id, (0..n).collect()))
            }
            ExprKind::Swizzle(b, comps) => {
                let (v, idx) = self.place(b)?;
                Ok((v, comps.iter().map(|&c| idx[c as usize]).collect()))
            }
            ExprKind::Index(b, i) => {
                let (v, idx) = self.place(b)?;
                let iv = self.expr(i)?[0];
                let Some(k) = self.cval(iv) else {
                    return no("an assignment through a varying index");
                };
                let s = element_size(&b.ty)?;
                let k = k as i32 as usize;
                idx.get(k * s..(k + 1) * s)
                    .map(|r| (v, r.to_vec()))
                    .ok_or_else(|| Unsupported("an index out of range".into()))
            }
            ExprKind::Field(b, k) => {
                let (v, idx) = self.place(b)?;
                let (off, n) = field_range(&b.ty, *k)?;
                Ok((v, idx[off..off + n].to_vec()))
            }
            _ => no("this kind of l-value"),
        }
    }

    fn unary(&mut self, op: UnOp, a: &Expr, e: &Expr) -> R<Vec<Val>> {
        let v = self.expr(a)?;
        let s = a.ty.scalar().unwrap_or(Scalar::Float);
        match op {
            UnOp::Plus => Ok(v),
            UnOp::Neg => Ok(v.iter().map(|&x| self.neg(x, s)).collect()),
            UnOp::Not | UnOp::BitNot => {
                let ones = if s == Scalar::Bool {
                    self.mask(true)
                } else {
                    self.i32(-1)
                };
                Ok(v.iter().map(|&x| self.op(Op::Xor(x, ones))).collect())
            }
            UnOp::PreInc | UnOp::PreDec | UnOp::PostInc | UnOp::PostDec => {
                let one = [match s {
                    Scalar::Float => self.f32(1.0),
                    _ => self.i32(1),
                }];
                let bop = if matches!(op, UnOp::PreInc | UnOp::PostInc) {
                    BinOp::Add
                } else {
                    BinOp::Sub
                };
                let st = Type::Scalar(s);
                let next = self.binary(bop, &v, &a.ty, &one, &st, &e.ty)?;
                self.store(a, &next)?;
                Ok(if matches!(op, UnOp::PreInc | UnOp::PreDec) {
                    next
                } else {
                    v
                })
            }
        }
    }

    /// `-x` of scalar type `s`.
    pub(super) fn neg(&mut self, x: Val, s: Scalar) -> Val {
        if s == Scalar::Float {
            self.op(Op::Un(Un::Neg, x))
        } else {
            let z = self.i32(0);
            self.op(Op::IBin(IOp::Sub, z, x))
        }
    }

    /// `float(u)` of a uint, rounded once as LLVM's `uitofp` is: values from 2^31 up
    /// are halved with their lowest bit kept as a sticky bit, converted and doubled.
    fn u2f(&mut self, x: Val) -> Val {
        let (one, zero) = (self.i32(1), self.i32(0));
        let half = self.op(Op::IBin(IOp::UShr, x, one));
        let low = self.op(Op::And(x, one));
        let sticky = self.op(Op::Or(half, low));
        let f = self.op(Op::ItoF(sticky));
        let two = self.f32(2.0);
        let big = self.op(Op::Mul(f, two));
        let small = self.op(Op::ItoF(x));
        let high = self.op(Op::SCmp(FCmp::Lt, x, zero));
        self.op(Op::Select(high, big, small))
    }

    /// `uint(f)`, as LLVM lowers `fptoui` without AVX-512: from 2^31 up, the truncation
    /// of `f − 2^31` with the top bit set; below, the signed truncation.
    fn f2u(&mut self, x: Val) -> Val {
        let limit = self.f32(2_147_483_648.0);
        let shifted = self.op(Op::Sub(x, limit));
        let t = self.op(Op::FtoI(shifted));
        let top = self.i32(i32::MIN);
        let big = self.op(Op::Xor(t, top));
        let small = self.op(Op::FtoI(x));
        let high = self.op(Op::FCmp(FCmp::Ge, x, limit));
        self.op(Op::Select(high, big, small))
    }

    /// Converts one component between scalar types.
    pub(super) fn convert(&mut self, x: Val, from: Scalar, to: Scalar) -> Val {
        use Scalar::*;
        match (from, to) {
            (Float, Float) | (Bool, Bool) | (Int | Uint, Int | Uint) => x,
            (Int, Float) => self.op(Op::ItoF(x)),
            (Uint, Float) => self.u2f(x),
            (Float, Int) => self.op(Op::FtoI(x)),
            (Float, Uint) => self.f2u(x),
            (Bool, Float) => {
                let (one, zero) = (self.f32(1.0), self.f32(0.0));
                self.op(Op::Select(x, one, zero))
            }
            (Bool, _) => {
                let (one, zero) = (self.i32(1), self.i32(0));
                self.op(Op::Select(x, one, zero))
            }
            (Float, Bool) => {
                let zero = self.f32(0.0);
                self.op(Op::FCmp(FCmp::Ne, x, zero))
            }
            (_, Bool) => {
                let zero = self.i32(0);
                self.op(Op::SCmp(FCmp::Ne, x, zero))
            }
        }
    }

    fn construct(&mut self, ty: &Type, args: &[Expr]) -> R<Vec<Val>> {
        let mut flat = Vec::new();
        let mut whole = Vec::new();
        let to = ty.scalar();
        for a in args {
            let v = self.expr(a)?;
            let from = a.ty.scalar().unwrap_or(Scalar::Float);
            let v: Vec<Val> = match to {
                Some(t) => v.iter().map(|&x| self.convert(x, from, t)).collect(),
                None => v,
            };
            whole.push(v.clone());
            flat.extend(v);
        }
        let n = size(ty)?;
        match ty {
            Type::Matrix { cols, rows } => {
                let (cols, rows) = (*cols as usize, *rows as usize);
                let zero = self.f32(0.0);
                let one = self.f32(1.0);
                if args.len() == 1 && args[0].ty.components() == 1 {
                    let d = flat[0];
                    return Ok((0..n)
                        .map(|k| if k / rows == k % rows { d } else { zero })
                        .collect());
                }
                if let (1, Type::Matrix { cols: c0, rows: r0 }) = (args.len(), &args[0].ty) {
                    let (c0, r0) = (*c0 as usize, *r0 as usize);
                    return Ok((0..n)
                        .map(|k| {
                            let (c, r) = (k / rows, k % rows);
                            if c < c0 && r < r0 {
                                flat[c * r0 + r]
                            } else if c == r {
                                one
                            } else {
                                zero
                            }
                        })
                        .collect());
                }
                let _ = cols;
                Ok(flat.into_iter().take(n).collect())
            }
            Type::Scalar(_) | Type::Vector(..) => {
                if flat.len() == 1 {
                    Ok(vec![flat[0]; n])
                } else {
                    Ok(flat.into_iter().take(n).collect())
                }
            }
            _ => Ok(whole.concat()),
        }
    }
}

/// The components of one element of an indexed type (array element, matrix column,
/// vector component).
fn element_size(ty: &Type) -> R<usize> {
    match ty {
        Type::Array(t, _) => size(t),
        Type::Matrix { rows, .. } => Ok(*rows as usize),
        Type::Vector(..) => Ok(1),
        _ => no("indexing this type"),
    }
}

/// The offset and size of member `k` of a struct type.
fn field_range(ty: &Type, k: usize) -> R<(usize, usize)> {
    let Type::Struct(s) = ty else {
        return no("a field of a non-struct");
    };
    let mut off = 0;
    for m in &s.members[..k] {
        off += size(&m.ty)?;
    }
    Ok((off, size(&s.members[k].ty)?))
}
