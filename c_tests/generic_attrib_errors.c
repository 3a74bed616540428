/* generic_attrib_errors: the GL 2.0 generic-attribute API's queries and error
 * codes against Mesa's: GL_MAX_VERTEX_ATTRIBS, the initial array state, every
 * glVertexAttrib conversion read back with glGetVertexAttrib{f,d,i}v (as exact
 * hex floats), glVertexAttribPointer state (a buffer object, normalised) with
 * glGetVertexAttribPointerv, display-list compilation of current values, the
 * ARB names through OSMesaGetProcAddress, and the GL_INVALID_VALUE /
 * GL_INVALID_ENUM / GL_INVALID_OPERATION cases (index >= 16, bad size, type,
 * stride and pname, attribute 0's current value). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include <math.h>

static FILE *out;

#define E(call) SGL_ERR(out, 70, #call, call)

static const GLenum PNAMES[] = {
    GL_VERTEX_ATTRIB_ARRAY_ENABLED, GL_VERTEX_ATTRIB_ARRAY_SIZE,
    GL_VERTEX_ATTRIB_ARRAY_STRIDE, GL_VERTEX_ATTRIB_ARRAY_TYPE,
    GL_VERTEX_ATTRIB_ARRAY_NORMALIZED, GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING};

/* every array query of attribute `index`, in the three types */
static void arrays(const char *label, GLuint index)
{
    unsigned k;
    void *p = (void *)1;
    for (k = 0; k < sizeof PNAMES / sizeof PNAMES[0]; k++) {
        GLint iv = -7;
        GLfloat fv = -7.0f;
        GLdouble dv = -7.0;
        glGetVertexAttribiv(index, PNAMES[k], &iv);
        glGetVertexAttribfv(index, PNAMES[k], &fv);
        glGetVertexAttribdv(index, PNAMES[k], &dv);
        sgl_text(out, "array", "%s attr %u pname 0x%04x: %d %a %a err 0x%04x\n", label,
                 index, PNAMES[k], iv, fv, dv, glGetError());
    }
    glGetVertexAttribPointerv(index, GL_VERTEX_ATTRIB_ARRAY_POINTER, &p);
    sgl_text(out, "array", "%s attr %u pointer %lu err 0x%04x\n", label, index,
             (unsigned long)(size_t)p, glGetError());
}

/* attribute `index`'s current value in the three types */
static void current(const char *label, GLuint index)
{
    GLfloat f[4] = {-7, -7, -7, -7};
    GLdouble d[4] = {-7, -7, -7, -7};
    GLint i[4] = {-7, -7, -7, -7};
    glGetVertexAttribfv(index, GL_CURRENT_VERTEX_ATTRIB, f);
    glGetVertexAttribdv(index, GL_CURRENT_VERTEX_ATTRIB, d);
    sgl_text(out, "current", "%-12s attr %2u: %a %a %a %a | %a %a %a %a err 0x%04x\n",
             label, index, f[0], f[1], f[2], f[3], d[0], d[1], d[2], d[3], glGetError());
    /* as integers (truncated) only where they fit: a float past 2^31 has no GLint */
    if (fabs(d[0]) < 2147483520.0 && fabs(d[1]) < 2147483520.0 &&
        fabs(d[2]) < 2147483520.0 && fabs(d[3]) < 2147483520.0) {
        glGetVertexAttribiv(index, GL_CURRENT_VERTEX_ATTRIB, i);
        sgl_text(out, "current", "%-12s attr %2u: %d %d %d %d err 0x%04x\n", label, index,
                 i[0], i[1], i[2], i[3], glGetError());
    }
}

int main(int argc, char **argv)
{
    OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
    unsigned char *buf;
    GLint max = -1;
    GLuint vbo, list;
    SGL_CHECK(ctx != NULL);
    out = sgl_open(argc, argv);
    buf = malloc(32 * 32 * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 32, 32));

    glGetIntegerv(GL_MAX_VERTEX_ATTRIBS, &max);
    sgl_text(out, "max", "GL_MAX_VERTEX_ATTRIBS %d err 0x%04x\n", max, glGetError());

    /* initial state */
    arrays("initial", 1);
    arrays("initial", 15);
    current("initial", 1);
    current("initial", 15);

    /* the conversions */
    {
        static const GLbyte b[4] = {-128, -1, 0, 127};
        static const GLshort s[4] = {-32768, -1, 0, 32767};
        static const GLint in[4] = {-2147483647 - 1, -1, 0, 2147483647};
        static const GLubyte ub[4] = {0, 1, 128, 255};
        static const GLushort us[4] = {0, 1, 32768, 65535};
        static const GLuint ui[4] = {0, 1, 2147483648u, 4294967295u};
        static const GLfloat f3[3] = {1.5f, -2.25f, 3.0f};
        static const GLdouble d4[4] = {0.1, -0.7, 2.7, -2.7};
        glVertexAttrib1f(1, 2.7f);
        current("1f", 1);
        glVertexAttrib1s(2, -3);
        current("1s", 2);
        glVertexAttrib1d(3, 0.3);
        current("1d", 3);
        glVertexAttrib2f(4, 1.25f, -0.5f);
        current("2f", 4);
        glVertexAttrib2s(5, 7, -8);
        current("2s", 5);
        glVertexAttrib2d(6, 1e5, -1e-3);
        current("2d", 6);
        glVertexAttrib3fv(7, f3);
        current("3fv", 7);
        glVertexAttrib3s(8, 1, 2, 3);
        current("3s", 8);
        glVertexAttrib3d(9, 0.1, 0.2, 0.3);
        current("3d", 9);
        glVertexAttrib4dv(10, d4);
        current("4dv", 10);
        glVertexAttrib4bv(11, b);
        current("4bv", 11);
        glVertexAttrib4sv(11, s);
        current("4sv", 11);
        glVertexAttrib4iv(11, in);
        current("4iv", 11);
        glVertexAttrib4ubv(11, ub);
        current("4ubv", 11);
        glVertexAttrib4usv(11, us);
        current("4usv", 11);
        glVertexAttrib4uiv(11, ui);
        current("4uiv", 11);
        glVertexAttrib4Nbv(12, b);
        current("4Nbv", 12);
        glVertexAttrib4Nsv(12, s);
        current("4Nsv", 12);
        glVertexAttrib4Niv(12, in);
        current("4Niv", 12);
        glVertexAttrib4Nub(12, 0, 1, 128, 255);
        current("4Nub", 12);
        glVertexAttrib4Nubv(12, ub);
        current("4Nubv", 12);
        glVertexAttrib4Nusv(12, us);
        current("4Nusv", 12);
        glVertexAttrib4Nuiv(12, ui);
        current("4Nuiv", 12);
        glVertexAttrib4f(15, 1.0f, 2.0f, 3.0f, 4.0f);
        current("4f", 15);
    }

    /* attribute 0: settable outside glBegin/glEnd, but its value is not readable */
    glVertexAttrib4f(0, 1.0f, 2.0f, 3.0f, 4.0f);
    current("attr0", 0);
    arrays("attr0", 0);

    /* array state, from a buffer object and from client memory */
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, 256, NULL, GL_STATIC_DRAW);
    glVertexAttribPointer(5, 3, GL_SHORT, GL_TRUE, 12, (const void *)36);
    glEnableVertexAttribArray(5);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    arrays("vbo", 5);
    glVertexAttribPointer(6, 1, GL_UNSIGNED_BYTE, GL_FALSE, 0, (const void *)4096);
    arrays("client", 6);
    glVertexAttribPointer(6, 2, GL_DOUBLE, GL_TRUE, 40, (const void *)8192);
    glEnableVertexAttribArray(6);
    glDisableVertexAttribArray(6);
    arrays("client2", 6);

    /* a display list records current values, applied when it runs */
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glVertexAttrib4f(13, 5.0f, 6.0f, 7.0f, 8.0f);
    glEndList();
    current("compiled", 13);
    glCallList(list);
    current("called", 13);
    glNewList(list, GL_COMPILE_AND_EXECUTE);
    glVertexAttrib2f(13, -1.0f, -2.0f);
    glEndList();
    current("comp+exec", 13);

    /* the ARB names */
    {
        PFNGLVERTEXATTRIB4FARBPROC f4 =
            (PFNGLVERTEXATTRIB4FARBPROC)OSMesaGetProcAddress("glVertexAttrib4fARB");
        PFNGLVERTEXATTRIBPOINTERARBPROC ptr =
            (PFNGLVERTEXATTRIBPOINTERARBPROC)OSMesaGetProcAddress("glVertexAttribPointerARB");
        PFNGLENABLEVERTEXATTRIBARRAYARBPROC en =
            (PFNGLENABLEVERTEXATTRIBARRAYARBPROC)OSMesaGetProcAddress("glEnableVertexAttribArrayARB");
        PFNGLVERTEXATTRIB4NUBARBPROC nub =
            (PFNGLVERTEXATTRIB4NUBARBPROC)OSMesaGetProcAddress("glVertexAttrib4NubARB");
        SGL_CHECK(f4 != NULL && ptr != NULL && en != NULL && nub != NULL);
        SGL_CHECK(OSMesaGetProcAddress("glVertexAttrib4Nusv") != NULL);
        SGL_CHECK(OSMesaGetProcAddress("glGetVertexAttribPointervARB") != NULL);
        f4(14, 0.5f, 0.25f, 0.125f, 2.0f);
        current("ARB 4f", 14);
        nub(14, 255, 0, 51, 102);
        current("ARB 4Nub", 14);
        ptr(14, 2, GL_INT, GL_FALSE, 8, (const void *)16);
        en(14);
        arrays("ARB", 14);
    }

    /* errors */
    E(glVertexAttrib4f(16, 1, 2, 3, 4));
    E(glVertexAttrib1f(0xffffffffu, 1));
    {
        static const GLfloat v[4] = {1, 2, 3, 4};
        static const GLbyte nb[4] = {1, 2, 3, 4};
        E(glVertexAttrib4fv(16, v));
        E(glVertexAttrib4Nbv(99, nb));
    }
    E(glVertexAttribPointer(16, 4, GL_FLOAT, GL_FALSE, 0, NULL));
    E(glVertexAttribPointer(1, 0, GL_FLOAT, GL_FALSE, 0, NULL));
    E(glVertexAttribPointer(1, 5, GL_FLOAT, GL_FALSE, 0, NULL));
    E(glVertexAttribPointer(1, -1, GL_FLOAT, GL_FALSE, 0, NULL));
    E(glVertexAttribPointer(1, 4, GL_RGBA, GL_FALSE, 0, NULL));
    E(glEnableVertexAttribArray(16));
    E(glDisableVertexAttribArray(1000));
    {
        GLfloat f[4];
        GLint iv[4];
        void *p;
        E(glGetVertexAttribfv(16, GL_VERTEX_ATTRIB_ARRAY_SIZE, f));
        E(glGetVertexAttribiv(16, GL_CURRENT_VERTEX_ATTRIB, iv));
        E(glGetVertexAttribfv(0, GL_CURRENT_VERTEX_ATTRIB, f));
        E(glGetVertexAttribiv(1, GL_TEXTURE_2D, iv));
        E(glGetVertexAttribPointerv(16, GL_VERTEX_ATTRIB_ARRAY_POINTER, &p));
        E(glGetVertexAttribPointerv(1, GL_VERTEX_ATTRIB_ARRAY_SIZE, &p));
    }
    /* the failed calls changed nothing */
    arrays("after errors", 1);
    current("after errors", 1);
    /* a negative stride: GL_INVALID_VALUE. (Mesa 22's validate_array records the
     * error and still stores the pointer, stride -4 included; softgl leaves the
     * array unchanged, so the state after this call is not compared.) */
    E(glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, -4, NULL));

    /* glVertexAttribPointer between glBegin and glEnd (read after glEnd) */
    glBegin(GL_POINTS);
    glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, 0, NULL);
    glEnd();
    E((void)0);
    /* glVertexAttrib is allowed between glBegin and glEnd */
    glBegin(GL_POINTS);
    glVertexAttrib3f(9, 9.0f, 8.0f, 7.0f);
    glEnd();
    E((void)0);
    current("in begin", 9);

    glDeleteBuffers(1, &vbo);
    OSMesaDestroyContext(ctx);
    free(buf);
    sgl_close(out);
    return 0;
}
