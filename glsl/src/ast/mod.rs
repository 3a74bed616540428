//! The syntax tree: what the source says, with positions, before any type checking.
//!
//! Type specifiers are syntactic (the type's name as written, array sizes as
//! expressions); the type checker resolves them. Qualifiers are kept in the order they
//! were written, since the versions before 4.20 constrain that order and the checker
//! reports it. [`print`](mod@print) writes a tree back as GLSL that parses to the same tree.

pub mod print;

use crate::diag::Pos;

/// The shader stage (one type for the whole front end, defined with the types).
pub use crate::types::Stage;

/// A parsed shader.
#[derive(Clone, Debug, PartialEq)]
pub struct Shader {
    /// The stage.
    pub stage: Stage,
    /// The `#version` (110 without one).
    pub version: u32,
    /// The `#version` line's profile.
    pub profile: crate::pp::Profile,
    /// The `#extension` directives.
    pub extensions: Vec<crate::pp::Extension>,
    /// The `#pragma` lines.
    pub pragmas: Vec<String>,
    /// The external declarations in order.
    pub items: Vec<External>,
}

/// A declaration at file scope.
#[derive(Clone, Debug, PartialEq)]
pub enum External {
    /// A declaration (variables, a prototype, a block, `precision`, …).
    Decl(Decl),
    /// A function definition.
    Function(FunctionDef),
}

/// A storage or parameter qualifier.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum Storage {
    Const,
    In,
    Out,
    Inout,
    Attribute,
    Uniform,
    Varying,
    Centroid,
}

/// An interpolation qualifier.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum Interp {
    Flat,
    Smooth,
    Noperspective,
}

/// A precision qualifier.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum Precision {
    Lowp,
    Mediump,
    Highp,
}

/// One `layout(...)` entry: a name, maybe with `= value`.
#[derive(Clone, Debug, PartialEq)]
pub struct LayoutId {
    /// The identifier as written (`location`, `std140`, `row_major`, …).
    pub name: String,
    /// The value after `=`.
    pub value: Option<Expr>,
    /// Where the identifier is.
    pub pos: Pos,
}

/// One qualifier.
#[derive(Clone, Debug, PartialEq)]
pub enum Qualifier {
    /// `const`, `in`, `out`, `inout`, `attribute`, `uniform`, `varying`, `centroid`.
    Storage(Storage),
    /// `flat`, `smooth`, `noperspective`.
    Interp(Interp),
    /// `invariant`.
    Invariant,
    /// `lowp`, `mediump`, `highp`.
    Precision(Precision),
    /// `layout(...)`.
    Layout(Vec<LayoutId>),
}

/// An array dimension: `[]` or `[size]`.
pub type ArraySize = Option<Expr>;

/// The name part of a type specifier.
#[derive(Clone, Debug, PartialEq)]
pub enum TypeName {
    /// A basic type or `void` (`vec4`, `sampler2D`, …) or a struct's name.
    Named(String),
    /// A struct defined in place.
    Struct(StructSpec),
}

/// A type specifier: a type name and array dimensions, as written.
#[derive(Clone, Debug, PartialEq)]
pub struct TypeSpec {
    /// The type's name or struct.
    pub name: TypeName,
    /// The dimensions after the type (`float[3]`), empty when none.
    pub array: Vec<ArraySize>,
    /// Where the specifier starts.
    pub pos: Pos,
}

/// A type with its qualifiers.
#[derive(Clone, Debug, PartialEq)]
pub struct FullType {
    /// The qualifiers in written order.
    pub qualifiers: Vec<Qualifier>,
    /// The type specifier.
    pub spec: TypeSpec,
}

/// A struct specifier.
#[derive(Clone, Debug, PartialEq)]
pub struct StructSpec {
    /// The struct's name, if any.
    pub name: Option<String>,
    /// The member declarations.
    pub members: Vec<Member>,
    /// Where `struct` is.
    pub pos: Pos,
}

/// A member declaration of a struct or interface block.
#[derive(Clone, Debug, PartialEq)]
pub struct Member {
    /// Its qualified type.
    pub ty: FullType,
    /// The names declared.
    pub names: Vec<Declarator>,
}

/// One declared name with its array dimensions and initializer.
#[derive(Clone, Debug, PartialEq)]
pub struct Declarator {
    /// The name.
    pub name: String,
    /// The dimensions after the name, empty when none.
    pub array: Vec<ArraySize>,
    /// The initializer.
    pub init: Option<Expr>,
    /// Where the name is.
    pub pos: Pos,
}

/// A function parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct Param {
    /// The parameter's qualified type.
    pub ty: FullType,
    /// Its name, when it has one.
    pub name: Option<String>,
    /// Dimensions after the name.
    pub array: Vec<ArraySize>,
    /// Where the parameter starts.
    pub pos: Pos,
}

/// A function prototype.
#[derive(Clone, Debug, PartialEq)]
pub struct Prototype {
    /// The return type.
    pub ret: FullType,
    /// The function's name.
    pub name: String,
    /// The parameters (`(void)` gives none).
    pub params: Vec<Param>,
    /// Where the name is.
    pub pos: Pos,
}

/// A function definition.
#[derive(Clone, Debug, PartialEq)]
pub struct FunctionDef {
    /// The prototype.
    pub proto: Prototype,
    /// The body's statements.
    pub body: Vec<Stmt>,
}

/// An interface block (`uniform Name { ... } instance[N];`).
#[derive(Clone, Debug, PartialEq)]
pub struct Block {
    /// The block's qualifiers (`layout(std140) uniform`, `out`, …).
    pub qualifiers: Vec<Qualifier>,
    /// The block name.
    pub name: String,
    /// The members.
    pub members: Vec<Member>,
    /// The instance name with its dimensions.
    pub instance: Option<(String, Vec<ArraySize>)>,
    /// Where the block name is.
    pub pos: Pos,
}

/// A declaration.
#[derive(Clone, Debug, PartialEq)]
pub enum Decl {
    /// Variables (or, with no names, a type alone such as `struct S {...};`).
    Vars {
        /// The qualified type.
        ty: FullType,
        /// The names declared.
        vars: Vec<Declarator>,
    },
    /// A function prototype.
    Prototype(Prototype),
    /// `precision highp float;`
    Precision {
        /// The precision.
        precision: Precision,
        /// The type it applies to.
        ty: TypeSpec,
        /// Where `precision` is.
        pos: Pos,
    },
    /// An interface block.
    Block(Block),
    /// Qualifiers alone (`layout(std140) uniform;`).
    Default {
        /// The qualifiers.
        qualifiers: Vec<Qualifier>,
        /// Where they start.
        pos: Pos,
    },
    /// `invariant a, b;` (redeclaring names as invariant).
    Invariant {
        /// The names with their positions.
        names: Vec<(String, Pos)>,
    },
}

/// A statement.
#[derive(Clone, Debug, PartialEq)]
pub struct Stmt {
    /// What it is.
    pub kind: StmtKind,
    /// Where it starts.
    pub pos: Pos,
}

/// A condition of `while` or `for`: an expression or a declaration with initializer.
#[derive(Clone, Debug, PartialEq)]
pub enum Condition {
    /// An expression.
    Expr(Expr),
    /// `type name = init`.
    Decl {
        /// The type.
        ty: FullType,
        /// The name.
        name: String,
        /// The initializer.
        init: Expr,
        /// Where the name is.
        pos: Pos,
    },
}

/// The kinds of statement.
#[derive(Clone, Debug, PartialEq)]
pub enum StmtKind {
    /// A declaration.
    Decl(Decl),
    /// An expression statement (`;` alone when `None`).
    Expr(Option<Expr>),
    /// `{ ... }`
    Compound(Vec<Stmt>),
    /// `if (c) a else b`
    If(Expr, Box<Stmt>, Option<Box<Stmt>>),
    /// `switch (e) { ... }`
    Switch(Expr, Vec<Stmt>),
    /// `case e:`
    Case(Expr),
    /// `default:`
    Default,
    /// `while (c) s`
    While(Condition, Box<Stmt>),
    /// `do s while (e);`
    DoWhile(Box<Stmt>, Expr),
    /// `for (init; cond; step) s`
    For {
        /// The init statement (a declaration or an expression statement).
        init: Box<Stmt>,
        /// The condition.
        cond: Option<Condition>,
        /// The step expression.
        step: Option<Expr>,
        /// The body.
        body: Box<Stmt>,
    },
    /// `break;`
    Break,
    /// `continue;`
    Continue,
    /// `return e;`
    Return(Option<Expr>),
    /// `discard;`
    Discard,
}

/// An expression.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    /// What it is.
    pub kind: ExprKind,
    /// Where Mesa locates it (its first token, or the operator of a prefix operation).
    pub pos: Pos,
}

/// Unary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum UnOp {
    Plus,
    Neg,
    Not,
    BitNot,
    PreInc,
    PreDec,
    PostInc,
    PostDec,
}

/// Binary operators (assignment apart).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum BinOp {
    Or,
    Xor,
    And,
    BitOr,
    BitXor,
    BitAnd,
    Eq,
    Ne,
    Lt,
    Gt,
    Le,
    Ge,
    Shl,
    Shr,
    Add,
    Sub,
    Mul,
    Div,
    Mod,
}

/// The binary operators' text, precedence level (higher binds tighter) and operator.
pub const BINOPS: &[(&str, u8, BinOp)] = &[
    ("||", 1, BinOp::Or),
    ("^^", 2, BinOp::Xor),
    ("&&", 3, BinOp::And),
    ("|", 4, BinOp::BitOr),
    ("^", 5, BinOp::BitXor),
    ("&", 6, BinOp::BitAnd),
    ("==", 7, BinOp::Eq),
    ("!=", 7, BinOp::Ne),
    ("<", 8, BinOp::Lt),
    (">", 8, BinOp::Gt),
    ("<=", 8, BinOp::Le),
    (">=", 8, BinOp::Ge),
    ("<<", 9, BinOp::Shl),
    (">>", 9, BinOp::Shr),
    ("+", 10, BinOp::Add),
    ("-", 10, BinOp::Sub),
    ("*", 11, BinOp::Mul),
    ("/", 11, BinOp::Div),
    ("%", 11, BinOp::Mod),
];

/// The assignment operators' text (`=` first); `None` stands for plain `=`.
pub const ASSIGNOPS: &[(&str, Option<BinOp>)] = &[
    ("=", None),
    ("*=", Some(BinOp::Mul)),
    ("/=", Some(BinOp::Div)),
    ("%=", Some(BinOp::Mod)),
    ("+=", Some(BinOp::Add)),
    ("-=", Some(BinOp::Sub)),
    ("<<=", Some(BinOp::Shl)),
    (">>=", Some(BinOp::Shr)),
    ("&=", Some(BinOp::BitAnd)),
    ("^=", Some(BinOp::BitXor)),
    ("|=", Some(BinOp::BitOr)),
];

/// What a call calls.
#[derive(Clone, Debug, PartialEq)]
pub enum Callee {
    /// A function by name (or a struct constructor, which the checker tells apart).
    Name(String),
    /// A constructor of a basic type or an array type (`vec4(...)`, `float[3](...)`).
    Type(TypeSpec),
    /// Any other expression before `(` (Mesa's grammar allows it; its checker says
    /// "function name is not an identifier").
    Expr(Box<Expr>),
}

/// The kinds of expression.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    /// A name.
    Ident(String),
    /// An `int` literal.
    Int(u32),
    /// A `uint` literal.
    Uint(u32),
    /// An `int64_t` literal (`l` suffix).
    Int64(u64),
    /// A `uint64_t` literal (`ul` suffix).
    Uint64(u64),
    /// A `float` literal.
    Float(f64),
    /// `true` or `false`.
    Bool(bool),
    /// A unary operation.
    Unary(UnOp, Box<Expr>),
    /// A binary operation.
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// An assignment (`None` for `=`, else the compound operator).
    Assign(Option<BinOp>, Box<Expr>, Box<Expr>),
    /// `c ? a : b`
    Ternary(Box<Expr>, Box<Expr>, Box<Expr>),
    /// `a, b`
    Comma(Box<Expr>, Box<Expr>),
    /// `a[i]`
    Index(Box<Expr>, Box<Expr>),
    /// `a.name` (fields and swizzles alike).
    Field(Box<Expr>, String),
    /// A function or constructor call.
    Call(Callee, Vec<Expr>),
    /// `{ a, b }`, an initializer list.
    InitList(Vec<Expr>),
    /// `a.name(args)` (`length()` of arrays).
    Method(Box<Expr>, String, Vec<Expr>),
}

/// A leaf put in place of a child being dropped.
fn leaf() -> Expr {
    Expr {
        kind: ExprKind::Bool(false),
        pos: Pos::default(),
    }
}

/// Moves the children of `k` to `out`, leaving leaves in their place.
fn take_children(k: &mut ExprKind, out: &mut Vec<Expr>) {
    let mut take = |b: &mut Box<Expr>| out.push(std::mem::replace(&mut **b, leaf()));
    match k {
        ExprKind::Unary(_, a) | ExprKind::Field(a, _) => take(a),
        ExprKind::Binary(_, a, b)
        | ExprKind::Assign(_, a, b)
        | ExprKind::Comma(a, b)
        | ExprKind::Index(a, b) => {
            take(a);
            take(b);
        }
        ExprKind::Ternary(a, b, c) => {
            take(a);
            take(b);
            take(c);
        }
        ExprKind::Method(a, _, args) => {
            take(a);
            out.append(args);
        }
        ExprKind::Call(callee, args) => {
            if let Callee::Expr(a) = callee {
                take(a);
            }
            out.append(args);
        }
        ExprKind::InitList(args) => out.append(args),
        _ => {}
    }
}

impl Drop for Expr {
    /// Drops the tree below iteratively: the parser builds an operator chain
    /// (`1.0 + 1.0 + ...`) with a loop, into a tree as deep as the chain is long, which
    /// the derived recursive drop would follow until the stack overflows.
    fn drop(&mut self) {
        let mut stack = Vec::new();
        take_children(&mut self.kind, &mut stack);
        while let Some(mut e) = stack.pop() {
            take_children(&mut e.kind, &mut stack);
        }
    }
}
