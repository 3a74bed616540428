/* bitmap_text: glBitmap glyphs drawn as text (raster position advance by
 * xmove/ymove), the raster colour latched at glRasterPos, fractional origins
 * and positions, GL_UNPACK_LSB_FIRST, row length / skip / alignment, zero-size
 * bitmaps that only move, the depth test against the raster z, blending,
 * an invalid raster position (no drawing, no move), display lists and errors. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 128
#define H 96

/* 8x10 glyphs, bottom row first */
static const unsigned char glyphs[4][10] = {
    {0x00, 0xC3, 0xC3, 0xC3, 0xFF, 0xC3, 0xC3, 0x66, 0x3C, 0x18}, /* A */
    {0x00, 0xFE, 0xC3, 0xC3, 0xC3, 0xFE, 0xC3, 0xC3, 0xC3, 0xFE}, /* B */
    {0x00, 0x7E, 0xE7, 0xC0, 0xC0, 0xC0, 0xC0, 0xC0, 0xE7, 0x7E}, /* C */
    {0x00, 0xFF, 0xC0, 0xC0, 0xC0, 0xFC, 0xC0, 0xC0, 0xC0, 0xFF}, /* E */
};

static void text(const char *s)
{
    for (; *s; s++) {
        int g = *s == 'A' ? 0 : *s == 'B' ? 1 : *s == 'C' ? 2 : 3;
        glBitmap(8, 10, 0.0f, 0.0f, 9.0f, 0.0f, glyphs[g]);
    }
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    static unsigned char wide[6 * 4];
    char errs[512];
    GLfloat rp[4];
    GLuint list;
    int n = 0, i;
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    for (i = 0; i < (int)sizeof wide; i++)
        wide[i] = (unsigned char)(i * 73 + 5);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.05f, 0.1f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

    glColor3f(1.0f, 1.0f, 0.0f);
    glRasterPos2i(3, 3);
    text("ABCEABBA");
    glColor3f(0.0f, 1.0f, 1.0f); /* not latched: same colour */
    text("CAB");
    glRasterPos2f(4.6f, 16.5f); /* latched now */
    text("EACB");
    /* fractional origin and negative move */
    glColor3f(1.0f, 0.3f, 0.6f);
    glRasterPos2f(120.2f, 30.7f);
    for (i = 0; i < 4; i++)
        glBitmap(8, 10, 2.5f, -1.25f, -11.0f, 1.5f, glyphs[i]);
    /* zero-size bitmaps only move */
    glRasterPos2i(3, 30);
    glBitmap(0, 0, 0, 0, 20.0f, 3.0f, NULL);
    glBitmap(0, 5, 0, 0, 5.0f, 0.0f, glyphs[0]);
    text("AB");
    /* LSB first, row length, skip pixels, alignment */
    glPixelStorei(GL_UNPACK_LSB_FIRST, 1);
    glRasterPos2i(3, 45);
    text("ABCE");
    glPixelStorei(GL_UNPACK_LSB_FIRST, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 20);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 3);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    glRasterPos2i(50, 45);
    glBitmap(13, 6, 0, 0, 0, 0, wide);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    /* depth test against the raster z */
    glEnable(GL_DEPTH_TEST);
    glColor3f(0.2f, 0.2f, 0.9f);
    glBegin(GL_QUADS);
    glVertex3f(70, 55, 0.0f);
    glVertex3f(110, 55, 0.0f);
    glVertex3f(110, 70, 0.0f);
    glVertex3f(70, 70, 0.0f);
    glEnd();
    glColor3f(1.0f, 1.0f, 1.0f);
    glRasterPos3f(68, 58, 0.5f); /* behind (z=-0.5 is nearer? ortho: -z) */
    text("ABCE");
    glRasterPos3f(68, 62, -0.5f);
    text("CAB");
    glDisable(GL_DEPTH_TEST);
    /* blending */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(1.0f, 0.5f, 0.0f, 0.5f);
    glRasterPos2i(3, 60);
    text("EEAA");
    glDisable(GL_BLEND);
    /* invalid raster position: no drawing and no move */
    glRasterPos2i(-10, 75);
    text("AB");
    glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
    n += snprintf(errs + n, sizeof errs - n, "invalid pos %g %g\n", rp[0], rp[1]);
    /* display list */
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    text("BEAC");
    glEndList();
    glColor3f(0.5f, 1.0f, 0.5f);
    glRasterPos2i(3, 80);
    glCallList(list);
    glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
    n += snprintf(errs + n, sizeof errs - n, "after list %g %g\n", rp[0], rp[1]);
    glRasterPos2i(60, 80);
    glCallList(list);
    /* errors */
    glGetError();
    glBitmap(-1, 2, 0, 0, 0, 0, glyphs[0]);
    n += snprintf(errs + n, sizeof errs - n, "neg %x\n", glGetError());
    glBitmap(8, 10, 0, 0, 0, 0, NULL);
    n += snprintf(errs + n, sizeof errs - n, "null %x\n", glGetError());

    glFinish();
    sgl_image(out, "bitmap_text", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "state", "%s", errs);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
