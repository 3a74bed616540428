/* vbo_indexed: vertex buffer objects.  GL_ARRAY_BUFFER holds interleaved
 * position+colour floats, GL_ELEMENT_ARRAY_BUFFER holds indices of type
 * GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT and GL_UNSIGNED_INT (non-zero
 * offsets), drawn with glDrawElements and glDrawRangeElements; part of the
 * data is then replaced with glBufferSubData and drawn again.  Also
 * glDrawArrays from the buffer and indices from client memory while a
 * vertex buffer is bound. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256
#define GX 9
#define GY 7

struct vtx {
    GLfloat x, y, z;
    GLfloat r, g, b;
};

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
    unsigned char *buf;
    struct vtx verts[GX * GY];
    GLubyte idx8[64];
    GLushort idx16[128];
    GLuint idx32[(GX - 1) * (GY - 1) * 6 + 4];
    GLuint vbo, ibo[3];
    int i, j, n;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(-0.13, 8.31, -0.27, 6.23, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);

    /* a wobbly grid of vertices */
    for (j = 0; j < GY; j++)
        for (i = 0; i < GX; i++) {
            struct vtx *v = &verts[j * GX + i];
            v->x = i + 0.1337f * ((i * 7 + j * 3) % 5) - 0.2f;
            v->y = j + 0.0913f * ((i * 3 + j * 5) % 7) - 0.25f;
            v->z = 0.0f;
            v->r = (float)i / (GX - 1);
            v->g = (float)j / (GY - 1);
            v->b = 0.5f + 0.5f * (float)((i + j) % 3) / 2.0f;
        }

    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof verts, verts, GL_STATIC_DRAW);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, sizeof(struct vtx), (const void *)0);
    glColorPointer(3, GL_FLOAT, sizeof(struct vtx), (const void *)(3 * sizeof(GLfloat)));

    /* bottom-left block: unsigned byte indices, triangles, offset 4 */
    n = 0;
    idx8[n++] = 0; idx8[n++] = 0; idx8[n++] = 0; idx8[n++] = 0; /* skipped by offset */
    for (j = 0; j < 2; j++)
        for (i = 0; i < 3; i++) {
            GLubyte a = (GLubyte)(j * GX + i), b = (GLubyte)(a + 1);
            GLubyte c = (GLubyte)(a + GX), d = (GLubyte)(c + 1);
            idx8[n++] = a; idx8[n++] = b; idx8[n++] = d;
            idx8[n++] = a; idx8[n++] = d; idx8[n++] = c;
        }
    glGenBuffers(3, ibo);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo[0]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, n, idx8, GL_STATIC_DRAW);
    glDrawElements(GL_TRIANGLES, n - 4, GL_UNSIGNED_BYTE, (const void *)4);

    /* right block: unsigned short indices, triangle strips per row */
    n = 0;
    for (i = 4; i < GX; i++) {
        idx16[n++] = (GLushort)(i);
        idx16[n++] = (GLushort)(GX + i);
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof idx16, NULL, GL_DYNAMIC_DRAW);
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 2 * sizeof(GLushort), n * sizeof(GLushort), idx16);
    glDrawElements(GL_TRIANGLE_STRIP, n, GL_UNSIGNED_SHORT, (const void *)(2 * sizeof(GLushort)));

    /* a fan with glDrawRangeElements */
    n = 0;
    idx16[n++] = 2 * GX + 6;
    idx16[n++] = 2 * GX + 8;
    idx16[n++] = 3 * GX + 8;
    idx16[n++] = 4 * GX + 7;
    idx16[n++] = 3 * GX + 5;
    idx16[n++] = 2 * GX + 4;
    glBufferSubData(GL_ELEMENT_ARRAY_BUFFER, 0, n * sizeof(GLushort), idx16);
    glDrawRangeElements(GL_TRIANGLE_FAN, 2 * GX + 4, 4 * GX + 8, n, GL_UNSIGNED_SHORT, (const void *)0);

    /* top rows: unsigned int indices, the whole upper grid */
    n = 0;
    for (j = 4; j < GY - 1; j++)
        for (i = 0; i < GX - 1; i++) {
            GLuint a = j * GX + i, b = a + 1, c = a + GX, d = c + 1;
            idx32[n++] = a; idx32[n++] = b; idx32[n++] = c;
            idx32[n++] = b; idx32[n++] = d; idx32[n++] = c;
        }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo[2]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, n * sizeof(GLuint), idx32, GL_STATIC_DRAW);
    glDrawRangeElements(GL_TRIANGLES, 4 * GX, GY * GX - 1, n / 2, GL_UNSIGNED_INT, (const void *)0);

    /* change colours of some vertices with glBufferSubData and draw the
     * second half of the same index buffer */
    for (i = 0; i < GX; i++) {
        GLfloat c[3] = {1.0f, 0.9137f - 0.1f * i, 0.1f * i};
        glBufferSubData(GL_ARRAY_BUFFER, (5 * GX + i) * sizeof(struct vtx) + 3 * sizeof(GLfloat),
                        sizeof c, c);
    }
    glDrawElements(GL_TRIANGLES, n - n / 2, GL_UNSIGNED_INT, (const void *)((n / 2) * sizeof(GLuint)));

    /* glDrawArrays straight from the vertex buffer (points 18..26 as a strip
     * shifted by the modelview) and client-memory indices with a VBO bound */
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    glPushMatrix();
    glTranslatef(0.37f, 3.0f, 0.0f);
    glScalef(0.5f, 0.4f, 1.0f);
    glDrawArrays(GL_TRIANGLE_STRIP, 2, 7);
    {
        static const GLubyte cidx[6] = {0, 10, 20, 20, 30, 2};
        glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, cidx);
    }
    glPopMatrix();

    glDisableClientState(GL_COLOR_ARRAY);
    glDisableClientState(GL_VERTEX_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDeleteBuffers(1, &vbo);
    glDeleteBuffers(3, ibo);

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "error", "glGetError=0x%04x\n", glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
