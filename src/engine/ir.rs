//! The engine's IR: a typed SSA list of operations on 8-lane values (one lane per
//! fragment), built with [`Builder`].
//!
//! Every value is a vector of lanes of one [`Ty`]; a uniform (a per-draw constant) is a
//! [`Op::Const`], which the executor materialises once per run instead of once per chunk.
//! Each operation's arithmetic is defined as llvmpipe's, so that a program lowered from a
//! fixed-function state computes today's bytes:
//! - [`Op::Mad`] is `fmuladd`: fused exactly on the instruction-set levels that fuse
//!   (README "Instruction sets"); [`Op::Mul`] followed by [`Op::Add`] never fuses.
//! - [`Op::Interp`] is the plane evaluation `fmuladd(dady, y, fmuladd(dadx, x, a0))` at
//!   the pixel's integer coordinates.
//! - [`Op::Min`] and [`Op::Max`] are `minps`/`maxps` (the second operand when either is
//!   NaN), [`Op::Sat`] is `min(max(v, 0), 1)` (NaN → 0), [`Op::CvtRne`] is `cvtps2dq`
//!   under the default rounding (half to even; out of range → `i32::MIN`).
//! - [`Op::UnpackUnorm8`] is `u8 · f32(1/255)`; [`Op::PackUnorm8`] is, per channel,
//!   `cvtps2dq(sat(c) · 255)`, packed R in the low byte.
//! - The shader operations ([`Op::Un`], [`Op::Pow`], the integer and bit operations):
//!   `floor`/`ceil` as `roundps`, `sqrt` correctly rounded, `exp2`/`log2`/`pow`/`sin`/`cos`
//!   as gallivm's polynomials (`lp_bld_arit.c`, fused on the levels that fuse), integer
//!   arithmetic wrapping, `FtoI` truncating (`cvttps2dq`).
//! - The fragment interface: [`Op::Kill`] clears lanes, [`Op::DepthTest`] compares a
//!   quantised depth with the buffer's (and writes it where it passes), [`Op::LoadColor`],
//!   [`Op::Blend`] (8-bit fixed point, docs/llvmpipe-rules.md) and [`Op::StoreColor`].
//! - Loops: the only operations not in SSA form. [`Op::VarStore`]/[`Op::VarLoad`] move a
//!   value through a numbered variable slot; [`Op::LoopEnd`] jumps back to its
//!   [`Op::LoopBegin`] while any lane of its mask is set and llvmpipe's iteration
//!   limiter (65535 per batch) allows.

use crate::fixed_function::fog::FogPlan;
use crate::fragment::StencilPlan;
use crate::pipe::{BlendState, CompareFunc};

/// The type of a value's lanes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Ty {
    /// 32-bit floats.
    F32,
    /// 32-bit integers (also packed RGBA8 colours and quantised depths).
    I32,
    /// Lane masks: all ones (true) or all zeros.
    Mask,
}

/// An SSA value: the index of the operation that defines it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct Val(pub u16);

/// A float comparison (ordered: false when either lane is NaN).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FCmp {
    /// `a < b`.
    Lt,
    /// `a <= b`.
    Le,
    /// `a > b`.
    Gt,
    /// `a >= b`.
    Ge,
    /// `a == b`.
    Eq,
    /// `a != b` (unordered: true when either lane is NaN).
    Ne,
}

/// The comparisons in the order of their codes in a step's immediate.
pub const FCMPS: [FCmp; 6] = [FCmp::Lt, FCmp::Le, FCmp::Gt, FCmp::Ge, FCmp::Eq, FCmp::Ne];

/// A unary f32 function ([`Op::Un`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Un {
    /// `roundps` toward −∞.
    Floor,
    /// `roundps` toward +∞ (as `-floor(-x)`, the same bits).
    Ceil,
    /// Correctly rounded square root.
    Sqrt,
    /// The sign bit cleared.
    Abs,
    /// The sign bit flipped.
    Neg,
    /// gallivm's `lp_build_exp2`.
    Exp2,
    /// gallivm's `lp_build_log2_safe`.
    Log2,
    /// gallivm's `lp_build_sin`.
    Sin,
    /// gallivm's `lp_build_cos`.
    Cos,
}

/// The unary functions in the order of their codes in a step's immediate.
pub const UNS: [Un; 9] = [
    Un::Floor,
    Un::Ceil,
    Un::Sqrt,
    Un::Abs,
    Un::Neg,
    Un::Exp2,
    Un::Log2,
    Un::Sin,
    Un::Cos,
];

/// A binary i32 operation ([`Op::IBin`]), wrapping.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum IOp {
    /// `a + b`.
    Add,
    /// `a - b`.
    Sub,
    /// The low 32 bits of `a * b`.
    Mul,
    /// The smaller (signed).
    Min,
    /// The larger (signed).
    Max,
    /// The signed quotient, truncated (gallivm's `idiv`: 0 where `b` is 0, `a` for
    /// `i32::MIN / -1`).
    Div,
    /// The unsigned quotient (gallivm's `udiv`: all ones where `b` is 0).
    UDiv,
    /// The unsigned remainder (gallivm's `umod`, which GLSL's `%` is for every integer
    /// type in Mesa: all ones where `b` is 0).
    URem,
    /// `a << (b & 31)`.
    Shl,
    /// `a >> (b & 31)`, arithmetic.
    Shr,
    /// `a >> (b & 31)`, logical.
    UShr,
}

impl IOp {
    /// The operation on one lane, as llvmpipe computes it at run time.
    pub fn apply(self, a: i32, b: i32) -> i32 {
        let (ua, ub) = (a as u32, b as u32);
        match self {
            IOp::Add => a.wrapping_add(b),
            IOp::Sub => a.wrapping_sub(b),
            IOp::Mul => a.wrapping_mul(b),
            IOp::Min => a.min(b),
            IOp::Max => a.max(b),
            IOp::Div if b == 0 => 0,
            IOp::Div => a.wrapping_div(b),
            IOp::UDiv => ua.checked_div(ub).unwrap_or(u32::MAX) as i32,
            IOp::URem => ua.checked_rem(ub).unwrap_or(u32::MAX) as i32,
            IOp::Shl => a.wrapping_shl(ub & 31),
            IOp::Shr => a.wrapping_shr(ub & 31),
            IOp::UShr => ua.wrapping_shr(ub & 31) as i32,
        }
    }
}

/// The integer operations in the order of their codes in a step's immediate.
pub const IOPS: [IOp; 11] = [
    IOp::Add,
    IOp::Sub,
    IOp::Mul,
    IOp::Min,
    IOp::Max,
    IOp::Div,
    IOp::UDiv,
    IOp::URem,
    IOp::Shl,
    IOp::Shr,
    IOp::UShr,
];

/// The blend state of an [`Op::Blend`] in 8-bit terms (factors, equations, constant).
pub type Blend8 = BlendState<[u8; 4]>;

/// One operation; operands are earlier values.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Op {
    /// A per-draw constant in every lane (f32 bits for [`Ty::F32`]).
    Const(Ty, u32),
    /// The pixel's x as f32.
    FragX,
    /// The pixel's y as f32.
    FragY,
    /// Plane `n` of the run's planes evaluated at the pixel (see the module doc).
    Interp(u16),
    /// Input stream `n` of the run (one packed value per lane, e.g. RGBA8 texels).
    Input(u16),
    /// Input stream `n` of the run as f32 lanes (e.g. one channel of sampled texels).
    InputF(u16),
    /// Uniform `n` of the run (a per-triangle f32, e.g. a flat-shaded colour) in every
    /// lane.
    Uniform(u16),
    /// `a + b`.
    Add(Val, Val),
    /// `a - b`.
    Sub(Val, Val),
    /// `a * b`.
    Mul(Val, Val),
    /// `a / b` (correctly rounded).
    Div(Val, Val),
    /// `minps(a, b)`.
    Min(Val, Val),
    /// `maxps(a, b)`.
    Max(Val, Val),
    /// `fmuladd(a, b, c)`: `a * b + c`, fused on fusing levels.
    Mad(Val, Val, Val),
    /// Clamp to [0, 1], NaN → 0.
    Sat(Val),
    /// f32 → i32, rounding half to even.
    CvtRne(Val),
    /// The bits of an f32 value as an i32 value.
    Bits(Val),
    /// Float comparison.
    FCmp(FCmp, Val, Val),
    /// Integer comparison `a FUNC b` for values in `0..2^31` (GL's compare functions).
    ICmp(CompareFunc, Val, Val),
    /// `a & b` (i32 or mask).
    And(Val, Val),
    /// `a | b` (i32 or mask).
    Or(Val, Val),
    /// The fog factor of the fog coordinate `a` per lane
    /// ([`crate::fixed_function::fog::FogPlan::factor`], llvmpipe's polynomial `exp2`).
    Fog(Val, FogPlan),
    /// Byte `n` (0 = lowest) of a packed value, as an integer.
    Byte(Val, u8),
    /// Byte `n` of a packed RGBA8 value as `u8 · f32(1/255)`.
    UnpackUnorm8(Val, u8),
    /// Four channels (R, G, B, A) converted to unorm8 and packed.
    PackUnorm8([Val; 4]),
    /// A unary f32 function.
    Un(Un, Val),
    /// gallivm's `lp_build_pow`: `exp2(log2_safe(a) · b)`, 0 where `a == 0`.
    Pow(Val, Val),
    /// A wrapping i32 operation.
    IBin(IOp, Val, Val),
    /// `a ^ b` (i32 or mask).
    Xor(Val, Val),
    /// Signed i32 comparison.
    SCmp(FCmp, Val, Val),
    /// i32 → f32 (`cvtdq2ps`).
    ItoF(Val),
    /// f32 → i32 truncated (`cvttps2dq`; out of range → `i32::MIN`).
    FtoI(Val),
    /// The bits of an i32 value as an f32 value.
    FromBits(Val),
    /// Per lane `a` where the mask is set, else `b` (both of the same type).
    Select(Val, Val, Val),
    /// Clears the live lanes where the mask is false (the alpha test, discard).
    Kill(Val),
    /// The depth test of a quantised depth against the buffer: clears the lanes that
    /// fail and, with `write`, stores the depth where it passes.
    DepthTest {
        /// The compare function (incoming FUNC stored).
        func: CompareFunc,
        /// glDepthMask.
        write: bool,
        /// The quantised depth.
        z: Val,
    },
    /// The stencil test of the triangle's face ([`StencilPlan`], the face chosen per run)
    /// and, for the lanes that pass it, the depth test of `z` (when `depth`: the compare
    /// function and glDepthMask); clears the lanes that fail either and updates the
    /// stencil buffer with the face's fail, zfail or zpass operation, as
    /// `fragment::span::stencil_depth` does.
    StencilDepth {
        /// Both faces' stencil state.
        stencil: StencilPlan,
        /// The depth test's function and write mask, if depth is tested.
        depth: Option<(CompareFunc, bool)>,
        /// The quantised depth (any i32 value without a depth test).
        z: Val,
    },
    /// Draw buffer `n`'s packed RGBA8 values at the live lanes (0: the target's colour,
    /// k ≥ 1: its `more_colors[k - 1]`).
    LoadColor(u8),
    /// 8-bit blending of a packed source with a packed destination.
    Blend(Blend8, Val, Val),
    /// Writes a packed colour to draw buffer `n` (as [`Op::LoadColor`]) at the live lanes.
    StoreColor(u8, Val),
    /// Writes a value's lanes to output `n` of the chunk (a vertex shader's results,
    /// [`super::exec::Program::run_streams`]).
    Output(u16, Val),
    /// Mutable variable `n`'s value, of type `ty`: what the last [`Op::VarStore`] to it
    /// wrote (the values a loop carries from one iteration to the next).
    VarLoad(u16, Ty),
    /// Writes a value to mutable variable `n` in every lane (the lowering selects under
    /// its masks first).
    VarStore(u16, Val),
    /// The start of loop `n`'s body: where its [`Op::LoopEnd`] jumps back to.
    LoopBegin(u16),
    /// The end of loop `n`'s body: the body runs again while any lane of the mask is
    /// set in any chunk of the batch, at most [`super::exec::LOOP_LIMIT`] back-jumps per
    /// batch over all loops (llvmpipe's `LP_MAX_TGSI_LOOP_ITERATIONS`, shared by every
    /// loop of a shader).
    LoopEnd(u16, Val),
    /// gallivm's `lp_build_ddx`: in each 2x2 quad, the right pixel's value minus the
    /// left one's, in both pixels of its row. A program with a derivative runs over
    /// chunk pairs ([`super::exec::Program::quads`]).
    Ddx(Val),
    /// gallivm's `lp_build_ddy`: in each 2x2 quad, the bottom pixel's value (the next
    /// row of the buffer) minus the top one's, in both pixels of its column.
    Ddy(Val),
    /// Samples texture lookup `lookup` at the coordinates `s`, `t`, `r` of every lane
    /// with the lookup's level-of-detail argument `l` (the run's
    /// [`super::exec::TexSampler`], a chunk pair at a time: what `l` is, a bias, a level
    /// of detail or none, is the lookup's own); [`Op::Texel`] reads the result.
    Sample {
        /// The lookup's index (its texel is streams `4 · lookup ..` of [`Op::Texel`]).
        lookup: u8,
        /// The first coordinate.
        s: Val,
        /// The second (0 where the target has none).
        t: Val,
        /// The third, or a shadow lookup's reference (0 where there is none).
        r: Val,
        /// The level-of-detail argument (0 where the lookup has none).
        l: Val,
    },
    /// Channel `n % 4` of the texel that the last [`Op::Sample`] of lookup `n / 4` gave.
    Texel(u16),
}

impl Op {
    /// The operands, in order.
    pub fn operands(&self) -> Vec<Val> {
        match *self {
            Op::Const(..)
            | Op::FragX
            | Op::FragY
            | Op::Interp(_)
            | Op::Input(_)
            | Op::InputF(_)
            | Op::Texel(_)
            | Op::Uniform(_) => vec![],
            Op::LoadColor(_) | Op::VarLoad(..) | Op::LoopBegin(_) => vec![],
            Op::VarStore(_, a) | Op::LoopEnd(_, a) => vec![a],
            Op::Ddx(a) | Op::Ddy(a) => vec![a],
            Op::Sample { s, t, r, l, .. } => vec![s, t, r, l],
            Op::Add(a, b)
            | Op::Sub(a, b)
            | Op::Mul(a, b)
            | Op::Div(a, b)
            | Op::Min(a, b)
            | Op::Max(a, b)
            | Op::FCmp(_, a, b)
            | Op::ICmp(_, a, b)
            | Op::And(a, b)
            | Op::Or(a, b)
            | Op::Pow(a, b)
            | Op::IBin(_, a, b)
            | Op::Xor(a, b)
            | Op::SCmp(_, a, b)
            | Op::Blend(_, a, b) => vec![a, b],
            Op::Mad(a, b, c) | Op::Select(a, b, c) => vec![a, b, c],
            Op::Sat(a)
            | Op::CvtRne(a)
            | Op::Bits(a)
            | Op::Un(_, a)
            | Op::ItoF(a)
            | Op::FtoI(a)
            | Op::FromBits(a)
            | Op::Fog(a, _)
            | Op::Byte(a, _)
            | Op::UnpackUnorm8(a, _) => vec![a],
            Op::Kill(a) | Op::StoreColor(_, a) | Op::DepthTest { z: a, .. } => vec![a],
            Op::StencilDepth { z, .. } => vec![z],
            Op::Output(_, a) => vec![a],
            Op::PackUnorm8(v) => v.to_vec(),
        }
    }
}

/// A type error found while building: the operation's index and what was wrong.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TypeError {
    /// Index of the offending operation.
    pub at: usize,
    /// What was expected.
    pub what: &'static str,
}

/// A built program: operations in order, each value's type.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Ir {
    /// The operations; value `i` is defined by `ops[i]`.
    pub ops: Vec<Op>,
    /// The type of each value (`None` for operations that define none).
    pub types: Vec<Option<Ty>>,
}

/// Builds an [`Ir`], checking types as it goes (the first error is kept and returned by
/// [`Builder::finish`]).
#[derive(Clone, Default)]
pub struct Builder {
    ir: Ir,
    error: Option<TypeError>,
}

impl Builder {
    /// An empty program.
    pub fn new() -> Self {
        Self::default()
    }

    /// The type of `v`, if it defines a value.
    pub fn ty(&self, v: Val) -> Option<Ty> {
        self.ir.types.get(v.0 as usize).copied().flatten()
    }

    /// The operation that defines `v`.
    pub fn op_of(&self, v: Val) -> Option<&Op> {
        self.ir.ops.get(v.0 as usize)
    }

    /// Appends `op` after checking its operand types; returns its value.
    pub fn push(&mut self, op: Op) -> Val {
        let at = self.ir.ops.len();
        let result = self.check(&op);
        let ty = match result {
            Ok(t) => t,
            Err(what) => {
                self.error.get_or_insert(TypeError { at, what });
                None
            }
        };
        self.ir.ops.push(op);
        self.ir.types.push(ty);
        Val(at as u16)
    }

    /// The result type of `op`, or what is wrong with its operands.
    fn check(&self, op: &Op) -> Result<Option<Ty>, &'static str> {
        use Ty::*;
        let t = |v: Val| self.ty(v);
        let want = |v: Val, ty: Ty, what: &'static str| {
            if t(v) == Some(ty) {
                Ok(())
            } else {
                Err(what)
            }
        };
        Ok(Some(match *op {
            Op::Const(ty, _) => ty,
            Op::FragX | Op::FragY | Op::Interp(_) | Op::InputF(_) | Op::Uniform(_) => F32,
            Op::Texel(_) => F32,
            Op::Ddx(a) | Op::Ddy(a) => {
                want(a, F32, "f32 operand")?;
                F32
            }
            Op::Sample { s, t, r, l, .. } => {
                for v in [s, t, r, l] {
                    want(v, F32, "f32 coordinate")?;
                }
                return Ok(None);
            }
            Op::Input(_) | Op::LoadColor(_) => I32,
            Op::VarLoad(_, ty) => ty,
            Op::VarStore(_, v) => {
                if t(v).is_none() {
                    return Err("a value to store");
                }
                return Ok(None);
            }
            Op::LoopBegin(_) => return Ok(None),
            Op::LoopEnd(_, m) => {
                want(m, Mask, "loop mask")?;
                return Ok(None);
            }
            Op::Add(a, b)
            | Op::Sub(a, b)
            | Op::Mul(a, b)
            | Op::Div(a, b)
            | Op::Min(a, b)
            | Op::Max(a, b) => {
                want(a, F32, "f32 operand")?;
                want(b, F32, "f32 operand")?;
                F32
            }
            Op::Mad(a, b, c) => {
                for v in [a, b, c] {
                    want(v, F32, "f32 operand")?;
                }
                F32
            }
            Op::Sat(a) | Op::Fog(a, _) | Op::Un(_, a) => {
                want(a, F32, "f32 operand")?;
                F32
            }
            Op::Pow(a, b) => {
                want(a, F32, "f32 operand")?;
                want(b, F32, "f32 operand")?;
                F32
            }
            Op::IBin(_, a, b) => {
                want(a, I32, "i32 operand")?;
                want(b, I32, "i32 operand")?;
                I32
            }
            Op::SCmp(_, a, b) => {
                want(a, I32, "i32 operand")?;
                want(b, I32, "i32 operand")?;
                Mask
            }
            Op::ItoF(a) | Op::FromBits(a) => {
                want(a, I32, "i32 operand")?;
                F32
            }
            Op::FtoI(a) => {
                want(a, F32, "f32 operand")?;
                I32
            }
            Op::And(a, b) | Op::Or(a, b) | Op::Xor(a, b) => {
                if !matches!(t(a), Some(I32 | Mask)) || t(a) != t(b) {
                    return Err("i32 or mask operands of one type");
                }
                return Ok(t(a));
            }
            Op::CvtRne(a) | Op::Bits(a) => {
                want(a, F32, "f32 operand")?;
                I32
            }
            Op::FCmp(_, a, b) => {
                want(a, F32, "f32 operand")?;
                want(b, F32, "f32 operand")?;
                Mask
            }
            Op::ICmp(_, a, b) => {
                want(a, I32, "i32 operand")?;
                want(b, I32, "i32 operand")?;
                Mask
            }
            Op::Byte(a, n) | Op::UnpackUnorm8(a, n) => {
                want(a, I32, "packed operand")?;
                if n > 3 {
                    return Err("byte index 0..=3");
                }
                if matches!(op, Op::Byte(..)) {
                    I32
                } else {
                    F32
                }
            }
            Op::PackUnorm8(v) => {
                for c in v {
                    want(c, F32, "f32 channel")?;
                }
                I32
            }
            Op::Select(m, a, b) => {
                want(m, Mask, "mask selector")?;
                if t(a).is_none() || t(a) != t(b) {
                    return Err("select operands of one type");
                }
                return Ok(t(a));
            }
            Op::Kill(m) => {
                want(m, Mask, "mask operand")?;
                return Ok(None);
            }
            Op::DepthTest { z, .. } | Op::StencilDepth { z, .. } => {
                want(z, I32, "quantised depth")?;
                return Ok(None);
            }
            Op::Blend(_, s, d) => {
                want(s, I32, "packed source")?;
                want(d, I32, "packed destination")?;
                I32
            }
            Op::StoreColor(_, c) => {
                want(c, I32, "packed colour")?;
                return Ok(None);
            }
            Op::Output(_, v) => {
                if t(v).is_none() {
                    return Err("a value to output");
                }
                return Ok(None);
            }
        }))
    }

    /// A builder that goes on appending to `ir` (a program built earlier, e.g. a lowered
    /// shader to which a caller adds its outputs).
    pub fn from_ir(ir: Ir) -> Self {
        Builder { ir, error: None }
    }

    /// The program, or the first type error.
    pub fn finish(self) -> Result<Ir, TypeError> {
        match self.error {
            Some(e) => Err(e),
            None => Ok(self.ir),
        }
    }

    /// An f32 constant.
    pub fn f32(&mut self, v: f32) -> Val {
        self.push(Op::Const(Ty::F32, v.to_bits()))
    }

    /// An i32 constant.
    pub fn i32(&mut self, v: i32) -> Val {
        self.push(Op::Const(Ty::I32, v as u32))
    }

    /// `a * b`.
    pub fn mul(&mut self, a: Val, b: Val) -> Val {
        self.push(Op::Mul(a, b))
    }

    /// `a + b`.
    pub fn add(&mut self, a: Val, b: Val) -> Val {
        self.push(Op::Add(a, b))
    }

    /// `a - b`.
    pub fn sub(&mut self, a: Val, b: Val) -> Val {
        self.push(Op::Sub(a, b))
    }
}
