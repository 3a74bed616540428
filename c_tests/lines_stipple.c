/* lines_stipple: glLineStipple patterns and factors on GL_LINES (pattern
 * restarts per segment), GL_LINE_STRIP and GL_LINE_LOOP (pattern continues
 * across segments), at widths 1, 2 and 3, and stippled lines clipped by the
 * window edge. */
#include "prims_common.h"

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    static const GLushort pats[4] = {0x00FF, 0x0F0F, 0xAAAA, 0x1C47};
    int i, k;
    prims_begin();
    glEnable(GL_LINE_STIPPLE);
    for (i = 0; i < 12; i++) {
        glLineStipple(1 + (i % 3) * 2, pats[i % 4]);
        glLineWidth(1.0f + (float)(i / 4));
        glBegin(GL_LINES);
        for (k = 0; k < 3; k++) {
            prims_color(i + k);
            glVertex2f(5.3f + 80.0f * k, 6.5f + 9.0f * i + 0.3f * k);
            prims_color(i + k + 5);
            glVertex2f(78.1f + 80.0f * k, 9.5f + 9.0f * i - 1.1f * k);
        }
        glEnd();
    }
    for (i = 0; i < 3; i++) {
        glLineStipple(2 + i, pats[(i + 1) % 4]);
        glLineWidth(1.0f + (float)i);
        glBegin(i == 2 ? GL_LINE_LOOP : GL_LINE_STRIP);
        for (k = 0; k < 7; k++) {
            prims_color(k * 3 + i);
            glVertex2f(10.5f + 80.0f * i + 60.0f * (float)(k & 1), 120.25f + 17.0f * k + (float)i);
        }
        glEnd();
    }
    /* steep and diagonal stippled lines, some crossing the window edge */
    glLineStipple(3, 0x3F07);
    glLineWidth(2.0f);
    glBegin(GL_LINES);
    for (i = 0; i < 8; i++) {
        prims_color(i);
        glVertex2f(-20.0f + 40.0f * i, 250.0f + 10.0f * (i & 1));
        prims_color(i + 9);
        glVertex2f(10.0f + 35.0f * i, 100.0f - 30.0f * (i & 1));
    }
    glEnd();
    prims_end(out, "stipple");
    prims_close(out);
    return 0;
}
