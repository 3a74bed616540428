/* fragment_state: the per-fragment state through glGetIntegerv, glGetFloatv,
 * glGetBooleanv and glGetDoublev (blend factors, equations and colour,
 * alpha test, stencil, scissor, colour/depth write masks, logic op) and
 * glIsEnabled of each capability: at the initial state, after setting odd
 * values, after setting out-of-range values (blend colour and alpha
 * reference outside [0,1], stencil reference above 2^8 - 1 and below 0,
 * all-ones masks), and after a series of invalid calls whose glGetError
 * codes are recorded (the state must be unchanged by them).  Values that
 * can lie outside [-1,1] are not read with glGetIntegerv where GL maps them
 * linearly (colours, alpha reference), because Mesa's conversion overflows.
 *
 * One of the "invalid" calls is glBlendFunc(..., GL_SRC_ALPHA_SATURATE):
 * GL 1.5 allows that factor only as a source factor; Mesa accepts it as a
 * destination factor when ARB_blend_func_extended is supported, which it
 * is.  The state dump after the errors shows what it did. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 32
#define H 32

#ifndef GL_BLEND_EQUATION_ALPHA_EXT
#define GL_BLEND_EQUATION_ALPHA_EXT 0x883D
#endif

static FILE *out;

struct q {
    const char *name;
    GLenum pname;
    int n;
    int int_ok;
};

static const struct q queries[] = {
    {"BLEND", GL_BLEND, 1, 1},
    {"BLEND_SRC", GL_BLEND_SRC, 1, 1},
    {"BLEND_DST", GL_BLEND_DST, 1, 1},
    {"BLEND_SRC_RGB", GL_BLEND_SRC_RGB, 1, 1},
    {"BLEND_DST_RGB", GL_BLEND_DST_RGB, 1, 1},
    {"BLEND_SRC_ALPHA", GL_BLEND_SRC_ALPHA, 1, 1},
    {"BLEND_DST_ALPHA", GL_BLEND_DST_ALPHA, 1, 1},
    {"BLEND_EQUATION", GL_BLEND_EQUATION, 1, 1},
    {"BLEND_EQUATION_ALPHA", GL_BLEND_EQUATION_ALPHA_EXT, 1, 1},
    {"BLEND_COLOR", GL_BLEND_COLOR, 4, 0},
    {"ALPHA_TEST", GL_ALPHA_TEST, 1, 1},
    {"ALPHA_TEST_FUNC", GL_ALPHA_TEST_FUNC, 1, 1},
    {"ALPHA_TEST_REF", GL_ALPHA_TEST_REF, 1, 0},
    {"STENCIL_TEST", GL_STENCIL_TEST, 1, 1},
    {"STENCIL_FUNC", GL_STENCIL_FUNC, 1, 1},
    {"STENCIL_REF", GL_STENCIL_REF, 1, 1},
    {"STENCIL_VALUE_MASK", GL_STENCIL_VALUE_MASK, 1, 1},
    {"STENCIL_FAIL", GL_STENCIL_FAIL, 1, 1},
    {"STENCIL_PASS_DEPTH_FAIL", GL_STENCIL_PASS_DEPTH_FAIL, 1, 1},
    {"STENCIL_PASS_DEPTH_PASS", GL_STENCIL_PASS_DEPTH_PASS, 1, 1},
    {"STENCIL_WRITEMASK", GL_STENCIL_WRITEMASK, 1, 1},
    {"STENCIL_CLEAR_VALUE", GL_STENCIL_CLEAR_VALUE, 1, 1},
    {"STENCIL_BITS", GL_STENCIL_BITS, 1, 1},
    {"SCISSOR_TEST", GL_SCISSOR_TEST, 1, 1},
    {"SCISSOR_BOX", GL_SCISSOR_BOX, 4, 1},
    {"COLOR_WRITEMASK", GL_COLOR_WRITEMASK, 4, 1},
    {"DEPTH_WRITEMASK", GL_DEPTH_WRITEMASK, 1, 1},
    {"DEPTH_TEST", GL_DEPTH_TEST, 1, 1},
    {"COLOR_LOGIC_OP", GL_COLOR_LOGIC_OP, 1, 1},
    {"INDEX_LOGIC_OP", GL_INDEX_LOGIC_OP, 1, 1},
    {"LOGIC_OP_MODE", GL_LOGIC_OP_MODE, 1, 1},
    {"DITHER", GL_DITHER, 1, 1},
};

static void dump_all(const char *phase)
{
    size_t k;
    for (k = 0; k < sizeof queries / sizeof queries[0]; k++) {
        const struct q *q = &queries[k];
        GLint iv[4];
        GLfloat fv[4];
        GLboolean bv[4];
        GLdouble dv[4];
        char line[1024];
        int i, len = 0;
        GLenum err;
        for (i = 0; i < 4; i++) {
            iv[i] = -12345;
            fv[i] = -12345.0f;
            bv[i] = 77;
            dv[i] = -12345.0;
        }
        if (q->int_ok)
            glGetIntegerv(q->pname, iv);
        glGetFloatv(q->pname, fv);
        glGetBooleanv(q->pname, bv);
        glGetDoublev(q->pname, dv);
        err = glGetError();
        len += snprintf(line + len, sizeof line - len, "%s %s err=0x%04x\n  i:", phase, q->name, err);
        for (i = 0; i < q->n; i++)
            len += snprintf(line + len, sizeof line - len, " %d", iv[i]);
        len += snprintf(line + len, sizeof line - len, "\n  f:");
        for (i = 0; i < q->n; i++)
            len += snprintf(line + len, sizeof line - len, " %.9g", fv[i]);
        len += snprintf(line + len, sizeof line - len, "\n  b:");
        for (i = 0; i < q->n; i++)
            len += snprintf(line + len, sizeof line - len, " %d", bv[i]);
        len += snprintf(line + len, sizeof line - len, "\n  d:");
        for (i = 0; i < q->n; i++)
            len += snprintf(line + len, sizeof line - len, " %.17g", dv[i]);
        snprintf(line + len, sizeof line - len, "\n");
        sgl_text(out, q->name, "%s", line);
    }
    sgl_text(out, "isenabled",
             "%s BLEND=%d ALPHA_TEST=%d STENCIL_TEST=%d DEPTH_TEST=%d SCISSOR_TEST=%d "
             "COLOR_LOGIC_OP=%d INDEX_LOGIC_OP=%d DITHER=%d err=0x%04x\n",
             phase, glIsEnabled(GL_BLEND), glIsEnabled(GL_ALPHA_TEST),
             glIsEnabled(GL_STENCIL_TEST), glIsEnabled(GL_DEPTH_TEST),
             glIsEnabled(GL_SCISSOR_TEST), glIsEnabled(GL_COLOR_LOGIC_OP),
             glIsEnabled(GL_INDEX_LOGIC_OP), glIsEnabled(GL_DITHER), glGetError());
}

static char errs[4096];
static int nerrs;

#define ERR(call)                                                                        \
    do {                                                                                 \
        call;                                                                            \
        nerrs += snprintf(errs + nerrs, sizeof errs - (size_t)nerrs, "%-60s -> 0x%04x\n", \
                          #call, glGetError());                                          \
    } while (0)

int main(int argc, char **argv)
{
    OSMesaContext ctx;
    unsigned char *buf;
    GLboolean isen;
    out = sgl_open(argc, argv);
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    dump_all("initial");

    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_CONSTANT_COLOR, GL_DST_ALPHA,
                        GL_ONE_MINUS_SRC_COLOR);
    glBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
    glBlendColor(0.37f, 0.61f, 0.83f, 0.29f);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GEQUAL, 0.37f);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_NOTEQUAL, 0x5A, 0x3C);
    glStencilOp(GL_INCR_WRAP, GL_DECR, GL_INVERT);
    glStencilMask(0xA5);
    glClearStencil(0x37);
    glEnable(GL_SCISSOR_TEST);
    glScissor(13, -7, 101, 77);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_NAND);
    glDisable(GL_DITHER);
    glEnable(GL_DEPTH_TEST);
    dump_all("changed");

    glBlendColor(1.3f, -0.2f, 0.5f, 2.0f);
    glAlphaFunc(GL_LESS, 1.3f);
    glStencilFunc(GL_LESS, 300, 0xFFFFFFFFu);
    glStencilMask(0xFFFFFF0Fu);
    glClearStencil(0x1234);
    glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ONE);
    glBlendEquation(GL_MAX);
    glLogicOp(GL_COPY_INVERTED);
    glDisable(GL_COLOR_LOGIC_OP);
    glEnable(GL_INDEX_LOGIC_OP);
    glScissor(-5, 3, 0, 100000);
    dump_all("range");

    glAlphaFunc(GL_NOTEQUAL, -0.25f);
    glStencilFunc(GL_GEQUAL, -5, 0x80);
    dump_all("negative");

    ERR(glBlendFunc(GL_LESS, GL_ONE));
    ERR(glBlendFunc(GL_ONE, GL_FUNC_ADD));
    ERR(glBlendFunc(GL_ZERO, GL_STENCIL_INDEX));
    ERR(glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_NEVER));
    ERR(glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE, GL_ALWAYS, GL_ONE));
    ERR(glBlendEquation(GL_ONE));
    ERR(glBlendEquation(GL_LOGIC_OP));
    ERR(glAlphaFunc(GL_ZERO, 0.5f));
    ERR(glAlphaFunc(GL_KEEP, 0.5f));
    ERR(glStencilFunc(GL_INCR, 1, 0xFF));
    ERR(glStencilOp(GL_INCR, GL_REPLACE, GL_LESS));
    ERR(glStencilOp(GL_ALWAYS, GL_KEEP, GL_KEEP));
    ERR(glStencilOp(GL_KEEP, 0x1234, GL_KEEP));
    ERR(glLogicOp(GL_ONE));
    ERR(glLogicOp(GL_ZERO));
    ERR(glScissor(0, 0, -1, 5));
    ERR(glScissor(0, 0, 5, -1));
    ERR(glDepthFunc(GL_KEEP));
    ERR(glEnable(0x1234));
    ERR(glDisable(GL_BLEND_SRC));
    ERR(isen = glIsEnabled(GL_BLEND_SRC));
    ERR(glBegin(GL_TRIANGLES); glBlendColor(0.1f, 0.2f, 0.3f, 0.4f); glEnd());
    ERR(glBegin(GL_TRIANGLES); glStencilMask(0x11); glEnd());
    ERR(glBegin(GL_TRIANGLES); glAlphaFunc(GL_ALWAYS, 0.0f); glEnd());
    ERR(glBegin(GL_TRIANGLES); glEnable(GL_BLEND); glEnd());
    ERR(glStencilOp(GL_INCR_WRAP, GL_DECR_WRAP, GL_INVERT));
    ERR(glBlendFunc(GL_ONE_MINUS_CONSTANT_ALPHA, GL_SRC_ALPHA_SATURATE));
    sgl_text(out, "errors", "%sglIsEnabled(bad)=%d\n", errs, isen);
    dump_all("after_errors");

    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
