/*
 * alpha_lines_points.c - the alpha test on lines and points (and a textured backdrop).
 *
 * A full-window quad textured with a 64x64 RGBA texture whose alpha is a
 * gradient, with GL_ALPHA_TEST GL_GREATER 0.5; then 4,000 lines (widths 1-3,
 * half of them stippled) and 12,000 points (sizes 1-4) with per-vertex
 * alpha, drawn in eight batches each with its own alpha function (all eight,
 * references 0.1-0.8), blending on for half of the batches, depth test off.
 */
#include <GL/gl.h>
#include "bench.h"

static void scene_setup(int w, int h)
{
    static unsigned char t[64 * 64 * 4];
    GLuint tex;
    int i;
    BENCH_UNUSED(w, h);
    for (i = 0; i < 64 * 64; i++) {
        int x = i % 64, y = i / 64;
        t[i * 4 + 0] = (unsigned char)(x * 4);
        t[i * 4 + 1] = (unsigned char)(y * 4);
        t[i * 4 + 2] = (unsigned char)(((x >> 3) ^ (y >> 3)) & 1 ? 200 : 50);
        t[i * 4 + 3] = (unsigned char)((x + y) * 2);
    }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, t);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    glLineStipple(2, 0xF0F3);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glClearColor(0.05f, 0.05f, 0.1f, 1.0f);
}

static void scene_frame(int w, int h)
{
    static const GLenum funcs[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                                    GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    int b, i;
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    glEnable(GL_TEXTURE_2D);
    glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, 0.0f);
    glVertex2f(-1.0f, -1.0f);
    glTexCoord2f(2.0f, 0.0f);
    glVertex2f(1.0f, -1.0f);
    glTexCoord2f(2.0f, 2.0f);
    glVertex2f(1.0f, 1.0f);
    glTexCoord2f(0.0f, 2.0f);
    glVertex2f(-1.0f, 1.0f);
    glEnd();
    glDisable(GL_TEXTURE_2D);

    bench_rand_state = 777u;
    for (b = 0; b < 8; b++) {
        glAlphaFunc(funcs[b], 0.1f * (float)(b + 1));
        if (b & 1)
            glEnable(GL_BLEND);
        else
            glDisable(GL_BLEND);
        if (b & 2)
            glEnable(GL_LINE_STIPPLE);
        else
            glDisable(GL_LINE_STIPPLE);
        glLineWidth(1.0f + (float)(b % 3));
        glBegin(GL_LINES);
        for (i = 0; i < 500; i++) {
            float x = 2.0f * bench_randf() - 1.0f, y = 2.0f * bench_randf() - 1.0f;
            float a = (float)((i * 37) % 256) / 255.0f;
            glColor4f(bench_randf(), bench_randf(), 0.8f, a);
            glVertex2f(x, y);
            glColor4f(0.9f, bench_randf(), bench_randf(), 1.0f - a);
            glVertex2f(x + 0.6f * bench_randf() - 0.3f, y + 0.6f * bench_randf() - 0.3f);
        }
        glEnd();
        glPointSize(1.0f + (float)(b % 4));
        glBegin(GL_POINTS);
        for (i = 0; i < 1500; i++) {
            glColor4f(bench_randf(), 0.7f, bench_randf(), (float)((i * 53) % 256) / 255.0f);
            glVertex2f(2.0f * bench_randf() - 1.0f, 2.0f * bench_randf() - 1.0f);
        }
        glEnd();
    }
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_LINE_STIPPLE);
    glLineWidth(1.0f);
    glPointSize(1.0f);
}
