/* vao_switch: ARB_vertex_array_object in a compatibility context. Three vertex
 * array objects of different layouts: built-in arrays interleaved in a buffer
 * with GL_UNSIGNED_SHORT indices in an element buffer; built-in vertex and
 * texture-coordinate and colour arrays in another buffer (a client-memory
 * pointer is refused there), GL_UNSIGNED_BYTE indices in an element buffer, drawn by fixed
 * function and by a vertex shader reading gl_MultiTexCoord0; generic
 * attributes (glVertexAttribPointer) with GL_UNSIGNED_INT indices for a
 * program. The element buffer binding is object state, GL_ARRAY_BUFFER is not;
 * switching between the objects and back to object 0, whose client arrays and
 * client indices (no element buffer) must be untouched. Queries and errors:
 * glIsVertexArray before and after the first bind and after deletion,
 * GL_VERTEX_ARRAY_BINDING, GL_ELEMENT_ARRAY_BUFFER_BINDING and
 * GL_ARRAY_BUFFER_BINDING per object, glIsEnabled of the client arrays and
 * GL_VERTEX_ATTRIB_ARRAY_ENABLED per object, binding a never generated or a
 * deleted name, glGenVertexArrays/glDeleteVertexArrays(-1), deleting the bound
 * object (the binding reverts to 0). Window and framebuffer object. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <math.h>
#define FW 96
#define FH 96
#include "errcheck.h"
#include "vert_program.h"

static const char *VS_T =
    "#version 120\n"
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  gl_FrontColor = vec4(gl_MultiTexCoord0.xy, gl_Color.b * 0.5, 1.0);\n"
    "}\n";

static const char *VS_G =
    "#version 120\n"
    "attribute vec3 pos;\n"
    "attribute vec4 col;\n"
    "attribute float k;\n"
    "void main() {\n"
    "  gl_Position = gl_ModelViewProjectionMatrix * vec4(pos, 1.0);\n"
    "  gl_FrontColor = vec4(col.rgb * k, 1.0);\n"
    "}\n";

#define GN 5 /* grid of GN x GN vertices in object 1 */

static GLuint vao[4], buf_a, buf_b, buf_c, ebo_a, ebo_b, ebo_c, buf_other;
static GLuint prog_t, prog_g;
static GLubyte client_col[8][4];
static GLfloat v0_pos[6][3];
static GLubyte v0_col[6][4];
static const GLushort v0_idx[9] = {0, 1, 2, 3, 4, 5, 1, 3, 5};

static void setup(void)
{
    static GLfloat grid[GN * GN][6];
    static GLushort gidx[(GN - 1) * (GN - 1) * 6];
    static GLfloat star[8][4]; /* x, y, s, t */
    static const GLubyte sidx[18] = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5, 0, 5, 6, 0, 6, 7};
    static GLfloat ring[16][7]; /* pos xyz, col rgba */
    static GLuint ridx[8 * 6];
    static const GLfloat k[16] = {1.0f, 0.9f, 0.8f, 0.7f, 0.6f, 0.5f, 0.4f, 0.3f,
                                  1.0f, 0.8f, 0.6f, 0.4f, 0.9f, 0.7f, 0.5f, 0.3f};
    int i, j, n = 0;

    for (j = 0; j < GN; j++)
        for (i = 0; i < GN; i++) {
            GLfloat *v = grid[j * GN + i];
            v[0] = 3.37f + i * 10.61f + ((i + j) % 3) * 0.71f;
            v[1] = 50.21f + j * 10.43f;
            v[2] = 0.4f - 0.1f * i;
            v[3] = i / (GN - 1.0f);
            v[4] = j / (GN - 1.0f);
            v[5] = 0.3f + 0.1f * ((i * j) % 5);
        }
    for (j = 0; j < GN - 1; j++)
        for (i = 0; i < GN - 1; i++) {
            GLushort a = (GLushort)(j * GN + i), b = (GLushort)(a + 1), c = (GLushort)(a + GN),
                     d = (GLushort)(c + 1);
            gidx[n++] = a; gidx[n++] = b; gidx[n++] = c;
            gidx[n++] = b; gidx[n++] = d; gidx[n++] = c;
        }
    star[0][0] = 72.3f; star[0][1] = 72.1f; star[0][2] = 0.5f; star[0][3] = 0.5f;
    for (i = 1; i < 8; i++) {
        float a = 6.2831853f * (i - 1) / 6.5f + 0.3f, r = (i & 1) ? 21.7f : 13.1f;
        star[i][0] = 72.3f + r * cosf(a);
        star[i][1] = 72.1f + r * sinf(a);
        star[i][2] = 0.5f + 0.5f * cosf(a);
        star[i][3] = 0.5f + 0.5f * sinf(a);
        client_col[i][0] = (GLubyte)(30 * i);
        client_col[i][1] = (GLubyte)(250 - 30 * i);
        client_col[i][2] = (GLubyte)(i & 1 ? 255 : 90);
        client_col[i][3] = 255;
    }
    client_col[0][0] = client_col[0][1] = client_col[0][2] = client_col[0][3] = 255;
    for (i = 0; i < 16; i++) {
        float a = 6.2831853f * (i / 2) / 8.0f + 0.13f, r = (i & 1) ? 9.3f : 22.6f;
        ring[i][0] = 25.1f + r * cosf(a);
        ring[i][1] = 24.7f + r * sinf(a);
        ring[i][2] = (i & 1) ? -0.5f : 0.5f;
        ring[i][3] = 0.5f + 0.5f * cosf(a);
        ring[i][4] = 0.5f + 0.5f * sinf(a);
        ring[i][5] = (i & 1) ? 1.0f : 0.2f;
        ring[i][6] = 1.0f;
    }
    for (i = 0, n = 0; i < 8; i++) {
        GLuint a = 2 * i, b = 2 * i + 1, c = (2 * i + 2) % 16, d = (2 * i + 3) % 16;
        ridx[n++] = a; ridx[n++] = c; ridx[n++] = b;
        ridx[n++] = b; ridx[n++] = c; ridx[n++] = d;
    }
    for (i = 0; i < 6; i++) {
        float a = 6.2831853f * i / 6.0f + 0.2f;
        v0_pos[i][0] = 71.3f + (i & 1 ? 23.9f : 14.2f) * cosf(a);
        v0_pos[i][1] = 24.6f + (i & 1 ? 23.9f : 14.2f) * sinf(a);
        v0_pos[i][2] = 0.2f * (i % 3) - 0.2f;
        v0_col[i][0] = (GLubyte)(i * 50);
        v0_col[i][1] = (GLubyte)(i & 1 ? 40 : 220);
        v0_col[i][2] = (GLubyte)(255 - i * 40);
        v0_col[i][3] = 255;
    }

    glGenBuffers(1, &buf_a); glGenBuffers(1, &buf_b); glGenBuffers(1, &buf_c);
    glGenBuffers(1, &ebo_a); glGenBuffers(1, &ebo_b); glGenBuffers(1, &ebo_c);
    glGenBuffers(1, &buf_other);
    glBindBuffer(GL_ARRAY_BUFFER, buf_other);
    glBufferData(GL_ARRAY_BUFFER, 64, NULL, GL_STATIC_DRAW);

    /* object 0: client arrays, client indices */
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glVertexPointer(3, GL_FLOAT, 0, v0_pos);
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, v0_col);

    glGenVertexArrays(4, vao);
    /* object 1: interleaved built-in arrays, ushort element buffer */
    glBindVertexArray(vao[0]);
    glBindBuffer(GL_ARRAY_BUFFER, buf_a);
    glBufferData(GL_ARRAY_BUFFER, sizeof grid, grid, GL_STATIC_DRAW);
    glVertexPointer(3, GL_FLOAT, sizeof grid[0], (void *)0);
    glColorPointer(3, GL_FLOAT, sizeof grid[0], (void *)(3 * sizeof(GLfloat)));
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_a);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof gidx, gidx, GL_STATIC_DRAW);

    /* object 2: vertex + texcoord from a buffer; a colour array in client memory is
     * refused in a named object (Mesa applies ARB_vertex_array_object's
     * INVALID_OPERATION in compatibility contexts too), so the colours go after the
     * vertices in the same buffer */
    glBindVertexArray(vao[1]);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    E(glColorPointer(4, GL_UNSIGNED_BYTE, 0, client_col));
    E(glColorPointer(4, GL_UNSIGNED_BYTE, 0, NULL));
    glBindBuffer(GL_ARRAY_BUFFER, buf_b);
    glBufferData(GL_ARRAY_BUFFER, sizeof star + sizeof client_col, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof star, star);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof star, sizeof client_col, client_col);
    glVertexPointer(2, GL_FLOAT, sizeof star[0], (void *)0);
    glTexCoordPointer(2, GL_FLOAT, sizeof star[0], (void *)(2 * sizeof(GLfloat)));
    glColorPointer(4, GL_UNSIGNED_BYTE, 0, (void *)sizeof star);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_b);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof sidx, sidx, GL_STATIC_DRAW);

    /* object 3: generic attributes, uint element buffer; 2 set after a detour */
    glBindVertexArray(vao[2]);
    glBindBuffer(GL_ARRAY_BUFFER, buf_c);
    glBufferData(GL_ARRAY_BUFFER, sizeof ring + sizeof k, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof ring, ring);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof ring, sizeof k, k);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof ring[0], (void *)0);
    glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof ring[0], (void *)(3 * sizeof(GLfloat)));
    glEnableVertexAttribArray(0);
    glEnableVertexAttribArray(1);
    glBindVertexArray(0); /* a detour: object 0 keeps its state */
    glBindVertexArray(vao[2]);
    glBindBuffer(GL_ARRAY_BUFFER, buf_c); /* still buf_c: not object state */
    glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, 0, (void *)sizeof ring);
    glEnableVertexAttribArray(2);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_c);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof ridx, ridx, GL_STATIC_DRAW);

    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, buf_other);
}

static void draw(const GLuint *progs, int n)
{
    (void)progs;
    (void)n;
    vert_begin_ortho(FW, FH);

    glBindVertexArray(vao[0]);
    glDrawElements(GL_TRIANGLES, (GN - 1) * (GN - 1) * 6, GL_UNSIGNED_SHORT, (void *)0);
    glBindVertexArray(vao[1]);
    glDrawElements(GL_TRIANGLES, 18, GL_UNSIGNED_BYTE, (void *)0);
    glUseProgram(prog_t);
    glTranslatef(-9.13f, -5.31f, -0.3f);
    glDrawElements(GL_TRIANGLES, 9, GL_UNSIGNED_BYTE, (void *)9);
    glLoadIdentity();
    glBindVertexArray(vao[2]);
    glUseProgram(prog_g);
    glDrawElements(GL_TRIANGLES, 8 * 6, GL_UNSIGNED_INT, (void *)0);
    glUseProgram(0);
    /* object 0: client indices work only if no element buffer is bound */
    glBindVertexArray(0);
    glDrawElements(GL_TRIANGLES, 9, GL_UNSIGNED_SHORT, v0_idx);
    glTranslatef(-30.7f, 3.3f, 0.0f);
    glDrawArrays(GL_TRIANGLES, 3, 3);
    glLoadIdentity();
    /* back to object 1: half of its grid again, shifted, over everything */
    glBindVertexArray(vao[0]);
    glTranslatef(37.3f, -31.1f, -0.9f);
    glDrawElements(GL_TRIANGLES, 24, GL_UNSIGNED_SHORT, (void *)(24 * sizeof(GLushort)));
    glLoadIdentity();
    glBindVertexArray(0);
}

static void q(const char *what, GLenum pname)
{
    GLint v = -7;
    glGetIntegerv(pname, &v);
    sgl_text(out, "query", "%-44s %d\n", what, v);
}

static void per_object(const char *label)
{
    GLint e[3] = {-7, -7, -7};
    int i;
    GLint vb = -7;
    for (i = 0; i < 3; i++)
        glGetVertexAttribiv((GLuint)i, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &e[i]);
    glGetIntegerv(GL_VERTEX_ARRAY_BUFFER_BINDING, &vb);
    sgl_text(out, "query", "%-8s vertex %d color %d texcoord %d attribs %d %d %d vbuf %d\n",
             label, glIsEnabled(GL_VERTEX_ARRAY), glIsEnabled(GL_COLOR_ARRAY),
             glIsEnabled(GL_TEXTURE_COORD_ARRAY), e[0], e[1], e[2], vb);
    q("  GL_VERTEX_ARRAY_BINDING", GL_VERTEX_ARRAY_BINDING);
    q("  GL_ELEMENT_ARRAY_BUFFER_BINDING", GL_ELEMENT_ARRAY_BUFFER_BINDING);
    q("  GL_ARRAY_BUFFER_BINDING", GL_ARRAY_BUFFER_BINDING);
}

static void queries(void)
{
    GLuint extra[2], never = 4242;
    int i;
    sgl_text(out, "names", "%u %u %u %u buffers a %u b %u c %u ebo %u %u %u other %u\n",
             vao[0], vao[1], vao[2], vao[3], buf_a, buf_b, buf_c, ebo_a, ebo_b, ebo_c,
             buf_other);
    /* vao[3] was generated but never bound */
    sgl_text(out, "query", "IsVertexArray generated-unbound %d\n", glIsVertexArray(vao[3]));
    for (i = 0; i < 3; i++)
        sgl_text(out, "query", "IsVertexArray(vao[%d]) %d\n", i, glIsVertexArray(vao[i]));
    sgl_text(out, "query", "IsVertexArray(0) %d never %d\n", glIsVertexArray(0),
             glIsVertexArray(never));
    per_object("vao 0");
    glBindVertexArray(vao[0]);
    per_object("vao[0]");
    glBindVertexArray(vao[1]);
    per_object("vao[1]");
    glBindVertexArray(vao[2]);
    per_object("vao[2]");
    glBindVertexArray(vao[3]);
    per_object("vao[3]");
    sgl_text(out, "query", "IsVertexArray vao[3] after bind %d\n", glIsVertexArray(vao[3]));
    glBindVertexArray(0);
    per_object("vao 0");

    E(glBindVertexArray(never));
    q("binding after bad bind", GL_VERTEX_ARRAY_BINDING);
    E(glGenVertexArrays(-1, extra));
    E(glDeleteVertexArrays(-1, extra));
    E(glGenVertexArrays(0, extra));
    E(glGenVertexArrays(2, extra));
    /* delete the bound object: the binding reverts to 0 and object 0's arrays show */
    E(glBindVertexArray(extra[0]));
    glDisableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    per_object("extra0");
    sgl_text(out, "query", "normal array in extra0 %d\n", glIsEnabled(GL_NORMAL_ARRAY));
    E(glDeleteVertexArrays(1, extra));
    per_object("deleted");
    sgl_text(out, "query", "normal array after delete %d IsVertexArray %d\n",
             glIsEnabled(GL_NORMAL_ARRAY), glIsVertexArray(extra[0]));
    E(glBindVertexArray(extra[0]));
    E(glDeleteVertexArrays(1, &never));
    E(glDeleteVertexArrays(2, extra)); /* one deleted, one never bound */
    sgl_text(out, "query", "IsVertexArray extra1 after delete %d\n", glIsVertexArray(extra[1]));
    E(glBindVertexArray(extra[1]));
    E(glBindVertexArray(0));
    q("final binding", GL_VERTEX_ARRAY_BINDING);
}

int main(int argc, char **argv)
{
    static const char *names[] = {"pos", "col", "k", NULL};
    static unsigned char rb[FW * FH * 4];
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    out = sgl_open(argc, argv);
    prog_t = vert_program(VS_T, NULL, NULL);
    prog_g = vert_program(VS_G, NULL, names);
    vert_scene_body(out, buf, rb, setup, draw, queries);
    return sgl_end_scene(ctx, buf);
}
