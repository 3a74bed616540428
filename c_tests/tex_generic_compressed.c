/* tex_generic_compressed: the GL 1.3 generic compressed internal formats
 * (GL_COMPRESSED_RGB, _RGBA, _ALPHA, _LUMINANCE, _LUMINANCE_ALPHA, _INTENSITY)
 * in glTexImage1D/2D/3D and glCopyTexImage1D/2D, and the legacy internal
 * formats 1-4, which glCopyTexImage refuses with GL_INVALID_ENUM.
 *
 * Mesa 22.3 llvmpipe stores GL_COMPRESSED_RGB/RGBA/LUMINANCE/LUMINANCE_ALPHA
 * of a 2D, cube or 3D texture as DXT1/DXT5/LATC1/LATC2 blocks and reports
 * GL_TEXTURE_COMPRESSED 1; a 1D texture, and ALPHA and INTENSITY everywhere,
 * are stored uncompressed, GL_TEXTURE_INTERNAL_FORMAT being the base format.
 * softgl stores every generic format uncompressed (which the spec allows),
 * so for the formats Mesa compresses the scene prints whether the answers
 * are one of the two consistent sets (compressed: a specific compressed
 * format of the right base and the block-size image size; uncompressed: the
 * base format and GL_INVALID_OPERATION for the image size) rather than the
 * values themselves.  Every other query is printed as is.
 *
 * The pixels are exact: the 2D images hold two colours per 4x4 block, each
 * exact in 5:6:5, so the DXT/LATC blocks Mesa's encoder writes decode to
 * the original texels; the lossy case is tex_generic_compressed_lossy.  The
 * 1D textures (uncompressed on Mesa too) use an arbitrary gradient.
 *
 * Mesa's glGetTexImage(GL_RGBA) of a LATC texture returns (L, 0, 0, 1) (a
 * Mesa bug: the decoded red is not spread to green and blue), so those
 * textures are read back as GL_LUMINANCE_ALPHA, which both agree on. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 192
#define H 128
#define TS 16

static const GLenum generic[6] = {
    GL_COMPRESSED_RGB,       GL_COMPRESSED_RGBA,
    GL_COMPRESSED_ALPHA,     GL_COMPRESSED_LUMINANCE,
    GL_COMPRESSED_LUMINANCE_ALPHA, GL_COMPRESSED_INTENSITY,
};
static const GLenum bases[6] = {GL_RGB, GL_RGBA, GL_ALPHA, GL_LUMINANCE,
                                GL_LUMINANCE_ALPHA, GL_INTENSITY};
static const char *names[6] = {"rgb", "rgba", "alpha", "lum", "lum_alpha", "intensity"};

/* Mesa compresses these four (not ALPHA, INTENSITY) outside 1D targets. */
static int may_compress(int k) { return k != 2 && k != 5; }

/* The base format of the specific compressed formats Mesa may choose. */
static GLenum specific_base(GLint f)
{
    switch (f) {
    case 0x83F0: /* GL_COMPRESSED_RGB_S3TC_DXT1_EXT */
        return GL_RGB;
    case 0x83F1: /* GL_COMPRESSED_RGBA_S3TC_DXT1_EXT */
    case 0x83F2: /* GL_COMPRESSED_RGBA_S3TC_DXT3_EXT */
    case 0x83F3: /* GL_COMPRESSED_RGBA_S3TC_DXT5_EXT */
        return GL_RGBA;
    case 0x8C70: /* GL_COMPRESSED_LUMINANCE_LATC1_EXT */
        return GL_LUMINANCE;
    case 0x8C72: /* GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT */
        return GL_LUMINANCE_ALPHA;
    default:
        return 0;
    }
}

static void drain(void)
{
    while (glGetError() != GL_NO_ERROR)
        ;
}

/* The level-0 queries of an image target, as text. */
static void print_queries(FILE *out, const char *name, GLenum target)
{
    static const GLenum sizes[6] = {GL_TEXTURE_RED_SIZE, GL_TEXTURE_GREEN_SIZE,
                                    GL_TEXTURE_BLUE_SIZE, GL_TEXTURE_ALPHA_SIZE,
                                    GL_TEXTURE_LUMINANCE_SIZE,
                                    GL_TEXTURE_INTENSITY_SIZE};
    GLint c = -1, f = -1, s = -1, z[6], i;
    GLenum e;
    drain();
    glGetTexLevelParameteriv(target, 0, GL_TEXTURE_COMPRESSED, &c);
    glGetTexLevelParameteriv(target, 0, GL_TEXTURE_INTERNAL_FORMAT, &f);
    for (i = 0; i < 6; i++)
        glGetTexLevelParameteriv(target, 0, sizes[i], &z[i]);
    glGetTexLevelParameteriv(target, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &s);
    e = glGetError();
    sgl_text(out, name, "compressed %d internal %#x sizes %d %d %d %d %d %d image_size %d err %#x",
             c, f, z[0], z[1], z[2], z[3], z[4], z[5], s, e);
}

/* For a format Mesa may compress: 1 when the answers are one consistent set. */
static void print_consistent(FILE *out, const char *name, GLenum target, GLenum base,
                             int blocks, int proxy)
{
    GLint c = -1, f = -1, s = -1;
    GLenum e;
    int ok;
    drain();
    glGetTexLevelParameteriv(target, 0, GL_TEXTURE_COMPRESSED, &c);
    glGetTexLevelParameteriv(target, 0, GL_TEXTURE_INTERNAL_FORMAT, &f);
    glGetTexLevelParameteriv(target, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &s);
    e = glGetError();
    if (c == 0)
        ok = f == (GLint)base && e == GL_INVALID_OPERATION;
    else if (c == 1 && proxy)
        ok = specific_base(f) == base && e == GL_INVALID_OPERATION;
    else
        ok = c == 1 && specific_base(f) == base && e == GL_NO_ERROR &&
             (s == blocks * 8 || s == blocks * 16);
    sgl_text(out, name, "consistent %d", ok);
    if (!ok)
        fprintf(stderr, "%s: compressed %d internal %#x image_size %d err %#x\n", name, c, f,
                s, e);
}

/* 5-bit and 6-bit values expanded to 8 bits, as DXT decoders do. */
static int e5(int v) { return (v << 3) | (v >> 2); }
static int e6(int v) { return (v << 2) | (v >> 4); }

/* TS x TS RGBA texels, two colours per 4x4 block, exact in 5:6:5. */
static void block_image(unsigned char *p)
{
    int x, y;
    for (y = 0; y < TS; y++)
        for (x = 0; x < TS; x++) {
            int b = (y / 4) * 4 + x / 4, which = ((x + y) & 1) ^ ((x * 3 + y) % 5 == 0);
            int k = b * 7 + which * 13 + 3;
            unsigned char *t = p + 4 * (y * TS + x);
            t[0] = (unsigned char)e5((k * 3) & 31);
            t[1] = (unsigned char)e6((k * 5 + which * 20) & 63);
            t[2] = (unsigned char)e5((k * 11) & 31);
            t[3] = (unsigned char)(which ? 200 + b : (37 * b + 9) & 255);
        }
}

/* Draws the bound texture of `target` as a quad at (x, y) (8 high for 1D). */
static void quad(GLenum target, float x, float y, float size)
{
    glEnable(target);
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, 0.0f);
    glVertex2f(x, y);
    glTexCoord2f(1.0f, 0.0f);
    glVertex2f(x + size, y);
    glTexCoord2f(1.0f, 1.0f);
    glVertex2f(x + size, y + (target == GL_TEXTURE_1D ? 8.0f : size));
    glTexCoord2f(0.0f, 1.0f);
    glVertex2f(x, y + (target == GL_TEXTURE_1D ? 8.0f : size));
    glEnd();
    glDisable(target);
}

static void readback(FILE *out, const char *what, int k, GLenum target, int n)
{
    static unsigned char back[TS * TS * 4];
    char name[64];
    int la = k == 3 || k == 4;
    memset(back, 0, sizeof back);
    glGetTexImage(target, 0, la ? GL_LUMINANCE_ALPHA : GL_RGBA, GL_UNSIGNED_BYTE, back);
    snprintf(name, sizeof name, "%s_%s_texels", what, names[k]);
    sgl_data(out, name, (size_t)n * (la ? 2 : 4), back);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    static unsigned char img[TS * TS * 4], grad[64 * 4];
    GLuint tex[6][4];
    char name[64];
    int k, i, filt;

    block_image(img);
    for (i = 0; i < 64; i++) {
        grad[4 * i + 0] = (unsigned char)(i * 4);
        grad[4 * i + 1] = (unsigned char)(255 - i * 3);
        grad[4 * i + 2] = (unsigned char)((i * 37) & 255);
        grad[4 * i + 3] = (unsigned char)(i * 2 + 60);
    }
    sgl_ortho(W, H);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT);

    /* the block image drawn with glDrawPixels, the source of the copies */
    glRasterPos2i(0, 0);
    glDrawPixels(TS, TS, GL_RGBA, GL_UNSIGNED_BYTE, img);

    for (k = 0; k < 6; k++) {
        GLenum e[4];
        glGenTextures(4, tex[k]);
        /* [0] 2D from client memory, [1] 2D copied, [2] 1D, [3] 1D copied */
        glBindTexture(GL_TEXTURE_2D, tex[k][0]);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)generic[k], TS, TS, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     img);
        e[0] = glGetError();
        glBindTexture(GL_TEXTURE_2D, tex[k][1]);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, generic[k], 0, 0, TS, TS, 0);
        e[1] = glGetError();
        glBindTexture(GL_TEXTURE_1D, tex[k][2]);
        glTexImage1D(GL_TEXTURE_1D, 0, (GLint)generic[k], 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, grad);
        e[2] = glGetError();
        glBindTexture(GL_TEXTURE_1D, tex[k][3]);
        glCopyTexImage1D(GL_TEXTURE_1D, 0, generic[k], 0, 5, TS, 0);
        e[3] = glGetError();
        snprintf(name, sizeof name, "%s_errors", names[k]);
        sgl_text(out, name, "%#x %#x %#x %#x", e[0], e[1], e[2], e[3]);

        for (i = 0; i < 2; i++) {
            glBindTexture(GL_TEXTURE_2D, tex[k][i]);
            snprintf(name, sizeof name, "%s_2d%s", names[k], i ? "_copy" : "");
            if (may_compress(k))
                print_consistent(out, name, GL_TEXTURE_2D, bases[k], 16, 0);
            else
                print_queries(out, name, GL_TEXTURE_2D);
            readback(out, i ? "copy" : "image", k, GL_TEXTURE_2D, TS * TS);
            glBindTexture(GL_TEXTURE_1D, tex[k][2 + i]);
            snprintf(name, sizeof name, "%s_1d%s", names[k], i ? "_copy" : "");
            print_queries(out, name, GL_TEXTURE_1D);
            readback(out, i ? "copy1d" : "image1d", k, GL_TEXTURE_1D, i ? TS : 64);
        }
    }

    /* every texture drawn at 3x, NEAREST and then LINEAR */
    glClear(GL_COLOR_BUFFER_BIT);
    for (filt = 0; filt < 2; filt++) {
        GLint f = filt ? GL_LINEAR : GL_NEAREST;
        for (k = 0; k < 6; k++) {
            for (i = 0; i < 4; i++) {
                GLenum t = i < 2 ? GL_TEXTURE_2D : GL_TEXTURE_1D;
                glBindTexture(t, tex[k][i]);
                glTexParameteri(t, GL_TEXTURE_MIN_FILTER, f);
                glTexParameteri(t, GL_TEXTURE_MAG_FILTER, f);
                glTexParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
                glTexParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
            }
            glBindTexture(GL_TEXTURE_2D, tex[k][0]);
            quad(GL_TEXTURE_2D, 32.0f * k, 0.0f, 30.0f);
            glBindTexture(GL_TEXTURE_2D, tex[k][1]);
            quad(GL_TEXTURE_2D, 32.0f * k, 32.0f, 30.0f);
            glBindTexture(GL_TEXTURE_1D, tex[k][2]);
            quad(GL_TEXTURE_1D, 32.0f * k, 64.0f, 30.0f);
            glBindTexture(GL_TEXTURE_1D, tex[k][3]);
            quad(GL_TEXTURE_1D, 32.0f * k, 74.0f, 30.0f);
        }
        glFinish();
        sgl_image(out, filt ? "drawn_linear" : "drawn_nearest", W, H, 4, "RGBA", W * 4, 1, buf);
        glClear(GL_COLOR_BUFFER_BIT);
    }

    /* the other targets: 3D, a cube face, a proxy, a border */
    for (k = 0; k < 6; k++) {
        GLuint t[3];
        GLenum e[4];
        glGenTextures(3, t);
        drain();
        glBindTexture(GL_TEXTURE_3D, t[0]);
        glTexImage3D(GL_TEXTURE_3D, 0, (GLint)generic[k], 8, 4, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     img);
        e[0] = glGetError();
        glBindTexture(GL_TEXTURE_CUBE_MAP, t[1]);
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, (GLint)generic[k], 8, 8, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, img);
        e[1] = glGetError();
        glTexImage2D(GL_PROXY_TEXTURE_2D, 0, (GLint)generic[k], 8, 8, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, NULL);
        e[2] = glGetError();
        glBindTexture(GL_TEXTURE_2D, t[2]);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)generic[k], 10, 6, 1, GL_RGBA, GL_UNSIGNED_BYTE,
                     img);
        e[3] = glGetError();
        snprintf(name, sizeof name, "%s_targets_errors", names[k]);
        sgl_text(out, name, "%#x %#x %#x %#x", e[0], e[1], e[2], e[3]);
        if (may_compress(k)) {
            snprintf(name, sizeof name, "%s_3d", names[k]);
            print_consistent(out, name, GL_TEXTURE_3D, bases[k], 2 * 1 * 2, 0);
            snprintf(name, sizeof name, "%s_cube", names[k]);
            print_consistent(out, name, GL_TEXTURE_CUBE_MAP_POSITIVE_Y, bases[k], 4, 0);
            snprintf(name, sizeof name, "%s_proxy", names[k]);
            print_consistent(out, name, GL_PROXY_TEXTURE_2D, bases[k], 4, 1);
            snprintf(name, sizeof name, "%s_border", names[k]);
            print_consistent(out, name, GL_TEXTURE_2D, bases[k], 2 * 1, 0);
        } else {
            snprintf(name, sizeof name, "%s_3d", names[k]);
            print_queries(out, name, GL_TEXTURE_3D);
            snprintf(name, sizeof name, "%s_cube", names[k]);
            print_queries(out, name, GL_TEXTURE_CUBE_MAP_POSITIVE_Y);
            snprintf(name, sizeof name, "%s_proxy", names[k]);
            print_queries(out, name, GL_PROXY_TEXTURE_2D);
            snprintf(name, sizeof name, "%s_border", names[k]);
            print_queries(out, name, GL_TEXTURE_2D);
        }
        glDeleteTextures(3, t);
    }

    /* the legacy internal formats 1-4: glTexImage takes them, glCopyTexImage
     * refuses them (GL_INVALID_ENUM) and leaves the image undefined */
    for (k = 1; k <= 4; k++) {
        GLuint t[3];
        GLenum e[3];
        glGenTextures(3, t);
        drain();
        glBindTexture(GL_TEXTURE_2D, t[0]);
        glTexImage2D(GL_TEXTURE_2D, 0, k, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
        e[0] = glGetError();
        glBindTexture(GL_TEXTURE_2D, t[1]);
        glCopyTexImage2D(GL_TEXTURE_2D, 0, (GLenum)k, 0, 0, 4, 4, 0);
        e[1] = glGetError();
        snprintf(name, sizeof name, "legacy%d_copy2d", k);
        print_queries(out, name, GL_TEXTURE_2D);
        glBindTexture(GL_TEXTURE_1D, t[2]);
        glCopyTexImage1D(GL_TEXTURE_1D, 0, (GLenum)k, 0, 0, 4, 0);
        e[2] = glGetError();
        snprintf(name, sizeof name, "legacy%d_errors", k);
        sgl_text(out, name, "%#x %#x %#x", e[0], e[1], e[2]);
        glDeleteTextures(3, t);
    }

    /* neighbours of the generic formats stay invalid */
    {
        GLuint t;
        GLenum e[4];
        glGenTextures(1, &t);
        glBindTexture(GL_TEXTURE_2D, t);
        drain();
        glTexImage2D(GL_TEXTURE_2D, 0, 0x84E8, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
        e[0] = glGetError();
        glTexImage2D(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSION_HINT, 4, 4, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, img);
        e[1] = glGetError();
        glCopyTexImage2D(GL_TEXTURE_2D, 0, 0x84E8, 0, 0, 4, 4, 0);
        e[2] = glGetError();
        glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_TEXTURE_COMPRESSION_HINT, 0, 0, 4, 0);
        e[3] = glGetError();
        sgl_text(out, "neighbours", "%#x %#x %#x %#x", e[0], e[1], e[2], e[3]);
        glDeleteTextures(1, &t);
    }

    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
