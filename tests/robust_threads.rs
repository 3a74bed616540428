//! Several contexts rendering on several threads at once give the same images as the
//! same scenes rendered one at a time.

mod robust_common;

use robust_common::*;
use softgl::ffi::enums::*;
use softgl::ffi::fragment::*;
use softgl::ffi::immediate::*;
use softgl::ffi::matrix::*;
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
