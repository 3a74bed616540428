//! The type checker: a parsed [`Shader`] in, a typed [`Program`]
//! out, or the info log of its errors in Mesa's words.
//!
//! The rules are the GLSL specifications' (1.10 to 3.30): scoping 4.1 and 6 (one scope
//! per function body and compound statement, `for`/`while` open their own), storage
//! qualifiers 4.3, operators 5.9, constructors 5.4, constant expressions 4.3.3,
//! function calls and overloading 6.1. Where Mesa's compiler (the tests' reference)
//! differs, the checker follows Mesa and says so where the rule is written: scalar
//! swizzles are an error before 4.20, an `int` return value is not converted to a
//! `float` return type, recursion is reported (as Mesa does at the end of compiling)
//! at position 0:0(0), `return` with a value in a void function names the type.
//!
//! Errors are reported where Mesa reports them and worded as Mesa words them
//! (`tests/check.rs` measures the agreement); after an error in an expression the
//! expression is dropped (`None`) so one mistake gives one message.
//!
//! The walk is recursive over the syntax tree, whose nesting the parser bounds; long
//! left-nested operator chains (which the parser builds with a loop) are bounded here
//! by [`MAX_DEPTH`].

mod block;
mod construct;
mod decl;
mod expr;
pub mod fold;
mod func;
mod ops;
mod stmt;

use crate::ast::Shader;
use crate::builtins;
use crate::diag::{Log, Pos};
use crate::hir::{Function, Program, Storage, Var, VarId};
use crate::types::{Stage, Struct, Type, Version};
use decl::AOA;
use std::collections::HashMap;
use std::sync::Arc;

/// The deepest expression nesting the checker follows before giving up with an error.
pub const MAX_DEPTH: u32 = 2000;

/// A name in a scope.
#[derive(Clone, Debug)]
enum Symbol {
    /// A variable.
    Var(VarId),
    /// A struct type.
    Struct(Arc<Struct>),
    /// User functions (global scope only).
    Functions(Vec<usize>),
}

/// What the statement walk is inside of.
#[derive(Clone, Copy, Debug, Default)]
struct Context {
    /// Loops enclosing the statement.
    loops: u32,
    /// Switches enclosing the statement (inside the innermost loop or not).
    switches: u32,
}

/// The checker's state for one shader.
pub struct Checker<'a> {
    log: &'a mut Log,
    /// The version and profile.
    pub version: Version,
    /// The stage.
    pub stage: Stage,
    exts: Vec<&'static str>,
    scopes: Vec<HashMap<String, Symbol>>,
    builtin_vars: HashMap<String, VarId>,
    block_names: Vec<(String, String)>,
    vars: Vec<Var>,
    functions: Vec<Function>,
    /// The function being checked (its index), for `return`.
    current: Option<usize>,
    /// Calls between user functions, for the recursion check.
    calls: Vec<(usize, usize)>,
    ctx: Context,
    depth: u32,
    /// Inside the operation of a compound assignment (for the operator's name).
    compound: bool,
    /// The functions in the order they were defined.
    defined: Vec<usize>,
    /// Whether the function being checked has a `return` with a value.
    returned: bool,
    /// The first of `gl_FragColor` / `gl_FragData` a fragment shader writes.
    wrote_builtin_color: Option<String>,
    /// The first user output variable a fragment shader writes.
    wrote_user_out: Option<String>,
}

/// Extension names the checker knows (for `exts`).
const KNOWN_EXTS: &[&str] = &[
    "GL_ARB_shader_texture_lod",
    "GL_ARB_shader_bit_encoding",
    "GL_EXT_texture_array",
    "GL_ARB_texture_multisample",
    "GL_ARB_draw_instanced",
    "GL_ARB_explicit_attrib_location",
    "GL_ARB_uniform_buffer_object",
];

impl<'a> Checker<'a> {
    fn new(shader: &Shader, log: &'a mut Log) -> Checker<'a> {
        let compat = shader.profile == crate::pp::Profile::Compatibility;
        let version = Version::new(shader.version.min(u16::MAX as u32) as u16, compat);
        let exts = KNOWN_EXTS
            .iter()
            .copied()
            .filter(|e| {
                shader
                    .extensions
                    .iter()
                    .any(|x| x.name == *e && (x.behavior == "enable" || x.behavior == "require"))
            })
            .collect();
        Checker {
            log,
            version,
            stage: shader.stage,
            exts,
            scopes: vec![HashMap::new()],
            builtin_vars: HashMap::new(),
            block_names: Vec::new(),
            vars: Vec::new(),
            functions: Vec::new(),
            current: None,
            calls: Vec::new(),
            ctx: Context::default(),
            depth: 0,
            returned: false,
            compound: false,
            defined: Vec::new(),
            wrote_builtin_color: None,
            wrote_user_out: None,
        }
    }

    /// Reports an error.
    fn error(&mut self, pos: Pos, text: impl Into<String>) {
        self.log.error(pos, text);
    }

    /// Whether an extension is enabled.
    fn ext(&self, name: &str) -> bool {
        self.exts.contains(&name)
    }

    /// Whether the version is at least `n`.
    fn at_least(&self, n: u16) -> bool {
        self.version.at_least(n)
    }

    /// Mesa's "X forbidden in GLSL 1.10 (GLSL 1.20 or GLSL ES 3.00 required)" suffix.
    fn version_text(&self) -> String {
        format!(
            "GLSL {}.{:02}",
            self.version.number / 100,
            self.version.number % 100
        )
    }

    /// Unless the version is at least `min`, reports Mesa's "WHAT in GLSL 1.10
    /// (REQUIRED required)" and returns false.
    fn require(&mut self, min: u16, pos: Pos, what: &str, required: &str) -> bool {
        if self.at_least(min) {
            return true;
        }
        let vt = self.version_text();
        self.error(pos, format!("{what} in {vt} ({required} required)"));
        false
    }

    fn push_scope(&mut self) {
        self.scopes.push(HashMap::new());
    }

    fn pop_scope(&mut self) {
        if self.scopes.len() > 1 {
            self.scopes.pop();
        }
    }

    fn global_scope(&self) -> bool {
        self.scopes.len() == 1
    }

    /// The symbol `name` resolves to, innermost scope first, then the built-ins.
    fn lookup(&mut self, name: &str) -> Option<Symbol> {
        for s in self.scopes.iter().rev() {
            if let Some(sym) = s.get(name) {
                return Some(sym.clone());
            }
        }
        self.builtin_var(name).map(Symbol::Var)
    }

    /// The symbol `name` in the innermost scope only.
    fn lookup_local(&self, name: &str) -> Option<&Symbol> {
        self.scopes.last().and_then(|s| s.get(name))
    }

    /// The built-in variable `name`, entered in the table on first use.
    fn builtin_var(&mut self, name: &str) -> Option<VarId> {
        if let Some(id) = self.builtin_vars.get(name) {
            return Some(*id);
        }
        let b = builtins::variable(name, self.version, self.stage, &self.exts)?;
        let mut ty = b.ty.clone();
        // gl_FragData is sized gl_MaxDrawBuffers; gl_TexCoord is implicitly sized.
        if let Type::Array(_, None) = ty {
            if name == "gl_TexCoord" {
                ty = Type::Array(Box::new(Type::vec(crate::types::Scalar::Float, 4)), None);
            }
        }
        let kind = b.kind;
        let id = self.add_var(Var {
            name: name.to_string(),
            ty,
            storage: Storage::Builtin(kind),
            interp: None,
            centroid: false,
            invariant: false,
            location: None,
            value: b
                .value
                .map(|v| crate::hir::Const::Scalars(vec![crate::hir::Value::Int(v)])),
            block: None,
            read_only: !b.writable(),
            pos: Pos::default(),
        });
        self.builtin_vars.insert(name.to_string(), id);
        Some(id)
    }

    fn add_var(&mut self, v: Var) -> VarId {
        self.vars.push(v);
        self.vars.len() - 1
    }

    /// Declares `name` as `sym` in the innermost scope.
    fn declare(&mut self, name: &str, sym: Symbol) {
        if let Some(s) = self.scopes.last_mut() {
            s.insert(name.to_string(), sym);
        }
    }

    /// The struct type named `name` in scope.
    fn struct_named(&self, name: &str) -> Option<Arc<Struct>> {
        for s in self.scopes.iter().rev() {
            match s.get(name) {
                Some(Symbol::Struct(st)) => return Some(st.clone()),
                Some(_) => return None,
                None => {}
            }
        }
        None
    }

    /// Enters one more level of expression nesting; false (with an error) past
    /// [`MAX_DEPTH`].
    fn enter(&mut self, pos: Pos) -> bool {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            if self.depth == MAX_DEPTH + 1 {
                self.error(pos, "expression nested too deeply");
            }
            return false;
        }
        true
    }

    fn leave(&mut self) {
        self.depth -= 1;
    }

    /// Mesa's end-of-compile check that a fragment shader writes either the built-in
    /// colour outputs or its own, not both (at 0:0(0)).
    fn check_outputs(&mut self) {
        if let (Some(b), Some(u)) = (&self.wrote_builtin_color, &self.wrote_user_out) {
            let text = format!("fragment shader writes to both `{b}' and `{u}'");
            self.error(Pos::new(0, 0), text);
        }
    }

    /// Notes a write to variable `v` for [`Checker::check_outputs`].
    fn note_write(&mut self, v: VarId) {
        if self.stage != Stage::Fragment {
            return;
        }
        let var = &self.vars[v];
        let slot = match var.storage {
            Storage::Builtin(_) if var.name == "gl_FragColor" || var.name == "gl_FragData" => {
                &mut self.wrote_builtin_color
            }
            Storage::Out => &mut self.wrote_user_out,
            _ => return,
        };
        if slot.is_none() {
            *slot = Some(var.name.clone());
        }
    }

    /// Reports static recursion among the defined functions as Mesa does at the end of
    /// compiling: `function `float g(float)' has static recursion` at 0:0(0).
    fn check_recursion(&mut self) {
        let n = self.functions.len();
        let mut adj = vec![Vec::new(); n];
        for &(a, b) in &self.calls {
            if a < n && b < n && !adj[a].contains(&b) {
                adj[a].push(b);
            }
        }
        // A function is recursive when it reaches itself: iterative search from each,
        // in the order of definition (the first Mesa names).
        for f in self.defined.clone() {
            let mut seen = vec![false; n];
            let mut stack = adj[f].clone();
            let mut hit = false;
            while let Some(g) = stack.pop() {
                if g == f {
                    hit = true;
                    break;
                }
                if !seen[g] {
                    seen[g] = true;
                    stack.extend(adj[g].iter().copied());
                }
            }
            if hit {
                let func = &self.functions[f];
                let params: Vec<String> = func
                    .params
                    .iter()
                    .map(|p| self.vars[*p].ty.to_string())
                    .collect();
                let text = format!(
                    "function `{} {}({})' has static recursion",
                    func.ret,
                    func.name,
                    params.join(", ")
                );
                self.error(Pos::new(0, 0), text);
                return;
            }
        }
    }
}

/// Type-checks a parsed shader into its typed tree; the errors go to `log`.
pub fn check(shader: &Shader, log: &mut Log) -> Option<Program> {
    let mut c = Checker::new(shader, log);
    let mut globals = Vec::new();
    for item in &shader.items {
        match item {
            crate::ast::External::Decl(d) => c.global_decl(d, &mut globals),
            crate::ast::External::Function(f) => c.function_def(f),
        }
    }
    if !c.log.has_errors() {
        c.check_outputs();
    }
    if !c.log.has_errors() {
        c.check_recursion();
    }
    if c.log.has_errors() {
        return None;
    }
    Some(Program {
        stage: c.stage,
        version: c.version,
        vars: c.vars,
        globals,
        functions: c.functions,
    })
}
