//! Draws with a current program (issue 43): a fragment shader colours triangles, lines
//! and points through the engine, a vertex shader replaces the vertex stage; what the
//! engine does not run (`noperspective` inputs, smooth lines, varyings that leave no
//! room for back colours or a clip vertex) draws nothing and is counted in `program_draws_refused`, and fixed function comes
//! back with glUseProgram(0). Hostile coordinates (infinite, NaN, huge) reach the
//! samplers and derivatives without harm.

use softgl::ffi::enums::*;
use softgl::ffi::immediate::*;
use softgl::ffi::osmesa::*;
use softgl::ffi::shaders::*;
use softgl::ffi::shaders_uniform::*;
use softgl::ffi::state::*;
use softgl::ffi::vertex_attrib::*;
use std::ffi::CString;

const W: usize = 16;
const GL_FRAGMENT_SHADER: u32 = 0x8B30;
const GL_VERTEX_SHADER: u32 = 0x8B31;
const GL_LINK_STATUS: u32 = 0x8B82;
const GL_VERTEX_PROGRAM_TWO_SIDE: u32 = 0x8643;

/// A current 16x16 RGBA context cleared to black.
struct Ctx {
    ctx: OSMesaContext,
    buf: Vec<u8>,
}

impl Ctx {
    fn new() -> Ctx {
        let ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, std::ptr::null_mut());
        assert!(!ctx.is_null());
        let mut buf = vec![0u8; W * W * 4];
        // SAFETY: the buffer holds W*W RGBA pixels and outlives the binding.
        let ok = unsafe {
            OSMesaMakeCurrent(
                ctx,
                buf.as_mut_ptr().cast(),
                GL_UNSIGNED_BYTE,
                W as i32,
                W as i32,
            )
        };
        assert_eq!(ok, GL_TRUE as u8);
        Ctx { ctx, buf }
    }

    fn pixel(&self, x: usize, y: usize) -> [u8; 4] {
        glFinish();
        let i = 4 * (y * W + x);
        [
            self.buf[i],
            self.buf[i + 1],
            self.buf[i + 2],
            self.buf[i + 3],
        ]
    }

    fn clear(&self) {
        glClearColor(0.0, 0.0, 0.0, 0.0);
        glClear(GL_COLOR_BUFFER_BIT);
    }
}

impl Drop for Ctx {
    fn drop(&mut self) {
        OSMesaDestroyContext(self.ctx);
    }
}

fn shader(kind: u32, src: &str) -> u32 {
    let s = glCreateShader(kind);
    let c = CString::new(src).unwrap();
    let p = c.as_ptr();
    // SAFETY: one NUL-terminated string.
    unsafe { glShaderSource(s, 1, &p, std::ptr::null()) };
    glCompileShader(s);
    s
}

fn program(vs: Option<&str>, fs: &str) -> u32 {
    let p = glCreateProgram();
    if let Some(v) = vs {
        glAttachShader(p, shader(GL_VERTEX_SHADER, v));
    }
    glAttachShader(p, shader(GL_FRAGMENT_SHADER, fs));
    glLinkProgram(p);
    let mut ok = 0;
    // SAFETY: one GLint.
    unsafe { glGetProgramiv(p, GL_LINK_STATUS, &mut ok) };
    assert_eq!(ok, 1, "link");
    p
}

fn stats() -> softgl::stats::Stats {
    softgl::ffi::current_stats().unwrap()
}

#[test]
fn fragment_programs_draw_and_refusals_draw_nothing() {
    let c = Ctx::new();
    c.clear();
    let p = program(
        None,
        "uniform vec4 k; void main() { gl_FragColor = k * gl_Color; }",
    );
    glUseProgram(p);
    let name = CString::new("k").unwrap();
    // SAFETY: a NUL-terminated name.
    let k = unsafe { glGetUniformLocation(p, name.as_ptr()) };
    assert!(k >= 0);
    glColor4f(1.0, 1.0, 1.0, 1.0);
    glUniform4f(k, 1.0, 0.0, 0.0, 1.0);
    let s0 = stats();
    glRectf(-1.0, -1.0, 0.0, 1.0);
    glUniform4f(k, 0.0, 1.0, 0.0, 1.0);
    glRectf(0.0, -1.0, 1.0, 1.0);
    let s1 = stats();
    assert_eq!(s1.program_draws - s0.program_draws, 2);
    assert_eq!(c.pixel(2, 5), [255, 0, 0, 255], "first uniform value");
    assert_eq!(
        c.pixel(13, 5),
        [0, 255, 0, 255],
        "the glUniform between the draws"
    );

    // A line with the program draws with it, and a smooth one (GL_LINE_SMOOTH) too, its
    // alpha times the coverage.
    c.clear();
    glBegin(GL_LINES);
    glVertex2f(-1.0, 0.01);
    glVertex2f(1.0, 0.01);
    glEnd();
    let s1b = stats();
    assert_eq!(s1b.program_draws - s1.program_draws, 1);
    assert_eq!(s1b.program_draws_refused, s1.program_draws_refused);
    assert!(
        (0..W).all(|x| c.pixel(x, 8) == [0, 255, 0, 255]),
        "the line in the uniform's colour"
    );
    c.clear();
    glEnable(0x0B20);
    glBegin(GL_LINES);
    glVertex2f(-1.0, 0.01);
    glVertex2f(1.0, 0.01);
    glEnd();
    glDisable(0x0B20);
    let s2 = stats();
    assert_eq!(s2.program_draws - s1b.program_draws, 1);
    assert_eq!(s2.program_draws_refused, s1b.program_draws_refused);
    // The line runs at window y = 8.08: row 8's centre is 0.42 pixel away, so a
    // one-pixel smooth line covers 1 - 0.42 of it there (alpha 148 of 255).
    for x in 4..12 {
        let p = c.pixel(x, 8);
        assert_eq!(p[..3], [0, 255, 0], "x {x}: the uniform's colour");
        assert!(
            (144..=152).contains(&p[3]),
            "x {x}: alpha {} is the coverage",
            p[3]
        );
    }

    // A vertex shader draws: its position, its colour.
    let pv = program(
        Some("void main() { gl_Position = gl_Vertex; gl_FrontColor = gl_Color.bgra; }"),
        "void main() { gl_FragColor = gl_Color; }",
    );
    glUseProgram(pv);
    glColor4f(1.0, 0.0, 0.0, 1.0);
    glRectf(-1.0, -1.0, 1.0, 1.0);
    let s2b = stats();
    assert_eq!(s2b.program_draws - s2.program_draws, 1);
    assert_eq!(c.pixel(8, 8), [0, 0, 255, 255]);

    // With a user clip plane x >= 0: a shader that does not write gl_ClipVertex is
    // measured at gl_Position with the eye-space plane (as Mesa does), so the right half
    // is drawn.
    c.clear();
    let plane = [1.0f64, 0.0, 0.0, 0.0];
    // SAFETY: four doubles.
    unsafe { softgl::ffi::texgen::glClipPlane(0x3000, plane.as_ptr()) };
    glEnable(0x3000);
    glRectf(-1.0, -1.0, 1.0, 1.0);
    glDisable(0x3000);
    let s3 = stats();
    assert_eq!(s3.program_draws - s2b.program_draws, 1);
    assert_eq!(s3.program_draws_refused, s2b.program_draws_refused);
    assert_eq!(c.pixel(12, 8), [0, 0, 255, 255]);
    assert_eq!(c.pixel(3, 8), [0; 4]);

    // A lookup with explicit gradients does not lower yet: nothing drawn, counted.
    c.clear();
    let pt = program(
        None,
        "#version 130
         uniform sampler2D t; out vec4 o;
         void main() { o = textureGrad(t, gl_TexCoord[0].xy * 2.0, vec2(0.1), vec2(0.0)); }",
    );
    glUseProgram(pt);
    glRectf(-1.0, -1.0, 1.0, 1.0);
    let s3b = stats();
    assert_eq!(s3b.program_draws_refused - s3.program_draws_refused, 1);
    assert_eq!(c.pixel(8, 8), [0; 4]);

    // Nor does a `noperspective` input (it would need screen-linear planes).
    let pf = program(
        Some(
            "#version 130
             noperspective out vec4 f;
             void main() { gl_Position = gl_Vertex; f = gl_Color; }",
        ),
        "#version 130
         noperspective in vec4 f;
         void main() { gl_FragColor = f; }",
    );
    glUseProgram(pf);
    glRectf(-1.0, -1.0, 1.0, 1.0);
    let s4 = stats();
    assert_eq!(s4.program_draws_refused - s3b.program_draws_refused, 1);
    assert_eq!(c.pixel(8, 8), [0; 4]);

    // At a varying, or at computed coordinates, it draws; unit 0 has no texture, so the
    // lookups give (0, 0, 0, 1).
    let pu = program(
        None,
        "uniform sampler2D t;
         void main() { gl_FragColor = texture2D(t, gl_TexCoord[0].xy) * 0.5
             + texture2D(t, gl_TexCoord[0].yx * 2.0) * 0.5 + vec4(0.0, 1.0, 0.0, 0.0); }",
    );
    glUseProgram(pu);
    glRectf(-1.0, -1.0, 1.0, 1.0);
    let s5 = stats();
    assert_eq!(s5.program_draws_refused, s4.program_draws_refused);
    assert_eq!(s5.program_draws - s4.program_draws, 1);
    assert_eq!(c.pixel(8, 8), [0, 255, 0, 255]);

    // glUseProgram(0): fixed function again.
    glUseProgram(0);
    glColor4f(0.0, 0.0, 1.0, 1.0);
    glRectf(-1.0, -1.0, 1.0, 1.0);
    assert_eq!(c.pixel(8, 8), [0, 0, 255, 255]);
    assert_eq!(stats().program_draws, s5.program_draws);
}

#[test]
fn discard_kills_and_frag_coord_is_the_window_position() {
    let c = Ctx::new();
    c.clear();
    let p = program(
        None,
        "void main() { if (gl_FragCoord.x < 4.0) discard; \
         gl_FragColor = vec4(gl_FragCoord.x / 64.0, gl_FragCoord.y / 64.0, 0.0, 1.0); }",
    );
    glUseProgram(p);
    glRectf(-1.0, -1.0, 1.0, 1.0);
    // OSMesa's buffer is bottom-up: row 0 in memory is window y 0.
    assert_eq!(c.pixel(2, 3), [0; 4], "discarded");
    assert_eq!(
        c.pixel(9, 3),
        [38, 14, 0, 255],
        "(x + 0.5) / 64 and (y + 0.5) / 64"
    );
    assert_eq!(c.pixel(15, 12), [62, 50, 0, 255]);
}

/// A generic attribute's current value feeds a vertex shader; glVertexAttrib draws a
/// deferred glBegin/glEnd batch first (it was given with the old value); a value set
/// between glBegin and glEnd is not recorded per vertex, so that batch is refused.
#[test]
fn generic_attributes_are_current_values_and_inside_begin_end_per_vertex() {
    let c = Ctx::new();
    c.clear();
    let p = glCreateProgram();
    glAttachShader(
        p,
        shader(
            GL_VERTEX_SHADER,
            "attribute vec4 col; void main() { gl_Position = gl_Vertex; gl_FrontColor = col; }",
        ),
    );
    glAttachShader(
        p,
        shader(
            GL_FRAGMENT_SHADER,
            "void main() { gl_FragColor = gl_Color; }",
        ),
    );
    let name = CString::new("col").unwrap();
    // SAFETY: a NUL-terminated name.
    unsafe { glBindAttribLocation(p, 1, name.as_ptr()) };
    glLinkProgram(p);
    glUseProgram(p);
    let tri = |x0: f32, x1: f32| {
        glBegin(GL_TRIANGLES);
        glVertex2f(x0, -1.0);
        glVertex2f(x1, -1.0);
        glVertex2f(x0, 1.0);
        glEnd();
    };
    let s0 = stats();
    glVertexAttrib4f(1, 1.0, 0.0, 0.0, 1.0);
    // Left half: red, deferred (GL_TRIANGLES batches merge) until the next call.
    tri(-1.0, 0.0);
    glVertexAttrib4f(1, 0.0, 1.0, 0.0, 1.0);
    // Right half: green.
    tri(0.0, 1.0);
    assert_eq!(
        c.pixel(1, 2),
        [255, 0, 0, 255],
        "the batch before the change"
    );
    assert_eq!(c.pixel(9, 2), [0, 255, 0, 255], "the batch after it");
    let s1 = stats();
    assert_eq!(s1.program_draws - s0.program_draws, 2);
    assert_eq!(s1.program_draws_refused, s0.program_draws_refused);

    // Values given between vertices belong to each vertex: blue at (-1, -1), yellow at
    // the other two. Pixel (0, 0)'s centre weighs the first vertex 15/16 and the others
    // 1/16 together; pixel (14, 0)'s weighs it 1/16.
    c.clear();
    glBegin(GL_TRIANGLES);
    glVertexAttrib4f(1, 0.0, 0.0, 1.0, 1.0);
    glVertex2f(-1.0, -1.0);
    glVertexAttrib4f(1, 1.0, 1.0, 0.0, 1.0);
    glVertex2f(1.0, -1.0);
    glVertex2f(-1.0, 1.0);
    glEnd();
    let near = |p: [u8; 4], want: [f32; 3]| {
        (0..3).all(|k| (f32::from(p[k]) - want[k] * 255.0).abs() <= 2.0) && p[3] == 255
    };
    let (first, second) = (c.pixel(0, 0), c.pixel(14, 0));
    assert!(
        near(first, [1.0 / 16.0, 1.0 / 16.0, 15.0 / 16.0]),
        "{first:?}"
    );
    assert!(
        near(second, [15.0 / 16.0, 15.0 / 16.0, 1.0 / 16.0]),
        "{second:?}"
    );
    let s2 = stats();
    assert_eq!(s2.program_draws_refused, s1.program_draws_refused);
    assert_eq!(s2.program_draws - s1.program_draws, 1);

    // The next batch, with the value set outside glBegin/glEnd, draws again.
    tri(-1.0, 1.0);
    assert_eq!(c.pixel(2, 2), [255, 255, 0, 255]);
    assert_eq!(stats().program_draws - s2.program_draws, 1);
}

#[test]
fn front_facing_follows_the_winding() {
    let c = Ctx::new();
    c.clear();
    let p = program(
        None,
        "void main() { gl_FragColor = gl_FrontFacing ? vec4(1.0, 0.0, 0.0, 1.0)
                                                    : vec4(0.0, 1.0, 0.0, 1.0); }",
    );
    glUseProgram(p);
    let before = stats();
    // lower left counter-clockwise (front), upper right clockwise (back)
    glBegin(GL_TRIANGLES);
    glVertex2f(-1.0, -1.0);
    glVertex2f(0.0, -1.0);
    glVertex2f(-1.0, 0.0);
    glVertex2f(1.0, 1.0);
    glVertex2f(1.0, 0.0);
    glVertex2f(0.0, 1.0);
    glEnd();
    let after = stats();
    assert_eq!(after.program_draws - before.program_draws, 1);
    assert_eq!(after.program_draws_refused, before.program_draws_refused);
    assert_eq!(c.pixel(2, 2), [255, 0, 0, 255]);
    assert_eq!(c.pixel(13, 13), [0, 255, 0, 255]);
}

#[test]
fn hostile_coordinates_and_derivatives_draw_without_harm() {
    use softgl::ffi::textures::*;
    let c = Ctx::new();
    c.clear();
    // A mipmapped 4x4 texture on unit 0, and a cube map with one texel per face.
    let mut tex = [0u32; 2];
    // SAFETY: room for two names.
    unsafe { glGenTextures(2, tex.as_mut_ptr()) };
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    let texels = [200u8; 4 * 4 * 4];
    for (level, size) in [(0, 4), (1, 2), (2, 1)] {
        // SAFETY: `texels` holds a 4x4 RGBA image, larger than every level.
        unsafe {
            glTexImage2D(
                GL_TEXTURE_2D,
                level,
                GL_RGBA as i32,
                size,
                size,
                0,
                GL_RGBA,
                GL_UNSIGNED_BYTE,
                texels.as_ptr().cast(),
            )
        };
    }
    glTexParameteri(
        GL_TEXTURE_2D,
        GL_TEXTURE_MIN_FILTER,
        GL_LINEAR_MIPMAP_LINEAR as i32,
    );
    let before = stats();
    // Infinite, NaN, huge and tiny coordinates and their derivatives, projected by 0.
    for fs in [
        "uniform sampler2D t; void main() {
           vec2 p = gl_TexCoord[0].st / 0.0;
           gl_FragColor = texture2D(t, p) + vec4(dFdx(p.x), dFdy(p.y), fwidth(p.x), 0.0);
         }",
        "uniform sampler2D t; void main() {
           vec2 p = vec2(1e38) * gl_FragCoord.xy;
           gl_FragColor = texture2D(t, p) + texture2DProj(t, vec3(p, 0.0))
             + texture2D(t, vec2(sqrt(-gl_FragCoord.x)));
         }",
        "uniform sampler2D t; void main() {
           float n = 0.0 / 0.0;
           gl_FragColor = texture2D(t, vec2(n, 1e-45 * gl_FragCoord.x))
             + vec4(dFdx(n), dFdy(1.0 / (gl_FragCoord.x - 8.5)), 0.0, 1.0);
         }",
    ] {
        let p = program(None, fs);
        glUseProgram(p);
        // SAFETY: a NUL-terminated name.
        let k = unsafe { glGetUniformLocation(p, c"t".as_ptr()) };
        glUniform1i(k, 0);
        glBegin(GL_TRIANGLES);
        glTexCoord2f(f32::INFINITY, 0.5);
        glVertex2f(-1.0, -1.0);
        glTexCoord2f(f32::NAN, -1e30);
        glVertex2f(1.0, -1.0);
        glTexCoord2f(0.0, 1e-30);
        glVertex2f(0.0, 1.0);
        glEnd();
        glBegin(GL_LINES);
        glVertex2f(-1.0, 0.0);
        glVertex2f(1.0, 0.5);
        glEnd();
    }
    glUseProgram(0);
    let after = stats();
    assert_eq!(
        after.program_draws - before.program_draws,
        6,
        "every draw ran"
    );
    assert_eq!(after.program_draws_refused, before.program_draws_refused);
    assert_eq!(glGetError(), GL_NO_ERROR);
    // Something was written (the texture's 200s or the derivatives' values).
    assert!((0..W).any(|x| c.pixel(x, 4) != [0; 4]));
}

#[test]
fn frag_data_0_is_the_colour_and_later_elements_go_to_unbound_buffers() {
    let c = Ctx::new();
    c.clear();
    let p0 = program(
        None,
        "void main() { gl_FragData[0] = vec4(0.0, 1.0, 0.0, 1.0); }",
    );
    glUseProgram(p0);
    let s0 = stats();
    glRectf(-1.0, -1.0, 1.0, 1.0);
    assert_eq!(stats().program_draws - s0.program_draws, 1);
    assert_eq!(c.pixel(8, 8), [0, 255, 0, 255]);
    c.clear();
    let p1 = program(
        None,
        "void main() { gl_FragData[0] = vec4(1.0); gl_FragData[1] = vec4(0.5); }",
    );
    glUseProgram(p1);
    let s1 = stats();
    glRectf(-1.0, -1.0, 1.0, 1.0);
    // The window has one draw buffer: element 1 has nowhere to go and is
    // dropped, element 0 is the colour.
    assert_eq!(stats().program_draws - s1.program_draws, 1);
    assert_eq!(stats().program_draws_refused - s1.program_draws_refused, 0);
    assert_eq!(c.pixel(8, 8), [255; 4]);
    glUseProgram(0);
}

#[test]
fn back_colours_and_clip_vertex_that_do_not_fit_refuse_the_draw() {
    let c = Ctx::new();
    c.clear();
    // Ten vec4 varyings after the colours: the fragment shader's varyings reach
    // `MAX_VARY` (52 floats), leaving no room for the back colours or the clip vertex.
    let decl = "varying vec4 v[10];";
    let vs = format!(
        "{decl} void main() {{ gl_Position = gl_Vertex; gl_FrontColor = vec4(1.0); \
         gl_BackColor = vec4(0.0, 1.0, 0.0, 1.0); gl_ClipVertex = gl_Vertex; \
         for (int i = 0; i < 10; i++) v[i] = vec4(0.1 * float(i)); }}"
    );
    let fs = format!(
        "{decl} void main() {{ vec4 s = vec4(0.0); \
         for (int i = 0; i < 10; i++) s += v[i]; gl_FragColor = gl_Color + s * 0.0; }}"
    );
    let p = program(Some(&vs), &fs);
    glUseProgram(p);
    let tri = || {
        glBegin(GL_TRIANGLES);
        glVertex2f(-1.0, -1.0);
        glVertex2f(1.0, -1.0);
        glVertex2f(-1.0, 1.0);
        glEnd();
    };
    let s0 = stats();
    tri();
    assert_eq!(c.pixel(2, 2), [255; 4], "fits without the enables");
    let s1 = stats();
    assert_eq!(s1.program_draws - s0.program_draws, 1);
    assert_eq!(s1.program_draws_refused, s0.program_draws_refused);
    for cap in [GL_VERTEX_PROGRAM_TWO_SIDE, 0x3000] {
        c.clear();
        glEnable(cap);
        tri();
        glDisable(cap);
        assert_eq!(c.pixel(2, 2), [0; 4], "{cap:#x}: refused");
    }
    let s2 = stats();
    assert_eq!(s2.program_draws_refused - s1.program_draws_refused, 2);
    assert_eq!(s2.program_draws, s1.program_draws);
}
