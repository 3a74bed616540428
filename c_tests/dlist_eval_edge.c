/* dlist_eval_edge: commands that display lists compile rather than execute:
 * glEdgeFlag inside glBegin/glEnd (GL_LINE polygons), glMap1f/glMap2f (the
 * control points are copied at compile time, so later changes to the array do
 * not matter), glEvalCoord1f/2f, glEvalPoint1/2 and glEvalMesh1/2 (evaluated
 * with the maps and grid current when the list runs). GL_COMPILE draws nothing
 * while compiling; the edge-flag list is compiled with GL_COMPILE_AND_EXECUTE.
 * (Mesa 22.3 mishandles the evaluator calls under GL_COMPILE_AND_EXECUTE: its
 * glEvalMesh then sends its glBegin/glEvalCoord to the list being compiled, so
 * nothing is drawn at compile time and the list gains compile-time copies; the
 * scene does not rely on that.) */
#include "prims_common.h"

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    static GLfloat curve[4][3] = {
        {10.0f, 10.0f, 0.0f}, {60.0f, 110.0f, 0.0f}, {110.0f, -40.0f, 0.0f}, {150.0f, 60.0f, 0.0f}};
    static GLfloat patch[3][3][3];
    static GLfloat colors[2][4] = {{1.0f, 0.2f, 0.2f, 1.0f}, {0.2f, 0.4f, 1.0f, 1.0f}};
    GLuint base;
    GLint order = 0;
    int i, j;
    for (i = 0; i < 3; i++)
        for (j = 0; j < 3; j++) {
            patch[i][j][0] = 140.0f + 50.0f * (float)j;
            patch[i][j][1] = 140.0f + 50.0f * (float)i;
            patch[i][j][2] = (i == 1 && j == 1) ? 0.5f : 0.0f;
        }
    prims_begin();
    base = glGenLists(4);

    /* 1: edge flags */
    glNewList(base, GL_COMPILE_AND_EXECUTE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glBegin(GL_POLYGON);
    glColor3f(1.0f, 1.0f, 0.3f);
    glEdgeFlag(GL_TRUE);
    glVertex2f(20.0f, 150.0f);
    glEdgeFlag(GL_FALSE);
    glVertex2f(100.0f, 150.0f);
    glEdgeFlag(GL_TRUE);
    glVertex2f(110.0f, 220.0f);
    glVertex2f(60.0f, 245.0f);
    glEdgeFlag(GL_FALSE);
    glVertex2f(15.0f, 220.0f);
    glEnd();
    glEdgeFlag(GL_TRUE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glEndList();

    /* 2: a 1D map and evaluated curve points and a mesh */
    glNewList(base + 1, GL_COMPILE);
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &curve[0][0]);
    glEnable(GL_MAP1_VERTEX_3);
    glColor3f(0.3f, 1.0f, 0.4f);
    glBegin(GL_LINE_STRIP);
    for (i = 0; i <= 20; i++)
        glEvalCoord1f((float)i / 20.0f);
    glEnd();
    glPointSize(4.0f);
    glBegin(GL_POINTS);
    for (i = 0; i <= 5; i++)
        glEvalPoint1(i);
    glEnd();
    glColor3f(1.0f, 0.5f, 0.9f);
    glEvalMesh1(GL_POINT, 0, 5);
    glEndList();

    /* 3: a 2D map with colours, mesh in fill and line, glEvalPoint2 */
    glNewList(base + 2, GL_COMPILE);
    glMap2f(GL_MAP2_VERTEX_3, 0.0f, 1.0f, 3, 3, 0.0f, 1.0f, 9, 3, &patch[0][0][0]);
    glMap2f(GL_MAP2_COLOR_4, 0.0f, 1.0f, 4, 2, 0.0f, 1.0f, 8, 1, &colors[0][0]);
    glEnable(GL_MAP2_VERTEX_3);
    glEnable(GL_MAP2_COLOR_4);
    glEvalMesh2(GL_FILL, 0, 4, 0, 4);
    glDisable(GL_MAP2_COLOR_4);
    glColor3f(0.0f, 0.0f, 0.0f);
    glEvalMesh2(GL_LINE, 0, 4, 0, 4);
    glPointSize(3.0f);
    glColor3f(1.0f, 1.0f, 1.0f);
    glBegin(GL_POINTS);
    glEvalPoint2(1, 1);
    glEvalPoint2(3, 2);
    glEvalCoord2f(0.9f, 0.1f);
    glEnd();
    glEndList();

    /* change everything the lists must not depend on */
    curve[1][1] = 250.0f;
    patch[1][1][1] = 10.0f;
    glMap1f(GL_MAP1_VERTEX_3, 0.0f, 1.0f, 3, 4, &curve[0][0]);
    glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, &order);
    sgl_text(out, "compiled", "order %d err 0x%x\n", order, glGetError());
    prims_end(out, "after_compile");

    glClear(GL_COLOR_BUFFER_BIT);
    glMapGrid1f(5, 0.0f, 1.0f);
    glMapGrid2f(4, 0.0f, 1.0f, 4, 0.0f, 1.0f);
    glCallList(base);
    glCallList(base + 1);
    glMapGrid2f(4, 0.0f, 0.5f, 4, 0.0f, 1.0f); /* the list uses this grid */
    glPushMatrix();
    glTranslatef(-120.0f, -120.0f, 0.0f);
    glCallList(base + 2);
    glPopMatrix();
    glGetMapiv(GL_MAP1_VERTEX_3, GL_ORDER, &order);
    sgl_text(out, "executed", "order %d err 0x%x\n", order, glGetError());
    prims_end(out, "executed");
    prims_close(out);
    return 0;
}
