/* blend_premultiplied: premultiplied-alpha "over" (ONE, ONE_MINUS_SRC_ALPHA)
 * onto a transparent buffer, as a compositor builds a layer.  Colours are
 * premultiplied per vertex (so they interpolate as premultiplied values);
 * alpha-zero vertices with non-zero colour give additive glows.  The alpha
 * channel, which accumulates the coverage, is compared with the colour. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <math.h>
#include "common.h"

#define W 256
#define H 256

/* emit a premultiplied colour */
static void pm(float r, float g, float b, float a)
{
    glColor4f(r * a, g * a, b * a, a);
}

static void blob(float cx, float cy, float rx, float ry, float r, float g, float b,
                 float a_in, float a_out, int n)
{
    int i;
    glBegin(GL_TRIANGLE_FAN);
    pm(r, g, b, a_in);
    glVertex2f(cx, cy);
    for (i = 0; i <= n; i++) {
        float t = (float)i * 6.2831853f / (float)n;
        pm(g, b, r, a_out);
        glVertex2f(cx + rx * cosf(t), cy + ry * sinf(t));
    }
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    unsigned char *buf;
    int i;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);

    /* a half-transparent backdrop with a diagonal alpha gradient */
    glBegin(GL_QUADS);
    pm(0.37f, 0.21f, 0.59f, 0.13f);
    glVertex2f(0.0f, 0.0f);
    pm(0.83f, 0.47f, 0.11f, 0.61f);
    glVertex2f(256.0f, 0.0f);
    pm(0.19f, 0.73f, 0.67f, 0.87f);
    glVertex2f(256.0f, 256.0f);
    pm(0.97f, 0.91f, 0.29f, 0.0f);
    glVertex2f(0.0f, 256.0f);
    glEnd();

    /* overlapping soft blobs (alpha falls to the rim) */
    for (i = 0; i < 9; i++)
        blob(41.3f + 23.9f * i, 60.7f + 17.3f * (i % 4), 47.1f - 2.3f * i, 33.7f + 1.9f * i,
             0.93f - 0.07f * i, 0.17f + 0.09f * i, 0.41f, 0.89f - 0.05f * i, 0.07f * i, 20 + i);

    /* opaque-edged, hollow-centred rings: alpha 0 in the middle */
    for (i = 0; i < 3; i++)
        blob(60.7f + 69.1f * i, 180.3f, 39.9f, 51.1f, 0.3f * i, 0.8f, 1.0f - 0.3f * i, 0.0f,
             0.97f, 17);

    /* additive glow: colour with alpha 0 adds and saturates */
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 6; i++) {
        float x = 12.1f + 39.7f * i;
        glColor4f(0.37f, 0.29f, 0.13f, 0.0f);
        glVertex2f(x, 215.3f);
        glColor4f(0.71f, 0.05f, 0.53f, 0.0f);
        glVertex2f(x + 71.9f, 231.7f);
        glColor4f(0.11f, 0.67f, 0.91f, 0.0f);
        glVertex2f(x + 20.3f, 254.9f);
    }
    glEnd();

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
