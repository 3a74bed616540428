/* depth_funcs: the eight depth functions, glDepthMask(GL_FALSE) and
 * glClearDepth.  Each cell holds a reference triangle written with
 * GL_ALWAYS, then (with the cell's function) a tilted triangle whose depth
 * crosses both the reference and the cleared depth, and the reference again
 * with identical vertices (so EQUAL/LEQUAL/GEQUAL/NOTEQUAL see exact ties). */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

static void cell(float ox, float oy, GLenum func, GLboolean mask)
{
    glPushMatrix();
    glTranslatef(ox, oy, 0.0f);

    glDepthMask(GL_TRUE);
    glDepthFunc(GL_ALWAYS);
    glBegin(GL_TRIANGLES); /* reference, z from -0.3137 to 0.4413 */
    glColor3f(0.8f, 0.1f, 0.1f);
    glVertex3f(2.3f, 3.1f, -0.3137f);
    glColor3f(0.9f, 0.6f, 0.1f);
    glVertex3f(58.1f, 9.7f, 0.4413f);
    glColor3f(0.7f, 0.2f, 0.5f);
    glVertex3f(20.9f, 58.3f, 0.1011f);
    glEnd();

    glDepthFunc(func);
    glDepthMask(mask);
    glBegin(GL_TRIANGLES); /* tilted, z from -0.9 to 0.83 */
    glColor3f(0.1f, 0.3f, 0.9f);
    glVertex3f(1.1f, 40.7f, -0.9f);
    glColor3f(0.1f, 0.9f, 0.7f);
    glVertex3f(61.7f, 1.9f, 0.83f);
    glColor3f(0.3f, 0.9f, 0.2f);
    glVertex3f(50.3f, 62.2f, 0.61f);
    glEnd();

    glBegin(GL_TRIANGLES); /* the reference again, other colour */
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex3f(2.3f, 3.1f, -0.3137f);
    glColor3f(0.4f, 0.4f, 0.4f);
    glVertex3f(58.1f, 9.7f, 0.4413f);
    glColor3f(0.9f, 0.9f, 0.0f);
    glVertex3f(20.9f, 58.3f, 0.1011f);
    glEnd();

    /* with mask off, this one shows whether depth was written above */
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
    glBegin(GL_TRIANGLES);
    glColor3f(0.5f, 0.0f, 0.5f);
    glVertex3f(30.3f, 30.3f, 0.2f);
    glColor3f(0.0f, 0.5f, 0.5f);
    glVertex3f(63.3f, 30.1f, 0.2f);
    glColor3f(0.5f, 0.5f, 0.0f);
    glVertex3f(47.7f, 63.7f, 0.2f);
    glEnd();
    glPopMatrix();
}

int main(int argc, char **argv)
{
    static const GLenum funcs[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                                    GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    unsigned char *buf;
    int i;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
    glClearDepth(0.6137);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);

    /* 8 functions with depth writes, 4 with writes masked off */
    for (i = 0; i < 8; i++)
        cell(0.37f + (i % 4) * 64.0f, 128.41f + (i / 4) * 64.0f, funcs[i], GL_TRUE);
    for (i = 0; i < 4; i++)
        cell(0.61f + i * 64.0f, 64.13f, funcs[i * 2 + 1], GL_FALSE);

    /* a big tilted triangle across the bottom row against the cleared depth */
    glDepthFunc(GL_LEQUAL);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.5f, 0.25f);
    glVertex3f(0.0f, 0.0f, 0.9f);
    glColor3f(0.25f, 0.5f, 1.0f);
    glVertex3f(256.0f, 3.7f, 0.1f);
    glColor3f(0.5f, 1.0f, 0.25f);
    glVertex3f(128.3f, 63.3f, 0.2274f); /* window z == cleared depth along a line */
    glEnd();

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
