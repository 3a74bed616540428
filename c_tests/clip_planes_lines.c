/* clip_planes_lines: lines against user clip planes: GL_LINES crossing a
 * diagonal plane (one end cut, colours interpolated to the new end), a line
 * strip in and out of two planes, and a line with both ends outside one
 * plane but crossing the other. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"
#include "texgen_common.h"

#define W 256
#define H 256

int main(int argc, char **argv)
{
    static const GLdouble diag[4] = {1.0, -1.0, 0.0, 3.3};
    static const GLdouble horiz[4] = {0.0, 1.0, 0.0, -10.5};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    int i;

    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, 128.0, 0.0, 128.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClipPlane(GL_CLIP_PLANE0, diag);
    glClipPlane(GL_CLIP_PLANE3, horiz);
    glEnable(GL_CLIP_PLANE0);
    glBegin(GL_LINES);
    for (i = 0; i < 16; i++) {
        glColor3f(1.0f, i / 16.0f, 0.2f);
        glVertex2f(2.5f + 7.0f * i, 4.0f);
        glColor3f(0.2f, 0.5f, 1.0f);
        glVertex2f(10.0f + 6.0f * i, 120.0f);
    }
    glEnd();
    glEnable(GL_CLIP_PLANE3);
    glBegin(GL_LINE_STRIP);
    glColor3f(1.0f, 1.0f, 1.0f);
    for (i = 0; i < 12; i++)
        glVertex2f(5.0f + 10.5f * i, 60.0f + ((i & 1) ? 25.0f : -20.0f));
    glEnd();

    glBegin(GL_LINES);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex2f(100.0f, 5.0f);
    glColor3f(1.0f, 0.0f, 1.0f);
    glVertex2f(126.0f, 40.0f);
    glEnd();

    glFinish();
    SGL_CHECK(glGetError() == GL_NO_ERROR);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
