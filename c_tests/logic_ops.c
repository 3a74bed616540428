/* logic_ops: GL_COLOR_LOGIC_OP with all 16 glLogicOp values (4 x 4 grid)
 * over a coloured background (smooth quads and flat stripes).  In each
 * cell two overlapping smooth triangles are drawn, then the first again
 * (so XOR/INVERT/EQUIV undo themselves where it is drawn twice).  In every
 * other cell GL_BLEND is also enabled with factors that would change the
 * result: the logic op must take precedence.  Alpha is operated on too. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

static void tri_a(float x, float y)
{
    glBegin(GL_TRIANGLES);
    glColor4f(0.91f, 0.37f, 0.13f, 0.61f);
    glVertex2f(x - 3.7f, y + 4.1f);
    glColor4f(0.17f, 0.83f, 0.59f, 0.29f);
    glVertex2f(x + 59.3f, y + 13.9f);
    glColor4f(0.53f, 0.07f, 0.97f, 1.0f);
    glVertex2f(x + 21.1f, y + 61.3f);
    glEnd();
}

static void tri_b(float x, float y)
{
    glBegin(GL_TRIANGLES);
    glColor4ub(37, 201, 255, 128);
    glVertex2f(x + 9.9f, y + 50.3f);
    glColor4ub(250, 250, 3, 7);
    glVertex2f(x + 43.7f, y - 2.9f);
    glColor4ub(129, 64, 32, 255);
    glVertex2f(x + 66.1f, y + 41.7f);
    glEnd();
}

int main(int argc, char **argv)
{
    static const GLenum ops[16] = {
        GL_CLEAR, GL_AND,  GL_AND_REVERSE, GL_COPY,  GL_AND_INVERTED, GL_NOOP,
        GL_XOR,   GL_OR,   GL_NOR,         GL_EQUIV, GL_INVERT,       GL_OR_REVERSE,
        GL_COPY_INVERTED, GL_OR_INVERTED, GL_NAND, GL_SET,
    };
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    unsigned char *buf;
    GLint mode;
    int i;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);

    /* background: a smooth quad and flat vertical stripes */
    glBegin(GL_QUADS);
    glColor4f(0.97f, 0.11f, 0.37f, 0.0f);
    glVertex2f(0.0f, 0.0f);
    glColor4f(0.13f, 0.93f, 0.29f, 0.5f);
    glVertex2f(256.0f, 0.0f);
    glColor4f(0.41f, 0.23f, 0.89f, 1.0f);
    glVertex2f(256.0f, 256.0f);
    glColor4f(0.77f, 0.71f, 0.05f, 0.37f);
    glVertex2f(0.0f, 256.0f);
    for (i = 0; i < 16; i++) {
        float x = 16.0f * i + 5.3f;
        glColor4ub((GLubyte)(i * 17), (GLubyte)(255 - i * 13), (GLubyte)(i * 71), (GLubyte)(i * 29));
        glVertex2f(x, 0.0f);
        glVertex2f(x + 4.4f, 0.0f);
        glVertex2f(x + 4.4f, 256.0f);
        glVertex2f(x, 256.0f);
    }
    glEnd();

    glEnable(GL_COLOR_LOGIC_OP);
    glBlendFunc(GL_ONE, GL_ONE);
    for (i = 0; i < 16; i++) {
        float x = 64.0f * (i % 4) + 0.37f, y = 64.0f * (i / 4) + 0.61f;
        glLogicOp(ops[i]);
        if (i & 1)
            glEnable(GL_BLEND);
        else
            glDisable(GL_BLEND);
        tri_a(x, y);
        tri_b(x, y);
        tri_a(x + 6.1f, y + 3.3f);
    }

    glFinish();
    glGetIntegerv(GL_LOGIC_OP_MODE, &mode);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "state", "LOGIC_OP_MODE=0x%04x error=0x%04x\n", (unsigned)mode, glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
