/*
 * Tutorial 11: the tessellator on touching and overlapping contours. Each panel is
 * one polygon: two squares sharing an edge, a square with a hole touching its
 * outline at a vertex, contours meeting at T-junctions, collinear overlapping edges,
 * a contour that doubles back on itself (zero area), repeated vertices, and a bow
 * tie crossing at an existing vertex. Frames 0-4 fill them under the five winding
 * rules, 5-9 draw the boundary-only loops, 10-14 the edge-flagged triangles as lines.
 */
#include <GL/glut.h>
#include <GL/glu.h>
#include <stdlib.h>

static GLUtesselator *tess;
static int frame = 0;
static GLdouble pool[1024][3];
static int npool = 0;

static void combine(GLdouble c[3], void *d[4], GLfloat w[4], void **out)
{
    GLdouble *v = pool[npool++ % 1024];
    (void)d;
    (void)w;
    v[0] = c[0];
    v[1] = c[1];
    v[2] = c[2];
    *out = v;
}

static void edge(GLboolean flag)
{
    glEdgeFlag(flag);
}

/* A contour from (x, y) pairs, offset to a panel. */
static void contour(const double *xy, int n, double ox, double oy)
{
    int i;
    gluTessBeginContour(tess);
    for (i = 0; i < n; i++) {
        GLdouble *v = pool[npool++ % 1024];
        v[0] = ox + xy[2 * i];
        v[1] = oy + xy[2 * i + 1];
        v[2] = 0.0;
        gluTessVertex(tess, v, v);
    }
    gluTessEndContour(tess);
}

static const double sq_a[] = { 0, 0, 30, 0, 30, 40, 0, 40 };
static const double sq_b[] = { 30, 0, 60, 0, 60, 40, 30, 40 };
static const double outer[] = { 0, 0, 60, 0, 60, 60, 0, 60 };
static const double touching_hole[] = { 0, 0, 20, 40, 40, 20 };
static const double t_outer[] = { 0, 0, 60, 0, 60, 30, 0, 30 };
static const double t_inner[] = { 30, 30, 45, 55, 15, 55 };
static const double long_bar[] = { 0, 10, 60, 10, 60, 20, 0, 20 };
static const double short_bar[] = { 15, 10, 45, 10, 45, 35, 15, 35 };
static const double doubled[] = { 0, 0, 50, 10, 0, 0, 10, 50 };
static const double repeated[] = { 0, 0, 0, 0, 55, 5, 55, 5, 55, 5, 30, 50, 0, 0 };
static const double bowtie[] = { 0, 0, 30, 25, 60, 0, 60, 50, 30, 25, 0, 50 };
static const double fan_a[] = { 30, 30, 60, 10, 60, 50 };
static const double fan_b[] = { 30, 30, 0, 50, 0, 10 };
static const double fan_c[] = { 30, 30, 10, 0, 50, 0 };

static void display(void)
{
    static const GLenum rules[5] = {
        GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO, GLU_TESS_WINDING_POSITIVE,
        GLU_TESS_WINDING_NEGATIVE, GLU_TESS_WINDING_ABS_GEQ_TWO
    };
    npool = 0;
    glClear(GL_COLOR_BUFFER_BIT);
    gluTessProperty(tess, GLU_TESS_WINDING_RULE, rules[frame % 5]);
    gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, frame >= 5 && frame < 10);
    gluTessCallback(tess, GLU_TESS_EDGE_FLAG, frame >= 10 ? (_GLUfuncptr)edge : NULL);
    glPolygonMode(GL_FRONT_AND_BACK, frame >= 10 ? GL_LINE : GL_FILL);

    glColor3f(1.0f, 0.6f, 0.3f);
    gluTessBeginPolygon(tess, NULL);
    contour(sq_a, 4, 10.5, 10.5);
    contour(sq_b, 4, 10.5, 10.5);
    gluTessEndPolygon(tess);

    glColor3f(0.4f, 0.9f, 0.4f);
    gluTessBeginPolygon(tess, NULL);
    contour(outer, 4, 85.5, 5.5);
    contour(touching_hole, 3, 85.5, 5.5);
    gluTessEndPolygon(tess);

    glColor3f(0.5f, 0.6f, 1.0f);
    gluTessBeginPolygon(tess, NULL);
    contour(t_outer, 4, 165.5, 5.5);
    contour(t_inner, 3, 165.5, 5.5);
    gluTessEndPolygon(tess);

    glColor3f(0.9f, 0.4f, 0.9f);
    gluTessBeginPolygon(tess, NULL);
    contour(long_bar, 4, 245.5, 10.5);
    contour(short_bar, 4, 245.5, 10.5);
    gluTessEndPolygon(tess);

    glColor3f(0.9f, 0.9f, 0.3f);
    gluTessBeginPolygon(tess, NULL);
    contour(doubled, 4, 10.5, 90.5);
    gluTessEndPolygon(tess);

    glColor3f(0.3f, 0.9f, 0.9f);
    gluTessBeginPolygon(tess, NULL);
    contour(repeated, 7, 85.5, 90.5);
    gluTessEndPolygon(tess);

    glColor3f(1.0f, 0.4f, 0.4f);
    gluTessBeginPolygon(tess, NULL);
    contour(bowtie, 6, 165.5, 90.5);
    gluTessEndPolygon(tess);

    glColor3f(0.7f, 0.7f, 0.7f);
    gluTessBeginPolygon(tess, NULL);
    contour(fan_a, 3, 245.5, 90.5);
    contour(fan_b, 3, 245.5, 90.5);
    contour(fan_c, 3, 245.5, 90.5);
    contour(outer, 4, 245.5, 90.5);
    gluTessEndPolygon(tess);

    frame++;
    glutSwapBuffers();
}

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 320, 0, 160, -1, 1);
    glMatrixMode(GL_MODELVIEW);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(320, 160);
    glutCreateWindow("tessdegen");
    glShadeModel(GL_FLAT);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    tess = gluNewTess();
    gluTessCallback(tess, GLU_TESS_BEGIN, (_GLUfuncptr)glBegin);
    gluTessCallback(tess, GLU_TESS_VERTEX, (_GLUfuncptr)glVertex3dv);
    gluTessCallback(tess, GLU_TESS_END, (_GLUfuncptr)glEnd);
    gluTessCallback(tess, GLU_TESS_COMBINE, (_GLUfuncptr)combine);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutMainLoop();
    return 0;
}
