//! The checked, typed tree (HIR) the type checker ([`crate::check`]) produces and the
//! lowering into softgl's engine consumes.
//!
//! Every expression carries its semantic [`Type`], whether it is an l-value, and its
//! value when it is a constant expression (folded by `check::fold`). Implicit
//! conversions are explicit [`ExprKind::Convert`] nodes; constructors, swizzles,
//! struct fields and calls are resolved (a call names a built-in signature or a user
//! function by index). Variables live in one table, [`Program::vars`], and
//! expressions refer to them by index.

use crate::ast::{BinOp, Interp, UnOp};
use crate::builtins;
use crate::diag::Pos;
use crate::types::{Stage, Type, Version};

/// An index into [`Program::vars`].
pub type VarId = usize;
/// An index into [`Program::functions`].
pub type FuncId = usize;

/// One scalar component of a constant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Value {
    /// A `bool`.
    Bool(bool),
    /// An `int`.
    Int(i32),
    /// A `uint`.
    Uint(u32),
    /// A `float`.
    Float(f32),
}

/// A constant value: the components of a scalar, vector or matrix (column by column),
/// or the elements of an array or the members of a struct.
#[derive(Clone, Debug, PartialEq)]
pub enum Const {
    /// Scalar components.
    Scalars(Vec<Value>),
    /// Array elements or struct members.
    Aggregate(Vec<Const>),
}

/// What a variable is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Storage {
    /// A function's local (or a global without qualifier).
    Plain,
    /// `const`, with its value in [`Var::value`].
    Const,
    /// A uniform (or a member of a uniform block).
    Uniform,
    /// A stage input (`attribute`, `varying` in fragment shaders, `in`).
    In,
    /// A stage output (`varying` in vertex shaders, `out`).
    Out,
    /// A function parameter with its direction.
    Param(ParamDir),
    /// A built-in variable of this kind.
    Builtin(builtins::variables::Kind),
}

/// A parameter's direction.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParamDir {
    /// `in` (the default), maybe `const`.
    In,
    /// `out`.
    Out,
    /// `inout`.
    Inout,
}

/// A variable.
#[derive(Clone, Debug, PartialEq)]
pub struct Var {
    /// Its name.
    pub name: String,
    /// Its type.
    pub ty: Type,
    /// What it is.
    pub storage: Storage,
    /// `flat`, `smooth` or `noperspective`.
    pub interp: Option<Interp>,
    /// `centroid`.
    pub centroid: bool,
    /// `invariant`.
    pub invariant: bool,
    /// `layout(location = N)`.
    pub location: Option<i32>,
    /// The value of a constant.
    pub value: Option<Const>,
    /// The interface block it is a member of (its name), if any.
    pub block: Option<String>,
    /// Read-only (`const`, inputs, uniforms, `const` parameters).
    pub read_only: bool,
    /// Where it is declared.
    pub pos: Pos,
}

/// A function (user-defined).
#[derive(Clone, Debug, PartialEq)]
pub struct Function {
    /// The name.
    pub name: String,
    /// The return type.
    pub ret: Type,
    /// The parameters (variables of storage `Param`).
    pub params: Vec<VarId>,
    /// The body, when defined.
    pub body: Option<Vec<Stmt>>,
    /// Where the name is.
    pub pos: Pos,
}

/// A checked expression.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    /// What it is.
    pub kind: ExprKind,
    /// Its type.
    pub ty: Type,
    /// Where it is.
    pub pos: Pos,
    /// Whether it may be assigned to (a writable variable, or a field, element or
    /// swizzle without repeated components of one).
    pub lvalue: bool,
    /// Its value, when it is a constant expression.
    pub value: Option<Const>,
}

/// The kinds of checked expression.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    /// A variable.
    Var(VarId),
    /// A literal (its value in [`Expr::value`]).
    Literal,
    /// A unary operation (increments and decrements included).
    Unary(UnOp, Box<Expr>),
    /// A binary operation; the operands already converted to a common base type.
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// An assignment (`None`: plain `=`), the right side converted to the left's type.
    Assign(Option<BinOp>, Box<Expr>, Box<Expr>),
    /// `c ? a : b`.
    Ternary(Box<Expr>, Box<Expr>, Box<Expr>),
    /// `a, b`.
    Comma(Box<Expr>, Box<Expr>),
    /// An array element, matrix column or vector component.
    Index(Box<Expr>, Box<Expr>),
    /// A struct or block member by index.
    Field(Box<Expr>, usize),
    /// A swizzle: component indices 0 to 3.
    Swizzle(Box<Expr>, Vec<u8>),
    /// An implicit conversion to [`Expr::ty`] (int or uint to float).
    Convert(Box<Expr>),
    /// A constructor of [`Expr::ty`].
    Construct(Vec<Expr>),
    /// A call of a built-in function signature.
    Builtin(&'static builtins::Function, Vec<Expr>),
    /// A call of a user function.
    Call(FuncId, Vec<Expr>),
    /// `a.length()` of an array.
    Length(Box<Expr>),
}

/// A checked statement.
#[derive(Clone, Debug, PartialEq)]
pub enum Stmt {
    /// A local variable with its initializer.
    Decl(VarId, Option<Expr>),
    /// An expression statement.
    Expr(Expr),
    /// A block.
    Block(Vec<Stmt>),
    /// `if`.
    If(Expr, Box<Stmt>, Option<Box<Stmt>>),
    /// A loop: `while` (test first), `do`-`while` (test last) or `for`.
    Loop {
        /// The initializer of a `for` (or the condition's declaration of a `while`).
        init: Option<Box<Stmt>>,
        /// The condition (`None`: forever).
        cond: Option<Expr>,
        /// The step of a `for`.
        step: Option<Expr>,
        /// The body.
        body: Box<Stmt>,
        /// `do`-`while`: the condition is tested after the body.
        test_last: bool,
    },
    /// `switch` with its body (holding [`Stmt::Case`] labels).
    Switch(Expr, Vec<Stmt>),
    /// `case` (`Some` value) or `default` (`None`).
    Case(Option<i64>),
    /// `break`.
    Break,
    /// `continue`.
    Continue,
    /// `return`.
    Return(Option<Expr>),
    /// `discard`.
    Discard,
}

/// A checked shader.
#[derive(Clone, Debug, PartialEq)]
pub struct Program {
    /// The stage.
    pub stage: Stage,
    /// The version and profile.
    pub version: Version,
    /// Every variable: built-ins used, globals, parameters and locals.
    pub vars: Vec<Var>,
    /// The global variables in declaration order, with their initializers.
    pub globals: Vec<(VarId, Option<Expr>)>,
    /// The user functions.
    pub functions: Vec<Function>,
}

impl Program {
    /// The `main` function, if the shader defines it.
    pub fn main(&self) -> Option<&Function> {
        self.functions
            .iter()
            .find(|f| f.name == "main" && f.body.is_some())
    }
}
