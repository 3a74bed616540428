/* clip_control: GL_ARB_clip_control as MuJoCo uses it and beyond.
 *
 * - GL_ZERO_TO_ONE with MuJoCo's reversed Z (projection glTranslatef(0,0,.5),
 *   glScalef(1,1,-.5) before glFrustum; clear depth 0; GL_GEQUAL), a decal drawn
 *   with glPolygonOffset(-1.5,-4), and triangles crossing the near and far planes.
 * - GL_ZERO_TO_ONE with an ordinary frustum: the near plane moves to z_ndc = 0,
 *   so a triangle spanning z_ndc -0.8 .. 0.8 is cut in the middle.
 * - GL_UPPER_LEFT: the image is flipped, front faces swap (culling), and the
 *   horizontal-edge fill rule swaps (rectangles on exact pixel centres).
 * - glRasterPos under both modes (the raster position and a glBitmap).
 * - Feedback under GL_UPPER_LEFT + GL_ZERO_TO_ONE.
 * - Depth read back as GL_FLOAT and GL_UNSIGNED_INT, glGet of both states,
 *   errors, display lists and glPushAttrib(GL_TRANSFORM_BIT).
 * glClipControl is fetched through OSMesaGetProcAddress, as MuJoCo does (Mesa's
 * libOSMesa does not export it). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <string.h>
#include "common.h"

#define W 192
#define H 160

static PFNGLCLIPCONTROLPROC clip_control;

static void states(FILE *out, const char *name)
{
    GLint o = 0, d = 0;
    GLfloat f[2] = {0, 0};
    GLboolean b = 7;
    glGetIntegerv(GL_CLIP_ORIGIN, &o);
    glGetIntegerv(GL_CLIP_DEPTH_MODE, &d);
    glGetFloatv(GL_CLIP_ORIGIN, &f[0]);
    glGetFloatv(GL_CLIP_DEPTH_MODE, &f[1]);
    glGetBooleanv(GL_CLIP_DEPTH_MODE, &b);
    sgl_text(out, name, "origin 0x%x depth 0x%x float %g %g bool %d err 0x%x\n", o, d,
             f[0], f[1], b, glGetError());
}

static void tri(const float *a, const float *b, const float *c)
{
    glColor3f(1.0f, 0.2f, 0.1f);
    glVertex3fv(a);
    glColor3f(0.1f, 0.9f, 0.3f);
    glVertex3fv(b);
    glColor3f(0.2f, 0.3f, 1.0f);
    glVertex3fv(c);
}

/* MuJoCo's projection: reversed Z into [0, 1]. */
static void mujoco_projection(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, 0.5f);
    glScalef(1.0f, 1.0f, -0.5f);
    glFrustum(-0.6, 0.6, -0.5, 0.5, 1.0, 12.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void scene_reversed_z(void)
{
    static const float a[3] = {-3.0f, -2.5f, -4.0f}, b[3] = {3.1f, -1.7f, -9.0f},
                       c[3] = {0.3f, 3.3f, -2.2f};
    static const float d[3] = {-2.9f, 2.1f, -7.5f}, e[3] = {2.6f, 2.7f, -3.1f},
                       f[3] = {-0.4f, -3.4f, -5.3f};
    /* crosses the near plane (z = -1) and the far plane (z = -12) */
    static const float g[3] = {-0.7f, -0.2f, -0.4f}, h[3] = {0.9f, 0.1f, -0.5f},
                       k[3] = {0.1f, 1.9f, -15.0f};
    mujoco_projection();
    glClearDepth(0.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GEQUAL);
    glBegin(GL_TRIANGLES);
    tri(a, b, c);
    tri(d, e, f);
    tri(g, h, k);
    glEnd();
    /* a decal coplanar with the first triangle, pulled forward by the offset */
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.5f, -4.0f);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 1.0f, 0.0f);
    glVertex3f(-1.5f, -1.8f, -5.11111f);
    glVertex3f(1.0f, -1.3f, -7.1888f);
    glVertex3f(-0.2f, 0.4f, -4.4f);
    glEnd();
    /* the same decal without offset: loses GEQUAL ties only where depths differ */
    glDisable(GL_POLYGON_OFFSET_FILL);
    glBegin(GL_QUADS); /* a wall crossing the others */
    glColor4f(0.6f, 0.6f, 0.6f, 1.0f);
    glVertex3f(-4.0f, 0.5f, -2.0f);
    glColor4f(0.9f, 0.4f, 0.6f, 1.0f);
    glVertex3f(4.0f, 0.5f, -10.0f);
    glColor4f(0.2f, 0.8f, 0.8f, 1.0f);
    glVertex3f(4.0f, 1.2f, -10.0f);
    glColor4f(0.6f, 0.3f, 0.1f, 1.0f);
    glVertex3f(-4.0f, 1.2f, -2.0f);
    glEnd();
}

/* An ordinary frustum and depth test: with GL_ZERO_TO_ONE the near plane is z_ndc = 0. */
static void scene_cut(float x0)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 5.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(x0, 0.0f, 0.0f);
    glDepthFunc(GL_LESS);
    glBegin(GL_TRIANGLES);
    glColor3f(0.9f, 0.9f, 0.2f);
    glVertex3f(-0.5f, -0.8f, -1.1f); /* z_ndc about -0.86 */
    glColor3f(0.2f, 0.9f, 0.9f);
    glVertex3f(0.45f, -0.7f, -1.2f);
    glColor3f(0.9f, 0.2f, 0.9f);
    glVertex3f(0.1f, 3.0f, -4.5f); /* z_ndc about 0.97 */
    glEnd();
    glBegin(GL_LINES);
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex3f(-0.7f, 0.6f, -1.05f);
    glVertex3f(0.3f, -0.6f, -4.0f);
    glEnd();
    glPointSize(3.0f);
    glBegin(GL_POINTS);
    glColor3f(1.0f, 0.5f, 0.0f);
    glVertex3f(-0.3f, -0.2f, -1.2f); /* culled by the half-z near plane */
    glVertex3f(0.3f, 0.2f, -3.0f);
    glEnd();
}

/* Exact pixel rectangles and both windings, with back faces culled. */
static void scene_upper_left(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, 128.0, 0.0, 128.0, -1.0, 1.0); /* exact window coordinates */
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glViewport(0, 0, 128, 128);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glBegin(GL_TRIANGLES);
    /* counter-clockwise in GL's y-up coordinates */
    glColor3f(0.9f, 0.1f, 0.1f);
    glVertex2f(4.5f, 4.5f);
    glVertex2f(20.5f, 4.5f);
    glVertex2f(4.5f, 20.5f);
    /* clockwise */
    glColor3f(0.1f, 0.9f, 0.1f);
    glVertex2f(24.5f, 4.5f);
    glVertex2f(24.5f, 20.5f);
    glVertex2f(40.5f, 4.5f);
    glEnd();
    glDisable(GL_CULL_FACE);
    /* rectangles whose edges lie on pixel centres: the fill rule decides */
    glBegin(GL_QUADS);
    glColor3f(0.2f, 0.4f, 0.9f);
    glVertex2f(44.5f, 4.5f);
    glVertex2f(52.5f, 4.5f);
    glVertex2f(52.5f, 12.5f);
    glVertex2f(44.5f, 12.5f);
    glColor3f(0.9f, 0.4f, 0.9f);
    glVertex2f(52.5f, 12.5f);
    glVertex2f(60.5f, 12.5f);
    glVertex2f(60.5f, 20.5f);
    glVertex2f(52.5f, 20.5f);
    glEnd();
    glBegin(GL_TRIANGLES); /* a triangle with a horizontal edge on its top */
    glColor3f(0.9f, 0.9f, 0.9f);
    glVertex2f(64.5f, 20.5f);
    glVertex2f(70.0f, 3.5f);
    glVertex2f(76.5f, 20.5f);
    glEnd();
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    glFrontFace(GL_CW);
    glBegin(GL_TRIANGLES); /* clockwise: front under GL_CW, culled */
    glColor3f(0.5f, 0.5f, 0.1f);
    glVertex2f(80.5f, 4.5f);
    glVertex2f(80.5f, 20.5f);
    glVertex2f(96.5f, 4.5f);
    glColor3f(0.1f, 0.5f, 0.5f); /* counter-clockwise: kept */
    glVertex2f(100.5f, 4.5f);
    glVertex2f(116.5f, 4.5f);
    glVertex2f(100.5f, 20.5f);
    glEnd();
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    glDisable(GL_CULL_FACE);
}

static void raster_positions(FILE *out, const char *name)
{
    static const GLubyte bits[8] = {0xff, 0x81, 0xbd, 0xa5, 0xa5, 0xbd, 0x81, 0xff};
    GLfloat p[4];
    GLboolean valid;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 5.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRasterPos3f(0.3f, 0.25f, -2.0f);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, p);
    glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    sgl_text(out, name, "raster %.9g %.9g %.9g %.9g valid %d\n", p[0], p[1], p[2], p[3], valid);
    glColor3f(1.0f, 1.0f, 0.0f);
    glBitmap(8, 8, 0.0f, 0.0f, 0.0f, 0.0f, bits);
    /* z_ndc about -0.67: inside in either depth mode for glRasterPos (Mesa tests -w) */
    glRasterPos3f(0.1f, -0.1f, -1.1f);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, p);
    glGetBooleanv(GL_CURRENT_RASTER_POSITION_VALID, &valid);
    sgl_text(out, name, "near %.9g %.9g %.9g %.9g valid %d\n", p[0], p[1], p[2], p[3], valid);
    glWindowPos3f(10.0f, 20.0f, 0.25f);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, p);
    sgl_text(out, name, "window %.9g %.9g %.9g\n", p[0], p[1], p[2]);
}

static void feedback(FILE *out)
{
    GLfloat fb[256];
    GLint n, i;
    glFeedbackBuffer(256, GL_3D, fb);
    glRenderMode(GL_FEEDBACK);
    scene_cut(0.0f);
    n = glRenderMode(GL_RENDER);
    sgl_text(out, "feedback_n", "%d\n", n);
    for (i = 0; i < n && i < 256; i++)
        sgl_text(out, "feedback", "%.9g\n", fb[i]);
}

static void read_depth(FILE *out, const char *name, int x, int y)
{
    static GLfloat zf[24 * 20];
    static GLuint zu[24 * 20];
    glReadPixels(x, y, 24, 20, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
    glReadPixels(x, y, 24, 20, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, zu);
    sgl_data(out, name, sizeof zf, zf);
    sgl_data(out, name, sizeof zu, zu);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf;
    const char *ext;
    GLuint list;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    ext = (const char *)glGetString(GL_EXTENSIONS);
    SGL_CHECK(ext != NULL && strstr(ext, "GL_ARB_clip_control") != NULL);
    clip_control = (PFNGLCLIPCONTROLPROC)OSMesaGetProcAddress("glClipControl");
    SGL_CHECK(clip_control != NULL);

    states(out, "initial");
    clip_control(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
    states(out, "set");
    clip_control(GL_LOWER_LEFT, GL_CCW); /* bad depth */
    states(out, "bad_depth");
    clip_control(GL_CCW, GL_ZERO_TO_ONE); /* bad origin */
    states(out, "bad_origin");
    clip_control(GL_UPPER_LEFT, GL_ZERO_TO_ONE); /* no change */
    states(out, "same");
    clip_control(GL_CCW, GL_CW); /* both bad */
    states(out, "both_bad");
    glBegin(GL_TRIANGLES);
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE); /* inside glBegin/glEnd */
    glEnd();
    states(out, "in_begin");
    glPushAttrib(GL_TRANSFORM_BIT);
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    states(out, "pushed");
    glPopAttrib();
    states(out, "popped");
    glPushAttrib(GL_ENABLE_BIT | GL_VIEWPORT_BIT);
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glPopAttrib();
    states(out, "other_bits");
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    clip_control(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
    clip_control(GL_LOWER_LEFT, 0x1234);
    glEndList();
    states(out, "compiled");
    glCallList(list);
    states(out, "called");

    /* 1. MuJoCo's reversed Z in the top half, then the half-z cut on the right */
    clip_control(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glViewport(0, H / 2, W, H / 2);
    scene_reversed_z();
    read_depth(out, "depth_reversed", 80, 110);
    glViewport(W / 2, 0, W / 2, H / 2);
    glClearDepth(1.0);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, W, H / 2);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    scene_cut(0.0f);
    /* the same with the default depth mode on the left */
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glViewport(0, 0, W / 2, H / 2);
    scene_cut(0.0f);
    glFinish();
    sgl_image(out, "lower_left", W, H, 4, "RGBA", W * 4, 1, buf);
    read_depth(out, "depth_cut", 130, 20);
    read_depth(out, "depth_cut_default", 34, 20);

    /* 2. GL_UPPER_LEFT: culling, fill rule, and the scenes again with half-z */
    glViewport(0, 0, W, H);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    clip_control(GL_UPPER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    scene_upper_left();
    glEnable(GL_DEPTH_TEST);
    clip_control(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
    glViewport(W / 2, H / 2, W / 2, H / 2);
    scene_cut(0.1f);
    glViewport(0, 0, W, H);
    raster_positions(out, "raster_upper_half");
    clip_control(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    raster_positions(out, "raster_lower_half");
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    raster_positions(out, "raster_default");
    glFinish();
    sgl_image(out, "upper_left", W, H, 4, "RGBA", W * 4, 1, buf);
    read_depth(out, "depth_upper", 130, 110);

    /* 3. feedback */
    clip_control(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
    glViewport(3, 5, 150, 120);
    glDepthRange(0.2, 0.9);
    feedback(out);
    glDepthRange(0.0, 1.0);
    sgl_text(out, "errors", "0x%x\n", glGetError());

    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
