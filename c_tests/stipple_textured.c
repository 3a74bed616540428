/* stipple_textured: textured polygons under GL_POLYGON_STIPPLE: a minified
 * mipmapped checkerboard on a perspective ground plane, two texture units,
 * GL_FLAT, fog, alpha test, and a stippled textured polygon in GL_LINE mode
 * next to it (the textured edges). */
#define GL_GLEXT_PROTOTYPES
#include "prim_tex_common.h"
#include <GL/glext.h>

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    GLubyte pat[128];
    GLuint checker, ramp;
    int i;
    for (i = 0; i < 128; i++)
        pat[i] = (GLubyte)((i * 37) ^ (i >> 2) ^ 0x5A);
    prims_begin();
    checker = prim_tex_checker();
    ramp = prim_tex_ramp();
    glPolygonStipple(pat);
    glEnable(GL_POLYGON_STIPPLE);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, checker);

    /* ground plane */
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, -1.0f, -1.5f);
    glRotatef(-75.0f, 1.0f, 0.0f, 0.0f);
    glBegin(GL_QUADS);
    glColor3f(1.0f, 1.0f, 1.0f);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(-6.0f, 0.0f, 0.0f);
    glColor3f(0.7f, 1.0f, 0.8f);
    glTexCoord2f(6.0f, 0.0f);
    glVertex3f(6.0f, 0.0f, 0.0f);
    glColor3f(0.9f, 0.6f, 1.0f);
    glTexCoord2f(6.0f, 30.0f);
    glVertex3f(6.0f, 30.0f, 0.0f);
    glColor3f(1.0f, 0.9f, 0.4f);
    glTexCoord2f(0.0f, 30.0f);
    glVertex3f(-6.0f, 30.0f, 0.0f);
    glEnd();
    prims_end(out, "ground");

    /* ortho: two units, flat, fog, alpha test */
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, PW, 0.0, PH, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, ramp);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glActiveTexture(GL_TEXTURE0);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.5f, 0.2f);
    glMultiTexCoord2f(GL_TEXTURE0, 0.0f, 0.0f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.0f, 0.0f);
    glVertex2f(5.5f, 5.5f);
    glColor3f(0.2f, 1.0f, 0.5f);
    glMultiTexCoord2f(GL_TEXTURE0, 1.5f, 0.0f);
    glMultiTexCoord2f(GL_TEXTURE1, 1.0f, 0.2f);
    glVertex2f(120.3f, 10.2f);
    glColor3f(0.5f, 0.2f, 1.0f);
    glMultiTexCoord2f(GL_TEXTURE0, 0.3f, 1.2f);
    glMultiTexCoord2f(GL_TEXTURE1, 0.4f, 1.0f);
    glVertex2f(40.7f, 118.9f);
    glEnd();
    glActiveTexture(GL_TEXTURE1);
    glDisable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);

    glShadeModel(GL_FLAT);
    glBegin(GL_QUADS);
    glColor3f(0.3f, 0.9f, 1.0f);
    glTexCoord2f(0.0f, 0.0f);
    glVertex2f(130.0f, 5.0f);
    glTexCoord2f(0.25f, 0.0f);
    glVertex2f(250.0f, 5.0f);
    glTexCoord2f(0.25f, 0.25f);
    glVertex2f(250.0f, 120.0f);
    glColor3f(1.0f, 0.9f, 0.3f);
    glTexCoord2f(0.0f, 0.25f);
    glVertex2f(130.0f, 120.0f);
    glEnd();
    glShadeModel(GL_SMOOTH);

    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_LINEAR);
    glFogf(GL_FOG_START, -1.0f);
    glFogf(GL_FOG_END, 1.0f);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GEQUAL, 0.6f);
    glBegin(GL_QUADS);
    glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(10.0f, 130.0f, -0.9f);
    glTexCoord2f(2.0f, 0.0f);
    glVertex3f(120.0f, 130.0f, 0.9f);
    glTexCoord2f(2.0f, 2.0f);
    glVertex3f(120.0f, 250.0f, 0.9f);
    glTexCoord2f(0.0f, 2.0f);
    glVertex3f(10.0f, 250.0f, -0.9f);
    glEnd();
    glDisable(GL_ALPHA_TEST);
    glDisable(GL_FOG);

    /* GL_LINE polygon mode with stipple on (the stipple does not apply to lines) */
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glLineWidth(3.0f);
    glBegin(GL_POLYGON);
    for (i = 0; i < 6; i++) {
        float a = 1.0471976f * (float)i;
        glColor3f(1.0f, 0.5f + 0.08f * (float)i, 0.5f);
        glTexCoord2f(0.5f + 0.5f * cosf(a), 0.5f + 0.5f * sinf(a));
        glVertex2f(190.0f + 50.0f * cosf(a), 190.0f + 50.0f * sinf(a));
    }
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    prims_end(out, "ortho");
    prims_close(out);
    return 0;
}
