/* lines_textured: textured lines through the whole fragment pipeline: a
 * mipmapped checkerboard on lines of widths 1..7 at several angles (the level
 * of detail comes from the line's major axis), stretched coordinates that
 * minify, a perspective-projected fan of lines, GL_FLAT, two texture units
 * (GL_MODULATE then GL_ADD), stippled textured strips, and fogged lines
 * (linear and EXP) with and without texturing. */
#define GL_GLEXT_PROTOTYPES
#include "prim_tex_common.h"
#include <GL/glext.h>

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    GLuint checker, ramp;
    int i;
    prims_begin();
    checker = prim_tex_checker();
    ramp = prim_tex_ramp();

    /* widths and angles; texture coordinates repeat 1..12 times along the line */
    glBindTexture(GL_TEXTURE_2D, checker);
    glEnable(GL_TEXTURE_2D);
    for (i = 0; i < 14; i++) {
        float a = 0.23f * (float)i, len = 70.0f;
        float cx = 40.0f + 85.0f * (float)(i % 3), cy = 40.0f + 34.0f * (float)(i / 3);
        glLineWidth(1.0f + (float)(i % 7));
        glBegin(GL_LINES);
        glColor3f(1.0f, 1.0f - 0.05f * (float)i, 0.6f + 0.02f * (float)i);
        glTexCoord2f(0.1f, 0.2f + 0.05f * (float)i);
        glVertex2f(cx - 0.5f * len * cosf(a), cy - 0.5f * len * sinf(a));
        glColor3f(0.5f, 0.9f, 1.0f);
        glTexCoord2f(0.1f + 0.9f * (float)(1 + i), 0.7f);
        glVertex2f(cx + 0.5f * len * cosf(a), cy + 0.5f * len * sinf(a));
        glEnd();
    }
    prims_end(out, "widths");

    /* a perspective fan of textured lines, smooth then flat */
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, -0.6f, -2.0f);
    glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
    for (i = 0; i < 20; i++) {
        glShadeModel(i < 10 ? GL_SMOOTH : GL_FLAT);
        glLineWidth(1.0f + (float)(i % 4));
        glBegin(GL_LINE_STRIP);
        glColor3f(1.0f, 0.8f, 0.5f);
        glTexCoord2f((float)i * 0.1f, 0.0f);
        glVertex3f(-2.0f + 0.2f * (float)i, 0.0f, 0.0f);
        glColor3f(0.4f, 1.0f, 0.9f);
        glTexCoord2f((float)i * 0.1f, 4.0f);
        glVertex3f(-3.0f + 0.3f * (float)i, 8.0f, 0.0f);
        glTexCoord2f((float)i * 0.1f + 2.0f, 8.0f);
        glVertex3f(-3.5f + 0.35f * (float)i, 16.0f, 0.5f);
        glEnd();
    }
    glShadeModel(GL_SMOOTH);
    prims_end(out, "perspective");

    /* two units: checker MODULATE, then a luminance ramp ADDed; stippled strips */
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, PW, 0.0, PH, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, ramp);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    glActiveTexture(GL_TEXTURE0);
    for (i = 0; i < 8; i++) {
        glLineWidth(1.0f + (float)(i % 3));
        if (i >= 4) {
            glEnable(GL_LINE_STIPPLE);
            glLineStipple(1 + i % 2, (GLushort)(0x0F3F << (i % 3)));
        }
        glBegin(GL_LINE_STRIP);
        glColor3f(0.6f, 0.5f, 0.4f);
        glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 0.0f);
        glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 0.1f * (float)i);
        glVertex2f(10.0f, 15.0f + 30.0f * (float)i);
        glMultiTexCoord2f(GL_TEXTURE0, 3.0f, 0.5f);
        glMultiTexCoord2f(GL_TEXTURE1, 1.0f, 0.5f);
        glVertex2f(130.0f, 30.0f + 30.0f * (float)i);
        glMultiTexCoord2f(GL_TEXTURE0, 5.0f, 1.5f);
        glMultiTexCoord2f(GL_TEXTURE1, 2.0f, 0.9f);
        glVertex2f(245.0f, 10.0f + 31.0f * (float)i);
        glEnd();
    }
    glDisable(GL_LINE_STIPPLE);
    glActiveTexture(GL_TEXTURE1);
    glDisable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);
    prims_end(out, "multitexture");

    /* fog: linear and EXP, untextured then textured, in perspective */
    glClearColor(0.2f, 0.3f, 0.4f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    {
        static const GLfloat fogc[4] = {0.8f, 0.7f, 0.6f, 1.0f};
        glEnable(GL_FOG);
        glFogfv(GL_FOG_COLOR, fogc);
        glFogf(GL_FOG_START, 1.0f);
        glFogf(GL_FOG_END, 12.0f);
        glFogf(GL_FOG_DENSITY, 0.25f);
    }
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, -0.8f, -1.5f);
    glRotatef(-75.0f, 1.0f, 0.0f, 0.0f);
    for (i = 0; i < 24; i++) {
        if (i % 12 < 6)
            glDisable(GL_TEXTURE_2D);
        else
            glEnable(GL_TEXTURE_2D);
        glFogi(GL_FOG_MODE, i < 12 ? GL_LINEAR : GL_EXP);
        glShadeModel(i % 3 == 2 ? GL_FLAT : GL_SMOOTH);
        glLineWidth(1.0f + (float)(i % 3));
        glBegin(GL_LINES);
        glColor3f(1.0f, 0.2f + 0.03f * (float)i, 0.1f);
        glTexCoord2f(0.0f, 0.0f);
        glVertex3f(-3.0f + 0.25f * (float)i, 0.0f, 0.0f);
        glColor3f(0.1f, 1.0f, 0.3f);
        glTexCoord2f(1.0f, 6.0f);
        glVertex3f(-3.0f + 0.25f * (float)i, 20.0f, 0.0f);
        glEnd();
    }
    glDisable(GL_FOG);
    glDisable(GL_TEXTURE_2D);
    glShadeModel(GL_SMOOTH);
    prims_end(out, "fog");
    prims_close(out);
    return 0;
}
