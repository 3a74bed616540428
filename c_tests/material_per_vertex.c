/* material_per_vertex: glMaterial between glBegin and glEnd changes the material
 * of the following vertices only (Mesa's vbo keeps materials as per-vertex
 * attributes): diffuse, ambient, emission, specular and shininess changing along
 * triangle strips and quads, front and back faces with two-sided lighting,
 * GL_COLOR_MATERIAL tracking glColor per vertex while glMaterial sets the other
 * terms, a glMaterial before the first vertex, in a display list, and the
 * material left current after glEnd (glGetMaterialfv). */
#include "prims_common.h"

static void strip(float y0, int mode)
{
    int i;
    glBegin(GL_TRIANGLE_STRIP);
    for (i = 0; i < 10; i++) {
        float t = (float)i / 9.0f;
        GLfloat d[4] = {0.2f + 0.8f * t, 0.9f - 0.7f * t, 0.3f + 0.5f * (float)(i & 1), 1.0f};
        GLfloat e[4] = {0.1f * (float)(i % 3), 0.0f, 0.15f * t, 1.0f};
        GLfloat s[4] = {t, t, 1.0f - t, 1.0f};
        if (mode == 0)
            glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, d);
        else if (mode == 1)
            glMaterialfv(GL_FRONT, GL_AMBIENT_AND_DIFFUSE, d);
        else if (mode == 2) {
            glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, e);
            glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, s);
            glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 4.0f + 12.0f * (float)i);
        } else {
            glColor3f(d[0], d[2], d[1]);
            glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, s);
            glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 2.0f + 10.0f * (float)i);
        }
        glNormal3f(0.3f * (t - 0.5f), 0.2f, 1.0f);
        glVertex2f(10.0f + 236.0f * t, y0);
        glNormal3f(-0.3f * (t - 0.5f), -0.3f, 1.0f);
        glVertex2f(10.0f + 236.0f * t, y0 + 22.0f);
    }
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    static const GLfloat lpos[4] = {0.3f, 0.5f, 1.0f, 0.0f};
    static const GLfloat lpos1[4] = {120.0f, 200.0f, 60.0f, 1.0f};
    static const GLfloat red[4] = {1.0f, 0.1f, 0.1f, 1.0f};
    static const GLfloat blue[4] = {0.1f, 0.2f, 1.0f, 1.0f};
    static const GLfloat grey[4] = {0.5f, 0.5f, 0.5f, 1.0f};
    GLfloat got[4 * 4];
    GLuint list;
    int k;
    prims_begin();
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, lpos);
    glEnable(GL_LIGHT1);
    glLightfv(GL_LIGHT1, GL_POSITION, lpos1);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, grey);
    glLightfv(GL_LIGHT1, GL_SPECULAR, grey);
    for (k = 0; k < 4; k++) {
        if (k == 3) {
            glEnable(GL_COLOR_MATERIAL);
            glColorMaterial(GL_FRONT_AND_BACK, GL_DIFFUSE);
        }
        strip(8.0f + 30.0f * (float)k, k);
    }
    glDisable(GL_COLOR_MATERIAL);

    /* quads: glMaterial before the first vertex and between quads */
    glBegin(GL_QUADS);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glVertex2f(10.0f, 130.0f);
    glVertex2f(70.0f, 130.0f);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, blue);
    glVertex2f(70.0f, 170.0f);
    glVertex2f(10.0f, 170.0f);
    glVertex2f(80.0f, 130.0f);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, red);
    glVertex2f(140.0f, 130.0f);
    glVertex2f(140.0f, 170.0f);
    glVertex2f(80.0f, 170.0f);
    glEnd();

    /* two-sided: back faces (clockwise) get the back material set per vertex */
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glBegin(GL_TRIANGLES);
    for (k = 0; k < 6; k++) {
        GLfloat b[4] = {0.15f * (float)k, 1.0f - 0.15f * (float)k, 0.5f, 1.0f};
        GLfloat f[4] = {1.0f, 0.15f * (float)k, 0.2f, 1.0f};
        float x = 150.0f + 17.0f * (float)k;
        glMaterialfv(GL_BACK, GL_DIFFUSE, b);
        glMaterialfv(GL_FRONT, GL_DIFFUSE, f);
        glNormal3f(0.0f, 0.0f, 1.0f);
        glVertex2f(x, 130.0f);
        if (k & 1) {
            glVertex2f(x + 8.0f, 170.0f);
            glVertex2f(x + 16.0f, 130.0f);
        } else {
            glVertex2f(x + 16.0f, 130.0f);
            glVertex2f(x + 8.0f, 170.0f);
        }
    }
    glEnd();
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);

    /* in a display list */
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    strip(190.0f, 0);
    glEndList();
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, grey);
    glCallList(list);
    glBegin(GL_TRIANGLES);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glVertex2f(10.0f, 220.0f);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, red);
    glVertex2f(60.0f, 220.0f);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, blue);
    glVertex2f(35.0f, 250.0f);
    glEnd();
    prims_end(out, "material");
    glGetMaterialfv(GL_FRONT, GL_DIFFUSE, got);
    glGetMaterialfv(GL_FRONT, GL_SPECULAR, got + 4);
    glGetMaterialfv(GL_BACK, GL_DIFFUSE, got + 8);
    glGetMaterialfv(GL_FRONT, GL_SHININESS, got + 12);
    sgl_text(out, "current", "%.4f %.4f %.4f %.4f / %.4f %.4f %.4f / %.4f %.4f %.4f / %.2f\n",
             got[0], got[1], got[2], got[3], got[4], got[5], got[6], got[8], got[9], got[10],
             got[12]);
    prims_close(out);
    return 0;
}
