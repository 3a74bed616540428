/* point_params: glPointParameter (GL 1.4, ARB_point_parameters).  Points under a
 * perspective projection at several depths with three distance attenuations;
 * GL_POINT_SIZE_MIN/MAX clamping with and without attenuation; the fade threshold
 * with blending on and off; attenuated points with lighting, fog, GL_POINT polygons
 * (one triangle clipped), vertex arrays and display lists; the queries, the
 * GL_POINT_BIT attribute group and the errors. */
#define GL_GLEXT_PROTOTYPES
#include "prims_common.h"
#include <GL/glext.h>

/* One row of points at eye distances 1.5 .. 1.5 + 3.1 * 15, spread across the
 * window at height ndc_y (the projection is glFrustum(-1, 1, -1, 1, 1, 100)). */
static void row(float ndc_y, int colour)
{
    int i;
    glBegin(GL_POINTS);
    for (i = 0; i < 16; i++) {
        float d = 1.5f + 3.1f * (float)i;
        float x = -0.92f + 0.122f * (float)i;
        prims_color(colour + i);
        glVertex3f(x * d, ndc_y * d, -d);
    }
    glEnd();
}

static void perspective(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 100.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void text_state(FILE *out, const char *name)
{
    GLfloat mn, mx, th, da[3], sz;
    glGetFloatv(GL_POINT_SIZE_MIN, &mn);
    glGetFloatv(GL_POINT_SIZE_MAX, &mx);
    glGetFloatv(GL_POINT_FADE_THRESHOLD_SIZE, &th);
    glGetFloatv(GL_POINT_DISTANCE_ATTENUATION, da);
    glGetFloatv(GL_POINT_SIZE, &sz);
    sgl_text(out, name, "size %g min %g max %g fade %g atten %g %g %g err 0x%x\n", sz, mn, mx,
             th, da[0], da[1], da[2], glGetError());
}

int main(int argc, char **argv)
{
    static const GLfloat quad_atten[3] = {0.0f, 0.0f, 1.0f};
    static const GLfloat mixed_atten[3] = {1.0f, 0.2f, 0.01f};
    static const GLfloat lin_atten[3] = {0.25f, 0.5f, 0.0f};
    static const GLfloat none[3] = {1.0f, 0.0f, 0.0f};
    static const GLint int_atten[3] = {0, 1, 0};
    static GLfloat pts[24 * 3];
    FILE *out = sgl_open(argc, argv);
    GLint ierr[8];
    GLfloat v[4];
    GLuint list;
    int i;

    prims_begin();
    text_state(out, "defaults");
    perspective();

    /* attenuation: size/d, a mixed polynomial, a linear one with size clamps */
    glPointSize(40.0f);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, quad_atten);
    row(0.8f, 0);
    glPointSize(20.0f);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, mixed_atten);
    row(0.5f, 16);
    glPointSize(30.0f);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, lin_atten);
    glPointParameterf(GL_POINT_SIZE_MIN, 2.5f);
    glPointParameterf(GL_POINT_SIZE_MAX, 9.0f);
    row(0.2f, 32);
    /* the same clamps without attenuation: a size above, inside and below */
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);
    glPointSize(14.0f);
    row(-0.1f, 48);
    glPointSize(1.0f);
    row(-0.35f, 64);
    /* an inverted range (min > max): Mesa's CLAMP tests the minimum first */
    glPointParameterf(GL_POINT_SIZE_MIN, 6.0f);
    glPointParameterf(GL_POINT_SIZE_MAX, 3.0f);
    glPointSize(4.0f);
    row(-0.6f, 80);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, quad_atten);
    glPointSize(60.0f);
    row(-0.85f, 96);
    prims_end(out, "attenuation");
    text_state(out, "after_rows");

    /* fade threshold: thin attenuated points, opaque and blended */
    glClear(GL_COLOR_BUFFER_BIT);
    glPointParameterf(GL_POINT_SIZE_MIN, 0.0f);
    glPointParameterf(GL_POINT_SIZE_MAX, 64.0f);
    glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 6.0f);
    glPointSize(24.0f);
    row(0.6f, 3);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    row(0.1f, 3);
    glColor4f(0.9f, 0.8f, 0.2f, 0.5f);
    glBegin(GL_POINTS);
    for (i = 0; i < 12; i++)
        glVertex3f(-0.8f * (2.0f + 4.0f * i) + 0.13f * (2.0f + 4.0f * i) * i,
                   -0.4f * (2.0f + 4.0f * i), -(2.0f + 4.0f * i));
    glEnd();
    glDisable(GL_BLEND);
    glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 0.0f);
    row(-0.8f, 3);
    prims_end(out, "fade");

    /* lighting (attenuation moves it into eye space), fog and vertex arrays */
    glClear(GL_COLOR_BUFFER_BIT);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, mixed_atten);
    glPointSize(26.0f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    v[0] = 0.3f; v[1] = 0.5f; v[2] = 1.0f; v[3] = 0.0f;
    glLightfv(GL_LIGHT0, GL_POSITION, v);
    glEnable(GL_COLOR_MATERIAL);
    glNormal3f(0.2f, 0.3f, 0.93f);
    glRotatef(7.0f, 0.0f, 0.0f, 1.0f);
    row(0.7f, 5);
    glDisable(GL_LIGHTING);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_EXP);
    glFogf(GL_FOG_DENSITY, 0.05f);
    row(0.3f, 9);
    glDisable(GL_FOG);
    for (i = 0; i < 24; i++) {
        float d = 2.0f + 1.7f * (float)i;
        pts[3 * i] = (-0.9f + 0.075f * (float)i) * d;
        pts[3 * i + 1] = -0.1f * d;
        pts[3 * i + 2] = -d;
    }
    glVertexPointer(3, GL_FLOAT, 0, pts);
    glEnableClientState(GL_VERTEX_ARRAY);
    glColor3f(0.2f, 0.9f, 0.6f);
    glDrawArrays(GL_POINTS, 0, 24);
    glTranslatef(0.0f, -0.35f * 6.0f, 0.0f);
    glDrawArrays(GL_POINTS, 3, 18);
    glDisableClientState(GL_VERTEX_ARRAY);
    glLoadIdentity();
    /* GL_POINT polygons: per-vertex sizes through the unfilled stage, one clipped */
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, quad_atten);
    glPointSize(30.0f);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.4f, 0.2f);
    glVertex3f(-1.5f, -1.6f, -2.0f);
    glVertex3f(-0.2f, -2.5f, -3.0f);
    glVertex3f(-0.8f, -1.2f, -6.0f);
    glColor3f(0.4f, 0.4f, 1.0f);
    glVertex3f(-3.2f, -4.0f, -5.0f);
    glVertex3f(0.5f, -5.5f, -7.0f);
    glVertex3f(-7.0f, -9.0f, -10.0f);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    prims_end(out, "combined");

    /* display lists: the parameters are compiled; glPointParameteriv keeps one value */
    glClear(GL_COLOR_BUFFER_BIT);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, none);
    glPointParameterf(GL_POINT_SIZE_MAX, 11.0f);
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, lin_atten);
    glPointSize(18.0f);
    row(0.5f, 11);
    glPointParameteriv(GL_POINT_DISTANCE_ATTENUATION, int_atten);
    glPointParameteri(GL_POINT_SIZE_MIN, 2);
    row(0.0f, 11);
    glEndList();
    text_state(out, "after_compile");
    glCallList(list);
    text_state(out, "after_call");
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, quad_atten);
    glPointParameteriv(GL_POINT_DISTANCE_ATTENUATION, int_atten);
    text_state(out, "iv_immediate");
    glPointParameterf(GL_POINT_DISTANCE_ATTENUATION, 0.5f);
    text_state(out, "f_attenuation");
    row(-0.5f, 21);
    prims_end(out, "lists");

    /* GL_POINT_BIT and errors */
    glPushAttrib(GL_POINT_BIT);
    glPointParameterf(GL_POINT_SIZE_MIN, 5.0f);
    glPointParameterf(GL_POINT_FADE_THRESHOLD_SIZE, 3.0f);
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, mixed_atten);
    text_state(out, "pushed");
    glPopAttrib();
    text_state(out, "popped");
    glPointParameterf(GL_POINT_SIZE_MIN, -1.0f);
    ierr[0] = glGetError();
    glPointParameterf(GL_POINT_SIZE_MAX, -0.5f);
    ierr[1] = glGetError();
    glPointParameteri(GL_POINT_FADE_THRESHOLD_SIZE, -2);
    ierr[2] = glGetError();
    glPointParameterf(GL_POINT_SIZE, 2.0f);
    ierr[3] = glGetError();
    glPointParameterf(GL_DISTANCE_ATTENUATION_EXT + 100, 2.0f);
    ierr[4] = glGetError();
    v[0] = -3.0f; v[1] = -1.0f; v[2] = 0.5f;
    glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION_ARB, v);
    ierr[5] = glGetError();
    glBegin(GL_POINTS);
    glPointParameterf(GL_POINT_SIZE_MIN, 1.0f);
    glEnd();
    ierr[6] = glGetError();
    glPointParameterfEXT(GL_POINT_SIZE_MAX_EXT, 7.0f);
    glPointParameterfARB(GL_POINT_FADE_THRESHOLD_SIZE_ARB, 0.25f);
    ierr[7] = glGetError();
    sgl_text(out, "errors", "%x %x %x %x %x %x %x %x\n", ierr[0], ierr[1], ierr[2], ierr[3],
             ierr[4], ierr[5], ierr[6], ierr[7]);
    text_state(out, "final");
    prims_close(out);
    return 0;
}
