//! Constant folding (GLSL 4.3.3, constant expressions): literals, `const` variables
//! and built-in constants, operators on them, constructors, swizzles and indexing, and
//! the built-in functions Mesa evaluates on constants (the component-wise math of
//! chapter 8: `max`, `min`, `abs`, `sin`, `sqrt`, `clamp`...).
//!
//! Values are [`Const`]: the scalar components of a scalar, vector or matrix (column
//! by column) or the parts of an array or struct. Integer arithmetic wraps, as the
//! GPU's does; division by zero is not folded (the expression is then not constant).

use crate::ast::{BinOp, UnOp};
use crate::hir::{Const, Value};
use crate::types::{Scalar, Type};

/// The scalar components of a scalar, vector or matrix constant.
pub fn comps(c: &Const) -> Option<&[Value]> {
    match c {
        Const::Scalars(v) => Some(v),
        Const::Aggregate(_) => None,
    }
}

/// A value as f32.
pub fn as_f32(v: Value) -> f32 {
    match v {
        Value::Bool(b) => b as u8 as f32,
        Value::Int(i) => i as f32,
        Value::Uint(u) => u as f32,
        Value::Float(f) => f,
    }
}

/// A value converted to the scalar type `s` (constructor rules: non-zero is true,
/// floats truncate toward zero).
pub fn convert(v: Value, s: Scalar) -> Value {
    match s {
        Scalar::Float => Value::Float(as_f32(v)),
        Scalar::Bool => Value::Bool(match v {
            Value::Bool(b) => b,
            Value::Int(i) => i != 0,
            Value::Uint(u) => u != 0,
            Value::Float(f) => f != 0.0,
        }),
        Scalar::Int => Value::Int(match v {
            Value::Bool(b) => b as i32,
            Value::Int(i) => i,
            Value::Uint(u) => u as i32,
            Value::Float(f) => f as i32,
        }),
        Scalar::Uint => Value::Uint(match v {
            Value::Bool(b) => b as u32,
            Value::Int(i) => i as u32,
            Value::Uint(u) => u,
            Value::Float(f) => f as i32 as u32,
        }),
    }
}

/// Converts every component of `c` to `s`.
pub fn convert_all(c: &Const, s: Scalar) -> Option<Const> {
    Some(Const::Scalars(
        comps(c)?.iter().map(|v| convert(*v, s)).collect(),
    ))
}

/// The integer value of a scalar int or uint constant.
pub fn as_int(c: &Const) -> Option<i64> {
    match comps(c)? {
        [Value::Int(i)] => Some(*i as i64),
        [Value::Uint(u)] => Some(*u as i64),
        _ => None,
    }
}

/// The unary operator `op` on a constant.
pub fn unary(op: UnOp, c: &Const) -> Option<Const> {
    let v = comps(c)?;
    let out: Option<Vec<Value>> = v
        .iter()
        .map(|x| match (op, *x) {
            (UnOp::Plus, x) => Some(x),
            (UnOp::Neg, Value::Int(i)) => Some(Value::Int(i.wrapping_neg())),
            (UnOp::Neg, Value::Uint(u)) => Some(Value::Uint(u.wrapping_neg())),
            (UnOp::Neg, Value::Float(f)) => Some(Value::Float(-f)),
            (UnOp::Not, Value::Bool(b)) => Some(Value::Bool(!b)),
            (UnOp::BitNot, Value::Int(i)) => Some(Value::Int(!i)),
            (UnOp::BitNot, Value::Uint(u)) => Some(Value::Uint(!u)),
            _ => None,
        })
        .collect();
    out.map(Const::Scalars)
}

fn scalar_op(op: BinOp, a: Value, b: Value) -> Option<Value> {
    use Value::*;
    Some(match (a, b) {
        (Int(x), Int(y)) => match op {
            BinOp::Add => Int(x.wrapping_add(y)),
            BinOp::Sub => Int(x.wrapping_sub(y)),
            BinOp::Mul => Int(x.wrapping_mul(y)),
            BinOp::Div if y != 0 => Int(x.wrapping_div(y)),
            BinOp::Mod if y != 0 => Int(x.wrapping_rem(y)),
            BinOp::BitAnd => Int(x & y),
            BinOp::BitOr => Int(x | y),
            BinOp::BitXor => Int(x ^ y),
            BinOp::Shl => Int(x.wrapping_shl(y as u32)),
            BinOp::Shr => Int(x.wrapping_shr(y as u32)),
            BinOp::Lt => Bool(x < y),
            BinOp::Gt => Bool(x > y),
            BinOp::Le => Bool(x <= y),
            BinOp::Ge => Bool(x >= y),
            _ => return None,
        },
        (Uint(x), Uint(y)) => match op {
            BinOp::Add => Uint(x.wrapping_add(y)),
            BinOp::Sub => Uint(x.wrapping_sub(y)),
            BinOp::Mul => Uint(x.wrapping_mul(y)),
            BinOp::Div if y != 0 => Uint(x / y),
            BinOp::Mod if y != 0 => Uint(x % y),
            BinOp::BitAnd => Uint(x & y),
            BinOp::BitOr => Uint(x | y),
            BinOp::BitXor => Uint(x ^ y),
            BinOp::Shl => Uint(x.wrapping_shl(y)),
            BinOp::Shr => Uint(x.wrapping_shr(y)),
            BinOp::Lt => Bool(x < y),
            BinOp::Gt => Bool(x > y),
            BinOp::Le => Bool(x <= y),
            BinOp::Ge => Bool(x >= y),
            _ => return None,
        },
        // Shifts may mix int and uint operands.
        (Int(x), Uint(y)) if matches!(op, BinOp::Shl | BinOp::Shr) => {
            return scalar_op(op, Int(x), Int(y as i32))
        }
        (Uint(x), Int(y)) if matches!(op, BinOp::Shl | BinOp::Shr) => {
            return scalar_op(op, Uint(x), Uint(y as u32))
        }
        (Float(x), Float(y)) => match op {
            BinOp::Add => Float(x + y),
            BinOp::Sub => Float(x - y),
            BinOp::Mul => Float(x * y),
            BinOp::Div => Float(x / y),
            BinOp::Lt => Bool(x < y),
            BinOp::Gt => Bool(x > y),
            BinOp::Le => Bool(x <= y),
            BinOp::Ge => Bool(x >= y),
            _ => return None,
        },
        (Bool(x), Bool(y)) => match op {
            BinOp::And => Bool(x && y),
            BinOp::Or => Bool(x || y),
            BinOp::Xor => Bool(x != y),
            _ => return None,
        },
        _ => return None,
    })
}

/// The binary operator `op` on constants of types `ta` and `tb` (already converted to
/// one base type): component-wise with a scalar spread over the
/// other operand, the linear-algebra product for `*` with a matrix, and `==`/`!=` on
/// whole values.
pub fn binary(op: BinOp, a: &Const, ta: &Type, b: &Const, tb: &Type) -> Option<Const> {
    if matches!(op, BinOp::Eq | BinOp::Ne) {
        let eq = a == b;
        return Some(Const::Scalars(vec![Value::Bool(eq == (op == BinOp::Eq))]));
    }
    let (x, y) = (comps(a)?, comps(b)?);
    let is_mat = |t: &Type| matches!(t, Type::Matrix { .. });
    if op == BinOp::Mul && (is_mat(ta) || is_mat(tb)) {
        // Vector * matrix: the vector is a row (1 x n); matrix * vector: a column.
        let (ar, ac) = match ta {
            Type::Matrix { cols, rows } => (*rows as usize, *cols as usize),
            Type::Vector(_, n) => (1, *n as usize),
            _ => return None,
        };
        let (br, bc) = match tb {
            Type::Matrix { cols, rows } => (*rows as usize, *cols as usize),
            Type::Vector(_, n) => (*n as usize, 1),
            _ => return None,
        };
        if ac != br || x.len() != ar * ac || y.len() != br * bc {
            return None;
        }
        let mut out = Vec::with_capacity(ar * bc);
        for j in 0..bc {
            for i in 0..ar {
                let mut s = 0.0f32;
                for k in 0..ac {
                    s += as_f32(x[k * ar + i]) * as_f32(y[j * br + k]);
                }
                out.push(Value::Float(s));
            }
        }
        return Some(Const::Scalars(out));
    }
    let n = x.len().max(y.len());
    let mut out = Vec::with_capacity(n);
    for i in 0..n {
        let u = if x.len() == 1 { x[0] } else { *x.get(i)? };
        let v = if y.len() == 1 { y[0] } else { *y.get(i)? };
        out.push(scalar_op(op, u, v)?);
    }
    Some(Const::Scalars(out))
}

/// Component `i` selection (swizzle) of a constant.
pub fn swizzle(c: &Const, idx: &[u8]) -> Option<Const> {
    let v = comps(c)?;
    let out: Option<Vec<Value>> = idx.iter().map(|i| v.get(*i as usize).copied()).collect();
    out.map(Const::Scalars)
}

/// Element `i` of an array constant, column `i` of a matrix or component `i` of a
/// vector.
pub fn index(c: &Const, ty: &Type, i: i64) -> Option<Const> {
    let i = usize::try_from(i).ok()?;
    match (c, ty) {
        (Const::Aggregate(v), _) => v.get(i).cloned(),
        (Const::Scalars(v), Type::Matrix { rows, .. }) => {
            let r = *rows as usize;
            v.get(i * r..i * r + r).map(|s| Const::Scalars(s.to_vec()))
        }
        (Const::Scalars(v), _) => v.get(i).map(|x| Const::Scalars(vec![*x])),
    }
}

/// A built-in function applied to constant arguments, for the component-wise math
/// functions Mesa folds; `None` for the others.
pub fn builtin(name: &str, args: &[&Const], ret: &Type) -> Option<Const> {
    let a: Vec<&[Value]> = args.iter().map(|c| comps(c)).collect::<Option<_>>()?;
    let n = ret.components() as usize;
    if n == 0 || a.is_empty() {
        return None;
    }
    let get = |k: usize, i: usize| -> Option<Value> {
        let v = a.get(k)?;
        if v.len() == 1 {
            Some(v[0])
        } else {
            v.get(i).copied()
        }
    };
    let f1 = |f: fn(f32) -> f32| -> Option<Const> {
        (0..n)
            .map(|i| match get(0, i)? {
                Value::Float(x) => Some(Value::Float(f(x))),
                _ => None,
            })
            .collect::<Option<Vec<_>>>()
            .map(Const::Scalars)
    };
    match name {
        "sin" => f1(f32::sin),
        "cos" => f1(f32::cos),
        "tan" => f1(f32::tan),
        "sqrt" => f1(f32::sqrt),
        "exp" => f1(f32::exp),
        "log" => f1(f32::ln),
        "exp2" => f1(f32::exp2),
        "log2" => f1(f32::log2),
        "floor" => f1(f32::floor),
        "ceil" => f1(f32::ceil),
        "fract" => f1(|x| x - x.floor()),
        "radians" => f1(f32::to_radians),
        "degrees" => f1(f32::to_degrees),
        "abs" | "min" | "max" | "clamp" | "sign" => {
            let mut out = Vec::with_capacity(n);
            for i in 0..n {
                let x = get(0, i)?;
                let v = match name {
                    "abs" => match x {
                        Value::Float(f) => Value::Float(f.abs()),
                        Value::Int(k) => Value::Int(k.wrapping_abs()),
                        _ => return None,
                    },
                    "sign" => match x {
                        Value::Float(f) => Value::Float(if f > 0.0 {
                            1.0
                        } else if f < 0.0 {
                            -1.0
                        } else {
                            0.0
                        }),
                        Value::Int(k) => Value::Int(k.signum()),
                        _ => return None,
                    },
                    "min" | "max" => {
                        let y = get(1, i)?;
                        let lt = matches!(scalar_op(BinOp::Lt, x, y)?, Value::Bool(true));
                        if (name == "min") == lt {
                            x
                        } else {
                            y
                        }
                    }
                    _ => {
                        let (lo, hi) = (get(1, i)?, get(2, i)?);
                        let m = if matches!(scalar_op(BinOp::Lt, x, lo)?, Value::Bool(true)) {
                            lo
                        } else {
                            x
                        };
                        if matches!(scalar_op(BinOp::Gt, m, hi)?, Value::Bool(true)) {
                            hi
                        } else {
                            m
                        }
                    }
                };
                out.push(v);
            }
            Some(Const::Scalars(out))
        }
        _ => None,
    }
}
