/* big_mesh: a generated 96 x 96 height field (18050 triangles, 9409
 * vertices) in a vertex buffer, drawn with one glDrawElements call of
 * GL_UNSIGNED_INT indices under a perspective projection with the depth
 * test, then a generated sphere (GL_UNSIGNED_SHORT indices) intersecting
 * it. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <math.h>
#include "common.h"

#define W 256
#define H 256
#define N 96
#define SLICES 48
#define STACKS 32

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
    unsigned char *buf;
    GLfloat *v, *c;
    GLuint *idx;
    GLushort *sidx;
    GLuint bufs[4];
    int i, j, n;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    v = malloc(sizeof(GLfloat) * 3 * N * N);
    c = malloc(sizeof(GLfloat) * 3 * N * N);
    idx = malloc(sizeof(GLuint) * 6 * (N - 1) * (N - 1));
    sidx = malloc(sizeof(GLushort) * 6 * SLICES * STACKS);
    SGL_CHECK(buf && v && c && idx && sidx);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.53f, 0.71f, 0.92f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-0.55, 0.55, -0.41, 0.6, 1.0, 100.0);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.137f, -2.2f, -13.37f);
    glRotatef(31.3f, 1.0f, 0.0f, 0.0f);
    glRotatef(-27.1f, 0.0f, 1.0f, 0.0f);

    /* height field */
    for (j = 0; j < N; j++)
        for (i = 0; i < N; i++) {
            float x = -8.0f + 16.0f * i / (N - 1), z = -8.0f + 16.0f * j / (N - 1);
            float h = 0.9f * sinf(x * 0.93f) * cosf(z * 0.71f) + 0.35f * sinf(x * 2.9f + z * 2.3f);
            GLfloat *p = v + 3 * (j * N + i), *q = c + 3 * (j * N + i);
            p[0] = x;
            p[1] = h;
            p[2] = z;
            q[0] = 0.35f + 0.3f * h;
            q[1] = 0.55f + 0.25f * sinf(z * 1.7f);
            q[2] = 0.25f - 0.2f * h;
        }
    n = 0;
    for (j = 0; j < N - 1; j++)
        for (i = 0; i < N - 1; i++) {
            GLuint a = j * N + i, b = a + 1, d = a + N, e = d + 1;
            idx[n++] = a; idx[n++] = d; idx[n++] = b;
            idx[n++] = b; idx[n++] = d; idx[n++] = e;
        }
    glGenBuffers(4, bufs);
    glBindBuffer(GL_ARRAY_BUFFER, bufs[0]);
    glBufferData(GL_ARRAY_BUFFER, sizeof(GLfloat) * 6 * N * N, NULL, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof(GLfloat) * 3 * N * N, v);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof(GLfloat) * 3 * N * N, sizeof(GLfloat) * 3 * N * N, c);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, bufs[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof(GLuint) * n, idx, GL_STATIC_DRAW);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, 0, (const void *)0);
    glColorPointer(3, GL_FLOAT, 0, (const void *)(sizeof(GLfloat) * 3 * N * N));
    glDrawElements(GL_TRIANGLES, n, GL_UNSIGNED_INT, (const void *)0);

    /* sphere, radius 2.3, sunk into the terrain */
    for (j = 0; j <= STACKS; j++)
        for (i = 0; i <= SLICES; i++) {
            float th = 3.14159265f * j / STACKS, ph = 6.2831853f * i / SLICES;
            GLfloat *p = v + 3 * (j * (SLICES + 1) + i), *q = c + 3 * (j * (SLICES + 1) + i);
            p[0] = 1.1f + 2.3f * sinf(th) * cosf(ph);
            p[1] = 0.4f + 2.3f * cosf(th);
            p[2] = -0.7f + 2.3f * sinf(th) * sinf(ph);
            q[0] = 0.6f + 0.4f * sinf(th) * cosf(ph);
            q[1] = 0.3f + 0.3f * cosf(th);
            q[2] = 0.6f + 0.4f * sinf(ph * 3.0f);
        }
    n = 0;
    for (j = 0; j < STACKS; j++)
        for (i = 0; i < SLICES; i++) {
            GLushort a = (GLushort)(j * (SLICES + 1) + i), b = (GLushort)(a + 1);
            GLushort d = (GLushort)(a + SLICES + 1), e = (GLushort)(d + 1);
            sidx[n++] = a; sidx[n++] = d; sidx[n++] = b;
            sidx[n++] = b; sidx[n++] = d; sidx[n++] = e;
        }
    glBindBuffer(GL_ARRAY_BUFFER, bufs[2]);
    glBufferData(GL_ARRAY_BUFFER, sizeof(GLfloat) * 3 * (STACKS + 1) * (SLICES + 1) * 2, NULL,
                 GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof(GLfloat) * 3 * (STACKS + 1) * (SLICES + 1), v);
    glBufferSubData(GL_ARRAY_BUFFER, sizeof(GLfloat) * 3 * (STACKS + 1) * (SLICES + 1),
                    sizeof(GLfloat) * 3 * (STACKS + 1) * (SLICES + 1), c);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, bufs[3]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof(GLushort) * n, sidx, GL_STATIC_DRAW);
    glVertexPointer(3, GL_FLOAT, 0, (const void *)0);
    glColorPointer(3, GL_FLOAT, 0,
                   (const void *)(sizeof(GLfloat) * 3 * (STACKS + 1) * (SLICES + 1)));
    glDrawElements(GL_TRIANGLES, n, GL_UNSIGNED_SHORT, (const void *)0);

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    free(v);
    free(c);
    free(idx);
    free(sidx);
    return 0;
}
