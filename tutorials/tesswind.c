/*
 * Tutorial 7: winding rules. Four groups of contours are tessellated with the current
 * rule: three nested squares all counterclockwise, the same with the middle one
 * clockwise, three overlapping rectangles, and a spiral-like contour crossing itself
 * twice. A fifth group lies in a tilted plane seen in perspective, with its normal
 * given by gluTessNormal; the sixth is the second group tessellated with the normal
 * (0, 0, -1), which negates every winding number. Keys: 'w' steps the rule (odd,
 * nonzero, positive, negative, abs >= 2), 'b' toggles boundary-only output (drawn as
 * line loops), Esc quits.
 */
#include <GL/glut.h>
#include <GL/glu.h>
#include <stdlib.h>

static GLUtesselator *tess;
static int rule = 0, boundary = 0;
static const GLenum rules[5] = {
    GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO, GLU_TESS_WINDING_POSITIVE,
    GLU_TESS_WINDING_NEGATIVE, GLU_TESS_WINDING_ABS_GEQ_TWO
};

static GLdouble pool[512][3];
static int npool = 0;

static void combine(GLdouble c[3], void *d[4], GLfloat w[4], void **out)
{
    GLdouble *v = pool[npool++ % 512];
    (void)d;
    (void)w;
    v[0] = c[0];
    v[1] = c[1];
    v[2] = c[2];
    *out = v;
}

/* A rectangle's corners, counterclockwise or clockwise, into the pool. */
static void rect(double x0, double y0, double x1, double y1, int cw)
{
    double xs[4], ys[4];
    int i;
    xs[0] = x0; ys[0] = y0;
    xs[1] = x1; ys[1] = y0;
    xs[2] = x1; ys[2] = y1;
    xs[3] = x0; ys[3] = y1;
    gluTessBeginContour(tess);
    for (i = 0; i < 4; i++) {
        int k = cw ? 3 - i : i;
        GLdouble *v = pool[npool++ % 512];
        v[0] = xs[k];
        v[1] = ys[k];
        v[2] = 0.0;
        gluTessVertex(tess, v, v);
    }
    gluTessEndContour(tess);
}

static void nested(double x, double y, int middle_cw)
{
    gluTessBeginPolygon(tess, NULL);
    rect(x, y, x + 70.3, y + 70.6, 0);
    rect(x + 10.2, y + 10.4, x + 60.1, y + 60.7, middle_cw);
    rect(x + 20.6, y + 20.3, x + 50.4, y + 50.2, 0);
    gluTessEndPolygon(tess);
}

static void overlapping(double x, double y)
{
    gluTessBeginPolygon(tess, NULL);
    rect(x, y, x + 50.3, y + 40.2, 0);
    rect(x + 20.1, y + 15.4, x + 70.7, y + 55.8, 0);
    rect(x + 35.2, y - 10.6, x + 55.5, y + 70.9, 1);
    gluTessEndPolygon(tess);
}

static GLdouble spiral[8][3] = {
    { 250.2, 130.1, 0 }, { 310.6, 130.4, 0 }, { 310.3, 210.8, 0 }, { 270.5, 210.2, 0 },
    { 270.9, 150.3, 0 }, { 295.1, 150.6, 0 }, { 295.4, 230.7, 0 }, { 250.8, 230.3, 0 }
};

static void draw_spiral(void)
{
    int i;
    gluTessBeginPolygon(tess, NULL);
    gluTessBeginContour(tess);
    for (i = 0; i < 8; i++)
        gluTessVertex(tess, spiral[i], spiral[i]);
    gluTessEndContour(tess);
    gluTessEndPolygon(tess);
}

/* A star-shaped contour twice around, in the plane z = 0.5 x: winding 2 inside. */
static void tilted(void)
{
    static GLdouble v[10][3];
    static const double px[5] = { 0.0, 0.59, -0.95, 0.95, -0.59 };
    static const double py[5] = { 1.0, -0.81, 0.31, 0.31, -0.81 };
    int i;
    gluTessNormal(tess, -0.5, 0.0, 1.0);
    gluTessBeginPolygon(tess, NULL);
    gluTessBeginContour(tess);
    for (i = 0; i < 10; i++) {
        double s = i < 5 ? 1.0 : 0.55;
        v[i][0] = px[i % 5] * s + 0.013;
        v[i][1] = py[i % 5] * s + 0.021;
        v[i][2] = 0.5 * v[i][0];
        gluTessVertex(tess, v[i], v[i]);
    }
    gluTessEndContour(tess);
    gluTessEndPolygon(tess);
    gluTessNormal(tess, 0.0, 0.0, 0.0);
}

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
}

static void display(void)
{
    npool = 0;
    gluTessProperty(tess, GLU_TESS_WINDING_RULE, rules[rule]);
    gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, boundary);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, 320.0, 0.0, 240.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor3f(1.0f, 0.8f, 0.3f);
    nested(10.3, 10.2, 0);
    glColor3f(0.4f, 0.9f, 0.5f);
    nested(90.6, 10.4, 1);
    glColor3f(0.5f, 0.6f, 1.0f);
    overlapping(175.2, 20.3);
    glColor3f(0.9f, 0.4f, 0.8f);
    draw_spiral();
    glColor3f(0.7f, 0.7f, 0.7f);
    gluTessNormal(tess, 0.0, 0.0, -1.0);
    nested(10.3, 130.2, 1);
    gluTessNormal(tess, 0.0, 0.0, 0.0);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.2, 0.2, -0.15, 0.15, 0.5, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.5f, -3.0f);
    glScalef(0.35f, 0.35f, 0.35f);
    glRotatef(35.0f, 0.0f, 1.0f, 0.0f);
    glColor3f(0.3f, 0.9f, 0.9f);
    tilted();
    glutSwapBuffers();
}

static void keyboard(unsigned char key, int x, int y)
{
    (void)x;
    (void)y;
    if (key == 'w')
        rule = (rule + 1) % 5;
    else if (key == 'b')
        boundary = !boundary;
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
    glutCreateWindow("tesswind");
    glClearColor(0.08f, 0.08f, 0.1f, 1.0f);
    glShadeModel(GL_FLAT);
    tess = gluNewTess();
    gluTessCallback(tess, GLU_TESS_BEGIN, (_GLUfuncptr)glBegin);
    gluTessCallback(tess, GLU_TESS_VERTEX, (_GLUfuncptr)glVertex3dv);
    gluTessCallback(tess, GLU_TESS_END, (_GLUfuncptr)glEnd);
    gluTessCallback(tess, GLU_TESS_COMBINE, (_GLUfuncptr)combine);
    glutDisplayFunc(display);
    glutReshapeFunc(reshape);
    glutKeyboardFunc(keyboard);
    glutMainLoop();
    return 0;
}
