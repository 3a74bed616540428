/* scissor_mask: scissored glClear (colour, depth) and scissored draws,
 * including a scissor box that reaches outside the buffer; glColorMask per
 * channel on draws and on clears (full-buffer and scissored clears with a
 * partial mask); glDepthMask(GL_FALSE) draws; and GL_DITHER enabled versus
 * disabled on the same gradient (Mesa never dithers, so both halves must be
 * equal).  The depth buffer is read back too. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

static void smooth_tri(float x, float y, float s, float z)
{
    glBegin(GL_TRIANGLES);
    glColor4f(0.93f, 0.37f, 0.11f, 0.29f);
    glVertex3f(x, y, z);
    glColor4f(0.13f, 0.81f, 0.47f, 0.91f);
    glVertex3f(x + s, y + 0.21f * s, z);
    glColor4f(0.41f, 0.17f, 0.97f, 0.59f);
    glVertex3f(x + 0.37f * s, y + 0.93f * s, z);
    glEnd();
}

int main(int argc, char **argv)
{
    static const GLboolean masks[6][4] = {
        {GL_TRUE, GL_FALSE, GL_FALSE, GL_FALSE}, {GL_FALSE, GL_TRUE, GL_FALSE, GL_FALSE},
        {GL_FALSE, GL_FALSE, GL_TRUE, GL_FALSE}, {GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE},
        {GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE},   {GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE},
    };
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    unsigned char *buf;
    GLuint *depth;
    int i;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    depth = malloc(W * H * sizeof(GLuint));
    SGL_CHECK(buf != NULL && depth != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);

    /* full clear, then a clear with a partial colour mask (the quad path) */
    glClearColor(0.37f, 0.21f, 0.67f, 0.53f);
    glClearDepth(0.75);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
    glClearColor(0.9f, 0.13f, 0.9f, 0.87f);
    glClear(GL_COLOR_BUFFER_BIT);

    /* scissored clears: full mask, partial mask, depth only */
    glEnable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glScissor(13, 27, 101, 77);
    glClearColor(0.61f, 0.83f, 0.29f, 0.11f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glScissor(71, 61, 93, 119);
    glClearColor(0.05f, 0.95f, 0.45f, 0.55f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glScissor(-17, 150, 77, 200); /* partly outside the buffer */
    glClearDepth(0.125);
    glClear(GL_DEPTH_BUFFER_BIT);
    glScissor(201, 3, 100, 41);
    glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    /* scissored draws with the depth test; the -17.. box has a near depth */
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glScissor(3, 131, 119, 117);
    smooth_tri(-20.3f, 120.1f, 170.7f, 0.1f); /* window z 0.45: fails where 0.125 */
    glScissor(-40, -40, 600, 600);             /* larger than the buffer */
    smooth_tri(120.3f, 140.9f, 133.1f, -0.7f); /* behind the 0.75 clear: hidden */
    smooth_tri(150.3f, 180.9f, 103.1f, 0.9f);
    glDisable(GL_SCISSOR_TEST);

    /* per-channel colour masks on draws: a row of six triangles */
    glDepthFunc(GL_ALWAYS);
    for (i = 0; i < 6; i++) {
        glColorMask(masks[i][0], masks[i][1], masks[i][2], masks[i][3]);
        smooth_tri(1.7f + 41.3f * i, 100.3f, 47.9f, 0.0f);
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    /* depth mask off: the near quad does not hide the far triangle after it */
    glDepthFunc(GL_LESS);
    glDepthMask(GL_FALSE);
    glBegin(GL_QUADS);
    glColor3f(0.99f, 0.61f, 0.13f);
    glVertex3f(130.3f, 5.3f, 0.8f);
    glVertex3f(190.7f, 5.3f, 0.8f);
    glVertex3f(190.7f, 70.9f, 0.8f);
    glVertex3f(130.3f, 70.9f, 0.8f);
    glEnd();
    glDepthMask(GL_TRUE);
    smooth_tri(140.1f, 20.3f, 80.9f, 0.4f);

    /* dithering on (left) and off (right): identical in Mesa */
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_DITHER);
    glBegin(GL_QUADS);
    glColor4f(0.0f, 0.37f, 1.0f, 0.0f);
    glVertex2f(0.0f, 0.0f);
    glColor4f(1.0f, 0.63f, 0.0f, 1.0f);
    glVertex2f(60.0f, 0.0f);
    glVertex2f(60.0f, 23.0f);
    glColor4f(0.0f, 0.37f, 1.0f, 0.0f);
    glVertex2f(0.0f, 23.0f);
    glEnd();
    glDisable(GL_DITHER);
    glBegin(GL_QUADS);
    glColor4f(0.0f, 0.37f, 1.0f, 0.0f);
    glVertex2f(64.0f, 0.0f);
    glColor4f(1.0f, 0.63f, 0.0f, 1.0f);
    glVertex2f(124.0f, 0.0f);
    glVertex2f(124.0f, 23.0f);
    glColor4f(0.0f, 0.37f, 1.0f, 0.0f);
    glVertex2f(64.0f, 23.0f);
    glEnd();

    glFinish();
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_data(out, "depth", W * H * sizeof(GLuint), depth);
    sgl_text(out, "error", "glGetError=0x%04x\n", glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    free(depth);
    return 0;
}
