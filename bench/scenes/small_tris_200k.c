/*
 * small_tris_200k.c - (c) 200k small indexed, depth-tested triangles.
 *
 * A 317x317-vertex height field (199,712 triangles, about one pixel each at
 * 512x512) seen in perspective from above, stored in two VBOs (interleaved
 * float position + ubyte colour; GLuint indices) and drawn with one
 * glDrawElements(GL_TRIANGLES) per frame with GL_LESS depth testing.  The
 * hills occlude each other, so the depth test rejects part of the mesh.
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include "bench.h"

#define N 317 /* vertices per side: 2*(N-1)^2 = 199712 triangles */

struct vert {
    float x, y, z;
    unsigned char r, g, b, a;
};

static GLuint vbo[2];
static GLsizei index_count;

static void scene_setup(int w, int h)
{
    struct vert *v = malloc(sizeof *v * N * N);
    GLuint *idx = malloc(sizeof *idx * 6 * (N - 1) * (N - 1));
    int i, j, k = 0;
    BENCH_UNUSED(w, h);
    if (!v || !idx) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }
    for (j = 0; j < N; j++) {
        for (i = 0; i < N; i++) {
            float x = -1.5f + 3.0f * (float)i / (N - 1);
            float z = -1.5f + 3.0f * (float)j / (N - 1);
            float g, y = 0.25f * sinf(5.0f * x) * cosf(4.0f * z) + 0.1f * sinf(17.0f * x + 11.0f * z);
            struct vert *p = &v[j * N + i];
            p->x = x;
            p->y = y;
            p->z = z;
            p->r = (unsigned char)(127.0f + 120.0f * sinf(9.0f * x));
            g = 127.0f + 400.0f * y;
            p->g = (unsigned char)(g < 0.0f ? 0.0f : g > 255.0f ? 255.0f : g);
            p->b = (unsigned char)(127.0f + 120.0f * cosf(7.0f * z));
            p->a = 255;
        }
    }
    for (j = 0; j < N - 1; j++) {
        for (i = 0; i < N - 1; i++) {
            GLuint a = (GLuint)(j * N + i), b = a + 1, c = a + N, d = c + 1;
            idx[k++] = a;
            idx[k++] = c;
            idx[k++] = b;
            idx[k++] = b;
            idx[k++] = c;
            idx[k++] = d;
        }
    }
    index_count = k;
    glGenBuffers(2, vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo[0]);
    glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(sizeof *v * N * N), v, GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, vbo[1]);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)(sizeof *idx * k), idx, GL_STATIC_DRAW);
    free(v);
    free(idx);

    glVertexPointer(3, GL_FLOAT, sizeof(struct vert), (const void *)0);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(struct vert), (const void *)(3 * sizeof(float)));
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);

    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glShadeModel(GL_SMOOTH);
    glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.6, 0.6, 1.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, -0.2f, -2.6f);
    glRotatef(35.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 1.0f, 0.0f);
}

static void scene_frame(int w, int h)
{
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_INT, (const void *)0);
}
