/* tex_sized_formats: images stored with fewer than 8 bits per component.
 * Mesa keeps sized small internal formats (GL_RGBA4, GL_RGB5, GL_RGB5_A1,
 * GL_R3_G3_B2, GL_RGBA2, GL_RGB4, GL_LUMINANCE4_ALPHA4) in that precision
 * (uploads round, `_mesa_unorm_to_unorm`/`_mesa_float_to_unorm`) and samples
 * the bit-replicated values.  A 16x16 RGBA8 ramp and the same ramp as floats
 * are uploaded into each, drawn magnified with NEAREST and LINEAR in a grid,
 * and read back with glGetTexImage; GL_RGBA4 also gets GL_GENERATE_MIPMAP
 * (drawn minified) and glTexSubImage2D.  The component sizes
 * glGetTexLevelParameter reports are dumped.  (glCopyTexImage2D into these
 * formats is left out: llvmpipe's blit rounds some texels up where the
 * texstore rounding does not, not reproduced yet.) */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <string.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256
#define N 7
#define S 16

static const GLint formats[N] = {GL_RGBA4, GL_RGB5, GL_RGB5_A1, GL_R3_G3_B2,
                                 GL_RGBA2, GL_RGB4, GL_LUMINANCE4_ALPHA4};

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    static unsigned char ramp[S * S * 4], readback[S * S * 4];
    static float framp[S * S * 4];
    char text[2000], name[32];
    int tlen = 0, i, k, f;
    GLuint tex[2 * N + 1];

    (void)ctx;
    for (i = 0; i < S * S; i++)
        for (k = 0; k < 4; k++) {
            ramp[4 * i + k] = (unsigned char)((i * (k + 1) * 37 + k * 61) & 255);
            framp[4 * i + k] = (float)((i * (k + 3) * 29 + k * 17) % 300) / 280.0f - 0.03f;
        }
    glGenTextures(2 * N + 1, tex);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    sgl_ortho(W, H);
    glClearColor(0.2f, 0.1f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (f = 0; f < 2; f++)
        for (i = 0; i < N; i++) {
            GLint r, g, b, a, l;
            float x0 = 1.5f + 36.0f * i, y0 = 2.5f + 40.0f * f;
            glBindTexture(GL_TEXTURE_2D, tex[f * N + i]);
            glTexImage2D(GL_TEXTURE_2D, 0, formats[i], S, S, 0, GL_RGBA,
                         f ? GL_FLOAT : GL_UNSIGNED_BYTE, f ? (void *)framp : (void *)ramp);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            sgl_tex_quad(x0, y0, x0 + 33.0f, y0 + 33.0f, 0.0f, 0.0f, 1.0f, 1.0f);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            sgl_tex_quad(x0, y0 + 84.0f, x0 + 33.7f, y0 + 117.3f, 0.1f, 0.05f, 0.9f, 0.93f);
            memset(readback, 0xCD, sizeof readback);
            glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, readback);
            snprintf(name, sizeof name, "readback%d_%d", f, i);
            sgl_data(out, name, sizeof readback, readback);
            glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &r);
            glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_GREEN_SIZE, &g);
            glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_BLUE_SIZE, &b);
            glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_ALPHA_SIZE, &a);
            glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_LUMINANCE_SIZE, &l);
            if (f == 0)
                tlen += snprintf(text + tlen, sizeof text - (size_t)tlen,
                                 "0x%04x: R%d G%d B%d A%d L%d\n", (unsigned)formats[i], r, g, b,
                                 a, l);
        }

    /* GL_RGBA4: generated mipmaps, minified; then a sub-image and a re-generation */
    glBindTexture(GL_TEXTURE_2D, tex[2 * N]);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA4, S, S, 0, GL_RGBA, GL_UNSIGNED_BYTE, ramp);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    sgl_tex_quad(10.5f, 180.5f, 13.7f, 183.9f, 0.0f, 0.0f, 1.0f, 1.0f);
    sgl_tex_quad(20.5f, 180.5f, 27.0f, 187.2f, 0.0f, 0.0f, 1.0f, 1.0f);
    glGetTexImage(GL_TEXTURE_2D, 1, GL_RGBA, GL_UNSIGNED_BYTE, readback);
    sgl_data(out, "rgba4_level1", 8 * 8 * 4, readback);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 5, 6, 4, GL_RGBA, GL_UNSIGNED_BYTE, ramp + 400);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, readback);
    sgl_data(out, "rgba4_sub", sizeof readback, readback);
    glGetTexImage(GL_TEXTURE_2D, 2, GL_RGBA, GL_UNSIGNED_BYTE, readback);
    sgl_data(out, "rgba4_sub_level2", 4 * 4 * 4, readback);

    SGL_CHECK(glGetError() == GL_NO_ERROR);
    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "sizes", "%s", text);
    sgl_close(out);
    return 0;
}
