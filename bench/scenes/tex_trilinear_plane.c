/*
 * tex_trilinear_plane.c - (e) a trilinear-filtered ground plane in perspective.
 *
 * A 256x256 RGBA8 procedural texture with all nine mip levels computed here
 * by 2x2 box filtering and uploaded one by one with glTexImage2D (no
 * gluBuild2DMipmaps), GL_REPEAT, tiled 40 times over a ground plane that
 * runs from the camera to the far plane, so every mip level is used.
 */
#include <GL/gl.h>
#include <math.h>
#include "bench.h"
#include "mipmaps.h"

#define TS 256

static GLuint tex;

static void scene_setup(int w, int h)
{
    static unsigned char level[2][TS * TS * 4];
    unsigned char *src = level[0], *dst = level[1];
    int x, y;
    BENCH_UNUSED(w, h);
    for (y = 0; y < TS; y++) {
        for (x = 0; x < TS; x++) {
            unsigned char *p = &src[(y * TS + x) * 4];
            int check = ((x >> 4) ^ (y >> 4)) & 1;
            int line = (x & 63) < 3 || (y & 63) < 3;
            p[0] = (unsigned char)(line ? 250 : check ? 200 : 60 + (x & 63));
            p[1] = (unsigned char)(line ? 240 : check ? 180 : 90 + (y & 63));
            p[2] = (unsigned char)(line ? 40 : check ? 120 : 40);
            p[3] = 255;
        }
    }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    mip_upload_rgba8(src, dst, TS);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.1, 0.1, -0.1, 0.1, 0.1, 200.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(8.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(25.0f, 0.0f, 1.0f, 0.0f);
    glClearColor(0.5f, 0.7f, 0.95f, 1.0f);
}

static void scene_frame(int w, int h)
{
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColor3f(1.0f, 1.0f, 1.0f);
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(-100.0f, -1.0f, 100.0f);
    glTexCoord2f(80.0f, 0.0f);
    glVertex3f(100.0f, -1.0f, 100.0f);
    glTexCoord2f(80.0f, 80.0f);
    glVertex3f(100.0f, -1.0f, -100.0f);
    glTexCoord2f(0.0f, 80.0f);
    glVertex3f(-100.0f, -1.0f, -100.0f);
    glEnd();
}
