/* stress_thin_fans: fans of thousands of very thin triangles drawn with
 * additive blending (glBlendFunc(GL_ONE, GL_ONE)) and a small colour, so
 * a pixel covered twice or not at all by the fan shows as a brighter or
 * darker one.  Images: 4000 slivers around a centre inside the viewport;
 * 3000 around a pixel corner reaching 1e4 px out; a fan whose centre is
 * 600 px off-screen; a GL_TRIANGLES fan (not GL_TRIANGLE_FAN) of 2000
 * slivers around a centre off the top-right corner; a perspective fan on a
 * tilted plane; and two half-fans meeting along a shared edge. */
#include <math.h>
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

static void begin_image(void)
{
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, W, 0.0, H, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
}

/* A GL_TRIANGLE_FAN of n slivers around (cx, cy) from angle a0 to a1 at
 * radius r; colour alternates so neighbours can be told apart. */
static void fan(float cx, float cy, float r, float a0, float a1, int n)
{
    int i;
    glBegin(GL_TRIANGLE_FAN);
    glColor4ub(40, 40, 40, 255);
    glVertex2f(cx, cy);
    for (i = 0; i <= n; i++) {
        float a = a0 + (a1 - a0) * (float)i / (float)n;
        glColor4ub((GLubyte)(20 + (i & 1) * 10), (GLubyte)(12 + (i % 3) * 4),
                   (GLubyte)(30 - (i & 1) * 10), 255);
        glVertex2f(cx + r * cosf(a), cy + r * sinf(a));
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

    /* 1: 4000 slivers around an inside point, full circle */
    begin_image();
    fan(128.3f, 127.7f, 300.0f, 0.0f, 6.2831853f, 4000);
    glFinish();
    sgl_image(out, "fan4000", W, H, 4, "RGBA", W * 4, 1, buf);

    /* 2: 3000 slivers around a pixel corner, radius 1e4 */
    begin_image();
    fan(128.0f, 128.0f, 1e4f, 0.0f, 6.2831853f, 3000);
    glFinish();
    sgl_image(out, "fan_corner_1e4", W, H, 4, "RGBA", W * 4, 1, buf);

    /* 3: centre 600 px left of the viewport, a narrow angle sweeping it */
    begin_image();
    fan(-600.0f, 131.3f, 1200.0f, -0.25f, 0.25f, 3000);
    glFinish();
    sgl_image(out, "fan_offscreen", W, H, 4, "RGBA", W * 4, 1, buf);

    /* 4: separate GL_TRIANGLES (vertices recomputed per triangle, so the
     * shared edges must be bit-identical through the same formula) around
     * a centre off the top-right corner */
    begin_image();
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 2000; i++) {
        float cx = 300.5f, cy = 290.25f, r = 700.0f;
        float a0 = 3.1415927f + 1.5707964f * (float)i / 2000.0f;
        float a1 = 3.1415927f + 1.5707964f * (float)(i + 1) / 2000.0f;
        glColor4ub(25, (GLubyte)(10 + (i & 3) * 5), 15, 255);
        glVertex2f(cx, cy);
        glVertex2f(cx + r * cosf(a0), cy + r * sinf(a0));
        glVertex2f(cx + r * cosf(a1), cy + r * sinf(a1));
    }
    glEnd();
    glFinish();
    sgl_image(out, "tris_offcorner", W, H, 4, "RGBA", W * 4, 1, buf);

    /* 5: perspective: a fan lying on a tilted plane, centre in view,
     * rim crossing the near plane and the sides */
    begin_image();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.1, 0.1, -0.1, 0.1, 0.1, 100.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.13f, -0.4f, -3.0f);
    glRotatef(-71.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(17.0f, 0.0f, 0.0f, 1.0f);
    glBegin(GL_TRIANGLE_FAN);
    glColor4ub(30, 30, 30, 255);
    glVertex3f(0.0f, 0.0f, 0.0f);
    for (i = 0; i <= 2500; i++) {
        float a = 6.2831853f * (float)i / 2500.0f;
        glColor4ub((GLubyte)(15 + (i & 1) * 15), 20, (GLubyte)(35 - (i & 1) * 15), 255);
        glVertex3f(8.0f * cosf(a), 8.0f * sinf(a), 0.0f);
    }
    glEnd();
    glFinish();
    sgl_image(out, "fan_perspective", W, H, 4, "RGBA", W * 4, 1, buf);

    /* 6: two half-fans from different centres sharing one long edge, plus
     * a fan with a degenerate (repeated) rim vertex every 100 */
    begin_image();
    fan(-50.0f, 128.0f, 400.0f, -0.6f, 0.6f, 1500);
    glBegin(GL_TRIANGLE_FAN);
    glColor4ub(20, 20, 60, 255);
    glVertex2f(190.7f, 60.2f);
    for (i = 0; i <= 1200; i++) {
        float a = 6.2831853f * (float)(i - (i % 100 == 50)) / 1200.0f;
        glColor4ub(20, (GLubyte)(10 + (i & 1) * 20), 20, 255);
        glVertex2f(190.7f + 55.0f * cosf(a), 60.2f + 55.0f * sinf(a));
    }
    glEnd();
    glFinish();
    sgl_image(out, "fans_mixed", W, H, 4, "RGBA", W * 4, 1, buf);

    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
