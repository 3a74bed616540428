/* points_sizes: GL_POINTS at sizes 1 to 12 including fractional ones (0.5,
 * 1.5, 2.5, 3.3, 4.5, 6.7), at fractional centres, and points near and across
 * the window edges (a point whose centre is outside vanishes whole). */
#include "prims_common.h"

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    static const float sizes[16] = {0.5f, 1.0f, 1.5f, 2.0f, 2.5f, 3.0f, 3.3f, 4.0f,
                                    4.5f, 5.0f, 6.0f, 6.7f, 8.0f, 9.0f, 10.0f, 12.0f};
    int i, j;
    prims_begin();
    for (i = 0; i < 16; i++) {
        glPointSize(sizes[i]);
        glBegin(GL_POINTS);
        for (j = 0; j < 8; j++) {
            prims_color(i * 8 + j);
            glVertex2f(8.0f + 15.5f * i + 0.125f * j, 12.0f + 28.0f * j + 0.37f * i);
        }
        glEnd();
    }
    /* edges: centres just inside and just outside */
    glPointSize(7.0f);
    glBegin(GL_POINTS);
    glColor3f(1, 1, 0);
    glVertex2f(0.2f, 240.0f);
    glVertex2f(255.9f, 240.0f);
    glVertex2f(-0.2f, 230.0f);
    glVertex2f(256.1f, 230.0f);
    glVertex2f(120.0f, 255.5f);
    glVertex2f(130.0f, 256.5f);
    glVertex2f(140.0f, 0.3f);
    glEnd();
    glPointSize(4.0f);
    glBegin(GL_POINTS);
    glColor3f(0, 1, 1);
    glVertex2f(1.5f, 250.0f);
    glVertex2f(254.5f, 250.0f);
    glVertex2f(150.5f, 1.5f);
    glEnd();
    prims_end(out, "points");

    /* flat shading and depth test with points */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glShadeModel(GL_FLAT);
    for (i = 0; i < 6; i++) {
        glPointSize(3.0f + 2.0f * i);
        glBegin(GL_POINTS);
        for (j = 0; j < 40; j++) {
            prims_color(j + i);
            glVertex3f(20.0f + 5.5f * j, 30.0f + 35.0f * i + (float)(j % 5), 0.9f - 0.04f * (float)((j * 7) % 40));
        }
        glEnd();
    }
    prims_end(out, "depth");
    prims_close(out);
    return 0;
}
