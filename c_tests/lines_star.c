/* lines_star: 24-line stars (GL_LINES, smooth colours) at widths 1, 1.5, 2, 2.5,
 * 3, 4, 5.5, 7, 8 and 10, each star centred at a fractional position, so every
 * octant, the diamond-exit end rules and the wide-line parallelogram show. */
#include "prims_common.h"

static void star(float cx, float cy, float r, float width)
{
    int i;
    glLineWidth(width);
    glBegin(GL_LINES);
    for (i = 0; i < 24; i++) {
        float a = (float)i * 6.2831853f / 24.0f + 0.05f;
        glColor3f(1.0f, 0.2f, 0.1f);
        glVertex2f(cx + 0.13f * (float)(i % 3), cy);
        prims_color(i);
        glVertex2f(cx + r * cosf(a), cy + r * sinf(a));
    }
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    static const float widths[10] = {1.0f, 1.5f, 2.0f, 2.5f, 3.0f, 4.0f, 5.5f, 7.0f, 8.0f, 10.0f};
    int i;
    prims_begin();
    for (i = 0; i < 4; i++)
        star(32.3f + 64.0f * i, 224.6f, 29.0f, widths[i]);
    for (i = 0; i < 3; i++)
        star(42.7f + 85.0f * i, 150.2f, 38.0f, widths[4 + i]);
    for (i = 0; i < 3; i++)
        star(42.5f + 85.0f * i, 55.5f, 40.0f, widths[7 + i]);
    prims_end(out, "stars");

    /* the same stars flat-shaded, drawn as one GL_LINE_STRIP per star */
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_FLAT);
    for (i = 0; i < 6; i++) {
        int k;
        glLineWidth(1.0f + 0.75f * i);
        glBegin(i & 1 ? GL_LINE_LOOP : GL_LINE_STRIP);
        for (k = 0; k < 13; k++) {
            float a = (float)k * 6.2831853f * 5.0f / 13.0f;
            prims_color(k + i);
            glVertex2f(40.5f + 85.0f * (i % 3) + 35.0f * cosf(a),
                       190.25f - 120.0f * (i / 3) + 35.0f * sinf(a));
        }
        glEnd();
    }
    prims_end(out, "strips");
    prims_close(out);
    return 0;
}
