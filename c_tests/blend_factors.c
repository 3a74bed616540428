/* blend_factors: every blend factor as source factor (rows) against every
 * factor as destination factor (columns): a 15 x 15 grid of 17-pixel cells
 * over a smooth full-screen background whose alpha also varies (so the
 * DST_ALPHA factors and SRC_ALPHA_SATURATE see many values).  Each cell
 * blends a smooth triangle that crosses the cell's corner and a
 * flat quad; glBlendColor is set to odd values for the CONSTANT factors.
 * GL 1.5 allows SRC_ALPHA_SATURATE only as a source factor; the glGetError
 * of every glBlendFunc call is recorded, so whatever Mesa does with it as
 * a destination factor is compared too. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256
#define NF 15

static const GLenum factors[NF] = {
    GL_ZERO,           GL_ONE,
    GL_SRC_COLOR,      GL_ONE_MINUS_SRC_COLOR,
    GL_DST_COLOR,      GL_ONE_MINUS_DST_COLOR,
    GL_SRC_ALPHA,      GL_ONE_MINUS_SRC_ALPHA,
    GL_DST_ALPHA,      GL_ONE_MINUS_DST_ALPHA,
    GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR,
    GL_CONSTANT_ALPHA, GL_ONE_MINUS_CONSTANT_ALPHA,
    GL_SRC_ALPHA_SATURATE,
};

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    unsigned char *buf;
    char errs[4096];
    int n = 0, s, d;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);

    /* background: a gradient in colour and alpha, in 4 quads */
    glBegin(GL_QUADS);
    for (s = 0; s < 4; s++) {
        float x0 = 64.0f * s, x1 = 64.0f * (s + 1);
        glColor4f(0.07f + 0.2f * s, 0.93f, 0.37f, 0.0f + 0.25f * s);
        glVertex2f(x0, 0.0f);
        glColor4f(0.27f + 0.2f * s, 0.13f, 0.61f, 0.21f + 0.25f * s);
        glVertex2f(x1, 0.0f);
        glColor4f(0.83f, 0.49f - 0.1f * s, 0.03f, 0.79f - 0.2f * s);
        glVertex2f(x1, 256.0f);
        glColor4f(0.51f, 0.71f - 0.1f * s, 0.97f, 1.0f - 0.25f * s);
        glVertex2f(x0, 256.0f);
    }
    glEnd();

    glEnable(GL_BLEND);
    glBlendColor(0.37f, 0.71f, 0.13f, 0.59f);
    for (s = 0; s < NF; s++) {
        for (d = 0; d < NF; d++) {
            float x = 0.5f + 17.0f * d, y = 0.5f + 17.0f * s;
            GLenum e;
            glBlendFunc(factors[s], factors[d]);
            e = glGetError();
            if (e != GL_NO_ERROR)
                n += snprintf(errs + n, sizeof errs - (size_t)n, "src=0x%04x dst=0x%04x err=0x%04x\n",
                              factors[s], factors[d], e);
            glBegin(GL_TRIANGLES);
            glColor4f(0.91f, 0.23f, 0.37f, 0.37f);
            glVertex2f(x - 1.3f, y + 1.7f);
            glColor4f(0.17f, 0.89f, 0.53f, 0.83f);
            glVertex2f(x + 15.9f, y + 3.1f);
            glColor4f(0.61f, 0.41f, 0.97f, 0.11f);
            glVertex2f(x + 6.3f, y + 15.1f);
            glEnd();
            glBegin(GL_QUADS);
            glColor4ub(201, 77, 13, 149);
            glVertex2f(x + 9.7f, y + 9.9f);
            glVertex2f(x + 16.2f, y + 9.9f);
            glVertex2f(x + 16.2f, y + 16.3f);
            glVertex2f(x + 9.7f, y + 16.3f);
            glEnd();
        }
    }

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "errors", "%s", n ? errs : "none\n");
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
