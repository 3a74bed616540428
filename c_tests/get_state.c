/* get_state: glGetIntegerv, glGetFloatv, glGetBooleanv and glGetDoublev of
 * the foundation state (viewport, depth range, matrices, stacks, limits,
 * depth/cull/shade state, clear values, current colour and normal, bit
 * depths, pixel store, arrays and buffer bindings), first at the initial
 * state, then after setting awkward values.  Every query goes through all
 * four getters, so the type conversions are compared too.  Floats are
 * printed with 9 significant digits and doubles with 17, i.e. exactly.
 * Values outside [-1,1] are not read as integers where GL maps them
 * linearly (colours, matrices), because Mesa's conversion overflows. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 64
#define H 48

static FILE *out;

/* int_ok = 0 where values outside [-1,1] would overflow Mesa's
 * float-to-integer mapping (undefined in C), so glGetIntegerv is skipped */
struct q {
    const char *name;
    GLenum pname;
    int n;
    int int_ok;
};

static const struct q queries[] = {
    {"VIEWPORT", GL_VIEWPORT, 4, 1},
    {"DEPTH_RANGE", GL_DEPTH_RANGE, 2, 1},
    {"MODELVIEW_MATRIX", GL_MODELVIEW_MATRIX, 16, 0},
    {"PROJECTION_MATRIX", GL_PROJECTION_MATRIX, 16, 0},
    {"MATRIX_MODE", GL_MATRIX_MODE, 1, 1},
    {"MODELVIEW_STACK_DEPTH", GL_MODELVIEW_STACK_DEPTH, 1, 1},
    {"PROJECTION_STACK_DEPTH", GL_PROJECTION_STACK_DEPTH, 1, 1},
    {"MAX_MODELVIEW_STACK_DEPTH", GL_MAX_MODELVIEW_STACK_DEPTH, 1, 1},
    {"MAX_PROJECTION_STACK_DEPTH", GL_MAX_PROJECTION_STACK_DEPTH, 1, 1},
    {"MAX_VIEWPORT_DIMS", GL_MAX_VIEWPORT_DIMS, 2, 1},
    {"DEPTH_TEST", GL_DEPTH_TEST, 1, 1},
    {"DEPTH_FUNC", GL_DEPTH_FUNC, 1, 1},
    {"DEPTH_WRITEMASK", GL_DEPTH_WRITEMASK, 1, 1},
    {"CULL_FACE", GL_CULL_FACE, 1, 1},
    {"CULL_FACE_MODE", GL_CULL_FACE_MODE, 1, 1},
    {"FRONT_FACE", GL_FRONT_FACE, 1, 1},
    {"SHADE_MODEL", GL_SHADE_MODEL, 1, 1},
    {"COLOR_CLEAR_VALUE", GL_COLOR_CLEAR_VALUE, 4, 1},
    {"DEPTH_CLEAR_VALUE", GL_DEPTH_CLEAR_VALUE, 1, 1},
    {"COLOR_WRITEMASK", GL_COLOR_WRITEMASK, 4, 1},
    {"CURRENT_COLOR", GL_CURRENT_COLOR, 4, 1},
    {"CURRENT_NORMAL", GL_CURRENT_NORMAL, 3, 1},
    {"RED_BITS", GL_RED_BITS, 1, 1},
    {"GREEN_BITS", GL_GREEN_BITS, 1, 1},
    {"BLUE_BITS", GL_BLUE_BITS, 1, 1},
    {"ALPHA_BITS", GL_ALPHA_BITS, 1, 1},
    {"DEPTH_BITS", GL_DEPTH_BITS, 1, 1},
    {"STENCIL_BITS", GL_STENCIL_BITS, 1, 1},
    {"SUBPIXEL_BITS", GL_SUBPIXEL_BITS, 1, 1},
    {"DOUBLEBUFFER", GL_DOUBLEBUFFER, 1, 1},
    {"DRAW_BUFFER", GL_DRAW_BUFFER, 1, 1},
    {"READ_BUFFER", GL_READ_BUFFER, 1, 1},
    {"DITHER", GL_DITHER, 1, 1},
    {"PACK_ALIGNMENT", GL_PACK_ALIGNMENT, 1, 1},
    {"UNPACK_ALIGNMENT", GL_UNPACK_ALIGNMENT, 1, 1},
    {"VERTEX_ARRAY", GL_VERTEX_ARRAY, 1, 1},
    {"VERTEX_ARRAY_SIZE", GL_VERTEX_ARRAY_SIZE, 1, 1},
    {"VERTEX_ARRAY_TYPE", GL_VERTEX_ARRAY_TYPE, 1, 1},
    {"VERTEX_ARRAY_STRIDE", GL_VERTEX_ARRAY_STRIDE, 1, 1},
    {"COLOR_ARRAY", GL_COLOR_ARRAY, 1, 1},
    {"COLOR_ARRAY_SIZE", GL_COLOR_ARRAY_SIZE, 1, 1},
    {"COLOR_ARRAY_TYPE", GL_COLOR_ARRAY_TYPE, 1, 1},
    {"COLOR_ARRAY_STRIDE", GL_COLOR_ARRAY_STRIDE, 1, 1},
    {"ARRAY_BUFFER_BINDING", GL_ARRAY_BUFFER_BINDING, 1, 1},
    {"ELEMENT_ARRAY_BUFFER_BINDING", GL_ELEMENT_ARRAY_BUFFER_BINDING, 1, 1},
    {"VERTEX_ARRAY_BUFFER_BINDING", GL_VERTEX_ARRAY_BUFFER_BINDING, 1, 1},
    {"COLOR_ARRAY_BUFFER_BINDING", GL_COLOR_ARRAY_BUFFER_BINDING, 1, 1},
};

static void dump_all(const char *phase)
{
    size_t k;
    for (k = 0; k < sizeof queries / sizeof queries[0]; k++) {
        const struct q *q = &queries[k];
        GLint iv[16];
        GLfloat fv[16];
        GLboolean bv[16];
        GLdouble dv[16];
        char line[2048];
        int i, len = 0;
        GLenum err;
        for (i = 0; i < 16; i++) {
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
    sgl_text(out, "isenabled", "%s DEPTH_TEST=%d CULL_FACE=%d DITHER=%d VERTEX_ARRAY=%d\n", phase,
             glIsEnabled(GL_DEPTH_TEST), glIsEnabled(GL_CULL_FACE), glIsEnabled(GL_DITHER),
             glIsEnabled(GL_VERTEX_ARRAY));
}

int main(int argc, char **argv)
{
    OSMesaContext ctx;
    unsigned char *buf;
    GLuint bo[2];
    static GLshort verts[8];
    out = sgl_open(argc, argv);
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    dump_all("initial");

    glViewport(7, -11, 201, 173);
    glDepthRange(0.1337, 0.9);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1.37, 0.913, -0.77, 0.8, 1.3, 77.7);
    glPushMatrix();
    glOrtho(-3.3, 13.37, -2.5, 12.1, -1.5, 7.0);
    glMatrixMode(GL_MODELVIEW);
    glPushMatrix();
    glTranslatef(1.337f, -2.5f, 0.1f);
    glPushMatrix();
    glRotatef(33.3f, 0.2f, 0.7f, 0.1f);
    glScalef(1.5f, -0.25f, 3.0f);
    glRotated(-91.7, 0.0, 0.0, 1.0);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GEQUAL);
    glDepthMask(GL_FALSE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT_AND_BACK);
    glFrontFace(GL_CW);
    glShadeModel(GL_FLAT);
    glClearColor(0.1337f, 1.25f, -0.5f, 0.6f);
    glClearDepth(0.3713);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glColor4f(0.1337f, -0.25f, 0.75f, 0.5f);
    glNormal3f(0.3f, -0.7f, 0.613f);
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glDisable(GL_DITHER);
    glGenBuffers(2, bo);
    glBindBuffer(GL_ARRAY_BUFFER, bo[1]);
    glBufferData(GL_ARRAY_BUFFER, 64, NULL, GL_STATIC_DRAW);
    glColorPointer(4, GL_UNSIGNED_BYTE, 12, (const void *)4);
    glBindBuffer(GL_ARRAY_BUFFER, bo[0]);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, bo[1]);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glVertexPointer(2, GL_SHORT, 6, verts);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);

    dump_all("changed");

    glMatrixMode(GL_PROJECTION);
    glPopMatrix();
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3ub(255, 128, 1);
    glNormal3b(127, -128, 64);
    glDepthRange(0.9, 0.2);
    glViewport(0, 0, 100000, 100000);
    dump_all("again");

    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
