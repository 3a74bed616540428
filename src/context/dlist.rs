//! Display lists (GL 1.5 §5.4): named sequences of recorded commands.
//!
//! A list holds two kinds of entries. A [`Cmd::Call`] is a boxed closure made at the C
//! boundary from an ordinary state call (glEnable, glRotatef …); it captures only the owned,
//! already-read argument values, so running it later is running the call later. A
//! [`Cmd::Node`] is a run of per-vertex commands ([`VertexOp`]: glBegin, glVertex, glColor
//! …) stored inline without boxing, the way Mesa's vbo "save" module compiles begin/end
//! geometry into a vertex node. Its primitives are drawn as *indexed* draws, as Mesa draws
//! vertex nodes, which decides the GL_QUADS split (docs/llvmpipe-rules.md §5).
//!
//! When a node closes it is also compiled, when it can be, into stored vertex arrays
//! ([`super::dlist_node`]: positions and only the attributes the node sets, an attribute
//! every vertex shares kept once): replaying it is then one indexed draw per run of
//! primitives straight from those arrays (through
//! [`crate::geometry::stored::StoredSource`], the draw path of glDrawElements), with the
//! attributes the node does not set taken from the current values at execution time, and
//! afterwards the current attributes are the last values the node set. MuJoCo replays
//! ~1.1M list vertices per frame; copying each into the immediate batch was ~12% of its
//! draw thread. Nodes that do not fit (a primitive split over nodes, an attribute first
//! set after the node's first vertex, glIndex, a compiled glDrawArrays following other
//! geometry in the node) and replays inside an open glBegin keep the op-by-op path: the
//! same immediate-mode code as glBegin/glEnd ([`Context::vertex_op`]). Like Mesa, a node
//! whose vertices would reference an attribute that first appears after them ("dangling"
//! attribute) is replayed through the plain immediate path ("loopback").
//!
//! Commands that GL executes immediately (glGen*, glGet*, client array state, glFlush …)
//! simply never reach a list. Lists are reference counted, so redefining or deleting a list
//! while it executes (glNewList(n, GL_COMPILE_AND_EXECUTE) calling list n) is safe: the
//! running copy lives until it returns.

use super::dlist_node::CompiledNode;
use super::error::{GlError, GlResult};
use super::state::{CurrentAttribs, Primitive, MAX_TEXTURE_UNITS};
use super::Context;
use std::collections::HashMap;
use std::sync::Arc;

/// GL_MAX_LIST_NESTING (Mesa's value): deeper glCallList calls are ignored.
pub const MAX_LIST_NESTING: usize = 64;

/// A recorded state command: runs the call on the context at execution time.
pub type ListFn = Box<dyn Fn(&mut Context) -> GlResult<()> + Send + Sync>;

/// One per-vertex command, recorded inline in a vertex node.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum VertexOp {
    /// glBegin.
    Begin(Primitive),
    /// glEnd.
    End,
    /// glVertex: emits a vertex with the current attributes.
    Vertex([f32; 4]),
    /// glColor.
    Color([f32; 4]),
    /// glSecondaryColor.
    SecondaryColor([f32; 3]),
    /// glNormal.
    Normal([f32; 3]),
    /// glTexCoord / glMultiTexCoord: unit and coordinates.
    TexCoord(u8, [f32; 4]),
    /// glFogCoord.
    FogCoord(f32),
    /// glEdgeFlag.
    EdgeFlag(bool),
    /// glIndex (the current colour index).
    Index(f32),
    /// Saves the current attributes (a compiled glDrawArrays does not change them).
    SaveCurrent,
    /// Restores the attributes saved by [`VertexOp::SaveCurrent`].
    RestoreCurrent,
}

impl VertexOp {
    /// The attribute bit this op sets (for the dangling-attribute rule), 0 for others:
    /// the bits of [`crate::geometry::stored`], and one more for glIndex.
    pub(super) fn attr_bit(&self) -> u32 {
        use crate::geometry::stored::{COLOR, EDGE, FOG, NORMAL, SECONDARY, TEX0};
        match self {
            VertexOp::Color(_) => COLOR,
            VertexOp::SecondaryColor(_) => SECONDARY,
            VertexOp::Normal(_) => NORMAL,
            VertexOp::FogCoord(_) => FOG,
            VertexOp::TexCoord(u, _) => TEX0 << u,
            VertexOp::EdgeFlag(_) => EDGE,
            VertexOp::Index(_) => EDGE << 1,
            _ => 0,
        }
    }
}

/// One entry of a display list.
pub enum Cmd {
    /// A state command, and whether it leaves a draw on the pool drawing (the calls
    /// `ffi::with_ctx_list_keep` makes; the others wait for it first).
    Call(ListFn, bool),
    /// A run of per-vertex commands.
    Node {
        /// The commands.
        ops: Vec<VertexOp>,
        /// Replay through the non-indexed immediate path (Mesa's loopback).
        loopback: bool,
        /// The commands compiled into vertex arrays, when they can be
        /// ([`super::dlist_node`]).
        compiled: Option<Arc<CompiledNode>>,
    },
}

/// A compiled display list.
#[derive(Default)]
pub struct DisplayList {
    /// Its entries in order.
    pub cmds: Vec<Cmd>,
}

/// The list being compiled (between glNewList and glEndList).
pub struct Compiling {
    /// Its name.
    pub name: u32,
    /// GL_COMPILE_AND_EXECUTE.
    pub execute: bool,
    /// Entries so far.
    cmds: Vec<Cmd>,
    /// The open vertex node.
    ops: Vec<VertexOp>,
    /// Whether the open node must be replayed by loopback.
    loopback: bool,
    /// Vertices in the open node.
    node_verts: usize,
    /// Attributes set so far in this list (bits of [`VertexOp::attr_bit`]).
    list_attrs: u32,
    /// Whether a glBegin is open at this point of the list.
    in_begin: bool,
}

impl Compiling {
    /// Closes the open vertex node, if any.
    fn close_node(&mut self) {
        if !self.ops.is_empty() {
            let ops = std::mem::take(&mut self.ops);
            let compiled = (!self.loopback)
                .then(|| super::dlist_node::compile(&ops).map(Arc::new))
                .flatten();
            self.cmds.push(Cmd::Node {
                ops,
                loopback: self.loopback,
                compiled,
            });
        }
        self.loopback = false;
        self.node_verts = 0;
    }
}

/// Display-list state of a context.
#[derive(Default)]
pub struct ListState {
    /// Defined lists by name.
    pub lists: HashMap<u32, Arc<DisplayList>>,
    /// Names glGenLists reserved that glNewList has not defined yet, as inclusive ranges
    /// (glIsList answers true for them, as in Mesa, which stores empty lists).
    reserved: Vec<(u32, u32)>,
    /// The list being compiled.
    pub compiling: Option<Compiling>,
    /// glListBase.
    pub base: u32,
    /// Current glCallList nesting depth.
    pub depth: usize,
    /// Attributes saved by [`VertexOp::SaveCurrent`].
    saved_current: Option<CurrentAttribs>,
    /// The largest name ever used: glGenLists continues after it, as Mesa's name table
    /// does (`_mesa_HashFindFreeKeyBlock`), before it searches for a gap.
    max_key: u32,
}

/// The part of [`ListState`] a share group shares: the lists and their names.
#[derive(Default)]
pub struct ListTable {
    lists: HashMap<u32, Arc<DisplayList>>,
    reserved: Vec<(u32, u32)>,
    max_key: u32,
}

impl ListState {
    /// Takes the list names and lists out (for the share group), leaving none.
    pub fn take_table(&mut self) -> ListTable {
        ListTable {
            lists: std::mem::take(&mut self.lists),
            reserved: std::mem::take(&mut self.reserved),
            max_key: std::mem::replace(&mut self.max_key, 0),
        }
    }

    /// Puts a share group's list names and lists in.
    pub fn put_table(&mut self, t: ListTable) {
        self.lists = t.lists;
        self.reserved = t.reserved;
        self.max_key = t.max_key;
    }

    /// `Some(execute)` while a list is being compiled.
    #[inline]
    pub fn compile_mode(&self) -> Option<bool> {
        self.compiling.as_ref().map(|k| k.execute)
    }

    /// Whether the list being compiled is between a glBegin and its glEnd.
    #[inline]
    pub fn compiling_inside_begin(&self) -> bool {
        self.compiling.as_ref().is_some_and(|k| k.in_begin)
    }

    /// Appends a state command to the list being compiled.
    pub fn push_call(&mut self, f: ListFn) {
        self.push_call_as(f, false)
    }

    /// [`ListState::push_call`] for a call that leaves a draw on the pool drawing when the
    /// list runs (`keep`, as `ffi::with_ctx_list_keep`).
    pub fn push_call_as(&mut self, f: ListFn, keep: bool) {
        if let Some(k) = self.compiling.as_mut() {
            // A call inside glBegin/glEnd (glEvalCoord, glMaterial …) splits the primitive
            // over nodes: Mesa then replays the rest of it by loopback.
            let split = k.in_begin;
            k.close_node();
            k.loopback = split;
            k.cmds.push(Cmd::Call(f, keep));
        }
    }

    /// Appends a per-vertex command to the list being compiled. An attribute given outside
    /// glBegin/glEnd is a node of its own (Mesa compiles it as a separate opcode).
    pub fn push_op(&mut self, op: VertexOp) {
        let Some(k) = self.compiling.as_mut() else {
            return;
        };
        let bit = op.attr_bit();
        if bit != 0 && !k.in_begin {
            k.close_node();
        }
        if bit != 0 && k.list_attrs & bit == 0 && k.node_verts > 0 {
            k.loopback = true;
        }
        k.list_attrs |= bit;
        match op {
            VertexOp::Vertex(_) => k.node_verts += 1,
            VertexOp::Begin(_) => k.in_begin = true,
            VertexOp::End => k.in_begin = false,
            _ => {}
        }
        k.ops.push(op);
        if bit != 0 && !k.in_begin {
            k.close_node();
        }
    }
}

impl Context {
    /// Runs one per-vertex command with immediate-mode semantics (glBegin … glEnd).
    ///
    /// The attribute setters and glVertex, which a list replays once per vertex, are
    /// handled here (inlined into the replay loop); glBegin, glEnd and the rest go through
    /// [`Context::vertex_op_rare`].
    #[inline]
    pub fn vertex_op(&mut self, op: VertexOp) -> GlResult<()> {
        let cur = &mut self.state.current;
        match op {
            VertexOp::Vertex(p) => {
                if self.immediate.active.is_some() {
                    self.push_immediate_vertex(p)?;
                    self.stream_immediate();
                }
            }
            VertexOp::Color(v) => cur.color = v,
            VertexOp::Normal(v) => cur.normal = v,
            VertexOp::TexCoord(u, v) => cur.texcoord[(u as usize) % MAX_TEXTURE_UNITS] = v,
            _ => return self.vertex_op_rare(op),
        }
        Ok(())
    }

    /// [`Context::vertex_op`] of the commands that come once per primitive or less.
    #[inline(never)]
    fn vertex_op_rare(&mut self, op: VertexOp) -> GlResult<()> {
        let cur = &mut self.state.current;
        match op {
            VertexOp::Begin(m) => {
                self.check_outside_begin()?;
                self.check_program_samplers()?;
                let im = &self.immediate;
                if im.pending != Some(m) || im.indexed != im.replaying {
                    self.flush_pending_keep();
                } else {
                    self.materialize_pending_node();
                }
                self.immediate.pending = None;
                self.immediate.active = Some(m);
            }
            VertexOp::End => {
                let Some(mode) = self.immediate.active.take() else {
                    return Err(GlError::InvalidOperation);
                };
                // Drop an incomplete trailing primitive so a merged batch stays aligned.
                let per = match mode {
                    Primitive::Lines => 2,
                    Primitive::Triangles => 3,
                    Primitive::Quads => 4,
                    _ => 1,
                };
                let im = &mut self.immediate;
                let whole = im.verts.len() - im.verts.len() % per;
                im.verts.truncate(whole);
                im.materials.truncate(whole);
                im.pending = Some(mode);
                im.indexed = im.replaying;
                if !super::immediate::Immediate::mergeable(mode) {
                    self.flush_pending_keep();
                }
            }
            // the per-vertex commands (handled by `vertex_op`; kept so the match is whole)
            VertexOp::Vertex(_)
            | VertexOp::Color(_)
            | VertexOp::Normal(_)
            | VertexOp::TexCoord(..) => return self.vertex_op(op),
            VertexOp::SecondaryColor(v) => cur.secondary_color = [v[0], v[1], v[2], 1.0],
            VertexOp::FogCoord(f) => cur.fog_coord = f,
            VertexOp::EdgeFlag(f) => cur.edge_flag = f,
            VertexOp::Index(i) => cur.index = i,
            VertexOp::SaveCurrent => self.lists.saved_current = Some(*cur),
            VertexOp::RestoreCurrent => {
                if let Some(s) = self.lists.saved_current.take() {
                    *cur = s;
                }
            }
        }
        Ok(())
    }

    /// glNewList.
    pub fn new_list(&mut self, name: u32, execute: bool) -> GlResult<()> {
        if name == 0 {
            return Err(GlError::InvalidValue);
        }
        if self.lists.compiling.is_some() {
            return Err(GlError::InvalidOperation);
        }
        self.lists.compiling = Some(Compiling {
            name,
            execute,
            cmds: Vec::new(),
            ops: Vec::new(),
            loopback: false,
            node_verts: 0,
            list_attrs: 0,
            in_begin: false,
        });
        Ok(())
    }

    /// glEndList: the new definition replaces the old one now.
    pub fn end_list(&mut self) -> GlResult<()> {
        let Some(mut k) = self.lists.compiling.take() else {
            return Err(GlError::InvalidOperation);
        };
        // Inside the list's own glBegin under GL_COMPILE_AND_EXECUTE, Mesa still ends the
        // list but raises GL_INVALID_OPERATION (piglit's beginend-coverage checks it).
        let inside = k.execute && k.in_begin;
        k.close_node();
        let list = Arc::new(DisplayList { cmds: k.cmds });
        self.lists.lists.insert(k.name, list);
        self.lists.max_key = self.lists.max_key.max(k.name);
        if inside {
            return Err(GlError::InvalidOperation);
        }
        Ok(())
    }

    /// glCallList (also each name of glCallLists): runs the list's commands; errors of
    /// recorded commands are recorded as they run. Undefined names and calls nested deeper
    /// than [`MAX_LIST_NESTING`] do nothing.
    pub fn call_list(&mut self, name: u32) {
        if self.lists.depth >= MAX_LIST_NESTING {
            return;
        }
        let Some(list) = self.lists.lists.get(&name).cloned() else {
            return;
        };
        self.lists.depth += 1;
        let was = self.immediate.replaying;
        for cmd in &list.cmds {
            let r = match cmd {
                Cmd::Call(f, keep) => {
                    if *keep {
                        self.flush_pending_keep();
                    } else {
                        self.flush_pending();
                    }
                    f(self)
                }
                Cmd::Node { ops, .. } if self.outside_begin_end().is_err() && begins(ops) => {
                    // A compiled draw or glBegin inside glBegin/glEnd: Mesa skips the node.
                    Err(GlError::InvalidOperation)
                }
                Cmd::Node {
                    compiled: Some(node),
                    ..
                } if self.immediate.active.is_none() => {
                    self.replay_compiled(node);
                    Ok(())
                }
                Cmd::Node { ops, loopback, .. } => {
                    self.immediate.replaying = !loopback;
                    for &op in ops {
                        if let Err(e) = self.vertex_op(op) {
                            self.record_error(e);
                        }
                    }
                    self.immediate.replaying = was;
                    Ok(())
                }
            };
            if let Err(e) = r {
                self.record_error(e);
            }
        }
        self.lists.depth -= 1;
    }

    /// glGenLists: `n` consecutive unused names (0 when there is no such range or n = 0).
    pub fn gen_lists(&mut self, n: i32) -> GlResult<u32> {
        if n < 0 {
            return Err(GlError::InvalidValue);
        }
        if n == 0 {
            return Ok(0);
        }
        let last_of = |base: u32| base.checked_add(n as u32 - 1);
        let base = match last_of(self.lists.max_key.saturating_add(1)) {
            Some(_) if self.lists.max_key < u32::MAX => self.lists.max_key + 1,
            _ => {
                // Search the gaps between used names from 1 up.
                let mut used: Vec<(u32, u32)> = self.lists.reserved.clone();
                used.extend(self.lists.lists.keys().map(|&k| (k, k)));
                used.sort_unstable();
                let mut base = 1u32;
                for (lo, hi) in used {
                    match last_of(base) {
                        Some(last) if last < lo => break,
                        None => return Ok(0),
                        _ if hi == u32::MAX => return Ok(0),
                        _ => base = base.max(hi + 1),
                    }
                }
                match last_of(base) {
                    Some(_) if base != 0 => base,
                    _ => return Ok(0),
                }
            }
        };
        let last = base + (n as u32 - 1);
        self.lists.reserved.push((base, last));
        self.lists.max_key = self.lists.max_key.max(last);
        Ok(base)
    }

    /// glDeleteLists.
    pub fn delete_lists(&mut self, list: u32, range: i32) -> GlResult<()> {
        if range < 0 {
            return Err(GlError::InvalidValue);
        }
        if range == 0 {
            return Ok(());
        }
        let last = list.saturating_add(range as u32 - 1);
        self.lists.lists.retain(|&k, _| k < list || k > last);
        let mut kept = Vec::with_capacity(self.lists.reserved.len() + 1);
        for &(lo, hi) in &self.lists.reserved {
            if hi < list || lo > last {
                kept.push((lo, hi));
                continue;
            }
            if lo < list {
                kept.push((lo, list - 1));
            }
            if hi > last {
                kept.push((last + 1, hi));
            }
        }
        self.lists.reserved = kept;
        Ok(())
    }

    /// glIsList.
    pub fn is_list(&self, list: u32) -> bool {
        self.lists.lists.contains_key(&list)
            || self
                .lists
                .reserved
                .iter()
                .any(|&(lo, hi)| (lo..=hi).contains(&list))
    }
}

impl Context {
    /// The per-vertex commands glArrayElement(`i`) stands for: the enabled arrays' values
    /// of element `i` (colour, normal, texture coordinates), then the vertex.
    pub fn array_element_ops(&self, i: u32, out: &mut Vec<VertexOp>) {
        use crate::geometry::fetch::fetch_attr;
        let a = &self.arrays;
        let fill = [0.0, 0.0, 0.0, 1.0];
        // SAFETY: the program promised that enabled client arrays cover element `i`;
        // buffer-object arrays are bounds-checked.
        unsafe {
            if a.vao.color.enabled {
                if let Some(v) = fetch_attr(a.input(&a.vao.color), i, true, fill) {
                    out.push(VertexOp::Color(v));
                }
            }
            if a.vao.normal.enabled {
                if let Some(n) = fetch_attr(a.input(&a.vao.normal), i, true, [0.0; 4]) {
                    out.push(VertexOp::Normal([n[0], n[1], n[2]]));
                }
            }
            for (u, arr) in a.vao.texcoord.iter().enumerate() {
                if arr.enabled {
                    if let Some(t) = fetch_attr(a.input(arr), i, false, fill) {
                        out.push(VertexOp::TexCoord(u as u8, t));
                    }
                }
            }
            if a.vao.edge_flag.enabled {
                if let Some(e) = fetch_attr(a.input(&a.vao.edge_flag), i, false, fill) {
                    out.push(VertexOp::EdgeFlag(e[0] != 0.0));
                }
            }
            if a.vao.secondary_color.enabled {
                if let Some(s) = fetch_attr(a.input(&a.vao.secondary_color), i, true, fill) {
                    out.push(VertexOp::SecondaryColor([s[0], s[1], s[2]]));
                }
            }
            if a.vao.fog_coord.enabled {
                if let Some(f) = fetch_attr(a.input(&a.vao.fog_coord), i, false, fill) {
                    out.push(VertexOp::FogCoord(f[0]));
                }
            }
            if a.position().enabled {
                let pos = a.position();
                if let Some(p) = fetch_attr(a.input(pos), i, pos.normalized, fill) {
                    out.push(VertexOp::Vertex(p));
                }
            }
        }
    }

    /// Compiles glDrawArrays/glDrawElements into the list being compiled, as Mesa does:
    /// the arrays are read now and become a glBegin/glEnd whose attributes leave the
    /// current values unchanged. A call that fails validation is compiled as its error.
    pub fn compile_draw(&mut self, mode: GlResult<Primitive>, elements: GlResult<Elements>) {
        let fail = |c: &mut Context, e: GlError| c.lists.push_call(Box::new(move |_| Err(e)));
        let (mode, elements) = match mode.and_then(|m| Ok((m, elements?))) {
            Ok(v) => v,
            Err(e) => return fail(self, e),
        };
        if !self.arrays.position().enabled {
            // No vertices, but still a primitive (it matters inside glBegin/glEnd).
            self.lists.push_op(VertexOp::Begin(mode));
            self.lists.push_op(VertexOp::End);
            return;
        }
        let n = match &elements {
            Elements::Range(_, count) => *count,
            Elements::List(v) => v.len(),
        };
        // At most one op per array and the vertex per element.
        let per = 6 + MAX_TEXTURE_UNITS;
        let mut ops = Vec::new();
        if n.checked_mul(per)
            .and_then(|k| ops.try_reserve(k + 4).ok())
            .is_none()
        {
            return fail(self, GlError::OutOfMemory);
        }
        ops.extend([VertexOp::SaveCurrent, VertexOp::Begin(mode)]);
        match elements {
            Elements::Range(first, count) => {
                for i in (0..count as u32).map_while(|i| first.checked_add(i)) {
                    self.array_element_ops(i, &mut ops);
                }
            }
            Elements::List(v) => {
                for i in v {
                    self.array_element_ops(i, &mut ops);
                }
            }
        }
        ops.extend([VertexOp::End, VertexOp::RestoreCurrent]);
        for op in ops {
            self.lists.push_op(op);
        }
    }
}

/// Whether a vertex node starts a primitive (its first glBegin/glEnd is a glBegin), as
/// Mesa's `draw_begins`.
fn begins(ops: &[VertexOp]) -> bool {
    ops.iter()
        .find(|op| matches!(op, VertexOp::Begin(_) | VertexOp::End))
        .is_some_and(|op| matches!(op, VertexOp::Begin(_)))
}

/// The elements a compiled draw call reads.
pub enum Elements {
    /// glDrawArrays: first and count.
    Range(u32, usize),
    /// glDrawElements: the indices.
    List(Vec<u32>),
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::Visual;
    use crate::framebuffer::{ColorFormat, DepthFormat};

    fn ctx() -> Context {
        Context::new(Visual {
            format: ColorFormat::Rgba,
            depth: DepthFormat::None,
            stencil: false,
            accum_bits: 0,
        })
    }

    #[test]
    fn gen_lists_reserves_ranges_without_storing_each_name() {
        let mut c = ctx();
        assert_eq!(c.gen_lists(i32::MAX), Ok(1));
        assert!(c.is_list(1) && c.is_list(i32::MAX as u32) && !c.is_list(i32::MAX as u32 + 1));
        c.delete_lists(10, 5).unwrap();
        assert!(c.is_list(9) && !c.is_list(10) && !c.is_list(14) && c.is_list(15));
        // Past the largest name used while it fits, then the first gap that fits.
        assert_eq!(c.gen_lists(3), Ok(i32::MAX as u32 + 1));
        assert_eq!(c.gen_lists(i32::MAX), Ok(0));
        assert_eq!(c.gen_lists(1), Ok(i32::MAX as u32 + 4));
        c.new_list(u32::MAX, false).unwrap();
        c.end_list().unwrap();
        assert_eq!(c.gen_lists(5), Ok(10));
        assert_eq!(c.gen_lists(-1), Err(GlError::InvalidValue));
    }

    #[test]
    fn nesting_stops_at_the_limit() {
        let mut c = ctx();
        c.new_list(1, false).unwrap();
        c.lists.push_call(Box::new(|c| {
            c.state.clear_stencil += 1;
            c.call_list(1);
            Ok(())
        }));
        c.end_list().unwrap();
        c.call_list(1);
        assert_eq!(c.state.clear_stencil, MAX_LIST_NESTING as i32);
        assert_eq!(c.lists.depth, 0);
    }
}
