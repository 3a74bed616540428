/* dlist_errors: display-list errors and queries, dumped as text.
 * glNewList/glEndList misuse, list 0, bad modes, glGenLists numbering, glIsList,
 * glDeleteLists, errors of compiled commands (raised when the list runs), commands that
 * execute immediately while compiling (glGet, glGenLists, client state), GL_LIST_* values,
 * glCallLists with a bad type or count, and the glNewList of a list that is running. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

static char text[8192];
static int len;

static void put(const char *what, unsigned v)
{
    len += snprintf(text + len, sizeof text - len, "%s 0x%x\n", what, v);
}

static void err(const char *what) { put(what, glGetError()); }

static void lists_state(const char *what)
{
    GLint idx = -1, mode = -1, base = -1, nest = -1;
    glGetIntegerv(GL_LIST_INDEX, &idx);
    glGetIntegerv(GL_LIST_MODE, &mode);
    glGetIntegerv(GL_LIST_BASE, &base);
    glGetIntegerv(GL_MAX_LIST_NESTING, &nest);
    len += snprintf(text + len, sizeof text - len, "%s index=%d mode=0x%x base=%d nest=%d\n",
                    what, idx, mode, base, nest);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
    unsigned char *buf;
    GLuint a, b, c;
    GLfloat mv[16];
    SGL_CHECK(ctx != NULL);
    buf = malloc(64 * 64 * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 64, 64));

    lists_state("initial");
    glEndList();
    err("endlist_without_newlist");
    glNewList(0, GL_COMPILE);
    err("newlist_0");
    glNewList(5, GL_RENDER);
    err("newlist_bad_mode");
    glNewList(0, GL_RENDER);
    err("newlist_0_bad_mode");
    put("genlists_neg", glGenLists(-1));
    err("genlists_neg_err");
    put("genlists_0", glGenLists(0));
    err("genlists_0_err");

    a = glGenLists(3);
    put("genlists_3", a);
    put("islist_a", glIsList(a));
    put("islist_a2", glIsList(a + 2));
    put("islist_a3", glIsList(a + 3));
    put("islist_0", glIsList(0));
    glDeleteLists(a, 3);
    put("islist_after_delete", glIsList(a));
    b = glGenLists(1);
    put("genlists_after_delete", b);
    glDeleteLists(b, -1);
    err("deletelists_neg");
    glDeleteLists(b, 0);
    err("deletelists_0");
    put("islist_b", glIsList(b));

    /* glBegin/glEnd misuse */
    glBegin(GL_TRIANGLES);
    glNewList(20, GL_COMPILE);
    err("newlist_in_begin");
    glEnd();
    err("end");

    /* compile: errors of compiled commands come at execution */
    glNewList(30, GL_COMPILE);
    lists_state("compiling");
    put("islist_30_while_compiling", glIsList(30));
    glNewList(31, GL_COMPILE);
    err("newlist_inside_newlist");
    lists_state("after_nested_newlist");
    glDepthFunc(0x1234);
    err("bad_depthfunc_compiled");
    glBegin(0x77);
    err("bad_begin_compiled");
    glEnable(0x4321);
    err("bad_enable_compiled");
    glTranslatef(1.0f, 2.0f, 3.0f);
    c = glGenLists(2); /* executes now */
    put("genlists_while_compiling", c);
    glGetFloatv(GL_MODELVIEW_MATRIX, mv); /* executes now: the translate was only compiled */
    len += snprintf(text + len, sizeof text - len, "mv_while_compiling %g %g %g\n", mv[12], mv[13], mv[14]);
    glPopMatrix();
    err("popmatrix_compiled");
    glCallLists(1, 0x9999, "a");
    err("calllists_bad_type_compiled");
    glCallLists(-1, GL_UNSIGNED_BYTE, "a");
    err("calllists_neg_compiled");
    glEndList();
    err("endlist");
    lists_state("after_endlist");
    put("islist_30", glIsList(30));
    put("islist_31", glIsList(31));

    glCallList(30);
    err("call30_first_error");
    err("call30_second");
    glGetFloatv(GL_MODELVIEW_MATRIX, mv);
    len += snprintf(text + len, sizeof text - len, "mv_after_call %g %g %g\n", mv[12], mv[13], mv[14]);
    glLoadIdentity();

    /* compile and execute: the error is raised now, and again on each call */
    glNewList(40, GL_COMPILE_AND_EXECUTE);
    lists_state("compile_and_execute");
    glDepthFunc(0x1234);
    err("bad_depthfunc_c_and_e");
    glEndList();
    glCallList(40);
    err("call40");

    /* calls outside lists */
    glCallList(0);
    err("calllist_0");
    glCallList(12345);
    err("calllist_undefined");
    glCallLists(-1, GL_UNSIGNED_BYTE, "a");
    err("calllists_neg");
    glCallLists(1, 0x9999, "a");
    err("calllists_bad_type");
    glCallLists(0, 0x9999, "a");
    err("calllists_0_bad_type");
    glCallLists(-1, 0x9999, "a");
    err("calllists_neg_bad_type");
    glCallLists(2, GL_UNSIGNED_BYTE, NULL);
    err("calllists_null");
    glListBase(7);
    lists_state("listbase_7");
    glListBase(0);

    /* glGenLists continues after the largest name used */
    glNewList(1000, GL_COMPILE);
    glEndList();
    put("genlists_after_1000", glGenLists(2));
    glDeleteLists(1000, 10);
    put("genlists_after_delete_1000", glGenLists(1));
    put("islist_1000", glIsList(1000));

    /* glEndList without glBegin's glEnd inside the list */
    glNewList(50, GL_COMPILE);
    glBegin(GL_POINTS);
    glEndList();
    err("endlist_inside_begin");
    glNewList(51, GL_COMPILE);
    glEnd();
    glEndList();
    err("list_with_end_only");
    glCallList(50);
    err("call50");
    glCallList(51);
    err("call51");

    /* glGetError between glNewList/glEndList executes */
    glNewList(60, GL_COMPILE);
    glEnable(0x4321);
    err("geterror_compiling");
    glEndList();
    glCallList(60);
    err("call60");

    sgl_text(out, "errors", "%s", text);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
