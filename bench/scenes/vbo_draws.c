/*
 * vbo_draws.c - many small glDrawElements draws from buffer objects.
 *
 * The way programs built on vertex buffers draw a scene of objects (VTK's
 * actors, a tutorial's crates): one sphere mesh (24 x 16 quads as 768
 * triangles, interleaved position, normal and texture coordinate in a
 * GL_ARRAY_BUFFER, 16-bit indices in a GL_ELEMENT_ARRAY_BUFFER) drawn 160
 * times a frame with glDrawElements, each with its own matrix and diffuse
 * material; every fourth object binds the other of two mipmapped textures, and
 * every eighth draws untextured. Two lights, depth test, smooth shading.
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include "bench.h"
#include "shapes.h"
#include "sphere_buffers.h"

#define NOBJ 160

static GLuint tex[2];

static void make_texture(GLuint name, int seed)
{
    static unsigned char px[64 * 64 * 3];
    int x, y;
    for (y = 0; y < 64; y++)
        for (x = 0; x < 64; x++) {
            unsigned char *p = px + (y * 64 + x) * 3;
            int on = ((x >> 3) + (y >> 3) + seed) & 1;
            p[0] = (unsigned char)(on ? 230 : 40 + 3 * x);
            p[1] = (unsigned char)(on ? 200 - seed * 60 : 60 + 2 * y);
            p[2] = (unsigned char)(on ? 90 + seed * 100 : 150);
        }
    glBindTexture(GL_TEXTURE_2D, name);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 64, 64, 0, GL_RGB, GL_UNSIGNED_BYTE, px);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
}

static void scene_setup(int w, int h)
{
    static const GLfloat pos0[4] = {0.4f, 0.7f, 1.0f, 0.0f}, pos1[4] = {-0.8f, -0.2f, 0.6f, 0.0f};
    static const GLfloat col1[4] = {0.4f, 0.35f, 0.5f, 1.0f};
    static const GLfloat spec[4] = {0.6f, 0.6f, 0.6f, 1.0f};
    BENCH_UNUSED(w, h);
    sphere_buffers(8);
    glGenTextures(2, tex);
    make_texture(tex[0], 0);
    make_texture(tex[1], 1);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);
    glLightfv(GL_LIGHT0, GL_POSITION, pos0);
    glLightfv(GL_LIGHT1, GL_POSITION, pos1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, col1);
    glMaterialfv(GL_FRONT, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT, GL_SHININESS, 24.0f);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glShadeModel(GL_SMOOTH);
    glClearColor(0.1f, 0.12f, 0.15f, 1.0f);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.6, 0.6, 1.0, 12.0);
    glMatrixMode(GL_MODELVIEW);
}

static void scene_frame(int w, int h)
{
    int i;
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (i = 0; i < NOBJ; i++) {
        GLfloat diff[4];
        int col = i % 16, row = i / 16;
        diff[0] = 0.3f + 0.02f * (float)col;
        diff[1] = 0.6f - 0.03f * (float)row;
        diff[2] = 0.35f + 0.02f * (float)((i * 7) % 13);
        diff[3] = 1.0f;
        glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, diff);
        if (i % 8 == 0)
            glDisable(GL_TEXTURE_2D);
        else if (i % 8 == 1)
            glEnable(GL_TEXTURE_2D);
        if (i % 4 == 0)
            glBindTexture(GL_TEXTURE_2D, tex[(i / 4) % 2]);
        glPushMatrix();
        glTranslatef(-2.7f + 0.36f * (float)col, -1.6f + 0.36f * (float)row, -4.0f - 0.15f * (float)(i % 5));
        glRotatef(17.0f * (float)i, 0.3f, 1.0f, 0.2f);
        glScalef(0.2f, 0.2f, 0.2f);
        glDrawElements(GL_TRIANGLES, SPHERE_NIDX, GL_UNSIGNED_SHORT, (const GLvoid *)0);
        glPopMatrix();
    }
}
