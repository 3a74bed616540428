/* blend_over: straight-alpha "over" compositing (SRC_ALPHA,
 * ONE_MINUS_SRC_ALPHA) the way a real program sorts it: opaque geometry
 * first with depth test and depth writes, then transparent geometry
 * back-to-front with glDepthMask(GL_FALSE), so transparent layers behind
 * the opaque ones are rejected by the depth test.  Per-vertex alpha is
 * smooth, colours and coordinates are odd, and the alpha channel of the
 * buffer (which the blend also writes) is compared too. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <math.h>
#include "common.h"

#define W 256
#define H 256

static void tri(float x0, float y0, float x1, float y1, float x2, float y2, float z,
                const float *c0, const float *c1, const float *c2)
{
    glBegin(GL_TRIANGLES);
    glColor4fv(c0);
    glVertex3f(x0, y0, z);
    glColor4fv(c1);
    glVertex3f(x1, y1, z);
    glColor4fv(c2);
    glVertex3f(x2, y2, z);
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    unsigned char *buf;
    int i;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.11f, 0.17f, 0.23f, 0.37f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);

    /* opaque pass: vertex z grows towards the viewer (glOrtho flips z) */
    {
        static const float a[4] = {0.83f, 0.29f, 0.17f, 1.0f};
        static const float b[4] = {0.91f, 0.77f, 0.13f, 0.71f};
        static const float c[4] = {0.23f, 0.53f, 0.89f, 0.43f};
        static const float d[4] = {0.31f, 0.83f, 0.41f, 1.0f};
        tri(20.3f, 30.7f, 230.9f, 60.1f, 110.4f, 140.6f, 0.1f, a, b, c);
        tri(150.2f, 120.3f, 250.7f, 240.9f, 60.6f, 220.1f, -0.2f, c, d, a);
        glBegin(GL_QUADS); /* a tilted opaque quad, depth crosses the layers */
        glColor4fv(d);
        glVertex3f(5.7f, 150.3f, -0.9f);
        glColor4fv(b);
        glVertex3f(120.1f, 160.9f, 0.9f);
        glColor4fv(a);
        glVertex3f(118.4f, 250.2f, 0.9f);
        glColor4fv(c);
        glVertex3f(9.9f, 241.6f, -0.9f);
        glEnd();
    }

    /* transparent pass, back to front */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    for (i = 0; i < 14; i++) {
        float z = -0.85f + 0.13f * i;
        float cx = 31.3f + 14.7f * i, cy = 47.9f + 11.3f * (i % 7);
        float c0[4] = {0.37f + 0.04f * i, 0.13f, 0.91f - 0.05f * i, 0.12f + 0.05f * i};
        float c1[4] = {0.05f, 0.61f + 0.02f * i, 0.29f, 0.83f - 0.04f * i};
        float c2[4] = {0.97f, 0.89f, 0.07f * i, 0.37f};
        tri(cx - 29.1f, cy - 23.7f, cx + 41.3f, cy - 9.9f, cx + 3.3f, cy + 61.7f, z, c0, c1, c2);
    }

    /* a ribbon whose alpha runs from 0 to 1, crossing everything */
    glBegin(GL_TRIANGLE_STRIP);
    for (i = 0; i <= 16; i++) {
        float t = i / 16.0f;
        glColor4f(1.0f - t, 0.5f + 0.3f * t, t, t);
        glVertex3f(3.3f + 15.6f * i, 100.7f + 20.1f * t, 0.95f);
        glColor4f(0.2f, 1.0f - t, 0.6f, 1.0f - t);
        glVertex3f(3.9f + 15.6f * i, 121.3f + 40.9f * t, 0.95f);
    }
    glEnd();

    /* nearly invisible and nearly opaque fans (alpha 1/255 .. 254/255) */
    glBegin(GL_TRIANGLE_FAN);
    glColor4ub(255, 255, 255, 1);
    glVertex3f(200.5f, 40.5f, 0.97f);
    for (i = 0; i <= 24; i++) {
        float a = (float)i * 0.2617994f;
        glColor4ub((GLubyte)(10 * i), 200, (GLubyte)(255 - 10 * i), (GLubyte)(254 - 10 * i));
        glVertex3f(200.5f + 47.3f * cosf(a), 40.5f + 37.1f * sinf(a), 0.97f);
    }
    glEnd();

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
