/*
 * polygon_modes_offset.c - polygon modes (FILL, LINE, POINT per face) and polygon offset.
 *
 * Twelve lit tori in perspective with depth test: hidden-line rendering
 * (filled with GL_POLYGON_OFFSET_FILL factor 1 units 1, then GL_LINE edges on
 * top), GL_FRONT FILL / GL_BACK LINE with culling off, GL_POINT vertices
 * (point size 3) over an offset fill, GL_POLYGON_OFFSET_LINE and
 * GL_POLYGON_OFFSET_POINT with negative offsets, glLineWidth 2 and flat
 * shading on some.
 */
#include <GL/gl.h>
#include "bench.h"
#include "shapes.h"

static void scene_setup(int w, int h)
{
    static const GLfloat pos[4] = {0.5f, 0.7f, 1.0f, 0.0f};
    BENCH_UNUSED(w, h);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glClearColor(0.15f, 0.15f, 0.2f, 1.0f);
}

static void scene_frame(int w, int h)
{
    int i;
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    shape_perspective(1.0, 2.0, 30.0);
    for (i = 0; i < 12; i++) {
        int kind = i % 4;
        glPushMatrix();
        glTranslatef(-3.0f + 2.0f * (float)(i % 4), -2.0f + 2.0f * (float)(i / 4), -7.0f);
        glRotatef(30.0f * (float)i, 1.0f, 0.6f, 0.2f);
        glShadeModel((i & 4) ? GL_FLAT : GL_SMOOTH);
        glEnable(GL_LIGHTING);
        glColor3f(0.3f + 0.05f * (float)i, 0.6f, 0.8f - 0.05f * (float)i);
        if (kind == 0 || kind == 2) {
            glEnable(GL_POLYGON_OFFSET_FILL);
            glPolygonOffset(1.0f, 1.0f);
            glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
            shape_torus(0.8f, 0.3f, 24, 12);
            glDisable(GL_POLYGON_OFFSET_FILL);
            glDisable(GL_LIGHTING);
            glColor3f(1.0f, 1.0f, 0.3f);
            if (kind == 0) {
                glLineWidth(i & 1 ? 2.0f : 1.0f);
                glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
            } else {
                glPointSize(3.0f);
                glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
            }
            shape_torus(0.8f, 0.3f, 24, 12);
        } else if (kind == 1) {
            glPolygonMode(GL_FRONT, GL_FILL);
            glPolygonMode(GL_BACK, GL_LINE);
            shape_torus(0.8f, 0.3f, 24, 12);
        } else {
            glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
            shape_torus(0.8f, 0.3f, 24, 12);
            glDisable(GL_LIGHTING);
            glColor3f(0.9f, 0.3f, 0.3f);
            glEnable(GL_POLYGON_OFFSET_LINE);
            glEnable(GL_POLYGON_OFFSET_POINT);
            glPolygonOffset(-1.0f, -2.0f);
            glPolygonMode(GL_FRONT, GL_LINE);
            glPolygonMode(GL_BACK, GL_POINT);
            glPointSize(2.0f);
            shape_torus(0.8f, 0.3f, 24, 12);
            glDisable(GL_POLYGON_OFFSET_LINE);
            glDisable(GL_POLYGON_OFFSET_POINT);
        }
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        glLineWidth(1.0f);
        glPointSize(1.0f);
        glPopMatrix();
    }
}
