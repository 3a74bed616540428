//! Feedback and selection where softgl follows the GL 1.5 spec rather than Mesa 22.3
//! (`c_tests/feedback_select.c` compares everything else with OSMesa): edge flags of
//! unfilled polygons in feedback (Mesa drops every edge once glEdgeFlag was called), and
//! glRenderMode's error cases (Mesa leaves the old mode before it validates the new one).
//! The expected values come from the spec's rules and the viewport arithmetic.

use softgl::ffi::enums::*;
use softgl::ffi::feedback::*;
use softgl::ffi::immediate::*;
use softgl::ffi::osmesa::*;
use softgl::ffi::query::*;
use softgl::ffi::rasterization::*;
use softgl::ffi::state::glGetError;

/// A current 64x48 RGBA context; the buffer lives as long as it.
struct Ctx {
    ctx: OSMesaContext,
    _buf: Vec<u8>,
}

impl Ctx {
    fn new() -> Ctx {
        let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, std::ptr::null_mut());
        assert!(!ctx.is_null());
        let mut buf = vec![0u8; 64 * 48 * 4];
        // SAFETY: the buffer holds 64x48 RGBA pixels and outlives the binding.
        let ok =
            unsafe { OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 64, 48) };
        assert_eq!(ok, GL_TRUE as u8);
        Ctx { ctx, _buf: buf }
    }
}

impl Drop for Ctx {
    fn drop(&mut self) {
        OSMesaDestroyContext(self.ctx);
    }
}

/// Window coordinates of NDC (x, y) in the 64x48 viewport.
fn win(x: f32, y: f32) -> [f32; 2] {
    [(x + 1.0) * 32.0, (y + 1.0) * 24.0]
}

/// Feeds back one triangle with per-vertex edge flags `flags` in polygon mode `mode`.
fn feedback_triangle(mode: u32, flags: [bool; 3]) -> Vec<f32> {
    let mut buf = vec![0f32; 256];
    glFeedbackBuffer(256, GL_2D, buf.as_mut_ptr());
    glRenderMode(GL_FEEDBACK);
    glPolygonMode(GL_FRONT_AND_BACK, mode);
    glBegin(GL_TRIANGLES);
    for (f, (x, y)) in flags.iter().zip([(-0.5, -0.5), (0.5, -0.5), (0.0, 0.5)]) {
        glEdgeFlag(*f as u8);
        glVertex2f(x, y);
    }
    glEnd();
    let n = glRenderMode(GL_RENDER);
    assert!(n >= 0);
    buf.truncate(n as usize);
    buf
}

#[test]
fn unfilled_feedback_honours_edge_flags() {
    let _c = Ctx::new();
    let [a, b, c] = [win(-0.5, -0.5), win(0.5, -0.5), win(0.0, 0.5)];
    // GL 1.5 §2.6.2/§3.5.4: an edge is a boundary edge when its first vertex's flag is
    // set; the unfilled stage writes v2→v0, v0→v1, v1→v2, the first after a reset token.
    let reset = GL_LINE_RESET_TOKEN as f32;
    let line = GL_LINE_TOKEN as f32;
    assert_eq!(
        feedback_triangle(GL_LINE, [true, false, true]),
        vec![reset, c[0], c[1], a[0], a[1], line, a[0], a[1], b[0], b[1]]
    );
    // With the first vertex's flag off only v1→v2 remains, still after a reset token.
    assert_eq!(
        feedback_triangle(GL_LINE, [false, true, false]),
        vec![reset, b[0], b[1], c[0], c[1]]
    );
    // Points: a vertex whose flag is off is not drawn.
    let point = GL_POINT_TOKEN as f32;
    assert_eq!(
        feedback_triangle(GL_POINT, [true, false, true]),
        vec![point, a[0], a[1], point, c[0], c[1]]
    );
    // All flags on: the whole outline.
    assert_eq!(feedback_triangle(GL_LINE, [true; 3]).len(), 15);
    assert_eq!(glGetError(), GL_NO_ERROR);
}

#[test]
fn invalid_render_mode_calls_change_nothing() {
    let _c = Ctx::new();
    let mut names = [0u32; 16];
    // No selection buffer yet: the mode stays GL_RENDER.
    glRenderMode(GL_SELECT);
    assert_eq!(glGetError(), GL_INVALID_OPERATION);
    let mut mode = 0;
    // SAFETY: one component.
    unsafe { glGetIntegerv(GL_RENDER_MODE, &mut mode) };
    assert_eq!(mode as u32, GL_RENDER);

    glSelectBuffer(16, names.as_mut_ptr());
    glRenderMode(GL_SELECT);
    glPushName(3);
    glBegin(GL_POINTS);
    glVertex2f(0.0, 0.0);
    glEnd();
    // A bad enum keeps selection mode, the pending hit and the name stack.
    assert_eq!(glRenderMode(0x1234), 0);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    // SAFETY: one component.
    unsafe { glGetIntegerv(GL_NAME_STACK_DEPTH, &mut mode) };
    assert_eq!(mode, 1);
    assert_eq!(glRenderMode(GL_RENDER), 1);
    // One hit: one name, z 0.5 at both ends (2^31), name 3.
    assert_eq!(&names[..4], &[1, 1 << 31, 1 << 31, 3]);
    // Negative sizes.
    glSelectBuffer(-1, names.as_mut_ptr());
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    glFeedbackBuffer(4, GL_2D, std::ptr::null_mut());
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    glFeedbackBuffer(4, 0x1234, [0f32; 4].as_mut_ptr());
    assert_eq!(glGetError(), GL_INVALID_ENUM);
}
