/* points_textured: textured points of sizes 1..12 (all attributes constant
 * over a point, so the texture is magnified and sampled at the vertex's
 * coordinate), texture coordinates with q != 1, two units, a perspective grid
 * of points, fogged points, and alpha-tested textured points. */
#define GL_GLEXT_PROTOTYPES
#include "prim_tex_common.h"
#include <GL/glext.h>

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    GLuint checker, ramp;
    int i, j;
    prims_begin();
    checker = prim_tex_checker();
    ramp = prim_tex_ramp();
    glBindTexture(GL_TEXTURE_2D, checker);
    glEnable(GL_TEXTURE_2D);
    for (i = 0; i < 12; i++) {
        glPointSize(1.0f + (float)i);
        glBegin(GL_POINTS);
        for (j = 0; j < 9; j++) {
            glColor3f(1.0f, 0.6f + 0.03f * (float)j, 0.9f);
            glTexCoord4f(0.07f * (float)j + 0.013f * (float)i, 0.11f * (float)i,
                         0.0f, 1.0f + 0.25f * (float)(j % 3));
            glVertex2f(12.3f + 20.0f * (float)i, 10.7f + 14.0f * (float)j);
        }
        glEnd();
    }
    /* two units */
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, ramp);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glActiveTexture(GL_TEXTURE0);
    glPointSize(5.0f);
    glBegin(GL_POINTS);
    for (i = 0; i < 40; i++) {
        glColor3f(0.9f, 0.9f, 0.9f);
        glMultiTexCoord2f(GL_TEXTURE0, 0.031f * (float)i, 0.5f);
        glMultiTexCoord2f(GL_TEXTURE1, 0.027f * (float)i, 0.3f);
        glVertex2f(8.5f + 6.0f * (float)i, 150.0f + 4.0f * (float)(i % 5));
    }
    glEnd();
    glActiveTexture(GL_TEXTURE1);
    glDisable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);
    /* alpha test on the checker's alpha (100 vs 255) */
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    glPointSize(7.0f);
    glBegin(GL_POINTS);
    for (i = 0; i < 30; i++) {
        glTexCoord2f(0.0625f * (float)i + 0.01f, 0.3f);
        glVertex2f(10.0f + 8.0f * (float)i, 190.0f);
    }
    glEnd();
    glDisable(GL_ALPHA_TEST);
    prims_end(out, "sizes");

    /* perspective grid with fog */
    glClearColor(0.1f, 0.1f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, -1.0f, -2.0f);
    glRotatef(-70.0f, 1.0f, 0.0f, 0.0f);
    glEnable(GL_FOG);
    glFogi(GL_FOG_MODE, GL_EXP2);
    glFogf(GL_FOG_DENSITY, 0.12f);
    for (j = 0; j < 12; j++) {
        glPointSize(1.0f + (float)(j % 4));
        glBegin(GL_POINTS);
        for (i = 0; i < 16; i++) {
            glColor3f(1.0f, 0.5f + 0.03f * (float)i, 0.3f);
            glTexCoord2f(0.0625f * (float)i, 0.08f * (float)j);
            glVertex3f(-4.0f + 0.5f * (float)i, 1.5f * (float)j, 0.0f);
        }
        glEnd();
    }
    glDisable(GL_FOG);
    prims_end(out, "perspective");
    prims_close(out);
    return 0;
}
