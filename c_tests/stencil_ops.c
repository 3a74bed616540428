/* stencil_ops: every stencil operation (KEEP, ZERO, REPLACE, INCR, DECR,
 * INVERT, INCR_WRAP, DECR_WRAP; columns) as the sfail, zfail and zpass
 * operation (rows 0-2), plus a row of zpass with glStencilMask(0x3C).
 * Each 32x64 cell starts with five bands of stencil values 0, 1, 0x80,
 * 254 and 255, has an occluding triangle in the depth buffer, and three
 * overlapping triangles are each drawn three times through a scissor box
 * around the cell, so values saturate and wrap.  Rows 0-1 write depth
 * (so in row 1 the later layers fail the depth test even outside the
 * occluder), rows 2-3 do not.  The sfail row uses
 * GL_LESS with ref 200, so values above 200 pass and stop changing.
 * The stencil buffer is dumped with glReadPixels(GL_STENCIL_INDEX) and
 * then made visible by 256 full-screen quads drawn with
 * glStencilFunc(GL_EQUAL, k, 0xff), one distinct colour per k.
 *
 * Separate front/back stencil (glStencilFuncSeparate/glStencilOpSeparate)
 * is GL 2.0 and not in GL 1.5 headers, so it is not used here. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

static const GLenum ops[8] = {GL_KEEP, GL_ZERO,   GL_REPLACE,   GL_INCR,
                              GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP};

static void quad(float x0, float y0, float x1, float y1, float z)
{
    glBegin(GL_QUADS);
    glVertex3f(x0, y0, z);
    glVertex3f(x1, y0, z);
    glVertex3f(x1, y1, z);
    glVertex3f(x0, y1, z);
    glEnd();
}

int main(int argc, char **argv)
{
    static const GLint bands[5] = {0, 1, 0x80, 254, 255};
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf, *sten;
    int row, col, b, k, rep;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    sten = malloc(W * H);
    SGL_CHECK(buf != NULL && sten != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClearStencil(0x33);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);

    /* initial stencil bands in every row of cells (1-pixel gaps keep 0x33) */
    glEnable(GL_STENCIL_TEST);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    for (row = 0; row < 4; row++)
        for (b = 0; b < 5; b++) {
            glStencilFunc(GL_ALWAYS, bands[b], 0xFF);
            quad(0.0f, 64.0f * row + 12.8f * b + 0.5f, 256.0f, 64.0f * row + 12.8f * b + 12.3f,
                 0.0f);
        }

    /* occluders: depth only, stencil test off so the stencil is untouched */
    glDisable(GL_STENCIL_TEST);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glBegin(GL_TRIANGLES);
    for (row = 0; row < 4; row++)
        for (col = 0; col < 8; col++) {
            float x = 32.0f * col, y = 64.0f * row;
            glVertex3f(x + 0.3f, y + 0.7f, 0.5f);
            glVertex3f(x + 27.9f, y + 0.7f, 0.5f);
            glVertex3f(x + 0.3f, y + 57.1f, 0.5f);
        }
    glEnd();

    /* the operations */
    glEnable(GL_STENCIL_TEST);
    glEnable(GL_SCISSOR_TEST);
    for (row = 0; row < 4; row++) {
        for (col = 0; col < 8; col++) {
            float x = 32.0f * col, y = 64.0f * row;
            glScissor(32 * col, 64 * row, 32, 64);
            glStencilMask(row == 3 ? 0x3C : 0xFF);
            /* rows 0-1 write depth, so a pixel's later layers fail the depth
             * test; rows 2-3 do not, so every layer passes it again */
            glDepthMask(row < 2 ? GL_TRUE : GL_FALSE);
            switch (row) {
            case 0:
                glStencilFunc(GL_LESS, 200, 0xFF);
                glStencilOp(ops[col], GL_KEEP, GL_KEEP);
                break;
            case 1:
                glStencilFunc(GL_ALWAYS, 0x5A, 0xFF);
                glStencilOp(GL_KEEP, ops[col], GL_KEEP);
                break;
            case 2:
                glStencilFunc(GL_ALWAYS, 0x5A, 0xFF);
                glStencilOp(GL_KEEP, GL_KEEP, ops[col]);
                break;
            default:
                glStencilFunc(GL_ALWAYS, 0xA5, 0xFF);
                glStencilOp(GL_KEEP, GL_KEEP, ops[col]);
                break;
            }
            for (rep = 0; rep < 3; rep++) {
                glBegin(GL_TRIANGLES);
                glVertex3f(x - 5.3f, y + 3.7f, 0.0f);
                glVertex3f(x + 29.9f, y + 21.3f, 0.0f);
                glVertex3f(x + 7.7f, y + 70.1f, 0.0f);

                glVertex3f(x + 2.1f, y + 33.3f, 0.0f);
                glVertex3f(x + 36.7f, y - 4.9f, 0.0f);
                glVertex3f(x + 30.3f, y + 61.9f, 0.0f);

                glVertex3f(x + 15.9f, y + 66.6f, 0.0f);
                glVertex3f(x - 3.1f, y + 17.7f, 0.0f);
                glVertex3f(x + 33.3f, y + 39.1f, 0.0f);
                glEnd();
            }
        }
    }
    glDisable(GL_SCISSOR_TEST);
    glStencilMask(0xFF);

    glFinish();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sten);

    /* make the stencil visible: one colour per value */
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_DEPTH_TEST);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    for (k = 0; k < 256; k++) {
        glStencilFunc(GL_EQUAL, k, 0xFF);
        glColor4ub((GLubyte)(k * 37), (GLubyte)(k * 101 + 50), (GLubyte)(k * 59 + 200),
                   (GLubyte)k);
        quad(0.0f, 0.0f, 256.0f, 256.0f, 0.0f);
    }

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_data(out, "stencil", W * H, sten);
    sgl_text(out, "error", "glGetError=0x%04x\n", glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    free(sten);
    return 0;
}
