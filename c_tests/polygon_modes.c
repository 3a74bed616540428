/* polygon_modes: glPolygonMode with front and back set separately (FILL, LINE,
 * POINT), on triangles, strips, fans, quads, quad strips and polygons with
 * both windings, smooth and flat, with glLineWidth/glPointSize, line stipple on
 * the outlines, and edge flags (glEdgeFlag) hiding edges in GL_LINE and
 * GL_POINT modes. */
#include "prims_common.h"

/* a cell of six primitives at (x, y); cw flips the winding */
static void cell(float x, float y, int cw)
{
    int i;
    float s = cw ? -1.0f : 1.0f;
    glPushMatrix();
    glTranslatef(x + (cw ? 40.0f : 0.0f), y, 0.0f);
    glScalef(s, 1.0f, 1.0f);
    glBegin(GL_TRIANGLES);
    prims_color(1); glVertex2f(2.3f, 2.2f);
    prims_color(2); glVertex2f(36.6f, 5.1f);
    prims_color(3); glVertex2f(14.4f, 33.7f);
    glEnd();
    glBegin(GL_QUADS);
    prims_color(4); glVertex2f(2.5f, 40.5f);
    prims_color(5); glVertex2f(37.2f, 41.3f);
    prims_color(6); glVertex2f(35.1f, 70.2f);
    prims_color(7); glVertex2f(4.4f, 68.8f);
    glEnd();
    glBegin(GL_POLYGON);
    for (i = 0; i < 6; i++) {
        float a = (float)i * 6.2831853f / 6.0f + 0.2f;
        prims_color(8 + i);
        glVertex2f(20.1f + 17.0f * cosf(a), 95.3f + 17.0f * sinf(a));
    }
    glEnd();
    glBegin(GL_TRIANGLE_STRIP);
    for (i = 0; i < 6; i++) {
        prims_color(14 + i);
        glVertex2f(2.7f + 7.0f * i, (i & 1) ? 118.2f : 136.6f);
    }
    glEnd();
    glBegin(GL_TRIANGLE_FAN);
    prims_color(20); glVertex2f(20.5f, 142.5f);
    for (i = 0; i < 5; i++) {
        float a = (float)i * 0.7f;
        prims_color(21 + i);
        glVertex2f(20.5f + 19.0f * cosf(a), 142.5f + 19.0f * sinf(a));
    }
    glEnd();
    glBegin(GL_QUAD_STRIP);
    for (i = 0; i < 6; i++) {
        prims_color(26 + i);
        glVertex2f(3.1f + 7.3f * (i / 2), (i & 1) ? 168.1f : 190.4f + (float)(i % 3));
    }
    glEnd();
    glPopMatrix();
}

static void row(void)
{
    cell(2.0f, 2.0f, 0);
    cell(44.0f, 2.0f, 1);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    prims_begin();
    /* front LINE / back FILL, then front POINT / back LINE, then both LINE wide */
    glPolygonMode(GL_FRONT, GL_LINE);
    glPolygonMode(GL_BACK, GL_FILL);
    row();
    glPushMatrix();
    glTranslatef(86.0f, 0.0f, 0.0f);
    glPolygonMode(GL_FRONT, GL_POINT);
    glPolygonMode(GL_BACK, GL_LINE);
    glPointSize(3.0f);
    row();
    glTranslatef(86.0f, 0.0f, 0.0f);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glLineWidth(2.0f);
    glShadeModel(GL_FLAT);
    row();
    glPopMatrix();
    prims_end(out, "modes");

    /* GL_CW front face, culling, stippled outlines and edge flags */
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_SMOOTH);
    glLineWidth(1.0f);
    glFrontFace(GL_CW);
    glPolygonMode(GL_FRONT, GL_LINE);
    glPolygonMode(GL_BACK, GL_POINT);
    row();
    glFrontFace(GL_CCW);
    glPushMatrix();
    glTranslatef(86.0f, 0.0f, 0.0f);
    glEnable(GL_CULL_FACE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x33FF);
    row();
    glDisable(GL_CULL_FACE);
    glDisable(GL_LINE_STIPPLE);
    glTranslatef(86.0f, 0.0f, 0.0f);
    /* edge flags: a polygon and quads with some edges hidden */
    glBegin(GL_POLYGON);
    glEdgeFlag(GL_TRUE);  prims_color(1); glVertex2f(5.5f, 5.5f);
    glEdgeFlag(GL_FALSE); prims_color(2); glVertex2f(75.5f, 8.5f);
    glEdgeFlag(GL_TRUE);  prims_color(3); glVertex2f(70.5f, 60.5f);
    glEdgeFlag(GL_FALSE); prims_color(4); glVertex2f(35.5f, 75.5f);
    glEdgeFlag(GL_TRUE);  prims_color(5); glVertex2f(3.5f, 50.5f);
    glEnd();
    glBegin(GL_QUADS);
    glEdgeFlag(GL_TRUE);  prims_color(6); glVertex2f(5.5f, 90.5f);
    glEdgeFlag(GL_TRUE);  prims_color(7); glVertex2f(70.5f, 92.5f);
    glEdgeFlag(GL_FALSE); prims_color(8); glVertex2f(72.5f, 140.5f);
    glEdgeFlag(GL_TRUE);  prims_color(9); glVertex2f(8.5f, 138.5f);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glPointSize(4.0f);
    glBegin(GL_TRIANGLES);
    glEdgeFlag(GL_TRUE);  prims_color(10); glVertex2f(10.5f, 160.5f);
    glEdgeFlag(GL_FALSE); prims_color(11); glVertex2f(70.5f, 165.5f);
    glEdgeFlag(GL_TRUE);  prims_color(12); glVertex2f(40.5f, 220.5f);
    glEnd();
    glEdgeFlag(GL_TRUE);
    glPopMatrix();
    prims_end(out, "flags");
    prims_close(out);
    return 0;
}
