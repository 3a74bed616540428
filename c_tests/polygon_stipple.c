/* polygon_stipple: glPolygonStipple + GL_POLYGON_STIPPLE on smooth and flat
 * triangles, quads and a polygon; the pattern is anchored at window (0,0), so
 * a shifted viewport does not move it; GL_UNPACK_LSB_FIRST on upload and
 * glGetPolygonStipple read back (with and without GL_PACK_LSB_FIRST). */
#include "prims_common.h"

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    GLubyte pat[128], back[128], back_lsb[128];
    int i;
    char txt[1024];
    int n = 0;
    for (i = 0; i < 128; i++)
        pat[i] = (GLubyte)((i * 37 + (i >> 2) * 11) ^ 0x5A);
    prims_begin();
    glPolygonStipple(pat);
    glEnable(GL_POLYGON_STIPPLE);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 0, 0); glVertex2f(3.5f, 3.5f);
    glColor3f(0, 1, 0); glVertex2f(120.5f, 10.2f);
    glColor3f(0, 0, 1); glVertex2f(60.3f, 120.7f);
    glEnd();
    glShadeModel(GL_FLAT);
    glBegin(GL_QUADS);
    prims_color(3); glVertex2f(130.5f, 5.5f);
    prims_color(4); glVertex2f(250.5f, 8.5f);
    prims_color(5); glVertex2f(245.5f, 120.5f);
    prims_color(6); glVertex2f(135.5f, 110.5f);
    glEnd();
    glShadeModel(GL_SMOOTH);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_TRUE);
    glPolygonStipple(pat);
    glPixelStorei(GL_UNPACK_LSB_FIRST, GL_FALSE);
    glViewport(7, 3, 256, 256);
    glBegin(GL_POLYGON);
    for (i = 0; i < 7; i++) {
        float a = (float)i * 6.2831853f / 7.0f;
        prims_color(i);
        glVertex2f(64.0f + 55.0f * cosf(a), 190.0f + 55.0f * sinf(a));
    }
    glEnd();
    glViewport(0, 0, 256, 256);
    glDisable(GL_POLYGON_STIPPLE);
    glBegin(GL_TRIANGLES);
    glColor3f(1, 1, 0); glVertex2f(140.5f, 140.5f);
    glColor3f(0, 1, 1); glVertex2f(250.5f, 150.2f);
    glColor3f(1, 0, 1); glVertex2f(190.3f, 250.7f);
    glEnd();
    prims_end(out, "stipple");

    glGetPolygonStipple(back);
    glPixelStorei(GL_PACK_LSB_FIRST, GL_TRUE);
    glGetPolygonStipple(back_lsb);
    for (i = 0; i < 16; i++)
        n += snprintf(txt + n, sizeof txt - (size_t)n, "%02x/%02x ", back[i], back_lsb[i]);
    n += snprintf(txt + n, sizeof txt - (size_t)n, "enabled %d err 0x%x\n",
                  glIsEnabled(GL_POLYGON_STIPPLE), glGetError());
    sgl_text(out, "readback", "%s", txt);
    prims_close(out);
    return 0;
}
