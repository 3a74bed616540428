/*
 * lights8.c - eight lights: spots, attenuation, two-sided lighting, separate specular colour.
 *
 * Eight GL_LIGHTs (one directional; three point lights with constant, linear
 * and quadratic attenuation; four spot lights with cut-offs 20-50 degrees and
 * exponents 2-30), GL_LIGHT_MODEL_TWO_SIDE with different front and back
 * materials, GL_LIGHT_MODEL_LOCAL_VIEWER, GL_SEPARATE_SPECULAR_COLOR, smooth
 * shading.  Each frame draws two 48x48 wavy sheets turned so both faces show,
 * and 9 tori, about 12,000 lit vertices, with depth test.
 */
#include <GL/gl.h>
#include "bench.h"
#include "shapes.h"

static void scene_setup(int w, int h)
{
    static const GLfloat fdiff[4] = {0.8f, 0.6f, 0.4f, 1.0f}, bdiff[4] = {0.3f, 0.5f, 0.9f, 1.0f};
    static const GLfloat spec[4] = {0.9f, 0.9f, 0.8f, 1.0f}, bspec[4] = {0.3f, 0.3f, 0.6f, 1.0f};
    static const GLfloat amb[4] = {0.1f, 0.1f, 0.1f, 1.0f};
    int i;
    BENCH_UNUSED(w, h);
    glEnable(GL_LIGHTING);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glLightModeli(GL_LIGHT_MODEL_LOCAL_VIEWER, GL_TRUE);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, fdiff);
    glMaterialfv(GL_BACK, GL_DIFFUSE, bdiff);
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialfv(GL_BACK, GL_SPECULAR, bspec);
    glMaterialf(GL_FRONT, GL_SHININESS, 40.0f);
    glMaterialf(GL_BACK, GL_SHININESS, 12.0f);
    for (i = 0; i < 8; i++) {
        GLenum l = GL_LIGHT0 + (GLenum)i;
        GLfloat col[4] = {0.3f + 0.1f * (float)(i % 3), 0.3f + 0.08f * (float)(i % 4),
                          0.3f + 0.07f * (float)(i % 5), 1.0f};
        glEnable(l);
        glLightfv(l, GL_DIFFUSE, col);
        glLightfv(l, GL_SPECULAR, col);
        if (i >= 1 && i <= 3) {
            glLightf(l, GL_CONSTANT_ATTENUATION, 0.5f);
            glLightf(l, GL_LINEAR_ATTENUATION, 0.1f * (float)i);
            glLightf(l, GL_QUADRATIC_ATTENUATION, 0.02f * (float)i);
        } else if (i >= 4) {
            GLfloat dir[3] = {0.2f * (float)(i - 6), -0.3f, -1.0f};
            glLightf(l, GL_SPOT_CUTOFF, 20.0f + 10.0f * (float)(i - 4));
            glLightf(l, GL_SPOT_EXPONENT, 2.0f + 9.0f * (float)(i - 4));
            glLightfv(l, GL_SPOT_DIRECTION, dir);
            glLightf(l, GL_LINEAR_ATTENUATION, 0.05f);
        }
    }
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_NORMALIZE);
    glShadeModel(GL_SMOOTH);
    glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
}

static void scene_frame(int w, int h)
{
    int i;
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    shape_perspective(1.0, 2.0, 30.0);
    /* Lights placed in eye space. */
    for (i = 0; i < 8; i++) {
        GLfloat pos[4] = {-3.0f + 0.9f * (float)i, 2.0f - 0.5f * (float)(i % 4), -3.0f,
                          i == 0 ? 0.0f : 1.0f};
        if (i == 0) {
            pos[0] = 0.3f;
            pos[1] = 0.5f;
            pos[2] = 1.0f;
        }
        glLightfv(GL_LIGHT0 + (GLenum)i, GL_POSITION, pos);
    }
    glPushMatrix();
    glTranslatef(-1.6f, 0.0f, -6.0f);
    glRotatef(70.0f, 0.0f, 1.0f, 0.0f);
    glRotatef(-30.0f, 1.0f, 0.0f, 0.0f);
    glScalef(2.5f, 2.5f, 2.5f);
    shape_sheet(48, 0.15f, 4.0f);
    glPopMatrix();
    glPushMatrix();
    glTranslatef(1.6f, 0.0f, -6.0f);
    glRotatef(-110.0f, 0.0f, 1.0f, 0.0f);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    glScalef(2.5f, 2.5f, 2.5f);
    shape_sheet(48, 0.2f, 3.0f);
    glPopMatrix();
    for (i = 0; i < 9; i++) {
        glPushMatrix();
        glTranslatef(-2.5f + 2.5f * (float)(i % 3), -2.5f + 2.5f * (float)(i / 3), -8.0f);
        glRotatef(40.0f * (float)i, 1.0f, 0.5f, 0.2f);
        shape_torus(0.9f, 0.35f, 24, 12);
        glPopMatrix();
    }
}
