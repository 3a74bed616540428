//! glBegin/glEnd: the vertices of the primitive being specified.

use super::state::Primitive;
use crate::geometry::fetch::VertexIn;

/// Immediate-mode state.
#[derive(Clone, Debug, Default)]
pub struct Immediate {
    /// The primitive of the glBegin in progress, if any.
    pub active: Option<Primitive>,
    /// Vertices given since glBegin.
    pub verts: Vec<VertexIn>,
    /// A finished glBegin/glEnd of this mode whose drawing is deferred, so that the next
    /// glBegin of the same mode can extend it: Mesa's vbo module merges such draws (which
    /// decides, for GL_QUADS, whether the merged draw takes the clipping path).
    pub pending: Option<Primitive>,
    /// Whether the pending batch came from a display list (drawn as an indexed draw).
    pub indexed: bool,
    /// Whether a display-list vertex node is being replayed.
    pub replaying: bool,
    /// Whether glMaterial was called inside this batch (see `vertex_material`).
    pub per_vertex_material: bool,
    /// With `per_vertex_material`, both faces' materials of each vertex in `verts`.
    pub materials: Vec<[super::lighting_state::Material; 2]>,
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
