//! Compiled vertex nodes: a display list's glBegin/glEnd geometry stored once as vertex
//! arrays and replayed as indexed draws from them, as Mesa's vbo "save" module replays
//! its vertex lists, instead of re-running every glVertex through immediate mode.
//!
//! A node is compiled ([`compile`]) when it is whole primitives (glBegin … glEnd, maybe
//! wrapped in the save/restore of a compiled glDrawArrays) and every attribute it sets is
//! set before its first vertex: then each vertex's attributes are the node's stored values
//! or, for attributes the node does not set, the current values at execution time. Other
//! nodes (a primitive split over nodes, a "dangling" attribute, glIndex …) keep the
//! op-by-op replay.
//!
//! Replay ([`Context::replay_compiled`]) reproduces the immediate path's draws exactly:
//! the node's consecutive primitives of one mergeable mode are one draw (merged at compile
//! time, as the immediate path merges them at replay), the last one stays pending
//! ([`PendingNode`]) so that whatever would have merged with it still does (it is then
//! copied into the immediate batch: [`Context::materialize_pending_node`]), each draw sees
//! the current colour the immediate path would have had at that point, and afterwards the
//! current attributes are the last values the node set.

use super::dlist::VertexOp;
use super::error::GlError;
use super::immediate::Immediate;
use super::state::{CurrentAttribs, Primitive};
use super::Context;
use crate::geometry::fetch::VertexIn;
use crate::geometry::stored::{self, StoredVerts};
use std::sync::Arc;

/// One draw of a compiled node: vertices `start..start + count` as `mode`.
#[derive(Debug)]
struct Group {
    mode: Primitive,
    start: usize,
    count: usize,
    /// The current colour when the immediate path draws it (at its glEnd, or at the
    /// next glBegin when it stays pending), if the node sets the colour.
    color: [f32; 4],
}

/// A vertex node compiled into stored vertex arrays.
#[derive(Debug)]
pub struct CompiledNode {
    verts: StoredVerts,
    groups: Vec<Group>,
    /// The last values of the attributes the node sets (`verts.set()`).
    last: CurrentAttribs,
    /// The node is a compiled glDrawArrays: it leaves the current attributes unchanged.
    restore: bool,
    /// 0, 1, 2 … up to the longest group (the indices of its indexed draws).
    idx: Vec<u32>,
}

/// A compiled node's last draw, held pending as the immediate path holds a batch.
#[derive(Clone, Debug)]
pub struct PendingNode {
    node: Arc<CompiledNode>,
    group: usize,
    /// The current attributes when the node was replayed.
    base: CurrentAttribs,
}

/// The vertices of a primitive of `mode` (the incomplete trailing one is dropped).
fn per_primitive(mode: Primitive) -> usize {
    match mode {
        Primitive::Lines => 2,
        Primitive::Triangles => 3,
        Primitive::Quads => 4,
        _ => 1,
    }
}

/// Compiles `ops` (one vertex node) if it has the shape the module doc describes.
pub fn compile(ops: &[VertexOp]) -> Option<CompiledNode> {
    let (body, restore) = match ops {
        [VertexOp::SaveCurrent, body @ .., VertexOp::RestoreCurrent] => (body, true),
        _ => (ops, false),
    };
    // The attributes set, each before the first vertex; whole primitives only.
    let (mut set, mut seen_vertex, mut open, mut any) = (0, false, false, false);
    let mut nverts = 0;
    for op in body {
        match op {
            VertexOp::Begin(_) if !open => (open, any) = (true, true),
            VertexOp::End if open => open = false,
            VertexOp::Vertex(_) if open => (seen_vertex, nverts) = (true, nverts + 1),
            VertexOp::Color(_)
            | VertexOp::SecondaryColor(_)
            | VertexOp::Normal(_)
            | VertexOp::TexCoord(..)
            | VertexOp::FogCoord(_)
            | VertexOp::EdgeFlag(_) => {
                let bit = op.attr_bit();
                if set & bit == 0 && seen_vertex {
                    return None;
                }
                set |= bit;
            }
            _ => return None,
        }
    }
    if open || !any {
        return None;
    }
    // Without the memory the node stays uncompiled (replayed op by op).
    let mut verts = StoredVerts::with_capacity(set, nverts)?;
    let mut last = CurrentAttribs::default();
    let mut groups: Vec<Group> = Vec::new();
    let mut begun = (Primitive::Points, 0);
    for &op in body {
        match op {
            VertexOp::Begin(m) => begun = (m, verts.len()),
            VertexOp::Vertex(p) => verts.push(&VertexIn::with_current(p, &last)),
            VertexOp::End => {
                let (mode, start) = begun;
                let n = verts.len() - start;
                verts.truncate(start + n - n % per_primitive(mode));
                let count = verts.len() - start;
                match groups.last_mut() {
                    // The next glBegin of a mergeable mode extends the pending batch.
                    Some(g) if g.mode == mode && Immediate::mergeable(mode) => {
                        g.count += count;
                        g.color = last.color;
                    }
                    _ => groups.push(Group {
                        mode,
                        start,
                        count,
                        color: last.color,
                    }),
                }
            }
            VertexOp::Color(v) => last.color = v,
            VertexOp::SecondaryColor(v) => last.secondary_color = [v[0], v[1], v[2], 1.0],
            VertexOp::Normal(v) => last.normal = v,
            VertexOp::TexCoord(u, v) => last.texcoord[u as usize % last.texcoord.len()] = v,
            VertexOp::FogCoord(f) => last.fog_coord = f,
            VertexOp::EdgeFlag(f) => last.edge_flag = f,
            _ => {}
        }
    }
    verts.finish();
    let longest = groups.iter().map(|g| g.count).max().unwrap_or(0);
    let mut idx = Vec::new();
    idx.try_reserve_exact(longest).ok()?;
    idx.extend(0..longest as u32);
    Some(CompiledNode {
        verts,
        groups,
        last,
        restore,
        idx,
    })
}

impl CompiledNode {
    /// Writes the attributes the node sets, as it leaves them, into `cur`.
    fn apply_last(&self, cur: &mut CurrentAttribs) {
        let (s, l) = (self.verts.set(), &self.last);
        if s & stored::COLOR != 0 {
            cur.color = l.color;
        }
        if s & stored::SECONDARY != 0 {
            cur.secondary_color = l.secondary_color;
        }
        if s & stored::NORMAL != 0 {
            cur.normal = l.normal;
        }
        if s & stored::FOG != 0 {
            cur.fog_coord = l.fog_coord;
        }
        if s & stored::EDGE != 0 {
            cur.edge_flag = l.edge_flag;
        }
        for (u, t) in cur.texcoord.iter_mut().enumerate() {
            if s & (stored::TEX0 << u) != 0 {
                *t = l.texcoord[u];
            }
        }
    }
}

impl Context {
    /// Replays a compiled node (outside glBegin/glEnd): the same draws, at the same
    /// points, as replaying its commands one by one.
    pub(super) fn replay_compiled(&mut self, node: &Arc<CompiledNode>) {
        let start = self.state.current;
        let sets_color = node.verts.set() & stored::COLOR != 0;
        for (gi, g) in node.groups.iter().enumerate() {
            // glBegin: extend a pending batch of this mode, or draw it.
            let im = &self.immediate;
            if im.pending == Some(g.mode) && im.indexed {
                self.materialize_pending_node();
                let pend = PendingNode {
                    node: Arc::clone(node),
                    group: gi,
                    base: start,
                };
                self.push_node_vertices(&pend);
            } else {
                self.flush_pending_keep();
                self.immediate.pending_node = Some(PendingNode {
                    node: Arc::clone(node),
                    group: gi,
                    base: start,
                });
            }
            // glEnd.
            self.immediate.pending = Some(g.mode);
            self.immediate.indexed = true;
            if sets_color {
                self.state.current.color = g.color;
            }
            if !Immediate::mergeable(g.mode) {
                self.flush_pending_keep();
            }
        }
        if node.restore {
            self.state.current = start;
        } else {
            node.apply_last(&mut self.state.current);
        }
    }

    /// Draws the pending compiled draw, if there is one (from `flush_pending`), leaving
    /// its last batch on the pool with `keep`: returns whether there was.
    pub(super) fn draw_pending_node(&mut self, mode: Primitive, keep: bool) -> bool {
        let Some(p) = self.immediate.pending_node.take() else {
            return false;
        };
        let g = &p.node.groups[p.group];
        let src = p.node.verts.source(g.start, g.count, &p.base);
        let idx = Some(&p.node.idx[..g.count]);
        super::draw::draw_batch(self, mode, &src, idx, None, keep);
        true
    }

    /// Turns the pending compiled draw, if any, into the immediate batch's vertices, for
    /// a glBegin that extends it.
    pub(super) fn materialize_pending_node(&mut self) {
        if let Some(p) = self.immediate.pending_node.take() {
            self.push_node_vertices(&p);
        }
    }

    /// Appends a compiled draw's vertices to the immediate batch, each with the current
    /// attributes it was given with.
    fn push_node_vertices(&mut self, p: &PendingNode) {
        let g = &p.node.groups[p.group];
        let saved = self.state.current;
        self.state.current = p.base;
        for k in g.start..g.start + g.count {
            p.node.verts.write_current(k, &mut self.state.current);
            if self
                .push_immediate_vertex(p.node.verts.position(k))
                .is_err()
            {
                self.record_error(GlError::OutOfMemory);
                break;
            }
        }
        self.state.current = saved;
    }
}

#[cfg(test)]
mod tests {
    use super::super::dlist::Cmd;
    use super::super::state::Cap;
    use super::*;
    use crate::context::Visual;
    use crate::framebuffer::{ColorFormat, DepthFormat};

    /// A triangle's vertices at `(x, y)` (in a 16x16 viewport's object space).
    fn tri(x: f32, y: f32) -> [VertexOp; 3] {
        [[x, y], [x + 0.5, y], [x, y + 0.5]].map(|[a, b]| VertexOp::Vertex([a, b, 0.0, 1.0]))
    }

    /// Records the lists the test draws; with `compiled` false, drops the compiled form
    /// of every node so that it replays op by op.
    fn record(c: &mut Context, compiled: bool) -> usize {
        use VertexOp::*;
        let red = Color([1.0, 0.0, 0.0, 1.0]);
        let blue = Color([0.0, 0.0, 1.0, 0.5]);
        // Compiled: merged triangles, a colour after the last vertex, an incomplete
        // triangle and line dropped at glEnd, a fan, quads left pending.
        let mut ops = vec![Begin(Primitive::Triangles), red];
        ops.extend(tri(-1.0, -1.0));
        ops.extend([End, Begin(Primitive::Triangles)]);
        ops.extend(tri(-0.5, -1.0));
        ops.extend([Vertex([0.0; 4]), blue, End, Begin(Primitive::Lines)]);
        ops.extend(tri(0.0, -1.0));
        ops.extend([End, Begin(Primitive::TriangleFan)]);
        ops.extend(tri(0.5, -1.0));
        ops.extend([Vertex([0.9, 0.0, 0.0, 1.0]), End, Begin(Primitive::Quads)]);
        ops.extend(tri(-1.0, 0.0));
        ops.extend([Vertex([-0.5, 0.5, 0.0, 1.0]), End]);
        // Not compiled: a colour outside glBegin/glEnd (a node of its own).
        ops.push(Color([0.0, 1.0, 0.0, 1.0]));
        // Compiled: quads that extend the pending ones, then triangles left pending.
        ops.extend([Begin(Primitive::Quads), Normal([0.0, 1.0, 0.0])]);
        ops.extend([TexCoord(1, [0.5; 4]), EdgeFlag(false), FogCoord(0.25)]);
        ops.extend(tri(0.0, 0.0));
        ops.extend([
            Vertex([0.5, 0.5, 0.0, 1.0]),
            End,
            Begin(Primitive::Triangles),
        ]);
        ops.extend(tri(0.2, 0.2));
        ops.push(End);
        // Not compiled: a colour after vertices (the list set it before, so it is not
        // dangling): op by op, extending the pending compiled triangles.
        ops.extend([Normal([0.0, 0.0, 1.0]), Begin(Primitive::Triangles)]);
        ops.extend(tri(0.4, 0.4));
        ops.push(blue);
        ops.extend(tri(-0.4, 0.4));
        ops.push(End);
        // Compiled: a compiled glDrawArrays (a node of its own after an attribute),
        // which restores the current attributes.
        ops.extend([FogCoord(0.5), SaveCurrent, Begin(Primitive::Points), red]);
        ops.extend([Vertex([0.7, 0.7, 0.0, 1.0]), End, RestoreCurrent]);
        c.new_list(1, false).unwrap();
        for &op in &ops {
            c.lists.push_op(op);
        }
        c.lists.push_call(Box::new(|c| {
            c.state.current.color[1] = 0.75;
            Ok(())
        }));
        // Compiled: triangles left pending at the end of the list.
        for op in [Begin(Primitive::Triangles), red] {
            c.lists.push_op(op);
        }
        for op in tri(0.1, -0.2).into_iter().chain([End]) {
            c.lists.push_op(op);
        }
        c.end_list().unwrap();
        // A list calling list 1 twice: its last draw merges with the next call's first.
        c.new_list(2, false).unwrap();
        c.lists.push_call(Box::new(|c| {
            c.call_list(1);
            Ok(())
        }));
        c.lists.push_call(Box::new(|c| {
            c.call_list(1);
            Ok(())
        }));
        c.end_list().unwrap();
        let mut n = 0;
        let list = c.lists.lists.get_mut(&1).unwrap();
        for cmd in &mut Arc::get_mut(list).unwrap().cmds {
            if let Cmd::Node { compiled: k, .. } = cmd {
                n += k.is_some() as usize;
                if !compiled {
                    *k = None;
                }
            }
        }
        n
    }

    /// Draws list 2 (so list 1 twice), then list 1 with lighting and colour material,
    /// and returns what the test compares.
    fn run(compiled: bool) -> (Vec<[u8; 4]>, String, usize) {
        let mut c = Context::new(Visual {
            format: ColorFormat::Rgba,
            depth: DepthFormat::None,
            stencil: false,
            accum_bits: 0,
        });
        c.bind_framebuffer(16, 16, false);
        let n = record(&mut c, compiled);
        c.state.current.color = [0.5, 0.5, 0.5, 1.0];
        c.call_list(2);
        let mid = format!("{:?}", c.state.current);
        c.set_cap(Cap::Lighting, true).unwrap();
        c.set_cap(Cap::ColorMaterial, true).unwrap();
        c.state.current.normal = [0.0, 0.0, -1.0];
        c.call_list(1);
        c.flush_pending();
        c.settle_draws();
        let state = format!("{mid} {:?} {:?}", c.state.current, c.light.material);
        (c.fb.as_ref().unwrap().color.to_vec(), state, n)
    }

    #[test]
    fn compiled_replay_draws_and_leaves_what_op_by_op_replay_does() {
        let (px, state, n) = run(true);
        let (px_ops, state_ops, _) = run(false);
        assert_eq!(n, 4, "the nodes that should compile");
        assert!(px.iter().any(|p| p[0] != 0));
        assert_eq!(state, state_ops);
        assert_eq!(px, px_ops);
    }
}
