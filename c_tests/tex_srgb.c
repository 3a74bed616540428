/* tex_srgb: sRGB textures (GL_EXT_texture_sRGB, GL 2.1) as MuJoCo uploads them.
 * GL_SRGB8 and GL_SRGB8_ALPHA8 textures (plus GL_SRGB, GL_SRGB_ALPHA, GL_SLUMINANCE8,
 * GL_SLUMINANCE8_ALPHA8) drawn magnified and minified with NEAREST, LINEAR and the
 * mipmap filters (mipmaps from glGenerateMipmap and GL_GENERATE_MIPMAP, which decode,
 * filter and re-encode), with MODULATE, BLEND, REPLACE and framebuffer blending, GL_CLAMP
 * with a border, a perspective ground plane; a 256-step ramp with REPLACE shows the decode
 * of every byte. Then glGetTexImage (ubyte and float: undecoded), the generated levels,
 * level queries and errors. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256
#define T 32

int main(int argc, char **argv)
{
    static const GLfloat env_color[4] = {0.2f, 0.45f, 0.9f, 0.6f};
    static const GLfloat border[4] = {0.8f, 0.3f, 0.1f, 0.5f};
    static const GLenum fmts[6] = {GL_SRGB8, GL_SRGB8_ALPHA8, GL_SRGB, GL_SRGB_ALPHA,
                                   GL_SLUMINANCE8, GL_SLUMINANCE8_ALPHA8};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    unsigned char img[T * T * 4], ramp[256 * 4], back[T * T * 4];
    float fback[T * T * 4];
    GLuint tex[6];
    GLint v[24];
    int i, x, y;

    /* a colourful pattern with soft gradients, hard edges and varying alpha */
    for (y = 0; y < T; y++)
        for (x = 0; x < T; x++) {
            unsigned char *p = img + 4 * (y * T + x);
            int cell = ((x / 4) + (y / 4)) & 1;
            p[0] = (unsigned char)(cell ? 8 * x + 3 : 250 - 5 * y);
            p[1] = (unsigned char)((x * y * 7 + 11) & 255);
            p[2] = (unsigned char)(cell ? 40 + 6 * y : 13 + 3 * x);
            p[3] = (unsigned char)(255 - ((x * 9 + y * 5) & 255));
        }
    for (i = 0; i < 256; i++) {
        ramp[4 * i + 0] = (unsigned char)i;
        ramp[4 * i + 1] = (unsigned char)(255 - i);
        ramp[4 * i + 2] = (unsigned char)((i * 7) & 255);
        ramp[4 * i + 3] = (unsigned char)i;
    }
    glGenTextures(6, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glClearColor(0.15f, 0.1f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    sgl_ortho(W, H);
    glEnable(GL_TEXTURE_2D);

    /* 1: the decode ramp, NEAREST + REPLACE, RGBA */
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, 256, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, ramp);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    sgl_tex_quad(0.0f, 248.0f, 256.0f, 256.0f, 0.0f, 0.0f, 1.0f, 1.0f);
    /* the same ramp magnified with LINEAR (filtering of decoded values) */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    sgl_tex_quad(0.0f, 240.0f, 256.0f, 248.0f, 0.1f / 256.0f, 0.0f, 37.3f / 256.0f, 1.0f);

    /* 2: SRGB8 (RGB) with generated mipmaps: magnified NEAREST / LINEAR, minified with
     * every mipmap filter, MODULATE */
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8, T, T, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor4f(0.9f, 0.75f, 1.0f, 1.0f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    sgl_tex_quad(2.0f, 170.0f, 66.0f, 234.0f, 0.05f, 0.1f, 0.55f, 0.6f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    sgl_tex_quad(70.0f, 170.0f, 134.0f, 234.0f, 0.05f, 0.1f, 0.55f, 0.6f);
    {
        static const GLenum mins[4] = {GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR_MIPMAP_NEAREST,
                                       GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR};
        for (i = 0; i < 4; i++) {
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, mins[i]);
            sgl_tex_quad(138.0f + 29.0f * i, 170.0f, 165.0f + 29.0f * i, 234.0f, 0.0f, 0.0f,
                         2.3f + 0.4f * i, 3.1f);
        }
    }

    /* 3: SRGB8_ALPHA8 with GL_GENERATE_MIPMAP, blended over, BLEND env and LINEAR */
    glBindTexture(GL_TEXTURE_2D, tex[2]);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, T, T, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(1.0f, 0.9f, 0.8f, 0.9f);
    sgl_tex_quad(2.0f, 100.0f, 66.0f, 164.0f, 0.1f, 0.05f, 0.9f, 0.7f);
    sgl_tex_quad(70.0f, 100.0f, 100.0f, 164.0f, 0.0f, 0.0f, 1.7f, 2.9f);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env_color);
    sgl_tex_quad(104.0f, 100.0f, 168.0f, 164.0f, 0.1f, 0.05f, 0.9f, 0.7f);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    /* GL_CLAMP with a border colour (the float path blends it in) */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    sgl_tex_quad(172.0f, 100.0f, 252.0f, 164.0f, -0.2f, -0.2f, 1.2f, 1.2f);
    glDisable(GL_BLEND);

    /* 4: the other sRGB formats, magnified LINEAR, MODULATE */
    for (i = 0; i < 4; i++) {
        glBindTexture(GL_TEXTURE_2D, tex[3]);
        glTexImage2D(GL_TEXTURE_2D, 0, fmts[2 + i], T, T, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glColor4f(0.8f, 1.0f, 0.7f, 0.85f);
        sgl_tex_quad(2.0f + 42.0f * i, 56.0f, 42.0f + 42.0f * i, 96.0f, 0.2f, 0.3f, 0.6f, 0.75f);
    }
    glDisable(GL_TEXTURE_2D);

    /* 5: a perspective ground plane with the mipmapped SRGB8 texture */
    glViewport(170, 2, 84, 94);
    sgl_ground_view(84.0 / 94.0);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    sgl_ground_plane(3.0f);
    glDisable(GL_TEXTURE_2D);
    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);

    /* readback: undecoded bytes and floats, generated levels */
    glBindTexture(GL_TEXTURE_2D, tex[2]);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    sgl_data(out, "level0", T * T * 4, back);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, fback);
    sgl_data(out, "level0_float", T * T * 16, fback);
    for (i = 1; i < 6; i++) {
        int s = T >> i;
        glGetTexImage(GL_TEXTURE_2D, i, GL_RGBA, GL_UNSIGNED_BYTE, back);
        sgl_data(out, "auto_level", (size_t)(s * s * 4), back);
    }
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    for (i = 1; i < 6; i++) {
        int s = T >> i;
        glGetTexImage(GL_TEXTURE_2D, i, GL_RGB, GL_UNSIGNED_BYTE, back);
        sgl_data(out, "call_level", (size_t)(s * s * 3), back);
    }
    for (i = 0; i < 6; i++) {
        glBindTexture(GL_TEXTURE_2D, tex[4]);
        glTexImage2D(GL_TEXTURE_2D, 0, fmts[i], 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &v[4 * i]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &v[4 * i + 1]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_ALPHA_SIZE, &v[4 * i + 2]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_LUMINANCE_SIZE, &v[4 * i + 3]);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
        sgl_data(out, "format_back", 4 * 4 * 4, back);
    }
    sgl_text(out, "queries",
             "%x %d %d %d / %x %d %d %d / %x %d %d %d / %x %d %d %d / %x %d %d %d / %x %d %d %d",
             v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11], v[12],
             v[13], v[14], v[15], v[16], v[17], v[18], v[19], v[20], v[21], v[22], v[23]);
    /* float data is stored linearly */
    {
        static const float fl[8] = {0.5f, 0.2f, 1.5f, -1.0f, 0.0031f, 0.73f, 0.999f, 0.25f};
        glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, 2, 1, 0, GL_RGBA, GL_FLOAT, fl);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
        sgl_data(out, "float_store", 8, back);
    }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, fback);
    v[0] = glGetError();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, 2, 2, 0, GL_DEPTH_STENCIL,
                 GL_UNSIGNED_INT_24_8, fback);
    v[1] = glGetError();
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, fback);
    v[2] = glGetError();
    sgl_text(out, "errors", "%x %x %x", v[0], v[1], v[2]);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
