//! Immediate mode: glBegin/glEnd and the glVertex, glColor, glTexCoord and glNormal
//! families. Integer colours and normals are converted as Mesa's vbo module does
//! (`u / 255.0f` for unsigned bytes, `(2c + 1) / (2^n - 1)` for signed types).
#![allow(non_snake_case)]

use super::families::{c_fns, vector_fns, Component};
use super::types::*;
use super::{with_ctx_list, with_ctx_vertex};
use crate::context::dlist::VertexOp;
use crate::context::state::Primitive;

/// glBegin.
#[no_mangle]
pub extern "C" fn glBegin(mode: GLenum) {
    let m = match Primitive::from_gl(mode) {
        Ok(m) => m,
        // An invalid mode is compiled as the error it raises when the list runs.
        Err(e) => return with_ctx_list(move |_| Err(e)),
    };
    with_ctx_vertex(VertexOp::Begin(m))
}

/// glEnd: draws the vertices given since glBegin (or defers them to merge with the next
/// glBegin of the same mode).
#[no_mangle]
pub extern "C" fn glEnd() {
    with_ctx_vertex(VertexOp::End)
}

/// Adds a vertex inside glBegin/glEnd (outside it, GL leaves the effect undefined; we
/// ignore it, as Mesa does).
fn vertex(p: [f32; 4]) {
    with_ctx_vertex(VertexOp::Vertex(p))
}

/// Sets the current colour.
fn color(v: [f32; 4]) {
    with_ctx_vertex(VertexOp::Color(v))
}

/// Sets the current texture coordinate of unit 0.
fn texcoord(v: [f32; 4]) {
    with_ctx_vertex(VertexOp::TexCoord(0, v))
}

/// Sets the current normal.
fn normal(v: [f32; 3]) {
    with_ctx_vertex(VertexOp::Normal(v))
}

vector_fns! {
    vertex cast [0.0, 0.0, 0.0, 1.0] {
        (x, y) glVertex2s glVertex2sv GLshort, glVertex2i glVertex2iv GLint, glVertex2f glVertex2fv GLfloat, glVertex2d glVertex2dv GLdouble;
        (x, y, z) glVertex3s glVertex3sv GLshort, glVertex3i glVertex3iv GLint, glVertex3f glVertex3fv GLfloat, glVertex3d glVertex3dv GLdouble;
        (x, y, z, w) glVertex4s glVertex4sv GLshort, glVertex4i glVertex4iv GLint, glVertex4f glVertex4fv GLfloat, glVertex4d glVertex4dv GLdouble;
    }
    color norm [0.0, 0.0, 0.0, 1.0] {
        (red, green, blue) glColor3b glColor3bv GLbyte, glColor3s glColor3sv GLshort, glColor3i glColor3iv GLint, glColor3f glColor3fv GLfloat;
        (red, green, blue) glColor3d glColor3dv GLdouble, glColor3ub glColor3ubv GLubyte, glColor3us glColor3usv GLushort, glColor3ui glColor3uiv GLuint;
        (red, green, blue, alpha) glColor4b glColor4bv GLbyte, glColor4s glColor4sv GLshort, glColor4i glColor4iv GLint, glColor4f glColor4fv GLfloat;
        (red, green, blue, alpha) glColor4d glColor4dv GLdouble, glColor4ub glColor4ubv GLubyte, glColor4us glColor4usv GLushort, glColor4ui glColor4uiv GLuint;
    }
    texcoord cast [0.0, 0.0, 0.0, 1.0] {
        (s) glTexCoord1s glTexCoord1sv GLshort, glTexCoord1i glTexCoord1iv GLint, glTexCoord1f glTexCoord1fv GLfloat, glTexCoord1d glTexCoord1dv GLdouble;
        (s, t) glTexCoord2s glTexCoord2sv GLshort, glTexCoord2i glTexCoord2iv GLint, glTexCoord2f glTexCoord2fv GLfloat, glTexCoord2d glTexCoord2dv GLdouble;
        (s, t, r) glTexCoord3s glTexCoord3sv GLshort, glTexCoord3i glTexCoord3iv GLint, glTexCoord3f glTexCoord3fv GLfloat, glTexCoord3d glTexCoord3dv GLdouble;
        (s, t, r, q) glTexCoord4s glTexCoord4sv GLshort, glTexCoord4i glTexCoord4iv GLint, glTexCoord4f glTexCoord4fv GLfloat, glTexCoord4d glTexCoord4dv GLdouble;
    }
    normal norm [0.0, 0.0, 0.0] {
        (nx, ny, nz) glNormal3b glNormal3bv GLbyte, glNormal3s glNormal3sv GLshort, glNormal3i glNormal3iv GLint, glNormal3f glNormal3fv GLfloat, glNormal3d glNormal3dv GLdouble;
    }
}

/// glRect as Mesa draws it: a GL_QUADS quad (x1,y1), (x2,y1), (x2,y2), (x1,y2) at z = 0.
/// A display list records it as one command that runs the immediate-mode path (Mesa's
/// OPCODE_RECTF), not as a vertex node.
fn rect([x1, y1, x2, y2]: [f32; 4]) {
    with_ctx_list(move |c| {
        for op in [
            VertexOp::Begin(Primitive::Quads),
            VertexOp::Vertex([x1, y1, 0.0, 1.0]),
            VertexOp::Vertex([x2, y1, 0.0, 1.0]),
            VertexOp::Vertex([x2, y2, 0.0, 1.0]),
            VertexOp::Vertex([x1, y2, 0.0, 1.0]),
            VertexOp::End,
        ] {
            c.vertex_op(op)?;
        }
        Ok(())
    })
}

/// glRect*v: the corners `v1` and `v2`, nothing when either is null.
///
/// # Safety
/// `v1` and `v2` must be null or point to 2 values each.
unsafe fn rect_v<T: Component>(v1: *const T, v2: *const T) {
    if v1.is_null() || v2.is_null() {
        return;
    }
    // SAFETY: the caller promises two readable values at each pointer.
    let [a, b] = [v1, v2].map(|v| unsafe { [v.read_unaligned(), v.add(1).read_unaligned()] });
    rect([a[0], a[1], b[0], b[1]].map(T::cast))
}

c_fns! {
    safe fn glRects(x1: GLshort, y1: GLshort, x2: GLshort, y2: GLshort) => rect([x1, y1, x2, y2].map(Component::cast));
    unsafe fn glRectsv(v1: *const GLshort, v2: *const GLshort) => rect_v(v1, v2);
    safe fn glRecti(x1: GLint, y1: GLint, x2: GLint, y2: GLint) => rect([x1, y1, x2, y2].map(Component::cast));
    unsafe fn glRectiv(v1: *const GLint, v2: *const GLint) => rect_v(v1, v2);
    safe fn glRectf(x1: GLfloat, y1: GLfloat, x2: GLfloat, y2: GLfloat) => rect([x1, y1, x2, y2]);
    unsafe fn glRectfv(v1: *const GLfloat, v2: *const GLfloat) => rect_v(v1, v2);
    safe fn glRectd(x1: GLdouble, y1: GLdouble, x2: GLdouble, y2: GLdouble) => rect([x1, y1, x2, y2].map(Component::cast));
    unsafe fn glRectdv(v1: *const GLdouble, v2: *const GLdouble) => rect_v(v1, v2);
}
