/*
 * sprites_10k.c - (g) 10,000 textured, blended 2D sprites.
 *
 * A 2D game-style pass: pixel-space glOrtho, a 32x32 RGBA sprite (a soft
 * disc with alpha), GL_REPLACE texture environment, GL_SRC_ALPHA /
 * GL_ONE_MINUS_SRC_ALPHA blending, and 10,000 sprites of 16x16 pixels at
 * 512x512 (scaled with the window) drawn from client vertex and texcoord
 * arrays with one glDrawArrays(GL_QUADS).
 */
#include <GL/gl.h>
#include <math.h>
#include "bench.h"

#define SPRITES 10000
#define SS 32

static GLuint tex;
static float *pos, *uv;

static void scene_setup(int w, int h)
{
    static unsigned char img[SS * SS * 4];
    float size = 16.0f * (float)w / 512.0f;
    int x, y, i, k;
    for (y = 0; y < SS; y++) {
        for (x = 0; x < SS; x++) {
            unsigned char *p = &img[(y * SS + x) * 4];
            float dx = ((float)x + 0.5f) / SS * 2.0f - 1.0f;
            float dy = ((float)y + 0.5f) / SS * 2.0f - 1.0f;
            float d = sqrtf(dx * dx + dy * dy);
            float a = d >= 1.0f ? 0.0f : 1.0f - d * d;
            p[0] = (unsigned char)(255.0f * (0.6f + 0.4f * dx * dx));
            p[1] = (unsigned char)(255.0f * (0.5f + 0.5f * dy));
            p[2] = (unsigned char)(200.0f * (1.0f - d > 0.0f ? 1.0f - d : 0.0f) + 40.0f);
            p[3] = (unsigned char)(255.0f * a);
        }
    }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, SS, SS, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_DEPTH_TEST);

    pos = malloc(sizeof(float) * 8 * SPRITES);
    uv = malloc(sizeof(float) * 8 * SPRITES);
    if (!pos || !uv) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }
    for (i = 0, k = 0; i < SPRITES; i++, k += 8) {
        float x0 = bench_randf() * ((float)w - size);
        float y0 = bench_randf() * ((float)h - size);
        pos[k + 0] = x0;
        pos[k + 1] = y0;
        pos[k + 2] = x0 + size;
        pos[k + 3] = y0;
        pos[k + 4] = x0 + size;
        pos[k + 5] = y0 + size;
        pos[k + 6] = x0;
        pos[k + 7] = y0 + size;
        uv[k + 0] = 0.0f;
        uv[k + 1] = 0.0f;
        uv[k + 2] = 1.0f;
        uv[k + 3] = 0.0f;
        uv[k + 4] = 1.0f;
        uv[k + 5] = 1.0f;
        uv[k + 6] = 0.0f;
        uv[k + 7] = 1.0f;
    }
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glTexCoordPointer(2, GL_FLOAT, 0, uv);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, (double)w, 0.0, (double)h, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.1f, 0.12f, 0.2f, 1.0f);
}

static void scene_frame(int w, int h)
{
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT);
    glDrawArrays(GL_QUADS, 0, 4 * SPRITES);
}
