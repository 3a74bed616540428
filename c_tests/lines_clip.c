/* lines_clip: wide lines (widths 1, 3, 6, 9) crossing the window edges at many
 * angles, so clipping before widening shows (llvmpipe cuts the line at the
 * viewport and then widens it), plus a viewport smaller than the window and
 * lines with a depth slope under GL_LESS. */
#include "prims_common.h"

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    static const float widths[4] = {1.0f, 3.0f, 6.0f, 9.0f};
    int i;
    prims_begin();
    for (i = 0; i < 32; i++) {
        float a = (float)i * 6.2831853f / 32.0f;
        glLineWidth(widths[i % 4]);
        glBegin(GL_LINES);
        glColor3f(0.9f, 0.9f, 0.2f);
        glVertex2f(128.3f + 60.0f * cosf(a), 128.6f + 60.0f * sinf(a));
        prims_color(i);
        glVertex2f(128.3f + 260.0f * cosf(a), 128.6f + 260.0f * sinf(a));
        glEnd();
    }
    prims_end(out, "edges");

    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glViewport(40, 30, 170, 190);
    glEnable(GL_DEPTH_TEST);
    for (i = 0; i < 16; i++) {
        glLineWidth(1.0f + (float)(i % 5));
        glBegin(GL_LINES);
        prims_color(i);
        glVertex3f(-30.0f + 20.0f * i, -20.0f, -0.9f + 0.1f * (float)(i % 7));
        prims_color(i + 3);
        glVertex3f(300.0f - 15.0f * i, 280.0f, 0.8f - 0.1f * (float)(i % 5));
        glEnd();
    }
    prims_end(out, "viewport");
    prims_close(out);
    return 0;
}
