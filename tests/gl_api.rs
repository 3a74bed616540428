//! GL API semantics through the exported C functions: errors leave state unchanged, the
//! first error is kept until read, OSMesa behaviour, and the work counters.

use softgl::ffi::arrays::*;
use softgl::ffi::buffers::*;
use softgl::ffi::draw::*;
use softgl::ffi::enums::*;
use softgl::ffi::glext_enums::*;
use softgl::ffi::immediate::*;
use softgl::ffi::matrix::*;
use softgl::ffi::osmesa::*;
use softgl::ffi::query::*;
use softgl::ffi::state::*;

/// A current 64x64 RGBA context with depth and stencil; the buffer lives as long as it.
struct Ctx {
    ctx: OSMesaContext,
    buf: Vec<u8>,
}

impl Ctx {
    fn new(w: i32, h: i32) -> Ctx {
        let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, std::ptr::null_mut());
        assert!(!ctx.is_null());
        let mut buf = vec![0xAAu8; (w * h * 4) as usize];
        // SAFETY: the buffer holds w*h RGBA pixels and outlives the binding (Drop unbinds).
        let ok = unsafe { OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, w, h) };
        assert_eq!(ok, GL_TRUE as u8);
        Ctx { ctx, buf }
    }
}

impl Drop for Ctx {
    fn drop(&mut self) {
        OSMesaDestroyContext(self.ctx);
    }
}

fn viewport() -> [i32; 4] {
    let mut v = [0i32; 4];
    // SAFETY: GL_VIEWPORT has 4 components.
    unsafe { glGetIntegerv(GL_VIEWPORT, v.as_mut_ptr()) };
    v
}

#[test]
fn errors_leave_state_unchanged() {
    let _c = Ctx::new(64, 64);
    assert_eq!(glGetError(), GL_NO_ERROR);

    glEnable(0x1234);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    assert_eq!(glGetError(), GL_NO_ERROR, "an error is reported once");

    glViewport(1, 2, 30, 40);
    glViewport(0, 0, -1, 5);
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    assert_eq!(viewport(), [1, 2, 30, 40]);

    glEnd();
    assert_eq!(glGetError(), GL_INVALID_OPERATION);

    let mut depth = 0;
    // SAFETY: one component.
    unsafe { glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &mut depth) };
    glPopMatrix();
    assert_eq!(glGetError(), GL_STACK_UNDERFLOW);
    let mut after = 0;
    // SAFETY: one component.
    unsafe { glGetIntegerv(GL_MODELVIEW_STACK_DEPTH, &mut after) };
    assert_eq!((depth, after), (1, 1));

    let mut buf = 0u32;
    // SAFETY: room for one name; data pointers valid for the sizes given.
    unsafe {
        glGenBuffers(1, &mut buf);
        glBindBuffer(GL_ARRAY_BUFFER, buf);
        glBufferData(GL_ARRAY_BUFFER, 16, std::ptr::null(), GL_STATIC_DRAW);
        glBufferData(GL_ARRAY_BUFFER, -1, std::ptr::null(), GL_STATIC_DRAW);
    }
    assert_eq!(glGetError(), GL_INVALID_VALUE);
    let mut size = 0;
    // SAFETY: one component.
    unsafe { glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &mut size) };
    assert_eq!(size, 16, "failed glBufferData kept the old store");

    glDrawArrays(0x1234, 0, 3);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
}

#[test]
fn first_error_is_kept_until_read() {
    let _c = Ctx::new(8, 8);
    glEnable(0x1234);
    glViewport(0, 0, -1, -1);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
    assert_eq!(glGetError(), GL_NO_ERROR);
}

#[test]
fn calls_not_allowed_inside_begin_end() {
    let _c = Ctx::new(8, 8);
    glBegin(GL_TRIANGLES);
    glViewport(0, 0, 4, 4);
    glBegin(GL_TRIANGLES);
    glEnd();
    assert_eq!(glGetError(), GL_INVALID_OPERATION);
    assert_eq!(viewport(), [0, 0, 8, 8]);
    glBegin(0x77);
    assert_eq!(glGetError(), GL_INVALID_ENUM);
}

#[test]
fn matrix_stack_overflow_at_mesa_depth() {
    let _c = Ctx::new(8, 8);
    let mut max = 0;
    // SAFETY: one component.
    unsafe { glGetIntegerv(GL_MAX_MODELVIEW_STACK_DEPTH, &mut max) };
    assert_eq!(max, 32);
    for _ in 0..31 {
        glPushMatrix();
    }
    assert_eq!(glGetError(), GL_NO_ERROR);
    glPushMatrix();
    assert_eq!(glGetError(), GL_STACK_OVERFLOW);
}

#[test]
fn user_buffer_written_only_on_flush_and_bottom_up() {
    let c = Ctx::new(4, 4);
    glClearColor(1.0, 0.0, 0.0, 1.0);
    glClear(GL_COLOR_BUFFER_BIT);
    assert!(
        c.buf.iter().all(|&b| b == 0xAA),
        "glClear alone does not write the user buffer"
    );
    glFinish();
    assert_eq!(&c.buf[..4], &[255, 0, 0, 255]);
    // Bottom-left triangle only: the first row of the buffer (bottom) gets it.
    glClearColor(0.0, 0.0, 0.0, 0.0);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 4.0, 0.0, 4.0, -1.0, 1.0);
    glBegin(GL_TRIANGLES);
    glColor3f(0.0, 1.0, 0.0);
    glVertex2f(0.0, 0.0);
    glVertex2f(4.0, 0.0);
    glVertex2f(0.0, 1.0);
    glEnd();
    glFinish();
    assert_eq!(&c.buf[..4], &[0, 255, 0, 255], "row 0 is the bottom row");
    assert_eq!(
        &c.buf[12 * 4..12 * 4 + 4],
        &[0, 0, 0, 0],
        "row 3 is the top row"
    );
}

#[test]
fn get_proc_address_finds_exports_only() {
    let f = |n: &str| {
        let s = std::ffi::CString::new(n).unwrap();
        // SAFETY: NUL-terminated name.
        unsafe { OSMesaGetProcAddress(s.as_ptr()) }
    };
    assert!(f("glBegin").is_some());
    assert!(f("glBufferData").is_some());
    assert!(f("OSMesaMakeCurrent").is_some());
    assert!(f("glNoSuchFunction").is_none());
    let p = f("glGetError").unwrap();
    // SAFETY: glGetError's real signature.
    let get_error: extern "C" fn() -> u32 = unsafe { std::mem::transmute(p) };
    assert_eq!(get_error(), GL_NO_ERROR);
}

#[test]
fn make_current_rejects_bad_arguments() {
    let ctx = OSMesaCreateContext(OSMESA_RGBA, std::ptr::null_mut());
    let mut buf = vec![0u8; 16];
    // SAFETY: the calls are expected to fail before touching the buffer.
    unsafe {
        assert_eq!(
            OSMesaMakeCurrent(ctx, std::ptr::null_mut(), GL_UNSIGNED_BYTE, 2, 2),
            0
        );
        assert_eq!(
            OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 0, 2),
            0
        );
        assert_eq!(
            OSMesaMakeCurrent(ctx, buf.as_mut_ptr().cast(), GL_FLOAT + 7, 2, 2),
            0
        );
        assert_eq!(
            OSMesaMakeCurrent(std::ptr::null_mut(), std::ptr::null_mut(), 0, 0, 0),
            1
        );
    }
    OSMesaDestroyContext(ctx);
    OSMesaDestroyContext(ctx); // a second destroy of the same handle is ignored
    assert!(OSMesaGetCurrentContext().is_null());
}

fn tri(z: f32) {
    glBegin(GL_TRIANGLES);
    glVertex3f(-1.0, -1.0, z);
    glVertex3f(1.0, -1.0, z);
    glVertex3f(0.0, 1.0, z);
    glEnd();
}

#[test]
fn counters_show_skipped_work() {
    let _c = Ctx::new(32, 32);
    let s0 = softgl::ffi::current_stats().unwrap();
    tri(0.0);
    let s1 = softgl::ffi::current_stats().unwrap();
    assert!(s1.fragments > 0 && s1.color_writes > 0);
    assert_eq!(s1.depth_reads, s0.depth_reads, "depth off: no depth read");
    assert_eq!(s1.color_reads, 0, "no blending: no colour read");

    glEnable(GL_DEPTH_TEST);
    tri(0.0);
    let s2 = softgl::ffi::current_stats().unwrap();
    assert_eq!(s2.depth_reads - s1.depth_reads, s2.fragments - s1.fragments);

    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    tri(0.0);
    let s3 = softgl::ffi::current_stats().unwrap();
    assert_eq!(s3.tris_culled, s2.tris_culled + 1);
    assert_eq!(
        s3.tris_rasterized, s2.tris_rasterized,
        "a culled triangle is not rasterized"
    );
    assert_eq!(s3.fragments, s2.fragments);

    glDisable(GL_CULL_FACE);
    glTranslatef(10.0, 0.0, 0.0);
    tri(0.0);
    let s4 = softgl::ffi::current_stats().unwrap();
    assert_eq!(
        s4.tris_clip_rejected,
        s3.tris_clip_rejected + 1,
        "off-screen: rejected before setup"
    );
    assert_eq!(s4.fragments, s3.fragments);
}

/// A quad with the given corner colours (counter-clockwise from the bottom left).
fn quad(corners: [[f32; 2]; 4], colors: [[f32; 3]; 4]) {
    glBegin(GL_QUADS);
    for (p, c) in corners.iter().zip(&colors) {
        glColor3f(c[0], c[1], c[2]);
        glVertex2f(p[0], p[1]);
    }
    glEnd();
}

#[test]
fn rectangles_of_two_triangles_are_drawn_as_one() {
    let _c = Ctx::new(32, 32);
    let rect = [[-0.61, -0.47], [0.53, -0.47], [0.53, 0.39], [-0.61, 0.39]];
    let s0 = softgl::ffi::current_stats().unwrap();
    quad(rect, [[0.2, 0.5, 0.9]; 4]);
    let s1 = softgl::ffi::current_stats().unwrap();
    assert_eq!(s1.tris_rasterized - s0.tris_rasterized, 2);
    assert_eq!(
        s1.tris_paired - s0.tris_paired,
        1,
        "one colour: same planes"
    );
    // The rectangle's pixel count: x from -0.61 to 0.53 and y from -0.47 to 0.39 in
    // NDC on 32 px are window x 6.24..24.48 and y 8.48..22.24, so pixel centres 6.5..23.5
    // (18 columns) and 8.5..21.5 (14 rows).
    assert_eq!(s1.fragments - s0.fragments, 18 * 14);
    // Corner colours that are not affine give the two triangles different planes.
    quad(
        rect,
        [
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [1.0, 1.0, 1.0],
            [0.0, 0.0, 1.0],
        ],
    );
    let s2 = softgl::ffi::current_stats().unwrap();
    assert_eq!(s2.tris_rasterized - s1.tris_rasterized, 2);
    assert_eq!(
        s2.tris_paired, s1.tris_paired,
        "different planes: drawn apart"
    );
    assert_eq!(s2.fragments - s1.fragments, 18 * 14);
    // A quad that is not axis-aligned is never paired.
    quad(
        [[-0.6, -0.5], [0.5, -0.4], [0.5, 0.4], [-0.6, 0.4]],
        [[0.2, 0.5, 0.9]; 4],
    );
    let s3 = softgl::ffi::current_stats().unwrap();
    assert_eq!(s3.tris_rasterized - s2.tris_rasterized, 2);
    assert_eq!(s3.tris_paired, s2.tris_paired, "not a rectangle");
}

#[test]
fn counters_show_skipped_fragment_work() {
    use softgl::ffi::fragment::*;
    let _c = Ctx::new(32, 32);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    let s0 = softgl::ffi::current_stats().unwrap();
    tri(0.0);
    let s1 = softgl::ffi::current_stats().unwrap();
    assert_eq!(
        s1.stencil_reads, s0.stencil_reads,
        "stencil test off: no stencil read"
    );
    assert!(
        s1.color_reads > s0.color_reads,
        "blending reads the destination"
    );

    glDisable(GL_BLEND);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    tri(0.0);
    let s2 = softgl::ffi::current_stats().unwrap();
    assert_eq!(
        s2.stencil_reads - s1.stencil_reads,
        s2.fragments - s1.fragments,
        "stencil test on: one read per fragment"
    );
    assert_eq!(
        s2.color_reads, s1.color_reads,
        "no blending: no colour read"
    );
    glDisable(GL_STENCIL_TEST);

    // An all-false colour mask with no depth or stencil writes: nothing is rasterized.
    glColorMask(0, 0, 0, 0);
    tri(0.0);
    let s3 = softgl::ffi::current_stats().unwrap();
    assert_eq!(
        s3.fragments, s2.fragments,
        "nothing can change: no fragments"
    );
    assert_eq!(s3.color_writes, s2.color_writes);
    // With the depth test writing depth, fragments run but no colour is written.
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    tri(0.0);
    let s4 = softgl::ffi::current_stats().unwrap();
    assert!(s4.fragments > s3.fragments);
    assert_eq!(
        s4.color_writes, s3.color_writes,
        "all-false colour mask: no colour written"
    );
}

/// A long glBegin(GL_TRIANGLES) batch is drawn in chunks while it is specified the first
/// time, then whole (its storage now holds it); both give exactly the image and counters
/// of one glDrawArrays of the same vertices. GL_QUADS batches are never drawn in chunks.
/// Clears colour and depth, runs `draw` and glFinish: the image and the counters before
/// and after.
fn counted_frame(
    c: &Ctx,
    draw: &dyn Fn(),
) -> (Vec<u8>, softgl::stats::Stats, softgl::stats::Stats) {
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    let s0 = softgl::ffi::current_stats().unwrap();
    draw();
    glFinish();
    let s1 = softgl::ffi::current_stats().unwrap();
    (c.buf.clone(), s0, s1)
}

#[test]
fn indexed_vertices_are_transformed_once_and_a_jump_starts_no_run() {
    let (w, h) = (64, 64);
    let c = Ctx::new(w, h);
    // A 24 x 24 grid of vertices (1058 triangles) in row order, like a height field.
    const G: usize = 24;
    let mut pos = Vec::new();
    let mut col = Vec::new();
    for j in 0..G {
        for i in 0..G {
            let (x, y) = (i as f32 / 11.5 - 1.0, j as f32 / 11.5 - 1.0);
            pos.extend([x * 0.97 + y * 0.05, y, 0.3 * (x * 3.0).sin() * y]);
            col.extend([i as f32 / 23.0, j as f32 / 23.0, ((i ^ j) & 7) as f32 / 7.0]);
        }
    }
    let mut idx: Vec<u32> = Vec::new();
    for j in 0..G - 1 {
        for i in 0..G - 1 {
            let a = (j * G + i) as u32;
            let (b, c, d) = (a + 1, a + G as u32, a + G as u32 + 1);
            idx.extend([a, c, b, b, c, d]);
        }
    }
    glEnable(GL_DEPTH_TEST);
    glVertexPointer(3, GL_FLOAT, 0, pos.as_ptr().cast());
    glColorPointer(3, GL_FLOAT, 0, col.as_ptr().cast());
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    let frame = |draw: &dyn Fn()| {
        let (img, s0, s1) = counted_frame(&c, draw);
        let offloaded = s1.draws_offloaded - s0.draws_offloaded;
        (
            img,
            s1.vertices - s0.vertices,
            s1.fragments - s0.fragments,
            offloaded,
        )
    };
    let indexed = frame(&|| {
        glDrawElements(
            GL_TRIANGLES,
            idx.len() as i32,
            GL_UNSIGNED_INT,
            idx.as_ptr().cast(),
        )
    });
    if indexed.3 == 0 {
        assert_eq!(
            indexed.1,
            (G * G) as u64,
            "each grid vertex transformed once"
        );
    } else {
        // A pool thread set up the second half of the rest of the draw
        // (`raster::batch::side`) with a cache of its own: the row the halves share is
        // transformed on both threads, and the first half's last run (at most 32
        // vertices) may reach into the second's.
        assert!(
            ((G * G) as u64..=(G * G + G + 32) as u64).contains(&indexed.1),
            "each grid vertex transformed once per half: {}",
            indexed.1
        );
    }
    assert!(indexed.2 > 2000, "the grid covers the frame: {}", indexed.2);
    // The same triangles, every vertex of them stored in order.
    let expand = |attr: &[f32]| -> Vec<f32> {
        idx.iter()
            .flat_map(|&i| attr[3 * i as usize..3 * i as usize + 3].to_vec())
            .collect()
    };
    let (flat_pos, flat_col) = (expand(&pos), expand(&col));
    let arrays = frame(&|| {
        glVertexPointer(3, GL_FLOAT, 0, flat_pos.as_ptr().cast());
        glColorPointer(3, GL_FLOAT, 0, flat_col.as_ptr().cast());
        glDrawArrays(GL_TRIANGLES, 0, idx.len() as i32);
    });
    assert_eq!(arrays.1, idx.len() as u64);
    assert_eq!(arrays.2, indexed.2);
    assert!(arrays.0 == indexed.0, "indexed and expanded draws differ");

    // Two triangles 200 vertices apart: the second costs its own three vertices, not a
    // second run ahead (the first may start one, of at most 32).
    glVertexPointer(3, GL_FLOAT, 0, pos.as_ptr().cast());
    glColorPointer(3, GL_FLOAT, 0, col.as_ptr().cast());
    let two = [0u32, 1, 24, 300, 301, 324];
    let jump = frame(&|| glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_INT, two.as_ptr().cast()));
    assert!(
        (6..=3 + 32).contains(&jump.1),
        "vertices transformed: {}",
        jump.1
    );
    assert_eq!(glGetError(), GL_NO_ERROR);
}

#[test]
fn long_triangle_batches_stream_in_chunks_with_the_same_pixels() {
    let (w, h) = (96, 80);
    let c = Ctx::new(w, h);
    let mut seed = 0x9E37_79B9u32;
    let mut rnd = move || {
        seed ^= seed << 13;
        seed ^= seed >> 17;
        seed ^= seed << 5;
        (seed >> 8) as f32 / (1u32 << 24) as f32
    };
    // 20000 small triangles, some crossing the frame's edges (clipped), overlapping in
    // depth: 60000 vertices, several times the first chunk.
    let mut pos = Vec::new();
    let mut col = Vec::new();
    for _ in 0..20000 {
        let (cx, cy, cz) = (rnd() * 2.4 - 1.2, rnd() * 2.4 - 1.2, rnd() * 1.8 - 0.9);
        for _ in 0..3 {
            pos.extend([cx + rnd() * 0.2 - 0.1, cy + rnd() * 0.2 - 0.1, cz]);
            col.extend([rnd(), rnd(), rnd()]);
        }
    }
    glEnable(GL_DEPTH_TEST);
    let frame = |draw: &dyn Fn()| {
        let (img, s0, s1) = counted_frame(&c, draw);
        (
            img,
            s1.draws - s0.draws,
            s1.tris_rasterized - s0.tris_rasterized,
            s1.fragments - s0.fragments,
            s1.depth_failed - s0.depth_failed,
        )
    };
    let immediate = || {
        glBegin(GL_TRIANGLES);
        for (p, k) in pos.chunks(3).zip(col.chunks(3)) {
            glColor3f(k[0], k[1], k[2]);
            glVertex3f(p[0], p[1], p[2]);
        }
        glEnd();
    };
    let first = frame(&immediate);
    let second = frame(&immediate);
    let arrays = frame(&|| {
        glVertexPointer(3, GL_FLOAT, 0, pos.as_ptr().cast());
        glColorPointer(3, GL_FLOAT, 0, col.as_ptr().cast());
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glDrawArrays(GL_TRIANGLES, 0, 60000);
        glDisableClientState(GL_VERTEX_ARRAY);
        glDisableClientState(GL_COLOR_ARRAY);
    });
    assert!(
        first.1 >= 3,
        "the first batch is drawn in chunks: {}",
        first.1
    );
    assert_eq!(second.1, 1, "the second batch is drawn whole");
    assert_eq!(arrays.1, 1);
    assert!(arrays.2 > 10000 && arrays.3 > 50000 && arrays.4 > 1000);
    for (name, f) in [("first", &first), ("second", &second)] {
        assert_eq!(
            (f.2, f.3, f.4),
            (arrays.2, arrays.3, arrays.4),
            "{name}: counters"
        );
        assert!(f.0 == arrays.0, "{name}: image differs from glDrawArrays");
    }
    assert_eq!(glGetError(), GL_NO_ERROR);

    // A long GL_QUADS batch stays one draw (its clip decision covers the whole draw).
    let quads = frame(&|| {
        glBegin(GL_QUADS);
        for p in pos.chunks(3).take(40000) {
            glVertex3f(p[0], p[1], p[2]);
        }
        glEnd();
    });
    assert_eq!(quads.1, 1);
}

/// The context is GL 2.1 compatibility: GL_VERSION and GL_SHADING_LANGUAGE_VERSION say so,
/// OSMesaCreateContextAttribs gives compatibility up to 2.1 and NULL above it or for a
/// core profile (GL 3.x is issue 44's).
#[test]
fn context_is_gl21_compatibility() {
    let attribs = |profile: i32, major: i32, minor: i32| {
        let list = [
            OSMESA_PROFILE,
            profile,
            OSMESA_CONTEXT_MAJOR_VERSION,
            major,
            OSMESA_CONTEXT_MINOR_VERSION,
            minor,
            0,
        ];
        // SAFETY: a zero-terminated attribute list.
        unsafe { OSMesaCreateContextAttribs(list.as_ptr(), std::ptr::null_mut()) }
    };
    for (major, minor) in [(1, 0), (1, 5), (2, 0), (2, 1)] {
        let c = attribs(OSMESA_COMPAT_PROFILE, major, minor);
        assert!(!c.is_null(), "compatibility {major}.{minor}");
        OSMesaDestroyContext(c);
    }
    for (profile, major, minor) in [
        (OSMESA_COMPAT_PROFILE, 2, 2),
        (OSMESA_COMPAT_PROFILE, 3, 0),
        (OSMESA_CORE_PROFILE, 3, 2),
        (OSMESA_CORE_PROFILE, 2, 1),
    ] {
        assert!(
            attribs(profile, major, minor).is_null(),
            "profile {profile:#x} {major}.{minor}"
        );
    }
    let _c = Ctx::new(4, 4);
    let string = |name| {
        let p = glGetString(name);
        assert!(!p.is_null());
        // SAFETY: glGetString returns a NUL-terminated static string.
        unsafe { std::ffi::CStr::from_ptr(p.cast()) }
            .to_str()
            .unwrap()
            .to_owned()
    };
    assert!(string(GL_VERSION).starts_with("2.1 softgl "));
    assert_eq!(string(GL_SHADING_LANGUAGE_VERSION), "1.20");
    assert_eq!(glGetError(), GL_NO_ERROR);
}
