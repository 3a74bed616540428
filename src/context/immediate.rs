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
}
