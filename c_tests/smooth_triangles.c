/* smooth_triangles: smooth-shaded triangles with per-vertex colours at
 * awkward coordinates: slivers, shared edges (fill rule), a fan, tiny and
 * large triangles, colours given as float, ubyte and double. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <math.h>
#include "common.h"

#define W 256
#define H 256

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf;
    int i;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    memset(buf, 0x5a, W * H * 4);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.1337f, 0.2113f, 0.3071f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.37, 13.37, -2.5, 12.1, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    /* A big triangle with colours at the corners. */
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.0f, 0.0f);
    glVertex2f(-0.77f, -1.93f);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex2f(12.9f, -0.41f);
    glColor3f(0.0f, 0.0f, 1.0f);
    glVertex2f(5.137f, 11.71f);
    glEnd();

    /* A grid of triangles sharing edges; each pixel on a shared edge must be
     * drawn exactly once, which shows in the colours. */
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 6; i++) {
        int j;
        for (j = 0; j < 6; j++) {
            float x0 = 0.3137f + i * 1.1119f, y0 = 0.2713f + j * 0.9871f;
            float x1 = x0 + 1.1119f, y1 = y0 + 0.9871f;
            glColor3ub((GLubyte)(i * 40 + 13), (GLubyte)(j * 37 + 7), 200);
            glVertex2f(x0, y0);
            glColor3ub(250, (GLubyte)(i * 21), (GLubyte)(j * 41));
            glVertex2f(x1, y0 + 0.0313f * i);
            glColor3ub(17, 240, (GLubyte)(i * j * 7));
            glVertex2f(x1, y1);

            glColor3ub((GLubyte)(i * 40 + 13), (GLubyte)(j * 37 + 7), 200);
            glVertex2f(x0, y0);
            glColor3ub(17, 240, (GLubyte)(i * j * 7));
            glVertex2f(x1, y1);
            glColor4f(0.5f, 0.5f, 0.5f, 1.0f);
            glVertex2f(x0 - 0.0171f * j, y1);
        }
    }
    glEnd();

    /* A fan around an off-grid centre. */
    glBegin(GL_TRIANGLE_FAN);
    glColor3d(0.9137, 0.8021, 0.1003);
    glVertex2d(10.137, 9.733);
    for (i = 0; i <= 13; i++) {
        double a = i * 6.2831853 / 13.0;
        double r = 1.0 + 0.63 * (i & 1);
        glColor3d(0.5 + 0.5 * (i % 3 == 0), 0.3 * (i % 2), 0.071 * i);
        glVertex2d(10.137 + r * (a < 3.1 ? 1.0 : 0.913) * cos(a),
                   9.733 + r * sin(a));
    }
    glEnd();

    /* Random triangles: slivers and small ones. */
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 60; i++) {
        float cx = -1.0f + 14.0f * sgl_randf();
        float cy = -2.0f + 14.0f * sgl_randf();
        float s = (i % 4 == 0) ? 4.0f : 0.6f;
        int k;
        for (k = 0; k < 3; k++) {
            glColor4f(sgl_randf(), sgl_randf(), sgl_randf(), 1.0f);
            if (i % 5 == 1 && k == 2)
                glVertex2f(cx + s * 0.9f, cy + s * 0.013f); /* sliver */
            else
                glVertex2f(cx + s * (sgl_randf() - 0.5f),
                           cy + s * (sgl_randf() - 0.5f));
        }
    }
    glEnd();

    /* Colours outside [0,1] are clamped. */
    glBegin(GL_TRIANGLES);
    glColor3f(1.7f, -0.3f, 0.5f);
    glVertex2f(-1.2f, 10.9f);
    glColor3f(-2.0f, 1.3f, 3.0f);
    glVertex2f(3.33f, 11.95f);
    glColor3f(0.25f, 0.5f, -1.0f);
    glVertex2f(0.41f, 7.77f);
    glEnd();

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
