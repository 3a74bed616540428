//! Declarations: type specifiers, structs, variables with their qualifiers (GLSL 4.3:
//! storage, interpolation, `invariant`, `layout`), interface blocks (4.3.7, from 1.40
//! for uniform blocks and 1.50 for inputs and outputs) and functions (6.1: prototypes,
//! definitions, overloading by parameter types).
//!
//! The legality rules per stage and version and their messages are Mesa's
//! (`ast_to_hir.cpp`): `attribute` only in vertex shaders, `in`/`out` globals from
//! 1.30, varyings of float base type before 1.30, integer fragment inputs `flat`,
//! samplers only as uniforms or parameters, uniform initializers from 1.20, no
//! initializer on inputs and outputs, `gl_` names reserved (apart from the built-ins a
//! shader may redeclare, such as `gl_TexCoord[]` with a size).

use super::{Checker, Symbol};
use crate::ast::{self, Decl, Declarator, FullType, Qualifier, TypeName, TypeSpec};
use crate::builtins;
use crate::diag::Pos;
use crate::hir::{self, Storage, Var, VarId};
use crate::types::{Member, Scalar, Struct, Type};
use std::sync::Arc;

/// The qualifiers of a declaration, gathered.
#[derive(Clone, Debug, Default)]
pub(super) struct Quals {
    pub storage: Option<ast::Storage>,
    pub centroid: bool,
    pub interp: Option<ast::Interp>,
    pub invariant: bool,
    pub location: Option<i32>,
    pub layout: Vec<String>,
    /// `const in` (a parameter).
    pub const_in: bool,
}

/// Mesa's message for an array of arrays.
pub(super) const AOA: &str =
    "GL_ARB_arrays_of_arrays or GLSL 4.30 required for defining arrays of arrays.";

/// Built-in variables a shader may redeclare (to size, qualify or make invariant).
const REDECLARABLE: &[&str] = &[
    "gl_TexCoord",
    "gl_FragDepth",
    "gl_FragCoord",
    "gl_Color",
    "gl_SecondaryColor",
    "gl_FrontColor",
    "gl_BackColor",
    "gl_FrontSecondaryColor",
    "gl_BackSecondaryColor",
    "gl_ClipDistance",
    "gl_Position",
    "gl_PointSize",
    "gl_FragColor",
    "gl_FragData",
];

impl Checker<'_> {
    /// Gathers the qualifiers (their order was checked by the parser's grammar).
    /// Reports a storage qualifier written twice and a `layout` value that is not a
    /// literal (constant expressions there are GLSL 4.40), at `pos`.
    pub(super) fn quals(&mut self, q: &[Qualifier], pos: Pos) -> Option<Quals> {
        let mut out = Quals::default();
        for q in q {
            match q {
                Qualifier::Storage(ast::Storage::Centroid) => out.centroid = true,
                // `const in` (a parameter).
                Qualifier::Storage(ast::Storage::In)
                    if out.storage == Some(ast::Storage::Const) =>
                {
                    out.storage = Some(ast::Storage::In);
                    out.const_in = true;
                }
                Qualifier::Storage(_) if out.storage.is_some() => {
                    self.error(pos, "duplicate storage qualifier");
                    return None;
                }
                Qualifier::Storage(s) => out.storage = Some(*s),
                Qualifier::Interp(i) => out.interp = Some(*i),
                Qualifier::Invariant => out.invariant = true,
                Qualifier::Precision(_) => {}
                Qualifier::Layout(ids) => {
                    for id in ids {
                        if let Some(e) = &id.value {
                            if !matches!(e.kind, ast::ExprKind::Int(_) | ast::ExprKind::Uint(_)) {
                                self.error(id.pos, "compile-time constant expressions require GLSL 4.40 or ARB_enhanced_layouts");
                                return None;
                            }
                        }
                        if id.name == "location" {
                            let v = id.value.as_ref().and_then(|e| self.expr(e));
                            out.location = v
                                .and_then(|v| v.value.as_ref().and_then(super::fold::as_int))
                                .map(|v| v as i32);
                        }
                        out.layout.push(id.name.clone());
                    }
                }
            }
        }
        Some(out)
    }

    /// The semantic type of a type specifier, with extra dimensions `dims` after the
    /// declared name; `None` after reporting an error.
    pub(super) fn resolve_type(
        &mut self,
        spec: &TypeSpec,
        dims: &[ast::ArraySize],
    ) -> Option<Type> {
        let base = match &spec.name {
            TypeName::Named(n) => match Type::named(n) {
                Some(t) if t.exists_with(self.version, &self.exts) => t,
                Some(_) | None => match self.struct_named(n) {
                    Some(s) => Type::Struct(s),
                    None => {
                        self.error(spec.pos, format!("`{n}' undeclared"));
                        return None;
                    }
                },
            },
            TypeName::Struct(s) => Type::Struct(self.struct_spec(s)?),
        };
        let all: Vec<&ast::ArraySize> = spec.array.iter().chain(dims.iter()).collect();
        if all.len() > 1 {
            self.error(spec.pos, AOA);
            return None;
        }
        match all.first() {
            None => Some(base),
            Some(None) => Some(base.array(None)),
            Some(Some(e)) => {
                let n = self.array_size(e)?;
                Some(base.array(Some(n)))
            }
        }
    }

    /// A constant array size: integral, constant and positive.
    pub(super) fn array_size(&mut self, e: &ast::Expr) -> Option<u32> {
        let x = self.expr(e)?;
        if !matches!(x.ty, Type::Scalar(Scalar::Int | Scalar::Uint)) {
            self.error(e.pos, "array size must be integer type");
            return None;
        }
        let Some(v) = x.value.as_ref().and_then(super::fold::as_int) else {
            self.error(e.pos, "array size must be a constant valued expression");
            return None;
        };
        if v <= 0 {
            self.error(e.pos, "array size must be > 0");
            return None;
        }
        Some(v.min(u32::MAX as i64) as u32)
    }

    /// Defines a struct type (named or not) and declares its name in the scope.
    fn struct_spec(&mut self, s: &ast::StructSpec) -> Option<Arc<Struct>> {
        let mut members = Vec::new();
        for m in &s.members {
            for d in &m.names {
                let ty = self.resolve_type(&m.ty.spec, &d.array)?;
                if ty == Type::Void {
                    // Mesa accepts a void member and only the use fails.
                }
                members.push(Member {
                    name: d.name.clone(),
                    ty,
                });
            }
        }
        let name = s.name.clone().unwrap_or_else(|| "#anon_struct".into());
        let st = Arc::new(Struct { name, members });
        if let Some(n) = &s.name {
            if n.starts_with("gl_") {
                self.error(
                    s.pos,
                    format!("identifier `{n}' uses reserved `gl_' prefix"),
                );
                return None;
            }
            if self.lookup_local(n).is_some() {
                self.error(s.pos, format!("struct `{n}' previously defined"));
                return None;
            }
            self.declare(n, Symbol::Struct(st.clone()));
        }
        Some(st)
    }

    /// A declaration at file scope.
    pub(super) fn global_decl(&mut self, d: &Decl, globals: &mut Vec<(VarId, Option<hir::Expr>)>) {
        let mut out = Vec::new();
        self.decl(d, &mut out);
        for s in out {
            if let hir::Stmt::Decl(v, init) = s {
                globals.push((v, init));
            }
        }
    }

    /// A declaration anywhere; the variables declared become `Decl` statements.
    pub(super) fn decl(&mut self, d: &Decl, out: &mut Vec<hir::Stmt>) {
        match d {
            Decl::Vars { ty, vars } => self.var_decl(ty, vars, out),
            Decl::Prototype(p) => {
                if !self.global_scope() {
                    self.error(
                        p.pos,
                        format!(
                            "declaration of function `{}' not allowed within function body",
                            p.name
                        ),
                    );
                    return;
                }
                self.prototype(p, false);
            }
            Decl::Precision { ty, pos, .. } => {
                let ok = match &ty.name {
                    TypeName::Named(n) => matches!(
                        Type::named(n),
                        Some(Type::Scalar(Scalar::Float | Scalar::Int) | Type::Sampler(_))
                    ),
                    TypeName::Struct(_) => false,
                };
                if !ok || !ty.array.is_empty() {
                    self.error(
                        *pos,
                        "default precision statements apply only to float, int, and opaque types",
                    );
                }
            }
            Decl::Default { .. } => {}
            Decl::Block(b) => self.block(b, out),
            Decl::Invariant { names } => {
                for (n, pos) in names {
                    if self.lookup(n).is_none() {
                        self.error(*pos, format!("`{n}' undeclared"));
                        return;
                    }
                }
            }
        }
    }

    fn var_decl(&mut self, fty: &FullType, vars: &[Declarator], out: &mut Vec<hir::Stmt>) {
        let pos = fty.spec.pos;
        let Some(q) = self.quals(&fty.qualifiers, pos) else {
            return;
        };
        if vars.is_empty() {
            // `struct S {...};` or a type alone.
            let _ = self.resolve_type(&fty.spec, &[]);
            return;
        }
        let Some(base) = self.resolve_type(&fty.spec, &[]) else {
            return;
        };
        for d in vars {
            let Some(ty) = self.with_dims(base.clone(), &d.array, d.pos) else {
                return;
            };
            if !self.one_var(&q, ty, (&d.name, d.pos, d.init.as_ref()), pos, out) {
                return;
            }
        }
    }

    /// `base` with the dimensions written after a declared name (one at most: arrays
    /// of arrays are GLSL 4.30).
    pub(super) fn with_dims(
        &mut self,
        base: Type,
        dims: &[ast::ArraySize],
        pos: Pos,
    ) -> Option<Type> {
        match dims {
            [] => Some(base),
            [_] if matches!(base, Type::Array(..)) => {
                self.error(pos, AOA);
                None
            }
            [None] => Some(base.array(None)),
            [Some(e)] => self.array_size(e).map(|n| base.array(Some(n))),
            _ => {
                self.error(pos, AOA);
                None
            }
        }
    }

    /// Checks and declares one variable (name, its position, its initializer); false
    /// after an error.
    pub(super) fn one_var(
        &mut self,
        q: &Quals,
        ty: Type,
        d: (&str, Pos, Option<&ast::Expr>),
        pos: Pos,
        out: &mut Vec<hir::Stmt>,
    ) -> bool {
        use ast::Storage as S;
        let (name, dpos, dinit) = d;
        let name = &name.to_string();
        let global = self.global_scope();
        let stage = self.stage;
        let vt = self.version_text();
        // Redeclared built-ins.
        if name.starts_with("gl_") {
            if global && REDECLARABLE.contains(&name.as_str()) && self.builtin_var(name).is_some() {
                let id = self.builtin_var(name).unwrap_or_default();
                let fits = match self.vars[id].storage {
                    Storage::Builtin(builtins::variables::Kind::Output) => {
                        matches!(q.storage, Some(ast::Storage::Out | ast::Storage::Varying))
                    }
                    Storage::Builtin(builtins::variables::Kind::Input) => matches!(
                        q.storage,
                        Some(ast::Storage::In | ast::Storage::Varying | ast::Storage::Attribute)
                    ),
                    _ => false,
                };
                if !fits {
                    self.error(
                        dpos,
                        format!("redeclaration cannot change qualification of `{name}'"),
                    );
                    return false;
                }
                if let (Type::Array(_, _), Type::Array(..)) = (&self.vars[id].ty, &ty) {
                    self.vars[id].ty = ty;
                }
                self.vars[id].invariant |= q.invariant;
                self.vars[id].interp = q.interp.or(self.vars[id].interp);
                return true;
            }
            self.error(
                pos,
                format!("identifier `{name}' uses reserved `gl_' prefix"),
            );
            return false;
        }
        if q.invariant && !global {
            self.error(
                pos,
                format!(
                    "`{name}' cannot be marked invariant; interfaces between shader stages only"
                ),
            );
            return false;
        }
        let storage = match q.storage {
            None => Storage::Plain,
            Some(S::Const) => Storage::Const,
            Some(S::Uniform) => Storage::Uniform,
            Some(S::Attribute) => Storage::In,
            Some(S::Varying) if stage == crate::types::Stage::Fragment => Storage::In,
            Some(S::Varying) => Storage::Out,
            Some(S::In) => Storage::In,
            Some(S::Out) => Storage::Out,
            Some(S::Inout) | Some(S::Centroid) => Storage::Plain,
        };
        match q.storage {
            Some(S::Attribute) if stage != crate::types::Stage::Vertex => {
                self.error(
                    pos,
                    "`attribute' variables may not be declared in the fragment shader",
                );
                return false;
            }
            Some(s @ (S::Attribute | S::Varying | S::Uniform)) if !global => {
                let w = match s {
                    S::Attribute => "attribute",
                    S::Varying => "varying",
                    _ => "uniform",
                };
                self.error(
                    pos,
                    format!("{w} variable `{name}' must be declared at global scope"),
                );
                return false;
            }
            Some(s @ (S::In | S::Out)) if !self.at_least(130) => {
                let w = if s == S::In { "in" } else { "out" };
                self.error(pos, format!("`{w}' qualifier in declaration of `{name}' only valid for function parameters in {vt}"));
                return false;
            }
            Some(s @ (S::In | S::Out | S::Inout)) if !global => {
                let w = match s {
                    S::In => "in",
                    S::Out => "out",
                    _ => "inout",
                };
                self.error(pos, format!("`{w}' qualifier in declaration of `{name}' only valid for function parameters in {vt}"));
                return false;
            }
            _ => {}
        }
        let base = element(&ty);
        let is_int = matches!(base.scalar(), Some(Scalar::Int | Scalar::Uint)) || contains_int(&ty);
        if storage == Storage::In && stage == crate::types::Stage::Vertex {
            let bad = match base {
                Type::Scalar(Scalar::Bool) | Type::Vector(Scalar::Bool, _) | Type::Struct(_) => {
                    true
                }
                Type::Scalar(_) | Type::Vector(..) => is_int && !self.at_least(130),
                _ => false,
            };
            if bad {
                self.error(
                    pos,
                    format!("vertex shader input / attribute cannot have type `{base}'"),
                );
                return false;
            }
            if matches!(ty, Type::Array(..)) && !self.at_least(150) {
                self.error(pos, format!("vertex shader input / attribute cannot have array type in {vt} (GLSL 1.50 required)"));
                return false;
            }
        }
        let varying = matches!(storage, Storage::In | Storage::Out)
            && !(storage == Storage::In && stage == crate::types::Stage::Vertex)
            && !(storage == Storage::Out
                && stage == crate::types::Stage::Fragment
                && self.at_least(130));
        if varying {
            if matches!(base.scalar(), Some(Scalar::Bool)) || matches!(base, Type::Sampler(_)) {
                self.error(pos, "illegal type for a varying variable");
                return false;
            }
            if !self.at_least(130) && base.scalar() != Some(Scalar::Float) {
                self.error(
                    pos,
                    format!("varying variables must be of base type float in {vt}"),
                );
                return false;
            }
            if storage == Storage::In
                && stage == crate::types::Stage::Fragment
                && is_int
                && q.interp != Some(ast::Interp::Flat)
            {
                self.error(pos, "if a fragment input is (or contains) an integer, then it must be qualified with 'flat'");
                return false;
            }
        }
        if matches!(base, Type::Sampler(_)) && storage != Storage::Uniform {
            self.error(pos, "image/sampler variables may only be declared as function parameters or uniform-qualified global variables");
            return false;
        }
        if q.location.is_some() && storage == Storage::Uniform {
            self.error(pos, "uniform explicit location requires GL_ARB_explicit_uniform_location and either GL_ARB_explicit_attrib_location or GLSL 3.30.");
            return false;
        }
        let varying_side = (storage == Storage::Out && stage == crate::types::Stage::Vertex)
            || (storage == Storage::In && stage == crate::types::Stage::Fragment);
        if q.location.is_some() && varying_side {
            let what = if storage == Storage::Out {
                "output"
            } else {
                "input"
            };
            self.error(pos, format!("shader {what} explicit location requires GL_ARB_separate_shader_objects extension or GLSL 4.20"));
            return false;
        }
        if q.location.is_some() && storage == Storage::Const {
            let st = stage.name();
            self.error(
                pos,
                format!("global constant cannot be given an explicit location in {st} shader"),
            );
            return false;
        }
        if let Some(i) = q
            .interp
            .filter(|_| storage == Storage::In && stage == crate::types::Stage::Vertex)
        {
            let w = interp_name(i);
            self.error(
                pos,
                format!("interpolation qualifier '{w}' cannot be applied to vertex shader inputs"),
            );
            return false;
        }
        if storage == Storage::Out
            && stage == crate::types::Stage::Fragment
            && matches!(base, Type::Matrix { .. } | Type::Struct(_))
        {
            self.error(
                pos,
                "fragment shader output cannot have struct or matrix type",
            );
            return false;
        }
        if let Some(i) = q
            .interp
            .filter(|_| !matches!(storage, Storage::In | Storage::Out))
        {
            let w = interp_name(i);
            self.error(pos, format!("interpolation qualifier `{w}' can only be applied to shader inputs or outputs."));
            return false;
        }
        if q.location.is_some()
            && !self.at_least(330)
            && !self.ext("GL_ARB_explicit_attrib_location")
        {
            let what = if storage == Storage::Out {
                "shader output"
            } else {
                "shader input"
            };
            if matches!(storage, Storage::In | Storage::Out) {
                self.error(pos, format!("{what} explicit location requires GL_ARB_explicit_attrib_location extension or GLSL 3.30"));
                return false;
            }
        }
        // Name conflicts in this scope.
        if let Some(sym) = self.lookup_local(name).cloned() {
            match sym {
                Symbol::Var(v) if global && self.vars[v].ty != ty => {
                    self.error(
                        dpos,
                        format!("redeclaration of `{name}' has incorrect type"),
                    );
                }
                Symbol::Var(_) => self.error(dpos, format!("`{name}' redeclared")),
                _ => self.error(
                    pos,
                    format!("name `{name}' already taken in the current scope"),
                ),
            }
            return false;
        }
        let mut var = Var {
            name: name.clone(),
            ty: ty.clone(),
            storage,
            interp: q.interp,
            centroid: q.centroid,
            invariant: q.invariant,
            location: q.location,
            value: None,
            block: None,
            read_only: matches!(storage, Storage::Const | Storage::Uniform | Storage::In),
            pos: dpos,
        };
        let mut init = None;
        if let Some(e) = dinit {
            let ipos = e.pos;
            match storage {
                Storage::Uniform if !self.at_least(120) => {
                    self.error(
                        ipos,
                        format!("cannot initialize uniform {name} in {vt} (GLSL 1.20 required)"),
                    );
                    return false;
                }
                Storage::In => {
                    let w = if stage == crate::types::Stage::Vertex {
                        "attribute"
                    } else {
                        "varying"
                    };
                    self.error(
                        ipos,
                        format!(
                            "cannot initialize {} shader input / {w} {name}",
                            stage.name()
                        ),
                    );
                    return false;
                }
                Storage::Out => {
                    self.error(
                        ipos,
                        format!("cannot initialize {} shader output {name}", stage.name()),
                    );
                    return false;
                }
                _ => {}
            }
            let Some(x) = self.initializer(e, &ty) else {
                return false;
            };
            if matches!(ty, Type::Array(..)) && !self.at_least(120) {
                self.error(pos, format!("whole array assignment forbidden in {vt} (GLSL 1.20 or GLSL ES 3.00 required)"));
                return false;
            }
            let x = match self.assign_convert(x, &ty) {
                Ok(x) => x,
                Err(found) => {
                    self.error(pos, format!("initializer of type {found} cannot be assigned to variable of type {ty}"));
                    return false;
                }
            };
            if storage == Storage::Const {
                match &x.value {
                    Some(v) => var.value = Some(v.clone()),
                    None => {
                        self.error(ipos, format!("initializer of const variable `{name}' must be a constant expression"));
                        return false;
                    }
                }
            }
            if let Type::Array(_, None) = var.ty {
                var.ty = x.ty.clone();
            }
            init = Some(x);
        } else if storage == Storage::Const {
            self.error(
                pos,
                format!("const declaration of `{name}' must be initialized"),
            );
            return false;
        }
        let id = self.add_var(var);
        self.declare(name, Symbol::Var(id));
        out.push(hir::Stmt::Decl(id, init));
        true
    }

    /// An initializer (an expression, or `{...}` lists from 4.20 which Mesa's
    /// 1.10 to 3.30 reject).
    fn initializer(&mut self, e: &ast::Expr, _ty: &Type) -> Option<hir::Expr> {
        if let ast::ExprKind::InitList(_) = e.kind {
            self.error(
                e.pos,
                "initializer lists require GLSL 4.20 or GL_ARB_shading_language_420pack",
            );
            return None;
        }
        self.expr(e)
    }
}

/// The qualifier's keyword.
fn interp_name(i: ast::Interp) -> &'static str {
    match i {
        ast::Interp::Flat => "flat",
        ast::Interp::Smooth => "smooth",
        ast::Interp::Noperspective => "noperspective",
    }
}

/// The element type of an array (the type itself otherwise).
fn element(t: &Type) -> &Type {
    match t {
        Type::Array(e, _) => element(e),
        t => t,
    }
}

/// Whether a type is or contains an integer.
fn contains_int(t: &Type) -> bool {
    match t {
        Type::Struct(s) => s.members.iter().any(|m| contains_int(&m.ty)),
        Type::Array(e, _) => contains_int(e),
        t => matches!(t.scalar(), Some(Scalar::Int | Scalar::Uint)),
    }
}

/// Whether a type is or contains a sampler.
pub(super) fn contains_opaque(t: &Type) -> bool {
    match t {
        Type::Sampler(_) => true,
        Type::Struct(s) => s.members.iter().any(|m| contains_opaque(&m.ty)),
        Type::Array(e, _) => contains_opaque(e),
        _ => false,
    }
}
