/* dlist_scene: display lists drawing geometry.
 * Cells (85x85, 3 per row):
 *   0 a smooth GL_QUADS quad compiled into a list (Mesa draws list geometry indexed:
 *     v1-v3 diagonal) and the same quad in immediate mode beside it (v0-v2)
 *   1 nesting: a list that translates/rotates and calls cell 0's list twice
 *   2 GL_COMPILE_AND_EXECUTE with lighting, material and normals inside the list
 *   3 a tiny "font" of lists called with glListBase + glCallLists of every type
 *   4 glDrawArrays/glDrawElements compiled into a list, then the arrays change
 *   5 a list whose vertex colour first appears after some vertices (Mesa's loopback)
 *   6 merged strips, line strips and fans in one list; glRect in a list
 *   7 texture binding, texture parameters and texenv inside a list
 *   8 glNewList(n, GL_COMPILE_AND_EXECUTE) calling the old list n; 70-deep nesting */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

static float cx(int cell) { return 0.37f + (cell % 3) * 85.0f; }
static float cy(int cell) { return 0.61f + (cell / 3) * 85.0f; }

static const GLfloat qv[4][2] = {{3.3f, 5.1f}, {39.7f, 2.9f}, {35.1f, 40.3f}, {1.9f, 36.6f}};
static const GLfloat qc[4][3] = {{1.0f, 0.9f, 0.2f}, {0.0f, 0.1f, 0.4f},
                                 {0.9f, 1.0f, 0.8f}, {0.2f, 0.0f, 0.1f}};

static void quad(void)
{
    int i;
    glBegin(GL_QUADS);
    for (i = 0; i < 4; i++) {
        glColor3fv(qc[i]);
        glVertex2fv(qv[i]);
    }
    glEnd();
}

static void cell(int c)
{
    glLoadIdentity();
    glTranslatef(cx(c), cy(c), 0.0f);
}

/* glyph k: k+1 small bars, then advance */
static void glyph(int k)
{
    int i;
    glColor3f(0.2f + 0.08f * k, 1.0f - 0.07f * k, 0.5f);
    glBegin(GL_QUADS);
    for (i = 0; i <= k % 4; i++) {
        glVertex2f(0.0f, 2.0f * i);
        glVertex2f(5.0f, 2.0f * i);
        glVertex2f(5.0f, 2.0f * i + 1.0f);
        glVertex2f(0.0f, 2.0f * i + 1.0f);
    }
    glEnd();
    glTranslatef(7.0f, 0.0f, 0.0f);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf;
    GLuint lq, lnest, lce, font, larr, ldang, lstrip, ltex, lself, chain, tex;
    GLfloat mv[16];
    int i;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.3f, 0.3f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -100.0, 100.0);
    glMatrixMode(GL_MODELVIEW);

    /* 0 */
    lq = glGenLists(1);
    glNewList(lq, GL_COMPILE);
    quad();
    glEndList();
    cell(0);
    glCallList(lq);
    glTranslatef(42.0f, 0.0f, 0.0f);
    quad();

    /* 1 */
    lnest = glGenLists(1);
    glNewList(lnest, GL_COMPILE);
    glPushMatrix();
    glScalef(0.9f, 0.9f, 1.0f);
    glCallList(lq);
    glTranslatef(60.0f, 10.0f, 0.0f);
    glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
    glCallList(lq);
    glPopMatrix();
    glEndList();
    cell(1);
    glCallList(lnest);
    glTranslatef(10.0f, 45.0f, 0.0f);
    glCallList(lnest);

    /* 2: compile and execute, then call again elsewhere */
    cell(2);
    lce = glGenLists(1);
    glNewList(lce, GL_COMPILE_AND_EXECUTE);
    {
        static const GLfloat pos[4] = {0.3f, 0.5f, 1.0f, 0.0f};
        static const GLfloat dif[4] = {0.9f, 0.6f, 0.3f, 1.0f};
        static const GLfloat amb[4] = {0.1f, 0.1f, 0.2f, 1.0f};
        glEnable(GL_LIGHTING);
        glEnable(GL_LIGHT0);
        glLightfv(GL_LIGHT0, GL_POSITION, pos);
        glMaterialfv(GL_FRONT, GL_DIFFUSE, dif);
        glMaterialfv(GL_FRONT, GL_AMBIENT, amb);
        glBegin(GL_TRIANGLES);
        glNormal3f(0.0f, 0.0f, 1.0f);
        glVertex2f(2.0f, 2.0f);
        glNormal3f(0.6f, 0.0f, 0.8f);
        glVertex2f(38.0f, 4.0f);
        glNormal3f(0.0f, 0.6f, 0.8f);
        glVertex2f(20.0f, 38.0f);
        glEnd();
        glDisable(GL_LIGHTING);
    }
    glEndList();
    glTranslatef(40.0f, 40.0f, 0.0f);
    glCallList(lce);

    /* 3: font */
    font = glGenLists(10);
    for (i = 0; i < 10; i++) {
        glNewList(font + i, GL_COMPILE);
        glyph(i);
        glEndList();
    }
    cell(3);
    glListBase(font - '0');
    glCallLists(5, GL_UNSIGNED_BYTE, "31415");
    glListBase(font);
    {
        static const GLbyte b[3] = {1, 2, 3};
        static const GLshort s[3] = {4, 5, 6};
        static const GLushort us[2] = {7, 8};
        static const GLint in[2] = {9, 0};
        static const GLuint ui[2] = {1, 2};
        static const GLfloat fl[3] = {3.7f, 4.2f, 5.9f};
        static const GLubyte b2[4] = {0, 6, 0, 7};
        static const GLubyte b3[3] = {0, 0, 8};
        static const GLubyte b4[4] = {0, 0, 0, 9};
        glLoadIdentity();
        glTranslatef(cx(3), cy(3) + 10.0f, 0.0f);
        glCallLists(3, GL_BYTE, b);
        glCallLists(3, GL_SHORT, s);
        glLoadIdentity();
        glTranslatef(cx(3), cy(3) + 20.0f, 0.0f);
        glCallLists(2, GL_UNSIGNED_SHORT, us);
        glCallLists(2, GL_INT, in);
        glCallLists(2, GL_UNSIGNED_INT, ui);
        glLoadIdentity();
        glTranslatef(cx(3), cy(3) + 30.0f, 0.0f);
        glCallLists(3, GL_FLOAT, fl);
        glCallLists(2, GL_2_BYTES, b2);
        glCallLists(1, GL_3_BYTES, b3);
        glCallLists(1, GL_4_BYTES, b4);
        /* glCallLists compiled into a list: the names are read now, the base later */
        larr = glGenLists(1);
        glNewList(larr, GL_COMPILE);
        glCallLists(3, GL_UNSIGNED_BYTE, "\001\002\003");
        glEndList();
        glLoadIdentity();
        glTranslatef(cx(3), cy(3) + 40.0f, 0.0f);
        glCallList(larr);
        glListBase(font + 4);
        glCallList(larr);
        glListBase(0);
        glDeleteLists(larr, 1);
    }

    /* 4: arrays dereferenced at compile time */
    {
        static GLfloat v[8][2] = {{0, 0}, {30, 0}, {30, 30}, {0, 30},
                                  {35, 0}, {70, 5}, {65, 35}, {40, 30}};
        static GLubyte col[8][4] = {{255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255},
                                    {255, 255, 0, 255}, {255, 0, 255, 255}, {0, 255, 255, 255},
                                    {128, 128, 128, 255}, {255, 128, 0, 255}};
        static const GLushort el[6] = {4, 5, 6, 4, 6, 7};
        cell(4);
        glEnableClientState(GL_VERTEX_ARRAY);
        glEnableClientState(GL_COLOR_ARRAY);
        glVertexPointer(2, GL_FLOAT, 0, v);
        glColorPointer(4, GL_UNSIGNED_BYTE, 0, col);
        glColor3f(0.1f, 0.2f, 0.9f);
        larr = glGenLists(1);
        glNewList(larr, GL_COMPILE);
        glDrawArrays(GL_QUADS, 0, 4);
        glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, el);
        glEndList();
        for (i = 0; i < 8; i++) {
            v[i][1] += 40.0f;
            col[i][0] = (GLubyte)(255 - col[i][0]);
        }
        glCallList(larr);
        glDrawArrays(GL_QUADS, 0, 4);
        glDisableClientState(GL_COLOR_ARRAY);
        glDisableClientState(GL_VERTEX_ARRAY);
        /* the list's vertex colours leave the current colour unchanged */
        glBegin(GL_TRIANGLES);
        glVertex2f(72.0f, 40.0f);
        glVertex2f(84.0f, 40.0f);
        glVertex2f(78.0f, 80.0f);
        glEnd();
    }

    /* 5: colour first given after some vertices of the list */
    ldang = glGenLists(1);
    glNewList(ldang, GL_COMPILE);
    glBegin(GL_QUADS);
    glVertex2fv(qv[0]);
    glVertex2fv(qv[1]);
    glColor3fv(qc[2]);
    glVertex2fv(qv[2]);
    glColor3fv(qc[3]);
    glVertex2fv(qv[3]);
    glEnd();
    glEndList();
    cell(5);
    glColor3f(1.0f, 1.0f, 1.0f);
    glCallList(ldang);
    glTranslatef(42.0f, 0.0f, 0.0f);
    glColor3f(0.0f, 1.0f, 0.0f);
    glCallList(ldang);

    /* 6: strips, line strips, fans, glRect */
    lstrip = glGenLists(1);
    glNewList(lstrip, GL_COMPILE);
    for (i = 0; i < 2; i++) {
        glBegin(GL_TRIANGLE_STRIP);
        glColor3f(1.0f, 0.3f * i, 0.0f);
        glVertex2f(2.0f + 20 * i, 2.0f);
        glColor3f(0.0f, 1.0f, 0.3f);
        glVertex2f(2.0f + 20 * i, 20.0f);
        glColor3f(0.2f, 0.0f, 1.0f);
        glVertex2f(12.0f + 20 * i, 3.0f);
        glVertex2f(13.0f + 20 * i, 19.0f);
        glColor3f(1.0f, 1.0f, 1.0f);
        glVertex2f(18.0f + 20 * i, 4.0f);
        glEnd();
    }
    for (i = 0; i < 2; i++) {
        glBegin(GL_LINE_STRIP);
        glColor3f(1.0f, 1.0f, 0.0f);
        glVertex2f(2.5f, 25.5f + 4 * i);
        glVertex2f(30.5f, 27.5f + 4 * i);
        glColor3f(0.0f, 1.0f, 1.0f);
        glVertex2f(60.5f, 24.5f + 4 * i);
        glEnd();
    }
    glBegin(GL_LINES);
    glVertex2f(2.5f, 35.5f);
    glVertex2f(70.5f, 36.5f);
    glEnd();
    glBegin(GL_TRIANGLE_FAN);
    glColor3f(0.9f, 0.9f, 0.9f);
    glVertex2f(60.0f, 60.0f);
    glColor3f(0.9f, 0.0f, 0.0f);
    glVertex2f(80.0f, 60.0f);
    glColor3f(0.0f, 0.9f, 0.0f);
    glVertex2f(75.0f, 75.0f);
    glColor3f(0.0f, 0.0f, 0.9f);
    glVertex2f(60.0f, 80.0f);
    glEnd();
    glColor3f(0.5f, 0.1f, 0.7f);
    glRectf(5.0f, 45.0f, 25.0f, 60.0f);
    glRecti(30, 45, 50, 60);
    glEndList();
    cell(6);
    glCallList(lstrip);

    /* 7: texture state in a list */
    {
        GLubyte texels[4 * 4 * 4];
        for (i = 0; i < 16; i++) {
            texels[4 * i + 0] = (GLubyte)(i * 16);
            texels[4 * i + 1] = (GLubyte)(255 - i * 16);
            texels[4 * i + 2] = (GLubyte)((i % 3) * 120);
            texels[4 * i + 3] = 255;
        }
        glGenTextures(1, &tex);
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
        glBindTexture(GL_TEXTURE_2D, 0);
        ltex = glGenLists(1);
        glNewList(ltex, GL_COMPILE);
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        glEnable(GL_TEXTURE_2D);
        glBegin(GL_QUADS);
        glColor3f(1.0f, 1.0f, 1.0f);
        glTexCoord2f(0.0f, 0.0f);
        glVertex2f(2.0f, 2.0f);
        glColor3f(1.0f, 0.5f, 0.5f);
        glTexCoord2f(1.0f, 0.0f);
        glVertex2f(70.0f, 4.0f);
        glColor3f(0.5f, 1.0f, 0.5f);
        glTexCoord2f(1.0f, 1.0f);
        glVertex2f(66.0f, 75.0f);
        glColor3f(0.5f, 0.5f, 1.0f);
        glTexCoord2f(0.0f, 1.0f);
        glVertex2f(5.0f, 70.0f);
        glEnd();
        glDisable(GL_TEXTURE_2D);
        glBindTexture(GL_TEXTURE_2D, 0);
        glEndList();
        cell(7);
        glCallList(ltex);

        /* glTexImage2D/glTexSubImage2D in a list: the pixels are read at compile time,
         * with the unpack state of that time */
        {
            static GLubyte img[6 * 4 * 3], sub[2 * 2 * 3];
            GLuint t2, limg;
            for (i = 0; i < 6 * 4 * 3; i++)
                img[i] = (GLubyte)(i * 37);
            for (i = 0; i < 2 * 2 * 3; i++)
                sub[i] = (GLubyte)(255 - i * 20);
            glGenTextures(1, &t2);
            glBindTexture(GL_TEXTURE_2D, t2);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glPixelStorei(GL_UNPACK_ROW_LENGTH, 6);
            limg = glGenLists(1);
            glNewList(limg, GL_COMPILE);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, img);
            glPixelStorei(GL_UNPACK_ROW_LENGTH, 0); /* executes now */
            glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, GL_RGB, GL_UNSIGNED_BYTE, sub);
            glEndList();
            for (i = 0; i < 6 * 4 * 3; i++)
                img[i] = 0;
            for (i = 0; i < 2 * 2 * 3; i++)
                sub[i] = 0;
            glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
            /* replaced now, and redefined again by the list */
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 2, 2, 0, GL_RGB, GL_UNSIGNED_BYTE, sub);
            glCallList(limg);
            glEnable(GL_TEXTURE_2D);
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
            glBegin(GL_QUADS);
            glTexCoord2f(0.0f, 0.0f);
            glVertex2f(72.0f, 50.0f);
            glTexCoord2f(1.0f, 0.0f);
            glVertex2f(84.0f, 50.0f);
            glTexCoord2f(1.0f, 1.0f);
            glVertex2f(84.0f, 82.0f);
            glTexCoord2f(0.0f, 1.0f);
            glVertex2f(72.0f, 82.0f);
            glEnd();
            glDisable(GL_TEXTURE_2D);
            glBindTexture(GL_TEXTURE_2D, 0);
        }
    }

    /* 8: redefining a list that the new definition calls; deep nesting */
    lself = glGenLists(1);
    glNewList(lself, GL_COMPILE);
    glColor3f(1.0f, 0.0f, 0.0f);
    glRectf(0.0f, 0.0f, 10.0f, 10.0f);
    glEndList();
    cell(8);
    glNewList(lself, GL_COMPILE_AND_EXECUTE);
    glCallList(lself);
    glTranslatef(12.0f, 0.0f, 0.0f);
    glColor3f(0.0f, 0.0f, 1.0f);
    glRectf(0.0f, 0.0f, 10.0f, 10.0f);
    glEndList();
    glLoadIdentity();
    glTranslatef(cx(8), cy(8) + 15.0f, 0.0f);
    glCallList(lself); /* recursion stops at the nesting limit */
    glGetFloatv(GL_MODELVIEW_MATRIX, mv);
    sgl_text(out, "self_recursion_tx", "%g %g\n", mv[12], mv[13]);

    chain = glGenLists(70);
    for (i = 0; i < 70; i++) {
        glNewList(chain + i, GL_COMPILE);
        glTranslatef(1.0f, 0.0f, 0.0f);
        if (i == 69) {
            glColor3f(0.0f, 1.0f, 0.0f);
            glRectf(0.0f, 0.0f, 5.0f, 5.0f);
        } else {
            glCallList(chain + i + 1);
        }
        glEndList();
    }
    glLoadIdentity();
    glTranslatef(cx(8), cy(8) + 50.0f, 0.0f);
    glCallList(chain);
    glGetFloatv(GL_MODELVIEW_MATRIX, mv);
    sgl_text(out, "chain_tx", "%g\n", mv[12] - cx(8));
    glLoadIdentity();
    glTranslatef(cx(8), cy(8) + 60.0f, 0.0f);
    glCallList(chain + 10);
    glGetFloatv(GL_MODELVIEW_MATRIX, mv);
    sgl_text(out, "chain10_tx", "%g\n", mv[12] - cx(8));
    sgl_text(out, "error", "0x%x\n", glGetError());

    glFinish();
    sgl_image(out, "scene", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
