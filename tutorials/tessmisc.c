/*
 * Tutorial 8: the rest of the tessellator's interface. The polygon data given to
 * gluTessBeginPolygon reaches the _DATA callbacks (here: the colour to draw with);
 * the GLU 1.0 calls gluBeginPolygon / gluNextContour / gluEndPolygon draw a polygon
 * with a hole; edge flags come through GLU_TESS_EDGE_FLAG_DATA; begin/end sequence
 * mistakes, bad properties and a self-intersecting polygon without a combine
 * callback are reported through GLU_TESS_ERROR_DATA. The errors and property values
 * are printed on stdout, and so are the combine calls for contours sharing vertices
 * and edges, repeating vertices and crossing. Key 'e' toggles drawing the triangles'
 * flagged edges only.
 */
#include <GL/glut.h>
#include <GL/glu.h>
#include <stdio.h>
#include <stdlib.h>

struct poly {
    const char *name;
    GLfloat rgb[3];
    int errors;
};

static GLUtesselator *tess;
static int edges_only = 0, frame = 0;

static void begin_data(GLenum mode, void *p)
{
    /* gluBeginPolygon gives no polygon data: the current colour stays. */
    if (p)
        glColor3fv(((struct poly *)p)->rgb);
    glBegin(mode);
}

static void vertex_data(void *v, void *p)
{
    (void)p;
    glVertex3dv((GLdouble *)v);
}

static void end_data(void *p)
{
    (void)p;
    glEnd();
}

static void edge_data(GLboolean flag, void *p)
{
    (void)p;
    glEdgeFlag(flag);
}

static void error_data(GLenum code, void *p)
{
    struct poly *poly = p;
    if (frame == 0)
        printf("%s: error %u (%s)\n", poly ? poly->name : "(none)", code,
               (const char *)gluErrorString(code));
    if (poly)
        poly->errors++;
}

static GLdouble outer[5][3] = {
    { 20.5, 20.5, 0 }, { 140.25, 25.75, 0 }, { 150.5, 110.5, 0 }, { 80.75, 140.25, 0 }, { 15.25, 100.5, 0 }
};
static GLdouble inner[4][3] = { { 50.5, 50.25, 0 }, { 60.75, 95.5, 0 }, { 110.25, 90.75, 0 }, { 105.5, 45.5, 0 } };
static GLdouble hole[3][3] = { { 215.5, 158.25, 0 }, { 240.25, 185.5, 0 }, { 242.5, 160.75, 0 } };
static GLdouble bow[4][3] = { { 180.5, 30.5, 0 }, { 300.25, 120.75, 0 }, { 300.75, 30.25, 0 }, { 180.25, 120.5, 0 } };
static GLdouble arrow[6][3] = {
    { 180.5, 150.5, 0 }, { 250.25, 150.25, 0 }, { 250.75, 130.5, 0 },
    { 300.5, 180.25, 0 }, { 250.25, 225.75, 0 }, { 250.5, 205.5, 0 }
};

static void contour(GLdouble (*v)[3], int n)
{
    int i;
    gluTessBeginContour(tess);
    for (i = 0; i < n; i++)
        gluTessVertex(tess, v[i], v[i]);
    gluTessEndContour(tess);
}

static GLdouble probe_pool[64][3];
static int probe_n = 0;

static void probe_vertex(void *v)
{
    (void)v;
}

static void probe_combine(GLdouble c[3], void *d[4], GLfloat w[4], void **out)
{
    GLdouble *v = probe_pool[probe_n++ % 64];
    printf("  combine at (%g, %g): %s%.4f %s%.4f %s%.4f %s%.4f\n", c[0], c[1],
           d[0] ? "" : "-", w[0], d[1] ? "" : "-", w[1], d[2] ? "" : "-", w[2],
           d[3] ? "" : "-", w[3]);
    v[0] = c[0];
    v[1] = c[1];
    v[2] = c[2];
    *out = v;
}

/* Tessellates contours of (x, y) pairs with a tessellator that prints its combines. */
static void probe(const char *name, const double *xy, const int *counts, int ncontours)
{
    GLUtesselator *t = gluNewTess();
    int c, i, k = 0;
    printf("%s\n", name);
    gluTessCallback(t, GLU_TESS_VERTEX, (_GLUfuncptr)probe_vertex);
    gluTessCallback(t, GLU_TESS_COMBINE, (_GLUfuncptr)probe_combine);
    gluTessBeginPolygon(t, NULL);
    for (c = 0; c < ncontours; c++) {
        gluTessBeginContour(t);
        for (i = 0; i < counts[c]; i++, k++) {
            GLdouble *v = probe_pool[probe_n++ % 64];
            v[0] = xy[2 * k];
            v[1] = xy[2 * k + 1];
            v[2] = 0.0;
            gluTessVertex(t, v, v);
        }
        gluTessEndContour(t);
    }
    gluTessEndPolygon(t);
    gluDeleteTess(t);
}

static void probes(void)
{
    static const double shared[] = { 0, 0, 30, 0, 30, 40, 0, 40, 30, 0, 60, 0, 60, 40, 30, 40 };
    static const double repeats[] = { 0, 0, 0, 0, 55, 5, 55, 5, 55, 5, 30, 50, 0, 0 };
    static const double touching[] = { 0, 0, 60, 0, 60, 60, 0, 60, 0, 0, 20, 40, 40, 20 };
    static const double crossing[] = { 0, 0, 10, 2, 10, 0, 2, 8, 3, -1, 4, 9, 20, 0, 30, 4, 20, 6, 27, -3 };
    static const int two_fours[] = { 4, 4 }, seven[] = { 7 }, four_three[] = { 4, 3 };
    static const int four_two[] = { 4, 2, 4 };
    probe("shared edge", shared, two_fours, 2);
    probe("repeated vertices", repeats, seven, 1);
    probe("hole touching at a corner", touching, four_three, 2);
    probe("crossings", crossing, four_two, 3);
}

static void display(void)
{
    static struct poly holed = { "holed", { 0.9f, 0.5f, 0.2f }, 0 };
    static struct poly bowtie = { "bowtie", { 0.3f, 0.8f, 0.9f }, 0 };
    static struct poly misuse = { "misuse", { 0.8f, 0.8f, 0.3f }, 0 };
    static struct poly props = { "props", { 1, 1, 1 }, 0 };
    GLdouble value = -1.0;
    int i;

    if (frame == 0)
        probes();
    glClear(GL_COLOR_BUFFER_BIT);
    glPolygonMode(GL_FRONT_AND_BACK, edges_only ? GL_LINE : GL_FILL);
    gluTessCallback(tess, GLU_TESS_EDGE_FLAG_DATA, edges_only ? (_GLUfuncptr)edge_data : NULL);

    /* _DATA callbacks with a hole. */
    gluTessBeginPolygon(tess, &holed);
    contour(outer, 5);
    contour(inner, 4);
    gluTessEndPolygon(tess);

    /* A bow tie without a combine callback: GLU reports that it needs one. */
    gluTessBeginPolygon(tess, &bowtie);
    contour(bow, 4);
    gluTessEndPolygon(tess);

    /* Sequence mistakes: a vertex before any contour, a polygon begun twice. */
    gluTessBeginPolygon(tess, &misuse);
    for (i = 0; i < 6; i++)
        gluTessVertex(tess, arrow[i], arrow[i]);
    gluTessEndContour(tess);
    gluTessEndPolygon(tess);
    gluTessBeginPolygon(tess, &misuse);
    gluTessBeginPolygon(tess, &misuse);
    gluTessEndPolygon(tess);

    /* Properties: bad values keep the old ones. */
    gluTessBeginPolygon(tess, &props);
    gluTessEndPolygon(tess);
    gluTessProperty(tess, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_NONZERO);
    gluTessProperty(tess, GLU_TESS_WINDING_RULE, 12345.0);
    gluGetTessProperty(tess, GLU_TESS_WINDING_RULE, &value);
    if (frame == 0)
        printf("winding rule %.0f\n", value);
    gluTessProperty(tess, GLU_TESS_TOLERANCE, 2.0);
    gluTessProperty(tess, GLU_TESS_TOLERANCE, 0.25);
    gluGetTessProperty(tess, GLU_TESS_TOLERANCE, &value);
    if (frame == 0)
        printf("tolerance %g\n", value);
    gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, 1.0);
    gluGetTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, &value);
    if (frame == 0)
        printf("boundary only %g\n", value);
    gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, 0.0);
    gluTessProperty(tess, GLU_TESS_TOLERANCE, 0.0);
    gluTessProperty(tess, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_ODD);
    gluTessProperty(tess, 4242, 1.0);
    value = -1.0;
    gluGetTessProperty(tess, 4242, &value);
    gluTessCallback(tess, 4242, NULL);
    if (frame == 0)
        printf("unknown property %g; errors: holed %d bowtie %d misuse %d props %d\n", value,
               holed.errors, bowtie.errors, misuse.errors, props.errors);

    /* GLU 1.0: the arrow with a hole cut by a second contour. */
    glColor3f(0.6f, 0.9f, 0.4f);
    gluBeginPolygon(tess);
    for (i = 0; i < 6; i++)
        gluTessVertex(tess, arrow[i], arrow[i]);
    gluNextContour(tess, GLU_INTERIOR);
    for (i = 0; i < 3; i++)
        gluTessVertex(tess, hole[i], hole[i]);
    gluEndPolygon(tess);
    fflush(stdout);
    frame++;
    glutSwapBuffers();
}

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, 320.0, 0.0, 240.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    if (key == 'e')
        edges_only = !edges_only;
    else if (key == 27) {
        gluDeleteTess(tess);
        exit(0);
    }
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(320, 240);
    glutCreateWindow("tessmisc");
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glShadeModel(GL_FLAT);
    tess = gluNewTess();
    gluTessCallback(tess, GLU_TESS_BEGIN_DATA, (_GLUfuncptr)begin_data);
    gluTessCallback(tess, GLU_TESS_VERTEX_DATA, (_GLUfuncptr)vertex_data);
    gluTessCallback(tess, GLU_TESS_END_DATA, (_GLUfuncptr)end_data);
    gluTessCallback(tess, GLU_TESS_ERROR_DATA, (_GLUfuncptr)error_data);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    return 0;
}
