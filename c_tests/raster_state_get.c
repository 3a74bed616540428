/* raster_state_get: glGet/glIsEnabled of line, point and polygon state
 * (defaults, ranges and granularity, values after setting them, clamping of
 * the stipple factor, unclamped width/size) and the errors: glLineWidth(<=0)
 * and glPointSize(<=0) INVALID_VALUE, bad glPolygonMode enums INVALID_ENUM,
 * calls inside glBegin/glEnd INVALID_OPERATION, with no state change. */
#include "prims_common.h"

static char txt[8192];
static int n;

static void show(const char *name, GLenum e)
{
    GLfloat f[4] = {-7, -7, -7, -7};
    GLint iv[4] = {-7, -7, -7, -7};
    GLboolean b[4] = {9, 9, 9, 9};
    glGetFloatv(e, f);
    glGetIntegerv(e, iv);
    glGetBooleanv(e, b);
    n += snprintf(txt + n, sizeof txt - (size_t)n, "%s %g %g | %d %d | %d %d\n", name,
                  f[0], f[1], iv[0], iv[1], b[0], b[1]);
}

static void all(void)
{
    show("LINE_WIDTH", GL_LINE_WIDTH);
    show("LINE_WIDTH_RANGE", GL_LINE_WIDTH_RANGE);
    show("LINE_WIDTH_GRANULARITY", GL_LINE_WIDTH_GRANULARITY);
    show("ALIASED_LINE_WIDTH_RANGE", GL_ALIASED_LINE_WIDTH_RANGE);
    show("SMOOTH_LINE_WIDTH_RANGE", GL_SMOOTH_LINE_WIDTH_RANGE);
    show("POINT_SIZE", GL_POINT_SIZE);
    show("POINT_SIZE_RANGE", GL_POINT_SIZE_RANGE);
    show("POINT_SIZE_GRANULARITY", GL_POINT_SIZE_GRANULARITY);
    show("ALIASED_POINT_SIZE_RANGE", GL_ALIASED_POINT_SIZE_RANGE);
    show("LINE_STIPPLE_PATTERN", GL_LINE_STIPPLE_PATTERN);
    show("LINE_STIPPLE_REPEAT", GL_LINE_STIPPLE_REPEAT);
    show("POLYGON_MODE", GL_POLYGON_MODE);
    show("POLYGON_OFFSET_FACTOR", GL_POLYGON_OFFSET_FACTOR);
    show("POLYGON_OFFSET_UNITS", GL_POLYGON_OFFSET_UNITS);
    show("EDGE_FLAG", GL_EDGE_FLAG);
    show("LINE_STIPPLE", GL_LINE_STIPPLE);
    show("LINE_SMOOTH", GL_LINE_SMOOTH);
    show("POINT_SMOOTH", GL_POINT_SMOOTH);
    show("POLYGON_STIPPLE", GL_POLYGON_STIPPLE);
    show("POLYGON_OFFSET_FILL", GL_POLYGON_OFFSET_FILL);
    show("POLYGON_OFFSET_LINE", GL_POLYGON_OFFSET_LINE);
    show("POLYGON_OFFSET_POINT", GL_POLYGON_OFFSET_POINT);
    n += snprintf(txt + n, sizeof txt - (size_t)n, "enabled %d %d %d %d %d %d %d err 0x%x\n",
                  glIsEnabled(GL_LINE_STIPPLE), glIsEnabled(GL_LINE_SMOOTH),
                  glIsEnabled(GL_POINT_SMOOTH), glIsEnabled(GL_POLYGON_STIPPLE),
                  glIsEnabled(GL_POLYGON_OFFSET_FILL), glIsEnabled(GL_POLYGON_OFFSET_LINE),
                  glIsEnabled(GL_POLYGON_OFFSET_POINT), glGetError());
}

static void err(const char *what)
{
    n += snprintf(txt + n, sizeof txt - (size_t)n, "%s -> 0x%x\n", what, glGetError());
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    prims_begin();
    all();
    glLineWidth(3.6f);
    glPointSize(300.0f);
    glLineStipple(0, 0xA5A5);
    glPolygonMode(GL_FRONT, GL_LINE);
    glPolygonMode(GL_BACK, GL_POINT);
    glPolygonOffset(1.25f, -2.5f);
    glEdgeFlag(GL_FALSE);
    glEnable(GL_LINE_STIPPLE);
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_POINT_SMOOTH);
    glEnable(GL_POLYGON_STIPPLE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glEnable(GL_POLYGON_OFFSET_LINE);
    glEnable(GL_POLYGON_OFFSET_POINT);
    all();
    glLineStipple(1000, 0x1234);
    show("LINE_STIPPLE_REPEAT(1000)", GL_LINE_STIPPLE_REPEAT);
    glLineWidth(300.0f);
    show("LINE_WIDTH(300)", GL_LINE_WIDTH);
    glLineWidth(0.0f); err("glLineWidth(0)");
    glLineWidth(-1.0f); err("glLineWidth(-1)");
    glPointSize(0.0f); err("glPointSize(0)");
    glPointSize(-2.0f); err("glPointSize(-2)");
    glPolygonMode(GL_FRONT_AND_BACK, GL_TRIANGLES); err("glPolygonMode(bad mode)");
    glPolygonMode(GL_LEFT, GL_LINE); err("glPolygonMode(bad face)");
    glBegin(GL_TRIANGLES);
    glLineWidth(5.0f);
    glEnd();
    err("glLineWidth in glBegin");
    glBegin(GL_TRIANGLES);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glEnd();
    err("glPolygonMode in glBegin");
    glBegin(GL_TRIANGLES);
    glPolygonOffset(9.0f, 9.0f);
    glEnd();
    err("glPolygonOffset in glBegin");
    glBegin(GL_TRIANGLES);
    glEdgeFlag(GL_TRUE);
    glEnd();
    err("glEdgeFlag in glBegin");
    all();
    sgl_text(out, "state", "%s", txt);
    prims_close(out);
    return 0;
}
