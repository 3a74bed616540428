/* vert_int_attribs: GL 3.0 integer vertex attributes (EXT_gpu_shader4). A
 * #version 130 vertex shader reads `in ivec4/uvec4/ivec2/uvec3/int/uvec2/ivec4/
 * uint` attributes and reduces them by integer arithmetic and bit operations
 * (shifts of negative values, `%` of uints, `int(-3)` from a GL_BYTE, 16777217
 * and 2^31 - 1 compared with ==, unsigned compares above 2^31) to float colours,
 * constant over each quad, so every pixel is a function of the integers; a
 * wrong component flips a channel. glVertexAttribIPointer of BYTE, UNSIGNED_BYTE,
 * SHORT, UNSIGNED_SHORT, INT and UNSIGNED_INT, sizes 1-4, interleaved (stride 48,
 * padding bytes between components that must not be read), tight and at offsets
 * in a buffer, and one array in client memory (vertex array object 0 only);
 * size-2 arrays read by an ivec4 as (x, y, 0, 1), size-3 ones by a uvec4 as
 * (x, y, z, 1). glDrawArrays of GL_QUADS in object 0 (top); glDrawElements of
 * triangles in a named object with arrays at a base offset and one attribute
 * disabled (bottom left); eight quads with every integer array disabled, each
 * drawn after some glVertexAttribI* current values change (1-4 component,
 * vector, byte/short forms, negative and above 2^31; bottom right). Queries of
 * current values (glGetVertexAttribIiv/Iuiv), GL_VERTEX_ATTRIB_ARRAY_INTEGER of
 * integer and float arrays, the type/size/stride/pointer of integer arrays, and
 * errors of glVertexAttribIPointer and glVertexAttribI4i. Window and
 * framebuffer object. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <stddef.h>
#include "errcheck.h"
#include "vert_program.h"

static const char *VS =
    "#version 130\n"
    "in vec2 pos;\n"
    "in ivec4 bv;\n"  /* GL_BYTE, 4 */
    "in uvec4 ubv;\n" /* GL_UNSIGNED_BYTE, 3: w reads 1 */
    "in ivec2 sv;\n"  /* GL_SHORT, 2 */
    "in uvec3 usv;\n" /* GL_UNSIGNED_SHORT, 3 */
    "in int iv;\n"    /* GL_INT, 1 */
    "in uvec2 uv;\n"  /* GL_UNSIGNED_INT, 2 */
    "in ivec4 mv;\n"  /* GL_SHORT or GL_INT, 2: reads (x, y, 0, 1) */
    "in uint cv;\n"   /* GL_UNSIGNED_SHORT, 1, client memory */
    "out vec4 col;\n"
    "void main() {\n"
    "  gl_Position = gl_ModelViewProjectionMatrix * vec4(pos, 0.0, 1.0);\n"
    "  int r = ((bv.x & 0xF0) >> 4) | ((bv.y & 3) << 4) | (bv.z < 0 ? 64 : 0)\n"
    "        | (bv.w == int(-3) ? 128 : 0);\n"
    "  r ^= int(((ubv.x >> 3u) ^ (ubv.y * 5u) ^ (ubv.z << 1u)) & 63u);\n"
    "  r ^= ubv.w == 1u ? 0 : 255;\n"
    "  int g = ((sv.x >> 9) & 15) | (sv.y < -1000 ? 16 : 0) | (int(usv.y % 7u) << 5);\n"
    "  g ^= int((usv.x >> 12u) ^ (usv.z & 15u));\n"
    "  g ^= (mv.x & 7) | ((mv.y & 3) << 3) | (-mv.x < 0 ? 0 : 32);\n"
    "  g ^= (mv.z == 0 && mv.w == 1) ? 0 : 255;\n"
    "  int b = (iv & 63) | (iv == 16777217 ? 64 : 0) | (iv < 0 ? 128 : 0);\n"
    "  b ^= (iv == 2147483647 || iv == -2147483647 - 1) ? 0x55 : 0;\n"
    "  b ^= int(uv.x >> 28u) | (int(uv.y % 7u) << 4) | (uv.x > 3000000000u ? 128 : 0);\n"
    "  b ^= int((cv % 13u) * 3u) & 31;\n"
    "  col = vec4(float(r & 255), float(g & 255), float(b & 255), 255.0) / 255.0;\n"
    "}\n";

static const char *FS =
    "#version 130\n"
    "in vec4 col;\n"
    "out vec4 o;\n"
    "void main() {\n"
    "  o = col;\n"
    "}\n";

typedef struct {
    GLfloat pos[2];  /* 0 */
    GLbyte b[4];     /* 8 */
    GLubyte ub[3];   /* 12 */
    GLubyte pad0;    /* 15: never read */
    GLshort s[2];    /* 16 */
    GLushort us[3];  /* 20 */
    GLushort pad1;   /* 26: never read */
    GLint i;         /* 28 */
    GLuint u[2];     /* 32 */
    GLint m[2];      /* 40 */
} Vtx;               /* 48 bytes */

#define N1 24 /* quads of the glDrawArrays draw (6 x 4, top) */
#define N2 16 /* quads of the glDrawElements draw (4 x 4, bottom left) */
#define N3 8  /* current-value quads (2 x 4, bottom right) */
#define NV (4 * (N1 + N2 + N3))
#define MT_OFF (NV * sizeof(Vtx) + 4) /* the tight GL_SHORT size-2 array */

static GLuint prog, vbo, ebo, vao;
static GLushort client_cv[4 * N1];

static GLuint hash(GLuint x)
{
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}

/* four corners of quad k of a cols-wide grid at (x, y) with cells w x h */
static void quad(Vtx *v, int k, int cols, float x, float y, float w, float h)
{
    float x0 = x + (float)(k % cols) * w + 0.37f, y0 = y + (float)(k / cols) * h + 0.4f;
    float x1 = x0 + w - 1.3f, y1 = y0 + h - 1.2f;
    v[0].pos[0] = x0; v[0].pos[1] = y0;
    v[1].pos[0] = x1; v[1].pos[1] = y0;
    v[2].pos[0] = x1; v[2].pos[1] = y1;
    v[3].pos[0] = x0; v[3].pos[1] = y1;
}

static void setup(void)
{
    static const GLint ispecial[8] = {16777217, 16777216, -16777217, 2147483647,
                                      -2147483647 - 1, -1, 0, 123456789};
    static const GLuint uspecial[6] = {4000000000u, 4294967295u, 16777217u, 2147483648u,
                                       3000000000u, 3000000001u};
    static Vtx v[NV];
    static GLshort mt[4 * N1][2];
    static GLushort idx[6 * N2];
    int c, k, j;
    for (c = 0; c < N1 + N2 + N3; c++) {
        Vtx d;
        GLuint h = hash((GLuint)c * 977u + 13u);
        memset(&d, 0, sizeof d);
        for (j = 0; j < 4; j++)
            d.b[j] = (GLbyte)((int)(hash(h + (GLuint)j) & 0xFF) - 128);
        if (c % 3 != 2)
            d.b[3] = -3;
        for (j = 0; j < 3; j++)
            d.ub[j] = (GLubyte)(hash(h ^ (GLuint)(j + 40)) & 0xFF);
        d.pad0 = 77;
        d.s[0] = (GLshort)((int)(hash(h + 7u) & 0xFFFF) - 32768);
        d.s[1] = (GLshort)((int)(hash(h + 8u) & 0x1FFF) - 4096);
        for (j = 0; j < 3; j++)
            d.us[j] = (GLushort)(hash(h ^ (GLuint)(j + 90)) & 0xFFFF);
        d.pad1 = 0xBEEF;
        d.i = c < N1 ? (c < 8 ? ispecial[c] : (GLint)(hash(h + 20u) & 0x7FFFFFFF) - 1000000000)
                     : (c - N1 < 8 ? ispecial[7 - (c - N1)] : -(c * 1000003));
        d.u[0] = c % 8 < 6 ? uspecial[c % 8] : hash(h + 30u);
        d.u[1] = hash(h + 31u);
        d.m[0] = (GLint)(hash(h + 50u) % 200u) - 100;
        d.m[1] = c - 20;
        for (k = 0; k < 4; k++)
            v[4 * c + k] = d;
        if (c < N1)
            quad(v + 4 * c, c, 6, 2.0f, 66.0f, 20.6f, 15.0f);
        else if (c < N1 + N2)
            quad(v + 4 * c, c - N1, 4, 2.0f, 2.0f, 15.0f, 15.0f);
        else
            quad(v + 4 * c, c - N1 - N2, 2, 66.0f, 2.0f, 30.0f, 15.0f);
        if (c < N1)
            for (k = 0; k < 4; k++) {
                mt[4 * c + k][0] = (GLshort)(-c * 37 + 5);
                mt[4 * c + k][1] = (GLshort)(c * 1234 - 9000);
                client_cv[4 * c + k] = (GLushort)(hash(h + 60u) & 0xFFFF);
            }
    }
    for (c = 0; c < N2; c++) { /* quads in reverse order, vertices from N1 * 4 on */
        GLushort q = (GLushort)(4 * (N2 - 1 - c));
        idx[6 * c + 0] = q; idx[6 * c + 1] = (GLushort)(q + 1); idx[6 * c + 2] = (GLushort)(q + 2);
        idx[6 * c + 3] = q; idx[6 * c + 4] = (GLushort)(q + 2); idx[6 * c + 5] = (GLushort)(q + 3);
    }
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, MT_OFF + sizeof mt, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof v, v);
    glBufferSubData(GL_ARRAY_BUFFER, MT_OFF, sizeof mt, mt);

    /* object 0: interleaved arrays, the tight mt array, cv from client memory */
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vtx), (void *)0);
    glVertexAttribIPointer(1, 4, GL_BYTE, sizeof(Vtx), (void *)offsetof(Vtx, b));
    glVertexAttribIPointer(2, 3, GL_UNSIGNED_BYTE, sizeof(Vtx), (void *)offsetof(Vtx, ub));
    glVertexAttribIPointer(3, 2, GL_SHORT, sizeof(Vtx), (void *)offsetof(Vtx, s));
    glVertexAttribIPointer(4, 3, GL_UNSIGNED_SHORT, sizeof(Vtx), (void *)offsetof(Vtx, us));
    glVertexAttribIPointer(5, 1, GL_INT, sizeof(Vtx), (void *)offsetof(Vtx, i));
    glVertexAttribIPointer(6, 2, GL_UNSIGNED_INT, sizeof(Vtx), (void *)offsetof(Vtx, u));
    glVertexAttribIPointer(7, 2, GL_SHORT, 0, (void *)MT_OFF);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glVertexAttribIPointer(8, 1, GL_UNSIGNED_SHORT, 0, client_cv);

    /* a named object: the arrays from vertex N1 * 4 on, mv from GL_INT, cv disabled */
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
#define AT(field) (void *)(4 * N1 * sizeof(Vtx) + offsetof(Vtx, field))
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(Vtx), AT(pos));
    glVertexAttribIPointer(1, 4, GL_BYTE, sizeof(Vtx), AT(b));
    glVertexAttribIPointer(2, 3, GL_UNSIGNED_BYTE, sizeof(Vtx), AT(ub));
    glVertexAttribIPointer(3, 2, GL_SHORT, sizeof(Vtx), AT(s));
    glVertexAttribIPointer(4, 3, GL_UNSIGNED_SHORT, sizeof(Vtx), AT(us));
    glVertexAttribIPointer(5, 1, GL_INT, sizeof(Vtx), AT(i));
    glVertexAttribIPointer(6, 2, GL_UNSIGNED_INT, sizeof(Vtx), AT(u));
    glVertexAttribIPointer(7, 2, GL_INT, sizeof(Vtx), AT(m));
    for (k = 0; k < 8; k++)
        glEnableVertexAttribArray((GLuint)k);
    glGenBuffers(1, &ebo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx, idx, GL_STATIC_DRAW);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

/* the current values of cell k of the bottom-right block, changed before its draw */
static void current_values(int k)
{
    static const GLint m0[4] = {5, -6, 0, 1}, i1 = 2147483647, s3[2] = {-32768, -1001},
                       m5[3] = {-7, 3, 0};
    static const GLbyte b1[4] = {-3, -128, 127, -3};
    static const GLubyte ub2[4] = {255, 0, 128, 1}, ub6[4] = {9, 99, 199, 1};
    static const GLushort us2[4] = {65535, 7, 12, 999}, us7[4] = {300, 301, 302, 303};
    static const GLshort s7[4] = {-512, -2000, 4, 4};
    static const GLuint u3[4] = {4000000000u, 13u, 0u, 1u}, cv3 = 4294967295u,
                        u6[2] = {2147483648u, 6u}, us6[3] = {4096, 8, 4095};
    switch (k) {
    case 0: /* every attribute */
        glVertexAttribI4i(1, -3, 100, -128, -3);
        glVertexAttribI4ui(2, 200, 7, 255, 1);
        glVertexAttribI2i(3, -5000, 32767);
        glVertexAttribI3ui(4, 65535, 20, 3);
        glVertexAttribI1i(5, 16777217);
        glVertexAttribI2ui(6, 4000000000u, 20);
        glVertexAttribI4iv(7, m0);
        glVertexAttribI1ui(8, 0xFFFFFFFFu);
        break;
    case 1: glVertexAttribI4bv(1, b1); glVertexAttribI1i(7, -77); glVertexAttribI1iv(5, &i1); break;
    case 2: glVertexAttribI4usv(4, us2); glVertexAttribI4ubv(2, ub2); glVertexAttribI2iv(3, s3); break;
    case 3: /* m.z = 3: the check flips green */
        glVertexAttribI3i(7, 1, 2, 3); glVertexAttribI4uiv(6, u3); glVertexAttribI1uiv(8, &cv3);
        break;
    case 4: glVertexAttribI2ui(6, 16777217u, 6u); glVertexAttribI1i(5, 16777216); break;
    case 5: glVertexAttribI4i(1, -1, -2, -3, -4); glVertexAttribI3iv(7, m5); glVertexAttribI1i(5, -9); break;
    case 6: glVertexAttribI4ubv(2, ub6); glVertexAttribI2uiv(6, u6); glVertexAttribI3uiv(4, us6); break;
    default: /* ubv.w = 303: the check flips red */
        glVertexAttribI4usv(2, us7); glVertexAttribI4sv(3, s7); glVertexAttribI2i(7, -32, 33);
        break;
    }
}

static void draw(const GLuint *progs, int n)
{
    int k;
    (void)progs;
    (void)n;
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, FW, 0.0, FH, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glUseProgram(prog);
    /* object 0: every array, cv from client memory */
    for (k = 0; k < 9; k++)
        glEnableVertexAttribArray((GLuint)k);
    glDrawArrays(GL_QUADS, 0, 4 * N1);
    /* the named object: cv from its current value */
    glVertexAttribI1ui(8, 40000u);
    glBindVertexArray(vao);
    glDrawElements(GL_TRIANGLES, 6 * N2, GL_UNSIGNED_SHORT, (void *)0);
    glBindVertexArray(0);
    /* object 0 with only the positions enabled: current values */
    for (k = 1; k < 9; k++)
        glDisableVertexAttribArray((GLuint)k);
    for (k = 0; k < N3; k++) {
        current_values(k);
        glDrawArrays(GL_QUADS, 4 * (N1 + N2 + k), 4);
    }
    glUseProgram(0);
}

static void queries(void)
{
    GLint maxa = 0, iv[4], ty = -7, sz = -7, st = -7, nm = -7, bb = -7, in[4];
    GLuint uv[4];
    void *p = NULL;
    int k;
    glGetIntegerv(GL_MAX_VERTEX_ATTRIBS, &maxa);
    sgl_text(out, "query", "GL_MAX_VERTEX_ATTRIBS %d\n", maxa);
    glVertexAttribI4i(9, -5, 6, -7, 8);
    glVertexAttribI4ui(10, 4000000000u, 1u, 2147483648u, 4294967295u);
    glVertexAttribI1i(11, -9);
    glVertexAttribI2ui(12, 3000000000u, 7u);
    glGetVertexAttribIiv(9, GL_CURRENT_VERTEX_ATTRIB, iv);
    glGetVertexAttribIuiv(10, GL_CURRENT_VERTEX_ATTRIB, uv);
    sgl_text(out, "query", "I4i(9) Iiv %d %d %d %d; I4ui(10) Iuiv %u %u %u %u\n", iv[0], iv[1],
             iv[2], iv[3], uv[0], uv[1], uv[2], uv[3]);
    glGetVertexAttribIiv(11, GL_CURRENT_VERTEX_ATTRIB, iv);
    glGetVertexAttribIuiv(12, GL_CURRENT_VERTEX_ATTRIB, uv);
    sgl_text(out, "query", "I1i(11) Iiv %d %d %d %d; I2ui(12) Iuiv %u %u %u %u\n", iv[0], iv[1],
             iv[2], iv[3], uv[0], uv[1], uv[2], uv[3]);
    for (k = 0; k < 4; k++) {
        in[k] = -7;
        glGetVertexAttribiv((GLuint)(k < 3 ? k * 3 : 8), GL_VERTEX_ATTRIB_ARRAY_INTEGER, &in[k]);
    }
    sgl_text(out, "query", "ARRAY_INTEGER attrib 0 (float) %d, 3 %d, 6 %d, 8 (client) %d\n",
             in[0], in[1], in[2], in[3]);
    glGetVertexAttribiv(6, GL_VERTEX_ATTRIB_ARRAY_TYPE, &ty);
    glGetVertexAttribiv(6, GL_VERTEX_ATTRIB_ARRAY_SIZE, &sz);
    glGetVertexAttribiv(6, GL_VERTEX_ATTRIB_ARRAY_STRIDE, &st);
    glGetVertexAttribiv(6, GL_VERTEX_ATTRIB_ARRAY_NORMALIZED, &nm);
    glGetVertexAttribiv(6, GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, &bb);
    glGetVertexAttribPointerv(6, GL_VERTEX_ATTRIB_ARRAY_POINTER, &p);
    sgl_text(out, "query", "attrib 6 type 0x%04x size %d stride %d normalized %d buffer %d (vbo %u) "
             "pointer %lu\n", ty, sz, st, nm, bb, vbo, (unsigned long)(size_t)p);
    glGetVertexAttribiv(7, GL_VERTEX_ATTRIB_ARRAY_TYPE, &ty);
    glGetVertexAttribiv(7, GL_VERTEX_ATTRIB_ARRAY_SIZE, &sz);
    glGetVertexAttribiv(7, GL_VERTEX_ATTRIB_ARRAY_STRIDE, &st);
    glGetVertexAttribPointerv(7, GL_VERTEX_ATTRIB_ARRAY_POINTER, &p);
    sgl_text(out, "query", "attrib 7 type 0x%04x size %d stride %d pointer %lu\n", ty, sz, st,
             (unsigned long)(size_t)p);
    glGetVertexAttribiv(8, GL_VERTEX_ATTRIB_ARRAY_TYPE, &ty);
    glGetVertexAttribiv(8, GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, &bb);
    glGetVertexAttribPointerv(8, GL_VERTEX_ATTRIB_ARRAY_POINTER, &p);
    sgl_text(out, "query", "attrib 8 type 0x%04x buffer %d pointer is client_cv %d\n", ty, bb,
             p == (void *)client_cv);
    /* a float pointer on an integer attribute clears the flag, an integer one sets it */
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glVertexAttribPointer(13, 2, GL_SHORT, GL_FALSE, 0, (void *)0);
    glGetVertexAttribiv(13, GL_VERTEX_ATTRIB_ARRAY_INTEGER, &in[0]);
    glVertexAttribIPointer(13, 2, GL_SHORT, 0, (void *)0);
    glGetVertexAttribiv(13, GL_VERTEX_ATTRIB_ARRAY_INTEGER, &in[1]);
    glVertexAttribPointer(13, 2, GL_SHORT, GL_FALSE, 0, (void *)0);
    glGetVertexAttribiv(13, GL_VERTEX_ATTRIB_ARRAY_INTEGER, &in[2]);
    sgl_text(out, "query", "attrib 13 ARRAY_INTEGER float %d int %d float %d\n", in[0], in[1],
             in[2]);

    E(glVertexAttribIPointer(13, 2, GL_FLOAT, 0, (void *)0));
    E(glVertexAttribIPointer(13, 2, GL_DOUBLE, 0, (void *)0));
    E(glVertexAttribIPointer(13, 5, GL_INT, 0, (void *)0));
    E(glVertexAttribIPointer(13, 0, GL_INT, 0, (void *)0));
    E(glVertexAttribIPointer(13, 2, GL_INT, -4, (void *)0));
    E(glVertexAttribIPointer((GLuint)maxa, 2, GL_INT, 0, (void *)0));
    E(glVertexAttribI4i((GLuint)maxa, 1, 2, 3, 4));
    E(glVertexAttribI4ui((GLuint)maxa, 1, 2, 3, 4));
    E(glGetVertexAttribIiv((GLuint)maxa, GL_CURRENT_VERTEX_ATTRIB, iv));
    E(glVertexAttribIPointer(13, 2, GL_UNSIGNED_INT, 8, (void *)16));
    glGetVertexAttribiv(13, GL_VERTEX_ATTRIB_ARRAY_TYPE, &ty);
    glGetVertexAttribiv(13, GL_VERTEX_ATTRIB_ARRAY_SIZE, &sz);
    glGetVertexAttribiv(13, GL_VERTEX_ATTRIB_ARRAY_STRIDE, &st);
    sgl_text(out, "query", "attrib 13 after the errors type 0x%04x size %d stride %d\n", ty, sz, st);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindVertexArray(vao); /* a client pointer in a named object */
    E(glVertexAttribIPointer(13, 1, GL_UNSIGNED_SHORT, 0, client_cv));
    glBindVertexArray(0);
}

int main(int argc, char **argv)
{
    static const char *names[] = {"pos", "bv", "ubv", "sv", "usv", "iv", "uv", "mv", "cv", NULL};
    static unsigned char rb[FW * FH * 4];
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    out = sgl_open(argc, argv);
    prog = vert_program(VS, FS, names);
    vert_scene_body(out, buf, rb, setup, draw, queries);
    return sgl_end_scene(ctx, buf);
}
