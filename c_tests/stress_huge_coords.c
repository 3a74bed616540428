/* stress_huge_coords: triangles whose vertices lie 1e4, 1e5, 1e6 and 1e7
 * pixels outside the 256x256 viewport and that cross it, with smooth
 * colours.  Each radius is its own image, once under glOrtho (pixel
 * coordinates) and once under glFrustum (the far vertices at varied depth,
 * so perspective-correct colour interpolation and depth clipping matter).
 * The 1e7 images are separate blocks so that a difference there (where
 * f32 clipping loses ~1 px, see docs/robustness.md) stays apart. */
#include <math.h>
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

/* One triangle with its long edge through (cx, cy) at angle ang, both ends
 * r pixels away, and a third vertex at distance r3 on the normal side. */
static void ortho_tri(float cx, float cy, float ang, float r, float r3, int k)
{
    float dx = cosf(ang), dy = sinf(ang);
    glColor3f(1.0f, 0.1f * (k % 8), 0.2f);
    glVertex2f(cx - r * dx, cy - r * dy);
    glColor3f(0.1f, 1.0f, 0.12f * (k % 6));
    glVertex2f(cx + r * dx, cy + r * dy);
    glColor3f(0.15f * (k % 5), 0.3f, 1.0f);
    glVertex2f(cx - r3 * dy, cy + r3 * dx);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    unsigned char *buf;
    static const float radii[4] = {1e4f, 1e5f, 1e6f, 1e7f};
    static const char *names[4] = {"1e4", "1e5", "1e6", "1e7"};
    char name[64];
    int ri, i;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    for (ri = 0; ri < 4; ri++) {
        float r = radii[ri];
        sgl_rand_state = 777u + (unsigned)ri;

        /* --- orthographic, pixel coordinates --- */
        glDisable(GL_DEPTH_TEST);
        glClearColor(0.05f, 0.05f, 0.08f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glOrtho(0.0, W, 0.0, H, -1.0, 1.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glShadeModel(GL_SMOOTH);
        glBegin(GL_TRIANGLES);
        for (i = 0; i < 10; i++) {
            float cx = 20.0f + 216.0f * sgl_randf();
            float cy = 20.0f + 216.0f * sgl_randf();
            float ang = 6.2831853f * sgl_randf();
            /* third vertex: far for the first two (drawn underneath), near for the rest */
            float r3 = (i < 2) ? r : 15.0f + 40.0f * sgl_randf();
            ortho_tri(cx, cy, ang, r, r3, i);
        }
        glEnd();
        /* all three vertices far away, covering the whole viewport;
         * scissored to the bottom-left corner */
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, 0, 64, 64);
        glBegin(GL_TRIANGLES);
        glColor3f(1.0f, 0.0f, 0.0f);
        glVertex2f(-r, -r);
        glColor3f(0.0f, 1.0f, 0.0f);
        glVertex2f(r, -0.5f * r);
        glColor3f(0.0f, 0.0f, 1.0f);
        glVertex2f(-0.3f * r, r);
        glEnd();
        glDisable(GL_SCISSOR_TEST);
        /* a quad strip of thin bands from -r to +r in x (shared edges) */
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i < 6; i++) {
            float y = 200.0f + 7.37f * i;
            glColor3f(0.2f * i, 0.5f, 1.0f - 0.15f * i);
            glVertex2f(-r, y + 0.31f * i);
            glVertex2f(r, y - 0.53f * i);
        }
        glEnd();
        glFinish();
        snprintf(name, sizeof name, "ortho_%s", names[ri]);
        sgl_image(out, name, W, H, 4, "RGBA", W * 4, 1, buf);

        /* --- perspective --- */
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glClearColor(0.08f, 0.05f, 0.05f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 1e6);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glBegin(GL_TRIANGLES);
        for (i = 0; i < 10; i++) {
            /* eye depth d; pixel offset p maps to x = p/128*d */
            float d1 = 2.0f + 30.0f * sgl_randf();
            float d2 = 2.0f + 30.0f * sgl_randf();
            float d3 = 2.0f + 8.0f * sgl_randf();
            float cx = -0.7f + 1.4f * sgl_randf();
            float cy = -0.7f + 1.4f * sgl_randf();
            float ang = 6.2831853f * sgl_randf();
            float s = r / 128.0f;
            float dx = cosf(ang), dy = sinf(ang);
            glColor3f(1.0f, 0.1f * (i % 8), 0.2f);
            glVertex3f((cx - s * dx) * d1, (cy - s * dy) * d1, -d1);
            glColor3f(0.1f, 1.0f, 0.12f * (i % 6));
            glVertex3f((cx + s * dx) * d2, (cy + s * dy) * d2, -d2);
            glColor3f(0.15f * (i % 5), 0.3f, 1.0f);
            glVertex3f((cx - 0.3f * dy) * d3, (cy + 0.3f * dx) * d3, -d3);
        }
        /* a triangle reaching from near the eye to r pixels sideways and
         * deep: crosses the near plane and two side planes */
        glColor3f(1.0f, 1.0f, 0.0f);
        glVertex3f(0.0f, -0.5f, 0.5f);
        glColor3f(0.0f, 1.0f, 1.0f);
        glVertex3f(r / 128.0f * 50.0f, 0.2f * 50.0f, -50.0f);
        glColor3f(1.0f, 0.0f, 1.0f);
        glVertex3f(-r / 128.0f * 20.0f, -r / 128.0f * 20.0f, -20.0f);
        glEnd();
        glFinish();
        snprintf(name, sizeof name, "persp_%s", names[ri]);
        sgl_image(out, name, W, H, 4, "RGBA", W * 4, 1, buf);
    }
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
