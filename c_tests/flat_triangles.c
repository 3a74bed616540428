/* flat_triangles: glShadeModel(GL_FLAT).  Every vertex has a different
 * colour, so the colour of each triangle shows which vertex provokes it
 * (the last one for triangles, strips and fans).  The last part switches
 * back to GL_SMOOTH to check the state change takes effect. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

static void vcolor(int i)
{
    /* distinct colour per vertex index */
    glColor3ub((GLubyte)(37 * i + 11), (GLubyte)(255 - 23 * i), (GLubyte)(97 * i + 50));
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

    glClearColor(0.05f, 0.05f, 0.0713f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, 25.6, 0.0, 25.6, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glShadeModel(GL_FLAT);

    /* Separate triangles. */
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 8; i++) {
        float x = 0.713f + i * 3.13f;
        vcolor(3 * i);
        glVertex2f(x, 0.61f);
        vcolor(3 * i + 1);
        glVertex2f(x + 2.97f, 1.3f + 0.21f * i);
        vcolor(3 * i + 2);
        glVertex2f(x + 0.51f * (i & 1), 6.137f);
    }
    glEnd();

    /* A strip: provoking vertex is the last of each triangle. */
    glBegin(GL_TRIANGLE_STRIP);
    for (i = 0; i < 18; i++) {
        vcolor(i);
        glVertex2f(0.37f + i * 1.37f, (i & 1) ? 7.1f : 11.9f + 0.05f * i);
    }
    glEnd();

    /* A fan. */
    glBegin(GL_TRIANGLE_FAN);
    vcolor(0);
    glVertex2f(6.66f, 18.13f);
    for (i = 0; i < 9; i++) {
        static const float px[9] = {12.1f, 11.3f, 8.9f, 4.7f, 1.1f, 0.9f, 2.3f, 5.1f, 9.77f};
        static const float py[9] = {18.0f, 21.7f, 24.9f, 25.1f, 22.2f, 17.3f, 14.1f, 12.9f, 13.3f};
        vcolor(i + 1);
        glVertex2f(px[i], py[i]);
    }
    glEnd();

    /* Flat triangles overlapping with colour given by ubyte, float, int. */
    glBegin(GL_TRIANGLES);
    glColor3f(0.1337f, 0.9f, 0.4f);
    glVertex2f(14.1f, 13.3f);
    glColor3f(0.9f, 0.2f, 0.1f);
    glVertex2f(25.2f, 14.7f);
    glColor3f(0.5019608f, 0.25f, 0.75f);  /* ~ 128/255: tie rounding */
    glVertex2f(19.9f, 24.9f);
    glColor4i(0x7fffffff, 0x40000000, 0x10000000, 0x7fffffff);
    glVertex2f(15.5f, 24.3f);
    glColor3ub(1, 2, 3);
    glVertex2f(13.9f, 17.1f);
    glColor3us(65535, 32768, 12345);
    glVertex2f(24.1f, 22.2f);
    glEnd();

    /* Back to smooth: same strip shape, must interpolate. */
    glShadeModel(GL_SMOOTH);
    glBegin(GL_TRIANGLE_STRIP);
    for (i = 0; i < 6; i++) {
        vcolor(i + 3);
        glVertex2f(13.0f + i * 2.1f, (i & 1) ? 8.9f : 12.3f);
    }
    glEnd();

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
