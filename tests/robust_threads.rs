//! Several contexts rendering on several threads at once give the same images as the
//! same scenes rendered one at a time.

mod robust_common;

use robust_common::*;
use softgl::ffi::arrays::*;
use softgl::ffi::draw::*;
use softgl::ffi::enums::*;
use softgl::ffi::fragment::*;
use softgl::ffi::immediate::*;
use softgl::ffi::matrix::*;
use softgl::ffi::osmesa::*;
use softgl::ffi::state::*;

/// Scene `k`: depth-tested, blended, perspective triangles from a seeded RNG.
fn scene(k: u64) -> Vec<u8> {
    let c = Ctx::new(96, 80);
    let mut r = Rng(0x1234_5678 + k * 7919);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glClearColor(0.1, 0.1, 0.2, 1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 50.0);
    glMatrixMode(GL_MODELVIEW);
    for _ in 0..300 {
        glLoadIdentity();
        glTranslatef(0.0, 0.0, -(r.range(2.0, 10.0) as f32));
        glRotatef(r.range(0.0, 360.0) as f32, 0.3, 1.0, 0.2);
        glBegin(GL_TRIANGLES);
        for _ in 0..3 {
            glColor4f(
                r.unit() as f32,
                r.unit() as f32,
                r.unit() as f32,
                r.unit() as f32,
            );
            glVertex3f(
                r.range(-3.0, 3.0) as f32,
                r.range(-3.0, 3.0) as f32,
                r.range(-3.0, 3.0) as f32,
            );
        }
        glEnd();
    }
    glFinish();
    assert_eq!(take_error(), GL_NO_ERROR);
    c.buf.clone()
}

#[test]
fn threads_render_the_same_images_as_one_at_a_time() {
    let n = 6;
    let sequential: Vec<Vec<u8>> = (0..n).map(scene).collect();
    for round in 0..3 {
        let handles: Vec<_> = (0..n)
            .map(|k| std::thread::spawn(move || scene(k)))
            .collect();
        for (k, h) in handles.into_iter().enumerate() {
            let img = h.join().expect("render thread panicked");
            assert!(
                img == sequential[k],
                "round {round}: scene {k} differs when threaded"
            );
        }
    }
    assert!(
        sequential.windows(2).all(|w| w[0] != w[1]),
        "scenes should differ"
    );
}

/// With threads on, each chunk of a long glBegin(GL_TRIANGLES) batch returns while the
/// pool still draws its last batch of triangles (`draws_detached` counts them), so that the
/// program's next vertices are taken meanwhile. Every way out waits for that batch first:
/// glEnd and glFinish, a GL call made (wrongly) inside glBegin/glEnd, OSMesaMakeCurrent with
/// another buffer, and OSMesaDestroyContext without glEnd. The images are those of one
/// glDrawArrays. (`scripts/sanitize.sh` runs this test under valgrind.)
#[test]
fn chunks_left_drawing_on_the_pool_are_settled_by_every_next_call() {
    let (w, h) = (160, 128);
    let mut r = Rng(0x2545_F491);
    let mut rnd = move || r.unit() as f32;
    // 14000 triangles of about 25 pixels across (every batch is worth the pool): 42000
    // vertices, two whole chunks and a part (the first chunk is the batch storage's first
    // capacity, 16383 vertices).
    let mut pos = Vec::new();
    let mut col = Vec::new();
    for _ in 0..14000 {
        let (cx, cy, cz) = (rnd() * 2.0 - 1.0, rnd() * 2.0 - 1.0, rnd() * 1.8 - 0.9);
        for _ in 0..3 {
            pos.extend([cx + rnd() * 0.6 - 0.3, cy + rnd() * 0.6 - 0.3, cz]);
            col.extend([rnd(), rnd(), rnd()]);
        }
    }
    let setup = || {
        glEnable(GL_DEPTH_TEST);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    };
    let vertices = |r: std::ops::Range<usize>| {
        for (p, k) in pos.chunks(3).zip(col.chunks(3)).take(r.end).skip(r.start) {
            glColor3f(k[0], k[1], k[2]);
            glVertex3f(p[0], p[1], p[2]);
        }
    };
    let threads = softgl::cpu::threads() > 1;
    let detached = || softgl::ffi::current_stats().unwrap().draws_detached;

    let reference = {
        let c = Ctx::new(w, h);
        setup();
        glVertexPointer(3, GL_FLOAT, 0, pos.as_ptr().cast());
        glColorPointer(3, GL_FLOAT, 0, col.as_ptr().cast());
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glDrawArrays(GL_TRIANGLES, 0, 42000);
        glFinish();
        // Like a glBegin/glEnd batch, the draw leaves its last batch on the pool.
        assert_eq!(detached(), threads as u64, "glDrawArrays' last batch");
        c.read()
    };
    assert!(
        reference.chunks(4).filter(|p| p[..3] != [0, 0, 0]).count()
            > w as usize * h as usize * 9 / 10
    );

    // glEnd, then glFinish.
    {
        let c = Ctx::new(w, h);
        setup();
        glBegin(GL_TRIANGLES);
        vertices(0..42000);
        glEnd();
        glFinish();
        let s = softgl::ffi::current_stats().unwrap();
        assert_eq!(s.draws, 3, "two chunks and the rest");
        assert_eq!(
            s.draws_detached,
            if threads { 2 } else { 0 },
            "one per chunk"
        );
        assert!(
            c.read() == reference,
            "chunks left on the pool: image differs"
        );
        assert_eq!(take_error(), GL_NO_ERROR);
    }
    // A call inside glBegin/glEnd right after two chunks (GL_INVALID_OPERATION, nothing
    // else), then the rest of the batch.
    {
        let c = Ctx::new(w, h);
        setup();
        glBegin(GL_TRIANGLES);
        vertices(0..33000);
        glFinish();
        vertices(33000..42000);
        glEnd();
        assert_eq!(take_error(), GL_INVALID_OPERATION);
        glFinish();
        // The two chunks, and the rest, which glGetError drew and left on the pool.
        assert_eq!(detached(), if threads { 3 } else { 0 });
        assert!(
            c.read() == reference,
            "a call inside the batch: image differs"
        );
    }
    // OSMesaMakeCurrent with another buffer size inside the batch, and
    // OSMesaDestroyContext without glEnd: no chunk may outlive its framebuffer.
    {
        let c = Ctx::new(w, h);
        setup();
        glBegin(GL_TRIANGLES);
        vertices(0..17000);
        let mut small = vec![0u8; 64 * 48 * 4];
        // SAFETY: `small` holds 64x48 RGBA pixels and outlives the binding (the context is
        // destroyed at the end of this block, before `small`).
        let ok = unsafe {
            OSMesaMakeCurrent(c.ctx, small.as_mut_ptr().cast(), GL_UNSIGNED_BYTE, 64, 48)
        };
        assert_eq!(ok, GL_TRUE as u8);
        vertices(17000..33000);
        drop(c);
        drop(small);
    }
}

/// With threads on, a glBegin/glEnd strip's last batch of triangles stays drawing on the
/// pool when glEnd returns, through matrix calls; the next strip's draw takes it back,
/// and every other call waits for it first. Textured strips drawn that way, with the texture they sample
/// re-specified and replaced between strips, give the image of the same strips each
/// followed by glFinish (which settles every batch at once), and the strips did stay on
/// the pool (`draws_detached`).
#[test]
fn textured_strips_left_on_the_pool_give_the_images_of_settled_draws() {
    use softgl::ffi::textures::*;
    let (w, h) = (200, 150);
    let texels = |seed: u32| -> Vec<u8> {
        (0..32 * 32 * 4)
            .map(|i: u32| (i.wrapping_mul(37).wrapping_add(seed * 101) >> 2) as u8)
            .collect()
    };
    let (a, b) = (texels(1), texels(2));
    let draw = |finish_each: bool| -> (Vec<u8>, u64, u64) {
        let c = Ctx::new(w, h);
        glClearColor(0.2, 0.1, 0.3, 1.0);
        glClear(GL_COLOR_BUFFER_BIT);
        let mut tex = 0;
        // SAFETY: one name into `tex`; `a` holds 32x32 RGBA bytes.
        unsafe {
            glGenTextures(1, &mut tex);
            glBindTexture(GL_TEXTURE_2D, tex);
            glTexImage2D(
                GL_TEXTURE_2D,
                0,
                GL_RGBA as i32,
                32,
                32,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                a.as_ptr().cast(),
            );
        }
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
        glEnable(GL_TEXTURE_2D);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glColor4f(1.0, 0.9, 0.8, 0.6);
        for round in 0..4 {
            for row in 0..10 {
                let (y0, y1) = (-1.0 + 0.2 * row as f32, -0.8 + 0.2 * row as f32);
                // Matrix calls between strips do not wait for the strip on the pool.
                glPushMatrix();
                glTranslatef(0.01 * row as f32, 0.0, 0.0);
                glBegin(GL_QUAD_STRIP);
                for i in 0..=12 {
                    let x = -1.0 + 2.0 * i as f32 / 12.0;
                    glTexCoord2f(x * (1 + round) as f32, y1);
                    glVertex2f(x, y1);
                    glTexCoord2f(x * (1 + round) as f32, y0);
                    glVertex2f(x, y0);
                }
                glEnd();
                glPopMatrix();
                if finish_each {
                    glFinish();
                }
            }
            // Right after a strip that sampled it: the texels replaced, then the image
            // re-specified at another size.
            // SAFETY: `b` and `a` hold 32x32 RGBA bytes (8x8 read of `b`, 16x16 of `a`).
            unsafe {
                if round % 2 == 0 {
                    glTexSubImage2D(
                        GL_TEXTURE_2D,
                        0,
                        2,
                        2,
                        8,
                        8,
                        GL_RGBA,
                        GL_UNSIGNED_BYTE,
                        b.as_ptr().cast(),
                    );
                } else {
                    glTexImage2D(
                        GL_TEXTURE_2D,
                        0,
                        GL_RGBA as i32,
                        16,
                        16,
                        0,
                        GL_RGBA,
                        GL_UNSIGNED_BYTE,
                        a.as_ptr().cast(),
                    );
                }
            }
        }
        glFinish();
        assert_eq!(take_error(), GL_NO_ERROR);
        let s = softgl::ffi::current_stats().unwrap();
        (c.read(), s.draws_detached, s.draws_adopted)
    };
    // Each strip but a round's first takes over the one before it, through the matrix
    // calls between them (36 of 40).
    check_left_on_pool("textured strips", draw, 100, 30);
}

/// Display-list draws (compiled vertex nodes, MuJoCo's kind) stay on the pool across the
/// state calls between them that keep it there (glMaterial, glEnable/glDisable, blending
/// and masks, glBindTexture and glActiveTexture, glLight, matrices, glGetError and
/// glIsEnabled, glCallList itself and a list's own recorded binding), while the calls
/// that change a texture image
/// (glTexSubImage2D, glDeleteTextures, glTexImage2D) wait for them. The image is the one
/// of the same draws each followed by glFinish, and the draws did take each other over.
#[test]
fn list_draws_across_state_calls_give_the_images_of_settled_draws() {
    use softgl::ffi::lighting::*;
    use softgl::ffi::lists::*;
    use softgl::ffi::textures::*;
    let (w, h) = (200, 150);
    let texels = |seed: u32, n: usize| -> Vec<u8> {
        (0..n * n * 4)
            .map(|i| ((i as u32).wrapping_mul(29).wrapping_add(seed * 77) >> 1) as u8)
            .collect()
    };
    let image = |tex: u32, n: usize, seed: u32| {
        let px = texels(seed, n);
        glBindTexture(GL_TEXTURE_2D, tex);
        // SAFETY: `px` holds n x n RGBA bytes.
        unsafe {
            glTexImage2D(
                GL_TEXTURE_2D,
                0,
                GL_RGBA as i32,
                n as i32,
                n as i32,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                px.as_ptr().cast(),
            );
        }
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR as i32);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR as i32);
    };
    let draw = |finish_each: bool| -> (Vec<u8>, u64, u64) {
        let c = Ctx::new(w, h);
        glClearColor(0.2, 0.1, 0.3, 1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        let mut tex = [0u32; 2];
        // SAFETY: two names into `tex`.
        unsafe { glGenTextures(2, tex.as_mut_ptr()) };
        image(tex[0], 32, 1);
        image(tex[1], 16, 2);
        let base = glGenLists(2);
        // A strip across the view, lit and textured.
        glNewList(base, GL_COMPILE);
        glBegin(GL_TRIANGLE_STRIP);
        for i in 0..=16 {
            let x = -1.0 + 2.0 * i as f32 / 16.0;
            glNormal3f(0.3 * x, 0.2, 1.0);
            glTexCoord2f(2.0 * x, 1.0);
            glVertex3f(x, 0.12, 0.2 * x);
            glTexCoord2f(2.0 * x, 0.0);
            glVertex3f(x, -0.12, -0.2 * x);
        }
        glEnd();
        glEndList();
        // The strip with the second texture bound by the list itself.
        glNewList(base + 1, GL_COMPILE);
        glBindTexture(GL_TEXTURE_2D, tex[1]);
        glCallList(base);
        glEndList();
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glEnable(GL_TEXTURE_2D);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        for round in 0..4 {
            for row in 0..10 {
                let k = (round * 10 + row) as f32;
                let diffuse = [0.3 + 0.05 * row as f32, 0.9 - 0.07 * round as f32, 0.5, 0.7];
                // SAFETY: four floats each.
                unsafe {
                    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse.as_ptr());
                    glLightfv(GL_LIGHT0, GL_POSITION, [0.2 * k, 1.0, 1.0, 0.0].as_ptr());
                }
                if row % 2 == 0 {
                    glEnable(GL_BLEND);
                } else {
                    glDisable(GL_BLEND);
                }
                glColorMask(1, (row % 3 != 1) as u8, 1, 1);
                glDepthMask((row % 4 != 3) as u8);
                glActiveTexture(GL_TEXTURE0);
                glBindTexture(GL_TEXTURE_2D, tex[row % 2]);
                glPushMatrix();
                glTranslatef(0.02 * round as f32, -0.9 + 0.19 * row as f32, 0.0);
                glRotatef(10.0 * k, 0.0, 1.0, 0.0);
                glCallList(base + (row % 3 == 2) as u32);
                // Queries of errors, enables and matrices keep the draw on the pool too.
                assert_eq!(glGetError(), GL_NO_ERROR);
                assert_eq!(glIsEnabled(GL_LIGHTING), GL_TRUE as u8);
                let mut mv = [0f32; 16];
                // SAFETY: room for 16 floats.
                unsafe { softgl::ffi::query::glGetFloatv(GL_MODELVIEW_MATRIX, mv.as_mut_ptr()) };
                assert_eq!(mv[15], 1.0);
                glPopMatrix();
                if finish_each {
                    glFinish();
                }
            }
            // Right after a strip that sampled them: the first texture's texels replaced,
            // the second deleted and made again at another size.
            let sub = texels(3 + round as u32, 8);
            // SAFETY: `sub` holds 8x8 RGBA bytes; one name.
            unsafe {
                glBindTexture(GL_TEXTURE_2D, tex[0]);
                glTexSubImage2D(
                    GL_TEXTURE_2D,
                    0,
                    4,
                    4,
                    8,
                    8,
                    GL_RGBA,
                    GL_UNSIGNED_BYTE,
                    sub.as_ptr().cast(),
                );
                glDeleteTextures(1, &tex[1]);
            }
            image(tex[1], 8 << (round % 2), 5 + round as u32);
        }
        glFinish();
        assert_eq!(take_error(), GL_NO_ERROR);
        let s = softgl::ffi::current_stats().unwrap();
        (c.read(), s.draws_detached, s.draws_adopted)
    };
    // Each strip but a round's first takes over the one before it (36 of 40).
    check_left_on_pool("list draws", draw, 100, 36);
}

/// Draws into a 4x multisample framebuffer object, drawn in one pass into all four sample
/// planes, stay on the pool across state calls as single-sample ones do: the batch holds
/// the sample planes, the next draw takes them over with it, and any call that settles
/// gives them back (here glBlitFramebuffer's resolve, the read and a glClear between
/// rounds). The resolved image is the one of the same draws each followed by glFinish,
/// and the draws did take each other over.
#[test]
fn multisample_draws_left_on_the_pool_give_the_images_of_settled_draws() {
    use softgl::ffi::framebuffers::*;
    use softgl::ffi::glext_enums::*;
    use softgl::ffi::lighting::*;
    use softgl::ffi::query::glGetIntegerv;
    let (w, h) = (160, 120);
    let draw = |finish_each: bool| -> (Vec<u8>, u64, u64) {
        let c = Ctx::new(w, h);
        let (mut fbo, mut rb) = (0u32, [0u32; 2]);
        // SAFETY: one and two names.
        unsafe {
            glGenFramebuffers(1, &mut fbo);
            glGenRenderbuffers(2, rb.as_mut_ptr());
        }
        glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, w, h);
        glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH_COMPONENT24, w, h);
        glBindFramebuffer(GL_FRAMEBUFFER, fbo);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
        assert_eq!(
            glCheckFramebufferStatus(GL_FRAMEBUFFER),
            GL_FRAMEBUFFER_COMPLETE
        );
        let mut samples = 0;
        // SAFETY: one integer.
        unsafe { glGetIntegerv(GL_SAMPLES, &mut samples) };
        assert_eq!(samples, 4);
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        for round in 0..3 {
            glClearColor(0.1 * round as f32, 0.2, 0.3, 1.0);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            for row in 0..12 {
                let k = (round * 12 + row) as f32;
                let diffuse = [0.9 - 0.05 * row as f32, 0.4 + 0.1 * round as f32, 0.6, 0.6];
                // SAFETY: four floats.
                unsafe { glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse.as_ptr()) };
                if row % 3 == 0 {
                    glEnable(GL_BLEND);
                } else {
                    glDisable(GL_BLEND);
                }
                glPushMatrix();
                glTranslatef(0.0, -0.9 + 0.15 * row as f32, 0.0);
                glRotatef(7.0 * k, 0.3, 1.0, 0.0);
                glBegin(GL_TRIANGLE_STRIP);
                for i in 0..=20 {
                    let x = -1.0 + 2.0 * i as f32 / 20.0;
                    glNormal3f(x, 0.3, 0.6);
                    glVertex3f(x, 0.1 + 0.03 * (i % 3) as f32, 0.3 * x);
                    glVertex3f(x + 0.04, -0.1, -0.3 * x);
                }
                glEnd();
                glPopMatrix();
                if finish_each {
                    glFinish();
                }
                if row % 6 == 5 {
                    // Read from the object's working copy, which the batch holds: these
                    // wait for it.
                    let (mut red, mut depth) = (0, 0);
                    // SAFETY: one integer each.
                    unsafe {
                        glGetIntegerv(GL_RED_BITS, &mut red);
                        glGetIntegerv(GL_DEPTH_BITS, &mut depth);
                    }
                    assert_eq!((red, depth), (8, 24));
                }
            }
        }
        // Resolved into the window, then read.
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        glFinish();
        assert_eq!(take_error(), GL_NO_ERROR);
        let s = softgl::ffi::current_stats().unwrap();
        (c.read(), s.draws_detached, s.draws_adopted)
    };
    // Each strip but a round's first and those after the bits queries takes over the one
    // before it (27 of 36).
    check_left_on_pool("multisample draws", draw, 50, 27);
}

/// Runs `draw` with glFinish after every draw (`true`) and without, and checks that both
/// give the same image with more than `colours` distinct colours, that the settled run
/// left nothing for a draw to take over, and that with threads at least `min` draws of
/// the other stayed on the pool and took the one before them over (none without).
fn check_left_on_pool(
    what: &str,
    draw: impl Fn(bool) -> (Vec<u8>, u64, u64),
    colours: usize,
    min: u64,
) {
    let (settled, _, adopted_settled) = draw(true);
    let (kept, detached, adopted) = draw(false);
    let distinct: std::collections::HashSet<&[u8]> = settled.chunks(4).collect();
    assert!(
        distinct.len() > colours,
        "{what}: only {} colours drawn",
        distinct.len()
    );
    assert!(kept == settled, "{what} left on the pool: image differs");
    // glFinish after every draw leaves nothing for the next one to take over.
    assert_eq!(adopted_settled, 0);
    if softgl::cpu::threads() > 1 {
        assert!(
            detached >= min,
            "{what}: only {detached} stayed on the pool"
        );
        assert!(
            adopted >= min,
            "{what}: only {adopted} took the one before over"
        );
    } else {
        assert_eq!((detached, adopted), (0, 0));
    }
}

/// glDrawElements and glDrawArrays draws from buffer objects and client arrays stay on
/// the pool across the state calls between them, like glBegin/glEnd draws: the vertices
/// are fetched before the call returns. The buffer's vertices rewritten
/// (glBufferSubData) and the client array changed in place right after a draw that read
/// them change only the draws after it. The image is the one of the same draws each
/// followed by glFinish, and the draws did take each other over.
#[test]
fn array_draws_left_on_the_pool_give_the_images_of_settled_draws() {
    use softgl::ffi::buffers::*;
    use softgl::ffi::glext_enums::*;
    use softgl::ffi::lighting::*;
    let (w, h) = (180, 140);
    // A strip of 24 quads as indexed triangles: position and normal interleaved.
    let strip = |bend: f32| -> Vec<f32> {
        (0..=24)
            .flat_map(|i| {
                let x = -1.0 + 2.0 * i as f32 / 24.0;
                let z = bend * x * x;
                [[x, 0.1, z, x, 0.2, 1.0], [x, -0.1, -z, -x, 0.2, 1.0]]
            })
            .flatten()
            .collect()
    };
    let idx: Vec<u16> = (0..24u16)
        .flat_map(|q| [2 * q, 2 * q + 1, 2 * q + 2, 2 * q + 2, 2 * q + 1, 2 * q + 3])
        .collect();
    let draw = |finish_each: bool| -> (Vec<u8>, u64, u64) {
        let c = Ctx::new(w, h);
        glClearColor(0.1, 0.1, 0.2, 1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        let mut client = strip(0.5);
        let first = strip(0.2);
        let mut bufs = [0u32; 2];
        // SAFETY: two names; the data pointers hold the sizes given.
        unsafe {
            glGenBuffers(2, bufs.as_mut_ptr());
            glBindBuffer(GL_ARRAY_BUFFER, bufs[0]);
            glBufferData(
                GL_ARRAY_BUFFER,
                (first.len() * 4) as isize,
                first.as_ptr().cast(),
                GL_DYNAMIC_DRAW,
            );
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, bufs[1]);
            glBufferData(
                GL_ELEMENT_ARRAY_BUFFER,
                (idx.len() * 2) as isize,
                idx.as_ptr().cast(),
                GL_STATIC_DRAW,
            );
        }
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_NORMAL_ARRAY);
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        for round in 0..4 {
            for row in 0..10 {
                let k = (round * 10 + row) as f32;
                let diffuse = [0.3 + 0.06 * row as f32, 0.8 - 0.1 * round as f32, 0.5, 1.0];
                // SAFETY: four floats.
                unsafe { glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse.as_ptr()) };
                glPushMatrix();
                glTranslatef(0.03 * round as f32, -0.9 + 0.19 * row as f32, 0.0);
                glRotatef(9.0 * k, 0.0, 1.0, 0.3);
                // SAFETY: the buffer (offsets 0 and 12 of 24-byte vertices, 144 indices)
                // or `client` (50 vertices of 6 floats) hold what the draws read.
                unsafe {
                    if row % 2 == 0 {
                        glBindBuffer(GL_ARRAY_BUFFER, bufs[0]);
                        glVertexPointer(3, GL_FLOAT, 24, std::ptr::null());
                        glNormalPointer(GL_FLOAT, 24, 12 as *const _);
                        glDrawElements(GL_TRIANGLES, 144, GL_UNSIGNED_SHORT, std::ptr::null());
                    } else {
                        glBindBuffer(GL_ARRAY_BUFFER, 0);
                        glVertexPointer(3, GL_FLOAT, 24, client.as_ptr().cast());
                        glNormalPointer(GL_FLOAT, 24, client.as_ptr().add(3).cast());
                        glDrawArrays(GL_TRIANGLE_STRIP, 0, 50);
                    }
                }
                glPopMatrix();
                if finish_each {
                    glFinish();
                }
                // Right after a draw: the client array changed in place (read by the
                // next odd row only), and every third row the buffer's vertices.
                let bend = 0.1 * (k % 7.0);
                client.copy_from_slice(&strip(bend));
                if row % 3 == 0 {
                    let v = strip(-bend);
                    // SAFETY: `v` holds the buffer's 50 vertices.
                    unsafe {
                        glBindBuffer(GL_ARRAY_BUFFER, bufs[0]);
                        glBufferSubData(
                            GL_ARRAY_BUFFER,
                            0,
                            (v.len() * 4) as isize,
                            v.as_ptr().cast(),
                        );
                    }
                }
            }
        }
        glFinish();
        assert_eq!(take_error(), GL_NO_ERROR);
        let s = softgl::ffi::current_stats().unwrap();
        (c.read(), s.draws_detached, s.draws_adopted)
    };
    // The draws after a glBufferSubData (rows 0, 3, 6 and 9 write the buffer) start
    // afresh; each other takes the one before it over (24 of 40).
    check_left_on_pool("array draws", draw, 50, 24);
}

/// Draws with GLSL programs stay on the pool across glUniform and glUseProgram calls: the
/// batch holds its own copy of the uniform values, and the vertex shader ran before the
/// draw returned. A uniform changed right after a draw changes only the draws after it,
/// and a program deleted while current and freed by the glUseProgram that leaves it
/// (right after a draw of it) draws as if nothing was on the pool. The image is the one
/// of the same draws each followed by glFinish, and the draws did take each other over.
#[test]
fn program_draws_across_uniform_calls_give_the_images_of_settled_draws() {
    use softgl::ffi::shaders::*;
    use softgl::ffi::shaders_uniform::*;
    const VS: &str = "uniform vec4 place;\n\
        void main() {\n\
          vec4 v = vec4(gl_Vertex.xy * place.w + place.xy, gl_Vertex.z, 1.0);\n\
          gl_FrontColor = vec4(gl_Vertex.x * 0.5 + 0.5, 0.3, place.z, 1.0);\n\
          gl_Position = gl_ModelViewProjectionMatrix * v;\n\
        }\n";
    const FS: [&str; 2] = [
        "uniform vec4 tint;\nvoid main() { gl_FragColor = gl_Color * tint; }\n",
        "uniform vec4 tint;\nvoid main() { gl_FragColor = gl_Color.bgra + tint * 0.25; }\n",
    ];
    let shader = |kind: u32, src: &str| {
        let s = glCreateShader(kind);
        let c = std::ffi::CString::new(src).unwrap();
        let p = c.as_ptr();
        // SAFETY: one NUL-terminated string.
        unsafe { glShaderSource(s, 1, &p, std::ptr::null()) };
        glCompileShader(s);
        s
    };
    let (w, h) = (150, 120);
    let draw = |finish_each: bool| -> (Vec<u8>, u64, u64) {
        let c = Ctx::new(w, h);
        glClearColor(0.1, 0.1, 0.1, 1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        let progs = FS.map(|fs| {
            let p = glCreateProgram();
            glAttachShader(p, shader(0x8B31, VS));
            glAttachShader(p, shader(0x8B30, fs));
            glLinkProgram(p);
            let (a, b) = (c"place", c"tint");
            // SAFETY: NUL-terminated names.
            let locs = unsafe {
                (
                    glGetUniformLocation(p, a.as_ptr()),
                    glGetUniformLocation(p, b.as_ptr()),
                )
            };
            assert!(locs.0 >= 0 && locs.1 >= 0);
            (p, locs)
        });
        glEnable(GL_DEPTH_TEST);
        for k in 0..36 {
            let (col, row) = ((k % 6) as f32, (k / 6) as f32);
            // Both programs in turn, the second until draw 20: deleted while current
            // after draw 19, it still draws draw 20, and the glUseProgram of draw 21
            // frees it while draw 20 may still be on the pool.
            let second = (k % 2 == 1 && k < 20) || k == 20;
            let (p, (place, tint)) = progs[usize::from(second)];
            glUseProgram(p);
            glUniform4f(place, -0.8 + 0.3 * col, -0.8 + 0.3 * row, 0.1 * row, 0.25);
            glUniform4f(tint, 1.0, 0.5 + 0.08 * col, 0.9 - 0.1 * row, 1.0);
            glBegin(GL_TRIANGLE_STRIP);
            for i in 0..=10 {
                let x = -1.0 + 0.2 * i as f32;
                glVertex3f(x, 0.6 + 0.2 * (i % 2) as f32, 0.1 * x);
                glVertex3f(x, -0.6, -0.1 * x);
            }
            glEnd();
            if finish_each {
                glFinish();
            }
            // Right after the draw: a uniform no later draw of this program keeps.
            glUniform4f(tint, 0.0, 0.0, 0.0, 0.0);
            if k == 19 {
                glDeleteProgram(progs[1].0);
            }
        }
        glFinish();
        assert_eq!(take_error(), GL_NO_ERROR);
        let s = softgl::ffi::current_stats().unwrap();
        assert_eq!(s.program_draws_refused, 0);
        (c.read(), s.draws_detached, s.draws_adopted)
    };
    // Each draw but the first, the one after glDeleteProgram and the one whose
    // glUseProgram frees the deleted program takes the one before it over (33 of 36).
    check_left_on_pool("program draws", draw, 30, 33);
}
