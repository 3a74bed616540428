/* tex_state: texturing state as text.  glGet of the texture limits and
 * bindings, glGetTexParameter / glGetTexLevelParameter / glGetTexEnv at the
 * defaults and after odd and out-of-range values (clamping of the border
 * colour and priority), proxy textures, per-unit texture matrices and
 * bindings, and the glGetError code of ~40 invalid texture calls (bad
 * target, bad filter and wrap enums, negative and too large sizes, bad
 * level, border and internal format, a packed type that does not fit the
 * format, glBindTexture with a target mismatch, glTexSubImage2D and
 * glCopyTexSubImage2D outside the texture, bad texture units, texenv enums
 * and scales, and a glTexImage2D inside glBegin/glEnd).  glActiveTexture
 * is only tried beyond 191: Mesa accepts units up to its combined image-unit
 * limit (192), softgl up to GL_MAX_TEXTURE_UNITS (8), as GL 1.5 without
 * shader units asks (tests/texture_api.rs checks GL_TEXTURE8 there). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 64
#define H 64

static char text[4096];
static int tlen;

static FILE *out;
static int nblock;

/* writes the text gathered so far as one block (common.h caps a block at 4 KiB) */
static void flush(void)
{
    char name[16];
    snprintf(name, sizeof name, "part%d", nblock++);
    sgl_text(out, name, "%s", text);
    tlen = 0;
    text[0] = 0;
}

static void put(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    tlen += vsnprintf(text + tlen, sizeof text - (size_t)tlen, fmt, ap);
    va_end(ap);
}

#define GETI(pname)                                                            \
    do {                                                                       \
        GLint v_[4] = {-7, -7, -7, -7};                                        \
        glGetIntegerv(pname, v_);                                              \
        put("%s = %d\n", #pname, v_[0]);                                       \
    } while (0)
#define GETF(pname)                                                            \
    do {                                                                       \
        GLfloat v_[16];                                                        \
        glGetFloatv(pname, v_);                                                \
        put("%s = %.6g\n", #pname, v_[0]);                                     \
    } while (0)
#define TEXPI(target, pname)                                                   \
    do {                                                                       \
        GLint v_[4] = {-7, -7, -7, -7};                                        \
        glGetTexParameteriv(target, pname, v_);                                \
        put("  %s = %d (0x%x)\n", #pname, v_[0], (unsigned)v_[0]);            \
    } while (0)
#define TEXPF(target, pname)                                                   \
    do {                                                                       \
        GLfloat v_[4] = {-7, -7, -7, -7};                                      \
        glGetTexParameterfv(target, pname, v_);                                \
        put("  %s = %.6g\n", #pname, v_[0]);                                   \
    } while (0)
#define LEVI(level, pname)                                                     \
    do {                                                                       \
        GLint v_ = -7;                                                         \
        glGetTexLevelParameteriv(GL_TEXTURE_2D, level, pname, &v_);            \
        put("  level %d %s = %d\n", level, #pname, v_);                        \
    } while (0)
#define ENVI(pname)                                                            \
    do {                                                                       \
        GLint v_[4] = {-7, -7, -7, -7};                                        \
        glGetTexEnviv(GL_TEXTURE_ENV, pname, v_);                              \
        put("  %s = 0x%x\n", #pname, (unsigned)v_[0]);                         \
    } while (0)
#define ERR(call)                                                              \
    do {                                                                       \
        call;                                                                  \
        put("%-70s -> 0x%04x\n", #call, glGetError());                         \
    } while (0)

static void tex_params(void)
{
    GLfloat bc[4] = {-7, -7, -7, -7};
    TEXPI(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER);
    TEXPI(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER);
    TEXPI(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S);
    TEXPI(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T);
    TEXPI(GL_TEXTURE_2D, GL_TEXTURE_WRAP_R);
    TEXPF(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD);
    TEXPF(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD);
    TEXPI(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL);
    TEXPI(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL);
    TEXPF(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS);
    TEXPI(GL_TEXTURE_2D, GL_GENERATE_MIPMAP);
    TEXPF(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY);
    TEXPF(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT);
    glGetTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, bc);
    put("  GL_TEXTURE_BORDER_COLOR = %.6g %.6g %.6g %.6g\n", bc[0], bc[1], bc[2], bc[3]);
}

static void env_params(void)
{
    GLfloat c[4] = {-7, -7, -7, -7}, f = -7;
    ENVI(GL_TEXTURE_ENV_MODE);
    ENVI(GL_COMBINE_RGB);
    ENVI(GL_COMBINE_ALPHA);
    ENVI(GL_SOURCE0_RGB);
    ENVI(GL_SOURCE1_RGB);
    ENVI(GL_SOURCE2_RGB);
    ENVI(GL_OPERAND0_RGB);
    ENVI(GL_OPERAND1_RGB);
    ENVI(GL_OPERAND2_RGB);
    ENVI(GL_SOURCE0_ALPHA);
    ENVI(GL_SOURCE2_ALPHA);
    ENVI(GL_OPERAND0_ALPHA);
    ENVI(GL_OPERAND2_ALPHA);
    glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, c);
    put("  GL_TEXTURE_ENV_COLOR = %.6g %.6g %.6g %.6g\n", c[0], c[1], c[2], c[3]);
    glGetTexEnvfv(GL_TEXTURE_ENV, GL_RGB_SCALE, &f);
    put("  GL_RGB_SCALE = %.6g\n", f);
    glGetTexEnvfv(GL_TEXTURE_ENV, GL_ALPHA_SCALE, &f);
    put("  GL_ALPHA_SCALE = %.6g\n", f);
    glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &f);
    put("  FILTER_CONTROL GL_TEXTURE_LOD_BIAS = %.6g\n", f);
}

int main(int argc, char **argv)
{
    static unsigned char pixels[64 * 64 * 4];
    out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    GLuint tex[4];
    GLint maxsize = 0, i;
    GLfloat m[16];

    memset(pixels, 0x5A, sizeof pixels);
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxsize);
    put("-- limits and initial bindings\n");
    GETI(GL_MAX_TEXTURE_SIZE);
    GETI(GL_MAX_TEXTURE_UNITS);
    GETI(GL_MAX_3D_TEXTURE_SIZE);
    GETI(GL_MAX_CUBE_MAP_TEXTURE_SIZE);
    GETF(GL_MAX_TEXTURE_LOD_BIAS);
    GETF(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT);
    GETI(GL_TEXTURE_BINDING_1D);
    GETI(GL_TEXTURE_BINDING_2D);
    GETI(GL_ACTIVE_TEXTURE);
    GETI(GL_CLIENT_ACTIVE_TEXTURE);
    GETI(GL_TEXTURE_2D);
    GETI(GL_TEXTURE_STACK_DEPTH);
    GETI(GL_MAX_TEXTURE_STACK_DEPTH);
    GETI(GL_UNPACK_ALIGNMENT);
    GETI(GL_GENERATE_MIPMAP_HINT);
    flush();
    put("-- default texture object 0 parameters\n");
    tex_params();
    flush();
    put("-- default texture environment\n");
    env_params();

    glGenTextures(4, tex);
    put("glIsTexture(generated, unbound) = %d\n", glIsTexture(tex[0]));
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    put("glIsTexture(bound) = %d\n", glIsTexture(tex[0]));
    GETI(GL_TEXTURE_BINDING_2D);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 37, 23, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    glTexImage2D(GL_TEXTURE_2D, 2, GL_RGB5, 9, 5, 0, GL_RGB, GL_UNSIGNED_BYTE, pixels);
    flush();
    put("-- level parameters (level 1 never specified)\n");
    for (i = 0; i < 3; i++) {
        LEVI(i, GL_TEXTURE_WIDTH);
        LEVI(i, GL_TEXTURE_HEIGHT);
        LEVI(i, GL_TEXTURE_BORDER);
        LEVI(i, GL_TEXTURE_INTERNAL_FORMAT);
        LEVI(i, GL_TEXTURE_RED_SIZE);
        LEVI(i, GL_TEXTURE_ALPHA_SIZE);
        LEVI(i, GL_TEXTURE_COMPRESSED);
    }
    flush();
    put("-- after odd values\n");
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLfloat)GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_MIRRORED_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_R, GL_CLAMP);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, 1.37f);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, -2.5f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 3);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 2);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, 99.5f);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, 7);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_PRIORITY, 1.7f);
    glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 5.5f);
    {
        GLfloat bc[4] = {-0.5f, 1.5f, 0.25f, 2.0f};
        glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, bc);
    }
    tex_params();
    {
        GLint ibc[4] = {-7, -7, -7, -7};
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, ibc);
        put("  GL_TEXTURE_BORDER_COLOR (int) = %d %d %d %d\n", ibc[0], ibc[1], ibc[2], ibc[3]);
    }
    {
        GLfloat c[4] = {1.5f, -0.25f, 0.3f, 0.7f};
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
        glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DOT3_RGBA);
        glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_SUBTRACT);
        glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, GL_PREVIOUS);
        glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, GL_ONE_MINUS_SRC_ALPHA);
        glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 4.0f);
        glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 2.0f);
        glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, c);
        glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 33.0f);
        env_params();
    }
    flush();
    put("-- proxy textures\n");
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 64, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    {
        GLint w = -7, h = -7;
        glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
        glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT, &h);
        put("  proxy 64x32: %d x %d, error 0x%x\n", w, h, glGetError());
        glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, maxsize * 2, 4, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, NULL);
        glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &w);
        put("  proxy too wide: width %d, error 0x%x\n", w, glGetError());
    }
    flush();
    put("-- units, matrices, bindings\n");
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glMatrixMode(GL_TEXTURE);
    glTranslatef(0.25f, 0.5f, 0.0f);
    glScalef(2.0f, 3.0f, 1.0f);
    glPushMatrix();
    GETI(GL_ACTIVE_TEXTURE);
    GETI(GL_TEXTURE_BINDING_2D);
    GETI(GL_TEXTURE_STACK_DEPTH);
    glGetFloatv(GL_TEXTURE_MATRIX, m);
    put("unit 1 texture matrix: %g %g %g %g / %g %g %g %g / %g %g %g %g / %g %g %g %g\n",
        m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8], m[9], m[10], m[11], m[12],
        m[13], m[14], m[15]);
    glActiveTexture(GL_TEXTURE0);
    GETI(GL_TEXTURE_BINDING_2D);
    GETI(GL_TEXTURE_STACK_DEPTH);
    glGetFloatv(GL_TEXTURE_MATRIX, m);
    put("unit 0 texture matrix [12..13]: %g %g\n", m[12], m[13]);
    glMatrixMode(GL_MODELVIEW);
    glClientActiveTexture(GL_TEXTURE3);
    GETI(GL_CLIENT_ACTIVE_TEXTURE);
    glClientActiveTexture(GL_TEXTURE0);
    glDeleteTextures(1, &tex[0]);
    put("after delete: glIsTexture = %d\n", glIsTexture(tex[0]));
    GETI(GL_TEXTURE_BINDING_2D);
    while (glGetError() != GL_NO_ERROR)
        ;

    flush();
    put("-- errors\n");
    glBindTexture(GL_TEXTURE_2D, tex[2]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    ERR(glTexImage2D(0x1234, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
    ERR(glTexParameteri(0x1234, GL_TEXTURE_MIN_FILTER, GL_LINEAR));
    ERR(glTexParameteri(GL_TEXTURE_2D, 0x1234, GL_LINEAR));
    ERR(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_RGBA));
    ERR(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR_MIPMAP_LINEAR));
    ERR(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_LINEAR));
    ERR(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_NEAREST));
    ERR(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, -1));
    ERR(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, -3));
    ERR(glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, 0.5f));
    ERR(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
    ERR(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, -1, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
    ERR(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, maxsize * 2, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL));
    ERR(glTexImage2D(GL_TEXTURE_2D, -1, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
    ERR(glTexImage2D(GL_TEXTURE_2D, 40, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
    ERR(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
    ERR(glTexImage2D(GL_TEXTURE_2D, 0, 5, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
    ERR(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, 0x1234, GL_UNSIGNED_BYTE, pixels));
    ERR(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, 0x1234, pixels));
    ERR(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, pixels));
    ERR(glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, pixels));
    ERR(glTexImage1D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
    ERR(glBindTexture(GL_TEXTURE_1D, tex[2]));
    ERR(glBindTexture(0x1234, tex[3]));
    flush();
    ERR(glTexSubImage2D(GL_TEXTURE_2D, 0, 10, 2, 7, 3, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
    ERR(glTexSubImage2D(GL_TEXTURE_2D, 0, -1, 0, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
    ERR(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 6, 2, 3, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
    ERR(glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 2, -2, 3, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
    ERR(glTexSubImage2D(GL_TEXTURE_2D, 3, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
    ERR(glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 16, 8, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
    ERR(glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 12, 0, 0, 0, 5, 5));
    ERR(glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 8, 4, 3));
    ERR(glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, -8, 4, 0));
    ERR(glActiveTexture(GL_TEXTURE0 + 192));
    ERR(glActiveTexture(GL_TEXTURE0 + 7));
    GETI(GL_ACTIVE_TEXTURE);
    put("(texenv and texparameter calls on unit 7:)\n");
    ERR(glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_LINEAR));
    ERR(glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_ADD));
    ERR(glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR));
    ERR(glActiveTexture(0x1234));
    ERR(glActiveTexture(GL_TEXTURE0));
    ERR(glClientActiveTexture(GL_TEXTURE0 + 8));
    /* glMultiTexCoord with a unit beyond 7 (and a junk target): Mesa uses the
     * target's low three bits as the unit, with no error */
    ERR(glMultiTexCoord4f(GL_TEXTURE0 + 9, 0.25f, 0.5f, 0.75f, 2.0f));
    ERR(glMultiTexCoord2f(0x1236, 0.125f, 4.0f));
    ERR(glActiveTexture(GL_TEXTURE1));
    GETF(GL_CURRENT_TEXTURE_COORDS);
    ERR(glActiveTexture(GL_TEXTURE6));
    GETF(GL_CURRENT_TEXTURE_COORDS);
    ERR(glActiveTexture(GL_TEXTURE0));
    flush();
    ERR(glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_LINEAR));
    ERR(glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, GL_DOT3_RGB));
    ERR(glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, GL_DECAL));
    ERR(glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, 3.0f));
    ERR(glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 0.5f));
    ERR(glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_ALPHA, GL_SRC_COLOR));
    ERR(glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, GL_TEXTURE0 + 7));
    /* (no GL_SOURCE0_RGB = GL_ONE: GL_ONE/GL_ZERO sources are
     * ATI_texture_env_combine3, not GL 1.5; Mesa accepts them, softgl does not) */
    ERR(glTexEnvi(0x1234, GL_TEXTURE_ENV_MODE, GL_MODULATE));
    {
        GLint v = -7;
        ERR(glGetTexLevelParameteriv(GL_TEXTURE_2D, -1, GL_TEXTURE_WIDTH, &v));
        ERR(glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, 0x1234, &v));
        ERR(glGetTexParameteriv(GL_TEXTURE_2D, 0x1234, &v));
        ERR(glGetTexEnviv(GL_TEXTURE_ENV, 0x1234, &v));
    }
    ERR(glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, pixels));
    ERR(glGetTexImage(GL_TEXTURE_2D, -1, GL_RGBA, GL_UNSIGNED_BYTE, pixels));
    ERR(glGenTextures(-1, tex));
    ERR(glDeleteTextures(-1, tex));
    glBegin(GL_TRIANGLES);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, pixels);
    glEnd();
    put("glTexImage2D inside glBegin/glEnd -> 0x%04x\n", glGetError());
    flush();
    put("-- state unchanged by the failed calls\n");
    LEVI(0, GL_TEXTURE_WIDTH);
    LEVI(0, GL_TEXTURE_HEIGHT);
    GETI(GL_ACTIVE_TEXTURE);
    GETI(GL_TEXTURE_BINDING_2D);
    GETI(GL_TEXTURE_BINDING_1D);
    tex_params();

    flush();
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
