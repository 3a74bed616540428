/* draw_instanced: ARB_draw_instanced and ARB_instanced_arrays. A #version 120
 * vertex shader (#extension GL_ARB_draw_instanced) places small quads by a
 * per-instance offset (glVertexAttribDivisor 1), tints them by an attribute
 * with divisor 3, sizes them by a per-vertex or (divisor 2) per-instance
 * scale, and sets depth and shade from gl_InstanceIDARB, so neighbouring
 * instances overlap in depth. glDrawArraysInstanced (40 quads as strips),
 * glDrawElementsInstanced (30 quads, divisor 2 on the scale),
 * glDrawElementsInstancedBaseVertex (12 diamonds from client indices; the base
 * vertex moves the per-vertex fetch only; tint divisor changed to 1, scale
 * divisor back to 0), a plain glDrawArrays (instance 0), instance count 0
 * (nothing drawn) and a fixed-function instanced draw with additive blending
 * (5 copies on top of each other add up). Queries of
 * GL_VERTEX_ATTRIB_ARRAY_DIVISOR and errors (negative instance count or count,
 * bad mode and type, divisor index out of range). Window and framebuffer object. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#define FW 128
#define FH 128
#include "errcheck.h"
#include "vert_program.h"

static const char *VS =
    "#version 120\n"
    "#extension GL_ARB_draw_instanced : require\n"
    "attribute vec2 corner;\n"
    "attribute vec2 offset;\n"
    "attribute vec3 tint;\n"
    "attribute float scale;\n"
    "varying vec3 c;\n"
    "void main() {\n"
    "  float id = float(gl_InstanceIDARB);\n"
    "  vec2 p = offset + corner * scale;\n"
    "  gl_Position = gl_ModelViewProjectionMatrix * vec4(p, fract(id * 0.377) * 1.6 - 0.8, 1.0);\n"
    "  c = tint * (0.45 + 0.55 * fract(id * 0.173)) + vec3(corner * 0.25, 0.0);\n"
    "}\n";

static const char *FS =
    "#version 120\n"
    "varying vec3 c;\n"
    "void main() {\n"
    "  gl_FragColor = vec4(c, 1.0);\n"
    "}\n";

#define NOFF 82 /* 40 + 30 + 12 offsets */
static GLuint prog, vbo_v, vbo_i, ebo;
static const GLubyte diamond_idx[6] = {0, 1, 2, 0, 2, 3};

static void setup(void)
{
    /* corners: a unit quad as a strip (0-3), a diamond (4-7); per-vertex scale */
    static const GLfloat corner[8][2] = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}, {1.0f, 1.0f},
                                         {0.5f, -0.1f}, {1.1f, 0.5f}, {0.5f, 1.1f}, {-0.1f, 0.5f}};
    static const GLfloat vscale[8] = {13.7f, 16.9f, 15.2f, 17.3f, 9.7f, 14.1f, 12.3f, 11.9f};
    static const GLushort quad_idx[6] = {0, 1, 3, 0, 3, 2};
    static GLfloat off[NOFF][2], tint[40][3], iscale[15];
    int i;
    for (i = 0; i < 40; i++) { /* 8 x 5 in the top half */
        off[i][0] = 2.3f + (i % 8) * 15.1f;
        off[i][1] = 60.2f + (i / 8) * 12.1f;
    }
    for (i = 0; i < 30; i++) { /* 6 x 5 bottom left */
        off[40 + i][0] = 2.7f + (i % 6) * 10.3f;
        off[40 + i][1] = 2.9f + (i / 6) * 10.9f;
    }
    for (i = 0; i < 12; i++) { /* 4 x 3 bottom right */
        off[70 + i][0] = 68.4f + (i % 4) * 14.3f;
        off[70 + i][1] = 3.6f + (i / 4) * 16.7f;
    }
    for (i = 0; i < 40; i++) {
        tint[i][0] = sgl_randf();
        tint[i][1] = sgl_randf();
        tint[i][2] = sgl_randf();
    }
    for (i = 0; i < 15; i++)
        iscale[i] = 8.3f + 0.37f * i;

    glGenBuffers(1, &vbo_v);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_v);
    glBufferData(GL_ARRAY_BUFFER, sizeof corner + sizeof vscale, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof corner, corner);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof corner, sizeof vscale, vscale);
    glGenBuffers(1, &vbo_i);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_i);
    glBufferData(GL_ARRAY_BUFFER, sizeof off + sizeof tint + sizeof iscale, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof off, off);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof off, sizeof tint, tint);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof off + sizeof tint, sizeof iscale, iscale);
    glGenBuffers(1, &ebo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof quad_idx, quad_idx, GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

static void arrays(int first_offset, int scale_divisor, int tint_divisor)
{
    size_t off_bytes = sizeof(GLfloat) * 2 * NOFF;
    glBindBuffer(GL_ARRAY_BUFFER, vbo_v);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, (void *)0);
    glBindBuffer(GL_ARRAY_BUFFER, vbo_i);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 0,
                          (void *)(sizeof(GLfloat) * 2 * (size_t)first_offset));
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, 0, (void *)off_bytes);
    if (scale_divisor) {
        glVertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, 0,
                              (void *)(off_bytes + sizeof(GLfloat) * 3 * 40));
    } else {
        glBindBuffer(GL_ARRAY_BUFFER, vbo_v);
        glVertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, 0, (void *)(sizeof(GLfloat) * 16));
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glVertexAttribDivisor(1, 1);
    glVertexAttribDivisor(2, (GLuint)tint_divisor);
    glVertexAttribDivisor(3, (GLuint)scale_divisor);
}

static void draw(const GLuint *progs, int n)
{
    int i;
    (void)progs;
    (void)n;
    vert_begin_ortho(FW, FH);
    glUseProgram(prog);
    for (i = 0; i < 4; i++)
        glEnableVertexAttribArray((GLuint)i);

    arrays(0, 0, 3);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, 40);
    arrays(40, 2, 3);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    glDrawElementsInstanced(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, (void *)0, 30);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    arrays(70, 0, 1);
    glDrawElementsInstancedBaseVertex(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, diamond_idx, 12, 4);
    /* not instanced: instance 0 only, at offset 79 moved up */
    glTranslatef(3.1f, 8.3f, 0.0f);
    arrays(79, 0, 1);
    glDrawArrays(GL_TRIANGLE_STRIP, 4, 4);
    /* no instances: nothing */
    glLoadIdentity();
    arrays(50, 0, 1);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, 0);
    glDrawElementsInstancedBaseVertex(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, diamond_idx, 0, 4);
    for (i = 0; i < 4; i++) {
        glVertexAttribDivisor((GLuint)i, 0);
        glDisableVertexAttribArray((GLuint)i);
    }
    glUseProgram(0);

    /* fixed function: 5 copies of a triangle at the same place, added up */
    {
        static const GLfloat tri[3][2] = {{41.3f, 27.9f}, {97.7f, 33.1f}, {66.1f, 71.7f}};
        glDisable(GL_DEPTH_TEST);
        glEnable(GL_BLEND);
        glBlendFunc(GL_ONE, GL_ONE);
        glColor3f(0.1f, 0.06f, 0.02f);
        glVertexPointer(2, GL_FLOAT, 0, tri);
        glEnableClientState(GL_VERTEX_ARRAY);
        glDrawArraysInstanced(GL_TRIANGLES, 0, 3, 5);
        glDisableClientState(GL_VERTEX_ARRAY);
        glDisable(GL_BLEND);
    }
}

static void queries(void)
{
    GLint maxa = 0, d[4];
    int i;
    glGetIntegerv(GL_MAX_VERTEX_ATTRIBS, &maxa);
    glUseProgram(prog);
    arrays(40, 2, 3);
    for (i = 0; i < 4; i++) {
        d[i] = -7;
        glGetVertexAttribiv((GLuint)i, GL_VERTEX_ATTRIB_ARRAY_DIVISOR, &d[i]);
    }
    sgl_text(out, "query", "divisors %d %d %d %d\n", d[0], d[1], d[2], d[3]);
    glVertexAttribDivisor(2, 0);
    glGetVertexAttribiv(2, GL_VERTEX_ATTRIB_ARRAY_DIVISOR, &d[2]);
    sgl_text(out, "query", "divisor 2 after reset %d\n", d[2]);
    for (i = 0; i < 4; i++)
        glEnableVertexAttribArray((GLuint)i);
    E(glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, -1));
    E(glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, -4, 3));
    E(glDrawArraysInstanced(0x7777, 0, 4, 3));
    E(glDrawElementsInstanced(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, diamond_idx, -2));
    E(glDrawElementsInstanced(GL_TRIANGLES, -6, GL_UNSIGNED_BYTE, diamond_idx, 2));
    E(glDrawElementsInstanced(GL_TRIANGLES, 6, GL_FLOAT, diamond_idx, 2));
    E(glDrawElementsInstancedBaseVertex(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, diamond_idx, -1, 4));
    E(glDrawElementsInstancedBaseVertex(0x7777, 6, GL_UNSIGNED_BYTE, diamond_idx, 1, 4));
    E(glVertexAttribDivisor((GLuint)maxa, 1));
    E(glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, 0));
    for (i = 0; i < 4; i++) {
        glVertexAttribDivisor((GLuint)i, 0);
        glDisableVertexAttribArray((GLuint)i);
    }
    glUseProgram(0);
}

int main(int argc, char **argv)
{
    static const char *names[] = {"corner", "offset", "tint", "scale", NULL};
    static unsigned char rb[FW * FH * 4];
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    out = sgl_open(argc, argv);
    prog = vert_program(VS, FS, names);
    setup();
    frag_window_and_fbo(out, buf, rb, draw, NULL, 0);
    queries();
    frag_output(out, "after_errors", buf);
    return sgl_end_scene(ctx, buf);
}
