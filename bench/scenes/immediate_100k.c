/*
 * immediate_100k.c - (h) 100,000 vertices through glBegin/glEnd.
 *
 * One glBegin(GL_TRIANGLES) ... glEnd() per frame with 33,334 small
 * triangles (100,002 vertices), each vertex sent as glColor3ub + glVertex3f,
 * at random positions and depths with GL_LESS depth testing.  Measures the
 * per-call cost of immediate mode more than fill rate.
 */
#include <GL/gl.h>
#include "bench.h"

#define TRIS 33334

static float *vtx;
static unsigned char *col;

static void scene_setup(int w, int h)
{
    int t, v;
    BENCH_UNUSED(w, h);
    vtx = malloc(sizeof(float) * 9 * TRIS);
    col = malloc(3 * 3 * TRIS);
    if (!vtx || !col) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }
    for (t = 0; t < TRIS; t++) {
        float cx = bench_randf() * 2.0f - 1.0f, cy = bench_randf() * 2.0f - 1.0f;
        float cz = bench_randf() * 1.8f - 0.9f;
        for (v = 0; v < 3; v++) {
            float *p = &vtx[(t * 3 + v) * 3];
            unsigned char *c = &col[(t * 3 + v) * 3];
            p[0] = cx + (bench_randf() - 0.5f) * 0.06f;
            p[1] = cy + (bench_randf() - 0.5f) * 0.06f;
            p[2] = cz + (bench_randf() - 0.5f) * 0.05f;
            c[0] = (unsigned char)(bench_randf() * 255.0f);
            c[1] = (unsigned char)(bench_randf() * 255.0f);
            c[2] = (unsigned char)(bench_randf() * 255.0f);
        }
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glShadeModel(GL_SMOOTH);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
}

static void scene_frame(int w, int h)
{
    int i;
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    for (i = 0; i < TRIS * 3; i++) {
        glColor3ub(col[i * 3], col[i * 3 + 1], col[i * 3 + 2]);
        glVertex3f(vtx[i * 3], vtx[i * 3 + 1], vtx[i * 3 + 2]);
    }
    glEnd();
}
