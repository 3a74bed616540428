/* frag_out_locations: GLSL user-defined fragment outputs and their locations
 * (GL 3.0 glBindFragDataLocation / glGetFragDataLocation, GLSL 1.30 `out`,
 * GLSL 3.30 `layout(location = N)`), in the compatibility context. A 64x64
 * framebuffer object with three RGBA8 colour renderbuffers and depth, all three
 * in glDrawBuffers, drawn with overlapping smooth triangles from a buffer
 * object (generic attributes at explicit `layout(location = N) in` locations
 * for the 3.30 programs, gl_Vertex/gl_Color arrays for the 1.30 ones):
 * (a) three 3.30 outputs at locations 0, 2, 1 (a glBindFragDataLocation of
 * one of them to 2 before the link loses to its layout); (b) two 1.30 outputs
 * bound to 2 and 0 before the link, then one rebound after it (no effect until
 * the relink, drawn before and after it; the buffer of the location no output
 * has is GL_NONE in glDrawBuffers, since an unwritten buffer is undefined);
 * (c) one 1.30 output without a location or binding into three buffers (it
 * gets location 0; only buffer 0 is read: the others are undefined);
 * (d) a 3.30 output array o[3] at location 0; (e) a 3.30 float at location 0
 * and a vec3 at 1, each drawn under a glColorMask of only the components it
 * writes. The attachments are read back through glReadBuffer after each case.
 * Then glGetFragDataLocation of every output (plus a non-output,
 * gl_FragColor, the array and its elements), glGetAttribLocation where the
 * layout beats glBindAttribLocation, GL_MAX_DRAW_BUFFERS, and the errors:
 * colour number >= GL_MAX_DRAW_BUFFERS, a "gl_" name, a non-program and a
 * shader name, glGetFragDataLocation on an unlinked program and a
 * non-program; the location the linker picks for an unbound output beside a
 * bound one (Mesa: the lowest free, 0). Last, program (a) drawn into the window: location 0 lands
 * there. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#define FW 64
#define FH 64
#include "errcheck.h"
#include "vert_program.h"

static const char *VS_330 =
    "#version 330\n"
    "layout(location = 0) in vec3 pos;\n"
    "layout(location = 1) in vec4 col;\n"
    "out vec4 v;\n"
    "void main() {\n"
    "  gl_Position = vec4(pos, 1.0);\n"
    "  v = col;\n"
    "}\n";

static const char *VS_130 =
    "#version 130\n"
    "out vec4 v;\n"
    "void main() {\n"
    "  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n"
    "  v = gl_Color;\n"
    "}\n";

static const char *FS_A =
    "#version 330\n"
    "in vec4 v;\n"
    "layout(location = 0) out vec4 a;\n"
    "layout(location = 2) out vec4 b;\n"
    "layout(location = 1) out vec4 c;\n"
    "void main() {\n"
    "  a = vec4(v.rgb, 1.0);\n"
    "  b = vec4(v.b, 1.0 - v.r, v.g * 0.5, 0.75);\n"
    "  c = vec4(v.g * v.g, 0.2 + 0.5 * v.a, 1.0 - v.b, 1.0);\n"
    "}\n";

static const char *FS_B =
    "#version 130\n"
    "in vec4 v;\n"
    "out vec4 x;\n"
    "out vec4 y;\n"
    "void main() {\n"
    "  x = vec4(1.0 - v.g, v.r, 0.9, 1.0);\n"
    "  y = vec4(v.b, v.b * 0.5, v.r, 0.5 + 0.5 * v.a);\n"
    "}\n";

static const char *FS_C =
    "#version 130\n"
    "in vec4 v;\n"
    "out vec4 color;\n"
    "void main() {\n"
    "  color = vec4(v.r, v.g * 0.5 + 0.5, v.b, 1.0);\n"
    "}\n";

static const char *FS_D =
    "#version 330\n"
    "in vec4 v;\n"
    "layout(location = 0) out vec4 o[3];\n"
    "void main() {\n"
    "  o[0] = vec4(v.r, 0.1, v.g, 1.0);\n"
    "  o[1] = vec4(0.3, v.b, v.r, 1.0);\n"
    "  o[2] = vec4(v.g, v.r * v.b, 0.7, v.a);\n"
    "}\n";

static const char *FS_E =
    "#version 330\n"
    "in vec4 v;\n"
    "layout(location = 1) out vec3 v3;\n"
    "layout(location = 0) out float f;\n"
    "void main() {\n"
    "  f = v.r * 0.5 + 0.25;\n"
    "  v3 = v.gbr;\n"
    "}\n";

#define NV 12
static const GLfloat verts[NV][7] = {
    /* x, y, z, r, g, b, a */
    {-0.93f, -0.87f, 0.30f, 1.0f, 0.1f, 0.0f, 1.0f},
    {0.71f, -0.62f, 0.30f, 0.9f, 0.9f, 0.1f, 0.4f},
    {-0.41f, 0.83f, 0.30f, 0.2f, 0.4f, 1.0f, 0.8f},
    {-0.22f, -0.97f, -0.50f, 0.0f, 1.0f, 0.3f, 1.0f},
    {0.96f, 0.13f, 0.60f, 0.1f, 0.2f, 0.9f, 0.2f},
    {0.05f, 0.91f, -0.10f, 1.0f, 0.6f, 0.7f, 0.6f},
    {-0.99f, 0.11f, -0.20f, 0.6f, 0.0f, 1.0f, 0.9f},
    {0.57f, 0.77f, -0.20f, 1.0f, 1.0f, 0.0f, 0.3f},
    {0.33f, -0.58f, 0.70f, 0.0f, 0.8f, 0.8f, 1.0f},
    {-0.63f, -0.31f, 0.90f, 0.9f, 0.5f, 0.2f, 0.7f},
    {0.88f, -0.92f, -0.80f, 0.3f, 0.3f, 0.3f, 1.0f},
    {0.79f, 0.95f, 0.10f, 0.8f, 0.1f, 0.6f, 0.5f},
};

static const GLenum all3[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1,
                               GL_COLOR_ATTACHMENT2};
static GLuint vao_generic, vao_builtin;
static unsigned char rb[FW * FH * 4];

/* A program of `vs` and `fs`, not linked. */
static GLuint program(const char *vs, const char *fs)
{
    GLuint p = glCreateProgram();
    vert_attach(p, GL_VERTEX_SHADER, vs);
    vert_attach(p, GL_FRAGMENT_SHADER, fs);
    return p;
}

static void setup_arrays(void)
{
    GLuint vbo;
    const GLsizei stride = sizeof verts[0];
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof verts, verts, GL_STATIC_DRAW);
    glGenVertexArrays(1, &vao_generic);
    glBindVertexArray(vao_generic);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, (void *)0);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, stride, (void *)(3 * sizeof(GLfloat)));
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glGenVertexArrays(1, &vao_builtin);
    glBindVertexArray(vao_builtin);
    glVertexPointer(3, GL_FLOAT, stride, (void *)0);
    glColorPointer(4, GL_FLOAT, stride, (void *)(3 * sizeof(GLfloat)));
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glBindVertexArray(0);
}

static GLuint setup_fbo(void)
{
    GLuint fbo, rbs[4];
    int i;
    glGenFramebuffers(1, &fbo);
    glGenRenderbuffers(4, rbs);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    for (i = 0; i < 4; i++) {
        glBindRenderbuffer(GL_RENDERBUFFER, rbs[i]);
        glRenderbufferStorage(GL_RENDERBUFFER, i < 3 ? GL_RGBA8 : GL_DEPTH_COMPONENT24, FW, FH);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, i < 3 ? all3[i] : GL_DEPTH_ATTACHMENT,
                                  GL_RENDERBUFFER, rbs[i]);
    }
    SGL_CHECK(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
    return fbo;
}

/* Clears every attachment (colour and depth) and sets the draw buffers. */
static void begin(const GLenum *bufs)
{
    glDrawBuffers(3, all3);
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawBuffers(3, bufs);
}

/* The triangles with `p`, through the generic or the built-in arrays. */
static void draw(GLuint p, int builtin)
{
    glUseProgram(p);
    glBindVertexArray(builtin ? vao_builtin : vao_generic);
    glDrawArrays(GL_TRIANGLES, 0, NV);
    glBindVertexArray(0);
    glUseProgram(0);
}

/* Attachments 0 .. n-1 read back as "<tag>_<i>", and the GL error. */
static void read_all(const char *tag, int n)
{
    char name[64];
    int i;
    for (i = 0; i < n; i++) {
        glReadBuffer(all3[i]);
        glReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_BYTE, rb);
        snprintf(name, sizeof name, "%s_%d", tag, i);
        sgl_image(out, name, FW, FH, 4, "RGBA", FW * 4, 1, rb);
    }
    sgl_text(out, "error", "%s 0x%04x\n", tag, glGetError());
}

static void frag_loc(const char *prog, GLuint p, const char *name)
{
    GLint l = glGetFragDataLocation(p, name);
    sgl_text(out, "frag_loc", "%-10s %-14s %d err 0x%04x\n", prog, name, l, glGetError());
}

static void attrib_loc(const char *prog, GLuint p, const char *name)
{
    GLint l = glGetAttribLocation(p, name);
    sgl_text(out, "attrib_loc", "%-10s %-14s %d err 0x%04x\n", prog, name, l, glGetError());
}

int main(int argc, char **argv)
{
    static const GLenum b_first[3] = {GL_COLOR_ATTACHMENT0, GL_NONE, GL_COLOR_ATTACHMENT2};
    static const GLenum b_second[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_NONE};
    static const GLenum e_v3[3] = {GL_NONE, GL_COLOR_ATTACHMENT1, GL_NONE};
    static const GLenum e_f[3] = {GL_COLOR_ATTACHMENT0, GL_NONE, GL_NONE};
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    GLuint pa, pb, pc, pd, pe, pu, fbo, shader;
    GLint maxdb = -7, r;
    out = sgl_open(argc, argv);

    setup_arrays();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &maxdb);
    sgl_text(out, "max_draw_buffers", "%d\n", maxdb);

    /* (a): the layouts win over glBindAttribLocation and glBindFragDataLocation */
    pa = program(VS_330, FS_A);
    glBindAttribLocation(pa, 3, "col");
    glBindAttribLocation(pa, 2, "pos");
    glBindFragDataLocation(pa, 2, "a");
    vert_link(pa);
    /* (b): bound before the link; "x" rebound after it */
    pb = program(VS_130, FS_B);
    glBindFragDataLocation(pb, 2, "x");
    glBindFragDataLocation(pb, 0, "y");
    vert_link(pb);
    glBindFragDataLocation(pb, 1, "x");
    pc = program(VS_130, FS_C);
    vert_link(pc);
    pd = program(VS_330, FS_D);
    vert_link(pd);
    pe = program(VS_330, FS_E);
    vert_link(pe);
    sgl_text(out, "setup", "err 0x%04x\n", glGetError());

    fbo = setup_fbo();
    begin(all3);
    draw(pa, 0);
    read_all("a", 3);

    begin(b_first);
    draw(pb, 1);
    read_all("b_first_link", 3);
    frag_loc("b", pb, "x");
    frag_loc("b", pb, "y");
    vert_link(pb);
    frag_loc("b_relinked", pb, "x");
    frag_loc("b_relinked", pb, "y");
    begin(b_second);
    draw(pb, 1);
    read_all("b_relinked", 3);

    /* (c): "color" gets location 0; llvmpipe fills buffers 1 and 2 with its
     * uninitialised stack (constant blocks that change with LP_NUM_THREADS),
     * which GL leaves undefined: only buffer 0 is read */
    begin(all3);
    draw(pc, 1);
    read_all("c", 1);

    begin(all3);
    draw(pd, 0);
    read_all("d", 3);

    /* (e): the components f and v3 leave unwritten are undefined in GL
     * (llvmpipe writes 0, softpipe 1 in alpha and other values in G and B of
     * f's buffer), so each buffer is drawn alone with a colour mask of only the
     * written components (glColorMaski is not needed), depth cleared between */
    begin(e_v3);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    draw(pe, 0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDrawBuffers(3, e_f);
    glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE);
    draw(pe, 0);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    read_all("e", 3);

    /* the queries */
    frag_loc("a", pa, "a");
    frag_loc("a", pa, "b");
    frag_loc("a", pa, "c");
    frag_loc("a", pa, "v");
    frag_loc("a", pa, "nothing");
    frag_loc("a", pa, "gl_FragColor");
    frag_loc("c", pc, "color");
    frag_loc("d", pd, "o");
    frag_loc("d", pd, "o[0]");
    frag_loc("d", pd, "o[1]");
    frag_loc("d", pd, "o[2]");
    frag_loc("e", pe, "f");
    frag_loc("e", pe, "v3");
    attrib_loc("a", pa, "pos");
    attrib_loc("a", pa, "col");
    attrib_loc("d", pd, "pos");
    attrib_loc("d", pd, "col");

    /* the errors: on a throwaway program, an unlinked one, a shader name, a non-name */
    pu = program(VS_130, FS_B);
    shader = glCreateShader(GL_FRAGMENT_SHADER);
    E(glBindFragDataLocation(pu, (GLuint)maxdb, "x"));
    E(glBindFragDataLocation(pu, (GLuint)maxdb - 1, "x"));
    E(glBindFragDataLocation(pu, 0, "gl_x"));
    E(glBindFragDataLocation(pu, 0, "gl_FragColor"));
    E(glBindFragDataLocation(pu, 0, "gl_FragData"));
    E(glBindFragDataLocation(shader, 0, "x"));
    E(glBindFragDataLocation(4242, 0, "x"));
    E(r = glGetFragDataLocation(pu, "x"));
    sgl_text(out, "unlinked", "%d\n", r);
    E(r = glGetFragDataLocation(shader, "x"));
    sgl_text(out, "shader", "%d\n", r);
    E(r = glGetFragDataLocation(4242, "x"));
    sgl_text(out, "non_program", "%d\n", r);
    vert_link(pu);
    /* "x" at the last valid colour number; "y" unbound */
    frag_loc("pu", pu, "x");
    frag_loc("pu", pu, "y");

    /* the window: location 0 of (a) */
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    draw(pa, 0);
    sgl_text(out, "final", "err 0x%04x\n", glGetError());
    return frag_end(out, "window", buf, ctx);
}
