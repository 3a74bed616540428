/* smooth_points: GL_POINT_SMOOTH with blending as tutorials use it: sizes
 * 0.5..20 (fractional too) at several sub-pixel positions, translucent
 * colours, blending off, the alpha test on the smoothed alpha, depth-tested
 * points in perspective, points clipped at the edges, and the smooth size
 * range queries. */
#include "prims_common.h"

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    GLfloat r[2], g;
    int i, j;
    char text[256];
    static const float sizes[] = {0.5f, 1.0f, 1.5f, 2.0f, 2.5f, 3.0f, 3.7f, 4.0f,
                                  5.0f, 6.5f, 8.0f, 10.0f, 12.5f, 16.0f, 20.0f};
    prims_begin();
    glGetFloatv(GL_SMOOTH_POINT_SIZE_RANGE, r);
    glGetFloatv(GL_SMOOTH_POINT_SIZE_GRANULARITY, &g);
    snprintf(text, sizeof text, "smooth point size range %g %g granularity %g\n", r[0], r[1],
             g);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_POINT_SMOOTH);
    glHint(GL_POINT_SMOOTH_HINT, GL_NICEST);
    for (i = 0; i < 15; i++) {
        glPointSize(sizes[i]);
        glBegin(GL_POINTS);
        for (j = 0; j < 4; j++) {
            prims_color(i + j);
            glVertex2f(12.0f + 16.5f * (float)i + 0.27f * (float)j,
                       12.0f + 26.0f * (float)j + 0.33f * (float)j);
        }
        glEnd();
    }
    /* translucent colours */
    glPointSize(9.0f);
    glBegin(GL_POINTS);
    for (i = 0; i < 8; i++) {
        glColor4f(1.0f, 0.5f, 0.2f, 0.15f + 0.1f * (float)i);
        glVertex2f(20.3f + 24.0f * (float)i, 130.7f);
    }
    glEnd();
    /* blending off */
    glDisable(GL_BLEND);
    glPointSize(7.0f);
    glBegin(GL_POINTS);
    glColor4f(0.2f, 0.9f, 0.9f, 0.5f);
    glVertex2f(220.5f, 130.5f);
    glColor4f(0.9f, 0.9f, 0.2f, 1.0f);
    glVertex2f(240.2f, 131.1f);
    glEnd();
    glEnable(GL_BLEND);
    /* alpha test on the smoothed alpha */
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    glPointSize(11.0f);
    glBegin(GL_POINTS);
    glColor4f(1.0f, 1.0f, 1.0f, 0.6f);
    glVertex2f(20.0f, 155.0f);
    glColor4f(1.0f, 0.3f, 1.0f, 0.9f);
    glVertex2f(40.0f, 155.0f);
    glEnd();
    glDisable(GL_ALPHA_TEST);
    /* clipped at the edges (centre outside: dropped) */
    glPointSize(14.0f);
    glBegin(GL_POINTS);
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex2f(2.0f, 170.0f);
    glVertex2f(-2.0f, 190.0f);
    glVertex2f(254.5f, 175.0f);
    glEnd();
    /* perspective, depth tested */
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glViewport(128, 128, 128, 128);
    glTranslatef(0.0f, 0.0f, -3.0f);
    glRotatef(-50.0f, 1.0f, 0.0f, 0.0f);
    glPointSize(6.0f);
    glBegin(GL_POINTS);
    for (i = -3; i <= 3; i++) {
        for (j = -3; j <= 3; j++) {
            glColor4f(0.5f + 0.07f * (float)i, 0.5f + 0.07f * (float)j, 0.8f, 0.9f);
            glVertex3f((float)i * 0.4f, (float)j * 0.4f, 0.1f * (float)(i * j));
        }
    }
    glEnd();
    prims_end(out, "smooth_points");
    sgl_text(out, "ranges", "%s", text);
    prims_close(out);
    return 0;
}
