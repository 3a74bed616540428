/* alpha_test: glAlphaFunc with all eight functions (columns) and six
 * references (rows: 0.0, 0.37, 0.5, 128/255, 1.0 and 1.3, which GL clamps
 * to 1).  Each cell holds a smooth quad whose alpha runs from 0 to 1 up the
 * cell (the boundary row shows the rounding of both the interpolated alpha
 * and the reference) plus flat strips with alpha exactly 0, 94/255, 0.37,
 * 127/255, 0.5, 128/255, 129/255 and 1.0, i.e. on and around the
 * reference values.  No textures, no blending.  The fragment alpha is
 * written to the buffer and compared too. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

int main(int argc, char **argv)
{
    static const GLenum funcs[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                                    GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    static const float refs[6] = {0.0f, 0.37f, 0.5f, 128.0f / 255.0f, 1.0f, 1.3f};
    static const float strip_alpha[8] = {0.0f, 94.0f / 255.0f, 0.37f, 127.0f / 255.0f,
                                         0.5f, 128.0f / 255.0f, 129.0f / 255.0f, 1.0f};
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    unsigned char *buf;
    GLint func;
    GLfloat ref;
    int i, j, k;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.07f, 0.09f, 0.13f, 0.77f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);

    glEnable(GL_ALPHA_TEST);
    for (j = 0; j < 6; j++) {
        for (i = 0; i < 8; i++) {
            float x = 32.0f * i + 0.37f, y = 42.6f * j + 0.61f;
            glAlphaFunc(funcs[i], refs[j]);
            /* smooth: alpha 0 at the bottom, 1 at the top, over 40.3 pixels */
            glBegin(GL_QUADS);
            glColor4f(0.93f, 0.31f, 0.17f, 0.0f);
            glVertex2f(x, y);
            glColor4f(0.37f, 0.83f, 0.21f, 0.0f);
            glVertex2f(x + 18.3f, y);
            glColor4f(0.19f, 0.47f, 0.97f, 1.0f);
            glVertex2f(x + 18.3f, y + 40.3f);
            glColor4f(0.71f, 0.13f, 0.89f, 1.0f);
            glVertex2f(x, y + 40.3f);
            glEnd();
            /* a triangle with alpha across, edges at odd slopes */
            glBegin(GL_TRIANGLES);
            glColor4f(1.0f, 1.0f, 0.5f, 0.0f);
            glVertex2f(x + 1.7f, y + 2.9f);
            glColor4f(0.5f, 1.0f, 1.0f, 1.0f);
            glVertex2f(x + 17.1f, y + 23.3f);
            glColor4f(1.0f, 0.5f, 1.0f, 0.5f);
            glVertex2f(x + 3.3f, y + 38.9f);
            glEnd();
            /* flat strips with exact alphas */
            glBegin(GL_QUADS);
            for (k = 0; k < 8; k++) {
                glColor4f(0.2f + 0.1f * k, 0.9f - 0.1f * k, 0.5f, strip_alpha[k]);
                glVertex2f(x + 19.0f, y + 5.0f * k);
                glVertex2f(x + 31.0f, y + 5.0f * k);
                glVertex2f(x + 31.0f, y + 5.0f * k + 4.0f);
                glVertex2f(x + 19.0f, y + 5.0f * k + 4.0f);
            }
            glEnd();
        }
    }

    glFinish();
    glGetIntegerv(GL_ALPHA_TEST_FUNC, &func);
    glGetFloatv(GL_ALPHA_TEST_REF, &ref);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "state", "ALPHA_TEST_FUNC=0x%04x ALPHA_TEST_REF=%.9g error=0x%04x\n",
             (unsigned)func, ref, glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
