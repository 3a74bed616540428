/*
 * tex_bilinear.c - (d) one full-screen bilinear-filtered texture.
 *
 * A 256x256 RGBA8 procedural texture (rings, a checkerboard and gradients)
 * magnified onto a window-sized quad with GL_LINEAR min/mag filters and the
 * default GL_MODULATE texture environment (white vertex colour).
 */
#include <GL/gl.h>
#include <math.h>
#include "bench.h"

#define TS 256

static GLuint tex;

static void scene_setup(int w, int h)
{
    static unsigned char img[TS * TS * 4];
    int x, y;
    BENCH_UNUSED(w, h);
    for (y = 0; y < TS; y++) {
        for (x = 0; x < TS; x++) {
            unsigned char *p = &img[(y * TS + x) * 4];
            float dx = (float)x - 127.5f, dy = (float)y - 127.5f;
            float ring = 0.5f + 0.5f * sinf(sqrtf(dx * dx + dy * dy) * 0.35f);
            int check = ((x >> 5) ^ (y >> 5)) & 1;
            p[0] = (unsigned char)(255.0f * ring);
            p[1] = (unsigned char)(check ? x : 255 - y);
            p[2] = (unsigned char)((x * 3 + y * 5) & 255);
            p[3] = 255;
        }
    }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, TS, TS, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glEnable(GL_TEXTURE_2D);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
}

static void scene_frame(int w, int h)
{
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, 0.0f);
    glVertex2f(-1.0f, -1.0f);
    glTexCoord2f(1.0f, 0.0f);
    glVertex2f(1.0f, -1.0f);
    glTexCoord2f(1.0f, 1.0f);
    glVertex2f(1.0f, 1.0f);
    glTexCoord2f(0.0f, 1.0f);
    glVertex2f(-1.0f, 1.0f);
    glEnd();
}
