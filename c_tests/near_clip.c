/* near_clip: clipping.  Under a glFrustum perspective: triangles crossing
 * the near plane, triangles with vertices behind the eye (clip w < 0),
 * a triangle entirely behind the eye, triangles crossing the far plane and
 * the left/right/top/bottom planes, a large quad spanning past all four
 * sides, and a strip and a fan crossing several planes at once. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

static void tri(const float *a, const float *b, const float *c, int k)
{
    glColor3f(1.0f, 0.2f + 0.1f * (k % 7), 0.1f);
    glVertex3fv(a);
    glColor3f(0.1f, 1.0f, 0.15f * (k % 5));
    glVertex3fv(b);
    glColor3f(0.2f * (k % 4), 0.3f, 1.0f);
    glVertex3fv(c);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
    unsigned char *buf;
    int i;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.1f, 0.1f, 0.13f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1.0137, 0.9871, -0.9713, 1.0317, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);

    /* a big quad far away, spanning past all sides, split by clipping */
    glBegin(GL_QUADS);
    glColor3f(0.3f, 0.0f, 0.3f);
    glVertex3f(-60.1f, -47.7f, -25.5f);
    glColor3f(0.0f, 0.3f, 0.3f);
    glVertex3f(55.5f, -50.3f, -25.5f);
    glColor3f(0.3f, 0.3f, 0.0f);
    glVertex3f(49.9f, 61.1f, -25.5f);
    glColor3f(0.1f, 0.1f, 0.4f);
    glVertex3f(-51.3f, 58.7f, -25.5f);
    glEnd();

    glBegin(GL_TRIANGLES);
    {
        /* crosses the near plane (z = -1): one vertex in front of it */
        float a[3] = {-0.91f, -0.77f, -0.5f}, b[3] = {0.63f, -0.41f, -4.3f},
              c[3] = {-0.2f, 0.95f, -3.1f};
        tri(a, b, c, 0);
    }
    {
        /* two vertices behind the eye (z > 0, clip w < 0) */
        float a[3] = {1.5f, 1.3f, 2.7f}, b[3] = {-1.1f, 0.9f, 0.9f},
              c[3] = {0.37f, 0.61f, -2.9f};
        tri(a, b, c, 1);
    }
    {
        /* one vertex exactly at the eye plane (w = 0) */
        float a[3] = {0.5f, -0.5f, 0.0f}, b[3] = {2.1f, -1.9f, -6.6f},
              c[3] = {0.9f, 0.4f, -5.5f};
        tri(a, b, c, 2);
    }
    {
        /* entirely behind the eye: must draw nothing */
        float a[3] = {-1.0f, -1.0f, 3.0f}, b[3] = {1.0f, -1.0f, 3.0f},
              c[3] = {0.0f, 1.0f, 3.0f};
        tri(a, b, c, 3);
    }
    {
        /* crosses the far plane */
        float a[3] = {-9.0f, -9.0f, -20.0f}, b[3] = {9.0f, -3.0f, -45.0f},
              c[3] = {-3.0f, 11.0f, -38.0f};
        tri(a, b, c, 4);
    }
    /* fans of thin triangles crossing left, right, top, bottom planes */
    for (i = 0; i < 16; i++) {
        float ang = i * 0.3926991f;
        float dx = (i & 1) ? 13.7f : 4.3f;
        float a[3], b[3], c[3];
        a[0] = -0.17f; a[1] = 0.13f; a[2] = -5.3f;
        b[0] = dx * (i < 4 || i > 12 ? 1.0f : (i < 8 ? 0.3f : -1.0f)) + 0.3f * ang;
        b[1] = dx * (i < 8 ? 0.5f : -0.7f) - 0.2f * ang;
        b[2] = -4.1f - i * 0.3f;
        c[0] = b[0] + 1.3f - 0.17f * i;
        c[1] = b[1] + 2.1f - 0.31f * i;
        c[2] = -6.0f + i * 0.1f;
        tri(a, b, c, i + 5);
    }
    glEnd();

    /* a strip running from behind the eye to far away */
    glBegin(GL_TRIANGLE_STRIP);
    for (i = 0; i < 12; i++) {
        float z = 3.3f - i * 3.1f;
        glColor3f(0.08f * i, 0.5f, 1.0f - 0.08f * i);
        glVertex3f((i & 1) ? -2.3f : -1.1f, -1.3f + 0.05f * i, z);
    }
    glEnd();

    /* a fan around the near plane corners */
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex3f(1.2f, 0.8f, -2.0f);
    for (i = 0; i < 9; i++) {
        glColor3f(0.1f * i, 0.9f - 0.1f * i, 0.5f);
        glVertex3f(1.2f + 2.5f * ((i % 3) - 1), 0.8f + 2.5f * ((i / 3) - 1), -0.6f - 0.2f * i);
    }
    glEnd();

    /* orthographic part: near/far clipping in z with a small viewport */
    glViewport(170, 3, 83, 61);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-1.0, 1.0, -1.0, 1.0, -0.5, 0.5);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClear(GL_DEPTH_BUFFER_BIT); /* whole buffer: viewport does not limit clears */
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.0f, 0.0f);
    glVertex3f(-1.3f, -0.9f, -0.9f);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex3f(1.3f, -0.7f, 0.9f);
    glColor3f(0.0f, 0.0f, 1.0f);
    glVertex3f(0.1f, 1.4f, 0.1f);
    glEnd();

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
