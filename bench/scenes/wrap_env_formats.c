/*
 * wrap_env_formats.c - wrap modes x texture environments x LUMINANCE/RGB/RGBA/NPOT textures.
 *
 * Five textures (64x64 GL_LUMINANCE8, GL_LUMINANCE8_ALPHA8 and GL_RGB8,
 * 64x64 GL_RGBA8, 100x60 non-power-of-two GL_RGBA8) x five wrap modes
 * (REPEAT, CLAMP, CLAMP_TO_EDGE, CLAMP_TO_BORDER with a border colour,
 * MIRRORED_REPEAT) x five environments (MODULATE, DECAL, BLEND, REPLACE, ADD):
 * each frame draws the 125 combinations as tiles of a grid covering the
 * window, texture coordinates from -1.25 to 2.25, NEAREST on odd tiles and
 * LINEAR on even ones, then the whole grid again shifted by half a tile and
 * blended with SRC_ALPHA / ONE_MINUS_SRC_ALPHA.
 */
#include <GL/gl.h>
#include "bench.h"

#define NTEX 5
static GLuint tex[NTEX];

static void scene_setup(int w, int h)
{
    static const GLenum ifmt[NTEX] = {GL_LUMINANCE8, GL_LUMINANCE8_ALPHA8, GL_RGB8, GL_RGBA8,
                                      GL_RGBA8};
    static const GLenum fmt[NTEX] = {GL_LUMINANCE, GL_LUMINANCE_ALPHA, GL_RGB, GL_RGBA, GL_RGBA};
    static const int bpp[NTEX] = {1, 2, 3, 4, 4};
    static const int tw[NTEX] = {64, 64, 64, 64, 100}, th[NTEX] = {64, 64, 64, 64, 60};
    static unsigned char data[100 * 64 * 4];
    static const GLfloat border[4] = {0.9f, 0.2f, 0.6f, 0.7f};
    int t, i;
    BENCH_UNUSED(w, h);
    glGenTextures(NTEX, tex);
    for (t = 0; t < NTEX; t++) {
        for (i = 0; i < tw[t] * th[t] * bpp[t]; i++) {
            int c = i % bpp[t], x = (i / bpp[t]) % tw[t], y = (i / bpp[t]) / tw[t];
            data[i] = (unsigned char)((((x >> 3) ^ (y >> 3)) & 1) ? 230 - c * 40
                                                                 : 20 + x * 2 + c * 30);
        }
        glBindTexture(GL_TEXTURE_2D, tex[t]);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)ifmt[t], tw[t], th[t], 0, fmt[t], GL_UNSIGNED_BYTE,
                     data);
        glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    }
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_TEXTURE_2D);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glClearColor(0.15f, 0.1f, 0.2f, 1.0f);
}

static void grid(float shift)
{
    static const GLint wraps[5] = {GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER,
                                   GL_MIRRORED_REPEAT};
    static const GLint envs[5] = {GL_MODULATE, GL_DECAL, GL_BLEND, GL_REPLACE, GL_ADD};
    static const GLfloat envc[4] = {0.2f, 0.8f, 0.4f, 0.5f};
    const int cols = 12, rows = 11;
    int k;
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envc);
    for (k = 0; k < NTEX * 25; k++) {
        int t = k / 25, wr = (k / 5) % 5, env = k % 5;
        float x0 = -1.0f + 2.0f * ((float)(k % cols) + shift) / (float)cols;
        float y0 = -1.0f + 2.0f * ((float)(k / cols) + shift) / (float)rows;
        float x1 = x0 + 2.0f / (float)cols, y1 = y0 + 2.0f / (float)rows;
        GLint filt = (k & 1) ? GL_NEAREST : GL_LINEAR;
        glBindTexture(GL_TEXTURE_2D, tex[t]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wraps[wr]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wraps[(wr + k) % 5]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filt);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filt);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, envs[env]);
        glBegin(GL_QUADS);
        glColor4f(1.0f, 0.8f, 0.6f, 0.8f);
        glTexCoord2f(-1.25f, -1.25f);
        glVertex2f(x0, y0);
        glColor4f(0.6f, 1.0f, 0.8f, 0.6f);
        glTexCoord2f(2.25f, -1.25f);
        glVertex2f(x1, y0);
        glColor4f(0.8f, 0.6f, 1.0f, 0.9f);
        glTexCoord2f(2.25f, 2.25f);
        glVertex2f(x1, y1);
        glColor4f(1.0f, 1.0f, 1.0f, 0.7f);
        glTexCoord2f(-1.25f, 2.25f);
        glVertex2f(x0, y1);
        glEnd();
    }
}

static void scene_frame(int w, int h)
{
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_BLEND);
    grid(0.0f);
    glEnable(GL_BLEND);
    grid(0.5f);
}
