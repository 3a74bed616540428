/* blend_40_quads: 40 full-screen quads at 512x512, each with its own
 * per-vertex colours and alphas, blended with SRC_ALPHA /
 * ONE_MINUS_SRC_ALPHA.  Every pixel goes through 40 successive 8-bit
 * blends, so any difference in the blend multiply's rounding accumulates.
 * Half of the quads are drawn with their corners rotated (so the quad
 * diagonal differs) and a few have an alpha of exactly 0 or 1 at a corner. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 512
#define H 512

int main(int argc, char **argv)
{
    static const float cx[4] = {-1.0f, 1.0f, 1.0f, -1.0f};
    static const float cy[4] = {-1.0f, -1.0f, 1.0f, 1.0f};
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    unsigned char *buf;
    int q, v;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.37f, 0.13f, 0.61f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);

    for (q = 0; q < 40; q++) {
        glBegin(GL_QUADS);
        for (v = 0; v < 4; v++) {
            int c = (v + (q & 1)) & 3; /* odd quads start at another corner */
            float r, g, b, a;
            r = sgl_randf(); /* one call per statement: argument order is unspecified */
            g = sgl_randf();
            b = sgl_randf();
            a = sgl_randf();
            if (q % 13 == 5 && v == 0)
                a = 0.0f;
            if (q % 11 == 3 && v == 2)
                a = 1.0f;
            glColor4f(r, g, b, a);
            glVertex2f(cx[c], cy[c]);
        }
        glEnd();
    }

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "error", "glGetError=0x%04x\n", glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
