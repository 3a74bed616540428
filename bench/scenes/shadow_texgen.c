/*
 * shadow_texgen.c - shadow compare with eye-linear texgen.
 *
 * Each frame renders 20 lit cubes on a ground grid twice: first from the
 * light into a 256x256 corner of the window (depth only, polygon offset),
 * copied with glCopyTexSubImage2D into a GL_DEPTH_COMPONENT24 texture; then
 * from the camera with GL_EYE_LINEAR texgen on S, T, R and Q and a texture
 * matrix (bias x light projection x light view x inverse camera view), the
 * texture compared with GL_COMPARE_R_TO_TEXTURE / GL_LEQUAL, GL_LINEAR,
 * GL_DEPTH_TEXTURE_MODE GL_LUMINANCE, modulating the lit colour.
 */
#include <GL/gl.h>
#include "bench.h"
#include "shapes.h"

#define SHADOW 256

static GLuint depth_tex;

static void scene_setup(int w, int h)
{
    static const GLfloat sx[4] = {1, 0, 0, 0}, sy[4] = {0, 1, 0, 0};
    static const GLfloat sz[4] = {0, 0, 1, 0}, sw[4] = {0, 0, 0, 1};
    static const GLfloat lpos[4] = {0.3f, 1.0f, 0.5f, 0.0f};
    BENCH_UNUSED(w, h);
    glGenTextures(1, &depth_tex);
    glBindTexture(GL_TEXTURE_2D, depth_tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, SHADOW, SHADOW, 0,
                 GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
    /* Eye planes given under an identity modelview: they are the eye coordinates. */
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
    glTexGenfv(GL_S, GL_EYE_PLANE, sx);
    glTexGenfv(GL_T, GL_EYE_PLANE, sy);
    glTexGenfv(GL_R, GL_EYE_PLANE, sz);
    glTexGenfv(GL_Q, GL_EYE_PLANE, sw);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, lpos);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);
    glClearColor(0.3f, 0.35f, 0.5f, 1.0f);
}

static void light_view(void)
{
    glTranslatef(0.0f, 0.0f, -14.0f);
    glRotatef(60.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(30.0f, 0.0f, 1.0f, 0.0f);
}

static void light_proj(void)
{
    glOrtho(-8.0, 8.0, -8.0, 8.0, 4.0, 24.0);
}

static void cam_view(void)
{
    glTranslatef(0.0f, -1.0f, -12.0f);
    glRotatef(35.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-20.0f, 0.0f, 1.0f, 0.0f);
}

/* The inverse of cam_view (applied in reverse, negated). */
static void cam_view_inverse(void)
{
    glRotatef(20.0f, 0.0f, 1.0f, 0.0f);
    glRotatef(-35.0f, 1.0f, 0.0f, 0.0f);
    glTranslatef(0.0f, 1.0f, 12.0f);
}

static void draw_world(void)
{
    int i, j;
    glColor3f(0.8f, 0.75f, 0.6f);
    glNormal3f(0.0f, 1.0f, 0.0f);
    for (j = 0; j < 16; j++) {
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i <= 16; i++) {
            glVertex3f(-8.0f + (float)i, 0.0f, -8.0f + (float)(j + 1));
            glVertex3f(-8.0f + (float)i, 0.0f, -8.0f + (float)j);
        }
        glEnd();
    }
    for (i = 0; i < 20; i++) {
        glPushMatrix();
        glTranslatef(-6.0f + 3.0f * (float)(i % 5), 0.8f + 0.3f * (float)(i % 3),
                     -5.0f + 3.0f * (float)(i / 5));
        glRotatef(17.0f * (float)i, 0.2f, 1.0f, 0.1f);
        glScalef(1.2f, 1.6f, 1.2f);
        glColor3f(0.3f + 0.03f * (float)i, 0.5f, 0.9f - 0.03f * (float)i);
        shape_cube();
        glPopMatrix();
    }
}

static void scene_frame(int w, int h)
{
    /* Pass 1: depth from the light. */
    glViewport(0, 0, SHADOW, SHADOW);
    glClear(GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    light_proj();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    light_view();
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDisable(GL_LIGHTING);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 4.0f);
    draw_world();
    glDisable(GL_POLYGON_OFFSET_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBindTexture(GL_TEXTURE_2D, depth_tex);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 0, SHADOW, SHADOW);

    /* Pass 2: the camera, shadowed. */
    glViewport(0, 0, w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTranslatef(0.5f, 0.5f, 0.5f);
    glScalef(0.5f, 0.5f, 0.5f);
    light_proj();
    light_view();
    cam_view_inverse();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.8, 0.8, -0.8, 0.8, 1.5, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    cam_view();
    glEnable(GL_LIGHTING);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_GEN_R);
    glEnable(GL_TEXTURE_GEN_Q);
    draw_world();
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glDisable(GL_TEXTURE_GEN_R);
    glDisable(GL_TEXTURE_GEN_Q);
    glDisable(GL_TEXTURE_2D);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
}
