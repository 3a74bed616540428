/* blend_equations: glBlendEquation with GL_FUNC_ADD, GL_FUNC_SUBTRACT,
 * GL_FUNC_REVERSE_SUBTRACT, GL_MIN and GL_MAX (columns), each with three
 * pairs of blend factors (rows), over a smooth background with varying
 * alpha.  Two overlapping smooth triangles per cell are blended, so every
 * cell has saturation, clamping at 0 and double blending.  GL_MIN and
 * GL_MAX ignore the factors. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

static void cell(float x, float y, float w, float h, GLenum eq, GLenum sf, GLenum df)
{
    glDisable(GL_BLEND);
    glBegin(GL_QUADS);
    glColor4f(0.13f, 0.57f, 0.91f, 0.21f);
    glVertex2f(x, y);
    glColor4f(0.87f, 0.33f, 0.07f, 0.79f);
    glVertex2f(x + w, y);
    glColor4f(0.61f, 0.97f, 0.43f, 1.0f);
    glVertex2f(x + w, y + h);
    glColor4f(0.29f, 0.11f, 0.59f, 0.0f);
    glVertex2f(x, y + h);
    glEnd();

    glEnable(GL_BLEND);
    glBlendEquation(eq);
    glBlendFunc(sf, df);
    glBegin(GL_TRIANGLES);
    glColor4f(0.91f, 0.37f, 0.23f, 0.37f);
    glVertex2f(x - 3.3f, y + 5.1f);
    glColor4f(0.45f, 0.83f, 0.17f, 0.93f);
    glVertex2f(x + w - 7.7f, y + 0.3f * h);
    glColor4f(0.19f, 0.29f, 0.99f, 0.61f);
    glVertex2f(x + 0.4f * w, y + h - 3.1f);

    glColor4f(0.73f, 0.73f, 0.73f, 0.5f);
    glVertex2f(x + 7.9f, y + 0.7f * h);
    glColor4f(0.03f, 0.51f, 0.77f, 0.13f);
    glVertex2f(x + 0.63f * w, y - 4.3f);
    glColor4f(1.0f, 0.97f, 0.0f, 0.87f);
    glVertex2f(x + w + 2.9f, y + h - 9.3f);
    glEnd();
}

int main(int argc, char **argv)
{
    static const GLenum eqs[5] = {GL_FUNC_ADD, GL_FUNC_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT,
                                  GL_MIN, GL_MAX};
    static const GLenum fac[3][2] = {{GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA},
                                     {GL_ONE, GL_ONE},
                                     {GL_CONSTANT_COLOR, GL_ONE_MINUS_DST_ALPHA}};
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    unsigned char *buf;
    int i, j;
    GLint eq;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glBlendColor(0.37f, 0.61f, 0.83f, 0.29f);

    for (j = 0; j < 3; j++)
        for (i = 0; i < 5; i++)
            cell(1.37f + 51.1f * i, 1.61f + 85.3f * j, 48.9f, 82.3f, eqs[i], fac[j][0],
                 fac[j][1]);

    glFinish();
    glGetIntegerv(GL_BLEND_EQUATION, &eq);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "state", "BLEND_EQUATION=0x%04x error=0x%04x\n", (unsigned)eq, glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
