/* osmesa_contexts: several OSMesa contexts, each on its own buffer. Context B shares
 * A's objects (OSMesaCreateContextExt sharelist): a texture and a vertex buffer made
 * in A are used by name in B. Context C shares nothing: the same names are unknown there.
 * Then A is resized (MakeCurrent with a new size: new zeroed buffer, old viewport kept),
 * rebound to a GL_UNSIGNED_SHORT buffer and back, and OSMesaColorClamp /
 * OSMesaPostprocess are called (accepted). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 48
#define H 40

static void draw_textured(GLuint tex, GLuint vbo)
{
    glClearColor(0.2f, 0.1f, 0.4f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, tex);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glVertexPointer(2, GL_FLOAT, 4 * sizeof(float), (void *)0);
    glTexCoordPointer(2, GL_FLOAT, 4 * sizeof(float), (void *)(2 * sizeof(float)));
    glColor3f(1.0f, 1.0f, 1.0f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisableClientState(GL_VERTEX_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDisable(GL_TEXTURE_2D);
}

int main(int argc, char **argv)
{
    static const float verts[] = {-0.9f, -0.9f, 0.0f, 0.0f, 0.9f, -0.7f, 1.0f, 0.0f,
                                  -0.2f, 0.9f, 0.5f, 1.0f};
    FILE *out = sgl_open(argc, argv);
    OSMesaContext a = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    OSMesaContext b = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, a);
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_BGRA, 16, 0, 0, NULL);
    unsigned char *ba = calloc(64 * 64 * 4, 1), *bb = calloc(W * H * 4, 1),
                  *bc = calloc(W * H * 4, 1);
    unsigned short *wide = calloc(W * H * 4, 2);
    unsigned char texels[4 * 4 * 4];
    GLuint tex = 0, vbo = 0;
    GLint vp[4], v;
    int i;
    SGL_CHECK(a && b && c && ba && bb && bc && wide);
    OSMesaPostprocess(a, "pp_nored", 0);
    for (i = 0; i < 16; i++) {
        texels[4 * i + 0] = (unsigned char)(i * 16);
        texels[4 * i + 1] = (unsigned char)(255 - i * 13);
        texels[4 * i + 2] = (unsigned char)((i % 3) * 120);
        texels[4 * i + 3] = 255;
    }

    /* A: make the objects, draw with them */
    SGL_CHECK(OSMesaMakeCurrent(a, ba, GL_UNSIGNED_BYTE, W, H));
    OSMesaColorClamp(GL_TRUE);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glGenBuffers(1, &vbo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof verts, verts, GL_STATIC_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    draw_textured(tex, vbo);
    glFinish();
    sgl_image(out, "a", W, H, 4, "RGBA", W * 4, 1, ba);

    /* B (shares with A): same names, same picture on its own buffer */
    SGL_CHECK(OSMesaMakeCurrent(b, bb, GL_UNSIGNED_BYTE, W, H));
    sgl_text(out, "b_names", "isTexture=%d isBuffer=%d err=0x%x\n", glIsTexture(tex),
             glIsBuffer(vbo), glGetError());
    draw_textured(tex, 0);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 4 * sizeof(float), (void *)0);
    glScalef(0.5f, 0.5f, 1.0f);
    glColor3f(0.0f, 1.0f, 0.3f);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisableClientState(GL_VERTEX_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glFinish();
    sgl_image(out, "b", W, H, 4, "RGBA", W * 4, 1, bb);

    /* C (own objects): the names mean nothing here */
    SGL_CHECK(OSMesaMakeCurrent(c, bc, GL_UNSIGNED_BYTE, W, H));
    sgl_text(out, "c_names", "isTexture=%d isBuffer=%d err=0x%x\n", glIsTexture(tex),
             glIsBuffer(vbo), glGetError());
    glClearColor(0.5f, 0.5f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, tex);
    glBegin(GL_TRIANGLES);
    glColor3f(0.9f, 0.2f, 0.1f);
    glTexCoord2f(0.5f, 0.5f);
    glVertex2f(-0.8f, -0.8f);
    glVertex2f(0.8f, -0.8f);
    glVertex2f(0.0f, 0.8f);
    glEnd();
    glFinish();
    sgl_image(out, "c", W, H, 4, "BGRA", W * 4, 1, bc);

    /* A again: the texture deleted from B is gone in A too */
    SGL_CHECK(OSMesaMakeCurrent(b, bb, GL_UNSIGNED_BYTE, W, H));
    glDeleteBuffers(1, &vbo);
    SGL_CHECK(OSMesaMakeCurrent(a, ba, GL_UNSIGNED_BYTE, W, H));
    sgl_text(out, "a_names", "isTexture=%d isBuffer=%d\n", glIsTexture(tex), glIsBuffer(vbo));

    /* resize A: a new zeroed buffer of 64x64, the viewport stays 48x40 */
    SGL_CHECK(OSMesaMakeCurrent(a, ba, GL_UNSIGNED_BYTE, 64, 64));
    glGetIntegerv(GL_VIEWPORT, vp);
    OSMesaGetIntegerv(OSMESA_WIDTH, &v);
    sgl_text(out, "resize", "viewport=%d,%d,%d,%d width=%d\n", vp[0], vp[1], vp[2], vp[3], v);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.5f, 0.25f);
    glVertex2f(-1.0f, -1.0f);
    glVertex2f(1.0f, -1.0f);
    glVertex2f(0.0f, 1.0f);
    glEnd();
    glFinish();
    sgl_image(out, "a_resized", 64, 64, 4, "RGBA", 64 * 4, 1, ba);

    /* A on a 16-bit buffer and back: each type change is a new zeroed buffer */
    SGL_CHECK(OSMesaMakeCurrent(a, wide, GL_UNSIGNED_SHORT, W, H));
    glGetIntegerv(GL_RED_BITS, &v);
    sgl_text(out, "wide", "red_bits=%d\n", v);
    glClearColor(0.0f, 0.6f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glFinish();
    sgl_data(out, "wide_px", 8, wide);
    SGL_CHECK(OSMesaMakeCurrent(a, ba, GL_UNSIGNED_BYTE, W, H));
    glGetIntegerv(GL_RED_BITS, &v);
    sgl_text(out, "narrow", "red_bits=%d\n", v);
    glBegin(GL_TRIANGLES);
    glColor3f(0.1f, 0.2f, 0.9f);
    glVertex2f(-1.0f, 1.0f);
    glVertex2f(1.0f, -1.0f);
    glVertex2f(1.0f, 1.0f);
    glEnd();
    glFinish();
    sgl_image(out, "a_back", W, H, 4, "RGBA", W * 4, 1, ba);
    sgl_text(out, "error", "glGetError=0x%x\n", glGetError());

    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(c);
    OSMesaDestroyContext(b);
    OSMesaDestroyContext(a);
    sgl_close(out);
    free(ba);
    free(bb);
    free(bc);
    free(wide);
    return 0;
}
