//! How the shapes reach GL: client-side vertex and normal arrays drawn with
//! `glDrawArrays`/`glDrawElements`, the calls freeglut makes on a compatibility
//! context, so a program sees the same primitives, vertex order and array state
//! (both arrays are disabled again afterwards) whichever GLUT it links.

use crate::gl::{GLenum, GLint, GLsizei, GL_FLOAT, GL_LINE_LOOP, GL_TRIANGLES};
use std::ffi::c_void;

const GL_TRIANGLE_STRIP: GLenum = crate::gl::GL_TRIANGLE_STRIP;
const GL_UNSIGNED_SHORT: GLenum = 0x1403;
const GL_VERTEX_ARRAY: GLenum = 0x8074;
const GL_NORMAL_ARRAY: GLenum = 0x8075;
const GL_TEXTURE_COORD_ARRAY: GLenum = 0x8078;

extern "C" {
    fn glEnableClientState(array: GLenum);
    fn glDisableClientState(array: GLenum);
    fn glVertexPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const c_void);
    fn glNormalPointer(ty: GLenum, stride: GLsizei, ptr: *const c_void);
    fn glTexCoordPointer(size: GLint, ty: GLenum, stride: GLsizei, ptr: *const c_void);
    fn glDrawArrays(mode: GLenum, first: GLint, count: GLsizei);
    fn glDrawElements(mode: GLenum, count: GLsizei, ty: GLenum, indices: *const c_void);
}

/// Vertex positions and normals, three floats each, one normal per vertex.
pub struct Mesh {
    /// x, y, z per vertex.
    pub verts: Vec<f32>,
    /// The unit (or, for some polyhedra, freeglut's unnormalised) normal per vertex.
    pub norms: Vec<f32>,
}

impl Mesh {
    /// An empty mesh with room for `n` vertices.
    pub fn with_capacity(n: usize) -> Self {
        Mesh {
            verts: Vec::with_capacity(3 * n),
            norms: Vec::with_capacity(3 * n),
        }
    }

    /// Appends one vertex and its normal.
    pub fn push(&mut self, v: [f32; 3], n: [f32; 3]) {
        self.verts.extend_from_slice(&v);
        self.norms.extend_from_slice(&n);
    }

    /// The number of vertices.
    pub fn len(&self) -> usize {
        self.verts.len() / 3
    }

    /// True when the mesh has no vertices.
    pub fn is_empty(&self) -> bool {
        self.verts.is_empty()
    }
}

/// Points GL's vertex, normal and (optionally) texture-coordinate arrays at the mesh,
/// runs `draw`, then disables the arrays again.
fn with_arrays(mesh: &Mesh, texcs: Option<&[f32]>, draw: impl FnOnce()) {
    debug_assert_eq!(mesh.verts.len(), mesh.norms.len());
    debug_assert!(texcs.is_none_or(|t| t.len() / 2 == mesh.len()));
    // SAFETY: the pointers are to the mesh's (and texcs') live buffers, which hold every
    // vertex the draw calls below index; they stay borrowed until the arrays are
    // disabled again, and client arrays are read during the draw call only.
    unsafe {
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_NORMAL_ARRAY);
        glVertexPointer(3, GL_FLOAT, 0, mesh.verts.as_ptr().cast());
        glNormalPointer(GL_FLOAT, 0, mesh.norms.as_ptr().cast());
        if let Some(t) = texcs {
            glEnableClientState(GL_TEXTURE_COORD_ARRAY);
            glTexCoordPointer(2, GL_FLOAT, 0, t.as_ptr().cast());
        }
    }
    draw();
    // SAFETY: plain state calls.
    unsafe {
        glDisableClientState(GL_VERTEX_ARRAY);
        glDisableClientState(GL_NORMAL_ARRAY);
        if texcs.is_some() {
            glDisableClientState(GL_TEXTURE_COORD_ARRAY);
        }
    }
}

/// `glDrawElements` of `idx` (16-bit indices into the enabled arrays).
fn elements(mode: GLenum, idx: &[u16]) {
    // SAFETY: idx is a live slice of idx.len() u16 indices; every caller builds the
    // indices below the length of the arrays in use.
    unsafe {
        glDrawElements(
            mode,
            idx.len() as GLsizei,
            GL_UNSIGNED_SHORT,
            idx.as_ptr().cast(),
        )
    }
}

/// Filled: the whole mesh as separate triangles when `idx` is `None`; otherwise
/// `idx` split in `parts` equal triangle strips, or one triangle list when `parts`
/// is 1.
pub fn solid(mesh: &Mesh, texcs: Option<&[f32]>, idx: Option<&[u16]>, parts: usize) {
    with_arrays(mesh, texcs, || match idx {
        // SAFETY: the arrays hold mesh.len() vertices.
        None => unsafe { glDrawArrays(GL_TRIANGLES, 0, mesh.len() as GLsizei) },
        Some(idx) if parts > 1 => {
            for strip in idx.chunks_exact(idx.len() / parts) {
                elements(GL_TRIANGLE_STRIP, strip);
            }
        }
        Some(idx) => elements(GL_TRIANGLES, idx),
    });
}

/// Outlines: `first` is drawn as runs of `first_len` vertices with `mode` (the
/// mesh itself, in order, when the index list is `None`); `loops` as line loops of
/// `loop_len` indices each.
pub fn wire(
    mesh: &Mesh,
    first: Option<&[u16]>,
    first_len: usize,
    mode: GLenum,
    loops: &[u16],
    loop_len: usize,
) {
    with_arrays(mesh, None, || {
        match first {
            None => {
                for start in (0..mesh.len()).step_by(first_len.max(1)) {
                    // SAFETY: every run lies inside the mesh's arrays.
                    unsafe { glDrawArrays(mode, start as GLint, first_len as GLsizei) }
                }
            }
            Some(idx) => {
                for run in idx.chunks_exact(first_len.max(1)) {
                    elements(mode, run);
                }
            }
        }
        for run in loops.chunks_exact(loop_len.max(1)) {
            elements(GL_LINE_LOOP, run);
        }
    });
}
