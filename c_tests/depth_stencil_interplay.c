/* depth_stencil_interplay: depth and stencil tests together.
 *
 * Context A has 24-bit depth and 8-bit stencil.  A tilted quad fills the
 * depth buffer, then four regions draw overlapping triangles three times
 * with depth writes on:
 *   0: stencil ALWAYS, sfail KEEP / zfail INCR / zpass DECR, depth LESS
 *   1: stencil EQUAL 0x10, sfail INVERT / zfail REPLACE / zpass INCR_WRAP
 *      (after a pixel's first change it fails the stencil test)
 *   2: depth test disabled (counts as passing: no zfail), stencil GEQUAL
 *      0x20 with mask 0x30, sfail ZERO / zfail INCR / zpass INVERT
 *   3: stencil test disabled with ops set: the stencil must not change
 * The stencil is then shown by 256 half-transparent quads (EQUAL k) and
 * read back, with the depth buffer.
 *
 * Context B has no stencil buffer (OSMesaCreateContextExt(..., 24, 0, 0,
 * ...)): the same drawing with GL_STENCIL_TEST enabled and glStencilFunc
 * NEVER/EQUAL must behave as if the stencil test always passed.  Its
 * GL_STENCIL_BITS and the error of glReadPixels(GL_STENCIL_INDEX) are
 * recorded. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

static void setup(void)
{
    glClearColor(0.17f, 0.19f, 0.23f, 1.0f);
    glClearDepth(0.5);
    glClearStencil(0x10);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);

    /* the tilted quad: z from -0.9 (far) on the left to 0.9 on the right */
    glBegin(GL_QUADS);
    glColor3f(0.31f, 0.37f, 0.53f);
    glVertex3f(0.0f, 0.0f, -0.9f);
    glColor3f(0.71f, 0.41f, 0.29f);
    glVertex3f(256.0f, 0.0f, 0.9f);
    glColor3f(0.61f, 0.67f, 0.23f);
    glVertex3f(256.0f, 256.0f, 0.9f);
    glColor3f(0.23f, 0.53f, 0.47f);
    glVertex3f(0.0f, 256.0f, -0.9f);
    glEnd();
}

static void triangles(float x, float y)
{
    int rep;
    for (rep = 0; rep < 3; rep++) {
        float z = -0.6f + 0.5f * rep;
        glBegin(GL_TRIANGLES);
        glColor3f(0.93f, 0.29f - 0.1f * rep, 0.13f);
        glVertex3f(x + 3.7f, y + 5.3f, z);
        glColor3f(0.19f, 0.83f, 0.37f + 0.2f * rep);
        glVertex3f(x + 121.9f, y + 31.1f + 11.3f * rep, z + 0.3f);
        glColor3f(0.59f, 0.11f, 0.97f);
        glVertex3f(x + 37.3f + 13.1f * rep, y + 119.7f, z - 0.1f);

        glColor3f(0.99f, 0.97f, 0.21f);
        glVertex3f(x + 11.1f + 17.3f * rep, y + 70.7f, 0.37f - 0.3f * rep);
        glColor3f(0.05f, 0.61f, 0.93f);
        glVertex3f(x + 88.3f, y + 2.9f + 9.1f * rep, -0.2f);
        glColor3f(0.77f, 0.07f, 0.51f);
        glVertex3f(x + 125.7f, y + 99.9f, 0.8f);
        glEnd();
    }
}

/* the four regions (see the top of the file) */
static void regions(void)
{
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0x5C, 0xFF);
    glStencilOp(GL_KEEP, GL_INCR, GL_DECR);
    triangles(0.37f, 0.61f);

    glStencilFunc(GL_EQUAL, 0x10, 0xFF);
    glStencilOp(GL_INVERT, GL_REPLACE, GL_INCR_WRAP);
    triangles(128.37f, 0.61f);

    glDisable(GL_DEPTH_TEST);
    glStencilFunc(GL_GEQUAL, 0x20, 0x30);
    glStencilOp(GL_ZERO, GL_INCR, GL_INVERT);
    triangles(0.37f, 128.61f);
    glEnable(GL_DEPTH_TEST);

    glDisable(GL_STENCIL_TEST);
    glStencilFunc(GL_NEVER, 0x77, 0xFF);
    glStencilOp(GL_INVERT, GL_INVERT, GL_INVERT);
    triangles(128.37f, 128.61f);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext a = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    OSMesaContext b = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    unsigned char *buf_a, *buf_b, *sten;
    GLuint *depth;
    GLint bits_a, bits_b, depth_bits_b;
    GLenum e_clear, e_read;
    int k;
    SGL_CHECK(a != NULL && b != NULL);
    buf_a = malloc(W * H * 4);
    buf_b = malloc(W * H * 4);
    sten = malloc(W * H);
    depth = malloc(W * H * sizeof(GLuint));
    SGL_CHECK(buf_a != NULL && buf_b != NULL && sten != NULL && depth != NULL);

    /* context A: depth + stencil */
    SGL_CHECK(OSMesaMakeCurrent(a, buf_a, GL_UNSIGNED_BYTE, W, H));
    glGetIntegerv(GL_STENCIL_BITS, &bits_a);
    setup();
    regions();
    glFinish();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sten);
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
    /* show the stencil values over the picture */
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (k = 0; k < 256; k++) {
        glStencilFunc(GL_EQUAL, k, 0xFF);
        glColor4ub((GLubyte)(k * 37), (GLubyte)(k * 101 + 50), (GLubyte)(k * 59 + 200), 128);
        glRecti(0, 0, W, H);
    }
    glFinish();
    sgl_image(out, "color_a", W, H, 4, "RGBA", W * 4, 1, buf_a);
    sgl_data(out, "stencil_a", W * H, sten);
    sgl_data(out, "depth_a", W * H * sizeof(GLuint), depth);
    sgl_text(out, "state_a", "STENCIL_BITS=%d error=0x%04x\n", bits_a, glGetError());

    /* context B: depth, no stencil */
    SGL_CHECK(OSMesaMakeCurrent(b, buf_b, GL_UNSIGNED_BYTE, W, H));
    glGetIntegerv(GL_STENCIL_BITS, &bits_b);
    glGetIntegerv(GL_DEPTH_BITS, &depth_bits_b);
    setup();
    e_clear = glGetError();
    regions();
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_NEVER, 0, 0xFF);
    glBegin(GL_TRIANGLES); /* a near triangle that NEVER would reject */
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex3f(100.3f, 100.7f, 0.99f);
    glColor3f(0.0f, 0.0f, 0.0f);
    glVertex3f(160.9f, 110.1f, 0.99f);
    glColor3f(1.0f, 0.0f, 0.5f);
    glVertex3f(120.1f, 161.3f, 0.99f);
    glEnd();
    glFinish();
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sten);
    e_read = glGetError();
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
    sgl_image(out, "color_b", W, H, 4, "RGBA", W * 4, 1, buf_b);
    sgl_data(out, "depth_b", W * H * sizeof(GLuint), depth);
    sgl_text(out, "state_b",
             "STENCIL_BITS=%d DEPTH_BITS=%d clear_error=0x%04x read_stencil_error=0x%04x "
             "error=0x%04x\n",
             bits_b, depth_bits_b, e_clear, e_read, glGetError());
    sgl_close(out);
    OSMesaDestroyContext(a);
    OSMesaDestroyContext(b);
    free(buf_a);
    free(buf_b);
    free(sten);
    free(depth);
    return 0;
}
