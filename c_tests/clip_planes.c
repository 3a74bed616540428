/* clip_planes: user clip planes (glClipPlane, GL_CLIP_PLANE0..7).  Two
 * planes cut a lit sphere in perspective (one given under a rotated
 * modelview, so it is moved to eye space at that moment and stays put when
 * the object moves); then points against a plane (points whose vertex is
 * outside vanish whole), all eight planes cutting a quad into an octagon,
 * and a flat-shaded fan (lines: clip_planes_lines.c).
 * glGetClipPlane values and the errors are dumped. */
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
    static const GLdouble p0[4] = {1.0, 0.3, 0.0, 0.2};
    static const GLdouble p1[4] = {-0.2, 1.0, 0.4, 0.35};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    GLdouble d[4];
    char text[2048];
    int n = 0, i;

    glEnable(GL_DEPTH_TEST);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);

    /* left half: a lit sphere cut by two planes */
    glViewport(0, 128, 128, 128);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.0f);
    glClipPlane(GL_CLIP_PLANE0, p0);
    glRotatef(35.0f, 0.0f, 0.0f, 1.0f);
    glClipPlane(GL_CLIP_PLANE1, p1);
    glEnable(GL_CLIP_PLANE0);
    glEnable(GL_CLIP_PLANE1);
    glRotatef(20.0f, 1.0f, 0.0f, 0.0f);
    sgl_sphere(1.0f, 24, 16);

    /* the same planes, the object moved */
    glViewport(128, 128, 128, 128);
    glLoadIdentity();
    glTranslatef(0.2f, -0.1f, -3.5f);
    glRotatef(60.0f, 0.3f, 1.0f, 0.0f);
    sgl_torus(0.9f, 0.35f, 24, 12);
    glDisable(GL_LIGHTING);

    /* points against a plane, ortho */
    glViewport(0, 0, 128, 128);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, 128.0, 0.0, 128.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glDisable(GL_CLIP_PLANE1);
    {
        static const GLdouble diag[4] = {1.0, -1.0, 0.0, 3.3};
        glClipPlane(GL_CLIP_PLANE0, diag);
    }
    glBegin(GL_POINTS);
    for (i = 0; i < 20; i++) {
        glColor3f(0.3f + i / 40.0f, 1.0f, 0.4f);
        glVertex2f(60.0f + 3.1f * i, 30.0f + 3.3f * i);
    }
    glEnd();
    /* all eight planes: an octagon out of a quad; a plane using w */
    glViewport(128, 0, 128, 128);
    glLoadIdentity();
    for (i = 0; i < 8; i++) {
        double a = i * 3.14159265358979 / 4.0 + 0.2;
        GLdouble pl[4];
        pl[0] = -cos(a), pl[1] = -sin(a), pl[2] = 0.0;
        pl[3] = 64.0 * cos(a) + 64.0 * sin(a) + 50.0;
        glClipPlane(GL_CLIP_PLANE0 + i, pl);
        glEnable(GL_CLIP_PLANE0 + i);
    }
    glBegin(GL_QUADS);
    glColor3f(1.0f, 0.0f, 0.0f);
    glVertex2f(4.0f, 4.0f);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex2f(124.0f, 4.0f);
    glColor3f(0.0f, 0.0f, 1.0f);
    glVertex2f(124.0f, 124.0f);
    glColor3f(1.0f, 1.0f, 0.0f);
    glVertex2f(4.0f, 124.0f);
    glEnd();
    for (i = 2; i < 8; i++)
        glDisable(GL_CLIP_PLANE0 + i);
    /* flat fan in the corner, cut by planes 0 and 1 */
    glShadeModel(GL_FLAT);
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(0.9f, 0.9f, 0.9f);
    glVertex2f(64.0f, 64.0f);
    for (i = 0; i < 7; i++) {
        glColor3f(i / 7.0f, 0.5f, 1.0f - i / 7.0f);
        glVertex2f(64.0f + 60.0f * (float)cos(i * 0.5), 64.0f + 60.0f * (float)sin(i * 0.5));
    }
    glEnd();
    glShadeModel(GL_SMOOTH);

    glFinish();
    SGL_CHECK(glGetError() == GL_NO_ERROR);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);

    glGetClipPlane(GL_CLIP_PLANE1, d);
    n += snprintf(text + n, sizeof text - n, "plane1 %.17g %.17g %.17g %.17g\n", d[0], d[1], d[2], d[3]);
    glGetClipPlane(GL_CLIP_PLANE0 + 7, d);
    n += snprintf(text + n, sizeof text - n, "plane7 %.17g %.17g %.17g %.17g\n", d[0], d[1], d[2], d[3]);
    n += snprintf(text + n, sizeof text - n, "enabled %d %d %d\n", glIsEnabled(GL_CLIP_PLANE0),
                  glIsEnabled(GL_CLIP_PLANE0 + 2), glIsEnabled(GL_CLIP_PLANE0 + 7));
    glClipPlane(GL_CLIP_PLANE0 + 8, p0);
    n += snprintf(text + n, sizeof text - n, "plane8 %x\n", glGetError());
    glGetClipPlane(GL_CLIP_PLANE0 - 1, d);
    n += snprintf(text + n, sizeof text - n, "get bad %x\n", glGetError());
    glEnable(GL_CLIP_PLANE0 + 8);
    n += snprintf(text + n, sizeof text - n, "enable 8 %x\n", glGetError());
    glBegin(GL_POINTS);
    glClipPlane(GL_CLIP_PLANE0, p0);
    glEnd();
    n += snprintf(text + n, sizeof text - n, "in begin %x\n", glGetError());
    sgl_text(out, "state", "%s", text);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
