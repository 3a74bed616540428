//! A frame that uses every kind of primitive and state, drawn through the C entry points
//! from a thread with a 256 KiB stack: a user's worker thread may be that small, so no
//! path of the library may need more. `tests/small_stack.rs` runs it on the release
//! library, as it ships, at every instruction-set level (`scripts/test.sh`). It is not a
//! unit test: the `unit` profile is unoptimised, and at opt-level 0 LLVM gives every
//! inlined call its own stack slots (the AVX2 texture walk's frame is 0.5 MB there).

use softgl::ffi::accum::*;
use softgl::ffi::arrays::*;
use softgl::ffi::draw::*;
use softgl::ffi::enums::*;
use softgl::ffi::feedback::*;
use softgl::ffi::fragment::*;
use softgl::ffi::glext_enums::*;
use softgl::ffi::immediate::*;
use softgl::ffi::lighting::*;
use softgl::ffi::lists::*;
use softgl::ffi::matrix::*;
use softgl::ffi::osmesa::*;
use softgl::ffi::pixels::*;
use softgl::ffi::pixels_draw::*;
use softgl::ffi::query::*;
use softgl::ffi::rasterization::*;
use softgl::ffi::state::*;
use softgl::ffi::textures::*;
use softgl::ffi::textures_3d::*;
use softgl::ffi::types::*;

/// Width and height of the frame: large enough that the big draws go to the thread pool.
pub const SIZE: (i32, i32) = (384, 320);

/// A stack small enough to catch a frame of a few hundred KiB: what a user's worker
/// thread may have.
pub const SMALL_STACK: usize = 256 * 1024;

/// An RGBA test pattern of `n`×`n` texels, different per `seed`.
fn pattern(n: usize, seed: u32) -> Vec<u8> {
    let mut v = Vec::with_capacity(n * n * 4);
    for y in 0..n {
        for x in 0..n {
            let c = ((x / 4 + y / 4) % 2) as u32 * 200;
            v.extend_from_slice(&[
                (c + seed * 37) as u8,
                ((x * 255 / n) as u32 ^ seed) as u8,
                (y * 255 / n) as u8,
                (128 + c / 2) as u8,
            ]);
        }
    }
    v
}

/// A new 2D texture of `n`×`n` with mipmaps, bound to the active unit.
fn texture_2d(n: i32, seed: u32, min: GLenum) -> GLuint {
    let mut id = 0;
    let img = pattern(n as usize, seed);
    // SAFETY: `id` is one GLuint; `img` holds n*n RGBA texels.
    unsafe {
        glGenTextures(1, &mut id);
        glBindTexture(GL_TEXTURE_2D, id);
        glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE as GLint);
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_RGBA as GLint,
            n,
            n,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            img.as_ptr().cast(),
        );
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min as GLint);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as GLint);
    id
}

/// A textured quad from (x0, y0) to (x1, y1) in the current projection.
fn quad(x0: f32, y0: f32, x1: f32, y1: f32, z: f32) {
    glBegin(GL_QUADS);
    glTexCoord2f(0.0, 0.0);
    glVertex3f(x0, y0, z);
    glTexCoord2f(2.0, 0.0);
    glVertex3f(x1, y0, z);
    glTexCoord2f(2.0, 2.0);
    glVertex3f(x1, y1, z);
    glTexCoord2f(0.0, 2.0);
    glVertex3f(x0, y1, z);
    glEnd();
}

/// Draws the frame into a new context and returns its colour buffer, with the first GL
/// error seen (`GL_NO_ERROR` when every call was valid).
pub fn draw_everything() -> (Vec<u8>, GLenum) {
    let (w, h) = SIZE;
    let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, std::ptr::null_mut());
    assert!(!ctx.is_null());
    let mut buf = vec![0u8; (w * h * 4) as usize];
    // SAFETY: `buf` holds w*h RGBA pixels and outlives the context (destroyed below).
    let ok = unsafe { OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, w, h) };
    assert_eq!(ok, GL_TRUE as u8);

    glClearColor(0.1, 0.15, 0.2, 1.0);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, w as f64, 0.0, h as f64, -10.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);

    // Big smooth triangles from arrays (threaded), then many small ones (the split
    // geometry path and the narrow blocks).
    let mut verts = Vec::new();
    let mut colors = Vec::new();
    for i in 0..4000 {
        let (x, y) = ((i * 37 % w) as f32, (i * 53 % h) as f32);
        let s = if i < 8 { 300.0 } else { 3.0 };
        for (dx, dy) in [(0.0, 0.0), (s, 0.5), (0.3, s)] {
            verts.extend_from_slice(&[x + dx, y + dy, -((i % 7) as f32)]);
            colors.extend_from_slice(&[(i % 5) as f32 / 4.0, dx / s, dy / s, 0.8]);
        }
    }
    // The arrays hold 3 floats per vertex and 4 per colour for every vertex drawn, and
    // outlive the draw.
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, verts.as_ptr().cast());
    glColorPointer(4, GL_FLOAT, 0, colors.as_ptr().cast());
    glDrawArrays(GL_TRIANGLES, 0, (verts.len() / 3) as GLsizei);
    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);

    // Blending (over and additive) and the stencil.
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColor4f(1.0, 0.5, 0.0, 0.5);
    glRectf(20.0, 20.0, 200.0, 120.0);
    glBlendFunc(GL_ONE, GL_ONE);
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glColor4f(0.0, 0.2, 0.4, 1.0);
    glRectf(60.0, 0.0, 300.0, 100.0);
    glDisable(GL_STENCIL_TEST);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

    // Textures: the one-unit fast path, a mipmapped unit, two units combined, and the
    // anisotropic, 3D, cube-map and depth-compare samplers.
    glEnable(GL_TEXTURE_2D);
    let t0 = texture_2d(64, 1, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE as GLint);
    quad(200.0, 150.0, 380.0, 310.0, 1.0);
    let t1 = texture_2d(32, 2, GL_LINEAR_MIPMAP_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE as GLint);
    glColor4f(1.0, 1.0, 1.0, 0.9);
    glBegin(GL_TRIANGLES);
    glTexCoord4f(0.0, 0.0, 0.0, 1.0);
    glVertex3f(10.0, 150.0, 2.0);
    glTexCoord4f(8.0, 0.0, 0.0, 2.0);
    glVertex3f(190.0, 160.0, 2.0);
    glTexCoord4f(0.0, 8.0, 0.0, 0.5);
    glVertex3f(30.0, 310.0, 2.0);
    glEnd();
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 8.0);
    quad(120.0, 240.0, 180.0, 250.0, 2.5);
    glActiveTexture(GL_TEXTURE1);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, t0);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE as GLint);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_ADD_SIGNED as GLint);
    glBegin(GL_QUADS);
    for (s, t, x, y) in [(0.0, 0.0, 250.0, 20.0), (1.0, 0.0, 370.0, 20.0)]
        .into_iter()
        .chain([(1.0, 1.0, 370.0, 140.0), (0.0, 1.0, 250.0, 140.0)])
    {
        glMultiTexCoord2f(GL_TEXTURE0, s * 3.0, t * 3.0);
        glMultiTexCoord2f(GL_TEXTURE1, s, t);
        glVertex3f(x, y, 3.0);
    }
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);
    glDisable(GL_TEXTURE_2D);

    let mut ids = [0u32; 3];
    let vol = pattern(8, 3);
    let face = pattern(16, 4);
    let depth: Vec<f32> = (0..16 * 16).map(|i| (i % 16) as f32 / 16.0).collect();
    // SAFETY: `ids` holds 3 names; `vol` holds 8x8x1 RGBA texels, `face` 16x16, `depth`
    // 16x16 floats.
    unsafe {
        glGenTextures(3, ids.as_mut_ptr());
        glBindTexture(GL_TEXTURE_3D, ids[0]);
        glTexImage3D(
            GL_TEXTURE_3D,
            0,
            GL_RGBA as GLint,
            8,
            8,
            1,
            0,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            vol.as_ptr().cast(),
        );
        glBindTexture(GL_TEXTURE_CUBE_MAP, ids[1]);
        for f in 0..6 {
            glTexImage2D(
                GL_TEXTURE_CUBE_MAP_POSITIVE_X + f,
                0,
                GL_RGBA as GLint,
                16,
                16,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                face.as_ptr().cast(),
            );
        }
        glBindTexture(GL_TEXTURE_2D, ids[2]);
        glTexImage2D(
            GL_TEXTURE_2D,
            0,
            GL_DEPTH_COMPONENT as GLint,
            16,
            16,
            0,
            GL_DEPTH_COMPONENT,
            GL_FLOAT,
            depth.as_ptr().cast(),
        );
    }
    for (target, id) in [(GL_TEXTURE_3D, ids[0]), (GL_TEXTURE_CUBE_MAP, ids[1])] {
        glBindTexture(target, id);
        glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR as GLint);
        glEnable(target);
        glBegin(GL_TRIANGLES);
        glTexCoord3f(0.1, 0.2, 0.3);
        glVertex3f(10.0, 10.0, 4.0);
        glTexCoord3f(0.9, -0.4, 0.5);
        glVertex3f(150.0, 30.0, 4.0);
        glTexCoord3f(-0.3, 0.8, 0.7);
        glVertex3f(40.0, 140.0, 4.0);
        glEnd();
        glDisable(target);
    }
    glBindTexture(GL_TEXTURE_2D, ids[2]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as GLint);
    glTexParameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_COMPARE_MODE,
        GL_COMPARE_R_TO_TEXTURE as GLint,
    );
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_TRIANGLES);
    glTexCoord3f(0.0, 0.0, 0.5);
    glVertex3f(300.0, 150.0, 4.5);
    glTexCoord3f(1.0, 0.0, 0.5);
    glVertex3f(380.0, 160.0, 4.5);
    glTexCoord3f(0.0, 1.0, 0.5);
    glVertex3f(310.0, 300.0, 4.5);
    glEnd();
    glDisable(GL_TEXTURE_2D);

    // Lighting and fog on a perspective fan.
    glMatrixMode(GL_PROJECTION);
    glPushMatrix();
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    let pos = [1.0f32, 2.0, 3.0, 0.0];
    let spot = [0.0f32, 0.0, 2.0, 1.0];
    // SAFETY: four floats each.
    unsafe {
        glLightfv(GL_LIGHT0, GL_POSITION, pos.as_ptr());
        glLightfv(GL_LIGHT1, GL_POSITION, spot.as_ptr());
    }
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_EXP2 as GLint);
    glFogf(GL_FOG_DENSITY, 0.2);
    glBegin(GL_TRIANGLE_FAN);
    glNormal3f(0.0, 0.0, 1.0);
    glVertex3f(0.0, 0.0, -3.0);
    for k in 0..=12 {
        let a = k as f32 * 0.5;
        glNormal3f(a.cos() * 0.5, a.sin() * 0.5, 1.0);
        glVertex3f(a.cos() * 2.0, a.sin() * 2.0, -4.0 - a * 0.3);
    }
    glEnd();
    glDisable(GL_LIGHTING);
    glDisable(GL_FOG);
    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glMatrixMode(GL_MODELVIEW);

    // Lines and points: thin, wide, stippled, smooth, textured, attenuated.
    glDisable(GL_DEPTH_TEST);
    for (width, stipple, smooth) in [(1.0, false, false), (4.0, true, false), (2.5, false, true)] {
        glLineWidth(width);
        if stipple {
            glEnable(GL_LINE_STIPPLE);
            glLineStipple(2, 0x0F0F);
        }
        if smooth {
            glEnable(GL_LINE_SMOOTH);
        }
        glBegin(GL_LINE_STRIP);
        glColor4f(1.0, 1.0, 0.0, 1.0);
        glVertex2f(5.0, 5.0 + width * 20.0);
        glColor4f(0.0, 1.0, 1.0, 0.6);
        glVertex2f(370.0, 80.0 + width * 30.0);
        glVertex2f(200.0, 300.0);
        glEnd();
        glDisable(GL_LINE_STIPPLE);
        glDisable(GL_LINE_SMOOTH);
    }
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, t1);
    glLineWidth(3.0);
    glBegin(GL_LINES);
    glTexCoord2f(0.0, 0.0);
    glVertex2f(10.0, 300.0);
    glTexCoord2f(4.0, 1.0);
    glVertex2f(300.0, 200.0);
    glEnd();
    glPointSize(6.0);
    glBegin(GL_POINTS);
    glTexCoord2f(0.5, 0.5);
    glVertex2f(100.0, 100.0);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    for smooth in [false, true] {
        if smooth {
            glEnable(GL_POINT_SMOOTH);
        }
        glPointSize(if smooth { 7.5 } else { 1.0 });
        glBegin(GL_POINTS);
        for i in 0..50 {
            glVertex2f((i * 7) as f32, (i * 5 + if smooth { 40 } else { 0 }) as f32);
        }
        glEnd();
        glDisable(GL_POINT_SMOOTH);
    }
    glPointSize(1.0);
    glLineWidth(1.0);

    // Polygon stipple, outlines and offset.
    let stipple: Vec<u8> = (0..128)
        .map(|i| if i % 8 < 4 { 0xAA } else { 0x55 })
        .collect();
    // SAFETY: a 32x32 stipple is 128 bytes.
    unsafe { glPolygonStipple(stipple.as_ptr()) };
    glEnable(GL_POLYGON_STIPPLE);
    glColor4f(0.9, 0.1, 0.9, 1.0);
    glRectf(150.0, 100.0, 250.0, 200.0);
    glDisable(GL_POLYGON_STIPPLE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEnable(GL_POLYGON_OFFSET_LINE);
    glPolygonOffset(1.0, 1.0);
    glRectf(160.0, 110.0, 240.0, 190.0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_POLYGON_OFFSET_LINE);

    // Pixel rectangles: glDrawPixels (zoomed), glBitmap, glCopyPixels, glReadPixels.
    let img = pattern(16, 5);
    let bits = [0xF0u8; 64];
    let mut back = vec![0u8; 32 * 32 * 4];
    // SAFETY: `img` holds 16x16 RGBA pixels, `bits` a 16x16 bitmap (2 bytes a row padded
    // to the unpack alignment of 4), `back` 32x32 RGBA pixels.
    unsafe {
        glRasterPos2i(320, 10);
        glPixelZoom(2.0, 1.5);
        glDrawPixels(16, 16, GL_RGBA, GL_UNSIGNED_BYTE, img.as_ptr().cast());
        glPixelZoom(1.0, 1.0);
        glRasterPos2i(300, 60);
        glBitmap(16, 16, 0.0, 0.0, 4.0, 0.0, bits.as_ptr());
        glCopyPixels(0, 0, 40, 40, GL_COLOR);
        glReadPixels(
            10,
            10,
            32,
            32,
            GL_RGBA,
            GL_UNSIGNED_BYTE,
            back.as_mut_ptr().cast(),
        );
    }
    assert!(back.iter().any(|&b| b != 0));

    // Accumulation, a display list, feedback and selection.
    glAccum(GL_LOAD, 0.5);
    glAccum(GL_ACCUM, 0.5);
    glAccum(GL_RETURN, 1.0);
    let list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glColor4f(0.2, 0.9, 0.3, 1.0);
    glRectf(5.0, 250.0, 60.0, 315.0);
    glEndList();
    glCallList(list);
    let mut fb = [0f32; 256];
    let mut sel = [0u32; 64];
    // The buffers hold 256 floats and 64 names and outlive the render modes.
    glFeedbackBuffer(256, GL_3D_COLOR, fb.as_mut_ptr());
    glRenderMode(GL_FEEDBACK);
    glCallList(list);
    assert!(glRenderMode(GL_RENDER) > 0);
    glSelectBuffer(64, sel.as_mut_ptr());
    glRenderMode(GL_SELECT);
    glInitNames();
    glPushName(7);
    glCallList(list);
    assert!(glRenderMode(GL_RENDER) > 0);
    glFinish();
    let err = glGetError();
    OSMesaDestroyContext(ctx);
    (buf, err)
}

/// Draws the frame on a thread with a [`SMALL_STACK`] stack and on one with 16 MiB, and
/// checks that both give the same, non-trivial image without a GL error.
#[test]
fn a_256_kib_thread_draws_what_a_16_mib_thread_draws() {
    let run = |stack: usize| {
        std::thread::Builder::new()
            .stack_size(stack)
            .spawn(draw_everything)
            .expect("spawn")
            .join()
            .expect("the drawing thread panicked")
    };
    let (small, err) = run(SMALL_STACK);
    assert_eq!(err, GL_NO_ERROR, "GL error {err:#x}");
    let (large, _) = run(16 << 20);
    assert!(small == large, "the small-stack image differs");
    let distinct: std::collections::HashSet<&[u8]> = small.chunks(4).collect();
    assert!(distinct.len() > 200, "only {} colours", distinct.len());
}
