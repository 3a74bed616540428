/*
 * wide_scene.h - the body of buffer_ushort.c and buffer_float.c.
 *
 * A lit, textured (MODULATE, GL_LINEAR_MIPMAP_LINEAR, mipmaps by
 * GL_GENERATE_MIPMAP), fogged and blended scene: a ground sheet, 12 spheres,
 * and 20 translucent bands, each a quarter of the window, 16 blended over (SRC_ALPHA /
 * ONE_MINUS_SRC_ALPHA) and 4 added (SRC_ALPHA, ONE), drawn into whatever OSMesa
 * buffer type the including scene set with BENCH_BUFFER_TYPE.
 */
#ifndef SGL_BENCH_WIDE_SCENE_H
#define SGL_BENCH_WIDE_SCENE_H

#include <GL/gl.h>
#include "bench.h"
#include "shapes.h"

static void scene_setup(int w, int h)
{
    static unsigned char t[128 * 128 * 4];
    static const GLfloat pos[4] = {0.4f, 0.8f, 0.6f, 0.0f};
    static const GLfloat spec[4] = {0.7f, 0.7f, 0.7f, 1.0f};
    static const GLfloat fogc[4] = {0.5f, 0.55f, 0.6f, 1.0f};
    GLuint tex;
    int i;
    BENCH_UNUSED(w, h);
    for (i = 0; i < 128 * 128; i++) {
        int x = i % 128, y = i / 128;
        t[i * 4 + 0] = (unsigned char)(((x >> 4) ^ (y >> 4)) & 1 ? 230 : 90);
        t[i * 4 + 1] = (unsigned char)(x * 2);
        t[i * 4 + 2] = (unsigned char)(y * 2);
        t[i * 4 + 3] = 255;
    }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 128, 128, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_COLOR_MATERIAL);
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 30.0f);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glFogi(GL_FOG_MODE, GL_EXP);
    glFogf(GL_FOG_DENSITY, 0.06f);
    glFogfv(GL_FOG_COLOR, fogc);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_NORMALIZE);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glClearColor(0.5f, 0.55f, 0.6f, 1.0f);
}

static void scene_frame(int w, int h)
{
    int i;
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    shape_perspective(0.8, 1.5, 60.0);
    glTranslatef(0.0f, -1.5f, -8.0f);
    glRotatef(25.0f, 1.0f, 0.0f, 0.0f);
    glEnable(GL_LIGHTING);
    glEnable(GL_FOG);
    glEnable(GL_TEXTURE_2D);
    glColor3f(0.9f, 0.85f, 0.7f);
    glPushMatrix();
    glRotatef(-90.0f, 1.0f, 0.0f, 0.0f);
    glScalef(12.0f, 12.0f, 1.0f);
    shape_sheet(40, 0.02f, 6.0f);
    glPopMatrix();
    for (i = 0; i < 12; i++) {
        glPushMatrix();
        glTranslatef(-5.0f + 2.0f * (float)(i % 6), 1.0f, -2.0f - 4.0f * (float)(i / 6));
        glColor3f(0.3f + 0.05f * (float)i, 0.6f, 0.9f - 0.05f * (float)i);
        shape_sphere(0.9f, 20, 14);
        glPopMatrix();
    }
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_FOG);
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glBegin(GL_QUADS);
    for (i = 0; i < 20; i++) {
        float s = (float)i / 19.0f, y0 = -1.0f + 0.08f * (float)i, y1 = y0 + 0.5f;
        if (i == 16) {
            glEnd();
            glBlendFunc(GL_SRC_ALPHA, GL_ONE);
            glBegin(GL_QUADS);
        }
        glColor4f(s, 0.2f, 1.0f - s, 0.12f);
        glVertex2f(-1.0f, y0);
        glColor4f(0.1f, 0.5f * s, 0.1f, 0.2f);
        glVertex2f(1.0f, y0);
        glColor4f(0.5f, s * 0.3f, 0.2f, 0.25f);
        glVertex2f(1.0f, y1);
        glColor4f(0.3f * s, 0.1f, 0.6f, 0.1f);
        glVertex2f(-1.0f, y1);
    }
    glEnd();
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
}

#endif
