//! GLSL operators and built-in functions as llvmpipe computes them, component by
//! component.
//!
//! The sequence of each follows Mesa 22.3's path from GLSL to machine code: the GLSL IR
//! built-in's body (`builtin_functions.cpp`), NIR's lowering with llvmpipe's options
//! (`lower_ffma32`, so no multiply-add is ever fused in shader arithmetic; `lower_flrp32`
//! with `x + t·(y − x)`; `lower_fmod` as `x − y·floor(x / y)`; `lower_fdot` as the
//! pairwise sums of products) and gallivm's code for each NIR operation (`lp_bld_nir.c`,
//! `lp_bld_arit.c`: `floor`/`ceil` as `roundps`, `fract` as `x − floor(x)`, `inversesqrt`
//! as `1 / sqrt(x)`, `sign` as `copysign(1, x)` but 0 at zero, and polynomial `exp2`,
//! `log2`, `pow`, `sin`, `cos`). `exp(x)` is `exp2(x · log2 e)` and `log(x)` is
//! `log2(x) · ln 2` (`nir_fexp`, `nir_flog`).

use super::lower::{no, Lower, R};
use crate::engine::ir::{FCmp, IOp, Op, Un, Val};
use softgl_glsl::ast::BinOp;
use softgl_glsl::hir::Expr;
use softgl_glsl::types::{Scalar, Type};

/// `log2(e)` as gallivm and NIR round it to f32.
const LOG2_E: f32 = std::f64::consts::LOG2_E as f32;
/// `1 / log2(e)` (NIR's `nir_flog`).
const INV_LOG2_E: f32 = (1.0 / std::f64::consts::LOG2_E) as f32;

impl Lower<'_> {
    /// A binary operator on components `x` (of type `xt`) and `y` (of `yt`), giving `rt`.
    pub(super) fn binary(
        &mut self,
        op: BinOp,
        x: &[Val],
        xt: &Type,
        y: &[Val],
        yt: &Type,
        rt: &Type,
    ) -> R<Vec<Val>> {
        let s = xt.scalar().unwrap_or(Scalar::Float);
        if op == BinOp::Mul {
            match (xt, yt) {
                (Type::Matrix { rows, .. }, Type::Vector(..)) => {
                    return Ok(self.mat_vec(x, *rows as usize, y));
                }
                (Type::Vector(..), Type::Matrix { rows, .. }) => {
                    let r = *rows as usize;
                    return Ok(y.chunks(r).map(|col| self.dot(x, col)).collect());
                }
                (Type::Matrix { rows, .. }, Type::Matrix { rows: r2, .. }) => {
                    let mut out = Vec::new();
                    for col in y.chunks(*r2 as usize) {
                        out.extend(self.mat_vec(x, *rows as usize, col));
                    }
                    return Ok(out);
                }
                _ => {}
            }
        }
        match op {
            BinOp::Eq | BinOp::Ne => {
                let eq = op == BinOp::Eq;
                let mut acc: Option<Val> = None;
                for (&a, &b) in x.iter().zip(y) {
                    let c = self.compare(if eq { FCmp::Eq } else { FCmp::Ne }, a, b, s);
                    acc = Some(match acc {
                        None => c,
                        Some(p) if eq => self.op(Op::And(p, c)),
                        Some(p) => self.op(Op::Or(p, c)),
                    });
                }
                return Ok(vec![acc.unwrap_or_else(|| self.mask(eq))]);
            }
            BinOp::Lt | BinOp::Gt | BinOp::Le | BinOp::Ge => {
                let c = match op {
                    BinOp::Lt => FCmp::Lt,
                    BinOp::Gt => FCmp::Gt,
                    BinOp::Le => FCmp::Le,
                    _ => FCmp::Ge,
                };
                return Ok(vec![self.compare(c, x[0], y[0], s)]);
            }
            _ => {}
        }
        let n = rt.components().max(1) as usize;
        let at = |v: &[Val], k: usize| if v.len() == 1 { v[0] } else { v[k] };
        let mut out = Vec::with_capacity(n);
        for k in 0..n {
            let (a, b) = (at(x, k), at(y, k));
            let float = s == Scalar::Float;
            out.push(match op {
                BinOp::Add if float => self.op(Op::Add(a, b)),
                BinOp::Sub if float => self.op(Op::Sub(a, b)),
                BinOp::Mul if float => self.op(Op::Mul(a, b)),
                BinOp::Div if float => self.op(Op::Div(a, b)),
                BinOp::Add => self.op(Op::IBin(IOp::Add, a, b)),
                BinOp::Sub => self.op(Op::IBin(IOp::Sub, a, b)),
                BinOp::Mul => self.op(Op::IBin(IOp::Mul, a, b)),
                // glsl_to_nir: `/` is idiv or udiv, `%` umod for both signednesses,
                // `>>` ishr or ushr after the left operand's type.
                BinOp::Div if s == Scalar::Uint => self.op(Op::IBin(IOp::UDiv, a, b)),
                BinOp::Div => self.op(Op::IBin(IOp::Div, a, b)),
                BinOp::Mod => self.op(Op::IBin(IOp::URem, a, b)),
                BinOp::Shl => self.op(Op::IBin(IOp::Shl, a, b)),
                BinOp::Shr if s == Scalar::Uint => self.op(Op::IBin(IOp::UShr, a, b)),
                BinOp::Shr => self.op(Op::IBin(IOp::Shr, a, b)),
                BinOp::And | BinOp::BitAnd => self.op(Op::And(a, b)),
                BinOp::Or | BinOp::BitOr => self.op(Op::Or(a, b)),
                BinOp::Xor | BinOp::BitXor => self.op(Op::Xor(a, b)),
                _ => return no(format!("the operator {op:?} on {xt:?}")),
            });
        }
        Ok(out)
    }

    /// `a OP b` of scalar type `s` as a mask.
    fn compare(&mut self, c: FCmp, a: Val, b: Val, s: Scalar) -> Val {
        match s {
            Scalar::Float => self.op(Op::FCmp(c, a, b)),
            Scalar::Bool => {
                // Masks are all ones or zeros: equal when their xor is zero.
                let d = self.op(Op::Xor(a, b));
                if c == FCmp::Ne {
                    d
                } else {
                    let ones = self.mask(true);
                    self.op(Op::Xor(d, ones))
                }
            }
            Scalar::Uint => {
                // Unsigned order is the signed order with the sign bits flipped.
                let flip = self.i32(i32::MIN);
                let (a, b) = (self.op(Op::Xor(a, flip)), self.op(Op::Xor(b, flip)));
                self.op(Op::SCmp(c, a, b))
            }
            _ => self.op(Op::SCmp(c, a, b)),
        }
    }

    /// A matrix (columns of `rows`) times a vector: `m[0]·v.x + m[1]·v.y + …`, as GLSL
    /// IR's `lower_mat_op_to_vec` sums the columns.
    pub(super) fn mat_vec(&mut self, m: &[Val], rows: usize, v: &[Val]) -> Vec<Val> {
        let mut acc: Vec<Val> = Vec::new();
        for (c, col) in m.chunks(rows).enumerate() {
            for r in 0..rows {
                let p = self.op(Op::Mul(col[r], v[c]));
                if c == 0 {
                    acc.push(p);
                } else {
                    acc[r] = self.op(Op::Add(acc[r], p));
                }
            }
        }
        acc
    }

    /// `dot(a, b)` as NIR's `lower_fdot` sums it: `(x + y) + (z + w)`, `(x + y) + z`.
    pub(super) fn dot(&mut self, a: &[Val], b: &[Val]) -> Val {
        let p: Vec<Val> = a
            .iter()
            .zip(b)
            .map(|(&x, &y)| self.op(Op::Mul(x, y)))
            .collect();
        match p.len() {
            1 => p[0],
            2 => self.op(Op::Add(p[0], p[1])),
            3 => {
                let xy = self.op(Op::Add(p[0], p[1]));
                self.op(Op::Add(xy, p[2]))
            }
            _ => {
                let xy = self.op(Op::Add(p[0], p[1]));
                let zw = self.op(Op::Add(p[2], p[3]));
                self.op(Op::Add(xy, zw))
            }
        }
    }

    /// `sign(x)`: `lp_build_sgn`, the sign bit of x on 1.0, and 0 where `x == 0`.
    fn sign(&mut self, x: Val) -> Val {
        let bits = self.op(Op::Bits(x));
        let sign = self.i32(i32::MIN);
        let one = self.i32(1.0f32.to_bits() as i32);
        let s = self.op(Op::And(bits, sign));
        let s = self.op(Op::Or(s, one));
        let s = self.op(Op::FromBits(s));
        let zero = self.f32(0.0);
        let nz = self.op(Op::FCmp(FCmp::Ne, x, zero));
        self.op(Op::Select(nz, s, zero))
    }

    /// `dFdy(x)` in GL's window coordinates: Mesa's `nir_lower_wpos_ytransform` makes
    /// `fddy(x)` `fddy(x · flip)`, and llvmpipe's `fddy` is the next buffer row's value
    /// minus this row's ([`Op::Ddy`]); where rows are stored top-down, `flip` is −1 (a
    /// sign flip, exact).
    fn ddy(&mut self, x: Val) -> Val {
        let x = match self.opts.flip_height {
            Some(_) => self.op(Op::Un(Un::Neg, x)),
            None => x,
        };
        self.op(Op::Ddy(x))
    }

    /// `1 / sqrt(x)` (`lp_build_rsqrt`).
    fn rsq(&mut self, x: Val) -> Val {
        let one = self.f32(1.0);
        let s = self.op(Op::Un(Un::Sqrt, x));
        self.op(Op::Div(one, s))
    }

    /// `clamp(x, lo, hi)`: `min(max(x, lo), hi)`.
    fn clamp(&mut self, x: Val, lo: Val, hi: Val) -> Val {
        let m = self.op(Op::Max(x, lo));
        self.op(Op::Min(m, hi))
    }
}

/// Lowers a call of the built-in `name` on `args` (lowered to `vals`), returning `ret`.
pub(super) fn call(
    l: &mut Lower<'_>,
    name: &str,
    args: &[Expr],
    vals: &[Vec<Val>],
    ret: &Type,
) -> R<Vec<Val>> {
    let n = ret.components().max(1) as usize;
    let s = args
        .first()
        .and_then(|a| a.ty.scalar())
        .unwrap_or(Scalar::Float);
    let at = |k: usize, i: usize| {
        let v = &vals[k];
        if v.len() == 1 {
            v[0]
        } else {
            v[i]
        }
    };
    // Component-wise functions of one to three arguments.
    let each = |l: &mut Lower<'_>, f: &mut dyn FnMut(&mut Lower<'_>, [Val; 3]) -> Val| {
        (0..n)
            .map(|i| {
                let a = [0, 1, 2].map(|k| if k < vals.len() { at(k, i) } else { at(0, i) });
                f(l, a)
            })
            .collect::<Vec<Val>>()
    };
    let un = |u: Un| move |l: &mut Lower<'_>, [a, ..]: [Val; 3]| l.op(Op::Un(u, a));
    let float = s == Scalar::Float;
    Ok(match name {
        "radians" | "degrees" => {
            let k = if name == "radians" {
                (std::f64::consts::PI / 180.0) as f32
            } else {
                (180.0 / std::f64::consts::PI) as f32
            };
            let kv = l.f32(k);
            each(l, &mut |l, [a, ..]| l.op(Op::Mul(a, kv)))
        }
        "sin" => each(l, &mut un(Un::Sin)),
        "cos" => each(l, &mut un(Un::Cos)),
        "tan" => each(l, &mut |l, [a, ..]| {
            let (s, c) = (l.op(Op::Un(Un::Sin, a)), l.op(Op::Un(Un::Cos, a)));
            l.op(Op::Div(s, c))
        }),
        "exp2" => each(l, &mut un(Un::Exp2)),
        "log2" => each(l, &mut un(Un::Log2)),
        "exp" => {
            let k = l.f32(LOG2_E);
            each(l, &mut |l, [a, ..]| {
                let m = l.op(Op::Mul(a, k));
                l.op(Op::Un(Un::Exp2, m))
            })
        }
        "log" => {
            let k = l.f32(INV_LOG2_E);
            each(l, &mut |l, [a, ..]| {
                let g = l.op(Op::Un(Un::Log2, a));
                l.op(Op::Mul(g, k))
            })
        }
        "pow" => each(l, &mut |l, [a, b, _]| l.op(Op::Pow(a, b))),
        "sqrt" => each(l, &mut un(Un::Sqrt)),
        "inversesqrt" => each(l, &mut |l, [a, ..]| l.rsq(a)),
        "abs" if float => each(l, &mut un(Un::Abs)),
        "abs" => each(l, &mut |l, [a, ..]| {
            let neg = l.neg(a, Scalar::Int);
            l.op(Op::IBin(IOp::Max, a, neg))
        }),
        "sign" if float => each(l, &mut |l, [a, ..]| l.sign(a)),
        "floor" => each(l, &mut un(Un::Floor)),
        "ceil" => each(l, &mut un(Un::Ceil)),
        "fract" => each(l, &mut |l, [a, ..]| {
            let f = l.op(Op::Un(Un::Floor, a));
            l.op(Op::Sub(a, f))
        }),
        "mod" if float => each(l, &mut |l, [x, y, _]| {
            let q = l.op(Op::Div(x, y));
            let f = l.op(Op::Un(Un::Floor, q));
            let p = l.op(Op::Mul(y, f));
            l.op(Op::Sub(x, p))
        }),
        "min" if float => each(l, &mut |l, [a, b, _]| l.op(Op::Min(a, b))),
        "max" if float => each(l, &mut |l, [a, b, _]| l.op(Op::Max(a, b))),
        "min" => each(l, &mut |l, [a, b, _]| l.op(Op::IBin(IOp::Min, a, b))),
        "max" => each(l, &mut |l, [a, b, _]| l.op(Op::IBin(IOp::Max, a, b))),
        "clamp" if float => each(l, &mut |l, [x, lo, hi]| l.clamp(x, lo, hi)),
        "clamp" => each(l, &mut |l, [x, lo, hi]| {
            let m = l.op(Op::IBin(IOp::Max, x, lo));
            l.op(Op::IBin(IOp::Min, m, hi))
        }),
        "mix" if args.get(2).and_then(|a| a.ty.scalar()) == Some(Scalar::Bool) => {
            each(l, &mut |l, [x, y, m]| l.op(Op::Select(m, y, x)))
        }
        "mix" => each(l, &mut |l, [x, y, t]| {
            let d = l.op(Op::Sub(y, x));
            let p = l.op(Op::Mul(t, d));
            l.op(Op::Add(x, p))
        }),
        "step" => each(l, &mut |l, [e, x, _]| {
            let ge = l.op(Op::FCmp(FCmp::Ge, x, e));
            let (one, zero) = (l.f32(1.0), l.f32(0.0));
            l.op(Op::Select(ge, one, zero))
        }),
        "smoothstep" => each(l, &mut |l, [e0, e1, x]| {
            let num = l.op(Op::Sub(x, e0));
            let den = l.op(Op::Sub(e1, e0));
            let q = l.op(Op::Div(num, den));
            let (zero, one) = (l.f32(0.0), l.f32(1.0));
            let t = l.clamp(q, zero, one);
            let (two, three) = (l.f32(2.0), l.f32(3.0));
            let tt = l.op(Op::Mul(two, t));
            let u = l.op(Op::Sub(three, tt));
            let v = l.op(Op::Mul(t, u));
            l.op(Op::Mul(t, v))
        }),
        "dot" => vec![l.dot(&vals[0], &vals[1])],
        "length" if vals[0].len() == 1 => vec![l.op(Op::Un(Un::Abs, vals[0][0]))],
        "length" => {
            let d = l.dot(&vals[0], &vals[0]);
            vec![l.op(Op::Un(Un::Sqrt, d))]
        }
        "distance" => {
            let p: Vec<Val> = (0..vals[0].len())
                .map(|i| l.op(Op::Sub(vals[0][i], vals[1][i])))
                .collect();
            if p.len() == 1 {
                vec![l.op(Op::Un(Un::Abs, p[0]))]
            } else {
                let d = l.dot(&p, &p);
                vec![l.op(Op::Un(Un::Sqrt, d))]
            }
        }
        "normalize" if vals[0].len() == 1 => vec![l.sign(vals[0][0])],
        "normalize" => {
            let d = l.dot(&vals[0], &vals[0]);
            let r = l.rsq(d);
            vals[0].iter().map(|&x| l.op(Op::Mul(x, r))).collect()
        }
        "cross" => {
            let (a, b) = (&vals[0], &vals[1]);
            (0..3)
                .map(|i| {
                    let (j, k) = ((i + 1) % 3, (i + 2) % 3);
                    let p = l.op(Op::Mul(a[j], b[k]));
                    let q = l.op(Op::Mul(a[k], b[j]));
                    l.op(Op::Sub(p, q))
                })
                .collect()
        }
        "reflect" => {
            let (i, nv) = (&vals[0], &vals[1]);
            let d = l.dot(nv, i);
            let two = l.f32(2.0);
            (0..i.len())
                .map(|k| {
                    let t = l.op(Op::Mul(d, nv[k]));
                    let t2 = l.op(Op::Mul(two, t));
                    l.op(Op::Sub(i[k], t2))
                })
                .collect()
        }
        "faceforward" => {
            let d = l.dot(&vals[2], &vals[1]);
            let zero = l.f32(0.0);
            let lt = l.op(Op::FCmp(FCmp::Lt, d, zero));
            vals[0]
                .iter()
                .map(|&x| {
                    let nx = l.op(Op::Un(Un::Neg, x));
                    l.op(Op::Select(lt, x, nx))
                })
                .collect()
        }
        "dFdx" | "dFdy" | "fwidth" if l.vertex => return no("derivatives in a vertex shader"),
        "dFdx" => each(l, &mut |l, [a, ..]| l.op(Op::Ddx(a))),
        "dFdy" => each(l, &mut |l, [a, ..]| l.ddy(a)),
        "fwidth" => each(l, &mut |l, [a, ..]| {
            let x = l.op(Op::Ddx(a));
            let y = l.ddy(a);
            let (x, y) = (l.op(Op::Un(Un::Abs, x)), l.op(Op::Un(Un::Abs, y)));
            l.op(Op::Add(x, y))
        }),
        "ftransform" => l.ftransform()?,
        _ => return no(format!("the built-in function {name}")),
    })
}
