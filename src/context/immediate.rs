//! glBegin/glEnd: the vertices of the primitive being specified, stored compactly
//! ([`ImmVerts`]), a finished batch kept pending so that the next glBegin of the same mode
//! can extend it (as Mesa's vbo module merges draws), and a long GL_TRIANGLES batch drawn
//! in chunks while it is specified ([`Context::stream_immediate`]).

use super::arrays::MAX_VERTEX_ATTRIBS;
use super::error::{GlError, GlResult};
use super::state::{CurrentAttribs, Primitive, MAX_TEXTURE_UNITS};
use super::Context;
use crate::geometry::fetch::VertexIn;
use crate::geometry::source::{VertexSlot, VertexSource};

/// The fewest vertices a glBegin(GL_TRIANGLES) batch holds before
/// [`Context::stream_immediate`] may draw it ahead of glEnd: 4096 triangles, 432 KiB of
/// stored vertices.
pub const STREAM_CHUNK: usize = 3 * 4096;

/// Immediate-mode state.
#[derive(Clone, Debug, Default)]
pub struct Immediate {
    /// The primitive of the glBegin in progress, if any.
    pub active: Option<Primitive>,
    /// Vertices given since glBegin.
    pub verts: ImmVerts,
    /// A finished glBegin/glEnd of this mode whose drawing is deferred, so that the next
    /// glBegin of the same mode can extend it: Mesa's vbo module merges such draws (which
    /// decides, for GL_QUADS, whether the merged draw takes the clipping path).
    pub pending: Option<Primitive>,
    /// Whether the pending batch came from a display list (drawn as an indexed draw).
    pub indexed: bool,
    /// The pending batch when it is a compiled display-list node's draw (then `verts`
    /// is empty): drawn from the node's stored vertices.
    pub pending_node: Option<super::dlist_node::PendingNode>,
    /// Whether a display-list vertex node is being replayed.
    pub replaying: bool,
    /// Vertices of the batch already drawn by [`Context::stream_immediate`].
    pub streamed: usize,
    /// Whether glMaterial was called inside this batch (see `vertex_material`).
    pub per_vertex_material: bool,
    /// With `per_vertex_material`, both faces' materials of each vertex in `verts`.
    pub materials: Vec<[super::lighting_state::Material; 2]>,
    /// Whether glVertexAttrib set a generic attribute (index 1 and up) inside this batch:
    /// from then on `verts` records each vertex's generic attributes (as Mesa's vbo
    /// module keeps them per vertex). A batch drawn without the record (a compiled
    /// display-list node, or memory ran out) is refused by a vertex shader that reads one
    /// rather than give every vertex the last value.
    pub generic_inside: bool,
}

impl Immediate {
    /// Whether glBegin/glEnd pairs of `mode` are merged when nothing happens in between
    /// (modes whose primitives are independent of each other).
    pub fn mergeable(mode: Primitive) -> bool {
        matches!(
            mode,
            Primitive::Points | Primitive::Lines | Primitive::Triangles | Primitive::Quads
        )
    }
}

impl Context {
    /// Draws the whole triangles of a glBegin(GL_TRIANGLES) batch of at least
    /// [`STREAM_CHUNK`] vertices when its storage is full, instead of growing it: a
    /// program's first long batch is drawn in chunks while it is specified, so a one-frame
    /// program does not fault in (and copy, as the storage doubles) megabytes of vertices.
    /// [`Context::flush_pending`] then reserves room for the whole batch, so the batches
    /// of later frames are drawn whole, in one draw.
    ///
    /// Triangles are independent of each other, so drawing them in several draws gives
    /// the same pixels (Mesa's vbo module also draws a long batch each time its vertex
    /// buffer fills). Other modes are left whole (a GL_QUADS draw's clip decision covers
    /// the whole draw), as are display-list replays (drawn indexed) and batches with
    /// per-vertex materials.
    #[inline]
    pub fn stream_immediate(&mut self) {
        let im = &self.immediate;
        let n = im.verts.len();
        if n < STREAM_CHUNK
            || im.verts.room() >= 3
            || !n.is_multiple_of(3)
            || im.active != Some(Primitive::Triangles)
            || im.replaying
            || im.per_vertex_material
            || im.generic_inside
        {
            return;
        }
        let verts = std::mem::take(&mut self.immediate.verts);
        super::draw::draw_chunk(self, Primitive::Triangles, &verts);
        let im = &mut self.immediate;
        im.verts = verts;
        im.verts.clear();
        im.streamed += n;
    }
}

/// The attributes of a vertex other than position, colour and normal, shared by
/// consecutive vertices that do not change them.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Rest {
    texcoord: [[f32; 4]; MAX_TEXTURE_UNITS],
    fog_coord: f32,
    edge_flag: bool,
    secondary: [f32; 4],
}

impl Rest {
    /// Whether the current attributes `cur` are bit for bit these (so a vertex given with
    /// them may share this entry). One branch-free pass over the bits: the float compare
    /// it replaces branched per float, and also merged 0.0 with -0.0.
    #[inline]
    fn same_bits(&self, cur: &CurrentAttribs) -> bool {
        let diff = |a: &[f32], b: &[f32]| {
            a.iter()
                .zip(b)
                .fold(0u32, |d, (x, y)| d | (x.to_bits() ^ y.to_bits()))
        };
        diff(self.texcoord.as_flattened(), cur.texcoord.as_flattened())
            | diff(&self.secondary, &cur.secondary_color)
            | (self.fog_coord.to_bits() ^ cur.fog_coord.to_bits())
            | (self.edge_flag != cur.edge_flag) as u32
            == 0
    }

    fn of(cur: &CurrentAttribs) -> Self {
        Rest {
            texcoord: cur.texcoord,
            fog_coord: cur.fog_coord,
            edge_flag: cur.edge_flag,
            secondary: cur.secondary_color,
        }
    }
}

/// One vertex of an [`ImmVerts`]: the attributes that usually change per vertex
/// (a smooth mesh gives every vertex its own normal) and the index of its entry in
/// `rest`.
#[derive(Clone, Copy, Debug)]
struct Vert {
    pos: [f32; 4],
    color: [f32; 4],
    normal: [f32; 3],
    rest: u32,
}

/// The vertices of an immediate-mode batch, stored compactly: position, colour and
/// normal per vertex, the other attributes (texture coordinates, ...) once per run of
/// vertices that share them. (With the normal among the shared ones, a mesh that sets a
/// normal per vertex copied a 160-byte entry per vertex.)
#[derive(Clone, Debug, Default)]
pub struct ImmVerts {
    verts: Vec<Vert>,
    rest: Vec<Rest>,
    /// Each vertex's generic attributes, once the batch sets one between glBegin and
    /// glEnd ([`ImmVerts::track_generic`]); empty otherwise.
    generic: Vec<Generic>,
}

/// The generic attributes' values a vertex is given with.
type Generic = [[f32; 4]; MAX_VERTEX_ATTRIBS];

impl ImmVerts {
    /// The number of vertices.
    pub fn len(&self) -> usize {
        self.verts.len()
    }

    /// Whether there are no vertices.
    pub fn is_empty(&self) -> bool {
        self.verts.is_empty()
    }

    /// Appends a vertex at `pos` with the current attributes `cur` (GL_OUT_OF_MEMORY when
    /// memory runs out). Reads `cur` in place: building a [`VertexIn`] first copied its
    /// 200 bytes per glVertex.
    #[inline]
    pub fn push_current(&mut self, pos: [f32; 4], cur: &CurrentAttribs) -> GlResult<()> {
        if !self.rest.last().is_some_and(|r| r.same_bits(cur)) {
            self.rest.try_reserve(1).map_err(|_| GlError::OutOfMemory)?;
            self.rest.push(Rest::of(cur));
        }
        self.verts
            .try_reserve(1)
            .map_err(|_| GlError::OutOfMemory)?;
        self.verts.push(Vert {
            pos,
            color: cur.color,
            normal: cur.normal,
            rest: (self.rest.len() - 1) as u32,
        });
        Ok(())
    }

    /// Starts recording each vertex's generic attributes (a glVertexAttrib between
    /// glBegin and glEnd): the vertices so far were given with `before`. Does nothing
    /// when recording already. GL_OUT_OF_MEMORY when memory runs out.
    pub fn track_generic(&mut self, before: &Generic) -> GlResult<()> {
        if self.generic.len() != self.verts.len() {
            self.generic.clear();
            let n = self.verts.len();
            self.generic
                .try_reserve(n)
                .map_err(|_| GlError::OutOfMemory)?;
            self.generic.resize(n, *before);
        }
        Ok(())
    }

    /// Records the generic attributes `g` of the vertex just appended, when recording.
    #[inline]
    pub fn push_generic(&mut self, g: &Generic) -> GlResult<()> {
        if self.generic.len() + 1 == self.verts.len() {
            self.generic
                .try_reserve(1)
                .map_err(|_| GlError::OutOfMemory)?;
            self.generic.push(*g);
        }
        Ok(())
    }

    /// Whether every vertex carries its generic attributes.
    pub fn has_generic(&self) -> bool {
        !self.verts.is_empty() && self.generic.len() == self.verts.len()
    }

    /// Keeps the first `n` vertices.
    pub fn truncate(&mut self, n: usize) {
        self.verts.truncate(n);
        self.generic.truncate(n);
        let rest = self.verts.last().map_or(0, |v| v.rest as usize + 1);
        self.rest.truncate(rest);
    }

    /// Removes every vertex (keeping the memory for the next batch).
    pub fn clear(&mut self) {
        self.verts.clear();
        self.generic.clear();
        self.rest.clear();
    }

    /// How many more vertices fit without growing the storage.
    pub fn room(&self) -> usize {
        self.verts.capacity() - self.verts.len()
    }

    /// Makes room for `n` vertices in all, if memory allows (a hint: without the room the
    /// storage grows, or [`Context::stream_immediate`] draws, as vertices arrive).
    pub fn reserve_total(&mut self, n: usize) {
        let more = n.saturating_sub(self.verts.len());
        let _ = self.verts.try_reserve_exact(more);
    }
}

impl VertexSource for ImmVerts {
    #[inline]
    fn count(&self) -> usize {
        self.verts.len()
    }

    #[inline]
    fn vertex(&self, i: usize) -> VertexIn {
        let v = self.verts[i];
        let r = &self.rest[v.rest as usize];
        VertexIn {
            pos: v.pos,
            color: v.color,
            normal: v.normal,
            texcoord: r.texcoord,
            fog_coord: r.fog_coord,
            edge_flag: r.edge_flag,
            secondary: r.secondary,
        }
    }

    #[inline]
    fn vertex_into(&self, i: usize, slot: &mut VertexSlot) {
        let Vert {
            pos,
            color,
            normal,
            rest: r,
        } = self.verts[i];
        slot.v.pos = pos;
        slot.v.color = color;
        slot.v.normal = normal;
        // Consecutive vertices mostly share their `rest` entry: copy it only on a change.
        if slot.tag != r as usize {
            slot.tag = r as usize;
            let r = &self.rest[r as usize];
            slot.v.texcoord = r.texcoord;
            slot.v.fog_coord = r.fog_coord;
            slot.v.edge_flag = r.edge_flag;
            slot.v.secondary = r.secondary;
        }
    }

    #[inline]
    fn position(&self, i: usize) -> [f32; 4] {
        self.verts[i].pos
    }

    #[inline]
    fn edge_flag(&self, i: usize) -> bool {
        self.rest[self.verts[i].rest as usize].edge_flag
    }

    /// The recorded value (attribute 0 is the position, never recorded).
    fn generic(&self, i: usize, loc: usize) -> Option<[f32; 4]> {
        if loc == 0 || !self.has_generic() {
            return None;
        }
        self.generic.get(i).map(|g| g[loc])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::context::state::CurrentAttribs;

    #[test]
    fn vertices_share_attributes_only_when_bits_are_equal() {
        let cur = CurrentAttribs::default();
        let mut iv = ImmVerts::default();
        let mut c = cur;
        let p = [0.0, 0.0, 0.0, 1.0];
        iv.push_current(p, &c).unwrap();
        iv.push_current(p, &c).unwrap();
        assert_eq!(iv.rest.len(), 1);
        // -0.0 == 0.0 as floats, but it is another value.
        c.texcoord[7][2] = -c.texcoord[7][2];
        iv.push_current(p, &c).unwrap();
        assert_eq!(iv.rest.len(), 2);
        assert_eq!(
            iv.vertex(2).texcoord[7][2].to_bits(),
            c.texcoord[7][2].to_bits()
        );
        assert_eq!(iv.vertex(0).texcoord, cur.texcoord);
        c.edge_flag = !c.edge_flag;
        iv.push_current(p, &c).unwrap();
        c.fog_coord = 0.25;
        iv.push_current(p, &c).unwrap();
        // Only the normal changes: kept per vertex, the entry is still shared.
        c.normal[1] = 0.5;
        iv.push_current(p, &c).unwrap();
        c.secondary_color[3] = 0.5;
        iv.push_current(p, &c).unwrap();
        // NaN is kept (and shared with an identical NaN).
        c.texcoord[0][0] = f32::NAN;
        iv.push_current(p, &c).unwrap();
        // Only the colour changes: the entry is still shared.
        c.color = [0.25; 4];
        iv.push_current([1.0, 2.0, 3.0, 1.0], &c).unwrap();
        assert_eq!(iv.rest.len(), 6);
        assert!(iv.vertex(8).texcoord[0][0].is_nan());
        assert_eq!(iv.vertex(8).color, [0.25; 4]);
        assert_eq!(iv.vertex(8).pos, [1.0, 2.0, 3.0, 1.0]);
        assert_eq!(iv.vertex(5).normal[1], 0.5);
        assert_eq!(iv.vertex(4).normal[1], cur.normal[1]);
        assert_eq!(iv.vertex(4).edge_flag, !cur.edge_flag);
        // A reused slot reads every vertex as `vertex` does, in any order (the slot skips
        // copying the shared attributes only while they stay the same entry).
        let mut slot = iv.new_slot();
        for i in [0, 1, 2, 8, 3, 3, 0, 7, 8, 5, 4, 6, 1] {
            iv.vertex_into(i, &mut slot);
            let (a, b) = (slot.v, iv.vertex(i));
            assert_eq!(format!("{a:?}"), format!("{b:?}"), "vertex {i}");
        }
    }

    #[test]
    fn generic_attributes_are_recorded_from_the_first_call_inside() {
        let cur = CurrentAttribs::default();
        let p = [0.0, 0.0, 0.0, 1.0];
        let mut iv = ImmVerts::default();
        let before = [[0.5; 4]; MAX_VERTEX_ATTRIBS];
        iv.push_current(p, &cur).unwrap();
        iv.push_generic(&before).unwrap();
        iv.push_current(p, &cur).unwrap();
        // Not recording yet: no vertex has its own values.
        assert!(!iv.has_generic());
        assert_eq!(iv.generic(1, 3), None);
        iv.track_generic(&before).unwrap();
        let mut g = before;
        g[3] = [1.0, 2.0, 3.0, 4.0];
        iv.push_current(p, &cur).unwrap();
        iv.push_generic(&g).unwrap();
        assert!(iv.has_generic());
        assert_eq!(iv.generic(0, 3), Some([0.5; 4]));
        assert_eq!(iv.generic(2, 3), Some([1.0, 2.0, 3.0, 4.0]));
        // Attribute 0 is the position, never a recorded value.
        assert_eq!(iv.generic(2, 0), None);
        iv.truncate(2);
        assert!(iv.has_generic());
        iv.clear();
        assert!(!iv.has_generic());
    }
}
