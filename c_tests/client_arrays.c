/* client_arrays: client-side vertex arrays with many types and strides:
 * GL_DOUBLE and GL_SHORT and GL_INT vertices, GL_UNSIGNED_BYTE, GL_FLOAT,
 * GL_UNSIGNED_SHORT colours, 4-component colours, interleaved strides,
 * glInterleavedArrays (GL_C4UB_V3F, GL_C3F_V3F, GL_V2F), glArrayElement
 * inside glBegin/glEnd, glDrawArrays with a first offset and
 * glMultiDrawArrays. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
    unsigned char *buf;
    int i;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.0713f, 0.0f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);

    /* 1: double vertices (3 comps), ubyte colours (4 comps), tight */
    {
        static const GLdouble v[] = {3.37, 2.11, 0.0,  60.13, 5.5, 0.0,  20.7, 59.9, 0.0,
                                     62.2, 9.9, 0.0,   40.4, 62.6, 0.0,  9.1, 61.3, 0.0};
        static const GLubyte c[] = {255, 0, 0, 255,  0, 255, 0, 255,  0, 0, 255, 255,
                                    255, 255, 0, 255, 0, 255, 255, 255, 255, 0, 255, 255};
        glVertexPointer(3, GL_DOUBLE, 0, v);
        glColorPointer(4, GL_UNSIGNED_BYTE, 0, c);
        glDrawArrays(GL_TRIANGLES, 0, 6);
    }

    /* 2: short vertices (2 comps) with a padded stride, float colours (3) */
    {
        static const GLshort v[] = {66, 2, 777,  127, 9, 777,  70, 61, 777,  125, 58, 777};
        static const GLfloat c[] = {0.1337f, 0.8f, 0.3f,  0.9f, 0.1f, 0.6f,
                                    0.3f, 0.3f, 0.95f,    0.95f, 0.95f, 0.2f};
        glVertexPointer(2, GL_SHORT, 3 * sizeof(GLshort), v);
        glColorPointer(3, GL_FLOAT, 0, c);
        glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    }

    /* 3: int vertices, unsigned short colours, first = 2 */
    {
        static const GLint v[] = {0, 0,  0, 0,  131, 3,  190, 7,  160, 60,  133, 50};
        static const GLushort c[] = {0, 0, 0,  0, 0, 0,  65535, 0, 0,  0, 65535, 0,
                                     0, 0, 65535,  30000, 40000, 50000};
        glVertexPointer(2, GL_INT, 0, v);
        glColorPointer(3, GL_UNSIGNED_SHORT, 0, c);
        glDrawArrays(GL_TRIANGLE_FAN, 2, 4);
    }

    /* 4: a struct array: float x,y then ubyte rgba, stride 12 */
    {
        struct { GLfloat x, y; GLubyte c[4]; } s[5] = {
            {196.6f, 1.7f, {200, 10, 10, 255}},
            {253.3f, 8.8f, {10, 200, 10, 255}},
            {250.1f, 61.1f, {10, 10, 200, 255}},
            {221.0f, 40.0f, {250, 250, 10, 255}},
            {198.8f, 57.7f, {10, 250, 250, 255}}};
        glVertexPointer(2, GL_FLOAT, sizeof s[0], &s[0].x);
        glColorPointer(4, GL_UNSIGNED_BYTE, sizeof s[0], s[0].c);
        glDrawArrays(GL_POLYGON, 0, 5);
    }

    /* 5: glInterleavedArrays GL_C4UB_V3F */
    {
        struct { GLubyte c[4]; GLfloat v[3]; } s[6];
        for (i = 0; i < 6; i++) {
            s[i].c[0] = (GLubyte)(40 * i + 30);
            s[i].c[1] = (GLubyte)(250 - 37 * i);
            s[i].c[2] = (GLubyte)(i & 1 ? 255 : 60);
            s[i].c[3] = 255;
            s[i].v[0] = 3.3f + 20.1f * (i / 2) + (i & 1) * 7.7f;
            s[i].v[1] = (i & 1) ? 125.5f : 68.8f + i;
            s[i].v[2] = 0.0f;
        }
        glInterleavedArrays(GL_C4UB_V3F, 0, s);
        glDrawArrays(GL_QUAD_STRIP, 0, 6);
    }

    /* 6: glInterleavedArrays GL_C3F_V3F with an explicit larger stride */
    {
        GLfloat s[4][8];
        for (i = 0; i < 4; i++) {
            s[i][0] = (i == 0) ? 1.0f : 0.2f;
            s[i][1] = (i == 1) ? 1.0f : 0.13f;
            s[i][2] = (i >= 2) ? 0.9f : 0.3f;
            s[i][3] = 70.5f + ((i == 1 || i == 2) ? 55.25f : 0.0f) + i * 0.7f;
            s[i][4] = 69.3f + (i >= 2 ? 54.4f : 0.0f);
            s[i][5] = 0.0f;
            s[i][6] = s[i][7] = -1.0f; /* padding */
        }
        glInterleavedArrays(GL_C3F_V3F, 8 * sizeof(GLfloat), s);
        glDrawArrays(GL_QUADS, 0, 4);
    }

    /* 7: glArrayElement inside glBegin/glEnd, mixed with glVertex */
    {
        static const GLfloat v[] = {131.1f, 67.7f,  190.9f, 70.3f,  185.5f, 126.6f,
                                    135.3f, 120.2f, 160.1f, 95.5f};
        static const GLubyte c[] = {255, 128, 0,  0, 128, 255,  128, 255, 0,
                                    255, 0, 128,  255, 255, 255};
        glInterleavedArrays(GL_V2F, 0, v); /* disables the colour array */
        glEnableClientState(GL_COLOR_ARRAY);
        glColorPointer(3, GL_UNSIGNED_BYTE, 0, c);
        glBegin(GL_TRIANGLES);
        glArrayElement(0);
        glArrayElement(1);
        glArrayElement(4);
        glArrayElement(2);
        glArrayElement(3);
        glColor3f(0.2f, 0.2f, 0.2f); /* overridden by the array for 4 */
        glArrayElement(4);
        glEnd();
        /* the current colour after glArrayElement is the last array colour */
        glDisableClientState(GL_COLOR_ARRAY);
        glBegin(GL_TRIANGLES);
        glVertex2f(195.5f, 70.1f);
        glVertex2f(252.2f, 71.3f);
        glVertex2f(230.0f, 125.9f);
        glEnd();
        glEnableClientState(GL_COLOR_ARRAY);
    }

    /* 8: glMultiDrawArrays: several strips from one array */
    {
        GLfloat v[40 * 2];
        GLubyte c[40 * 3];
        GLint first[4] = {0, 10, 20, 31};
        GLsizei count[4] = {10, 8, 10, 9};
        for (i = 0; i < 40; i++) {
            int strip = i / 10, k = i % 10;
            v[2 * i] = 4.4f + k * 12.13f + strip * 1.7f;
            v[2 * i + 1] = 133.3f + strip * 30.1f + ((k & 1) ? 25.5f : 0.0f);
            c[3 * i] = (GLubyte)(k * 25);
            c[3 * i + 1] = (GLubyte)(strip * 80);
            c[3 * i + 2] = (GLubyte)(255 - k * 20);
        }
        glVertexPointer(2, GL_FLOAT, 0, v);
        glColorPointer(3, GL_UNSIGNED_BYTE, 0, c);
        glMultiDrawArrays(GL_TRIANGLE_STRIP, first, count, 4);
    }

    /* 9: colour array disabled: current colour is used */
    {
        static const GLfloat v[] = {140.5f, 140.5f, 250.5f, 150.5f, 200.0f, 250.0f};
        glDisableClientState(GL_COLOR_ARRAY);
        glColor4f(0.6137f, 0.3f, 0.9f, 1.0f);
        glVertexPointer(2, GL_FLOAT, 0, v);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "error", "glGetError=0x%04x\n", glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
