/*
 * blend_quads.c - (b) 40 full-screen blended quads.
 *
 * Forty window-sized GL_QUADS, each with a smooth colour gradient and alpha
 * between 0.15 and 0.35, composited with GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA:
 * 40 read-modify-write passes over every pixel.
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
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
}

static void scene_frame(int w, int h)
{
    int i;
    (void)w;
    (void)h;
    glClear(GL_COLOR_BUFFER_BIT);
    glBegin(GL_QUADS);
    for (i = 0; i < 40; i++) {
        float a = 0.15f + 0.2f * (float)(i % 5) / 4.0f;
        float s = (float)i / 39.0f;
        glColor4f(s, 0.3f, 1.0f - s, a);
        glVertex2f(-1.0f, -1.0f);
        glColor4f(0.2f, 1.0f - s, s, a);
        glVertex2f(1.0f, -1.0f);
        glColor4f(1.0f - s, s, 0.5f, a);
        glVertex2f(1.0f, 1.0f);
        glColor4f(0.9f, 0.9f * s, 0.1f, a);
        glVertex2f(-1.0f, 1.0f);
    }
    glEnd();
}
