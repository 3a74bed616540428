/* tex_small_formats_wrap: textures stored with fewer than 8 bits per
 * component under every wrap mode.  llvmpipe samples such a texture on its
 * 8-bit path (bit-replicated components) when both wraps are REPEAT or
 * CLAMP_TO_EDGE, and on its float path otherwise (GL_CLAMP, CLAMP_TO_BORDER,
 * MIRRORED_REPEAT), where a component c of n bits becomes c / (2^n - 1) in
 * float (`lp_build_unsigned_norm_to_float`), not the replicated byte / 255.
 * One image per storage format (GL_RGBA4, GL_RGB5, GL_RGB5_A1, GL_R3_G3_B2,
 * GL_RGB4, GL_RGBA2, GL_LUMINANCE4_ALPHA4, GL_RGB with 5_6_5 texels): the
 * five wrap modes by column (s and t alike); by row NEAREST and LINEAR on a
 * power-of-two (8x8) and a non-power-of-two (7x5) texture, with GL_REPLACE and
 * with GL_MODULATE by a colour.  Texture coordinates run from -0.45 to 1.55
 * so that the clamps, the border colour and the mirror show.  A last image
 * minifies each format mipmapped (GL_GENERATE_MIPMAP, LINEAR_MIPMAP_LINEAR)
 * under MIRRORED_REPEAT and CLAMP_TO_BORDER. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <string.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256
#define NF 8

static const GLenum modes[5] = {GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE, GL_CLAMP_TO_BORDER,
                                GL_MIRRORED_REPEAT};
static const GLint formats[NF] = {GL_RGBA4, GL_RGB5, GL_RGB5_A1, GL_R3_G3_B2,
                                  GL_RGB4,  GL_RGBA2, GL_LUMINANCE4_ALPHA4, GL_RGB};
static const char *names[NF] = {"rgba4", "rgb5",   "rgb5_a1",   "r3_g3_b2",
                                "rgb4",  "rgba2", "l4_a4", "rgb_565"};

/* Uploads a w x h image into the bound texture as format f (level 0). */
static void upload(int f, int w, int h, int seed)
{
    static unsigned char rgba[16 * 16 * 4];
    static unsigned short packed[16 * 16];
    int i, k;
    for (i = 0; i < w * h; i++)
        for (k = 0; k < 4; k++)
            rgba[4 * i + k] = (unsigned char)((i * (k + 3) * 53 + k * 71 + seed * 29) & 255);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    if (formats[f] == GL_RGB) {
        /* 5_6_5 texels: Mesa stores them as R5G6B5 (6-bit green) */
        for (i = 0; i < w * h; i++)
            packed[i] = (unsigned short)((rgba[4 * i] >> 3) << 11 | (rgba[4 * i + 1] >> 2) << 5 |
                                         rgba[4 * i + 2] >> 3);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, w, h, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, packed);
    } else {
        glTexImage2D(GL_TEXTURE_2D, 0, formats[f], w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    }
}

int main(int argc, char **argv)
{
    static const GLfloat border[4] = {0.93f, 0.41f, 0.07f, 0.61f};
    static const GLfloat color[4] = {0.83f, 0.61f, 0.97f, 0.71f};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    GLuint tex[NF][3];
    char name[48];
    int f, i, row;

    glGenTextures(3 * NF, &tex[0][0]);
    glEnable(GL_TEXTURE_2D);
    sgl_ortho(W, H);
    for (f = 0; f < NF; f++) {
        glBindTexture(GL_TEXTURE_2D, tex[f][0]);
        upload(f, 8, 8, f);
        glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
        glBindTexture(GL_TEXTURE_2D, tex[f][1]);
        upload(f, 7, 5, f + 11);
        glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
        glBindTexture(GL_TEXTURE_2D, tex[f][2]);
        glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
        upload(f, 16, 16, f + 5);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    }

    for (f = 0; f < NF; f++) {
        glClearColor(0.2f, 0.1f, 0.3f, 0.5f);
        glClear(GL_COLOR_BUFFER_BIT);
        /* rows: filter (NEAREST, LINEAR) x size (8x8, 7x5) x env (REPLACE, MODULATE) */
        for (row = 0; row < 8; row++) {
            GLint filter = (row & 1) ? GL_LINEAR : GL_NEAREST;
            int npot = (row >> 1) & 1, modulate = row >> 2;
            glBindTexture(GL_TEXTURE_2D, tex[f][npot]);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, modulate ? GL_MODULATE : GL_REPLACE);
            glColor4fv(color);
            for (i = 0; i < 5; i++) {
                float x0 = 1.3f + 51.0f * (float)i, y0 = 1.7f + 32.0f * (float)row;
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)modes[i]);
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)modes[i]);
                sgl_tex_quad(x0, y0, x0 + 48.9f, y0 + 29.3f, -0.45f, -0.43f, 1.55f, 1.57f);
            }
        }
        glFinish();
        SGL_CHECK(glGetError() == GL_NO_ERROR);
        snprintf(name, sizeof name, "%s", names[f]);
        sgl_image(out, name, W, H, 4, "RGBA", W * 4, 1, buf);
    }

    /* minified and mipmapped: per format a column, MIRRORED_REPEAT and
     * CLAMP_TO_BORDER in two sizes each */
    glClearColor(0.2f, 0.1f, 0.3f, 0.5f);
    glClear(GL_COLOR_BUFFER_BIT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    for (f = 0; f < NF; f++) {
        glBindTexture(GL_TEXTURE_2D, tex[f][2]);
        for (row = 0; row < 4; row++) {
            GLint mode = (row & 1) ? GL_CLAMP_TO_BORDER : GL_MIRRORED_REPEAT;
            float x0 = 2.3f + 31.0f * (float)f, y0 = 3.1f + 60.0f * (float)row;
            float size = (row & 2) ? 11.3f : 27.6f;
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, mode);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, mode);
            sgl_tex_quad(x0, y0, x0 + size, y0 + size * 1.9f, -0.7f, -0.3f, 2.1f, 3.3f);
        }
    }
    glFinish();
    SGL_CHECK(glGetError() == GL_NO_ERROR);
    sgl_image(out, "mipmapped", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
