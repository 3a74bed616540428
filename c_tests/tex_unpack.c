/* tex_unpack: texture uploads through the pixel unpack path.  Sixteen small
 * textures, each uploaded differently, drawn magnified with NEAREST in a
 * 4x4 grid: GL_RGB and GL_LUMINANCE with odd widths and UNPACK_ALIGNMENT 1,
 * GL_RGB with alignment 8, UNPACK_ROW_LENGTH with SKIP_PIXELS/SKIP_ROWS,
 * GL_FLOAT (values outside [0,1]), the packed 16-bit types (5_6_5,
 * 4_4_4_4, 5_5_5_1 and their REV forms), GL_BGRA and GL_BGR, 8_8_8_8 and
 * 8_8_8_8_REV, GL_UNSIGNED_SHORT luminance-alpha, GL_ALPHA with skips.
 * Every texture is read back with glGetTexImage (RGBA ubyte), two also as
 * float and 5_6_5, and the component sizes Mesa chose are dumped. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256
#define N 16

struct upload {
    GLint internal;
    int w, h;
    GLenum format, type;
    int align, row_length, skip_pixels, skip_rows;
};

static const struct upload ups[N] = {
    {GL_RGB, 13, 7, GL_RGB, GL_UNSIGNED_BYTE, 1, 0, 0, 0},
    {GL_LUMINANCE, 11, 5, GL_LUMINANCE, GL_UNSIGNED_BYTE, 1, 0, 0, 0},
    {GL_RGBA, 9, 6, GL_RGBA, GL_UNSIGNED_BYTE, 4, 20, 3, 2},
    {GL_RGB, 7, 5, GL_RGB, GL_UNSIGNED_BYTE, 8, 0, 0, 0},
    {GL_RGBA, 8, 8, GL_RGBA, GL_FLOAT, 4, 0, 0, 0},
    {GL_RGB, 8, 4, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 2, 0, 0, 0},
    {GL_RGB, 7, 4, GL_RGB, GL_UNSIGNED_SHORT_5_6_5_REV, 2, 0, 0, 0},
    {GL_RGBA, 8, 4, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, 2, 0, 0, 0},
    {GL_RGBA, 8, 4, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4_REV, 2, 0, 0, 0},
    {GL_RGBA, 5, 4, GL_RGBA, GL_UNSIGNED_SHORT_5_5_5_1, 2, 0, 0, 0},
    {GL_RGBA, 8, 4, GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV, 2, 0, 0, 0},
    {GL_RGBA, 8, 4, GL_BGRA, GL_UNSIGNED_BYTE, 4, 0, 0, 0},
    {GL_RGB, 5, 3, GL_BGR, GL_UNSIGNED_BYTE, 1, 0, 0, 0},
    {GL_RGBA, 6, 4, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, 4, 0, 0, 0},
    {GL_LUMINANCE_ALPHA, 6, 6, GL_LUMINANCE_ALPHA, GL_UNSIGNED_SHORT, 4, 0, 0, 0},
    {GL_ALPHA, 5, 5, GL_ALPHA, GL_UNSIGNED_BYTE, 2, 9, 2, 3},
};

/* fills n bytes of source data deterministically (bytes, shorts, floats) */
static void fill(void *dst, size_t n, GLenum type, unsigned seed)
{
    size_t i;
    if (type == GL_FLOAT) {
        float *f = dst;
        for (i = 0; i < n / 4; i++)
            f[i] = -0.2f + 1.5f * (float)((i * 37 + seed) % 64) / 63.0f;
    } else if (type == GL_UNSIGNED_BYTE) {
        unsigned char *b = dst;
        for (i = 0; i < n; i++)
            b[i] = (unsigned char)((i * 71 + seed * 13 + (i / 3) * 29) & 255);
    } else {
        unsigned short *s = dst;
        for (i = 0; i < n / 2; i++)
            s[i] = (unsigned short)(i * 40503u + seed * 977u);
    }
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    static unsigned char src[16384], readback[16384];
    char text[4000];
    int tlen = 0;
    GLuint tex[N];
    int i;

    glGenTextures(N, tex);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    sgl_ortho(W, H);
    glClearColor(0.3f, 0.0f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    for (i = 0; i < N; i++) {
        const struct upload *u = &ups[i];
        float x0 = 2.3f + 64.0f * (i % 4), y0 = 3.1f + 64.0f * (i / 4);
        GLint r, g, b, a, l, in, ifmt;
        char name[32];
        /* source buffer big enough for row length and skips */
        fill(src, sizeof src, u->type, (unsigned)i);
        glBindTexture(GL_TEXTURE_2D, tex[i]);
        glPixelStorei(GL_UNPACK_ALIGNMENT, u->align);
        glPixelStorei(GL_UNPACK_ROW_LENGTH, u->row_length);
        glPixelStorei(GL_UNPACK_SKIP_PIXELS, u->skip_pixels);
        glPixelStorei(GL_UNPACK_SKIP_ROWS, u->skip_rows);
        glTexImage2D(GL_TEXTURE_2D, 0, u->internal, u->w, u->h, 0, u->format, u->type, src);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        SGL_CHECK(glGetError() == GL_NO_ERROR);
        glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
        sgl_tex_quad(x0, y0, x0 + 59.3f, y0 + 58.7f, 0.0f, 0.0f, 1.0f, 1.0f);

        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        memset(readback, 0xCD, sizeof readback);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, readback);
        snprintf(name, sizeof name, "getteximage%d", i);
        sgl_data(out, name, (size_t)(u->w * u->h * 4), readback);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &r);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_GREEN_SIZE, &g);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_BLUE_SIZE, &b);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_ALPHA_SIZE, &a);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_LUMINANCE_SIZE, &l);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTENSITY_SIZE, &in);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &ifmt);
        tlen += snprintf(text + tlen, sizeof text - (size_t)tlen,
                         "%d: internal 0x%04x sizes R%d G%d B%d A%d L%d I%d\n", i,
                         (unsigned)ifmt, r, g, b, a, l, in);
    }
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);

    /* the float texture read back as float, the 565 one as 565 */
    glBindTexture(GL_TEXTURE_2D, tex[4]);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, readback);
    sgl_data(out, "float_as_float", 8 * 8 * 4 * 4, readback);
    glBindTexture(GL_TEXTURE_2D, tex[5]);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, readback);
    sgl_data(out, "rgb565_as_565", 8 * 4 * 2, readback);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, readback);
    sgl_data(out, "lum_as_lum_align1", 11 * 5, readback);
    SGL_CHECK(glGetError() == GL_NO_ERROR);
    sgl_text(out, "sizes", "%s", text);

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
