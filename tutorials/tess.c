/*
 * Tutorial 6: the GLU tessellator on concave, holed and self-intersecting polygons.
 *
 * Three polygons go through one tessellator into display lists: a frame with a
 * triangular hole, a five-pointed star drawn as one self-intersecting contour (its
 * crossings become new vertices through the combine callback) and two overlapping
 * squares. Keys: 'w' steps the winding rule (odd, nonzero, positive, negative,
 * abs >= 2), 'm' steps the output mode (filled triangles, boundary-only line loops,
 * triangles drawn as lines with GLU's edge flags, so only the polygon's boundary
 * shows), Esc quits. Each polygon is one flat colour.
 */
#include <GL/glut.h>
#include <GL/glu.h>
#include <stdio.h>
#include <stdlib.h>

static GLUtesselator *tess;
static GLuint lists;
static int rule = 0, mode = 0;
static const GLenum rules[5] = {
    GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO, GLU_TESS_WINDING_POSITIVE,
    GLU_TESS_WINDING_NEGATIVE, GLU_TESS_WINDING_ABS_GEQ_TWO
};

/* Vertices made by the combine callback live here until the lists are rebuilt. */
static GLdouble made[256][3];
static int nmade = 0;

static void combine(GLdouble coords[3], void *data[4], GLfloat weight[4], void **out)
{
    GLdouble *v = made[nmade++ % 256];
    (void)data;
    (void)weight;
    v[0] = coords[0];
    v[1] = coords[1];
    v[2] = coords[2];
    *out = v;
}

static void error(GLenum code)
{
    fprintf(stderr, "tess error: %s\n", (const char *)gluErrorString(code));
}

static void edge(GLboolean flag)
{
    glEdgeFlag(flag);
}

static GLdouble frame_outer[4][3] = {
    { 20.5, 30.25, 0 }, { 110.75, 30.25, 0 }, { 110.75, 150.5, 0 }, { 20.5, 150.5, 0 }
};
static GLdouble frame_hole[3][3] = { { 40.25, 50.5, 0 }, { 65.5, 130.75, 0 }, { 90.5, 50.5, 0 } };
static GLdouble star[5][3] = {
    { 200.3, 200.1, 0 }, { 226.7, 120.4, 0 }, { 157.9, 170.2, 0 },
    { 242.6, 170.9, 0 }, { 173.2, 119.8, 0 }
};
static GLdouble sq_a[4][3] = { { 215.5, 20.5, 0 }, { 295.5, 20.5, 0 }, { 295.5, 100.5, 0 }, { 215.5, 100.5, 0 } };
static GLdouble sq_b[4][3] = { { 250.2, 60.3, 0 }, { 310.9, 45.1, 0 }, { 300.4, 110.6, 0 }, { 240.8, 115.2, 0 } };

static void contour(GLdouble (*v)[3], int n)
{
    int i;
    gluTessBeginContour(tess);
    for (i = 0; i < n; i++)
        gluTessVertex(tess, v[i], v[i]);
    gluTessEndContour(tess);
}

static void build(void)
{
    nmade = 0;
    gluTessProperty(tess, GLU_TESS_WINDING_RULE, rules[rule]);
    gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, mode == 1 ? GL_TRUE : GL_FALSE);
    gluTessCallback(tess, GLU_TESS_EDGE_FLAG, mode == 2 ? (_GLUfuncptr)edge : NULL);

    glNewList(lists, GL_COMPILE);
    glColor3f(0.9f, 0.6f, 0.2f);
    gluTessBeginPolygon(tess, NULL);
    contour(frame_outer, 4);
    contour(frame_hole, 3);
    gluTessEndPolygon(tess);
    glEndList();

    glNewList(lists + 1, GL_COMPILE);
    glColor3f(0.3f, 0.8f, 0.4f);
    gluTessBeginPolygon(tess, NULL);
    contour(star, 5);
    gluTessEndPolygon(tess);
    glEndList();

    glNewList(lists + 2, GL_COMPILE);
    glColor3f(0.4f, 0.5f, 1.0f);
    gluTessBeginPolygon(tess, NULL);
    contour(sq_a, 4);
    contour(sq_b, 4);
    gluTessEndPolygon(tess);
    glEndList();
}

static void init(void)
{
    glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
    glShadeModel(GL_FLAT);
    tess = gluNewTess();
    gluTessCallback(tess, GLU_TESS_BEGIN, (_GLUfuncptr)glBegin);
    gluTessCallback(tess, GLU_TESS_VERTEX, (_GLUfuncptr)glVertex3dv);
    gluTessCallback(tess, GLU_TESS_END, (_GLUfuncptr)glEnd);
    gluTessCallback(tess, GLU_TESS_COMBINE, (_GLUfuncptr)combine);
    gluTessCallback(tess, GLU_TESS_ERROR, (_GLUfuncptr)error);
    lists = glGenLists(3);
    build();
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

static void display(void)
{
    glClear(GL_COLOR_BUFFER_BIT);
    glPolygonMode(GL_FRONT_AND_BACK, mode == 2 ? GL_LINE : GL_FILL);
    glCallList(lists);
    glCallList(lists + 1);
    glCallList(lists + 2);
    glutSwapBuffers();
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    switch (key) {
    case 'w':
        rule = (rule + 1) % 5;
        break;
    case 'm':
        mode = (mode + 1) % 3;
        break;
    case 27:
        gluDeleteTess(tess);
        exit(0);
    default:
        return;
    }
    build();
    glutPostRedisplay();
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(320, 240);
    glutCreateWindow("tess");
    init();
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    return 0;
}
