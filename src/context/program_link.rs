//! glLinkProgram: the link rules of GL 2.0 §2.15.2 as Mesa applies them, and the active
//! attributes and uniforms a linked program reports.
//!
//! The checks run in Mesa's order, each failure ending the link with Mesa's message:
//! 1. every attached shader compiled (`error: linking with uncompiled/unspecialized
//!    shader`);
//! 2. per stage present: exactly one `main` (`error: vertex shader lacks `main'`,
//!    `error: function `main' is multiply defined`) and every function called from it
//!    defined in some shader of the stage (`error: unresolved reference to function `f'`);
//! 3. a uniform declared in several shaders has one type and one initializer
//!    (`error: uniform `u' declared as type `vec4' and type `vec3'`);
//! 4. a fragment input has a vertex output of its name and type (`error: vertex shader
//!    output `c' declared as type `vec3', but fragment shader input declared as type
//!    `vec4'`; a used input nobody writes: `error: fragment shader varying c not written
//!    by vertex shader` then a line with `.`, which Mesa repeats once per internal
//!    re-link and softgl writes once).
//!
//! A program with no shaders, or with only one stage, links (Mesa's compatibility rule).
//!
//! "Active" is approximated without an optimiser: a variable is active when code reachable
//! from `main` (globals' initializers included) reads or writes it. Mesa decides after
//! dead-code elimination, so a uniform whose every use is optimised away is active here
//! and not there. An array uniform indexed only by constants is shortened to its highest
//! index used plus one, as Mesa's `update_array_sizes` does. Built-in attributes
//! (`gl_Vertex` ...) and built-in uniforms are listed as Mesa lists them, without location.
//!
//! Attribute locations: glBindAttribLocation's first, then the rest in declaration order,
//! largest first, each at the lowest free run of slots (Mesa's
//! `assign_attribute_or_color_locations`).

use std::collections::HashMap;
use std::sync::Arc;

use softgl_glsl::hir::{self, Const, Expr, ExprKind, Stmt, Storage, Value, VarId};
use softgl_glsl::types::{Scalar, Type};
use softgl_glsl::{builtins, Stage};

use super::shader_objects::{ShaderOrProgram, ShaderTable};
use super::Context;
use crate::gl::error::GlResult;

/// An active attribute.
#[derive(Clone, Debug, PartialEq)]
pub struct ActiveAttrib {
    /// Its name.
    pub name: String,
    /// Its GL type enum (GL_FLOAT_VEC4 ...).
    pub gl_type: u32,
    /// Its location (-1 for a built-in).
    pub location: i32,
}

/// An active uniform: one basic-typed leaf of a uniform variable (a struct's members each
/// their own, an array of basic type one with `size` elements).
#[derive(Clone, Debug, PartialEq)]
pub struct Uniform {
    /// Its name (`u`, `s.f`, `sa[1].f`), without `[0]`.
    pub name: String,
    /// Its type (scalar, vector, matrix or sampler).
    pub ty: Type,
    /// The array size reported (`None`: not an array).
    pub array: Option<u32>,
    /// The location of element 0 (-1 for a built-in).
    pub location: i32,
    /// The values: `size` elements of [`Uniform::components`] 32-bit words each (float
    /// bits, an int, or 0/1 for a bool).
    pub values: Vec<u32>,
}

impl Uniform {
    /// The name glGetActiveUniform reports (`a[0]` for an array).
    pub fn active_name(&self) -> String {
        if self.array.is_some() {
            format!("{}[0]", self.name)
        } else {
            self.name.clone()
        }
    }

    /// Words per element.
    pub fn components(&self) -> usize {
        words_per_element(&self.ty)
    }

    /// Elements.
    pub fn size(&self) -> usize {
        self.array.unwrap_or(1) as usize
    }
}

/// The 32-bit words one element of a basic type holds: its components, one unit for a
/// sampler.
pub fn words_per_element(ty: &Type) -> usize {
    match ty {
        Type::Sampler(_) => 1,
        t => t.components() as usize,
    }
}

/// What a successful link made.
#[derive(Clone, Debug, Default)]
pub struct Linked {
    /// The vertex shaders' checked trees.
    pub vertex: Vec<Arc<hir::Program>>,
    /// The fragment shaders' checked trees.
    pub fragment: Vec<Arc<hir::Program>>,
    /// Active attributes.
    pub attributes: Vec<ActiveAttrib>,
    /// Active uniforms, in location order.
    pub uniforms: Vec<Uniform>,
    /// The uniform and element of each location.
    pub locations: Vec<(usize, usize)>,
    /// The fragment shader as draws run it (`None` without a fragment stage; `Err` says
    /// why the engine cannot run it).
    pub draw: Option<Result<Arc<crate::shader::draw::FragShader>, String>>,
    /// The vertex shader as draws run it (`None` without a vertex stage).
    pub vert: Option<Result<Arc<crate::shader::vertex_draw::VertShader>, String>>,
    /// The fragment shader's user-defined outputs and their draw buffers.
    pub frag_outputs: Vec<super::frag_outputs::FragOutput>,
}

/// The GL type enum of a basic GLSL type (GL 2.0 table 2.9, GL 2.1's non-square matrices,
/// GL 3.0's unsigned and array sampler types).
pub fn gl_type(ty: &Type) -> u32 {
    use softgl_glsl::types::Dim;
    let vec = |s: Scalar, n: u8| -> u32 {
        let (one, two) = match s {
            Scalar::Float => (0x1406, 0x8B50),
            Scalar::Int => (0x1404, 0x8B53),
            Scalar::Bool => (0x8B56, 0x8B57),
            Scalar::Uint => (0x1405, 0x8DC6),
        };
        if n == 1 {
            one
        } else {
            two + n as u32 - 2
        }
    };
    match ty {
        Type::Scalar(s) => vec(*s, 1),
        Type::Vector(s, n) => vec(*s, *n),
        Type::Matrix { cols, rows } => match (cols, rows) {
            (2, 2) => 0x8B5A,
            (3, 3) => 0x8B5B,
            (4, 4) => 0x8B5C,
            (2, 3) => 0x8B65,
            (2, 4) => 0x8B66,
            (3, 2) => 0x8B67,
            (3, 4) => 0x8B68,
            (4, 2) => 0x8B69,
            _ => 0x8B6A,
        },
        Type::Sampler(s) => match (s.texel, s.dim, s.array, s.shadow) {
            (Scalar::Float, Dim::D1, false, false) => 0x8B5D,
            (Scalar::Float, Dim::D2, false, false) => 0x8B5E,
            (Scalar::Float, Dim::D3, false, false) => 0x8B5F,
            (Scalar::Float, Dim::Cube, false, false) => 0x8B60,
            (Scalar::Float, Dim::D1, false, true) => 0x8B61,
            (Scalar::Float, Dim::D2, false, true) => 0x8B62,
            (Scalar::Float, Dim::Rect, false, false) => 0x8B63,
            (Scalar::Float, Dim::Rect, false, true) => 0x8B64,
            (Scalar::Float, Dim::D1, true, false) => 0x8DC0,
            (Scalar::Float, Dim::D2, true, false) => 0x8DC1,
            (Scalar::Float, Dim::Buffer, _, _) => 0x8DC2,
            (Scalar::Float, Dim::D1, true, true) => 0x8DC3,
            (Scalar::Float, Dim::D2, true, true) => 0x8DC4,
            (Scalar::Float, Dim::Cube, _, true) => 0x8DC5,
            (Scalar::Int, Dim::D1, false, _) => 0x8DC9,
            (Scalar::Int, Dim::D2, false, _) => 0x8DCA,
            (Scalar::Int, Dim::D3, _, _) => 0x8DCB,
            (Scalar::Int, Dim::Cube, _, _) => 0x8DCC,
            (Scalar::Int, Dim::D1, true, _) => 0x8DCE,
            (Scalar::Int, Dim::D2, true, _) => 0x8DCF,
            (Scalar::Uint, Dim::D1, false, _) => 0x8DD1,
            (Scalar::Uint, Dim::D2, false, _) => 0x8DD2,
            (Scalar::Uint, Dim::D3, _, _) => 0x8DD3,
            (Scalar::Uint, Dim::Cube, _, _) => 0x8DD4,
            (Scalar::Uint, Dim::D1, true, _) => 0x8DD6,
            (Scalar::Uint, Dim::D2, true, _) => 0x8DD7,
            _ => 0x8B5E,
        },
        _ => 0,
    }
}

/// Which variables of one shader code reachable from `main` uses: `None` for a whole
/// use, `Some(n)` when only elements below `n` are read by constant indices.
#[derive(Default)]
struct Usage {
    vars: HashMap<VarId, Option<u32>>,
    calls: Vec<usize>,
    /// `ftransform()` is called: it reads `gl_Vertex` and `gl_ModelViewProjectionMatrix`.
    ftransform: bool,
}

/// A constant boolean condition's value.
fn constant_bool(e: &Expr) -> Option<bool> {
    match &e.value {
        Some(Const::Scalars(v)) => match v.first() {
            Some(Value::Bool(b)) => Some(*b),
            _ => None,
        },
        _ => None,
    }
}

impl Usage {
    fn whole(&mut self, v: VarId) {
        self.vars.insert(v, None);
    }

    fn element(&mut self, v: VarId, i: u32) {
        let e = self.vars.entry(v).or_insert(Some(0));
        if let Some(n) = e {
            *n = (*n).max(i.saturating_add(1));
        }
    }

    fn expr(&mut self, e: &Expr) {
        match &e.kind {
            ExprKind::Var(v) => self.whole(*v),
            ExprKind::Literal | ExprKind::Length(_) => {}
            ExprKind::Index(base, idx) => {
                let constant = match &idx.value {
                    Some(Const::Scalars(s)) => match s.first() {
                        Some(Value::Int(i)) => u32::try_from(*i).ok(),
                        Some(Value::Uint(i)) => Some(*i),
                        _ => None,
                    },
                    _ => None,
                };
                match (&base.kind, constant) {
                    (ExprKind::Var(v), Some(i)) if matches!(base.ty, Type::Array(..)) => {
                        self.element(*v, i)
                    }
                    _ => self.expr(base),
                }
                self.expr(idx);
            }
            ExprKind::Unary(_, a)
            | ExprKind::Convert(a)
            | ExprKind::Swizzle(a, _)
            | ExprKind::Field(a, _) => self.expr(a),
            ExprKind::Binary(_, a, b) | ExprKind::Assign(_, a, b) | ExprKind::Comma(a, b) => {
                self.expr(a);
                self.expr(b);
            }
            ExprKind::Ternary(a, b, c) => {
                self.expr(a);
                match constant_bool(a) {
                    Some(true) => self.expr(b),
                    Some(false) => self.expr(c),
                    None => {
                        self.expr(b);
                        self.expr(c);
                    }
                }
            }
            ExprKind::Builtin(f, args) => {
                self.ftransform |= f.name == "ftransform";
                args.iter().for_each(|a| self.expr(a))
            }
            ExprKind::Construct(args) => args.iter().for_each(|a| self.expr(a)),
            ExprKind::Call(f, args) => {
                self.calls.push(*f);
                args.iter().for_each(|a| self.expr(a));
            }
        }
    }

    fn stmt(&mut self, s: &Stmt) {
        match s {
            Stmt::Decl(_, Some(e)) | Stmt::Expr(e) | Stmt::Return(Some(e)) => self.expr(e),
            Stmt::Block(b) => b.iter().for_each(|s| self.stmt(s)),
            Stmt::Switch(e, b) => {
                self.expr(e);
                b.iter().for_each(|s| self.stmt(s));
            }
            // Mesa drops the branch a constant condition never takes, and what only it used.
            Stmt::If(c, a, b) => {
                self.expr(c);
                if constant_bool(c) != Some(false) {
                    self.stmt(a);
                }
                if let (Some(b), false) = (b, constant_bool(c) == Some(true)) {
                    self.stmt(b);
                }
            }
            Stmt::Loop {
                init,
                cond,
                step,
                body,
                ..
            } => {
                if let Some(i) = init {
                    self.stmt(i);
                }
                for e in cond.iter().chain(step.iter()) {
                    self.expr(e);
                }
                self.stmt(body);
            }
            _ => {}
        }
    }
}

/// One stage's shaders with what their reachable code uses: per shader, its usage.
struct StageUse<'a> {
    shaders: &'a [Arc<hir::Program>],
    used: Vec<Usage>,
}

/// Whether two functions have the same name and parameter types.
fn same_signature(a: &hir::Program, fa: usize, b: &hir::Program, fb: usize) -> bool {
    let (x, y) = (&a.functions[fa], &b.functions[fb]);
    x.name == y.name
        && x.params.len() == y.params.len()
        && x.params
            .iter()
            .zip(&y.params)
            .all(|(p, q)| a.vars[*p].ty == b.vars[*q].ty)
}

/// Checks `main` and the calls of one stage; the usage of each shader, or the error.
fn link_stage(shaders: &[Arc<hir::Program>], stage: Stage) -> Result<StageUse<'_>, String> {
    let mains: Vec<usize> = (0..shaders.len())
        .filter(|&i| shaders[i].main().is_some())
        .collect();
    match mains.len() {
        0 => return Err(format!("error: {} shader lacks `main'\n", stage.name())),
        1 => {}
        _ => return Err("error: function `main' is multiply defined\n".into()),
    }
    let mut used: Vec<Usage> = shaders.iter().map(|_| Usage::default()).collect();
    let mut done: Vec<Vec<bool>> = shaders
        .iter()
        .map(|s| vec![false; s.functions.len()])
        .collect();
    let m = mains[0];
    let main_fn = shaders[m]
        .functions
        .iter()
        .position(|f| f.name == "main" && f.body.is_some())
        .unwrap_or(0);
    let mut work = vec![(m, main_fn)];
    // Globals' initializers run before main.
    for (i, s) in shaders.iter().enumerate() {
        for (_, init) in &s.globals {
            if let Some(e) = init {
                used[i].expr(e);
            }
        }
        let calls = std::mem::take(&mut used[i].calls);
        work.extend(calls.into_iter().map(|f| (i, f)));
    }
    while let Some((si, fi)) = work.pop() {
        // A prototype resolves to a definition in any shader of the stage.
        let (si, fi) = if shaders[si].functions[fi].body.is_some() {
            (si, fi)
        } else {
            let found = shaders.iter().enumerate().find_map(|(sj, s)| {
                (0..s.functions.len()).find_map(|fj| {
                    (s.functions[fj].body.is_some() && same_signature(&shaders[si], fi, s, fj))
                        .then_some((sj, fj))
                })
            });
            match found {
                Some(f) => f,
                None => {
                    return Err(format!(
                        "error: unresolved reference to function `{}'\n",
                        shaders[si].functions[fi].name
                    ))
                }
            }
        };
        if std::mem::replace(&mut done[si][fi], true) {
            continue;
        }
        for s in shaders[si].functions[fi].body.iter().flatten() {
            used[si].stmt(s);
        }
        let calls = std::mem::take(&mut used[si].calls);
        work.extend(calls.into_iter().map(|f| (si, f)));
    }
    Ok(StageUse { shaders, used })
}

/// A global variable of a stage: the first declaration, its initializer's value, and its
/// use (`None`: unused; `Some(None)`: whole; `Some(Some(n))`: elements below `n`).
type Global<'a> = (&'a hir::Var, Option<&'a Const>, Option<Option<u32>>);

/// The global variables of one storage of a stage, first declaration of each name, with
/// whether it is used and how.
fn globals<'a>(st: &'a StageUse<'_>, keep: impl Fn(&hir::Var) -> bool) -> Vec<Global<'a>> {
    let mut out: Vec<Global<'a>> = Vec::new();
    for (i, s) in st.shaders.iter().enumerate() {
        let inits: HashMap<VarId, Option<&Const>> = s
            .globals
            .iter()
            .map(|(v, e)| (*v, e.as_ref().and_then(|e| e.value.as_ref())))
            .collect();
        for (id, var) in s.vars.iter().enumerate() {
            let global = inits.contains_key(&id) || matches!(var.storage, Storage::Builtin(_));
            if !global || !keep(var) {
                continue;
            }
            let use_ = st.used[i].vars.get(&id).copied();
            let init = inits.get(&id).copied().flatten().or(var.value.as_ref());
            match out.iter_mut().find(|(v, ..)| v.name == var.name) {
                Some(o) => {
                    o.2 = merge_use(o.2, use_);
                }
                None => out.push((var, init, use_)),
            }
        }
    }
    out
}

/// Two uses of one variable together.
fn merge_use(a: Option<Option<u32>>, b: Option<Option<u32>>) -> Option<Option<u32>> {
    match (a, b) {
        (None, x) | (x, None) => x,
        (Some(None), _) | (_, Some(None)) => Some(None),
        (Some(Some(x)), Some(Some(y))) => Some(Some(x.max(y))),
    }
}

/// The scalar words of a constant, flattened in declaration order.
fn flatten(c: &Const, out: &mut Vec<u32>) {
    match c {
        Const::Scalars(v) => out.extend(v.iter().map(|v| match *v {
            Value::Bool(b) => b as u32,
            Value::Int(i) => i as u32,
            Value::Uint(u) => u,
            Value::Float(f) => f.to_bits(),
        })),
        Const::Aggregate(v) => v.iter().for_each(|c| flatten(c, out)),
    }
}

/// The number of scalar words of a type.
fn words(ty: &Type) -> usize {
    match ty {
        Type::Array(e, n) => words(e) * n.unwrap_or(0) as usize,
        Type::Struct(s) => s.members.iter().map(|m| words(&m.ty)).sum(),
        t => words_per_element(t),
    }
}

/// The leaves of uniform `name` of type `ty` with their values from `init` (at `*at`);
/// `used` shortens a top-level array.
fn leaves(name: &str, ty: &Type, used: Option<u32>, init: &[u32], at: &mut usize) -> Vec<Uniform> {
    let mut out = vec![];
    match ty {
        Type::Struct(s) => {
            for m in &s.members {
                out.extend(leaves(&format!("{name}.{}", m.name), &m.ty, None, init, at));
            }
        }
        Type::Array(e, n) if matches!(**e, Type::Struct(_) | Type::Array(..)) => {
            let n = n.unwrap_or(0);
            for i in 0..n {
                let mut l = leaves(&format!("{name}[{i}]"), e, None, init, at);
                if used.is_none_or(|u| i < u) {
                    out.append(&mut l);
                }
            }
        }
        Type::Array(e, n) => {
            let n = n.unwrap_or(0) as usize;
            let size = used.map_or(n, |u| (u as usize).min(n)).max(1);
            let c = words_per_element(e);
            let mut values = vec![0u32; size * c];
            for (k, v) in values.iter_mut().enumerate() {
                *v = init.get(*at + k).copied().unwrap_or(0);
            }
            *at += n * c;
            out.push(Uniform {
                name: name.to_string(),
                ty: (**e).clone(),
                array: Some(size as u32),
                location: -1,
                values,
            });
        }
        t => {
            let c = words_per_element(t);
            let values = (0..c).map(|k| init.get(*at + k).copied().unwrap_or(0));
            let values = values.collect();
            *at += c;
            out.push(Uniform {
                name: name.to_string(),
                ty: t.clone(),
                array: None,
                location: -1,
                values,
            });
        }
    }
    out
}

/// Links the shaders of `table`'s program: the linked program, or the info log.
pub fn link(
    table: &ShaderTable,
    shader_names: &[u32],
    bindings: &HashMap<String, u32>,
) -> Result<Linked, String> {
    let mut vertex = vec![];
    let mut fragment = vec![];
    for s in shader_names {
        let Some(ShaderOrProgram::Shader(sh)) = table.objects.get(s) else {
            continue;
        };
        let Some(tree) = sh.compiled.clone().filter(|_| sh.compile_status) else {
            return Err("error: linking with uncompiled/unspecialized shader".into());
        };
        match sh.stage {
            Stage::Vertex => vertex.push(tree),
            _ => fragment.push(tree),
        }
    }
    let vs = if vertex.is_empty() {
        None
    } else {
        Some(link_stage(&vertex, Stage::Vertex)?)
    };
    let fs = if fragment.is_empty() {
        None
    } else {
        Some(link_stage(&fragment, Stage::Fragment)?)
    };
    let stages: Vec<&StageUse> = vs.iter().chain(fs.iter()).collect();
    let ftransform = vs
        .as_ref()
        .is_some_and(|v| v.used.iter().any(|u| u.ftransform));

    // Uniforms: one type and initializer per name across every shader.
    let is_uniform = |v: &hir::Var| {
        matches!(
            v.storage,
            Storage::Uniform | Storage::Builtin(builtins::variables::Kind::Uniform)
        ) && v.block.is_none()
    };
    let mut all: Vec<Global> = vec![];
    for st in &stages {
        for (var, init, use_) in globals(st, is_uniform) {
            match all.iter_mut().find(|(v, ..)| v.name == var.name) {
                Some(o) => {
                    if o.0.ty != var.ty {
                        return Err(format!(
                            "error: uniform `{}' declared as type `{}' and type `{}'\n",
                            var.name, var.ty, o.0.ty
                        ));
                    }
                    if let (Some(a), Some(b)) = (o.1, init) {
                        if a != b {
                            return Err(format!(
                                "error: initializers for uniform `{}' have differing values\n",
                                var.name
                            ));
                        }
                    }
                    o.1 = o.1.or(init);
                    o.2 = merge_use(o.2, use_);
                }
                None => all.push((var, init, use_)),
            }
        }
    }
    // Within one stage the first declaration wins; check the others' types too.
    for st in &stages {
        for s in st.shaders.iter() {
            for v in s.vars.iter().filter(|v| is_uniform(v)) {
                if let Some(o) = all.iter().find(|(a, ..)| a.name == v.name) {
                    if o.0.ty != v.ty && s.globals.iter().any(|(g, _)| s.vars[*g].name == v.name) {
                        return Err(format!(
                            "error: uniform `{}' declared as type `{}' and type `{}'\n",
                            v.name, v.ty, o.0.ty
                        ));
                    }
                }
            }
        }
    }

    // Varyings.
    if let (Some(vs), Some(fs)) = (&vs, &fs) {
        let outs = globals(vs, |v| v.storage == Storage::Out);
        let ins = globals(fs, |v| v.storage == Storage::In);
        for (input, _, use_) in ins {
            match outs.iter().find(|(o, ..)| o.name == input.name) {
                Some((o, ..)) if o.ty != input.ty => {
                    return Err(format!(
                        "error: vertex shader output `{}' declared as type `{}', but fragment \
                         shader input declared as type `{}'\n",
                        o.name, o.ty, input.ty
                    ))
                }
                None if use_.is_some() => {
                    return Err(format!(
                        "error: fragment shader varying {} not written by vertex shader\n.",
                        input.name
                    ))
                }
                _ => {}
            }
        }
    }

    // ftransform() reads two built-ins the tree does not name.
    let mvp = hir::Var {
        name: "gl_ModelViewProjectionMatrix".into(),
        ty: Type::mat(4, 4),
        storage: Storage::Builtin(builtins::variables::Kind::Uniform),
        interp: None,
        centroid: false,
        invariant: false,
        location: None,
        value: None,
        block: None,
        read_only: true,
        pos: Default::default(),
    };
    if ftransform && !all.iter().any(|(v, ..)| v.name == mvp.name) {
        all.push((&mvp, None, Some(None)));
    }

    // Active uniforms and their locations.
    let mut linked = Linked {
        vertex: vertex.clone(),
        fragment: fragment.clone(),
        ..Default::default()
    };
    for (var, init, use_) in all {
        let Some(use_) = use_ else { continue };
        let mut words_ = Vec::with_capacity(words(&var.ty));
        if let Some(c) = init {
            flatten(c, &mut words_);
        }
        let mut at = 0;
        for mut u in leaves(&var.name, &var.ty, use_, &words_, &mut at) {
            if !var.name.starts_with("gl_") {
                u.location = linked.locations.len() as i32;
                let index = linked.uniforms.len();
                linked.locations.extend((0..u.size()).map(|e| (index, e)));
            }
            linked.uniforms.push(u);
        }
    }

    // Active attributes.
    if let Some(vs) = &vs {
        let is_attr = |v: &hir::Var| {
            matches!(
                v.storage,
                Storage::In | Storage::Builtin(builtins::variables::Kind::Input)
            )
        };
        let mut free = [true; super::arrays::MAX_VERTEX_ATTRIBS];
        let mut pending = vec![];
        let mut attrs = globals(vs, is_attr);
        let vertex = hir::Var {
            name: "gl_Vertex".into(),
            ty: Type::vec(Scalar::Float, 4),
            storage: Storage::Builtin(builtins::variables::Kind::Input),
            ..mvp.clone()
        };
        if ftransform && !attrs.iter().any(|(v, ..)| v.name == vertex.name) {
            attrs.push((&vertex, None, Some(None)));
        }
        // gl_Vertex is generic attribute 0 in the compatibility profile: Mesa keeps the
        // slot from the others.
        if attrs
            .iter()
            .any(|(v, _, u)| v.name == vertex.name && u.is_some())
        {
            free[0] = false;
        }
        for (var, _, use_) in attrs {
            if use_.is_none() {
                continue;
            }
            let slots = match var.ty {
                Type::Matrix { cols, .. } => cols as usize,
                _ => 1,
            };
            let mut a = ActiveAttrib {
                name: var.name.clone(),
                gl_type: gl_type(&var.ty),
                location: -1,
            };
            if matches!(var.storage, Storage::In) {
                // `layout(location = N)` wins over glBindAttribLocation (GL 3.3 §2.11.3).
                let explicit = var.location.and_then(|l| u32::try_from(l).ok());
                if let Some(b) = explicit.or_else(|| bindings.get(&var.name).copied()) {
                    a.location = b as i32;
                    for s in free.iter_mut().skip(b as usize).take(slots) {
                        *s = false;
                    }
                } else {
                    pending.push((linked.attributes.len(), slots));
                }
            }
            linked.attributes.push(a);
        }
        pending.sort_by_key(|p| std::cmp::Reverse(p.1));
        for (i, slots) in pending {
            let Some(at) = (0..=free.len().saturating_sub(slots))
                .find(|&s| free[s..s + slots].iter().all(|f| *f))
            else {
                return Err(format!(
                    "error: insufficient contiguous locations available for vertex shader \
                     input `{}'\n",
                    linked.attributes[i].name
                ));
            };
            free[at..at + slots].iter_mut().for_each(|f| *f = false);
            linked.attributes[i].location = at as i32;
        }
    }
    Ok(linked)
}

impl Context {
    /// glLinkProgram.
    pub fn link_program(&mut self, program: u32) -> GlResult<()> {
        let p = self.shaders.table.program(program)?;
        let result =
            link(&self.shaders.table, &p.shaders.clone(), &p.bindings.clone()).and_then(|mut l| {
                l.frag_outputs = super::frag_outputs::assign(&l.fragment, &p.frag_bindings)?;
                Ok(l)
            });
        let p = self.shaders.table.program_mut(program)?;
        p.validate_status = false;
        match result {
            Ok(mut l) => {
                let vertex = !l.vertex.is_empty();
                let outs = &l.frag_outputs;
                l.draw = match l.fragment.as_slice() {
                    [] => None,
                    [f] => Some(crate::shader::draw::FragShader::prepare(
                        Arc::new(super::frag_outputs::with_locations(f, outs)),
                        vertex,
                    )),
                    _ => Some(Err("several fragment shaders".into())),
                };
                let attrs = &l.attributes;
                let location = |n: &str| attrs.iter().find(|a| a.name == n).map(|a| a.location);
                l.vert = match l.vertex.as_slice() {
                    [] => None,
                    [v] => Some(crate::shader::vertex_draw::VertShader::prepare(v, location)),
                    _ => Some(Err("several vertex shaders".into())),
                };
                p.link_status = true;
                p.log.clear();
                p.linked = Some(l);
            }
            Err(log) => {
                p.link_status = false;
                p.log = log;
                p.linked = None;
            }
        }
        Ok(())
    }
}
