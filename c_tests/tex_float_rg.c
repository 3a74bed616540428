/* tex_float_rg: float and red/green textures (GL_ARB_texture_float, GL_ARB_texture_rg,
 * GL_ARB_half_float_pixel) sampled by fixed function. Every internal format is uploaded
 * from GL_FLOAT with values inside and outside [0,1] and drawn with REPLACE and MODULATE
 * (NEAREST), then a few with LINEAR, mipmaps (glGenerateMipmap), ADD, COMBINE, GL_CLAMP
 * with a border, uploads from GL_UNSIGNED_BYTE, GL_HALF_FLOAT and GL_UNSIGNED_SHORT, and
 * glTexSubImage. Read back with glGetTexImage (float, half, ubyte, ushort, byte), level
 * queries (sizes, types), errors and a float attachment's framebuffer status. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <string.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256
#define T 8

static const GLenum fmts[] = {
    GL_R8, GL_R16, GL_RG8, GL_RG16, GL_R16F, GL_R32F, GL_RG16F, GL_RG32F, GL_RED, GL_RG,
    GL_RGBA32F_ARB, GL_RGB32F_ARB, GL_ALPHA32F_ARB, GL_INTENSITY32F_ARB,
    GL_LUMINANCE32F_ARB, GL_LUMINANCE_ALPHA32F_ARB, GL_RGBA16F_ARB, GL_RGB16F_ARB,
    GL_ALPHA16F_ARB, GL_INTENSITY16F_ARB, GL_LUMINANCE16F_ARB, GL_LUMINANCE_ALPHA16F_ARB};
#define NF (int)(sizeof fmts / sizeof fmts[0])

static float img[T * T * 4];

static void params(GLenum minf, GLenum magf)
{
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)minf);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (GLint)magf);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    static float fback[T * T * 4];
    static unsigned char ub[T * T * 4];
    static unsigned short us[T * T * 4], half[T * T * 4];
    static signed char sb[T * T * 4];
    GLint q[16];
    GLuint tex[4];
    int i, j, x, y;
    char text[4096];
    size_t n = 0;

    /* values from -1.5 to 3.0, a pattern with hard edges */
    for (y = 0; y < T; y++)
        for (x = 0; x < T; x++) {
            float *p = img + 4 * (y * T + x);
            p[0] = -1.5f + 4.5f * (float)x / (T - 1);
            p[1] = (float)((x + 2 * y) % 5) * 0.37f - 0.2f;
            p[2] = 1.0f - 0.3f * (float)y + 0.013f * (float)(x * y);
            p[3] = ((x ^ y) & 1) ? 1.7f : 0.1f + 0.1f * (float)y;
        }
    glGenTextures(4, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glClearColor(0.3f, 0.2f, 0.25f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    sgl_ortho(W, H);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, tex[0]);

    /* 1: every format, NEAREST, REPLACE (top) and MODULATE with a dim colour (below) */
    for (i = 0; i < NF; i++) {
        float x0 = (float)(i % 11) * 23.0f + 2.0f, y0 = 232.0f - 48.0f * (float)(i / 11);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)fmts[i], T, T, 0, GL_RGBA, GL_FLOAT, img);
        params(GL_NEAREST, GL_NEAREST);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
        sgl_tex_quad(x0, y0, x0 + 21.0f, y0 + 21.0f, 0.0f, 0.0f, 1.0f, 1.0f);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
        glColor4f(0.3f, 0.45f, 0.6f, 0.5f);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        sgl_tex_quad(x0, y0 - 23.0f, x0 + 21.0f, y0 - 2.0f, 0.0f, 0.0f, 1.0f, 1.0f);
        glDisable(GL_BLEND);
        glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, fback);
        sgl_data(out, "float_back", sizeof fback, fback);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, ub);
        sgl_data(out, "ubyte_back", sizeof ub, ub);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_HALF_FLOAT_ARB, half);
        sgl_data(out, "half_back", sizeof half, half);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RGB, GL_UNSIGNED_SHORT, us);
        sgl_data(out, "ushort_back", T * T * 6, us);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, GL_BYTE, sb);
        sgl_data(out, "byte_back", T * T * 2, sb);
        {
            static const GLenum pn[] = {
                GL_TEXTURE_INTERNAL_FORMAT, GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE,
                GL_TEXTURE_BLUE_SIZE, GL_TEXTURE_ALPHA_SIZE, GL_TEXTURE_LUMINANCE_SIZE,
                GL_TEXTURE_INTENSITY_SIZE, GL_TEXTURE_RED_TYPE_ARB, GL_TEXTURE_GREEN_TYPE_ARB,
                GL_TEXTURE_BLUE_TYPE_ARB, GL_TEXTURE_ALPHA_TYPE_ARB,
                GL_TEXTURE_LUMINANCE_TYPE_ARB, GL_TEXTURE_INTENSITY_TYPE_ARB,
                GL_TEXTURE_DEPTH_TYPE_ARB};
            for (j = 0; j < 14; j++) {
                q[0] = -1;
                glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, pn[j], q);
                n += (size_t)snprintf(text + n, sizeof text - n, "%x ", q[0]);
            }
            n += (size_t)snprintf(text + n, sizeof text - n, "/ ");
        }
    }
    sgl_text(out, "levels", "%s", text);

    /* 2: magnified LINEAR, REPLACE and MODULATE (float lerps of values outside [0,1]) */
    {
        static const GLenum lin[] = {GL_RGBA32F_ARB, GL_RGBA16F_ARB, GL_R16, GL_RG32F,
                                     GL_LUMINANCE_ALPHA16F_ARB, GL_INTENSITY32F_ARB,
                                     GL_RG8, GL_ALPHA32F_ARB};
        for (i = 0; i < 8; i++) {
            float x0 = 2.0f + 32.0f * (float)i;
            glTexImage2D(GL_TEXTURE_2D, 0, (GLint)lin[i], T, T, 0, GL_RGBA, GL_FLOAT, img);
            params(GL_LINEAR, GL_LINEAR);
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, i & 1 ? GL_MODULATE : GL_REPLACE);
            glColor4f(0.6f, 0.4f, 0.9f, 0.8f);
            sgl_tex_quad(x0, 100.0f, x0 + 30.0f, 130.0f, 0.03f, 0.1f, 0.93f, 0.77f);
        }
    }

    /* 3: mipmaps from glGenerateMipmap, minified with the mipmap filters; ADD; COMBINE */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F_ARB, T, T, 0, GL_RGBA, GL_FLOAT, img);
    glGenerateMipmap(GL_TEXTURE_2D);
    for (i = 1; i < 4; i++) {
        glGetTexImage(GL_TEXTURE_2D, i, GL_RGBA, GL_FLOAT, fback);
        sgl_data(out, "mip16f", (size_t)((T >> i) * (T >> i) * 16), fback);
    }
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor4f(0.5f, 0.5f, 0.5f, 1.0f);
    params(GL_NEAREST_MIPMAP_NEAREST, GL_LINEAR);
    sgl_tex_quad(2.0f, 66.0f, 18.0f, 96.0f, 0.0f, 0.0f, 3.1f, 5.3f);
    params(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR);
    sgl_tex_quad(20.0f, 66.0f, 36.0f, 96.0f, 0.0f, 0.0f, 3.1f, 5.3f);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, T, T, 0, GL_RGBA, GL_FLOAT, img);
    glGenerateMipmap(GL_TEXTURE_2D);
    for (i = 1; i < 4; i++) {
        glGetTexImage(GL_TEXTURE_2D, i, GL_RED, GL_FLOAT, fback);
        sgl_data(out, "mip32f", (size_t)((T >> i) * (T >> i) * 4), fback);
    }
    params(GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST);
    sgl_tex_quad(38.0f, 66.0f, 54.0f, 96.0f, 0.0f, 0.0f, 2.7f, 4.1f);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD);
    glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
    params(GL_LINEAR, GL_LINEAR);
    sgl_tex_quad(56.0f, 66.0f, 86.0f, 96.0f, 0.0f, 0.0f, 1.0f, 1.0f);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_PRIMARY_COLOR);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_SRC_COLOR);
    glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
    sgl_tex_quad(88.0f, 66.0f, 118.0f, 96.0f, 0.0f, 0.0f, 1.0f, 1.0f);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_MODULATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_RGB_SCALE, 2);
    sgl_tex_quad(120.0f, 66.0f, 150.0f, 96.0f, 0.0f, 0.0f, 1.0f, 1.0f);
    glTexEnvi(GL_TEXTURE_ENV, GL_RGB_SCALE, 1);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor4f(1.0f, 1.0f, 1.0f, 1.0f);

    /* 4: GL_CLAMP with a border; MIRRORED_REPEAT; RG8 AoS LINEAR next to RG16 */
    {
        static const GLfloat border[4] = {0.8f, 0.3f, 0.1f, 0.5f};
        glBindTexture(GL_TEXTURE_2D, tex[2]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RG16F, T, T, 0, GL_RGBA, GL_FLOAT, img);
        params(GL_LINEAR, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP);
        glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
        sgl_tex_quad(152.0f, 66.0f, 182.0f, 96.0f, -0.3f, -0.2f, 1.2f, 1.3f);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
        sgl_tex_quad(184.0f, 66.0f, 214.0f, 96.0f, -0.7f, -0.4f, 1.6f, 1.3f);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RG8, T, T, 0, GL_RGBA, GL_FLOAT, img);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        sgl_tex_quad(216.0f, 66.0f, 246.0f, 96.0f, -0.7f, -0.4f, 1.6f, 1.3f);
    }

    /* 5: uploads from other types, and glTexSubImage */
    {
        static unsigned char bytes[T * T * 4];
        static unsigned short shorts[T * T * 2];
        static unsigned short halves[T * T * 4];
        static const GLenum up[] = {GL_RGBA32F_ARB, GL_R16, GL_LUMINANCE16F_ARB, GL_RG32F};
        for (i = 0; i < T * T * 4; i++) {
            bytes[i] = (unsigned char)(i * 37 + 11);
            halves[i] = (unsigned short)(0x3000 + i * 97 % 0x1400);
        }
        for (i = 0; i < T * T * 2; i++)
            shorts[i] = (unsigned short)(i * 4099 + 7);
        glBindTexture(GL_TEXTURE_2D, tex[3]);
        params(GL_NEAREST, GL_NEAREST);
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
        for (i = 0; i < 4; i++) {
            float x0 = 2.0f + 64.0f * (float)i;
            glTexImage2D(GL_TEXTURE_2D, 0, (GLint)up[i], T, T, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                         bytes);
            glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, fback);
            sgl_data(out, "from_ubyte", sizeof fback, fback);
            sgl_tex_quad(x0, 34.0f, x0 + 20.0f, 62.0f, 0.0f, 0.0f, 1.0f, 1.0f);
            glTexImage2D(GL_TEXTURE_2D, 0, (GLint)up[i], T, T, 0, GL_RGBA, GL_HALF_FLOAT_ARB,
                         halves);
            glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, fback);
            sgl_data(out, "from_half", sizeof fback, fback);
            sgl_tex_quad(x0 + 21.0f, 34.0f, x0 + 41.0f, 62.0f, 0.0f, 0.0f, 1.0f, 1.0f);
            glTexImage2D(GL_TEXTURE_2D, 0, (GLint)up[i], T, T, 0, GL_RG, GL_UNSIGNED_SHORT,
                         shorts);
            glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 3, 4, 2, GL_RGBA, GL_FLOAT, img);
            glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, fback);
            sgl_data(out, "from_ushort_sub", sizeof fback, fback);
            sgl_tex_quad(x0 + 42.0f, 34.0f, x0 + 62.0f, 62.0f, 0.0f, 0.0f, 1.0f, 1.0f);
        }
    }
    glDisable(GL_TEXTURE_2D);
    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);

    /* 6: errors, and a float texture attached to a framebuffer object */
    {
        GLint e[8];
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, 2, 2, 0, GL_RG, GL_UNSIGNED_BYTE_3_3_2, ub);
        e[0] = (GLint)glGetError();
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R32F, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT, fback);
        e[1] = (GLint)glGetError();
        glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE32F_ARB, 2, 2, 0, GL_RG, GL_FLOAT, fback);
        e[2] = (GLint)glGetError();
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RG16, 2, 2, 0, GL_RGBA, GL_HALF_FLOAT_ARB, half);
        e[3] = (GLint)glGetError();
        glTexImage2D(GL_TEXTURE_2D, 0, GL_R16F, 2, 2, 0, GL_RED, GL_BITMAP, ub);
        e[4] = (GLint)glGetError();
        glGetTexImage(GL_TEXTURE_2D, 0, GL_RG, GL_FLOAT, fback);
        e[5] = (GLint)glGetError();
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RG_INTEGER, 2, 2, 0, GL_RG, GL_FLOAT, fback);
        e[6] = (GLint)glGetError();
        e[7] = 0;
        sgl_text(out, "errors", "%x %x %x %x %x %x %x", e[0], e[1], e[2], e[3], e[4], e[5],
                 e[6]);
    }
    sgl_text(out, "extensions", "%d %d %d",
             strstr((const char *)glGetString(GL_EXTENSIONS), "GL_ARB_texture_float") != NULL,
             strstr((const char *)glGetString(GL_EXTENSIONS), "GL_ARB_texture_rg") != NULL,
             strstr((const char *)glGetString(GL_EXTENSIONS), "GL_ARB_half_float_pixel") !=
                 NULL);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
