/* rect_pairs: axis-aligned quads whose two triangles share every plane
 * (sprites, UI rectangles).  softgl draws such a pair as one rectangle
 * (src/raster/batch.rs, `pair`); every pixel must still be what llvmpipe
 * gives for the two triangles.  Image 0: 400 textured, blended sprites
 * (LINEAR, REPLACE, SRC_ALPHA/ONE_MINUS_SRC_ALPHA) of 0.3 to 40 px at random
 * sub-pixel positions, from one glDrawArrays(GL_QUADS) that stays inside the
 * window (the no-clip path: both triangles start at v0).  Image 1: smooth
 * rectangles whose corner colours are affine in x and y, depth-tested
 * rectangles at constant depths, rectangles on pixel centres and on pixel
 * edges, and glRectf.  Image 2: the same sprites with MODULATE by a per-quad
 * colour, 32 px wide (two 8-pixel chunks and more per row). */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256
#define N 400
#define TS 8

static GLfloat pos[N * 8], uv[N * 8], col[N * 16];

static void make_quads(int n, float minsz, float maxsz)
{
    int i, k;
    for (i = 0; i < n; i++) {
        float sw = minsz + sgl_randf() * (maxsz - minsz);
        float sh = minsz + sgl_randf() * (maxsz - minsz);
        float x0 = 0.5f + sgl_randf() * ((float)W - sw - 1.0f);
        float y0 = 0.5f + sgl_randf() * ((float)H - sh - 1.0f);
        float r = sgl_randf(), g = sgl_randf(), b = sgl_randf(), a = 0.3f + 0.7f * sgl_randf();
        if (i % 7 == 0) {
            x0 = (float)(int)x0 + 0.5f;
            y0 = (float)(int)y0;
            sw = (float)(int)sw + 1.0f;
        }
        k = i * 8;
        pos[k + 0] = x0;      pos[k + 1] = y0;
        pos[k + 2] = x0 + sw; pos[k + 3] = y0;
        pos[k + 4] = x0 + sw; pos[k + 5] = y0 + sh;
        pos[k + 6] = x0;      pos[k + 7] = y0 + sh;
        uv[k + 0] = 0.0f; uv[k + 1] = 0.0f;
        uv[k + 2] = 1.0f; uv[k + 3] = 0.0f;
        uv[k + 4] = 1.0f; uv[k + 5] = 1.0f;
        uv[k + 6] = 0.0f; uv[k + 7] = 1.0f;
        for (k = 0; k < 4; k++) {
            col[i * 16 + k * 4 + 0] = r;
            col[i * 16 + k * 4 + 1] = g;
            col[i * 16 + k * 4 + 2] = b;
            col[i * 16 + k * 4 + 3] = a;
        }
    }
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    unsigned char *buf;
    static unsigned char img[TS * TS * 4];
    GLuint tex;
    int i, x, y;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    for (y = 0; y < TS; y++) {
        for (x = 0; x < TS; x++) {
            unsigned char *p = &img[(y * TS + x) * 4];
            p[0] = (unsigned char)(x * 32 + 10);
            p[1] = (unsigned char)(y * 32 + 5);
            p[2] = (unsigned char)((x ^ y) * 30);
            p[3] = (unsigned char)(((x + y) * 37) & 255);
        }
    }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, TS, TS, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, (double)W, 0.0, (double)H, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);

    /* Image 0: textured sprites. */
    glClearColor(0.1f, 0.12f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    make_quads(N, 0.3f, 40.0f);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glTexCoordPointer(2, GL_FLOAT, 0, uv);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glDrawArrays(GL_QUADS, 0, 4 * N);
    glFinish();
    sgl_image(out, "sprites", W, H, 4, "RGBA", W * 4, 1, buf);

    /* Image 1: untextured rectangles. */
    glDisable(GL_TEXTURE_2D);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_BLEND);
    /* Smooth, corner colours affine in x and y. */
    glBegin(GL_QUADS);
    for (i = 0; i < 60; i++) {
        float x0 = 2.0f + sgl_randf() * 200.0f, y0 = 2.0f + sgl_randf() * 200.0f;
        float x1 = x0 + 0.5f + sgl_randf() * 50.0f, y1 = y0 + 0.5f + sgl_randf() * 50.0f;
        glColor3f(x0 / 256.0f, y0 / 256.0f, 0.5f);
        glVertex2f(x0, y0);
        glColor3f(x1 / 256.0f, y0 / 256.0f, 0.5f);
        glVertex2f(x1, y0);
        glColor3f(x1 / 256.0f, y1 / 256.0f, 0.5f);
        glVertex2f(x1, y1);
        glColor3f(x0 / 256.0f, y1 / 256.0f, 0.5f);
        glVertex2f(x0, y1);
    }
    glEnd();
    /* Depth-tested rectangles at constant depths, on pixel centres and edges. */
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    for (i = 0; i < 80; i++) {
        float x0 = (float)(int)(sgl_randf() * 220.0f), y0 = (float)(int)(sgl_randf() * 220.0f);
        float z = sgl_randf() * 1.8f - 0.9f;
        float half = (i & 1) ? 0.5f : 0.0f;
        glColor4f(sgl_randf(), sgl_randf(), sgl_randf(), 1.0f);
        glBegin(GL_QUADS);
        glVertex3f(x0 + half, y0 + half, z);
        glVertex3f(x0 + half + 3.0f + (float)(i % 30), y0 + half, z);
        glVertex3f(x0 + half + 3.0f + (float)(i % 30), y0 + half + 2.0f + (float)(i % 23), z);
        glVertex3f(x0 + half, y0 + half + 2.0f + (float)(i % 23), z);
        glEnd();
    }
    glDisable(GL_DEPTH_TEST);
    glColor3f(0.9f, 0.8f, 0.1f);
    glRectf(10.25f, 230.75f, 70.6f, 250.1f);
    glRectf(120.5f, 240.5f, 121.5f, 241.5f);
    glRectf(200.0f, 200.0f, 199.7f, 230.0f); /* clockwise: the other winding */
    glFinish();
    sgl_image(out, "rects", W, H, 4, "RGBA", W * 4, 1, buf);

    /* Image 2: MODULATE by a per-quad colour, wide sprites. */
    glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    make_quads(150, 20.0f, 32.0f);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_BLEND);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glColorPointer(4, GL_FLOAT, 0, col);
    glDrawArrays(GL_QUADS, 0, 4 * 150);
    glFinish();
    sgl_image(out, "modulate", W, H, 4, "RGBA", W * 4, 1, buf);

    OSMesaDestroyContext(ctx);
    free(buf);
    sgl_close(out);
    return 0;
}
