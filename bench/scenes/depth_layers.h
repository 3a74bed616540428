/*
 * depth_layers.h - 30 layers of nearly full-screen quads at different depths.
 *
 * Included by depth_front_to_back.c and depth_back_to_front.c, which define
 * LAYER_ORDER_FRONT_TO_BACK as 1 or 0.  Each layer is a smooth-coloured
 * GL_QUADS quad covering ~90% of the window, shifted a little per layer, at
 * its own depth in an orthographic projection, with GL_LESS depth testing.
 * Front to back, most fragments fail the depth test (an implementation with
 * early/hierarchical depth rejection skips them); back to front, every layer
 * overwrites the previous one (30x overdraw).
 */
#include <GL/gl.h>
#include "bench.h"

#define LAYERS 30

static void scene_setup(int w, int h)
{
    BENCH_UNUSED(w, h);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glShadeModel(GL_SMOOTH);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClearDepth(1.0);
}

static void draw_layer(int i)
{
    /* Layer 0 is the nearest (glOrtho: z = +0.9 is near, -0.9 far). */
    float z = 0.9f - 1.8f * (float)i / (LAYERS - 1);
    float dx = 0.08f * (float)((i * 7) % 5 - 2) / 2.0f;
    float dy = 0.08f * (float)((i * 3) % 5 - 2) / 2.0f;
    float s = (float)i / (LAYERS - 1);
    glColor3f(s, 0.2f + 0.6f * (1.0f - s), 0.5f);
    glVertex3f(-0.92f + dx, -0.92f + dy, z);
    glColor3f(0.9f, s, 0.3f);
    glVertex3f(0.92f + dx, -0.92f + dy, z);
    glColor3f(0.2f, 0.9f - 0.5f * s, s);
    glVertex3f(0.92f + dx, 0.92f + dy, z);
    glColor3f(1.0f - s, 0.5f, 0.9f);
    glVertex3f(-0.92f + dx, 0.92f + dy, z);
}

static void scene_frame(int w, int h)
{
    int i;
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glBegin(GL_QUADS);
    for (i = 0; i < LAYERS; i++)
        draw_layer(LAYER_ORDER_FRONT_TO_BACK ? i : LAYERS - 1 - i);
    glEnd();
}
