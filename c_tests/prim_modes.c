/* prim_modes: GL_TRIANGLES, TRIANGLE_STRIP, TRIANGLE_FAN, QUADS, QUAD_STRIP
 * and POLYGON, each in its own cell, top half smooth, bottom half flat.
 * Every vertex has a distinct colour so the triangle split and the
 * provoking vertex show. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

static void vcolor(int i)
{
    static const GLubyte c[12][3] = {
        {255, 0, 0},   {0, 255, 0},   {0, 0, 255},   {255, 255, 0},
        {255, 0, 255}, {0, 255, 255}, {255, 128, 0}, {128, 0, 255},
        {0, 128, 64},  {200, 200, 200}, {90, 30, 10}, {10, 90, 250}};
    glColor3ubv(c[i % 12]);
}

/* Draw all six modes; cell size is 80 x 60 in a 256 x 128 half. */
static void draw_modes(void)
{
    int i;
    /* cell 0: triangles */
    glPushMatrix();
    glTranslatef(3.3f, 4.1f, 0.0f);
    glBegin(GL_TRIANGLES);
    vcolor(0); glVertex2f(0.5f, 1.1f);
    vcolor(1); glVertex2f(37.3f, 3.7f);
    vcolor(2); glVertex2f(12.9f, 53.3f);
    vcolor(3); glVertex2f(41.1f, 7.7f);
    vcolor(4); glVertex2f(77.7f, 2.1f);
    vcolor(5); glVertex2f(60.2f, 55.5f);
    glEnd();
    glPopMatrix();

    /* cell 1: strip */
    glPushMatrix();
    glTranslatef(86.6f, 4.4f, 0.0f);
    glBegin(GL_TRIANGLE_STRIP);
    for (i = 0; i < 8; i++) {
        vcolor(i);
        glVertex2f(0.7f + i * 10.9f, (i & 1) ? 3.3f + i : 53.9f - i * 1.3f);
    }
    glEnd();
    glPopMatrix();

    /* cell 2: fan */
    glPushMatrix();
    glTranslatef(170.1f, 3.9f, 0.0f);
    glBegin(GL_TRIANGLE_FAN);
    vcolor(0); glVertex2f(40.3f, 1.3f);
    vcolor(1); glVertex2f(79.1f, 13.3f);
    vcolor(2); glVertex2f(71.7f, 40.1f);
    vcolor(3); glVertex2f(52.5f, 56.6f);
    vcolor(4); glVertex2f(21.1f, 55.1f);
    vcolor(5); glVertex2f(3.3f, 36.9f);
    vcolor(6); glVertex2f(1.9f, 9.1f);
    glEnd();
    glPopMatrix();

    /* cell 3: quads (two quads, non-planar-looking colours) */
    glPushMatrix();
    glTranslatef(2.7f, 66.3f, 0.0f);
    glBegin(GL_QUADS);
    vcolor(0); glVertex2f(1.1f, 2.3f);
    vcolor(1); glVertex2f(36.6f, 0.7f);
    vcolor(2); glVertex2f(33.3f, 57.1f);
    vcolor(3); glVertex2f(4.4f, 49.9f);
    vcolor(4); glVertex2f(41.3f, 9.9f);
    vcolor(5); glVertex2f(78.8f, 2.2f);
    vcolor(6); glVertex2f(70.1f, 44.4f);
    vcolor(7); glVertex2f(44.7f, 57.3f);
    glEnd();
    glPopMatrix();

    /* cell 4: quad strip */
    glPushMatrix();
    glTranslatef(86.1f, 66.9f, 0.0f);
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i < 8; i++) {
        vcolor(i + 2);
        glVertex2f(1.3f + (i / 2) * 25.7f + (i & 1) * 3.1f,
                   (i & 1) ? 56.1f - i : 2.7f + i * 0.9f);
    }
    glEnd();
    glPopMatrix();

    /* cell 5: polygon (convex heptagon) */
    glPushMatrix();
    glTranslatef(170.7f, 66.1f, 0.0f);
    glBegin(GL_POLYGON);
    vcolor(5); glVertex2f(37.7f, 1.1f);
    vcolor(6); glVertex2f(72.2f, 10.3f);
    vcolor(7); glVertex2f(79.3f, 35.5f);
    vcolor(8); glVertex2f(55.5f, 57.7f);
    vcolor(9); glVertex2f(21.2f, 56.1f);
    vcolor(10); glVertex2f(2.1f, 33.3f);
    vcolor(11); glVertex2f(9.9f, 8.8f);
    glEnd();
    glPopMatrix();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
    unsigned char *buf;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);

    /* top half: smooth */
    glPushMatrix();
    glTranslatef(0.0f, 128.0f, 0.0f);
    glShadeModel(GL_SMOOTH);
    draw_modes();
    glPopMatrix();

    /* bottom half: flat */
    glShadeModel(GL_FLAT);
    draw_modes();

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
