/* blend_separate: glBlendFuncSeparate (GL 1.4) and separate RGB/alpha blend
 * equations with the constant colour, in a 4 x 4 grid of settings over a
 * background whose alpha varies.  The alpha channel is the point here:
 * the whole RGBA buffer is compared, and glReadPixels(GL_ALPHA) of it too.
 *
 * glBlendEquationSeparate is GL 2.0, so a GL 1.5 program gets it as
 * glBlendEquationSeparateEXT (GL_EXT_blend_equation_separate) through
 * OSMesaGetProcAddress after checking GL_EXTENSIONS, as real programs do. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

typedef void (*blend_eq_sep_fn)(GLenum mode_rgb, GLenum mode_alpha);

struct setting {
    GLenum src_rgb, dst_rgb, src_a, dst_a, eq_rgb, eq_a;
};

static const struct setting settings[16] = {
    {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ZERO, GL_FUNC_ADD, GL_FUNC_ADD},
    {GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA, GL_FUNC_ADD, GL_FUNC_ADD},
    {GL_ONE, GL_ONE, GL_ZERO, GL_ONE, GL_FUNC_ADD, GL_FUNC_ADD},
    {GL_ZERO, GL_ONE, GL_ONE, GL_ONE, GL_FUNC_ADD, GL_FUNC_ADD},
    {GL_DST_ALPHA, GL_ONE, GL_SRC_ALPHA, GL_DST_ALPHA, GL_FUNC_ADD, GL_FUNC_REVERSE_SUBTRACT},
    {GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_ALPHA, GL_ZERO, GL_FUNC_ADD,
     GL_FUNC_ADD},
    {GL_ONE_MINUS_CONSTANT_ALPHA, GL_CONSTANT_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_ONE,
     GL_FUNC_SUBTRACT, GL_FUNC_ADD},
    {GL_SRC_ALPHA_SATURATE, GL_ONE, GL_SRC_ALPHA_SATURATE, GL_ONE, GL_FUNC_ADD, GL_FUNC_ADD},
    {GL_ONE, GL_ONE, GL_ONE, GL_ONE, GL_FUNC_ADD, GL_MIN},
    {GL_ONE, GL_ONE, GL_ONE, GL_ONE, GL_MAX, GL_FUNC_SUBTRACT},
    {GL_SRC_COLOR, GL_DST_COLOR, GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA, GL_MIN, GL_FUNC_ADD},
    {GL_DST_COLOR, GL_ZERO, GL_ZERO, GL_ONE_MINUS_CONSTANT_ALPHA, GL_FUNC_REVERSE_SUBTRACT,
     GL_MAX},
    {GL_ONE_MINUS_DST_ALPHA, GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA, GL_DST_ALPHA, GL_FUNC_ADD,
     GL_FUNC_ADD},
    {GL_CONSTANT_ALPHA, GL_SRC_COLOR, GL_ONE, GL_ONE, GL_FUNC_SUBTRACT, GL_FUNC_SUBTRACT},
    {GL_ONE_MINUS_SRC_COLOR, GL_ONE_MINUS_DST_COLOR, GL_ZERO, GL_ZERO, GL_FUNC_ADD,
     GL_FUNC_ADD},
    {GL_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_CONSTANT_COLOR, GL_CONSTANT_COLOR,
     GL_FUNC_REVERSE_SUBTRACT, GL_FUNC_REVERSE_SUBTRACT},
};

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 0, 0, 0, NULL);
    unsigned char *buf, *alpha;
    const char *ext;
    blend_eq_sep_fn blend_eq_sep;
    GLint v[6];
    int i;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    alpha = malloc(W * H);
    SGL_CHECK(buf != NULL && alpha != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    ext = (const char *)glGetString(GL_EXTENSIONS);
    SGL_CHECK(ext != NULL && strstr(ext, "GL_EXT_blend_equation_separate") != NULL);
    SGL_CHECK(strstr(ext, "GL_EXT_blend_func_separate") != NULL);
    blend_eq_sep = (blend_eq_sep_fn)OSMesaGetProcAddress("glBlendEquationSeparateEXT");
    SGL_CHECK(blend_eq_sep != NULL);

    glClearColor(0.21f, 0.43f, 0.65f, 0.37f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);

    /* background bands: alpha from 0 to 1 across, unblended, with gaps
     * where the clear value (alpha 0.37) stays */
    glBegin(GL_QUADS);
    for (i = 0; i < 4; i++) {
        float y0 = 64.0f * i + 3.3f, y1 = 64.0f * i + 51.7f;
        glColor4f(0.91f, 0.17f + 0.2f * i, 0.29f, 0.0f);
        glVertex2f(0.0f, y0);
        glColor4f(0.13f, 0.79f, 0.47f + 0.1f * i, 1.0f);
        glVertex2f(256.0f, y0);
        glColor4f(0.55f, 0.05f, 0.97f, 0.61f);
        glVertex2f(256.0f, y1);
        glColor4f(0.37f, 0.93f, 0.11f, 0.29f - 0.07f * i);
        glVertex2f(0.0f, y1);
    }
    glEnd();

    glEnable(GL_BLEND);
    glBlendColor(0.83f, 0.37f, 0.19f, 0.61f);
    for (i = 0; i < 16; i++) {
        const struct setting *st = &settings[i];
        float x = 64.0f * (i % 4) + 1.37f, y = 64.0f * (i / 4) + 1.61f;
        glBlendFuncSeparate(st->src_rgb, st->dst_rgb, st->src_a, st->dst_a);
        blend_eq_sep(st->eq_rgb, st->eq_a);
        glBegin(GL_TRIANGLES);
        glColor4f(0.97f, 0.41f, 0.07f, 0.37f);
        glVertex2f(x - 2.1f, y + 3.9f);
        glColor4f(0.23f, 0.89f, 0.59f, 0.95f);
        glVertex2f(x + 61.3f, y + 11.7f);
        glColor4f(0.49f, 0.15f, 0.81f, 0.07f);
        glVertex2f(x + 29.9f, y + 63.1f);

        glColor4f(0.33f, 0.33f, 0.67f, 0.5f);
        glVertex2f(x + 5.3f, y + 47.7f);
        glColor4f(0.77f, 0.63f, 0.11f, 0.13f);
        glVertex2f(x + 40.1f, y - 3.7f);
        glColor4f(0.05f, 1.0f, 0.35f, 0.79f);
        glVertex2f(x + 65.7f, y + 57.9f);
        glEnd();
    }

    glFinish();
    glGetIntegerv(GL_BLEND_SRC_RGB, &v[0]);
    glGetIntegerv(GL_BLEND_DST_RGB, &v[1]);
    glGetIntegerv(GL_BLEND_SRC_ALPHA, &v[2]);
    glGetIntegerv(GL_BLEND_DST_ALPHA, &v[3]);
    glGetIntegerv(GL_BLEND_EQUATION, &v[4]);
    glGetIntegerv(0x883D /* GL_BLEND_EQUATION_ALPHA_EXT */, &v[5]);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, W, H, GL_ALPHA, GL_UNSIGNED_BYTE, alpha);

    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_data(out, "alpha", W * H, alpha);
    sgl_text(out, "state",
             "SRC_RGB=0x%04x DST_RGB=0x%04x SRC_ALPHA=0x%04x DST_ALPHA=0x%04x "
             "EQUATION_RGB=0x%04x EQUATION_ALPHA=0x%04x error=0x%04x\n",
             v[0], v[1], v[2], v[3], v[4], v[5], glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    free(alpha);
    return 0;
}
