/* smooth_lines: GL_LINE_SMOOTH as tutorials use it (blending SRC_ALPHA,
 * ONE_MINUS_SRC_ALPHA): a fan of widths 1..8 (fractional too), short segments
 * (under one pixel), a line strip and loop with smooth colours, flat shading,
 * line stipple with smoothing, lines clipped by the viewport, smooth lines
 * with blending off, depth-tested smooth lines over a perspective grid, a
 * textured smooth line, and the smooth width range queries. */
#include "prims_common.h"

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    GLfloat r[2], g;
    int i;
    char text[256];
    static unsigned char tex[4 * 4 * 4];
    prims_begin();
    glGetFloatv(GL_SMOOTH_LINE_WIDTH_RANGE, r);
    glGetFloatv(GL_SMOOTH_LINE_WIDTH_GRANULARITY, &g);
    snprintf(text, sizeof text, "smooth line width range %g %g granularity %g\n", r[0], r[1],
             g);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_LINE_SMOOTH);
    glHint(GL_LINE_SMOOTH_HINT, GL_NICEST);
    /* a fan of widths */
    for (i = 0; i < 16; i++) {
        float a = (float)i * 6.2831853f / 16.0f + 0.05f;
        glLineWidth(0.5f + 0.5f * (float)i);
        glBegin(GL_LINES);
        prims_color(i);
        glVertex2f(64.3f, 64.6f);
        glVertex2f(64.3f + 60.0f * cosf(a), 64.6f + 60.0f * sinf(a));
        glEnd();
    }
    /* short segments (shorter than a pixel) and a degenerate one */
    glLineWidth(1.0f);
    glBegin(GL_LINES);
    for (i = 0; i < 8; i++) {
        prims_color(i + 20);
        glVertex2f(140.2f + 6.0f * (float)i, 10.5f);
        glVertex2f(140.2f + 6.0f * (float)i + 0.15f * (float)i, 10.5f + 0.1f * (float)i);
    }
    glVertex2f(200.5f, 10.5f);
    glVertex2f(200.5f, 10.5f);
    glEnd();
    /* smooth-coloured strip and loop, width 2 */
    glLineWidth(2.0f);
    glBegin(GL_LINE_STRIP);
    for (i = 0; i < 8; i++) {
        prims_color(i + 3);
        glVertex2f(140.0f + 14.0f * (float)i, 30.0f + 20.0f * (float)(i & 1));
    }
    glEnd();
    glLineWidth(1.5f);
    glBegin(GL_LINE_LOOP);
    glColor4f(1.0f, 0.2f, 0.2f, 1.0f);
    glVertex2f(150.0f, 70.0f);
    glColor4f(0.2f, 1.0f, 0.2f, 0.6f);
    glVertex2f(240.0f, 80.0f);
    glColor4f(0.2f, 0.2f, 1.0f, 0.3f);
    glVertex2f(200.0f, 120.0f);
    glEnd();
    /* flat shading */
    glShadeModel(GL_FLAT);
    glLineWidth(3.0f);
    glBegin(GL_LINES);
    glColor3f(1.0f, 1.0f, 0.0f);
    glVertex2f(140.0f, 130.0f);
    glColor3f(0.0f, 1.0f, 1.0f);
    glVertex2f(250.0f, 150.0f);
    glEnd();
    glShadeModel(GL_SMOOTH);
    /* stipple with smoothing */
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x0F3F);
    glLineWidth(1.0f);
    glBegin(GL_LINE_STRIP);
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex2f(10.0f, 140.0f);
    glVertex2f(120.0f, 160.0f);
    glVertex2f(60.0f, 200.0f);
    glEnd();
    glLineWidth(4.0f);
    glBegin(GL_LINES);
    glColor3f(1.0f, 0.5f, 0.0f);
    glVertex2f(10.0f, 130.0f);
    glVertex2f(125.0f, 128.0f);
    glEnd();
    glDisable(GL_LINE_STIPPLE);
    /* clipped by the viewport */
    glLineWidth(5.0f);
    glBegin(GL_LINES);
    glColor3f(0.7f, 0.3f, 1.0f);
    glVertex2f(-20.0f, 230.0f);
    glVertex2f(100.0f, 270.0f);
    glVertex2f(250.0f, 200.0f);
    glVertex2f(300.0f, 250.0f);
    glEnd();
    /* blending off: coverage goes to the alpha channel only */
    glDisable(GL_BLEND);
    glLineWidth(2.5f);
    glBegin(GL_LINES);
    glColor4f(0.9f, 0.9f, 0.4f, 0.8f);
    glVertex2f(10.0f, 215.0f);
    glVertex2f(130.0f, 245.0f);
    glEnd();
    glEnable(GL_BLEND);
    /* a textured smooth line */
    for (i = 0; i < 16; i++) {
        tex[4 * i + 0] = (unsigned char)(i * 16);
        tex[4 * i + 1] = (unsigned char)(255 - i * 16);
        tex[4 * i + 2] = (unsigned char)(i * 40);
        tex[4 * i + 3] = 255;
    }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glLineWidth(6.0f);
    glBegin(GL_LINES);
    glColor3f(1.0f, 1.0f, 1.0f);
    glTexCoord2f(0.0f, 0.1f);
    glVertex2f(140.0f, 180.0f);
    glTexCoord2f(1.0f, 0.9f);
    glVertex2f(250.0f, 190.0f);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    /* perspective, depth-tested grid */
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glViewport(128, 128, 128, 128);
    glTranslatef(0.0f, -0.5f, -3.0f);
    glRotatef(-60.0f, 1.0f, 0.0f, 0.0f);
    glLineWidth(1.0f);
    glBegin(GL_LINES);
    for (i = -4; i <= 4; i++) {
        glColor3f(0.3f, 1.0f, 0.3f);
        glVertex3f((float)i * 0.5f, -3.0f, 0.0f);
        glColor3f(0.3f, 0.3f, 1.0f);
        glVertex3f((float)i * 0.5f, 3.0f, 0.0f);
        glVertex3f(-3.0f, (float)i * 0.5f, 0.0f);
        glColor3f(1.0f, 0.3f, 0.3f);
        glVertex3f(3.0f, (float)i * 0.5f, 0.0f);
    }
    glEnd();
    prims_end(out, "smooth_lines");
    sgl_text(out, "ranges", "%s", text);
    prims_close(out);
    return 0;
}
