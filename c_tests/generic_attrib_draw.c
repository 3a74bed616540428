/* generic_attrib_draw: GL 2.0 generic vertex attributes drawn by fixed function
 * (compatibility profile, no program): glVertexAttrib*(0, ...) between glBegin
 * and glEnd emits a vertex (mixed with glVertex, every type and arity), and
 * outside glBegin/glEnd it does not; attributes 1-15 draw nothing; an enabled
 * attribute-0 array is the vertex array (alone, or winning over an enabled
 * GL_VERTEX_ARRAY), of every type, normalised or not, in client memory and in
 * a buffer object, with glDrawArrays, glDrawElements, glArrayElement and in a
 * display list; disabling it gives GL_VERTEX_ARRAY back. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

/* a cell of a 4x4 grid of 64-pixel cells: the modelview maps [0,1]^2 into it */
static void cell(int cx, int cy)
{
    glLoadIdentity();
    glTranslatef(cx * 64.0f + 3.0f, cy * 64.0f + 3.0f, 0.0f);
    glScalef(58.0f, 58.0f, 1.0f);
}

/* one triangle from an attribute-0 array in cell (cx, cy), in its centred half-size
 * square when `centred` (for signed data in [-1, 1]); integers are normalised */
static void attr0_triangle(int cx, int cy, int centred, GLint size, GLenum type,
                           GLsizei stride, const void *p)
{
    cell(cx, cy);
    if (centred) {
        glTranslatef(0.5f, 0.5f, 0.0f);
        glScalef(0.5f, 0.5f, 1.0f);
    }
    glVertexAttribPointer(0, size, type, type == GL_DOUBLE ? GL_FALSE : GL_TRUE, stride, p);
    glDrawArrays(GL_TRIANGLES, 0, 3);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf;
    GLuint vbo, list;
    int i;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.05f, 0.07f, 0.11f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);

    /* 1: immediate mode, attribute 0 in several types and arities, mixed with
     * glVertex; attributes 1 and 7 set between vertices change nothing */
    cell(0, 0);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.2f, 0.1f);
    glVertexAttrib2f(0, 0.03f, 0.05f);
    glVertexAttrib1f(1, 0.5f);
    glColor3f(0.1f, 1.0f, 0.3f);
    glVertexAttrib3d(0, 0.97, 0.11, 0.0);
    glVertexAttrib4f(7, 9.0f, 9.0f, 9.0f, 9.0f);
    glColor3f(0.2f, 0.3f, 1.0f);
    glVertex2f(0.41f, 0.93f);
    {
        static const GLfloat a[4] = {0.2f, 0.6f, 0.0f, 1.0f};
        static const GLdouble b[2] = {0.9, 0.7};
        static const GLfloat c[3] = {0.6f, 0.99f, 0.0f};
        glColor3f(0.9f, 0.9f, 0.2f);
        glVertexAttrib4fv(0, a);
        glVertexAttrib2dv(0, b);
        glVertexAttrib3fv(0, c);
    }
    glEnd();

    /* 2: integer attribute-0 forms in window-sized units (identity modelview) */
    glLoadIdentity();
    glBegin(GL_QUADS);
    glColor3f(0.8f, 0.4f, 0.9f);
    glVertexAttrib2s(0, 70, 4);
    glVertexAttrib3s(0, 124, 6, 0);
    {
        static const GLshort s4[4] = {120, 60, 0, 1};
        static const GLint i4[4] = {69, 58, 0, 1};
        glVertexAttrib4sv(0, s4);
        glVertexAttrib4iv(0, i4);
    }
    glEnd();
    glBegin(GL_TRIANGLES);
    glColor3f(0.3f, 0.9f, 0.9f);
    {
        static const GLubyte ub[4] = {134, 5, 0, 1};
        static const GLushort us[4] = {190, 10, 0, 1};
        static const GLuint ui[4] = {160, 61, 0, 1};
        static const GLbyte b4[4] = {120, 100, 0, 1};
        glVertexAttrib4ubv(0, ub);
        glVertexAttrib4usv(0, us);
        glVertexAttrib4uiv(0, ui);
        /* a w of 2 halves the position */
        glVertexAttrib4d(0, 400.0, 12.0, 0.0, 2.0);
        glVertexAttrib4bv(0, b4);
        glVertexAttrib4s(0, 250, 60, 0, 1);
    }
    glEnd();

    /* 3: glVertexAttrib(0) outside glBegin/glEnd emits nothing: the strip below
     * has only the three vertices given inside */
    cell(0, 1);
    glVertexAttrib2f(0, 0.5f, 0.5f);
    glVertexAttrib4Nub(0, 255, 255, 0, 255);
    glColor3f(1.0f, 0.6f, 0.0f);
    glBegin(GL_TRIANGLE_STRIP);
    glVertexAttrib2f(0, 0.1f, 0.1f);
    glVertexAttrib2f(0, 0.9f, 0.2f);
    glVertexAttrib2f(0, 0.3f, 0.8f);
    glEnd();
    /* normalised forms as positions in [0,1] (and [-1,1]) */
    cell(1, 1);
    glBegin(GL_TRIANGLES);
    glColor3f(0.5f, 1.0f, 0.5f);
    glVertexAttrib4Nub(0, 10, 20, 0, 255);
    {
        static const GLubyte nub[4] = {250, 40, 0, 255};
        static const GLushort nus[4] = {30000, 65000, 0, 65535};
        static const GLuint nui[4] = {4000000000u, 3000000000u, 0, 4294967295u};
        static const GLshort nsv[4] = {32000, 100, 0, 32767};
        static const GLbyte nbv[4] = {60, 127, 0, 127};
        static const GLint niv[4] = {2000000000, 1000000000, 0, 2147483647};
        glVertexAttrib4Nubv(0, nub);
        glVertexAttrib4Nusv(0, nus);
        glColor3f(0.2f, 0.5f, 1.0f);
        glVertexAttrib4Nuiv(0, nui);
        glVertexAttrib4Nsv(0, nsv);
        glVertexAttrib4Nbv(0, nbv);
        glColor3f(1.0f, 0.3f, 0.6f);
        glVertexAttrib4Niv(0, niv);
        glVertexAttrib2f(0, 0.98f, 0.98f);
        glVertexAttrib2f(0, 0.4f, 0.99f);
    }
    glEnd();

    /* 4: an attribute-0 float array alone (GL_VERTEX_ARRAY disabled), colours from
     * a colour array */
    {
        static const GLfloat p[] = {0.02f, 0.02f, 0.98f, 0.1f, 0.5f, 0.97f,
                                    0.1f, 0.9f, 0.9f, 0.95f, 0.6f, 0.3f};
        static const GLubyte c[] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255,
                                    255, 255, 0, 255, 0, 255, 255, 255, 255, 0, 255, 255};
        cell(2, 0);
        glEnableClientState(GL_COLOR_ARRAY);
        glColorPointer(4, GL_UNSIGNED_BYTE, 0, c);
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, p);
        glEnableVertexAttribArray(0);
        glDrawArrays(GL_TRIANGLES, 0, 6);
    }

    /* 5: attribute 0 wins over an enabled GL_VERTEX_ARRAY; disabled again, the
     * vertex array draws */
    {
        static const GLfloat p[] = {0.1f, 0.1f, 0.9f, 0.1f, 0.9f, 0.5f};
        static const GLfloat v[] = {0.1f, 0.55f, 0.9f, 0.6f, 0.2f, 0.95f};
        cell(3, 0);
        glDisableClientState(GL_COLOR_ARRAY);
        glColor3f(0.9f, 0.5f, 0.1f);
        glEnableClientState(GL_VERTEX_ARRAY);
        glVertexPointer(2, GL_FLOAT, 0, v);
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, p);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDisableVertexAttribArray(0);
        glColor3f(0.1f, 0.6f, 0.9f);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glDisableClientState(GL_VERTEX_ARRAY);
        /* neither enabled: nothing is drawn */
        glColor3f(1.0f, 1.0f, 1.0f);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    /* 6: every type, normalised and not, strides, in cells of row 2 */
    glEnableVertexAttribArray(0);
    {
        static const GLubyte ub[] = {5, 5, 0, 250, 10, 0, 128, 245, 0};
        static const GLbyte sb[] = {-120, -120, 0, 0, 120, -100, 0, 0, -10, 127, 0, 0};
        static const GLushort us[] = {1000, 2000, 64000, 9000, 30000, 60000};
        static const GLshort ss[] = {-32000, -30000, 32767, -31000, 0, 30000};
        static const GLuint ui[] = {100000000u, 200000000u, 4200000000u,
                                    500000000u, 2000000000u, 4100000000u};
        static const GLint si[] = {-2100000000, -2000000000, 2147483647,
                                   -1900000000, 100000000, 2000000000};
        static const GLdouble d[] = {0.05, 0.9, 0.5, 0.95, 0.08, 0.02, 0.95, 0.1, 0.2};
        static const GLshort raw[] = {3, 3, 55, 10, 20, 56};
        glColor3f(1.0f, 0.8f, 0.3f);
        attr0_triangle(0, 2, 0, 3, GL_UNSIGNED_BYTE, 0, ub);
        attr0_triangle(1, 2, 1, 2, GL_BYTE, 4, sb);
        glColor3f(0.4f, 1.0f, 0.7f);
        attr0_triangle(2, 2, 0, 2, GL_UNSIGNED_SHORT, 0, us);
        attr0_triangle(3, 2, 1, 2, GL_SHORT, 0, ss);
        glColor3f(0.7f, 0.5f, 1.0f);
        attr0_triangle(0, 3, 0, 2, GL_UNSIGNED_INT, 0, ui);
        attr0_triangle(1, 3, 1, 2, GL_INT, 0, si);
        glColor3f(1.0f, 0.4f, 0.4f);
        attr0_triangle(2, 3, 0, 3, GL_DOUBLE, 0, d);
        /* not normalised: integers are coordinates */
        glLoadIdentity();
        glTranslatef(192.0f, 192.0f, 0.0f);
        glVertexAttribPointer(0, 2, GL_SHORT, GL_FALSE, 0, raw);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glVertexAttribPointer(0, 1, GL_FLOAT, GL_FALSE, 0, d);
        glColor3f(0.3f, 0.3f, 1.0f);
        glTranslatef(10.0f, 30.0f, 0.0f);
        glScalef(50.0f, 1.0f, 1.0f);
        glDrawArrays(GL_POINTS, 0, 9);
    }

    /* 7: attribute 0 in a buffer object (offset pointer, padded stride) with
     * glDrawElements, and glArrayElement between glBegin and glEnd */
    {
        GLfloat data[4 * 8];
        for (i = 0; i < 8; i++) {
            data[4 * i + 0] = -1.0f;
            data[4 * i + 1] = (i & 1) ? 0.92f : 0.07f;
            data[4 * i + 2] = (i & 2) ? 0.93f : 0.06f;
            data[4 * i + 3] = 0.0f;
        }
        data[1 + 4 * 2] = 0.95f; /* a slanted edge */
        glGenBuffers(1, &vbo);
        glBindBuffer(GL_ARRAY_BUFFER, vbo);
        glBufferData(GL_ARRAY_BUFFER, sizeof data, data, GL_STATIC_DRAW);
        glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 16, (const void *)4);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        cell(1, 0);
        glScalef(0.5f, 1.0f, 1.0f);
        glColor3f(0.9f, 0.2f, 0.9f);
        {
            static const GLushort quad[] = {0, 1, 3, 3, 2, 0};
            glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_SHORT, quad);
        }
        glTranslatef(1.0f, 0.0f, 0.0f);
        glColor3f(0.2f, 0.9f, 0.4f);
        glBegin(GL_TRIANGLES);
        glArrayElement(0);
        glArrayElement(1);
        glArrayElement(2);
        glEnd();
    }

    /* 8: a display list: glVertexAttrib(0) inside glBegin/glEnd compiled as
     * vertices, and a compiled glDrawArrays of the attribute-0 array */
    {
        static const GLfloat p[] = {0.55f, 0.1f, 0.95f, 0.2f, 0.75f, 0.6f};
        list = glGenLists(1);
        glNewList(list, GL_COMPILE);
        glBegin(GL_TRIANGLES);
        glVertexAttrib2f(0, 0.05f, 0.6f);
        glVertexAttrib2f(0, 0.45f, 0.62f);
        glVertexAttrib2f(0, 0.2f, 0.97f);
        glEnd();
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, p);
        glDrawArrays(GL_TRIANGLES, 0, 3);
        glEndList();
        glDisableVertexAttribArray(0);
        cell(2, 1);
        glColor3f(0.95f, 0.95f, 0.5f);
        glCallList(list);
    }
    /* 9: attributes 1-15 arrays enabled (fixed function ignores them) */
    {
        static const GLfloat junk[64] = {0};
        static const GLfloat p[] = {0.1f, 0.1f, 0.9f, 0.3f, 0.4f, 0.9f};
        for (i = 1; i < 16; i++) {
            glVertexAttribPointer(i, 4, GL_FLOAT, GL_FALSE, 0, junk);
            glEnableVertexAttribArray(i);
        }
        glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, p);
        glEnableVertexAttribArray(0);
        cell(3, 1);
        glColor3f(0.6f, 0.8f, 1.0f);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    glFinish();
    sgl_image(out, "generic_attrib_draw", W, H, 4, "RGBA", W * 4, 1, buf);
    glDeleteBuffers(1, &vbo);
    OSMesaDestroyContext(ctx);
    free(buf);
    sgl_close(out);
    return 0;
}
