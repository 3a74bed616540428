/* tex_color_index: glTexImage2D / glTexSubImage2D of GL_COLOR_INDEX data (GL_BITMAP,
 * unsigned byte and float indices) turned into RGBA by GL_INDEX_SHIFT/OFFSET and the
 * GL_PIXEL_MAP_I_TO_* maps, into RGBA, RGB and luminance textures, directly and compiled
 * in display lists (piglit's gl-1.1-read-pixels-after-display-list), plus the errors of
 * index uploads.  Dumps the texels (glGetTexImage), a textured drawing and the error
 * codes. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 64
#define H 32

static char log_buf[4096];
static int log_len;

static void note(const char *what)
{
    GLenum e = glGetError();
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, "%s=%x\n", what, e);
}

/* draws the bound 2D texture as a w x h quad at (x, y), GL_REPLACE */
static void quad(float x, float y, float w, float h)
{
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(x, y);
    glTexCoord2f(1, 0); glVertex2f(x + w, y);
    glTexCoord2f(1, 1); glVertex2f(x + w, y + h);
    glTexCoord2f(0, 1); glVertex2f(x, y + h);
    glEnd();
    glDisable(GL_TEXTURE_2D);
}

static void dump_tex(FILE *out, const char *name, int w, int h)
{
    static unsigned char texels[16 * 16 * 4];
    memset(texels, 0xcd, sizeof texels);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    sgl_data(out, name, (size_t)(w * h * 4), texels);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    static const GLfloat r2[] = {0, 1}, g2[] = {0, 0}, b2[] = {1, 0}, a2[] = {1, 1};
    static const GLfloat r8[] = {0.1f, 0.9f, 0.3f, 0.7f, 0.5f, 0.0f, 1.0f, 0.25f};
    static const GLfloat g8[] = {0.8f, 0.2f, 0.6f, 0.4f, 0.0f, 1.0f, 0.5f, 0.75f};
    static const GLfloat b8[] = {0.5f, 0.5f, 0.1f, 0.9f, 1.0f, 0.3f, 0.0f, 0.6f};
    static const GLfloat a8[] = {1.0f, 0.5f, 0.25f, 0.75f, 0.0f, 1.0f, 0.5f, 0.125f};
    static const GLubyte bits[] = {0x8f, 0xff, 0x7f, 0x70, 0xa5, 0x3c, 0x00, 0xff};
    GLubyte idx[16];
    GLfloat fidx[16];
    GLuint tex[4];
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    for (int i = 0; i < 16; i++) {
        idx[i] = (GLubyte)(i * 5 + 1);
        fidx[i] = (GLfloat)i * 0.75f + 0.4f;
    }
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glGenTextures(4, tex);
    for (int i = 0; i < 4; i++) {
        glBindTexture(GL_TEXTURE_2D, tex[i]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }

    /* 1: piglit's case: a 1x1 bitmap with two-entry maps, in a list compiled and run */
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 2, r2);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 2, g2);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 2, b2);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 2, a2);
    for (int k = 0; k < 4; k++) {
        glNewList(1, GL_COMPILE_AND_EXECUTE);
        glBindTexture(GL_TEXTURE_2D, tex[0]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_COLOR_INDEX, GL_BITMAP, &bits[k]);
        quad((float)(k * 4), 0, 4, 4);
        glEndList();
        note("list compile_and_execute");
        glTranslatef(0, 4, 0);
        glCallList(1);
        glTranslatef(0, -4, 0);
        glDeleteLists(1, 1);
        note("list call");
    }

    /* 2: an 8x4 bitmap into an RGB texture.  Rows of whole bytes, MSB first and no
     * skipping only: Mesa 22.3 (`_mesa_unpack_color_index_to_rgba_float`) reads an
     * index image as one run of width*height indices, so it ignores row padding,
     * GL_UNPACK_ROW_LENGTH and (measured) GL_UNPACK_LSB_FIRST; softgl unpacks index
     * images as glDrawPixels does, by the unpack state. */
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 8, 4, 0, GL_COLOR_INDEX, GL_BITMAP, bits);
    note("bitmap rgb");
    dump_tex(out, "bitmap_rgb", 8, 4);
    quad(16, 0, 16, 8);

    /* 3: byte and float indices through eight-entry maps, shifted and offset, with a
     * colour scale that must not apply (GL_MAP_COLOR and scale are for RGBA data) */
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 8, r8);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 8, g8);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_B, 8, b8);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 8, a8);
    glPixelTransferi(GL_INDEX_SHIFT, 1);
    glPixelTransferi(GL_INDEX_OFFSET, 3);
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    glBindTexture(GL_TEXTURE_2D, tex[2]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE, idx);
    note("ubyte rgba");
    dump_tex(out, "ubyte_rgba", 4, 4);
    quad(32, 0, 16, 16);
    glPixelTransferi(GL_INDEX_SHIFT, -1);
    glNewList(2, GL_COMPILE);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 2, 2, GL_COLOR_INDEX, GL_FLOAT, fidx);
    glEndList();
    glCallList(2);
    note("float sub in list");
    dump_tex(out, "float_sub", 4, 4);
    quad(48, 0, 16, 16);
    glBindTexture(GL_TEXTURE_2D, tex[3]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, 4, 4, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE,
                 idx);
    note("ubyte luminance_alpha");
    dump_tex(out, "ubyte_la", 4, 4);
    quad(32, 16, 16, 16);
    glPixelTransferi(GL_INDEX_SHIFT, 0);
    glPixelTransferi(GL_INDEX_OFFSET, 0);
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    glPixelTransferi(GL_MAP_COLOR, GL_FALSE);

    /* 4: errors */
    glBindTexture(GL_TEXTURE_2D, tex[3]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_SHORT_5_6_5, idx);
    note("index 565");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_INT_8_8_8_8, idx);
    note("index 8888");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 2, 0, GL_COLOR_INDEX, GL_UNSIGNED_BYTE,
                 idx);
    note("index into depth");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_BITMAP, idx);
    note("rgba bitmap");
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_COLOR_INDEX, GL_UNSIGNED_SHORT_4_4_4_4, idx);
    note("sub index 4444");
    glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 3, 2, 2, GL_COLOR_INDEX, GL_BITMAP, bits);
    note("sub index outside");
    dump_tex(out, "after_errors", 4, 4);

    glFinish();
    sgl_image(out, "tex_color_index", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "errors", "%s", log_buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
