/*
 * Tutorial 9: the tessellator on random polygons. Each frame draws twelve polygons
 * of one to three random contours (3 to 11 vertices each, crossing themselves and
 * each other at will), one flat colour each. Frames 0-4 fill them under the five
 * winding rules, frames 5-9 draw boundary-only loops, frames 10-14 draw the filled
 * triangles as lines with GLU's edge flags (only the boundary shows). The random
 * numbers come from a fixed linear congruential generator seeded by the frame.
 */
#include <GL/glut.h>
#include <GL/glu.h>
#include <stdlib.h>

static GLUtesselator *tess;
static int frame = 0;
static GLdouble pool[8192][3];
static int npool = 0;
static unsigned seed = 1;

static GLdouble *new_vertex(void)
{
    return pool[npool++ % 8192];
}

static void combine(GLdouble c[3], void *d[4], GLfloat w[4], void **out)
{
    GLdouble *v = new_vertex();
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

static double rnd(void)
{
    seed = seed * 1103515245u + 12345u;
    return ((seed >> 8) & 0xffff) / 65536.0;
}

static void display(void)
{
    static const GLenum rules[5] = {
        GLU_TESS_WINDING_ODD, GLU_TESS_WINDING_NONZERO, GLU_TESS_WINDING_POSITIVE,
        GLU_TESS_WINDING_NEGATIVE, GLU_TESS_WINDING_ABS_GEQ_TWO
    };
    int p, c, i;

    npool = 0;
    seed = 1 + frame % 5;
    glClear(GL_COLOR_BUFFER_BIT);
    gluTessProperty(tess, GLU_TESS_WINDING_RULE, rules[frame % 5]);
    gluTessProperty(tess, GLU_TESS_BOUNDARY_ONLY, frame >= 5 && frame < 10);
    gluTessCallback(tess, GLU_TESS_EDGE_FLAG, frame >= 10 ? (_GLUfuncptr)edge : NULL);
    glPolygonMode(GL_FRONT_AND_BACK, frame >= 10 ? GL_LINE : GL_FILL);
    for (p = 0; p < 12; p++) {
        double cx = 40 + (p % 4) * 80, cy = 40 + (p / 4) * 80;
        glColor3f(0.3f + 0.05f * p, 1.0f - 0.05f * p, 0.5f);
        gluTessBeginPolygon(tess, NULL);
        for (c = 0; c < 1 + p % 3; c++) {
            int n = 3 + (int)(rnd() * 9);
            gluTessBeginContour(tess);
            for (i = 0; i < n; i++) {
                GLdouble *v = new_vertex();
                v[0] = cx + (rnd() - 0.5) * 75;
                v[1] = cy + (rnd() - 0.5) * 75;
                v[2] = 0;
                gluTessVertex(tess, v, v);
            }
            gluTessEndContour(tess);
        }
        gluTessEndPolygon(tess);
    }
    frame++;
    glutSwapBuffers();
}

static void reshape(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, 320, 0, 240, -1, 1);
    glMatrixMode(GL_MODELVIEW);
}

int main(int argc, char **argv)
{
    glutInit(&argc, argv);
    glutInitDisplayMode(GLUT_DOUBLE | GLUT_RGB);
    glutInitWindowSize(320, 240);
    glutCreateWindow("tessrand");
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
