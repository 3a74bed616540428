/* secondary_color_array: GL_COLOR_SUM without lighting, the secondary colour coming
 * from glSecondaryColorPointer (GL 1.4, EXT_secondary_color): client memory with a
 * stride and from a buffer object, every component type, 3 and 4 components, drawn
 * with glDrawArrays, glDrawElements, glDrawRangeElements, glMultiDrawArrays,
 * glArrayElement and a display list; flat shading; GL_COLOR_SUM off; the array
 * state queries, glPushClientAttrib and the errors. */
#define GL_GLEXT_PROTOTYPES
#include "prims_common.h"
#include <GL/glext.h>

struct vert {
    GLfloat x, y;
    GLubyte rgba[4];
    GLubyte sec[3];
    GLubyte pad;
};

/* A 4x2 grid of triangles (as a strip of 10 vertices) at (x0, y0), 60x30 pixels. */
static void grid(struct vert *v, float x0, float y0, int seed)
{
    int i;
    for (i = 0; i < 10; i++) {
        v[i].x = x0 + 12.0f * (float)(i / 2) + 0.3f * (float)(i % 3);
        v[i].y = y0 + 29.5f * (float)(i % 2);
        v[i].rgba[0] = (GLubyte)((i * 53 + seed) % 200);
        v[i].rgba[1] = (GLubyte)((i * 97 + 40 + seed) % 180);
        v[i].rgba[2] = (GLubyte)((i * 31 + 10 + seed) % 160);
        v[i].rgba[3] = 255;
        v[i].sec[0] = (GLubyte)((i * 71 + 120 + seed) % 256);
        v[i].sec[1] = (GLubyte)((i * 29 + 7 + seed) % 256);
        v[i].sec[2] = (GLubyte)((i * 113 + 60 + seed) % 256);
        v[i].pad = 0;
    }
}

static void use_struct(const struct vert *v)
{
    glVertexPointer(2, GL_FLOAT, sizeof(struct vert), &v[0].x);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(struct vert), v[0].rgba);
    glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, sizeof(struct vert), v[0].sec);
}

int main(int argc, char **argv)
{
    static struct vert a[10], b[10], c[10];
    static const GLushort idx[12] = {0, 1, 2, 2, 1, 3, 4, 5, 6, 7, 8, 9};
    static const GLuint idx32[6] = {9, 8, 7, 0, 1, 2};
    static GLfloat secf[10 * 4];
    static GLbyte secb[10 * 3];
    static GLshort secs[10 * 3];
    static GLushort secus[10 * 3];
    static GLint seci[10 * 4];
    static GLuint secui[10 * 3];
    static GLdouble secd[10 * 3];
    static const GLint firsts[2] = {0, 4};
    static const GLsizei counts[2] = {4, 6};
    FILE *out = sgl_open(argc, argv);
    GLuint buf[2], list;
    GLint iv[8], err[8];
    GLvoid *p;
    GLfloat cur[4];
    int i, j;

    prims_begin();
    glEnable(GL_COLOR_SUM);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glEnableClientState(GL_SECONDARY_COLOR_ARRAY);

    /* client memory, interleaved: DrawArrays, DrawElements, DrawRangeElements */
    grid(a, 4.0f, 220.0f, 0);
    use_struct(a);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 10);
    grid(b, 70.0f, 220.0f, 33);
    use_struct(b);
    glDrawElements(GL_TRIANGLES, 12, GL_UNSIGNED_SHORT, idx);
    grid(c, 136.0f, 220.0f, 77);
    use_struct(c);
    glDrawRangeElements(GL_TRIANGLES, 0, 9, 6, GL_UNSIGNED_INT, idx32);
    glMultiDrawArrays(GL_TRIANGLE_STRIP, firsts, counts, 2);

    /* every component type, separate arrays over grid a's positions */
    grid(a, 4.0f, 180.0f, 5);
    glVertexPointer(2, GL_FLOAT, sizeof(struct vert), &a[0].x);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(struct vert), a[0].rgba);
    for (i = 0; i < 10; i++) {
        for (j = 0; j < 4; j++) {
            float s = (float)((i * 37 + j * 61 + 11) % 97) / 96.0f;
            secf[4 * i + j] = s * 1.2f - 0.1f;
            seci[4 * i + j] = (GLint)((s - 0.3f) * 2147483647.0f);
            if (j < 3) {
                secb[3 * i + j] = (GLbyte)(s * 255.0f - 100.0f);
                secs[3 * i + j] = (GLshort)(s * 65535.0f - 20000.0f);
                secus[3 * i + j] = (GLushort)(s * 65535.0f);
                secui[3 * i + j] = (GLuint)(s * 4294967295.0);
                secd[3 * i + j] = (double)s;
            }
        }
    }
    glSecondaryColorPointer(4, GL_FLOAT, 0, secf);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 10);
    glTranslatef(64.0f, 0.0f, 0.0f);
    glSecondaryColorPointer(3, GL_BYTE, 0, secb);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 10);
    glTranslatef(64.0f, 0.0f, 0.0f);
    glSecondaryColorPointer(3, GL_SHORT, 0, secs);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 10);
    glTranslatef(64.0f, 0.0f, 0.0f);
    glSecondaryColorPointer(3, GL_UNSIGNED_SHORT, 0, secus);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 10);
    glLoadIdentity();
    glTranslatef(0.0f, -40.0f, 0.0f);
    glSecondaryColorPointerEXT(4, GL_INT, 0, seci);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 10);
    glTranslatef(64.0f, 0.0f, 0.0f);
    glSecondaryColorPointer(3, GL_UNSIGNED_INT, 0, secui);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 10);
    glTranslatef(64.0f, 0.0f, 0.0f);
    glSecondaryColorPointer(3, GL_DOUBLE, 0, secd);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 10);
    glTranslatef(64.0f, 0.0f, 0.0f);
    /* GL_COLOR_SUM off: the array is ignored */
    glDisable(GL_COLOR_SUM);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 10);
    glEnable(GL_COLOR_SUM);
    glLoadIdentity();

    /* buffer objects: positions and colours interleaved, the secondary colour float */
    grid(b, 4.0f, 100.0f, 50);
    for (i = 0; i < 10; i++)
        for (j = 0; j < 3; j++)
            secf[3 * i + j] = (float)((i * 17 + j * 45 + 3) % 50) / 49.0f;
    glGenBuffers(2, buf);
    glBindBuffer(GL_ARRAY_BUFFER, buf[0]);
    glBufferData(GL_ARRAY_BUFFER, sizeof(b), b, GL_STATIC_DRAW);
    glVertexPointer(2, GL_FLOAT, sizeof(struct vert), (const GLvoid *)0);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(struct vert), (const GLvoid *)8);
    glBindBuffer(GL_ARRAY_BUFFER, buf[1]);
    glBufferData(GL_ARRAY_BUFFER, 30 * sizeof(GLfloat), secf, GL_STATIC_DRAW);
    glSecondaryColorPointer(3, GL_FLOAT, 0, (const GLvoid *)0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING, &iv[0]);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 10);
    glTranslatef(66.0f, 0.0f, 0.0f);
    glDrawElements(GL_TRIANGLES, 12, GL_UNSIGNED_SHORT, idx);
    glTranslatef(66.0f, 0.0f, 0.0f);
    glShadeModel(GL_FLAT);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 10);
    glShadeModel(GL_SMOOTH);
    glLoadIdentity();

    /* glArrayElement and a compiled glDrawArrays (read at compile time) */
    grid(c, 4.0f, 60.0f, 90);
    use_struct(c);
    glSecondaryColor3f(0.1f, 0.2f, 0.3f);
    glBegin(GL_TRIANGLE_STRIP);
    for (i = 0; i < 10; i++)
        glArrayElement(i);
    glEnd();
    glGetFloatv(GL_CURRENT_SECONDARY_COLOR, cur);
    sgl_text(out, "current_after_array_element", "%g %g %g %g\n", cur[0], cur[1], cur[2], cur[3]);
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glTranslatef(66.0f, 0.0f, 0.0f);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 10);
    glTranslatef(66.0f, 0.0f, 0.0f);
    glBegin(GL_TRIANGLES);
    glArrayElement(2);
    glArrayElement(3);
    glArrayElement(4);
    glEnd();
    glEndList();
    for (i = 0; i < 10; i++)
        c[i].sec[0] = c[i].sec[1] = c[i].sec[2] = 0;
    glSecondaryColor3f(0.0f, 0.5f, 0.0f);
    glCallList(list);
    glGetFloatv(GL_CURRENT_SECONDARY_COLOR, cur);
    sgl_text(out, "current_after_list", "%g %g %g %g\n", cur[0], cur[1], cur[2], cur[3]);
    glLoadIdentity();
    glTranslatef(200.0f, 0.0f, 0.0f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glLoadIdentity();
    prims_end(out, "secondary");

    /* state */
    glSecondaryColorPointer(4, GL_SHORT, 12, secs);
    glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_SIZE, &iv[1]);
    glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_TYPE, &iv[2]);
    glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_STRIDE, &iv[3]);
    glGetIntegerv(GL_SECONDARY_COLOR_ARRAY, &iv[4]);
    glGetPointerv(GL_SECONDARY_COLOR_ARRAY_POINTER, &p);
    sgl_text(out, "state", "vbo %d size %d type 0x%x stride %d on %d enabled %d ptr_ok %d err 0x%x\n",
             iv[0] == (GLint)buf[1], iv[1], iv[2], iv[3], iv[4],
             glIsEnabled(GL_SECONDARY_COLOR_ARRAY), p == (GLvoid *)secs, glGetError());
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
    glSecondaryColorPointer(3, GL_UNSIGNED_BYTE, 0, secb);
    glPopClientAttrib();
    glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_SIZE, &iv[1]);
    glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_TYPE, &iv[2]);
    glGetPointerv(GL_SECONDARY_COLOR_ARRAY_POINTER, &p);
    sgl_text(out, "popped", "size %d type 0x%x on %d ptr_ok %d\n", iv[1], iv[2],
             glIsEnabled(GL_SECONDARY_COLOR_ARRAY), p == (GLvoid *)secs);

    /* errors */
    glSecondaryColorPointer(2, GL_FLOAT, 0, secf);
    err[0] = glGetError();
    glSecondaryColorPointer(5, GL_FLOAT, 0, secf);
    err[1] = glGetError();
    glSecondaryColorPointer(3, GL_BITMAP, 0, secf);
    err[2] = glGetError();
    glSecondaryColorPointer(2, GL_BITMAP, 0, secf);
    err[3] = glGetError();
    glBegin(GL_TRIANGLES);
    glSecondaryColorPointer(2, GL_BITMAP, -1, secf);
    glEnd();
    err[4] = glGetError();
    glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
    err[5] = glGetError();
    glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_SIZE, &iv[1]);
    glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_TYPE, &iv[2]);
    glGetIntegerv(GL_SECONDARY_COLOR_ARRAY_STRIDE, &iv[3]);
    /* The stride is checked first.  (Mesa 22.3 then stores the negative stride anyway,
     * so nothing is queried after these.) */
    glSecondaryColorPointer(3, GL_FLOAT, -4, secf);
    err[6] = glGetError();
    glSecondaryColorPointer(2, GL_BITMAP, -4, secf);
    err[7] = glGetError();
    sgl_text(out, "errors", "%x %x %x %x %x %x %x %x size %d type 0x%x stride %d\n", err[0],
             err[1], err[2], err[3], err[4], err[5], err[6], err[7], iv[1], iv[2], iv[3]);
    glDeleteBuffers(2, buf);
    prims_close(out);
    return 0;
}
