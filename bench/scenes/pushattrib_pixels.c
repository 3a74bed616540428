/*
 * pushattrib_pixels.c - glPushAttrib/glPopAttrib around glDrawPixels and glBitmap.
 *
 * Each frame: 24 rounds of glPushAttrib (GL_ALL_ATTRIB_BITS, or a union of
 * COLOR_BUFFER, PIXEL_MODE, CURRENT, ENABLE and DEPTH bits), a state change
 * (blending, pixel zoom 1-2.5, GL_RED_SCALE/GL_GREEN_BIAS transfer, depth
 * test with a raster position depth, colour mask), one glDrawPixels of a
 * 96x96 RGBA (or 128x64 RGB) image at a raster position, and 120 13x8
 * glBitmap glyphs in the current raster colour; then glPopAttrib.  A
 * glPushClientAttrib guards the unpack alignment.
 */
#include <GL/gl.h>
#include "bench.h"

static unsigned char img_rgba[96 * 96 * 4];
static unsigned char img_rgb[128 * 64 * 3];
static GLubyte glyphs[16][13];

static void scene_setup(int w, int h)
{
    int i, j;
    BENCH_UNUSED(w, h);
    for (i = 0; i < 96 * 96; i++) {
        int x = i % 96, y = i / 96;
        img_rgba[i * 4 + 0] = (unsigned char)(x * 2 + 40);
        img_rgba[i * 4 + 1] = (unsigned char)(y * 2 + 20);
        img_rgba[i * 4 + 2] = (unsigned char)((x ^ y) & 16 ? 220 : 60);
        img_rgba[i * 4 + 3] = (unsigned char)(255 - x - y);
    }
    for (i = 0; i < 128 * 64; i++) {
        int x = i % 128, y = i / 128;
        img_rgb[i * 3 + 0] = (unsigned char)(x * 2);
        img_rgb[i * 3 + 1] = (unsigned char)((x / 8 + y / 8) & 1 ? 200 : 30);
        img_rgb[i * 3 + 2] = (unsigned char)(y * 4);
    }
    for (i = 0; i < 16; i++)
        for (j = 0; j < 13; j++)
            glyphs[i][j] = (GLubyte)((0x5A ^ (i * 37) ^ (j * 11)) & 0xFE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.15f, 0.1f, 1.0f);
    glDepthFunc(GL_LESS);
}

static void scene_frame(int w, int h)
{
    int r, g;
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (r = 0; r < 24; r++) {
        float x = -1.0f + 1.6f * (float)((r * 7) % 24) / 24.0f;
        float y = -1.0f + 1.6f * (float)((r * 11) % 24) / 24.0f;
        glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
        glPushAttrib((r % 3) == 0 ? GL_ALL_ATTRIB_BITS
                                  : (GL_COLOR_BUFFER_BIT | GL_PIXEL_MODE_BIT | GL_CURRENT_BIT |
                                     GL_ENABLE_BIT | GL_DEPTH_BUFFER_BIT));
        if (r & 1) {
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        }
        if (r & 2) {
            glPixelTransferf(GL_RED_SCALE, 0.6f);
            glPixelTransferf(GL_GREEN_BIAS, 0.2f);
        }
        if (r & 4) {
            glEnable(GL_DEPTH_TEST);
        }
        if (r % 5 == 4)
            glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
        glPixelZoom(1.0f + 0.25f * (float)(r % 7), 1.0f + 0.2f * (float)(r % 5));
        glRasterPos3f(x, y, 0.9f - 0.07f * (float)r);
        if (r & 8) {
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glDrawPixels(128, 64, GL_RGB, GL_UNSIGNED_BYTE, img_rgb);
        } else {
            glDrawPixels(96, 96, GL_RGBA, GL_UNSIGNED_BYTE, img_rgba);
        }
        glColor3f(1.0f - 0.04f * (float)r, 0.9f, 0.2f + 0.03f * (float)r);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glRasterPos2f(-1.0f, -1.0f + 2.0f * (float)r / 24.0f);
        for (g = 0; g < 120; g++)
            glBitmap(8, 13, 0.0f, 0.0f, (float)w / 60.0f, (g % 60 == 59) ? (float)h / 48.0f : 0.0f,
                     glyphs[(g + r) % 16]);
        glPopAttrib();
        glPopClientAttrib();
    }
}
