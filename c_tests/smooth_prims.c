/* smooth_prims: GL_LINE_SMOOTH and GL_POINT_SMOOTH enabled (with blending, as
 * antialiasing is meant to be used): llvmpipe draws them through the draw
 * module's aaline/aapoint stages, with coverage in alpha. */
#include "prims_common.h"

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    int i;
    prims_begin();
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_LINE_SMOOTH);
    for (i = 0; i < 12; i++) {
        float a = (float)i * 6.2831853f / 12.0f + 0.1f;
        glLineWidth(1.0f + 0.5f * (float)i);
        glBegin(GL_LINES);
        prims_color(i);
        glVertex2f(64.3f, 64.6f);
        glVertex2f(64.3f + 58.0f * cosf(a), 64.6f + 58.0f * sinf(a));
        glEnd();
    }
    glDisable(GL_LINE_SMOOTH);
    glEnable(GL_POINT_SMOOTH);
    for (i = 0; i < 12; i++) {
        glPointSize(1.0f + 1.5f * (float)i);
        glBegin(GL_POINTS);
        prims_color(i + 3);
        glVertex2f(140.5f + 20.0f * (float)(i % 6), 30.3f + 40.0f * (float)(i / 6));
        glEnd();
    }
    prims_end(out, "smooth");
    prims_close(out);
    return 0;
}
