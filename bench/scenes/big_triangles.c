/*
 * big_triangles.c - (a) a few large, overlapping smooth-shaded triangles.
 *
 * Six triangles, each covering a large part of the window, drawn with
 * glBegin(GL_TRIANGLES) and per-vertex colours; no depth test.  Measures raw
 * fill rate of the colour interpolation path.
 */
#include <GL/gl.h>
#include "bench.h"

static void scene_setup(int w, int h)
{
    (void)w;
    (void)h;
    glShadeModel(GL_SMOOTH);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
}

static void scene_frame(int w, int h)
{
    static const float tri[6][3][2] = {
        {{-1.3f, -1.2f}, {1.4f, -1.1f}, {0.05f, 1.35f}},
        {{-1.1f, 1.2f}, {-0.9f, -1.3f}, {1.3f, 0.2f}},
        {{1.2f, 1.25f}, {-1.25f, 0.4f}, {0.9f, -1.3f}},
        {{-0.8f, -0.9f}, {0.95f, -0.6f}, {-0.3f, 0.97f}},
        {{0.7f, 0.9f}, {-0.9f, 0.6f}, {0.2f, -0.95f}},
        {{-1.2f, 0.1f}, {0.3f, -1.2f}, {1.1f, 1.1f}},
    };
    int t, v;
    (void)w;
    (void)h;
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_TRIANGLES);
    for (t = 0; t < 6; t++) {
        for (v = 0; v < 3; v++) {
            float r = (float)((t + v) % 3 == 0), g = (float)((t + v) % 3 == 1);
            glColor4f(r * 0.9f + 0.05f * t, g * 0.8f + 0.1f, 1.0f - 0.15f * t, 1.0f);
            glVertex2f(tri[t][v][0], tri[t][v][1]);
        }
    }
    glEnd();
}
