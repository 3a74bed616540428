//! Vertices stored once, per attribute, and drawn many times: a compiled display-list
//! vertex node keeps its positions and only the attributes the node itself sets
//! ([`StoredVerts`]); a draw reads a range of them through [`StoredSource`], with the
//! attributes the node does not set taken from one base vertex (the current values when
//! the node is replayed).

use super::boxes::{boxes_of, PosBox, PositionBoxes};
use super::fetch::VertexIn;
use super::source::{VertexSlot, VertexSource};
use crate::pipe::{CurrentAttribs, MAX_TEXTURE_UNITS};

/// Attribute bit of the primary colour.
pub const COLOR: u32 = 1;
/// Attribute bit of the secondary colour.
pub const SECONDARY: u32 = 2;
/// Attribute bit of the normal.
pub const NORMAL: u32 = 4;
/// Attribute bit of the fog coordinate.
pub const FOG: u32 = 8;
/// Attribute bit of texture unit 0's coordinates (unit `u` is `TEX0 << u`).
pub const TEX0: u32 = 16;
/// Attribute bit of the edge flag.
pub const EDGE: u32 = 1 << 12;

/// Positions and the attributes named by `set`, one entry per vertex, or once when every
/// vertex has the same value (a floor grid's one normal).
#[derive(Debug)]
pub struct StoredVerts {
    /// The attributes stored (bits [`COLOR`], [`NORMAL`] …).
    set: u32,
    /// Those of `set` stored per vertex; the others of `set` are in `consts`.
    varying: u32,
    /// The value of each attribute of `set` that is not `varying`.
    consts: VertexIn,
    pos: Vec<[f32; 4]>,
    color: Vec<[f32; 4]>,
    secondary: Vec<[f32; 4]>,
    normal: Vec<[f32; 3]>,
    fog: Vec<f32>,
    edge: Vec<bool>,
    /// Each stored unit and its coordinates.
    tex: Vec<(usize, Vec<[f32; 4]>)>,
    /// The boxes of the positions' runs ([`boxes_of`]), made by [`Self::finish`].
    boxes: Vec<Option<PosBox>>,
}

impl StoredVerts {
    /// Room for `n` vertices storing the attributes `set` besides the position, if
    /// memory allows.
    pub fn with_capacity(set: u32, n: usize) -> Option<Self> {
        fn room<T>(v: &mut Vec<T>, n: usize) -> Option<()> {
            v.try_reserve_exact(n).ok()
        }
        let mut s = Self::new(set);
        let on = |bit: u32| if set & bit != 0 { n } else { 0 };
        room(&mut s.pos, n)?;
        room(&mut s.color, on(COLOR))?;
        room(&mut s.secondary, on(SECONDARY))?;
        room(&mut s.normal, on(NORMAL))?;
        room(&mut s.fog, on(FOG))?;
        room(&mut s.edge, on(EDGE))?;
        for (_, t) in &mut s.tex {
            room(t, n)?;
        }
        Some(s)
    }

    /// No vertices, storing the attributes `set` besides the position.
    pub fn new(set: u32) -> Self {
        let tex = (0..MAX_TEXTURE_UNITS)
            .filter(|&u| set & (TEX0 << u) != 0)
            .map(|u| (u, Vec::new()))
            .collect();
        StoredVerts {
            set,
            varying: set,
            consts: VertexIn::with_current([0.0; 4], &CurrentAttribs::default()),
            tex,
            pos: Vec::new(),
            color: Vec::new(),
            secondary: Vec::new(),
            normal: Vec::new(),
            fog: Vec::new(),
            edge: Vec::new(),
            boxes: Vec::new(),
        }
    }

    /// Keeps each attribute whose vertices all have the same value (bit for bit) once
    /// instead of per vertex, and boxes the positions; call when every vertex is pushed.
    pub fn finish(&mut self) {
        self.boxes = boxes_of(&self.pos);
        fn same<T: Copy, B: PartialEq>(v: &[T], bits: impl Fn(T) -> B) -> bool {
            v.first()
                .is_some_and(|&a| v.iter().all(|&b| bits(b) == bits(a)))
        }
        let b4 = |v: [f32; 4]| v.map(f32::to_bits);
        let c = &mut self.consts;
        if same(&self.color, b4) {
            c.color = self.color[0];
            self.varying &= !COLOR;
            self.color = Vec::new();
        }
        if same(&self.secondary, b4) {
            c.secondary = self.secondary[0];
            self.varying &= !SECONDARY;
            self.secondary = Vec::new();
        }
        if same(&self.normal, |v: [f32; 3]| v.map(f32::to_bits)) {
            c.normal = self.normal[0];
            self.varying &= !NORMAL;
            self.normal = Vec::new();
        }
        if same(&self.fog, f32::to_bits) {
            c.fog_coord = self.fog[0];
            self.varying &= !FOG;
            self.fog = Vec::new();
        }
        if same(&self.edge, |e| e) {
            c.edge_flag = self.edge[0];
            self.varying &= !EDGE;
            self.edge = Vec::new();
        }
        let varying = &mut self.varying;
        self.tex.retain(|(u, t)| {
            if !same(t, b4) {
                return true;
            }
            c.texcoord[*u] = t[0];
            *varying &= !(TEX0 << u);
            false
        });
    }

    /// The attributes stored.
    #[inline]
    pub fn set(&self) -> u32 {
        self.set
    }

    /// The number of vertices.
    pub fn len(&self) -> usize {
        self.pos.len()
    }

    /// Whether there are no vertices.
    pub fn is_empty(&self) -> bool {
        self.pos.is_empty()
    }

    /// Appends `v`'s position and stored attributes.
    pub fn push(&mut self, v: &VertexIn) {
        // Boxes cover the positions `finish` saw.
        self.boxes.clear();
        self.pos.push(v.pos);
        let s = self.set;
        if s & COLOR != 0 {
            self.color.push(v.color);
        }
        if s & SECONDARY != 0 {
            self.secondary.push(v.secondary);
        }
        if s & NORMAL != 0 {
            self.normal.push(v.normal);
        }
        if s & FOG != 0 {
            self.fog.push(v.fog_coord);
        }
        if s & EDGE != 0 {
            self.edge.push(v.edge_flag);
        }
        for (u, t) in &mut self.tex {
            t.push(v.texcoord[*u]);
        }
    }

    /// Keeps the first `n` vertices.
    pub fn truncate(&mut self, n: usize) {
        self.boxes.clear();
        self.pos.truncate(n);
        self.color.truncate(n);
        self.secondary.truncate(n);
        self.normal.truncate(n);
        self.fog.truncate(n);
        self.edge.truncate(n);
        for (_, t) in &mut self.tex {
            t.truncate(n);
        }
    }

    /// Writes vertex `k`'s position and stored attributes into `v` (the others are left).
    #[inline(always)]
    fn write(&self, k: usize, v: &mut VertexIn) {
        v.pos = self.pos[k];
        let s = self.varying;
        if s & COLOR != 0 {
            v.color = self.color[k];
        }
        if s & NORMAL != 0 {
            v.normal = self.normal[k];
        }
        for (u, t) in &self.tex {
            v.texcoord[*u] = t[k];
        }
        if s & (SECONDARY | FOG | EDGE) != 0 {
            if s & SECONDARY != 0 {
                v.secondary = self.secondary[k];
            }
            if s & FOG != 0 {
                v.fog_coord = self.fog[k];
            }
            if s & EDGE != 0 {
                v.edge_flag = self.edge[k];
            }
        }
    }

    /// Position `k`.
    #[inline]
    pub fn position(&self, k: usize) -> [f32; 4] {
        self.pos[k]
    }

    /// `v` with the attributes stored once written in.
    fn with_consts(&self, mut v: VertexIn) -> VertexIn {
        let (s, c) = (self.set & !self.varying, &self.consts);
        if s & COLOR != 0 {
            v.color = c.color;
        }
        if s & SECONDARY != 0 {
            v.secondary = c.secondary;
        }
        if s & NORMAL != 0 {
            v.normal = c.normal;
        }
        if s & FOG != 0 {
            v.fog_coord = c.fog_coord;
        }
        if s & EDGE != 0 {
            v.edge_flag = c.edge_flag;
        }
        for (u, t) in v.texcoord.iter_mut().enumerate() {
            if s & (TEX0 << u) != 0 {
                *t = c.texcoord[u];
            }
        }
        v
    }

    /// Writes vertex `k`'s stored attributes into the current attributes `cur` (what the
    /// node's commands had made them when it gave the vertex).
    pub fn write_current(&self, k: usize, cur: &mut CurrentAttribs) {
        let mut v = self.with_consts(VertexIn::with_current(self.pos[k], cur));
        self.write(k, &mut v);
        cur.color = v.color;
        cur.secondary_color = v.secondary;
        cur.normal = v.normal;
        cur.texcoord = v.texcoord;
        cur.fog_coord = v.fog_coord;
        cur.edge_flag = v.edge_flag;
    }

    /// The vertices `start..start + count` as a draw's source, with the attributes not
    /// stored taken from `base`.
    pub fn source(&self, start: usize, count: usize, base: &CurrentAttribs) -> StoredSource<'_> {
        assert!(start + count <= self.len());
        StoredSource {
            verts: self,
            start,
            count,
            base: self.with_consts(VertexIn::with_current([0.0, 0.0, 0.0, 1.0], base)),
        }
    }
}

/// A range of [`StoredVerts`] read as a draw's vertices 0..count.
pub struct StoredSource<'a> {
    verts: &'a StoredVerts,
    start: usize,
    count: usize,
    /// The attributes that are not stored.
    base: VertexIn,
}

impl VertexSource for StoredSource<'_> {
    #[inline]
    fn count(&self) -> usize {
        self.count
    }

    #[inline]
    fn vertex(&self, i: usize) -> VertexIn {
        let mut v = self.base;
        self.verts.write(self.start + i, &mut v);
        v
    }

    fn new_slot(&self) -> VertexSlot {
        VertexSlot {
            v: self.base,
            tag: 0,
        }
    }

    #[inline]
    fn vertex_into(&self, i: usize, slot: &mut VertexSlot) {
        // `slot.v` came from `new_slot` and was written only here: its attributes that
        // are not stored still hold `base`.
        self.verts.write(self.start + i, &mut slot.v);
    }

    #[inline]
    fn position(&self, i: usize) -> [f32; 4] {
        self.verts.pos[self.start + i]
    }

    fn position_boxes(&self) -> Option<PositionBoxes<'_>> {
        // Boxes made before the last push (none are: `finish` comes after) would not
        // cover the positions.
        let b = &self.verts.boxes;
        (b.len() == self.verts.pos.len().div_ceil(super::boxes::BOX_VERTS)).then_some(
            PositionBoxes {
                first: self.start,
                boxes: b,
            },
        )
    }

    #[inline]
    fn edge_flag(&self, i: usize) -> bool {
        if self.verts.varying & EDGE != 0 {
            self.verts.edge[self.start + i]
        } else {
            self.base.edge_flag
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_range_reads_stored_attributes_and_the_base_for_the_rest() {
        let cur = CurrentAttribs::default();
        let mut s = StoredVerts::new(NORMAL | (TEX0 << 3) | EDGE);
        let mut v = VertexIn::with_current([0.0; 4], &cur);
        for k in 0..5 {
            v.pos = [k as f32, 1.0, 2.0, 1.0];
            v.normal = [0.0, k as f32, 0.0];
            v.texcoord[3] = [k as f32 * 0.5; 4];
            v.edge_flag = k % 2 == 0;
            v.color = [9.0; 4]; // not stored
            s.push(&v);
        }
        s.truncate(4);
        assert_eq!(s.len(), 4);
        s.finish();
        assert_eq!(s.varying, NORMAL | (TEX0 << 3) | EDGE);
        let mut base = cur;
        base.color = [0.25; 4];
        base.texcoord[0] = [7.0; 4];
        let src = s.source(1, 3, &base);
        assert_eq!(src.count(), 3);
        let mut slot = src.new_slot();
        for i in [2, 0, 1, 1, 2] {
            src.vertex_into(i, &mut slot);
            let (a, b) = (slot.v, src.vertex(i));
            assert_eq!(format!("{a:?}"), format!("{b:?}"));
            assert_eq!(b.pos[0], (i + 1) as f32);
            assert_eq!(b.normal[1], (i + 1) as f32);
            assert_eq!(b.texcoord[3][0], (i + 1) as f32 * 0.5);
            assert_eq!(b.texcoord[0], [7.0; 4]);
            assert_eq!(b.color, [0.25; 4]);
            assert_eq!(src.edge_flag(i), (i + 1) % 2 == 0);
            assert_eq!(src.position(i), b.pos);
        }
        let mut c = base;
        s.write_current(2, &mut c);
        assert_eq!((c.normal[1], c.color), (2.0, [0.25; 4]));
    }

    #[test]
    fn an_attribute_every_vertex_shares_is_kept_once_bit_for_bit() {
        let cur = CurrentAttribs::default();
        let mut s = StoredVerts::new(COLOR | NORMAL | FOG | TEX0);
        let mut v = VertexIn::with_current([0.0; 4], &cur);
        v.normal = [0.0, 0.0, -1.0];
        v.fog_coord = 0.5;
        for k in 0..3 {
            v.pos[0] = k as f32;
            // -0.0 and 0.0 are different values: the colour stays per vertex.
            v.color[0] = if k == 1 { -0.0 } else { 0.0 };
            v.texcoord[0][1] = 2.0;
            s.push(&v);
        }
        s.finish();
        assert_eq!(s.varying, COLOR);
        assert!(s.normal.is_empty() && s.tex.is_empty() && s.fog.is_empty());
        let src = s.source(0, 3, &cur);
        for i in 0..3 {
            let w = src.vertex(i);
            assert_eq!((w.normal, w.fog_coord, w.pos[0]), (v.normal, 0.5, i as f32));
            assert_eq!(w.texcoord[0][1], 2.0);
            assert_eq!(w.color[0].is_sign_negative(), i == 1);
            assert_eq!(w.texcoord[1], cur.texcoord[1]);
        }
        let mut c = cur;
        s.write_current(0, &mut c);
        assert_eq!((c.normal, c.fog_coord), (v.normal, 0.5));
    }
}
