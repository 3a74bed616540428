//! Constructors (GLSL 5.4): scalars, vectors and matrices from components (with
//! conversion of every component to the constructed base type), a matrix from a
//! matrix (from 1.20), structs member by member (with the version's implicit
//! conversions) and arrays (from 1.20, element by element). Opaque types cannot be
//! constructed. The messages are Mesa's (`ast_function.cpp`).

use super::expr::node;
use super::{fold, Checker};
use crate::diag::Pos;
use crate::hir::{Const, Expr, ExprKind, Value};
use crate::types::{Scalar, Type};

impl Checker<'_> {
    /// A constructor of `ty` from `args`.
    pub(super) fn construct(&mut self, ty: Type, args: Vec<Expr>, pos: Pos) -> Option<Expr> {
        match &ty {
            Type::Sampler(_) => {
                self.error(pos, format!("cannot construct opaque type `{ty}'"));
                None
            }
            Type::Void => {
                self.error(pos, "cannot construct `void' type");
                None
            }
            Type::Array(e, n) => self.array_ctor((**e).clone(), *n, args, pos),
            Type::Struct(s) => {
                if super::decl::contains_opaque(&ty) {
                    self.error(pos, format!("cannot construct opaque type `{ty}'"));
                    return None;
                }
                let s = s.clone();
                if args.len() < s.members.len() {
                    self.error(
                        pos,
                        format!("insufficient parameters in constructor for `{}'", s.name),
                    );
                    return None;
                }
                if args.len() > s.members.len() {
                    self.error(
                        pos,
                        format!("too many parameters in constructor for `{}'", s.name),
                    );
                    return None;
                }
                let mut out = Vec::new();
                for (a, m) in args.into_iter().zip(&s.members) {
                    let found = a.ty.clone();
                    match self.convert(a, &m.ty) {
                        Some(a) => out.push(a),
                        None => {
                            self.error(
                                pos,
                                format!(
                                    "parameter type mismatch in constructor for `{}.{}' ({} vs {})",
                                    s.name, m.name, found, m.ty
                                ),
                            );
                            return None;
                        }
                    }
                }
                let value: Option<Vec<Const>> = out.iter().map(|a| a.value.clone()).collect();
                let mut x = node(ExprKind::Construct(out), ty, pos);
                x.value = value.map(Const::Aggregate);
                Some(x)
            }
            _ => self.basic_ctor(ty, args, pos),
        }
    }

    fn array_ctor(
        &mut self,
        elem: Type,
        n: Option<u32>,
        args: Vec<Expr>,
        pos: Pos,
    ) -> Option<Expr> {
        if !self.require(
            120,
            pos,
            "array constructors forbidden",
            "GLSL 1.20 or GLSL ES 3.00",
        ) {
            return None;
        }
        let len = n.unwrap_or(args.len() as u32);
        if args.len() as u32 != len || len == 0 {
            self.error(
                pos,
                format!("array constructor must have exactly {len} parameters"),
            );
            return None;
        }
        let mut out = Vec::new();
        for a in args {
            let found = a.ty.clone();
            match self.convert(a, &elem) {
                Some(a) => out.push(a),
                None => {
                    self.error(
                        pos,
                        format!("type error in array constructor: expected: {elem}, found {found}"),
                    );
                    return None;
                }
            }
        }
        let value: Option<Vec<Const>> = out.iter().map(|a| a.value.clone()).collect();
        let mut x = node(ExprKind::Construct(out), elem.array(Some(len)), pos);
        x.value = value.map(Const::Aggregate);
        Some(x)
    }

    fn basic_ctor(&mut self, ty: Type, args: Vec<Expr>, pos: Pos) -> Option<Expr> {
        let want = ty.components();
        let base = ty.scalar().unwrap_or(Scalar::Float);
        let is_mat = matches!(ty, Type::Matrix { .. });
        let mut used = 0u32;
        let mut has_matrix = false;
        for a in &args {
            if !matches!(
                a.ty,
                Type::Scalar(_) | Type::Vector(..) | Type::Matrix { .. }
            ) {
                self.error(
                    pos,
                    format!("cannot construct `{ty}' from a non-numeric data type"),
                );
                return None;
            }
            if used >= want {
                self.error(pos, format!("too many parameters to `{ty}' constructor"));
                return None;
            }
            has_matrix |= matches!(a.ty, Type::Matrix { .. });
            used += a.ty.components();
        }
        if is_mat && has_matrix {
            if args.len() != 1 {
                self.error(
                    pos,
                    format!("for matrix `{ty}' constructor, matrix must be only parameter"),
                );
                return None;
            }
            if !self.require(
                120,
                pos,
                &format!("cannot construct `{ty}' from a matrix"),
                "GLSL 1.20 or GLSL ES 1.00",
            ) {
                return None;
            }
        } else if used < want && !(used == 1 && args.len() == 1) {
            self.error(pos, format!("too few components to construct `{ty}'"));
            return None;
        }
        // Fold: every argument constant.
        let comps: Option<Vec<Vec<Value>>> = args
            .iter()
            .map(|a| a.value.as_ref().and_then(fold::comps).map(|c| c.to_vec()))
            .collect();
        let value = comps.and_then(|c| fold_ctor(&ty, base, &args, &c));
        let mut x = node(ExprKind::Construct(args), ty, pos);
        x.value = value;
        Some(x)
    }
}

/// The value of a constructor of scalars, vectors and matrices from constants.
fn fold_ctor(ty: &Type, base: Scalar, args: &[Expr], comps: &[Vec<Value>]) -> Option<Const> {
    let want = ty.components() as usize;
    let conv = |v: &Value| fold::convert(*v, base);
    if comps.len() == 1 && comps[0].len() == 1 {
        let v = conv(&comps[0][0]);
        return Some(Const::Scalars(match ty {
            Type::Matrix { cols, rows } => {
                let zero = fold::convert(Value::Float(0.0), base);
                (0..*cols as usize)
                    .flat_map(|c| (0..*rows as usize).map(move |r| if c == r { v } else { zero }))
                    .collect()
            }
            _ => vec![v; want],
        }));
    }
    if let (
        Type::Matrix { cols, rows },
        [Expr {
            ty: Type::Matrix { cols: c2, rows: r2 },
            ..
        }],
    ) = (ty, args)
    {
        let src = &comps[0];
        let mut out = Vec::with_capacity(want);
        for c in 0..*cols as usize {
            for r in 0..*rows as usize {
                out.push(if c < *c2 as usize && r < *r2 as usize {
                    src[c * *r2 as usize + r]
                } else {
                    Value::Float(if c == r { 1.0 } else { 0.0 })
                });
            }
        }
        return Some(Const::Scalars(out));
    }
    let flat: Vec<Value> = comps.iter().flatten().take(want).map(conv).collect();
    (flat.len() == want).then_some(Const::Scalars(flat))
}
