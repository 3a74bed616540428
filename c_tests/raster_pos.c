/* raster_pos: glRasterPos and glWindowPos state.  The raster position goes
 * through the modelview, projection, viewport and depth range; it becomes
 * invalid when the point is outside the view volume (x, y, near, far) or
 * behind a user clip plane; the raster colour, secondary colour, texture
 * coordinates (through texgen and the texture matrix) and distance are
 * latched; glWindowPos sets window coordinates directly, clamping colours
 * and mapping z into the depth range.  Also glPixelZoom state and errors. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 64
#define H 64

static char text[8192];
static int n;

static void dump(const char *what)
{
    GLfloat p[4], c[4], t[4], d;
    GLboolean valid;
    glGetFloatv(GL_CURRENT_RASTER_POSITION, p);
    glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    glGetFloatv(GL_CURRENT_RASTER_COLOR, c);
    glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, t);
    glGetFloatv(GL_CURRENT_RASTER_DISTANCE, &d);
    n += snprintf(text + n, sizeof text - n,
                  "%s: valid %d pos %.9g %.9g %.9g %.9g col %.9g %.9g %.9g %.9g tc %.9g %.9g %.9g %.9g d %.9g err %x\n",
                  what, valid, p[0], p[1], p[2], p[3], c[0], c[1], c[2], c[3], t[0], t[1], t[2], t[3], d,
                  glGetError());
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    static const GLdouble plane[4] = {1.0, 0.0, 0.0, -0.25};
    static const GLfloat fv[3] = {0.3f, -0.2f, -2.0f};
    static const GLdouble dv[4] = {0.1, 0.2, -1.5, 1.0};
    static const GLint iv[2] = {7, 9};
    static const GLshort sv[3] = {3, 4, 1};
    GLint vi[4];

    dump("initial");
    glColor4f(0.2f, 1.5f, -0.25f, 0.5f);
    glTexCoord4f(0.5f, 0.25f, 0.0f, 2.0f);
    glRasterPos2f(0.3f, -0.4f);
    dump("ortho identity");
    glMatrixMode(GL_PROJECTION);
    glFrustum(-0.6, 0.5, -0.4, 0.45, 1.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.1f, -0.2f, -0.5f);
    glRotatef(30.0f, 0.2f, 1.0f, 0.1f);
    glRasterPos3fv(fv);
    dump("perspective");
    glRasterPos4dv(dv);
    dump("4dv");
    glRasterPos3f(0.0f, 0.0f, 1.0f);
    dump("behind near");
    glRasterPos3f(30.0f, 0.0f, -3.0f);
    dump("outside x");
    glRasterPos3f(0.0f, 0.0f, -40.0f);
    dump("beyond far");
    glViewport(5, 7, 40, 30);
    glDepthRange(0.2, 0.7);
    glRasterPos3f(0.3f, 0.1f, -2.0f);
    dump("viewport depthrange");
    glClipPlane(GL_CLIP_PLANE2, plane);
    glEnable(GL_CLIP_PLANE2);
    glRasterPos3f(0.3f, 0.1f, -2.0f);
    dump("user plane keeps");
    glRasterPos3f(0.0f, 0.1f, -2.0f);
    dump("user plane clips");
    glDisable(GL_CLIP_PLANE2);
    glMatrixMode(GL_TEXTURE);
    glTranslatef(0.5f, 0.0f, 0.0f);
    glScalef(2.0f, 3.0f, 1.0f);
    glMatrixMode(GL_MODELVIEW);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glEnable(GL_TEXTURE_GEN_S);
    glRasterPos3f(0.25f, 0.1f, -2.0f);
    dump("texgen texmat");
    glDisable(GL_TEXTURE_GEN_S);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glFogCoordf(3.5f);
    glRasterPos3f(0.25f, 0.1f, -2.0f);
    dump("fog coord distance");
    glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);

    glWindowPos2i(10, 20);
    dump("window 2i");
    glWindowPos3f(1.5f, 2.25f, 0.5f);
    dump("window 3f");
    glWindowPos3fARB(1.0f, 2.0f, 1.5f);
    dump("window ARB z clamp");
    glWindowPos2iv(iv);
    dump("window 2iv");
    glWindowPos3sv(sv);
    dump("window 3sv");
    glWindowPos2d(-5.0, 80.0);
    dump("window off screen stays valid");
    /* (clamped colours only: Mesa's FLOAT_TO_INT of 1.5 overflows) */
    glGetIntegerv(GL_CURRENT_RASTER_COLOR, vi);
    n += snprintf(text + n, sizeof text - n, "int col %d %d %d %d\n", vi[0], vi[1], vi[2], vi[3]);
    glRasterPos2s(1, 1);
    glRasterPos2i(1, 1);
    glRasterPos2d(0.5, 0.5);
    glRasterPos3i(0, 0, -2);
    glRasterPos4f(0.0f, 0.0f, -2.0f, 1.0f);
    dump("misc");
    glGetIntegerv(GL_CURRENT_RASTER_POSITION, vi);
    n += snprintf(text + n, sizeof text - n, "int pos %d %d %d %d\n", vi[0], vi[1], vi[2], vi[3]);

    glPixelZoom(2.5f, -1.0f);
    {
        GLfloat z[2];
        glGetFloatv(GL_ZOOM_X, &z[0]);
        glGetFloatv(GL_ZOOM_Y, &z[1]);
        n += snprintf(text + n, sizeof text - n, "zoom %g %g\n", z[0], z[1]);
    }
    glBegin(GL_POINTS);
    glRasterPos2f(0.0f, 0.0f);
    glEnd();
    n += snprintf(text + n, sizeof text - n, "rasterpos in begin %x\n", glGetError());
    glBegin(GL_POINTS);
    glWindowPos2f(0.0f, 0.0f);
    glEnd();
    n += snprintf(text + n, sizeof text - n, "windowpos in begin %x\n", glGetError());
    glBegin(GL_POINTS);
    glPixelZoom(1.0f, 1.0f);
    glEnd();
    n += snprintf(text + n, sizeof text - n, "zoom in begin %x\n", glGetError());
    sgl_text(out, "state", "%s", text);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
