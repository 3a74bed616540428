/* fog_coord_array: GL_FOG_COORD_SRC = GL_FOG_COORD with the fog coordinate from
 * glFogCoordPointer (GL 1.4, EXT_fog_coord): GL_LINEAR, GL_EXP and GL_EXP2, float and
 * double arrays with a stride, a buffer object, negative coordinates (|c| is used),
 * glDrawArrays, glDrawElements, glArrayElement and a display list, and textured quads;
 * then the array state, glPushClientAttrib and the errors. */
#define GL_GLEXT_PROTOTYPES
#include "prims_common.h"
#include <GL/glext.h>

#define N 12

/* A strip of N vertices, 80x36 pixels at (x0, y0). */
static void strip_positions(GLfloat *pos, float x0, float y0)
{
    int i;
    for (i = 0; i < N; i++) {
        pos[2 * i] = x0 + 14.5f * (float)(i / 2) + 0.25f * (float)(i % 3);
        pos[2 * i + 1] = y0 + 35.0f * (float)(i % 2);
    }
}

int main(int argc, char **argv)
{
    static GLfloat pos[N * 2], fogf[N * 2], tc[N * 2];
    static GLdouble fogd[N];
    static const GLubyte idx[9] = {0, 1, 2, 3, 2, 1, 8, 9, 10};
    static const GLfloat fog_colour[4] = {0.7f, 0.75f, 0.9f, 1.0f};
    static const GLenum modes[3] = {GL_LINEAR, GL_EXP, GL_EXP2};
    static GLubyte tex[16 * 16 * 4];
    FILE *out = sgl_open(argc, argv);
    GLuint vbo, list;
    GLint iv[6], err[6];
    GLvoid *p;
    GLfloat cur;
    int i, m;

    prims_begin();
    for (i = 0; i < N; i++) {
        fogf[2 * i] = -2.0f + 1.1f * (float)i;   /* negative ones too */
        fogf[2 * i + 1] = 99.0f;                 /* skipped by the stride */
        fogd[i] = 0.4 * (double)(N - i) + 0.05;
        tc[2 * i] = (float)(i / 2) / 5.0f;
        tc[2 * i + 1] = (float)(i % 2);
    }
    for (i = 0; i < 16 * 16; i++) {
        tex[4 * i] = (GLubyte)(((i % 16) / 4 + (i / 64)) % 2 ? 230 : 40);
        tex[4 * i + 1] = (GLubyte)(i % 200);
        tex[4 * i + 2] = 120;
        tex[4 * i + 3] = 255;
    }
    glEnable(GL_FOG);
    glFogfv(GL_FOG_COLOR, fog_colour);
    glFogf(GL_FOG_START, 0.5f);
    glFogf(GL_FOG_END, 9.0f);
    glFogf(GL_FOG_DENSITY, 0.27f);
    glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
    glColor3f(0.9f, 0.3f, 0.1f);
    glVertexPointer(2, GL_FLOAT, 0, pos);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_FOG_COORD_ARRAY);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof(fogd), fogd, GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);

    for (m = 0; m < 3; m++) {
        float y = 212.0f - 70.0f * (float)m;
        glFogi(GL_FOG_MODE, (GLint)modes[m]);
        strip_positions(pos, 2.0f, y);
        glFogCoordPointer(GL_FLOAT, 2 * sizeof(GLfloat), fogf);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, N);
        glTranslatef(84.0f, 0.0f, 0.0f);
        glFogCoordPointer(GL_DOUBLE, 0, fogd);
        glDrawElements(GL_TRIANGLES, 9, GL_UNSIGNED_BYTE, idx);
        glTranslatef(84.0f, 0.0f, 0.0f);
        glBindBuffer(GL_ARRAY_BUFFER, vbo);
        glFogCoordPointerEXT(GL_DOUBLE, 0, (const GLvoid *)(2 * sizeof(GLdouble)));
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, N - 2);
        glLoadIdentity();
        glTranslatef(0.0f, -34.0f, 0.0f);
        /* glArrayElement, fog on textured quads, fog-coordinate source switched back */
        glFogCoordPointer(GL_FLOAT, 2 * sizeof(GLfloat), fogf);
        glBegin(GL_TRIANGLE_STRIP);
        for (i = 0; i < N; i += 1)
            glArrayElement(N - 1 - i);
        glEnd();
        glTranslatef(84.0f, 0.0f, 0.0f);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glEnable(GL_TEXTURE_2D);
        glTexCoordPointer(2, GL_FLOAT, 0, tc);
        glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, N);
        glDisableClientState(GL_TEXTURE_COORD_ARRAY);
        glDisable(GL_TEXTURE_2D);
        glTranslatef(84.0f, 0.0f, 0.0f);
        glFogi(GL_FOG_COORD_SRC, GL_FRAGMENT_DEPTH);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, N);
        glFogi(GL_FOG_COORD_SRC, GL_FOG_COORD);
        glLoadIdentity();
    }

    /* a display list reads the coordinates when it is compiled */
    glFogi(GL_FOG_MODE, GL_LINEAR);
    strip_positions(pos, 2.0f, 2.0f);
    glFogCoordPointer(GL_FLOAT, 2 * sizeof(GLfloat), fogf);
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, N);
    glEndList();
    for (i = 0; i < N; i++)
        fogf[2 * i] = 0.0f;
    glFogCoordf(3.5f);
    glCallList(list);
    glGetFloatv(GL_CURRENT_FOG_COORD, &cur);
    glTranslatef(84.0f, 0.0f, 0.0f);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, N);
    glLoadIdentity();
    prims_end(out, "fog");

    glFogCoordPointer(GL_DOUBLE, 24, fogd);
    glGetIntegerv(GL_FOG_COORD_ARRAY_TYPE, &iv[0]);
    glGetIntegerv(GL_FOG_COORD_ARRAY_STRIDE, &iv[1]);
    glGetIntegerv(GL_FOG_COORD_ARRAY, &iv[2]);
    glGetIntegerv(GL_FOG_COORD_ARRAY_BUFFER_BINDING, &iv[3]);
    glGetPointerv(GL_FOG_COORD_ARRAY_POINTER, &p);
    sgl_text(out, "state", "type 0x%x stride %d on %d vbo %d ptr_ok %d cur %g err 0x%x\n", iv[0],
             iv[1], iv[2], iv[3], p == (GLvoid *)fogd, cur, glGetError());
    glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
    glDisableClientState(GL_FOG_COORD_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glFogCoordPointer(GL_FLOAT, 0, (const GLvoid *)4);
    glGetIntegerv(GL_FOG_COORD_ARRAY_BUFFER_BINDING, &iv[3]);
    glPopClientAttrib();
    glGetIntegerv(GL_FOG_COORD_ARRAY_TYPE, &iv[0]);
    glGetIntegerv(GL_FOG_COORD_ARRAY_BUFFER_BINDING, &iv[4]);
    glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &iv[5]);
    sgl_text(out, "popped", "vbo_in %d type 0x%x on %d vbo %d bound %d\n", iv[3] == (GLint)vbo,
             iv[0], glIsEnabled(GL_FOG_COORD_ARRAY), iv[4], iv[5]);

    glFogCoordPointer(GL_INT, 0, fogf);
    err[0] = glGetError();
    glFogCoordPointer(GL_UNSIGNED_BYTE, 0, fogf);
    err[1] = glGetError();
    glEnableClientState(GL_FOG_COORD_ARRAY + 1);
    err[2] = glGetError();
    glBegin(GL_POINTS);
    glFogCoordPointer(GL_INT, 0, fogf);
    glEnd();
    err[3] = glGetError();
    glGetIntegerv(GL_FOG_COORD_ARRAY_TYPE, &iv[0]);
    glGetIntegerv(GL_FOG_COORD_ARRAY_STRIDE, &iv[1]);
    /* The stride is checked first.  (Mesa 22.3 then stores the negative stride anyway,
     * so nothing is queried after these.) */
    glFogCoordPointer(GL_FLOAT, -8, fogf);
    err[4] = glGetError();
    glFogCoordPointer(GL_SHORT, -8, fogf);
    err[5] = glGetError();
    sgl_text(out, "errors", "%x %x %x %x %x %x type 0x%x stride %d\n", err[0], err[1], err[2],
             err[3], err[4], err[5], iv[0], iv[1]);
    glDeleteBuffers(1, &vbo);
    prims_close(out);
    return 0;
}
