/* cull_face: GL_CULL_FACE with GL_BACK, GL_FRONT, GL_FRONT_AND_BACK, and
 * glFrontFace(GL_CW), on triangles of both windings, a strip (whose
 * winding alternates), a quad, a polygon and a mirrored (negative scale)
 * modelview. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

static void shapes(void)
{
    int i;
    glBegin(GL_TRIANGLES);
    /* counter-clockwise */
    glColor3f(1.0f, 0.2f, 0.2f); glVertex2f(2.1f, 2.3f);
    glColor3f(1.0f, 0.8f, 0.2f); glVertex2f(27.7f, 4.4f);
    glColor3f(0.8f, 0.2f, 0.6f); glVertex2f(13.3f, 27.1f);
    /* clockwise */
    glColor3f(0.2f, 0.2f, 1.0f); glVertex2f(32.2f, 3.3f);
    glColor3f(0.2f, 0.8f, 1.0f); glVertex2f(45.5f, 28.8f);
    glColor3f(0.6f, 0.2f, 0.8f); glVertex2f(61.1f, 1.7f);
    glEnd();

    glBegin(GL_TRIANGLE_STRIP);
    for (i = 0; i < 7; i++) {
        glColor3f(0.1f * i, 1.0f - 0.13f * i, 0.5f);
        glVertex2f(1.7f + i * 9.9f, (i & 1) ? 32.3f : 47.9f);
    }
    glEnd();

    glBegin(GL_QUADS); /* ccw quad */
    glColor3f(0.9f, 0.9f, 0.9f); glVertex2f(2.2f, 50.5f);
    glColor3f(0.3f, 0.9f, 0.3f); glVertex2f(29.9f, 51.1f);
    glColor3f(0.3f, 0.3f, 0.9f); glVertex2f(28.8f, 62.7f);
    glColor3f(0.9f, 0.3f, 0.3f); glVertex2f(3.1f, 61.9f);
    glEnd();

    glBegin(GL_POLYGON); /* cw polygon */
    glColor3f(0.9f, 0.5f, 0.1f); glVertex2f(35.1f, 51.1f);
    glColor3f(0.5f, 0.9f, 0.1f); glVertex2f(36.3f, 62.2f);
    glColor3f(0.1f, 0.5f, 0.9f); glVertex2f(50.7f, 63.3f);
    glColor3f(0.5f, 0.1f, 0.9f); glVertex2f(62.1f, 56.6f);
    glColor3f(0.9f, 0.1f, 0.5f); glVertex2f(55.5f, 50.2f);
    glEnd();
}

int main(int argc, char **argv)
{
    struct { int enable; GLenum cull; GLenum front; } cfg[8] = {
        {0, GL_BACK, GL_CCW},           {1, GL_BACK, GL_CCW},
        {1, GL_FRONT, GL_CCW},          {1, GL_FRONT_AND_BACK, GL_CCW},
        {1, GL_BACK, GL_CW},            {1, GL_FRONT, GL_CW},
        {0, GL_FRONT_AND_BACK, GL_CW},  {1, GL_BACK, GL_CCW}};
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
    unsigned char *buf;
    int i;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);

    for (i = 0; i < 8; i++) {
        if (cfg[i].enable)
            glEnable(GL_CULL_FACE);
        else
            glDisable(GL_CULL_FACE);
        glCullFace(cfg[i].cull);
        glFrontFace(cfg[i].front);
        glLoadIdentity();
        glTranslatef(0.3f + (i % 4) * 64.0f, 0.7f + (i / 4) * 64.0f, 0.0f);
        shapes();
    }

    /* mirrored modelview flips the winding in window space */
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    for (i = 0; i < 4; i++) {
        glLoadIdentity();
        glTranslatef(64.3f + i * 64.0f, 128.9f + (i & 1) * 64.0f, 0.0f);
        glScalef(-1.0f, 1.0f, 1.0f);
        if (i >= 2)
            glCullFace(GL_FRONT);
        shapes();
    }

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
