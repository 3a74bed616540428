/* tex_s3tc: pre-compressed textures as DDS loaders upload them. Every S3TC, sRGB S3TC,
 * RGTC and LATC format gets deterministic random blocks (with forced blocks for DXT1's
 * 3-colour mode and equal colours, DXT5's 6- and 8-value alpha modes, and the signed
 * extremes -128/-127/127) in a full mipmap chain, drawn magnified with NEAREST and LINEAR,
 * with MIRRORED_REPEAT (the float path), and minified with mipmaps; signed formats are
 * drawn through GL_INTERPOLATE as 0.5 + 0.5 * texel. Then glGetCompressedTexImage round
 * trips, glCompressedTexSubImage2D, glGetTexImage of the decoded texels, level queries,
 * the format list, the extensions, display lists and the error codes. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <string.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256
#define NF 16
#define T 16

static const GLenum fmts[NF] = {
    GL_COMPRESSED_RGB_S3TC_DXT1_EXT, GL_COMPRESSED_RGBA_S3TC_DXT1_EXT,
    GL_COMPRESSED_RGBA_S3TC_DXT3_EXT, GL_COMPRESSED_RGBA_S3TC_DXT5_EXT,
    GL_COMPRESSED_SRGB_S3TC_DXT1_EXT, GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT,
    GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT3_EXT, GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT,
    GL_COMPRESSED_RED_RGTC1, GL_COMPRESSED_SIGNED_RED_RGTC1,
    GL_COMPRESSED_RG_RGTC2, GL_COMPRESSED_SIGNED_RG_RGTC2,
    GL_COMPRESSED_LUMINANCE_LATC1_EXT, GL_COMPRESSED_SIGNED_LUMINANCE_LATC1_EXT,
    GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT, GL_COMPRESSED_SIGNED_LUMINANCE_ALPHA_LATC2_EXT,
};

static unsigned int rng = 0x2468aceu;
static unsigned char rb(void)
{
    rng = rng * 1664525u + 1013904223u;
    return (unsigned char)(rng >> 24);
}

static int block_bytes(int f)
{
    GLenum e = fmts[f];
    return (e == GL_COMPRESSED_RGB_S3TC_DXT1_EXT || e == GL_COMPRESSED_RGBA_S3TC_DXT1_EXT ||
            e == GL_COMPRESSED_SRGB_S3TC_DXT1_EXT ||
            e == GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT1_EXT || e == GL_COMPRESSED_RED_RGTC1 ||
            e == GL_COMPRESSED_SIGNED_RED_RGTC1 || e == GL_COMPRESSED_LUMINANCE_LATC1_EXT ||
            e == GL_COMPRESSED_SIGNED_LUMINANCE_LATC1_EXT)
               ? 8
               : 16;
}

static int is_signed(int f) { return f >= 8 && (f & 1); }
static int is_dxt(int f) { return f < 8; }
static int size_of(int f, int w, int h) { return ((w + 3) / 4) * ((h + 3) / 4) * block_bytes(f); }

/* Fills one block; k is the block's index, used to force the special modes. */
static void fill_block(int f, int k, unsigned char *b)
{
    int n = block_bytes(f), i;
    for (i = 0; i < n; i++)
        b[i] = rb();
    if (is_dxt(f)) {
        unsigned char *c = b + n - 8;
        if (k % 4 == 0) { /* equal colours */
            c[2] = c[0];
            c[3] = c[1];
        } else if (k % 4 == 1 && (c[1] << 8 | c[0]) < (c[3] << 8 | c[2])) {
            unsigned char t0 = c[0], t1 = c[1]; /* 4-colour mode */
            c[0] = c[2], c[1] = c[3], c[2] = t0, c[3] = t1;
        } else if (k % 4 == 2 && (c[1] << 8 | c[0]) > (c[3] << 8 | c[2])) {
            unsigned char t0 = c[0], t1 = c[1]; /* 3-colour mode */
            c[0] = c[2], c[1] = c[3], c[2] = t0, c[3] = t1;
        }
        if (n == 16 && (f == 3 || f == 7)) { /* DXT5 alpha modes */
            if (k % 3 == 0 && b[0] > b[1]) {
                unsigned char t = b[0];
                b[0] = b[1], b[1] = t;
            } else if (k % 3 == 1 && b[0] < b[1]) {
                unsigned char t = b[0];
                b[0] = b[1], b[1] = t;
            } else if (k % 3 == 2)
                b[1] = b[0];
        }
    } else {
        int half;
        for (half = 0; half < n / 8; half++) {
            unsigned char *a = b + 8 * half;
            switch (k % 5) {
            case 0: a[0] = is_signed(f) ? 0x80 : 0x00; a[1] = is_signed(f) ? 0x81 : 0xff; break;
            case 1: a[0] = 0x7f; a[1] = 0x80; break;
            case 2: a[0] = 0x80; a[1] = 0x7f; break;
            case 3: if (a[0] < a[1]) { unsigned char t = a[0]; a[0] = a[1]; a[1] = t; } break;
            default: if (a[0] > a[1]) { unsigned char t = a[0]; a[0] = a[1]; a[1] = t; } break;
            }
        }
    }
}

static unsigned char *levels[NF][5];
static const int lsize[5] = {16, 8, 4, 2, 1};

static void make_texture(int f, GLuint name)
{
    int l;
    glBindTexture(GL_TEXTURE_2D, name);
    for (l = 0; l < 5; l++) {
        int s = lsize[l], n = size_of(f, s, s), k;
        if (!levels[f][l]) {
            levels[f][l] = malloc((size_t)n);
            SGL_CHECK(levels[f][l] != NULL);
            for (k = 0; k < n / block_bytes(f); k++)
                fill_block(f, k + l, levels[f][l] + k * block_bytes(f));
        }
        glCompressedTexImage2D(GL_TEXTURE_2D, l, fmts[f], s, s, 0, n, levels[f][l]);
    }
}

static void set_env(int f)
{
    static const GLfloat half[4] = {1.0f, 1.0f, 1.0f, 0.5f};
    if (!is_signed(f)) {
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
        return;
    }
    /* 0.5 + 0.5 * texel: INTERPOLATE(texture, constant 1, constant alpha 0.5) */
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, half);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_INTERPOLATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_INTERPOLATE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, GL_CONSTANT);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_CONSTANT);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, GL_SRC_ALPHA);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_ALPHA, GL_TEXTURE);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_ALPHA, GL_CONSTANT);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_ALPHA, GL_CONSTANT);
}

static void quad(float x0, float y0, float x1, float y1, float s0, float t0, float s1, float t1)
{
    glBegin(GL_QUADS);
    glTexCoord2f(s0, t0); glVertex2f(x0, y0);
    glTexCoord2f(s1, t0); glVertex2f(x1, y0);
    glTexCoord2f(s1, t1); glVertex2f(x1, y1);
    glTexCoord2f(s0, t1); glVertex2f(x0, y1);
    glEnd();
}

/* One pass: every format in a 4x4 grid of 64x64 cells. */
static void pass(FILE *out, const char *name, const GLuint *tex, int mode)
{
    int f;
    glClear(GL_COLOR_BUFFER_BIT);
    for (f = 0; f < NF; f++) {
        float x = (float)(f % 4) * 64.0f, y = (float)(f / 4) * 64.0f;
        glBindTexture(GL_TEXTURE_2D, tex[f]);
        set_env(f);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, mode == 2 ? GL_MIRRORED_REPEAT : GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, mode == 2 ? GL_MIRRORED_REPEAT : GL_REPEAT);
        switch (mode) {
        case 0: /* magnified 4x, NEAREST */
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
            quad(x, y, x + 64, y + 64, 0, 0, 1, 1);
            break;
        case 1: /* magnified, LINEAR, off the texel grid */
        case 2: /* the same with MIRRORED_REPEAT across the edges */
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            if (mode == 1)
                quad(x, y, x + 64, y + 64, 0.013f, 0.027f, 1.013f, 1.027f);
            else
                quad(x, y, x + 64, y + 64, -0.37f, -0.29f, 1.41f, 1.33f);
            break;
        default: /* minified with mipmaps: trilinear, and nearest-nearest */
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glBegin(GL_QUADS);
            glTexCoord2f(0, 0); glVertex2f(x + 2, y + 2);
            glTexCoord2f(3.1f, 0); glVertex2f(x + 62, y + 2);
            glTexCoord2f(7.3f, 5.2f); glVertex2f(x + 50, y + 30);
            glTexCoord2f(0, 2.2f); glVertex2f(x + 10, y + 30);
            glEnd();
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
            quad(x + 2, y + 34, x + 30, y + 62, 0.1f, 0.2f, 4.3f, 4.6f);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_NEAREST);
            quad(x + 34, y + 34, x + 43, y + 43, 0.0f, 0.0f, 2.0f, 3.0f);
            quad(x + 46, y + 34, x + 62, y + 62, 0.3f, 0.1f, 1.4f, 1.9f);
            break;
        }
    }
    glFinish();
    {
        unsigned char *px = malloc(W * H * 4);
        SGL_CHECK(px != NULL);
        glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
        sgl_image(out, name, W, H, 4, "RGBA", W * 4, 1, px);
        free(px);
    }
}

#define ERR(what) sgl_text(out, "err", "%s: 0x%x\n", what, glGetError())

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf, back[2048], data[2048];
    float fback[T * T * 4];
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    GLuint tex[NF], other, list;
    GLint v[16], n, i, l, f;
    const char *ext;
    static const char *names[6] = {"GL_EXT_texture_compression_s3tc", "GL_ARB_texture_compression_rgtc",
                                    "GL_EXT_texture_compression_rgtc", "GL_EXT_texture_compression_latc",
                                    "GL_EXT_texture_sRGB", "GL_ARB_texture_compression"};

    glGenTextures(NF, tex);
    glGenTextures(1, &other);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    sgl_ortho(W, H);
    glEnable(GL_TEXTURE_2D);
    for (f = 0; f < NF; f++) {
        make_texture(f, tex[f]);
        sgl_text(out, "upload", "%d 0x%x: 0x%x\n", f, fmts[f], glGetError());
    }
    pass(out, "nearest", tex, 0);
    pass(out, "linear", tex, 1);
    pass(out, "mirrored", tex, 2);
    pass(out, "mipmaps", tex, 3);

    /* round trips and queries */
    for (f = 0; f < NF; f++) {
        glBindTexture(GL_TEXTURE_2D, tex[f]);
        for (l = 0; l < 5; l++) {
            int s = lsize[l], sz = size_of(f, s, s);
            memset(back, 0xcd, sizeof back);
            glGetCompressedTexImage(GL_TEXTURE_2D, l, back);
            sgl_text(out, "roundtrip", "%d %d: %s %s 0x%x\n", f, l,
                     memcmp(back, levels[f][l], (size_t)sz) == 0 ? "same" : "DIFFERENT",
                     back[sz] == 0xcd ? "tail-untouched" : "TAIL-WRITTEN", glGetError());
        }
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &v[0]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &v[1]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &v[2]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 4, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &v[3]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v[4]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &v[5]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_GREEN_SIZE, &v[6]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_BLUE_SIZE, &v[7]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_ALPHA_SIZE, &v[8]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_LUMINANCE_SIZE, &v[9]);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTENSITY_SIZE, &v[10]);
        sgl_text(out, "levelq", "%d: if 0x%x c %d sz %d %d w %d rgbali %d %d %d %d %d %d err 0x%x\n", f,
                 v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], glGetError());
        /* the decoded texels of level 0, which llvmpipe blits with its sampler (Mesa
         * reads the signed formats and LATC2 back through its CPU decoder instead, with
         * exact fifths and sevenths: softgl does not, see the README) */
        if (!is_signed(f) && fmts[f] != GL_COMPRESSED_LUMINANCE_ALPHA_LATC2_EXT) {
            glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
            sgl_data(out, "getteximage", T * T * 4, back);
            glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, fback);
            sgl_data(out, "getteximage-float", sizeof fback, fback);
            ERR("getteximage");
        }
    }

    /* proxies */
    for (f = 0; f < NF; f += 3) {
        glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 0, fmts[f], 64, 32, 0, size_of(f, 64, 32), NULL);
        glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v[0]);
        glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &v[1]);
        glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &v[2]);
        sgl_text(out, "proxy", "%d: w %d if 0x%x c %d err 0x%x\n", f, v[0], v[1], v[2], glGetError());
        glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &v[3]);
        ERR("proxy image size");
    }
    glCompressedTexImage2D(GL_PROXY_TEXTURE_2D, 0, fmts[0], 32768, 4, 0, size_of(0, 32768, 4), NULL);
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v[0]);
    sgl_text(out, "proxy-too-big", "w %d err 0x%x\n", v[0], glGetError());

    /* the format list and the extensions */
    glGetIntegerv(GL_NUM_COMPRESSED_TEXTURE_FORMATS, &n);
    {
        GLint list_[64];
        SGL_CHECK(n < 64);
        glGetIntegerv(GL_COMPRESSED_TEXTURE_FORMATS, list_);
        for (f = 0; f < NF; f++) {
            int found = 0;
            for (i = 0; i < n; i++)
                found |= list_[i] == (GLint)fmts[f];
            sgl_text(out, "listed", "0x%x %d\n", fmts[f], found);
        }
    }
    ext = (const char *)glGetString(GL_EXTENSIONS);
    for (i = 0; i < 6; i++) {
        const char *p = strstr(ext, names[i]);
        size_t len = strlen(names[i]);
        sgl_text(out, "ext", "%s %d\n", names[i], p && (p[len] == ' ' || p[len] == 0));
    }

    /* glCompressedTexSubImage2D: an inner block, a block at the edge of a 2x2 level */
    for (f = 0; f < NF; f++) {
        int bb = block_bytes(f);
        glBindTexture(GL_TEXTURE_2D, tex[f]);
        for (i = 0; i < 2 * bb; i++)
            data[i] = rb();
        glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 4, 8, 8, 4, fmts[f], 2 * bb, data);
        glCompressedTexSubImage2D(GL_TEXTURE_2D, 3, 0, 0, 2, 2, fmts[f], bb, data + bb);
        ERR("subimage");
        glGetCompressedTexImage(GL_TEXTURE_2D, 0, back);
        sgl_data(out, "sub-level0", (size_t)size_of(f, 16, 16), back);
        glGetCompressedTexImage(GL_TEXTURE_2D, 3, back);
        sgl_data(out, "sub-level3", (size_t)bb, back);
    }
    pass(out, "after-sub", tex, 0);

    /* a display list holding the upload */
    glBindTexture(GL_TEXTURE_2D, other);
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, fmts[3], 16, 16, 0, size_of(3, 16, 16), levels[3][0]);
    glEndList();
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v[0]);
    glCallList(list);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v[1]);
    glGetCompressedTexImage(GL_TEXTURE_2D, 0, back);
    sgl_text(out, "list", "w %d %d %s err 0x%x\n", v[0], v[1],
             memcmp(back, levels[3][0], (size_t)size_of(3, 16, 16)) == 0 ? "same" : "DIFFERENT",
             glGetError());

    /* errors */
    glBindTexture(GL_TEXTURE_2D, other);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, fmts[0], 8, 8, 0, 31, levels[0][0]);
    ERR("image size 31");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, fmts[0], 8, 8, 0, 0, NULL);
    ERR("image size 0");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, fmts[0], 8, 8, 1, 32, levels[0][0]);
    ERR("border 1");
    glCompressedTexImage2D(GL_TEXTURE_2D, -1, fmts[0], 8, 8, 0, 32, levels[0][0]);
    ERR("level -1");
    glCompressedTexImage2D(GL_TEXTURE_2D, 15, fmts[0], 1, 1, 0, 8, levels[0][0]);
    ERR("level 15");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, 32, levels[0][0]);
    ERR("format RGBA");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGB, 8, 8, 0, 32, levels[0][0]);
    ERR("format generic");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, 0x1234, 8, 8, 0, 32, levels[0][0]);
    ERR("format 0x1234");
    glCompressedTexImage1D(GL_TEXTURE_1D, 0, fmts[0], 8, 0, 16, levels[0][0]);
    ERR("1D");
    glCompressedTexImage1D(GL_PROXY_TEXTURE_1D, 0, fmts[8], 8, 0, 16, levels[0][0]);
    ERR("proxy 1D");
    glCompressedTexImage3D(GL_TEXTURE_3D, 0, fmts[0], 4, 4, 1, 0, 8, levels[0][0]);
    ERR("3D");
    glCompressedTexImage3D(GL_PROXY_TEXTURE_3D, 0, fmts[3], 4, 4, 1, 0, 16, levels[0][0]);
    ERR("proxy 3D");
    glCompressedTexImage3D(GL_TEXTURE_2D, 0, fmts[3], 4, 4, 1, 0, 16, levels[0][0]);
    ERR("3D call, 2D target");
    glCompressedTexImage2D(GL_TEXTURE_CUBE_MAP, 0, fmts[0], 8, 8, 0, 32, levels[0][0]);
    ERR("cube map target");
    glCompressedTexImage2D(GL_TEXTURE_1D, 0, fmts[0], 8, 8, 0, 32, levels[0][0]);
    ERR("2D call, 1D target");
    glCompressedTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, fmts[0], 8, 4, 0, 16, levels[0][0]);
    ERR("cube face not square");
    glCompressedTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, fmts[1], 8, 8, 0, 32, levels[1][0]);
    ERR("cube face");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, fmts[0], 32768, 4, 0, size_of(0, 32768, 4), NULL);
    ERR("too wide");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, fmts[0], -1, 4, 0, 0, NULL);
    ERR("width -1");
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, fmts[0], 6, 6, 0, 32, levels[0][0]);
    ERR("6x6 (partial blocks)");
    glCompressedTexImage2D(GL_TEXTURE_2D, 1, fmts[0], 3, 3, 0, 8, levels[0][0]);
    ERR("3x3 level 1");
    glBegin(GL_TRIANGLES);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, fmts[0], 8, 8, 0, 32, levels[0][0]);
    glEnd();
    ERR("inside begin/end");

    /* sub-images against the 6x6 DXT1 image */
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 2, 0, 4, 4, fmts[0], 8, data);
    ERR("sub x 2");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 4, fmts[0], 8, data);
    ERR("sub width 2 inside");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 4, 4, 2, 2, fmts[0], 8, data);
    ERR("sub 2x2 at the edge");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 4, 0, 4, 4, fmts[0], 8, data);
    ERR("sub past the edge");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, -4, 0, 4, 4, fmts[0], 8, data);
    ERR("sub x -4");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, -4, 4, fmts[0], 0, data);
    ERR("sub width -4");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, fmts[0], 16, data);
    ERR("sub size 16");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, fmts[2], 16, data);
    ERR("sub other format");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_RGBA, 8, data);
    ERR("sub RGBA");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 4, 4, GL_COMPRESSED_RGBA, 8, data);
    ERR("sub generic");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, 3, 0, 0, 4, 4, fmts[0], 8, data);
    ERR("sub missing level");
    glCompressedTexSubImage2D(GL_TEXTURE_2D, -1, 0, 0, 4, 4, fmts[0], 8, data);
    ERR("sub level -1");
    glCompressedTexSubImage2D(GL_TEXTURE_1D, 0, 0, 0, 4, 4, fmts[0], 8, data);
    ERR("sub 1D target");
    glCompressedTexSubImage1D(GL_TEXTURE_1D, 0, 0, 4, fmts[0], 8, data);
    ERR("sub 1D");
    glCompressedTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 0, 4, 4, 1, fmts[0], 8, data);
    ERR("sub 3D");
    glCompressedTexSubImage3D(GL_TEXTURE_2D, 0, 0, 0, 0, 4, 4, 1, fmts[0], 8, data);
    ERR("sub 3D call, 2D target");
    glCompressedTexSubImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, 4, 4, 4, 4, fmts[1], 8, data);
    ERR("sub cube face");
    glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, data);
    ERR("TexSubImage x 2");
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, data);
    ERR("TexSubImage 2x2 inside");
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 8, 4, GL_RGBA, GL_UNSIGNED_BYTE, data);
    ERR("TexSubImage past the edge");

    glGetCompressedTexImage(GL_TEXTURE_2D, 0, back);
    sgl_data(out, "blocks-6x6", 32, back);
    ERR("get 6x6");
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &v[0]);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 1, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &v[1]);
    sgl_text(out, "size-6x6", "%d %d 0x%x\n", v[0], v[1], glGetError());
    glGetCompressedTexImage(GL_PROXY_TEXTURE_2D, 0, back);
    ERR("get proxy");
    glGetCompressedTexImage(GL_TEXTURE_2D, -1, back);
    ERR("get level -1");
    glGetCompressedTexImage(GL_TEXTURE_2D, 5, back);
    ERR("get missing level");
    glGetCompressedTexImage(GL_TEXTURE_CUBE_MAP, 0, back);
    ERR("get cube map");
    glGetCompressedTexImage(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, back);
    sgl_data(out, "cube-face-blocks", 32, back);
    ERR("get cube face");
    glGetCompressedTexImage(GL_TEXTURE_2D, 0, NULL);
    ERR("get NULL");
    {
        unsigned char rgba[64];
        memset(rgba, 7, sizeof rgba);
        glBindTexture(GL_TEXTURE_2D, other);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
        glGetCompressedTexImage(GL_TEXTURE_2D, 0, back);
        ERR("get uncompressed");
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &v[0]);
        ERR("size of uncompressed");
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &v[0]);
        sgl_text(out, "uncompressed", "%d 0x%x\n", v[0], glGetError());
    }

    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
