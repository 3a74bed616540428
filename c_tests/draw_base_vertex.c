/* draw_base_vertex: ARB_draw_elements_base_vertex. One vertex buffer packs
 * three copies of a set of four meshes (a grid, a fan, a strip, three loose
 * triangles); each copy sits in its own column and has its own tint, so the
 * base vertex alone picks which copy (column) a draw lands in. Draws:
 * glDrawElementsBaseVertex with GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT and
 * GL_UNSIGNED_INT indices from an element buffer and from client memory,
 * triangles and strips; negative base vertices on biased indices (index + base
 * stays >= 0); glDrawRangeElementsBaseVertex (the range bounds the indices
 * before the base is added); glMultiDrawElementsBaseVertex from the element
 * buffer and from client pointers, with mixed and negative bases and a zero
 * count. The meshes cross in depth. Errors: negative count, bad mode and
 * type, end < start, a negative count or draw count in the multi draw, after
 * which only one valid draw shows. Window and framebuffer object. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <math.h>
#define FW 128
#define FH 128
#include "errcheck.h"
#include "vert_program.h"

#define SET 43 /* vertices in one copy: grid 16 @0, fan 8 @16, strip 10 @24, tris 9 @34 */

static GLuint vbo, ebo;
/* byte offsets in the element buffer */
#define OFF_GRID8 0     /* 54 ubyte */
#define OFF_FAN16 64    /* 21 ushort */
#define OFF_STRIP32 128 /* 10 uint */
#define OFF_BIAS32 192  /* 54 uint: grid + 200 */
#define OFF_GRID16 448  /* 54 ushort */
#define OFF_TRIS16 560  /* 9 ushort */
static GLubyte grid8[54], tris_bias8[9], strip8[10], strip_bias8[10];
static GLushort fan16[21], tris16[9], grid16[54];
static GLuint strip32[10], grid_bias32[54];

static void setup(void)
{
    static GLfloat v[3 * SET][6];
    int c, i, j, n;
    for (c = 0; c < 3; c++) {
        GLfloat (*s)[6] = v + c * SET, dx = 42.5f * c + 3.3f;
        for (j = 0; j < 4; j++) /* grid: 4 x 4 */
            for (i = 0; i < 4; i++) {
                GLfloat *p = s[j * 4 + i];
                p[0] = dx + i * 11.7f + (j & 1) * 0.61f;
                p[1] = 3.1f + j * 11.9f;
                p[2] = -0.5f + 0.33f * i;
                p[3] = i / 3.0f; p[4] = j / 3.0f; p[5] = 0.2f + 0.25f * c;
            }
        for (i = 0; i < 8; i++) { /* fan: centre and 7 rim vertices */
            GLfloat *p = s[16 + i], a = 6.2831853f * i / 7.0f + 0.17f, r = i ? 17.3f : 0.0f;
            p[0] = dx + 19.1f + r * cosf(a);
            p[1] = 20.3f + r * sinf(a);
            p[2] = i ? 0.4f : -0.8f;
            p[3] = 0.9f - 0.1f * i; p[4] = 0.3f * c; p[5] = (i & 1) ? 1.0f : 0.4f;
        }
        for (i = 0; i < 10; i++) { /* strip: a zigzag band */
            GLfloat *p = s[24 + i];
            p[0] = dx + 2.7f + 3.9f * i;
            p[1] = (i & 1) ? 31.7f : 22.9f - 1.3f * i;
            p[2] = (i & 1) ? -0.7f : 0.7f;
            p[3] = 1.0f; p[4] = 0.1f * i; p[5] = 0.3f * c;
        }
        for (i = 0; i < 9; i++) { /* three loose triangles */
            GLfloat *p = s[34 + i];
            int t = i / 3, k = i % 3;
            p[0] = dx + 5.3f + 11.1f * t + (k == 1 ? 14.2f : 0.0f) + (k == 2 ? 4.4f : 0.0f);
            p[1] = 6.7f + 4.1f * t + (k == 2 ? 27.3f : 0.0f);
            p[2] = (k == 2) ? 0.9f : -0.9f;
            p[3] = 0.5f * (k & 1); p[4] = 1.0f - 0.3f * t; p[5] = 0.2f * c + 0.1f * k;
        }
    }
    for (j = 0, n = 0; j < 3; j++)
        for (i = 0; i < 3; i++) {
            int a = j * 4 + i;
            int q[6] = {a, a + 1, a + 4, a + 1, a + 5, a + 4};
            for (c = 0; c < 6; c++, n++) {
                grid8[n] = (GLubyte)q[c];
                grid16[n] = (GLushort)q[c];
                grid_bias32[n] = (GLuint)q[c] + 200u;
            }
        }
    for (i = 0; i < 7; i++) {
        fan16[3 * i] = 0;
        fan16[3 * i + 1] = (GLushort)(1 + i);
        fan16[3 * i + 2] = (GLushort)(1 + (i + 1) % 7);
    }
    for (i = 0; i < 10; i++) {
        strip8[i] = (GLubyte)i;
        strip_bias8[i] = (GLubyte)(i + 30);
        strip32[i] = (GLuint)i;
    }
    for (i = 0; i < 9; i++) {
        tris16[i] = (GLushort)i;
        tris_bias8[i] = (GLubyte)(i + 100);
    }

    vbo = vert_color_vbo(v, sizeof v, sizeof v[0]);
    glGenBuffers(1, &ebo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, 1024, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, OFF_GRID8, sizeof grid8, grid8);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, OFF_FAN16, sizeof fan16, fan16);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, OFF_STRIP32, sizeof strip32, strip32);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, OFF_BIAS32, sizeof grid_bias32, grid_bias32);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, OFF_GRID16, sizeof grid16, grid16);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, OFF_TRIS16, sizeof tris16, tris16);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

static void begin(void)
{
    vert_begin_ortho(FW, FH);
}

#define EB(off) ((const void *)(size_t)(off))

static void draw(const GLuint *progs, int n)
{
    static const GLsizei mc[3] = {54, 21, 9}, sc[4] = {10, 0, 10, 10};
    static const GLint mb[3] = {2 * SET, 16, SET + 34};
    static const GLint sb[4] = {24, 7, SET + 24, 2 * SET + 24 - 30};
    const void *mi[3] = {EB(OFF_GRID16), EB(OFF_FAN16), EB(OFF_TRIS16)};
    const void *si[4] = {strip8, grid8, strip8, strip_bias8};
    (void)progs;
    (void)n;
    begin();
    /* top row: one mesh per column, from the element buffer and client memory */
    glTranslatef(0.0f, 85.0f, 0.0f);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    glDrawElementsBaseVertex(GL_TRIANGLES, 54, GL_UNSIGNED_BYTE, EB(OFF_GRID8), 0);
    glDrawElementsBaseVertex(GL_TRIANGLES, 21, GL_UNSIGNED_SHORT, EB(OFF_FAN16), SET + 16);
    glDrawElementsBaseVertex(GL_TRIANGLE_STRIP, 10, GL_UNSIGNED_INT, EB(OFF_STRIP32),
                             2 * SET + 24);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glDrawElementsBaseVertex(GL_TRIANGLES, 9, GL_UNSIGNED_SHORT, tris16, 34);
    /* middle row: negative bases on biased indices, then range draws */
    glLoadIdentity();
    glTranslatef(0.0f, 42.5f, 0.0f);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    glDrawElementsBaseVertex(GL_TRIANGLES, 54, GL_UNSIGNED_INT, EB(OFF_BIAS32), -200);
    glDrawRangeElementsBaseVertex(GL_TRIANGLES, 0, 7, 21, GL_UNSIGNED_SHORT, EB(OFF_FAN16),
                                  SET + 16);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glDrawElementsBaseVertex(GL_TRIANGLES, 9, GL_UNSIGNED_BYTE, tris_bias8, SET + 34 - 100);
    glDrawRangeElementsBaseVertex(GL_TRIANGLE_STRIP, 0, 9, 10, GL_UNSIGNED_INT, strip32,
                                  2 * SET + 24);
    glDrawRangeElementsBaseVertex(GL_TRIANGLES, 100, 108, 9, GL_UNSIGNED_BYTE, tris_bias8,
                                  2 * SET + 34 - 100);
    /* bottom row: multi draws, element buffer then client pointers */
    glLoadIdentity();
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    glMultiDrawElementsBaseVertex(GL_TRIANGLES, mc, GL_UNSIGNED_SHORT, mi, 3, mb);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glTranslatef(0.0f, 4.3f, 0.1f);
    glMultiDrawElementsBaseVertex(GL_TRIANGLE_STRIP, sc, GL_UNSIGNED_BYTE, si, 4, sb);
    glLoadIdentity();
}

static void errors(void)
{
    static const GLsizei badc[2] = {9, -1}, okc[2] = {9, 9};
    static const GLint base[2] = {34, SET + 34};
    const void *ind[2] = {tris16, tris16};
    begin();
    glTranslatef(0.0f, 42.5f, 0.0f);
    E(glDrawElementsBaseVertex(GL_TRIANGLES, -1, GL_UNSIGNED_SHORT, grid16, 0));
    E(glDrawElementsBaseVertex(0x7777, 54, GL_UNSIGNED_SHORT, grid16, 0));
    E(glDrawElementsBaseVertex(GL_TRIANGLES, 54, GL_FLOAT, grid16, 0));
    E(glDrawElementsBaseVertex(GL_TRIANGLES, 54, GL_SHORT, grid16, 0));
    E(glDrawRangeElementsBaseVertex(GL_TRIANGLES, 9, 0, 54, GL_UNSIGNED_SHORT, grid16, SET));
    E(glDrawRangeElementsBaseVertex(GL_TRIANGLES, 0, 15, -3, GL_UNSIGNED_SHORT, grid16, SET));
    E(glDrawRangeElementsBaseVertex(GL_TRIANGLES, 0, 15, 54, GL_BYTE, grid16, SET));
    E(glMultiDrawElementsBaseVertex(GL_TRIANGLES, badc, GL_UNSIGNED_SHORT, ind, 2, base));
    E(glMultiDrawElementsBaseVertex(GL_TRIANGLES, okc, GL_UNSIGNED_SHORT, ind, -1, base));
    E(glMultiDrawElementsBaseVertex(0x7777, okc, GL_UNSIGNED_SHORT, ind, 2, base));
    E(glMultiDrawElementsBaseVertex(GL_TRIANGLES, okc, GL_UNSIGNED_SHORT, ind, 0, base));
    /* the one valid draw: the middle column's grid */
    E(glDrawElementsBaseVertex(GL_TRIANGLES, 54, GL_UNSIGNED_SHORT, grid16, SET));
    glLoadIdentity();
}

int main(int argc, char **argv)
{
    static unsigned char rb[FW * FH * 4];
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    out = sgl_open(argc, argv);
    setup();
    frag_window_and_fbo(out, buf, rb, draw, NULL, 0);
    errors();
    frag_output(out, "errors", buf);
    return sgl_end_scene(ctx, buf);
}
