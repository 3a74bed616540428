/* stencil_portal: the classic portal/mirror technique.  Stencil masks are
 * written with colour and depth writes off: a round portal (ref 1,
 * REPLACE), then a tilted square portal written through glStencilMask(0x02)
 * (so only bit 1 changes where they overlap).  Then the outside world
 * is drawn where the stencil is NOTEQUAL to the round portal's, another
 * scene inside the square only (EQUAL with a value mask), and a third
 * where the stencil EQUALs the round portal's.  Finally
 * a scissored glClear of the stencil with glClearStencil(0x85) and a
 * partial glStencilMask(0x0F) marks a rectangle that a full-screen quad then
 * shows.  The stencil buffer is read back too. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <math.h>
#include "common.h"

#define W 256
#define H 256

static void fan(float cx, float cy, float r, int n, float z)
{
    int i;
    glBegin(GL_TRIANGLE_FAN);
    glVertex3f(cx, cy, z);
    for (i = 0; i <= n; i++) {
        float t = (float)i * 6.2831853f / (float)n;
        glVertex3f(cx + r * cosf(t), cy + 0.87f * r * sinf(t), z);
    }
    glEnd();
}

/* a field of smooth triangles crossing the portal borders */
static void world(float r, float g, float b, float shift)
{
    int i;
    glBegin(GL_QUADS); /* the world's sky, behind everything */
    glColor3f(r * 0.5f, g * 0.5f, b * 0.5f);
    glVertex3f(0.0f, 0.0f, -0.99f);
    glColor3f(b * 0.7f, r * 0.7f, g * 0.7f);
    glVertex3f(256.0f, 0.0f, -0.99f);
    glColor3f(g * 0.3f, b * 0.3f, r * 0.3f);
    glVertex3f(256.0f, 256.0f, -0.99f);
    glColor3f(0.37f, 0.37f, 0.37f);
    glVertex3f(0.0f, 256.0f, -0.99f);
    glEnd();
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 12; i++) {
        float x = 7.3f + 21.7f * i + shift, y = 13.9f + 17.1f * (i % 5);
        glColor3f(r, g * 0.3f, b);
        glVertex3f(x, y, -0.5f + 0.07f * i);
        glColor3f(r * 0.2f, g, b * 0.5f);
        glVertex3f(x + 61.3f, y + 29.7f, 0.3f);
        glColor3f(1.0f - r, 1.0f - g, b);
        glVertex3f(x + 9.1f, y + 151.3f, -0.1f * i);
    }
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf, *sten;
    GLint bits;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    sten = malloc(W * H);
    SGL_CHECK(buf != NULL && sten != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    glGetIntegerv(GL_STENCIL_BITS, &bits);

    glClearColor(0.31f, 0.29f, 0.37f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);

    /* 1. portal masks: no colour, no depth */
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    fan(97.3f, 131.7f, 71.9f, 29, 0.0f);
    glStencilMask(0x02);
    glStencilFunc(GL_ALWAYS, 0xFF, 0xFF);
    glPushMatrix();
    glTranslatef(171.3f, 101.1f, 0.0f);
    glRotatef(27.3f, 0.0f, 0.0f, 1.0f);
    glBegin(GL_QUADS);
    glVertex2f(-60.7f, -55.1f);
    glVertex2f(58.9f, -57.3f);
    glVertex2f(61.1f, 60.3f);
    glVertex2f(-57.7f, 59.9f);
    glEnd();
    glPopMatrix();

    /* 2. draw the worlds through the mask, stencil unchanged */
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilFunc(GL_NOTEQUAL, 1, 0x01); /* outside the round portal */
    world(0.61f, 0.23f, 0.41f, 17.9f);
    glClear(GL_DEPTH_BUFFER_BIT);
    glStencilFunc(GL_EQUAL, 2, 0x03); /* inside the square, outside the circle */
    world(0.97f, 0.77f, 0.11f, -40.3f);
    glClear(GL_DEPTH_BUFFER_BIT);
    glStencilFunc(GL_EQUAL, 1, 0x01); /* inside the round portal */
    world(0.13f, 0.91f, 0.83f, 0.0f);

    /* 3. scissored stencil clear with a partial write mask */
    glEnable(GL_SCISSOR_TEST);
    glScissor(23, 19, 97, 61);
    glClearStencil(0x85);
    glStencilMask(0x0F);
    glClear(GL_STENCIL_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glStencilMask(0xFF);
    glDisable(GL_DEPTH_TEST);
    glStencilFunc(GL_EQUAL, 0x05, 0x0F);
    glBegin(GL_QUADS);
    glColor4f(1.0f, 1.0f, 1.0f, 0.5f);
    glVertex2f(0.0f, 0.0f);
    glColor4f(0.0f, 0.0f, 0.0f, 0.5f);
    glVertex2f(256.0f, 0.0f);
    glVertex2f(256.0f, 256.0f);
    glColor4f(1.0f, 0.0f, 0.0f, 0.5f);
    glVertex2f(0.0f, 256.0f);
    glEnd();

    glFinish();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sten);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_data(out, "stencil", W * H, sten);
    sgl_text(out, "state", "STENCIL_BITS=%d error=0x%04x\n", bits, glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    free(sten);
    return 0;
}
