//! A fragment shader's user-defined outputs (GLSL 1.30's `out` variables) and the draw
//! buffers they go to (GL 3.0 §3.9.2, GL 3.3 `layout(location = N)`): the link gives each
//! output a location from its layout qualifier, else from glBindFragDataLocation, else
//! the lowest free one (as Mesa's linker does); an array takes one location per element.
//! Output `k` locations on is written to draw buffer `k` ([`crate::shader::lower`] reads
//! the locations from the checked tree, [`with_locations`]).

use super::{Context, GlError, GlResult};
use crate::shader::lower::MAX_DRAW_BUFFERS;
use softgl_glsl::hir::{self, Storage};
use softgl_glsl::types::Type;
use std::collections::HashMap;
use std::sync::Arc;

/// One output of a linked fragment shader.
#[derive(Clone, Debug, PartialEq)]
pub struct FragOutput {
    /// Its name.
    pub name: String,
    /// Its first location (draw buffer).
    pub location: i32,
    /// How many locations it takes (an array's length, else 1).
    pub slots: u32,
}

/// The user-defined outputs of the fragment shaders `fragment` with their locations:
/// explicit ones (a layout qualifier, else a glBindFragDataLocation `binding`) first,
/// then the others in declaration order at the lowest free run of locations. `Err` is
/// the link log when they do not fit the draw buffers or overlap.
pub fn assign(
    fragment: &[Arc<hir::Program>],
    bindings: &HashMap<String, u32>,
) -> Result<Vec<FragOutput>, String> {
    let mut outs: Vec<(FragOutput, bool)> = Vec::new();
    for p in fragment {
        for v in p.vars.iter().filter(|v| v.storage == Storage::Out) {
            if outs.iter().any(|(o, _)| o.name == v.name) {
                continue;
            }
            let slots = match &v.ty {
                Type::Array(_, Some(n)) => *n,
                _ => 1,
            };
            let explicit = v
                .location
                .or_else(|| bindings.get(&v.name).map(|&b| b as i32));
            let out = FragOutput {
                name: v.name.clone(),
                location: explicit.unwrap_or(-1),
                slots,
            };
            outs.push((out, explicit.is_some()));
        }
    }
    let mut used = [false; MAX_DRAW_BUFFERS];
    let too_many = |name: &str| {
        format!("error: insufficient contiguous locations available for fragment shader output `{name}'\n")
    };
    for (o, _) in outs.iter().filter(|(_, e)| *e) {
        let (at, n) = (o.location as usize, o.slots as usize);
        if o.location < 0 || at + n > MAX_DRAW_BUFFERS {
            return Err(too_many(&o.name));
        }
        if used[at..at + n].iter().any(|&u| u) {
            return Err(format!(
                "error: data location {at} is assigned to more than one fragment output\n"
            ));
        }
        used[at..at + n].iter_mut().for_each(|u| *u = true);
    }
    for (o, _) in outs.iter_mut().filter(|(_, e)| !*e) {
        let n = o.slots as usize;
        let Some(at) =
            (0..=MAX_DRAW_BUFFERS.saturating_sub(n)).find(|&s| used[s..s + n].iter().all(|&u| !u))
        else {
            return Err(too_many(&o.name));
        };
        used[at..at + n].iter_mut().for_each(|u| *u = true);
        o.location = at as i32;
    }
    Ok(outs.into_iter().map(|(o, _)| o).collect())
}

/// `p` with each output's location set as `outs` assigns it (what the lowering reads).
pub fn with_locations(p: &hir::Program, outs: &[FragOutput]) -> hir::Program {
    let mut p = p.clone();
    for v in p.vars.iter_mut().filter(|v| v.storage == Storage::Out) {
        if let Some(o) = outs.iter().find(|o| o.name == v.name) {
            v.location = Some(o.location);
        }
    }
    p
}

impl Context {
    /// glBindFragDataLocation: takes effect at the next link. Mesa's checks in its order:
    /// the program, then a `gl_` name (GL_INVALID_OPERATION), then a colour number past
    /// GL_MAX_DRAW_BUFFERS (GL_INVALID_VALUE).
    pub fn bind_frag_data_location(
        &mut self,
        program: u32,
        color: u32,
        name: &str,
    ) -> GlResult<()> {
        let p = self.shaders.table.program_mut(program)?;
        if name.starts_with("gl_") {
            return Err(GlError::InvalidOperation);
        }
        if color as usize >= MAX_DRAW_BUFFERS {
            return Err(GlError::InvalidValue);
        }
        p.frag_bindings.insert(name.to_string(), color);
        Ok(())
    }

    /// glGetFragDataLocation: the location of output `name` (an array by its name or an
    /// element `name[k]`), -1 for a name that is no output or starts with `gl_`;
    /// GL_INVALID_OPERATION for a program not linked.
    pub fn frag_data_location(&self, program: u32, name: &str) -> GlResult<i32> {
        let p = self.shaders.table.program(program)?;
        let l = p
            .linked
            .as_ref()
            .filter(|_| p.link_status)
            .ok_or(GlError::InvalidOperation)?;
        if name.starts_with("gl_") {
            return Ok(-1);
        }
        let (base, elem) = match name.strip_suffix(']').and_then(|n| n.split_once('[')) {
            Some((b, k)) => match k.parse::<u32>() {
                Ok(k) => (b, k),
                Err(_) => return Ok(-1),
            },
            None => (name, 0),
        };
        Ok(l.frag_outputs
            .iter()
            .find(|o| o.name == base && elem < o.slots)
            .map_or(-1, |o| o.location + elem as i32))
    }
}
