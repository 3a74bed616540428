/* primitive_restart: GL_PRIMITIVE_RESTART and glPrimitiveRestartIndex (the GL 3.1
 * names, which Mesa's compatibility context accepts). An 8 x 8 grid of vertices
 * (indices r * 8 + c) is cut into several primitives by the restart index:
 * triangle strips, line strips, triangle fans, GL_POLYGON and GL_TRIANGLES (a
 * restart drops the unfinished triangle), with GL_UNSIGNED_SHORT and
 * GL_UNSIGNED_INT indices from an element buffer and from client memory; the
 * restart index 0xFFFF and 5 (a grid vertex); the lists with 5 drawn again with
 * restart disabled, where 5 is an ordinary vertex; glDrawRangeElements,
 * glMultiDrawElements, glDrawElementsBaseVertex (the index is compared before
 * the base is added). Each draw in its own 32 x 32 cell, depth test on.
 * glIsEnabled(GL_PRIMITIVE_RESTART) and GL_PRIMITIVE_RESTART_INDEX (initial,
 * 0xFFFF, 5, 0xFFFFFFFF) in a text block. Window and framebuffer object. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <math.h>
#define FW 128
#define FH 128
#include "errcheck.h"
#include "vert_program.h"

#define R 0xFFFFu
#define V(r, c) ((r) * 8 + (c))
#define MAXI 64

/* index lists, built once; [0] uses 0xFFFF, [1] uses 5 */
static GLuint strip[2][MAXI], lines[2][MAXI], fan[2][MAXI], poly[2][MAXI], tris[MAXI];
static int nstrip[2], nlines[2], nfan[2], npoly[2], ntris;
static GLuint vbo, ebo;

static void add_strip(GLuint *l, int *n, int r, int c0, int c1)
{
    int c;
    for (c = c0; c <= c1; c++) {
        l[(*n)++] = (GLuint)V(r + 1, c);
        l[(*n)++] = (GLuint)V(r, c);
    }
}

static void add_line(GLuint *l, int *n, int r, int c0, int c1)
{
    int c;
    for (c = c0; c <= c1; c++)
        l[(*n)++] = (GLuint)V(r + (c & 1), c);
}

static void add_fan(GLuint *l, int *n, int r, int c)
{
    static const int ring[9][2] = {{-1, -1}, {-1, 0}, {-1, 1}, {0, 1}, {1, 1},
                                   {1, 0},   {1, -1}, {0, -1}, {-1, -1}};
    int k;
    l[(*n)++] = (GLuint)V(r, c);
    for (k = 0; k < 9; k++)
        if (k != 5) /* leave one side open */
            l[(*n)++] = (GLuint)V(r + ring[k][0], c + ring[k][1]);
}

static void add_poly(GLuint *l, int *n, int r, int c)
{
    static const int oct[8][2] = {{-2, -1}, {-2, 1}, {-1, 2}, {1, 2},
                                  {2, 1},   {2, -1}, {1, -2}, {-1, -2}};
    int k;
    for (k = 0; k < 8; k++)
        l[(*n)++] = (GLuint)V(r + oct[k][0], c + oct[k][1]);
}

static void setup(void)
{
    static GLfloat v[64][6];
    static const GLuint t[] = {V(0, 0), V(0, 1), V(1, 0), V(1, 1), R, V(1, 2), V(1, 3),
                               V(2, 2), V(2, 3), V(2, 4), R, V(3, 3), V(3, 4), V(4, 3),
                               V(5, 5), V(5, 7), V(7, 6), V(6, 0), R, R, V(6, 1), V(7, 1),
                               V(7, 0)};
    int r, c, k;
    GLuint sep;
    for (r = 0; r < 8; r++)
        for (c = 0; c < 8; c++) {
            GLfloat *p = v[V(r, c)];
            p[0] = 1.13f + c * 4.31f;
            p[1] = 1.29f + r * 4.27f;
            p[2] = 0.6f * sinf(r * 1.3f + c * 0.7f);
            p[3] = r / 7.0f;
            p[4] = c / 7.0f;
            p[5] = 0.5f + 0.5f * cosf(r * 0.9f - c * 0.5f);
        }
    for (k = 0; k < 2; k++) {
        sep = k ? 5u : R;
        /* the lists with 5 use rows >= 1, so vertex 5 (row 0) is only the separator */
        add_strip(strip[k], &nstrip[k], k ? 1 : 0, 0, 7);
        strip[k][nstrip[k]++] = sep;
        add_strip(strip[k], &nstrip[k], 3, 1, 6);
        strip[k][nstrip[k]++] = sep;
        add_strip(strip[k], &nstrip[k], 5, 0, 4);
        add_line(lines[k], &nlines[k], k ? 1 : 0, 0, 7);
        lines[k][nlines[k]++] = sep;
        add_line(lines[k], &nlines[k], 3, 1, 6);
        lines[k][nlines[k]++] = sep;
        lines[k][nlines[k]++] = sep;
        add_line(lines[k], &nlines[k], 6, 0, 5);
        add_fan(fan[k], &nfan[k], 2, 2);
        fan[k][nfan[k]++] = sep;
        add_fan(fan[k], &nfan[k], 5, 2);
        fan[k][nfan[k]++] = sep;
        add_fan(fan[k], &nfan[k], 4, 5);
        add_poly(poly[k], &npoly[k], k ? 3 : 2, 2);
        poly[k][npoly[k]++] = sep;
        add_poly(poly[k], &npoly[k], 3, 5);
        poly[k][npoly[k]++] = sep;
        add_poly(poly[k], &npoly[k], 5, 3);
    }
    ntris = (int)(sizeof t / sizeof t[0]);
    memcpy(tris, t, sizeof t);

    vbo = vert_color_vbo(v, sizeof v, sizeof v[0]);
    glGenBuffers(1, &ebo);
}

/* Draws `l` (n indices) as `type` in cell (cx, cy), from the element buffer
 * when `in_buffer`. */
static void cell(int cx, int cy, GLenum mode, const GLuint *l, int n, GLenum type, int in_buffer)
{
    static GLushort s[MAXI];
    const void *ptr = l;
    int i;
    if (type == GL_UNSIGNED_SHORT) {
        for (i = 0; i < n; i++)
            s[i] = (GLushort)l[i];
        ptr = s;
    }
    glLoadIdentity();
    glTranslatef(32.0f * cx, 32.0f * cy, 0.0f);
    if (in_buffer) {
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, n * (type == GL_UNSIGNED_SHORT ? 2 : 4), ptr,
                     GL_STREAM_DRAW);
        glDrawElements(mode, n, type, (void *)0);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    } else {
        glDrawElements(mode, n, type, ptr);
    }
}

static void draw(const GLuint *progs, int n)
{
    static const GLushort m0[] = {V(0, 0), V(1, 0), V(0, 1), V(1, 1), R, V(2, 2), V(3, 2), V(2, 3)};
    static const GLushort m1[] = {V(5, 4), V(6, 4), R, V(5, 5), V(6, 5), V(5, 6), V(6, 6)};
    static const GLsizei mc[2] = {8, 7};
    const void *mi[2] = {m0, m1};
    (void)progs;
    (void)n;
    vert_begin_ortho(FW, FH);

    glEnable(GL_PRIMITIVE_RESTART);
    glPrimitiveRestartIndex(0xFFFF);
    cell(0, 3, GL_TRIANGLE_STRIP, strip[0], nstrip[0], GL_UNSIGNED_SHORT, 1);
    cell(1, 3, GL_TRIANGLE_STRIP, strip[0], nstrip[0], GL_UNSIGNED_INT, 0);
    cell(2, 3, GL_LINE_STRIP, lines[0], nlines[0], GL_UNSIGNED_SHORT, 0);
    cell(3, 3, GL_TRIANGLE_FAN, fan[0], nfan[0], GL_UNSIGNED_INT, 1);
    cell(0, 2, GL_POLYGON, poly[0], npoly[0], GL_UNSIGNED_SHORT, 1);
    cell(1, 2, GL_TRIANGLES, tris, ntris, GL_UNSIGNED_INT, 0);
    /* a range draw, a multi draw, a base vertex (restart tested before the base) */
    glLoadIdentity();
    glTranslatef(64.0f, 64.0f, 0.0f);
    glDrawRangeElements(GL_TRIANGLE_STRIP, 0, 63, nstrip[0] - 20, GL_UNSIGNED_INT, strip[0] + 20);
    glTranslatef(32.0f, 0.0f, 0.0f);
    glMultiDrawElements(GL_TRIANGLE_STRIP, mc, GL_UNSIGNED_SHORT, mi, 2);
    glTranslatef(0.0f, -8.54f, 0.1f);
    glDrawElementsBaseVertex(GL_TRIANGLE_STRIP, 8, GL_UNSIGNED_SHORT, m0, 16);

    glPrimitiveRestartIndex(5);
    cell(0, 1, GL_TRIANGLE_STRIP, strip[1], nstrip[1], GL_UNSIGNED_SHORT, 0);
    cell(1, 1, GL_LINE_STRIP, lines[1], nlines[1], GL_UNSIGNED_INT, 1);
    cell(2, 1, GL_TRIANGLE_FAN, fan[1], nfan[1], GL_UNSIGNED_SHORT, 1);
    cell(3, 1, GL_POLYGON, poly[1], npoly[1], GL_UNSIGNED_INT, 0);

    /* disabled: 5 is an ordinary vertex again */
    glDisable(GL_PRIMITIVE_RESTART);
    cell(0, 0, GL_TRIANGLE_STRIP, strip[1], nstrip[1], GL_UNSIGNED_INT, 1);
    cell(1, 0, GL_LINE_STRIP, lines[1], nlines[1], GL_UNSIGNED_SHORT, 0);
    cell(2, 0, GL_TRIANGLE_FAN, fan[1], nfan[1], GL_UNSIGNED_INT, 0);
    cell(3, 0, GL_POLYGON, poly[1], npoly[1], GL_UNSIGNED_SHORT, 1);
    glLoadIdentity();
}

static void state(const char *when)
{
    GLint idx = -7;
    glGetIntegerv(GL_PRIMITIVE_RESTART_INDEX, &idx);
    sgl_text(out, "state", "%-22s enabled %d index %d (0x%x) err 0x%04x\n", when,
             glIsEnabled(GL_PRIMITIVE_RESTART), idx, (unsigned)idx, glGetError());
}

int main(int argc, char **argv)
{
    static unsigned char rb[FW * FH * 4];
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    out = sgl_open(argc, argv);
    state("initial");
    glEnable(GL_PRIMITIVE_RESTART);
    state("enabled");
    glPrimitiveRestartIndex(0xFFFF);
    state("index 0xFFFF");
    glPrimitiveRestartIndex(5);
    state("index 5");
    glPrimitiveRestartIndex(0xFFFFFFFFu);
    state("index 0xFFFFFFFF");
    glDisable(GL_PRIMITIVE_RESTART);
    state("disabled");
    setup();
    frag_window_and_fbo(out, buf, rb, draw, NULL, 0);
    state("after drawing");
    return sgl_end_scene(ctx, buf);
}
