//! Operator typing (GLSL 5.9, 5.10, 5.11): arithmetic with scalar/vector spreading and
//! the linear-algebra `*`, integer `%`, bit-wise and shift operators (from 1.30),
//! relational operators on scalars, equality on whole values, logical operators on
//! scalar `bool`, and the unary operators with `++`/`--` on numeric l-values. The
//! implicit conversions are the version's (`Type::converts_to`); the messages are
//! those of Mesa's `arithmetic_result_type` and friends.

use super::expr::node;
use super::{fold, Checker};
use crate::ast::{BinOp, UnOp};
use crate::diag::Pos;
use crate::hir::{Expr, ExprKind};
use crate::types::{Scalar, Type};

/// Whether a type is a numeric scalar, vector or matrix (not bool).
fn numeric(t: &Type) -> bool {
    matches!(
        t,
        Type::Scalar(s) | Type::Vector(s, _) if *s != Scalar::Bool
    ) || matches!(t, Type::Matrix { .. })
}

/// Whether a type is an integer scalar or vector.
fn integer(t: &Type) -> bool {
    matches!(
        t,
        Type::Scalar(Scalar::Int | Scalar::Uint) | Type::Vector(Scalar::Int | Scalar::Uint, _)
    )
}

/// The operator's text.
fn text(op: BinOp) -> &'static str {
    crate::ast::BINOPS
        .iter()
        .find(|(_, _, o)| *o == op)
        .map(|(t, _, _)| *t)
        .unwrap_or("?")
}

impl Checker<'_> {
    /// The operator's text in messages: with `=` inside a compound assignment.
    fn op_text(&self, op: BinOp) -> String {
        format!("{}{}", text(op), if self.compound { "=" } else { "" })
    }

    /// Converts `a` and `b` to one base type (int or uint to float); `None` when they
    /// cannot be.
    fn unify(&self, a: Expr, b: Expr) -> Option<(Expr, Expr)> {
        let (sa, sb) = (a.ty.scalar()?, b.ty.scalar()?);
        if sa == sb {
            return Some((a, b));
        }
        let widen = |c: &Checker, x: Expr, s: Scalar| {
            let to = match &x.ty {
                Type::Scalar(_) => Type::Scalar(s),
                Type::Vector(_, n) => Type::Vector(s, *n),
                t => t.clone(),
            };
            c.convert(x, &to)
        };
        if sb == Scalar::Float {
            Some((widen(self, a, sb)?, b))
        } else if sa == Scalar::Float {
            let b = widen(self, b, sa)?;
            Some((a, b))
        } else {
            None
        }
    }

    /// A unary operation.
    pub(super) fn unary(&mut self, op: UnOp, x: Expr, pos: Pos) -> Option<Expr> {
        let ty = x.ty.clone();
        match op {
            UnOp::Plus | UnOp::Neg if !numeric(&ty) => {
                self.error(pos, "operands to arithmetic operators must be numeric");
                return None;
            }
            UnOp::Not if ty != Type::BOOL => {
                self.error(pos, "operand of `!' must be scalar boolean");
                return None;
            }
            UnOp::BitNot if !self.at_least(130) => {
                let vt = self.version_text();
                self.error(pos, format!("bit-wise operations are forbidden in {vt} (GLSL 1.30 or GLSL ES 3.00 required)"));
                return None;
            }
            UnOp::BitNot if !integer(&ty) => {
                self.error(pos, "operand of `~' must be an integer");
                return None;
            }
            UnOp::PreInc | UnOp::PreDec | UnOp::PostInc | UnOp::PostDec => {
                if !numeric(&ty) {
                    self.error(pos, "operands to arithmetic operators must be numeric");
                    return None;
                }
                if !self.assignable(&x, pos) {
                    return None;
                }
            }
            _ => {}
        }
        let value = match op {
            UnOp::Plus | UnOp::Neg | UnOp::Not | UnOp::BitNot => {
                x.value.as_ref().and_then(|c| fold::unary(op, c))
            }
            _ => None,
        };
        let mut n = node(ExprKind::Unary(op, Box::new(x)), ty, pos);
        n.value = value;
        Some(n)
    }

    /// A binary operation.
    pub(super) fn binary(&mut self, op: BinOp, a: Expr, b: Expr, pos: Pos) -> Option<Expr> {
        let ty = match op {
            BinOp::Add | BinOp::Sub | BinOp::Mul | BinOp::Div => {
                return self.arithmetic(op, a, b, pos);
            }
            BinOp::Mod => {
                if !self.require(
                    130,
                    pos,
                    "operator '%' is reserved",
                    "GLSL 1.30 or GLSL ES 3.00",
                ) {
                    return None;
                }
                if !integer(&a.ty) {
                    self.error(pos, "LHS of operator % must be an integer");
                    return None;
                }
                if !integer(&b.ty) {
                    self.error(pos, "RHS of operator % must be an integer");
                    return None;
                }
                return self.arithmetic(op, a, b, pos);
            }
            BinOp::BitAnd | BinOp::BitOr | BinOp::BitXor | BinOp::Shl | BinOp::Shr => {
                if !self.require(
                    130,
                    pos,
                    "bit-wise operations are forbidden",
                    "GLSL 1.30 or GLSL ES 3.00",
                ) {
                    return None;
                }
                let t = self.op_text(op);
                if matches!(op, BinOp::Shl | BinOp::Shr) {
                    if !integer(&a.ty) {
                        self.error(
                            pos,
                            format!("LHS of operator {t} must be an integer or integer vector"),
                        );
                        return None;
                    }
                    if !integer(&b.ty) {
                        self.error(
                            pos,
                            format!("RHS of operator {t} must be an integer or integer vector"),
                        );
                        return None;
                    }
                    match (&a.ty, &b.ty) {
                        (Type::Scalar(_), Type::Vector(..)) => {
                            self.error(pos, format!("if the first operand of {t} is scalar, the second must be scalar as well"));
                            return None;
                        }
                        (Type::Vector(_, n), Type::Vector(_, m)) if n != m => {
                            self.error(pos, format!("vector operands to operator {t} must have same number of elements"));
                            return None;
                        }
                        _ => {}
                    }
                    a.ty.clone()
                } else {
                    if !integer(&a.ty) {
                        self.error(pos, format!("LHS of `{t}' must be an integer"));
                        return None;
                    }
                    if !integer(&b.ty) {
                        self.error(pos, format!("RHS of `{t}' must be an integer"));
                        return None;
                    }
                    if a.ty.scalar() != b.ty.scalar() {
                        self.error(
                            pos,
                            format!("could not implicitly convert operands to `{t}` operator"),
                        );
                        return None;
                    }
                    match (&a.ty, &b.ty) {
                        (Type::Vector(_, n), Type::Vector(_, m)) if n != m => {
                            self.error(
                                pos,
                                format!("operands of `{t}' cannot be vectors of different sizes"),
                            );
                            return None;
                        }
                        (Type::Scalar(_), t) => t.clone(),
                        (t, _) => t.clone(),
                    }
                }
            }
            BinOp::And | BinOp::Or | BinOp::Xor => {
                let t = self.op_text(op);
                if a.ty != Type::BOOL {
                    self.error(a.pos, format!("LHS of `{t}' must be scalar boolean"));
                    return None;
                }
                if b.ty != Type::BOOL {
                    self.error(b.pos, format!("RHS of `{t}' must be scalar boolean"));
                    return None;
                }
                Type::BOOL
            }
            BinOp::Lt | BinOp::Gt | BinOp::Le | BinOp::Ge => {
                let scalar_num = |t: &Type| matches!(t, Type::Scalar(s) if *s != Scalar::Bool);
                if !scalar_num(&a.ty) || !scalar_num(&b.ty) {
                    self.error(
                        pos,
                        "operands to relational operators must be scalar and numeric",
                    );
                    return None;
                }
                let Some((a, b)) = self.unify(a, b) else {
                    self.error(
                        pos,
                        "could not implicitly convert operands to relational operator",
                    );
                    return None;
                };
                return Some(self.fold_binary(op, a, b, Type::BOOL, pos));
            }
            BinOp::Eq | BinOp::Ne => {
                let t = self.op_text(op);
                let (a, b) = if a.ty == b.ty {
                    (a, b)
                } else {
                    match (
                        self.convert(a.clone(), &b.ty),
                        self.convert(b.clone(), &a.ty),
                    ) {
                        (Some(a2), _) => (a2, b),
                        (_, Some(b2)) => (a, b2),
                        _ => {
                            self.error(pos, format!("operands of `{t}' must have the same type"));
                            return None;
                        }
                    }
                };
                if super::decl::contains_opaque(&a.ty) || a.ty == Type::Void {
                    self.error(pos, format!("operands of `{t}' must have the same type"));
                    return None;
                }
                if matches!(a.ty, Type::Array(..)) && !self.at_least(120) {
                    let vt = self.version_text();
                    self.error(pos, format!("array comparisons forbidden in {vt} (GLSL 1.20 or GLSL ES 3.00 required)"));
                    return None;
                }
                return Some(self.fold_binary(op, a, b, Type::BOOL, pos));
            }
        };
        Some(self.fold_binary(op, a, b, ty, pos))
    }

    fn fold_binary(&self, op: BinOp, a: Expr, b: Expr, ty: Type, pos: Pos) -> Expr {
        let value = match (&a.value, &b.value) {
            (Some(x), Some(y)) => fold::binary(op, x, &a.ty, y, &b.ty),
            _ => None,
        };
        let mut n = node(ExprKind::Binary(op, Box::new(a), Box::new(b)), ty, pos);
        n.value = value;
        n
    }

    /// `+ - * / %`: Mesa's `arithmetic_result_type`.
    fn arithmetic(&mut self, op: BinOp, a: Expr, b: Expr, pos: Pos) -> Option<Expr> {
        if !numeric(&a.ty) || !numeric(&b.ty) {
            self.error(pos, "operands to arithmetic operators must be numeric");
            return None;
        }
        let Some((a, b)) = self.unify(a, b) else {
            let what = if op == BinOp::Mod {
                "modulus (%) operator"
            } else {
                "arithmetic operator"
            };
            self.error(
                pos,
                format!("could not implicitly convert operands to {what}"),
            );
            return None;
        };
        if a.ty.scalar() != b.ty.scalar() {
            self.error(pos, "base type mismatch for arithmetic operator");
            return None;
        }
        let ty = match (&a.ty, &b.ty) {
            (Type::Scalar(_), t) | (t, Type::Scalar(_)) => t.clone(),
            (Type::Vector(_, n), Type::Vector(_, m)) => {
                if n != m {
                    // Mesa's modulus_result_type has no message of its own for this.
                    let text = if op == BinOp::Mod {
                        "type mismatch"
                    } else {
                        "vector size mismatch for arithmetic operator"
                    };
                    self.error(pos, text);
                    return None;
                }
                a.ty.clone()
            }
            _ if op != BinOp::Mul => {
                if a.ty != b.ty {
                    self.error(pos, "type mismatch");
                    return None;
                }
                a.ty.clone()
            }
            (Type::Matrix { cols, rows }, Type::Matrix { cols: c2, rows: r2 }) => {
                if cols != r2 {
                    self.error(pos, "size mismatch for matrix multiplication");
                    return None;
                }
                Type::mat(*c2, *rows)
            }
            (Type::Matrix { cols, rows }, Type::Vector(_, n)) => {
                if cols != n {
                    self.error(pos, "size mismatch for matrix multiplication");
                    return None;
                }
                Type::vec(Scalar::Float, *rows)
            }
            (Type::Vector(_, n), Type::Matrix { cols, rows }) => {
                if rows != n {
                    self.error(pos, "size mismatch for matrix multiplication");
                    return None;
                }
                Type::vec(Scalar::Float, *cols)
            }
            _ => {
                self.error(pos, "type mismatch");
                return None;
            }
        };
        Some(self.fold_binary(op, a, b, ty, pos))
    }
}
