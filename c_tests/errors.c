/* errors: glGetError after invalid calls, and the state that must be left
 * unchanged by them.  Every call's error code is written as text, so the
 * codes are compared against Mesa's; a final drawing shows the state. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 128
#define H 128

static FILE *out;

/* run a call and record the error it raised (and that one read clears it) */
#define E(call) SGL_ERR(out, 60, #call, call)

/* record the pending error (and that one read clears it) */
static void rec(const char *label)
{
    GLenum e1 = glGetError(), e2 = glGetError();
    sgl_text(out, "err", "%-60s -> 0x%04x then 0x%04x\n", label, e1, e2);
}

static void dump_ints(const char *name, GLenum pname, int n)
{
    GLint v[16];
    char line[512];
    int i, len = 0;
    for (i = 0; i < 16; i++)
        v[i] = -777;
    glGetIntegerv(pname, v);
    len += snprintf(line + len, sizeof line - len, "%s:", name);
    for (i = 0; i < n; i++)
        len += snprintf(line + len, sizeof line - len, " %d", v[i]);
    sgl_text(out, "state", "%s error=0x%04x\n", line, glGetError());
}

int main(int argc, char **argv)
{
    OSMesaContext ctx;
    unsigned char *buf;
    GLuint bo;
    int i;
    static const GLfloat tri[] = {10.5f, 10.5f, 100.3f, 20.7f, 50.1f, 110.9f};
    out = sgl_open(argc, argv);
    ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    E((void)0); /* no error pending at start */
    glViewport(3, 5, 120, 117);
    glDepthFunc(GL_GEQUAL);
    glShadeModel(GL_FLAT);
    glCullFace(GL_FRONT);

    /* the errors of the brief */
    E(glEnable(0x1234));
    E(glViewport(0, 0, -1, 5));
    E(glEnd());
    E(glPopMatrix());
    glGenBuffers(1, &bo);
    glBindBuffer(GL_ARRAY_BUFFER, bo);
    E(glBufferData(GL_ARRAY_BUFFER, -4, NULL, GL_STATIC_DRAW));
    E(glDrawArrays(0x1234, 0, 3));

    /* more enums */
    E(glDisable(0x1234));
    E(glDepthFunc(GL_FRONT));
    E(glCullFace(GL_LESS));
    E(glFrontFace(GL_LESS));
    E(glShadeModel(GL_CW));
    E(glMatrixMode(GL_TEXTURE + 7));
    E(glClear(0x00000001));
    E(glEnableClientState(GL_DEPTH_TEST));
    E(glBindBuffer(GL_TEXTURE_2D, bo));
    E(glBufferData(GL_ARRAY_BUFFER, 16, NULL, 0x1234));
    E(glVertexPointer(2, GL_UNSIGNED_BYTE, 0, tri));
    E(glColorPointer(3, 0x1234, 0, tri));
    E(glDrawElements(GL_TRIANGLES, 3, GL_FLOAT, tri));
    E(glPixelStorei(0x1234, 4));
    E(glReadPixels(0, 0, 1, 1, GL_RGBA, 0x1234, buf));
    E(glIsEnabled(0x1234));
    E(glGetIntegerv(0x1234, (GLint *)buf));

    /* values */
    E(glViewport(0, 0, 5, -1));
    E(glVertexPointer(5, GL_FLOAT, 0, tri));
    E(glColorPointer(2, GL_FLOAT, 0, tri));
    E(glDrawArrays(GL_TRIANGLES, 0, -1));
    E(glDrawElements(GL_TRIANGLES, -3, GL_UNSIGNED_SHORT, tri));
    E(glDrawRangeElements(GL_TRIANGLES, 5, 2, 3, GL_UNSIGNED_SHORT, tri));
    E(glPixelStorei(GL_PACK_ALIGNMENT, 3));
    E(glReadPixels(0, 0, -1, 1, GL_RGBA, GL_UNSIGNED_BYTE, buf));
    E(glGenBuffers(-1, &bo));
    E(glDeleteBuffers(-1, &bo));
    E(glBufferSubData(GL_ARRAY_BUFFER, 0, 4, tri)); /* buffer has size 0 */
    E(glFrustum(-1.0, 1.0, -1.0, 1.0, -1.0, 10.0));
    E(glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 1.0));
    E(glOrtho(1.0, 1.0, -1.0, 1.0, -1.0, 1.0));
    E(glClearDepth(7.5)); /* clamped, no error */
    E(glDepthRange(-0.5, 1.5)); /* clamped, no error */
    E(glDepthRange(0.0, 1.0));

    /* operations */
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    E(glBufferData(GL_ARRAY_BUFFER, 16, NULL, GL_STATIC_DRAW));
    E(glBufferSubData(GL_ARRAY_BUFFER, 0, 4, tri));
    glBindBuffer(GL_ARRAY_BUFFER, bo);
    glBufferData(GL_ARRAY_BUFFER, 16, NULL, GL_STATIC_DRAW);
    E(glBufferSubData(GL_ARRAY_BUFFER, 8, 12, tri));
    E(glBufferSubData(GL_ARRAY_BUFFER, -1, 4, tri));
    glBindBuffer(GL_ARRAY_BUFFER, 0);

    /* stacks */
    glMatrixMode(GL_PROJECTION);
    E(glPopMatrix());
    for (i = 0; i < 40; i++)
        glPushMatrix();
    rec("40 x glPushMatrix on the projection stack");
    glMatrixMode(GL_MODELVIEW);
    for (i = 0; i < 31; i++)
        glPushMatrix();
    rec("31 x glPushMatrix on the modelview stack");
    E(glPushMatrix());
    dump_ints("modelview_stack_depth", GL_MODELVIEW_STACK_DEPTH, 1);
    dump_ints("projection_stack_depth", GL_PROJECTION_STACK_DEPTH, 1);
    for (i = 0; i < 40; i++)
        glPopMatrix();
    rec("40 x glPopMatrix on the modelview stack");
    glMatrixMode(GL_PROJECTION);
    for (i = 0; i < 50; i++)
        glPopMatrix();
    glMatrixMode(GL_MODELVIEW);
    rec("50 x glPopMatrix on the projection stack");

    /* inside glBegin/glEnd */
    glBegin(GL_TRIANGLES);
    glBegin(GL_TRIANGLES);
    glEnd();
    rec("glBegin inside glBegin");
    glBegin(GL_TRIANGLES);
    glEnable(GL_DEPTH_TEST);
    glEnd();
    rec("glEnable inside glBegin");
    glBegin(GL_TRIANGLES);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnd();
    rec("glDrawArrays inside glBegin");
    glBegin(GL_TRIANGLES);
    glVertex2f(1.0f, 2.0f);
    {
        GLenum e = glGetError(); /* itself invalid here: returns 0 */
        glEnd();
        sgl_text(out, "err", "glGetError inside glBegin returned 0x%04x\n", e);
    }
    rec("after glGetError inside glBegin");
    E(glBegin(0x1234));
    E(glEnd());

    /* first error wins until read */
    glEnable(0x1234);
    glViewport(0, 0, -1, -1);
    glPopMatrix();
    rec("three errors, first wins");

    /* state after all that */
    dump_ints("viewport", GL_VIEWPORT, 4);
    dump_ints("depth_func", GL_DEPTH_FUNC, 1);
    dump_ints("shade_model", GL_SHADE_MODEL, 1);
    dump_ints("cull_face_mode", GL_CULL_FACE_MODE, 1);
    dump_ints("front_face", GL_FRONT_FACE, 1);
    dump_ints("matrix_mode", GL_MATRIX_MODE, 1);
    dump_ints("modelview_stack_depth", GL_MODELVIEW_STACK_DEPTH, 1);
    dump_ints("projection_stack_depth", GL_PROJECTION_STACK_DEPTH, 1);
    dump_ints("pack_alignment", GL_PACK_ALIGNMENT, 1);
    dump_ints("array_buffer_binding", GL_ARRAY_BUFFER_BINDING, 1);
    dump_ints("vertex_array_size", GL_VERTEX_ARRAY_SIZE, 1);
    dump_ints("vertex_array_type", GL_VERTEX_ARRAY_TYPE, 1);
    dump_ints("vertex_array_stride", GL_VERTEX_ARRAY_STRIDE, 1);
    dump_ints("color_array_size", GL_COLOR_ARRAY_SIZE, 1);
    dump_ints("depth_test", GL_DEPTH_TEST, 1);
    dump_ints("vertex_array_enabled", GL_VERTEX_ARRAY, 1);
    {
        GLfloat m[16], d[2];
        glGetFloatv(GL_PROJECTION_MATRIX, m);
        glGetFloatv(GL_DEPTH_RANGE, d);
        sgl_text(out, "state", "projection: %g %g %g %g / %g %g %g %g depth_range %g %g\n",
                 m[0], m[5], m[10], m[15], m[12], m[13], m[14], m[11], d[0], d[1]);
    }

    /* draw with whatever state survived */
    glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, 128.0, 0.0, 128.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.0f, 0.0f);
    glVertex2fv(tri);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex2fv(tri + 2);
    glColor3f(0.0f, 0.0f, 1.0f);
    glVertex2fv(tri + 4);
    glEnd();
    glFinish();
    rec("after drawing");
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);

    glDeleteBuffers(1, &bo);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
