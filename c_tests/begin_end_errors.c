/* begin_end_errors: every exported GL entry point called between glBegin and glEnd
 * (c_tests/begin_end_calls.h, generated from our headers by tools/gen_begin_end_calls.py,
 * with sane arguments).  GL 1.5 §2.6.3 allows only the per-vertex commands, glMaterial,
 * glEvalCoord/Point, glArrayElement and glCallList(s) there; every other command is
 * GL_INVALID_OPERATION and changes nothing.  For each call the scene prints the error
 * glEnd leaves, the value returned, and how many bytes of the output buffer the call
 * wrote.  Then each call is compiled into a display list of its own, and the list called
 * inside glBegin/glEnd.  The state the calls could have changed and the window's pixels
 * (a full-window triangle drawn from the arrays last) show that nothing changed. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 16
#define H 16

static unsigned char ob[8192];
static void *pp;
static const GLubyte cub[256] = {1, 1, 1, 1, 1, 1, 1, 1};
static const GLubyte idx[3] = {0, 1, 2};
static const GLvoid *const idxp[1] = {idx};
static const GLint cfirst[1] = {0};
static const GLsizei ccount[1] = {3};
static GLfloat c_float[64];
static GLdouble c_double[64];
static GLint c_int[64];
static GLuint c_uint[64];
static GLshort c_short[64];
static GLushort c_ushort[64];
static const GLfloat off_float[4] = {2, 2, 0, 1};
static const GLdouble off_double[4] = {2, 2, 0, 1};
static const GLint off_int[4] = {2, 2, 0, 1};
static const GLshort off_short[4] = {2, 2, 0, 1};
static const GLfloat rect_lo_float[2] = {-1, -1}, rect_hi_float[2] = {1, 1};
static const GLdouble rect_lo_double[2] = {-1, -1}, rect_hi_double[2] = {1, 1};
static const GLint rect_lo_int[2] = {-1, -1}, rect_hi_int[2] = {1, 1};
static const GLshort rect_lo_short[2] = {-1, -1}, rect_hi_short[2] = {1, 1};
/* A window-covering triangle, and a fourth vertex off the window for glArrayElement. */
static const GLfloat tri[8] = {-1, -1, 3, -1, -1, 3, 5, 5};

static int written(void)
{
    int n = 0;
    for (size_t i = 0; i < sizeof ob; i++)
        n += ob[i] != 0xA5;
    return n + (pp != (void *)ob);
}

static void drain(void)
{
    while (glGetError() != GL_NO_ERROR)
        ;
}

#define PRINT_V(x) (x, 0.0)
#define PRINT_N(x) ((double)(x))
#define PRINT_P(x) ((x) != NULL ? 1.0 : 0.0)

static void state(FILE *out, const char *name)
{
    GLint v[16];
    GLfloat f[16];
    char buf[4096];
    int n = 0;
#define GETI(p)                                                                        \
    do {                                                                               \
        memset(v, 0, sizeof v);                                                        \
        glGetIntegerv(p, v);                                                           \
        n += snprintf(buf + n, sizeof buf - (size_t)n, "%s=%d,%d,%d,%d\n", #p, v[0], v[1], \
                      v[2], v[3]);                                                     \
    } while (0)
    GETI(GL_BLEND);
    GETI(GL_COLOR_ARRAY);
    GETI(GL_VERTEX_ARRAY);
    GETI(GL_MATRIX_MODE);
    GETI(GL_MODELVIEW_STACK_DEPTH);
    GETI(GL_ATTRIB_STACK_DEPTH);
    GETI(GL_CLIENT_ATTRIB_STACK_DEPTH);
    GETI(GL_NAME_STACK_DEPTH);
    GETI(GL_LIST_BASE);
    GETI(GL_LIST_INDEX);
    GETI(GL_RENDER_MODE);
    GETI(GL_VIEWPORT);
    GETI(GL_SCISSOR_BOX);
    GETI(GL_TEXTURE_BINDING_2D);
    GETI(GL_ARRAY_BUFFER_BINDING);
    GETI(GL_FRAMEBUFFER_BINDING);
    GETI(GL_RENDERBUFFER_BINDING);
    GETI(GL_ACTIVE_TEXTURE);
    GETI(GL_CLIENT_ACTIVE_TEXTURE);
    GETI(GL_UNPACK_ALIGNMENT);
    GETI(GL_DRAW_BUFFER);
    GETI(GL_READ_BUFFER);
    GETI(GL_DEPTH_FUNC);
    GETI(GL_SHADE_MODEL);
    GETI(GL_POLYGON_MODE);
    GETI(GL_BLEND_EQUATION);
    GETI(GL_COLOR_WRITEMASK);
    glGetBufferParameteriv(GL_ARRAY_BUFFER, GL_BUFFER_MAPPED, v);
    n += snprintf(buf + n, sizeof buf - (size_t)n, "mapped=%d\n", v[0]);
    glGetFloatv(GL_MODELVIEW_MATRIX, f);
    n += snprintf(buf + n, sizeof buf - (size_t)n, "modelview=%g,%g,%g\n", f[0], f[5], f[12]);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, f);
    n += snprintf(buf + n, sizeof buf - (size_t)n, "rasterpos=%g,%g\n", f[0], f[1]);
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, f);
    n += snprintf(buf + n, sizeof buf - (size_t)n, "border=%g\n", f[0]);
    n += snprintf(buf + n, sizeof buf - (size_t)n,
                  "is: tex1=%d tex2=%d buf1=%d buf2=%d list1=%d list5=%d fb2=%d rb2=%d q2=%d\n",
                  glIsTexture(1), glIsTexture(2), glIsBuffer(1), glIsBuffer(2), glIsList(1),
                  glIsList(5), glIsFramebuffer(2), glIsRenderbuffer(2), glIsQuery(2));
    n += snprintf(buf + n, sizeof buf - (size_t)n, "err=%x\n", glGetError());
    sgl_text(out, name, "%s", buf);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 16, NULL);
    unsigned char *buf = malloc(W * H * 4);
    GLubyte texel[4] = {10, 20, 30, 40};
    GLuint one = 1;
    char line[256];
    static char log[65536];
    int len = 0;
    double r;
    GLenum e;

    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    for (int i = 0; i < 64; i++) {
        c_float[i] = 0.5f;
        c_double[i] = 0.5;
        c_int[i] = 1;
        c_uint[i] = 1;
        c_short[i] = 1;
        c_ushort[i] = 1;
    }

    /* The objects the calls name (1), a list that only sets the colour, the arrays. */
    glBindTexture(GL_TEXTURE_2D, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
    glGenBuffers(1, &one);
    glNewList(1, GL_COMPILE);
    glColor4f(0.25f, 0.75f, 0.5f, 1.0f);
    glEndList();
    glVertexPointer(2, GL_FLOAT, 0, tri);
    glEnableClientState(GL_VERTEX_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, 1);
    glBufferData(GL_ARRAY_BUFFER, 16, cub, GL_STATIC_DRAW);
    glScalef(0.75f, 0.75f, 1.0f);
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT);
    glClearColor(0.9f, 0.8f, 0.7f, 0.6f);
    drain();
    state(out, "state_before");

#define CALL(name, kind, call)                                                          \
    memset(ob, 0xA5, sizeof ob);                                                        \
    pp = ob;                                                                            \
    glBegin(GL_POINTS);                                                                 \
    r = PRINT_##kind(call);                                                             \
    glEnd();                                                                            \
    e = glGetError();                                                                   \
    len += snprintf(log + len, sizeof log - (size_t)len, "%s err=%x ret=%g out=%d\n", #name, \
                    e, r, written());                                                   \
    drain();
#include "begin_end_calls.h"
#undef CALL
    sgl_data(out, "immediate", (size_t)len, log);
    state(out, "state_after_immediate");

    /* Each call compiled into a list of its own (those GL executes at once run here,
     * outside glBegin/glEnd, except the few that would spoil the rest), then the list
     * called inside glBegin/glEnd. */
    len = 0;
    GLuint list = 100;
#define SPOILS(n)                                                                         \
    (!strcmp(n, "glBegin") || strstr(n, "Delete") || strstr(n, "List") ||                 \
     strstr(n, "Pointer") || strstr(n, "ClientState") || strstr(n, "Interleaved") ||      \
     strstr(n, "RenderMode") || strstr(n, "FeedbackBuffer") || strstr(n, "SelectBuffer") || \
     strstr(n, "MapBuffer") || strstr(n, "BindBuffer") || strstr(n, "BufferData") ||      \
     strstr(n, "BindFramebuffer") || strstr(n, "PixelStore") || strstr(n, "ClientAttrib") || \
     strstr(n, "ClientActive"))
#define CALL(name, kind, call)                                                           \
    if (!SPOILS(#name)) {                                                                \
        GLenum ce;                                                                       \
        memset(ob, 0xA5, sizeof ob);                                                     \
        pp = ob;                                                                         \
        glNewList(list, GL_COMPILE);                                                     \
        (void)PRINT_##kind(call);                                                        \
        glEndList();                                                                     \
        ce = glGetError();                                                               \
        drain();                                                                         \
        glBegin(GL_POINTS);                                                              \
        glCallList(list);                                                                \
        glEnd();                                                                         \
        e = glGetError();                                                                \
        len += snprintf(log + len, sizeof log - (size_t)len, "%s compile=%x err=%x\n", #name, \
                        ce, e);                                                          \
        drain();                                                                         \
        list++;                                                                          \
    }
#include "begin_end_calls.h"
#undef CALL
    sgl_data(out, "listed", (size_t)len, log);
    state(out, "state_after_listed");

    /* A compiled glDrawArrays with the vertex array disabled, called inside. */
    glDisableClientState(GL_VERTEX_ARRAY);
    glNewList(10, GL_COMPILE);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEndList();
    glEnableClientState(GL_VERTEX_ARRAY);
    glBegin(GL_POINTS);
    glCallList(10);
    glEnd();
    snprintf(line, sizeof line, "%x", glGetError());
    sgl_text(out, "draw_arrays_disabled", "%s", line);

    /* glEndList inside a glBegin of a GL_COMPILE_AND_EXECUTE list. */
    glNewList(11, GL_COMPILE_AND_EXECUTE);
    glBegin(GL_POINTS);
    glEndList();
    e = glGetError();
    glEnd();
    snprintf(line, sizeof line, "endlist=%x end=%x", e, glGetError());
    sgl_text(out, "endlist_compile_and_execute", "%s", line);
    drain();

    /* Invalid arguments inside glBegin/glEnd: the refused commands are
     * GL_INVALID_OPERATION before their arguments are looked at; the allowed ones
     * report their own errors. */
    len = 0;
#define ONE(what, call)                                                                   \
    glBegin(GL_POINTS);                                                                   \
    call;                                                                                 \
    glEnd();                                                                              \
    len += snprintf(log + len, sizeof log - (size_t)len, "%s err=%x\n", what, glGetError()); \
    drain();
    ONE("texparameterf_border", glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 0.5f));
    ONE("texparameteri_border", glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, 1));
    ONE("texparameteri_bad_enum", glTexParameteri(GL_TEXTURE_2D, 0x1234, 1));
    ONE("enable_bad_cap", glEnable(0x1234));
    ONE("interleaved_bad_format", glInterleavedArrays(0x1234, 0, tri));
    ONE("getstring_bad_name", (void)glGetString(0x1234));
    ONE("viewport_negative", glViewport(0, 0, -1, -1));
    ONE("drawarrays_bad_mode", glDrawArrays(0x1234, 0, 3));
    ONE("begin_bad_mode", glBegin(0x1234));
    ONE("calllists_bad_type", glCallLists(1, 0x1234, cub));
    ONE("calllist_zero", glCallList(0));
    ONE("material_bad_pname", glMaterialf(GL_FRONT, 0x1234, 1.0f));
    ONE("evalcoord", glEvalCoord1f(0.5f));
    ONE("evalpoint", glEvalPoint2(0, 1));
    ONE("newlist_zero", glNewList(0, GL_COMPILE));
    ONE("genlists", (void)glGenLists(1));
    ONE("vertex_pointer", glVertexPointer(2, GL_FLOAT, 0, cub));
    ONE("pushclientattrib", glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS));
    ONE("popclientattrib", glPopClientAttrib());
    ONE("getpointerv", glGetPointerv(GL_VERTEX_ARRAY_POINTER, &pp));
    ONE("getpixelmap", glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, c_float));
    ONE("endlist_not_compiling", glEndList());
    /* glEnable compiled between a glBegin and glEnd of the list itself. */
    glNewList(12, GL_COMPILE);
    glBegin(GL_POINTS);
    glEnable(GL_BLEND);
    glLineWidth(3.0f);
    glEnd();
    glEndList();
    len += snprintf(log + len, sizeof log - (size_t)len, "compile_inside err=%x\n", glGetError());
    drain();
    glCallList(12);
    len += snprintf(log + len, sizeof log - (size_t)len, "call_compiled_inside err=%x blend=%d\n",
                    glGetError(), glIsEnabled(GL_BLEND));
    drain();
    glNewList(13, GL_COMPILE_AND_EXECUTE);
    glBegin(GL_POINTS);
    glEnable(GL_BLEND);
    len += snprintf(log + len, sizeof log - (size_t)len, "cae_inside err=%x\n", glGetError());
    glGetIntegerv(GL_VIEWPORT, c_int);
    len += snprintf(log + len, sizeof log - (size_t)len, "cae_get err=%x vp=%d\n", glGetError(),
                    c_int[2]);
    glEnd();
    glEndList();
    len += snprintf(log + len, sizeof log - (size_t)len, "cae_end err=%x blend=%d\n",
                    glGetError(), glIsEnabled(GL_BLEND));
    drain();
    glCallList(13);
    len += snprintf(log + len, sizeof log - (size_t)len, "call_cae err=%x blend=%d\n",
                    glGetError(), glIsEnabled(GL_BLEND));
    drain();
    {
        GLfloat lw = 0;
        glGetFloatv(GL_LINE_WIDTH, &lw);
        len += snprintf(log + len, sizeof log - (size_t)len, "line_width=%g\n", lw);
    }
    sgl_data(out, "extras", (size_t)len, log);

    /* The window: the clear colour, then the arrays' triangle in the current colour. */
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glFinish();
    state(out, "state_end");
    sgl_image(out, "window", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
