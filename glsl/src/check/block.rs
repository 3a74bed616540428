//! Interface blocks (GLSL 1.40 4.3.5 for uniform blocks, 1.50 4.3.7 for input and
//! output blocks): the members of a block without instance name become variables of
//! the enclosing scope, an instance name becomes one variable of the block's struct
//! type. Mesa's rules and words: uniform blocks from 1.40 (or
//! ARB_uniform_buffer_object), no `in` block in vertex shaders nor `out` block in
//! fragment shaders, no opaque member in a uniform block, one block name per kind;
//! Mesa reports the last two at 0:0(0).

use super::decl::contains_opaque;
use super::{Checker, Symbol, AOA};
use crate::ast;
use crate::diag::Pos;
use crate::hir::{self, Storage, Var};
use crate::types::{Member, Struct, Type};
use std::sync::Arc;

impl Checker<'_> {
    /// An interface block: its members become globals (or members of the instance).
    pub(super) fn block(&mut self, b: &ast::Block, out: &mut Vec<hir::Stmt>) {
        let Some(q) = self.quals(&b.qualifiers, b.pos) else {
            return;
        };
        let (kind, storage) = match q.storage {
            Some(ast::Storage::Uniform) => ("uniform", Storage::Uniform),
            Some(ast::Storage::In) => ("in", Storage::In),
            Some(ast::Storage::Out) => ("out", Storage::Out),
            _ => ("uniform", Storage::Uniform),
        };
        if let Some(l) = q.layout.iter().find(|l| {
            storage != Storage::Uniform
                && ["std140", "shared", "packed", "row_major", "column_major"].contains(&l.as_str())
        }) {
            let text = format!("invalid qualifier for block '{}': {l}", b.name);
            self.error(Pos::new(0, 0), text);
            return;
        }
        if storage == Storage::Uniform {
            if !self.at_least(140) && !self.ext("GL_ARB_uniform_buffer_object") {
                self.error(b.pos, "#version 140 / GL_ARB_uniform_buffer_object required for defining uniform blocks");
                return;
            }
        } else if !self.at_least(150) {
            self.error(b.pos, "#version 150 required for using interface blocks");
            return;
        } else if storage == Storage::In && self.stage == crate::types::Stage::Vertex {
            self.error(
                b.pos,
                "`in' interface block is not allowed for a vertex shader",
            );
            return;
        } else if storage == Storage::Out && self.stage == crate::types::Stage::Fragment {
            self.error(
                b.pos,
                "`out' interface block is not allowed for a fragment shader",
            );
            return;
        }
        // Mesa reports this on the instance's line, which the syntax tree does not keep.
        if b.name.starts_with("gl_") && b.name != "gl_PerVertex" {
            let n = &b.name;
            self.error(
                b.pos,
                format!("identifier `{n}' uses reserved `gl_' prefix"),
            );
            return;
        }
        if self
            .block_names
            .iter()
            .any(|(n, k)| n == &b.name && k == kind)
        {
            self.error(
                Pos::new(0, 0),
                format!(
                    "interface block `{}' with type `{kind}' already taken in the current scope",
                    b.name
                ),
            );
            return;
        }
        self.block_names.push((b.name.clone(), kind.to_string()));
        let mut members = Vec::new();
        for m in &b.members {
            for d in &m.names {
                if d.name.starts_with("gl_") {
                    let n = &d.name;
                    self.error(
                        d.pos,
                        format!("identifier `{n}' uses reserved `gl_' prefix"),
                    );
                    return;
                }
                let Some(ty) = self.resolve_type(&m.ty.spec, &d.array) else {
                    return;
                };
                if storage == Storage::Uniform && contains_opaque(&ty) {
                    self.error(
                        m.ty.spec.pos,
                        "uniform/buffer in non-default interface block contains opaque variable",
                    );
                    return;
                }
                members.push((d.name.clone(), ty, d.pos));
            }
        }
        let read_only = storage != Storage::Out;
        let mk = |name: &str, ty: Type, pos: Pos| Var {
            name: name.to_string(),
            ty,
            storage,
            interp: None,
            centroid: false,
            invariant: false,
            location: None,
            value: None,
            block: Some(b.name.clone()),
            read_only,
            pos,
        };
        match &b.instance {
            None => {
                for (name, ty, pos) in members {
                    if self.lookup_local(&name).is_some() {
                        self.error(Pos::new(0, 0), format!("`{name}' redeclared"));
                        return;
                    }
                    let id = self.add_var(mk(&name, ty, pos));
                    self.declare(&name, Symbol::Var(id));
                    out.push(hir::Stmt::Decl(id, None));
                }
            }
            Some((inst, dims)) => {
                let st = Arc::new(Struct {
                    name: b.name.clone(),
                    members: members
                        .into_iter()
                        .map(|(name, ty, _)| Member { name, ty })
                        .collect(),
                });
                let mut ty = Type::Struct(st);
                match dims.as_slice() {
                    [] => {}
                    [None] => ty = ty.array(None),
                    [Some(e)] => match self.array_size(e) {
                        Some(n) => ty = ty.array(Some(n)),
                        None => return,
                    },
                    _ => {
                        self.error(b.pos, AOA);
                        return;
                    }
                }
                if self.lookup_local(inst).is_some() {
                    self.error(b.pos, format!("`{inst}' redeclared"));
                    return;
                }
                let id = self.add_var(mk(inst, ty, b.pos));
                self.declare(inst, Symbol::Var(id));
                out.push(hir::Stmt::Decl(id, None));
            }
        }
    }
}
