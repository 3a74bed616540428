/* stress_degenerate: degenerate input mixed with normal triangles.
 * Image "mixed" (glOrtho, pixel coordinates), 8 columns x 2 rows of cells,
 * each with a normal smooth triangle and some of: zero-area triangles
 * (repeated vertices, collinear points, on pixel centres and edges), a
 * strip and a fan with repeated vertices, a quad with two equal corners,
 * NaN and +-Inf vertex coordinates, NaN/Inf colours.
 * Image "clipw" (glFrustum and glVertex4f): vertices with w = 0 and w < 0,
 * all-negative w, and a triangle with a NaN w, plus normal triangles.
 * Depth is on so a NaN depth that slipped through would show. */
#include <math.h>
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

static void normal_tri(float x, float y, int k)
{
    glColor3f(0.9f, 0.2f + 0.1f * (k % 6), 0.1f);
    glVertex3f(x + 2.3f, y + 3.1f, 0.2f);
    glColor3f(0.1f, 0.8f, 0.3f);
    glVertex3f(x + 28.7f, y + 6.6f, -0.3f);
    glColor3f(0.2f, 0.3f, 0.1f * (k % 9));
    glVertex3f(x + 12.1f, y + 29.4f, 0.0f);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    unsigned char *buf;
    float nan = nanf(""), inf = INFINITY;
    int i;
    GLenum err;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, W, 0.0, H, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    /* background: a normal triangle in each 32x32 cell of the bottom half */
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 32; i++)
        normal_tri(32.0f * (i % 8), 32.0f * (i / 8), i);
    glEnd();

    /* zero-area triangles, drawn white over the cells: must draw nothing */
    glColor3f(1.0f, 1.0f, 1.0f);
    glBegin(GL_TRIANGLES);
    /* repeated vertex (all three equal), on a pixel centre and an edge */
    glVertex2f(16.5f, 16.5f); glVertex2f(16.5f, 16.5f); glVertex2f(16.5f, 16.5f);
    glVertex2f(48.0f, 16.0f); glVertex2f(48.0f, 16.0f); glVertex2f(48.0f, 16.0f);
    /* two equal vertices */
    glVertex2f(70.0f, 4.5f); glVertex2f(90.0f, 25.5f); glVertex2f(70.0f, 4.5f);
    /* collinear: horizontal through pixel centres, vertical on an edge,
     * diagonal, and a long collinear one across the viewport */
    glVertex2f(100.0f, 12.5f); glVertex2f(110.0f, 12.5f); glVertex2f(125.0f, 12.5f);
    glVertex2f(140.0f, 3.0f); glVertex2f(140.0f, 17.0f); glVertex2f(140.0f, 29.0f);
    glVertex2f(161.0f, 1.0f); glVertex2f(175.0f, 15.0f); glVertex2f(190.0f, 30.0f);
    glVertex2f(-10.0f, 40.5f); glVertex2f(100.25f, 40.5f); glVertex2f(300.0f, 40.5f);
    glVertex2f(0.0f, 0.0f); glVertex2f(128.0f, 128.0f); glVertex2f(256.0f, 256.0f);
    glEnd();

    /* strip and fan with repeated vertices (degenerate joins), drawn green */
    glColor3f(0.2f, 1.0f, 0.4f);
    glBegin(GL_TRIANGLE_STRIP);
    glVertex2f(200.0f, 2.0f); glVertex2f(200.0f, 30.0f);
    glVertex2f(215.0f, 2.0f); glVertex2f(215.0f, 2.0f);    /* repeat */
    glVertex2f(215.0f, 30.0f); glVertex2f(215.0f, 30.0f);  /* repeat */
    glVertex2f(230.0f, 2.0f); glVertex2f(230.0f, 30.0f);
    glVertex2f(230.0f, 30.0f); glVertex2f(254.0f, 16.0f);
    glEnd();
    glColor3f(0.9f, 0.9f, 0.2f);
    glBegin(GL_TRIANGLE_FAN);
    glVertex2f(16.0f, 48.0f);
    glVertex2f(30.0f, 48.0f); glVertex2f(30.0f, 48.0f);
    glVertex2f(16.0f, 62.0f); glVertex2f(2.0f, 48.0f); glVertex2f(2.0f, 48.0f);
    glVertex2f(16.0f, 34.0f);
    glEnd();
    /* quad with two equal corners (a triangle), and a quad folded to a line */
    glBegin(GL_QUADS);
    glColor3f(1.0f, 0.5f, 0.0f);
    glVertex2f(36.0f, 36.0f); glVertex2f(60.0f, 36.0f);
    glVertex2f(60.0f, 36.0f); glVertex2f(48.0f, 60.0f);
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex2f(68.0f, 36.0f); glVertex2f(92.0f, 60.0f);
    glVertex2f(68.0f, 36.0f); glVertex2f(92.0f, 60.0f);
    glEnd();

    /* NaN and Inf vertex coordinates next to normal triangles (second row
     * of cells, y 64..127): the poisoned triangles must not disturb the
     * normal ones in the same glBegin */
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.0f, 1.0f);
    glVertex2f(nan, 70.0f); glVertex2f(30.0f, 70.0f); glVertex2f(15.0f, 95.0f);
    glColor3f(0.0f, 1.0f, 1.0f);
    glVertex2f(34.0f, 66.0f); glVertex2f(60.0f, 66.0f); glVertex2f(47.0f, 90.0f);
    glColor3f(1.0f, 0.0f, 1.0f);
    glVertex2f(66.0f, 70.0f); glVertex2f(inf, 70.0f); glVertex2f(80.0f, 95.0f);
    glColor3f(1.0f, 1.0f, 0.0f);
    glVertex2f(98.0f, 66.0f); glVertex2f(124.0f, 66.0f); glVertex2f(111.0f, 90.0f);
    glColor3f(1.0f, 0.0f, 1.0f);
    glVertex2f(130.0f, 70.0f); glVertex2f(150.0f, -inf); glVertex2f(145.0f, 95.0f);
    glVertex3f(162.0f, 66.0f, nan); glVertex3f(188.0f, 66.0f, 0.0f); glVertex3f(175.0f, 90.0f, 0.0f);
    glVertex3f(194.0f, 66.0f, inf); glVertex3f(220.0f, 66.0f, 0.0f); glVertex3f(207.0f, 90.0f, 0.0f);
    glVertex4f(226.0f, 66.0f, 0.0f, nan); glVertex2f(252.0f, 66.0f); glVertex2f(239.0f, 90.0f);
    glEnd();

    /* NaN and Inf colours on otherwise normal triangles (y 96..127): the
     * colour is unspecified but must not disturb coverage or neighbours.
     * Only the channel that is finite is compared meaningfully; the
     * poisoned channel is drawn with glColorMask off. */
    glBegin(GL_TRIANGLES);
    glColor3f(nan, 0.5f, 0.2f);
    glVertex2f(2.0f, 98.0f); glVertex2f(60.0f, 100.0f); glVertex2f(30.0f, 126.0f);
    glColor3f(0.3f, inf, 0.2f);
    glVertex2f(66.0f, 98.0f); glVertex2f(124.0f, 100.0f); glVertex2f(94.0f, 126.0f);
    glColor3f(0.3f, 0.5f, -inf);
    glVertex2f(130.0f, 98.0f); glVertex2f(188.0f, 100.0f); glVertex2f(158.0f, 126.0f);
    glEnd();
    /* smooth: one NaN vertex colour among normal ones, with the NaN channel
     * masked out of the write */
    glColorMask(GL_FALSE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBegin(GL_TRIANGLES);
    glColor3f(0.2f, 0.1f, 0.9f);
    glVertex2f(194.0f, 98.0f);
    glColor3f(nan, 0.9f, 0.1f);
    glVertex2f(252.0f, 100.0f);
    glColor3f(0.8f, 0.4f, 0.4f);
    glVertex2f(222.0f, 126.0f);
    glEnd();
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    /* a full-size normal triangle after everything: state still sane */
    glBegin(GL_TRIANGLES);
    glColor3f(0.5f, 0.5f, 0.5f);
    glVertex3f(3.0f, 130.0f, 0.5f);
    glColor3f(0.9f, 0.1f, 0.4f);
    glVertex3f(250.0f, 132.0f, 0.5f);
    glColor3f(0.1f, 0.4f, 0.9f);
    glVertex3f(120.0f, 252.0f, 0.5f);
    glEnd();
    glFinish();
    err = glGetError();
    sgl_text(out, "error_mixed", "0x%x\n", (unsigned)err);
    sgl_image(out, "mixed", W, H, 4, "RGBA", W * 4, 1, buf);

    /* --- w = 0 and w < 0 vertices through glVertex4f --- */
    glClearColor(0.12f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    /* identity matrices: clip = object coordinates */
    glBegin(GL_TRIANGLES);
    /* a normal triangle */
    glColor3f(1.0f, 0.0f, 0.0f); glVertex4f(-0.9f, -0.9f, 0.0f, 1.0f);
    glColor3f(0.0f, 1.0f, 0.0f); glVertex4f(-0.1f, -0.8f, 0.0f, 1.0f);
    glColor3f(0.0f, 0.0f, 1.0f); glVertex4f(-0.5f, -0.1f, 0.0f, 1.0f);
    /* one vertex with w = 0 (a point at infinity in direction (0.3, 0.2)) */
    glColor3f(1.0f, 1.0f, 0.0f); glVertex4f(0.1f, -0.9f, 0.0f, 1.0f);
    glColor3f(0.0f, 1.0f, 1.0f); glVertex4f(0.9f, -0.8f, 0.0f, 1.0f);
    glColor3f(1.0f, 0.0f, 1.0f); glVertex4f(0.3f, 0.2f, 0.0f, 0.0f);
    /* one vertex with w < 0 (external triangle: the clipped part is what
     * lies between the other two and the far side) */
    glColor3f(0.9f, 0.5f, 0.1f); glVertex4f(-0.9f, 0.1f, 0.0f, 1.0f);
    glColor3f(0.1f, 0.5f, 0.9f); glVertex4f(-0.2f, 0.15f, 0.0f, 1.0f);
    glColor3f(0.5f, 0.9f, 0.1f); glVertex4f(0.3f, 0.4f, 0.1f, -0.5f);
    /* two vertices with w < 0 */
    glColor3f(0.8f, 0.8f, 0.8f); glVertex4f(0.5f, 0.5f, 0.0f, 1.0f);
    glColor3f(0.8f, 0.2f, 0.2f); glVertex4f(0.2f, -0.1f, 0.0f, -1.0f);
    glColor3f(0.2f, 0.2f, 0.8f); glVertex4f(-0.3f, 0.1f, 0.0f, -2.0f);
    /* all w < 0: the image of a triangle behind the eye, drawn nothing */
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex4f(-0.5f, 0.5f, 0.0f, -1.0f);
    glVertex4f(0.5f, 0.5f, 0.0f, -1.0f);
    glVertex4f(0.0f, 0.9f, 0.0f, -1.0f);
    /* all w = 0 */
    glVertex4f(-0.5f, 0.6f, 0.0f, 0.0f);
    glVertex4f(0.5f, 0.6f, 0.0f, 0.0f);
    glVertex4f(0.0f, 0.95f, 0.0f, 0.0f);
    /* w = 0 and x = y = z = 0 */
    glVertex4f(0.0f, 0.0f, 0.0f, 0.0f);
    glVertex4f(0.9f, 0.6f, 0.0f, 1.0f);
    glVertex4f(0.6f, 0.9f, 0.0f, 1.0f);
    /* a NaN w */
    glVertex4f(-0.9f, 0.7f, 0.0f, nan);
    glVertex4f(-0.6f, 0.95f, 0.0f, 1.0f);
    glVertex4f(-0.95f, 0.95f, 0.0f, 1.0f);
    glEnd();
    /* the same under glFrustum: vertices exactly on the eye plane and
     * behind it, in a quad strip */
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 10.0);
    glViewport(128, 0, 128, 128);
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i < 8; i++) {
        float z = 1.5f - 0.9f * i; /* eye z from +1.5 (behind) to -4.8 */
        glColor3f(0.12f * i, 0.9f - 0.1f * i, 0.5f);
        glVertex3f(-1.5f + 0.1f * i, -0.8f, z);
        glVertex3f(1.3f, -0.6f + 0.15f * i, (i == 2) ? 0.0f : z);
    }
    glEnd();
    glViewport(0, 0, W, H);
    glFinish();
    err = glGetError();
    sgl_text(out, "error_clipw", "0x%x\n", (unsigned)err);
    sgl_image(out, "clipw", W, H, 4, "RGBA", W * 4, 1, buf);

    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
