/*
 * format_scene.h - the small scene drawn by the format_* scenes, each of
 * which renders it into an OSMesa context of a different pixel format.
 * The size is odd (201 x 133) so no row is padded.
 */
#ifndef SGL_FORMAT_SCENE_H
#define SGL_FORMAT_SCENE_H

#include <GL/gl.h>

#define FW 201
#define FH 133

static inline void format_scene_draw(void)
{
    int i;
    glClearColor(0.137f, 0.25f, 0.5f, 0.75f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.0, 1.0, -0.66, 0.66, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 12; i++) {
        float x = -0.97f + 0.153f * i, y = -0.61f + 0.0713f * (i % 5);
        glColor4f(1.0f, 0.08f * i, 0.0f, 1.0f);
        glVertex3f(x, y, 0.5f - 0.09f * i);
        glColor4f(0.0f, 1.0f, 0.07f * i, 0.5f);
        glVertex3f(x + 0.41f, y + 0.137f, -0.3f + 0.05f * i);
        glColor4f(0.1f * (i % 3), 0.2f, 1.0f, 0.25f);
        glVertex3f(x + 0.11f, y + 0.83f, 0.0f);
    }
    glEnd();
    /* an asymmetric marker in the top-left corner shows the row order */
    glBegin(GL_QUADS);
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex2f(-0.99f, 0.41f);
    glVertex2f(-0.71f, 0.41f);
    glVertex2f(-0.71f, 0.65f);
    glVertex2f(-0.99f, 0.65f);
    glEnd();
}

#endif
