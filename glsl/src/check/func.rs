//! Functions (GLSL 6.1): prototypes and definitions, overloading by parameter types
//! (a definition matches the prototype with the same parameter types and must agree
//! on the return type), `main` without parameters returning void, and parameter
//! qualifiers (`in`, `out`, `inout`, `const`). Mesa's words for each error.

use super::{Checker, Symbol};
use crate::ast;
use crate::diag::Pos;
use crate::hir::{self, ParamDir, Storage, Var, VarId};
use crate::types::Type;

impl Checker<'_> {
    /// A prototype: declares (or finds) the function; its index, or `None` after an
    /// error. `defining`: the prototype of a definition.
    pub(super) fn prototype(&mut self, p: &ast::Prototype, defining: bool) -> Option<usize> {
        let ret = self.resolve_type(&p.ret.spec, &[])?;
        if p.name.starts_with("gl_") {
            let n = &p.name;
            self.error(
                p.pos,
                format!("identifier `{n}' uses reserved `gl_' prefix"),
            );
            return None;
        }
        let mut params = Vec::new();
        for prm in &p.params {
            let q = self.quals(&prm.ty.qualifiers, prm.pos)?;
            // Mesa checks the names of a definition's parameters, not a prototype's.
            if let Some(n) = prm
                .name
                .as_ref()
                .filter(|n| defining && n.starts_with("gl_"))
            {
                self.error(
                    prm.pos,
                    format!("identifier `{n}' uses reserved `gl_' prefix"),
                );
                return None;
            }
            let ty = self.resolve_type(&prm.ty.spec, &prm.array)?;
            if ty == Type::Void {
                if prm.name.is_some() {
                    self.error(prm.pos, "named parameter cannot have type `void'");
                    return None;
                }
                continue;
            }
            let dir = match q.storage {
                Some(ast::Storage::Out) => ParamDir::Out,
                Some(ast::Storage::Inout) => ParamDir::Inout,
                _ => ParamDir::In,
            };
            let constant = q.storage == Some(ast::Storage::Const) || q.const_in;
            params.push((prm.name.clone(), ty, dir, constant, prm.pos));
        }
        if p.name == "main" {
            if !params.is_empty() {
                self.error(p.pos, "main() must not take any parameters");
                return None;
            }
            if ret != Type::Void {
                self.error(p.ret.spec.pos, "main() must return void");
                return None;
            }
        }
        // Find a previous declaration with the same parameter types.
        let existing = match self.scopes[0].get(&p.name) {
            Some(Symbol::Functions(f)) => f.clone(),
            Some(_) => {
                self.error(
                    p.pos,
                    format!("function name `{}' conflicts with non-function", p.name),
                );
                return None;
            }
            None => Vec::new(),
        };
        for f in existing {
            let same = self.functions[f].params.len() == params.len()
                && self.functions[f]
                    .params
                    .iter()
                    .zip(&params)
                    .all(|(v, p)| self.vars[*v].ty == p.1);
            if same {
                if self.functions[f].ret != ret {
                    self.error(
                        p.pos,
                        format!("function `{}' return type doesn't match prototype", p.name),
                    );
                    return None;
                }
                if defining && self.functions[f].body.is_some() {
                    self.error(p.pos, format!("function `{}' redefined", p.name));
                    return None;
                }
                if defining {
                    // The definition's parameter names and qualifiers replace the
                    // prototype's.
                    let ids = self.param_vars(&params);
                    self.functions[f].params = ids;
                }
                return Some(f);
            }
        }
        let ids = self.param_vars(&params);
        self.functions.push(hir::Function {
            name: p.name.clone(),
            ret,
            params: ids,
            body: None,
            pos: p.pos,
        });
        let id = self.functions.len() - 1;
        match self.scopes[0].get_mut(&p.name) {
            Some(Symbol::Functions(v)) => v.push(id),
            _ => {
                self.scopes[0].insert(p.name.clone(), Symbol::Functions(vec![id]));
            }
        }
        Some(id)
    }

    fn param_vars(&mut self, params: &[(Option<String>, Type, ParamDir, bool, Pos)]) -> Vec<VarId> {
        params
            .iter()
            .map(|(name, ty, dir, constant, pos)| {
                self.add_var(Var {
                    name: name.clone().unwrap_or_default(),
                    ty: ty.clone(),
                    storage: Storage::Param(*dir),
                    interp: None,
                    centroid: false,
                    invariant: false,
                    location: None,
                    value: None,
                    block: None,
                    read_only: *constant,
                    pos: *pos,
                })
            })
            .collect()
    }

    /// A function definition.
    pub(super) fn function_def(&mut self, f: &ast::FunctionDef) {
        let Some(id) = self.prototype(&f.proto, true) else {
            return;
        };
        self.current = Some(id);
        self.push_scope();
        for p in self.functions[id].params.clone() {
            let name = self.vars[p].name.clone();
            if !name.is_empty() {
                self.declare(&name, Symbol::Var(p));
            }
        }
        // The body shares the parameters' scope (redeclaring a parameter is an error).
        self.returned = false;
        let body = self.stmts(&f.body);
        self.pop_scope();
        self.current = None;
        self.functions[id].body = Some(body);
        self.defined.push(id);
        let ret = &self.functions[id].ret;
        if *ret != Type::Void && !self.returned && !self.log.has_errors() {
            let text = format!(
                "function `{}' has non-void return type {ret}, but no return statement",
                f.proto.name
            );
            self.error(f.proto.ret.spec.pos, text);
        }
    }
}
