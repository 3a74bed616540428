/* shared_lists: display lists belong to the share group (OSMesaCreateContextExt
 * sharelist), like textures and buffers. A compiles two lists (one calls the
 * other); B, sharing A's objects, sees the names, draws them and generates
 * names after A's; C shares nothing and sees none. A list deleted in B is gone
 * in A. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 48
#define H 40

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext a = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    OSMesaContext b = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, a);
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    unsigned char *ba = calloc(W * H * 4, 1), *bb = calloc(W * H * 4, 1),
                  *bc = calloc(W * H * 4, 1);
    GLuint tri, both, more, other;
    SGL_CHECK(a && b && c && ba && bb && bc);

    /* A: two lists, the second calls the first */
    SGL_CHECK(OSMesaMakeCurrent(a, ba, GL_UNSIGNED_BYTE, W, H));
    tri = glGenLists(2);
    both = tri + 1;
    glNewList(tri, GL_COMPILE);
    glBegin(GL_TRIANGLES);
    glColor3f(0.9f, 0.3f, 0.1f);
    glVertex2f(-0.9f, -0.9f);
    glColor3f(0.1f, 0.8f, 0.2f);
    glVertex2f(0.9f, -0.6f);
    glColor3f(0.2f, 0.3f, 1.0f);
    glVertex2f(-0.3f, 0.9f);
    glEnd();
    glEndList();
    glNewList(both, GL_COMPILE);
    glCallList(tri);
    glTranslatef(0.4f, 0.2f, 0.0f);
    glScalef(0.5f, 0.5f, 1.0f);
    glCallList(tri);
    glEndList();
    glCallList(both);
    glFinish();
    sgl_image(out, "a", W, H, 4, "RGBA", W * 4, 1, ba);

    /* B shares: same names, same picture; new names continue after A's */
    SGL_CHECK(OSMesaMakeCurrent(b, bb, GL_UNSIGNED_BYTE, W, H));
    sgl_text(out, "b_names", "isList tri=%d both=%d err=0x%x\n", glIsList(tri), glIsList(both),
             glGetError());
    glClearColor(0.2f, 0.2f, 0.25f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glCallList(both);
    more = glGenLists(3);
    sgl_text(out, "b_gen", "more=%u (tri=%u)\n", more, tri);
    glNewList(more, GL_COMPILE);
    glColor3f(1.0f, 1.0f, 0.0f);
    glRectf(-0.2f, -0.2f, 0.1f, 0.1f);
    glEndList();
    glCallList(more);
    glFinish();
    sgl_image(out, "b", W, H, 4, "RGBA", W * 4, 1, bb);

    /* C shares nothing */
    SGL_CHECK(OSMesaMakeCurrent(c, bc, GL_UNSIGNED_BYTE, W, H));
    other = glGenLists(1);
    sgl_text(out, "c_names", "isList tri=%d more=%d gen=%u\n", glIsList(tri), glIsList(more),
             other);
    glCallList(tri);
    glFinish();
    sgl_image(out, "c", W, H, 4, "RGBA", W * 4, 1, bc);

    /* B deletes the first list; A sees the rest, and the list B made */
    SGL_CHECK(OSMesaMakeCurrent(b, bb, GL_UNSIGNED_BYTE, W, H));
    glDeleteLists(tri, 1);
    SGL_CHECK(OSMesaMakeCurrent(a, ba, GL_UNSIGNED_BYTE, W, H));
    sgl_text(out, "a_names", "isList tri=%d both=%d more=%d\n", glIsList(tri), glIsList(both),
             glIsList(more));
    glLoadIdentity();
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glCallList(both); /* calls the deleted list: nothing from it */
    glCallList(more);
    glFinish();
    sgl_image(out, "a_after", W, H, 4, "RGBA", W * 4, 1, ba);

    sgl_close(out);
    OSMesaDestroyContext(c);
    OSMesaDestroyContext(b);
    OSMesaDestroyContext(a);
    free(ba);
    free(bb);
    free(bc);
    return 0;
}
