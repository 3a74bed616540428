/* fbo_float_tex: float and 16-bit colour *textures* as framebuffer attachments
 * (GL_RGBA16F, RGBA32F, RGB16F, RGB32F, R16F, R32F, RG16F, RG32F, R16, RG16, RGBA16,
 * RGB16 and the ARB_texture_float alpha / luminance / luminance-alpha / intensity
 * formats). Each is checked (glCheckFramebufferStatus, the attachment's sizes and
 * component type, GL_RED_BITS …), cleared with values outside [0, 1], drawn into with an
 * HDR float texture (GL_REPLACE, values −1.5 … 3), additive and subtractive blending, a
 * scissored clear, and read back as GL_FLOAT and GL_UNSIGNED_BYTE; glGetTexImage shows
 * what the render stored. A second pass samples the rendered texture into an RGBA32F
 * target (values beyond [0, 1] must survive: HDR round trip) and onto the 8-bit window
 * with GL_REPLACE and GL_MODULATE. Mesa renders every one of these formats at its own
 * precision (llvmpipe: no fragment clamp for float targets, half floats converted
 * toward zero, 16-bit unorm in 16-bit fixed point; docs/fbo-rules.md §6). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <math.h>
#include "common.h"

#define W 96
#define H 64
#define TW 13
#define TH 11
#define HW 8

struct fmt {
    const char *name;
    GLenum internal;
    int unorm_single; /* a 16-bit unorm target of one channel */
};

static const struct fmt formats[] = {
    {"rgba16f", GL_RGBA16F, 0},
    {"rgba32f", GL_RGBA32F, 0},
    {"rgb16f", GL_RGB16F, 0},
    {"rgb32f", GL_RGB32F, 0},
    {"r16f", GL_R16F, 0},
    {"r32f", GL_R32F, 0},
    {"rg16f", GL_RG16F, 0},
    {"rg32f", GL_RG32F, 0},
    {"r16", GL_R16, 1},
    {"rg16", GL_RG16, 0},
    {"rgba16", GL_RGBA16, 0},
    {"rgb16", GL_RGB16, 0},
    {"a16f", GL_ALPHA16F_ARB, 0},
    {"a32f", GL_ALPHA32F_ARB, 0},
    {"l16f", GL_LUMINANCE16F_ARB, 0},
    {"l32f", GL_LUMINANCE32F_ARB, 0},
    {"la16f", GL_LUMINANCE_ALPHA16F_ARB, 0},
    {"la32f", GL_LUMINANCE_ALPHA32F_ARB, 0},
    {"i16f", GL_INTENSITY16F_ARB, 0},
    {"i32f", GL_INTENSITY32F_ARB, 0},
};

#define NF ((int)(sizeof formats / sizeof formats[0]))

static GLuint hdr_tex; /* an RGBA32F source with values in [-1.5, 3] */

static void make_hdr(void)
{
    static float px[HW * HW * 4];
    int x, y, k;
    for (y = 0; y < HW; y++)
        for (x = 0; x < HW; x++)
            for (k = 0; k < 4; k++)
                px[(y * HW + x) * 4 + k] =
                    -1.5f + 4.5f * (float)((x * 3 + y * 5 + k * 7) % 11) / 10.0f +
                    0.0137f * (float)(x * y);
    glGenTextures(1, &hdr_tex);
    glBindTexture(GL_TEXTURE_2D, hdr_tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, HW, HW, 0, GL_RGBA, GL_FLOAT, px);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

static void tex_quad(float x0, float y0, float x1, float y1)
{
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, 0.0f);
    glVertex2f(x0, y0);
    glTexCoord2f(1.0f, 0.0f);
    glVertex2f(x1, y0);
    glTexCoord2f(1.0f, 1.0f);
    glVertex2f(x1, y1);
    glTexCoord2f(0.0f, 1.0f);
    glVertex2f(x0, y1);
    glEnd();
}

static void color_quad(float x0, float y0, float x1, float y1, const float *c0,
                       const float *c1)
{
    glBegin(GL_QUADS);
    glColor4fv(c0);
    glVertex2f(x0, y0);
    glColor4fv(c1);
    glVertex2f(x1, y0);
    glColor4fv(c0);
    glVertex2f(x1, y1);
    glColor4fv(c1);
    glVertex2f(x0, y1);
    glEnd();
}

/* Pass 1: draw into the bound target (TW x TH). llvmpipe blends a target of one channel
 * (R, A, L or I) with `rgb_alpha_same` forced true (lp_bld_blend_aos.c), so
 * complementary factors become a lerp, dst + f·(src − dst): softgl models that for float
 * targets; for a 16-bit unorm one (`unorm_single`, R16) the fixed-point lerp is not
 * modelled and the over blend is left out. */
static void draw_target(int unorm_single)
{
    static const float a[4] = {0.9f, 0.3f, 0.1f, 0.6f}, b[4] = {0.2f, 0.8f, 0.7f, 0.3f};
    static const float c[4] = {0.7f, 0.6f, 0.9f, 0.9f}, d[4] = {0.1f, 0.2f, 0.3f, 0.4f};
    glViewport(0, 0, TW, TH);
    glClearColor(2.5f, -0.5f, 0.3f, 1.7f);
    glClear(GL_COLOR_BUFFER_BIT);
    /* the HDR source, unclamped into float targets */
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, hdr_tex);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    tex_quad(-0.9f, -0.9f, 0.5f, 0.7f);
    glDisable(GL_TEXTURE_2D);
    /* additive: above 1 */
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    color_quad(-0.2f, -0.6f, 0.9f, 0.4f, c, a);
    /* subtract: below 0 */
    glBlendEquation(GL_FUNC_SUBTRACT);
    color_quad(0.3f, 0.1f, 1.0f, 1.0f, b, d);
    /* over, with alpha */
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    if (!unorm_single)
        color_quad(-1.0f, 0.2f, 0.1f, 1.0f, d, c);
    /* additive again, over the lower edge */
    glBlendFunc(GL_ONE, GL_ONE);
    color_quad(-0.6f, -1.0f, 0.0f, -0.3f, a, d);
    glDisable(GL_BLEND);
    /* a scissored clear */
    glEnable(GL_SCISSOR_TEST);
    glScissor(1, 1, 3, 2);
    glClearColor(-0.75f, 1.25f, 4.0f, -2.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
}

static void run(FILE *out, const struct fmt *f, GLuint hdr_fb, GLuint hdr_dst, int slot)
{
    GLuint tex, fb;
    GLint q[7], bits[4];
    GLenum st;
    static float rf[TW * TH * 4], gt[TW * TH * 4];
    static unsigned char ru[TW * TH * 4];
    static const GLenum qn[7] = {
        GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE,   GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE,
        GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE,  GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE,
        GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE,
        GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING};
    char label[64];
    int k;
    float x0, y0;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, f->internal, TW, TH, 0, GL_RGBA, GL_FLOAT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
    st = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    for (k = 0; k < 7; k++) {
        q[k] = -1;
        glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, qn[k],
                                              &q[k]);
    }
    glGetIntegerv(GL_RED_BITS, &bits[0]);
    glGetIntegerv(GL_GREEN_BITS, &bits[1]);
    glGetIntegerv(GL_BLUE_BITS, &bits[2]);
    glGetIntegerv(GL_ALPHA_BITS, &bits[3]);
    sgl_text(out, "info",
             "%s status=0x%x sizes=%d,%d,%d,%d,%d type=0x%x enc=0x%x bits=%d,%d,%d,%d "
             "err=0x%x\n",
             f->name, st, q[0], q[1], q[2], q[3], q[4], q[5], q[6], bits[0], bits[1], bits[2],
             bits[3], glGetError());
    if (st != GL_FRAMEBUFFER_COMPLETE)
        goto done;
    draw_target(f->unorm_single);
    glReadPixels(0, 0, TW, TH, GL_RGBA, GL_FLOAT, rf);
    snprintf(label, sizeof label, "%s_float", f->name);
    sgl_data(out, label, sizeof rf, rf);
    glReadPixels(0, 0, TW, TH, GL_RGBA, GL_UNSIGNED_BYTE, ru);
    snprintf(label, sizeof label, "%s_ubyte", f->name);
    sgl_data(out, label, sizeof ru, ru);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindTexture(GL_TEXTURE_2D, tex);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, gt);
    snprintf(label, sizeof label, "%s_teximage", f->name);
    sgl_data(out, label, sizeof gt, gt);
    /* HDR round trip: sample the rendered texture into an RGBA32F target */
    glBindFramebuffer(GL_FRAMEBUFFER, hdr_fb);
    glViewport(0, 0, TW, TH);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    tex_quad(-1.0f, -1.0f, 1.0f, 1.0f);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor4f(0.5f, 0.25f, 1.0f, 0.75f);
    tex_quad(-0.5f, -0.5f, 1.0f, 1.0f);
    glDisable(GL_BLEND);
    glDisable(GL_TEXTURE_2D);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindTexture(GL_TEXTURE_2D, hdr_dst);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, gt);
    snprintf(label, sizeof label, "%s_hdr", f->name);
    sgl_data(out, label, sizeof gt, gt);
    /* onto the window: REPLACE (left) and MODULATE (right), clamped to 8 bits */
    glViewport(0, 0, W, H);
    glBindTexture(GL_TEXTURE_2D, tex);
    glEnable(GL_TEXTURE_2D);
    x0 = -1.0f + 0.4f * (float)(slot % 5);
    y0 = -1.0f + 0.5f * (float)(slot / 5);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    tex_quad(x0, y0, x0 + 0.2f, y0 + 0.45f);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor4f(0.6f, 0.9f, 0.3f, 1.0f);
    tex_quad(x0 + 0.2f, y0, x0 + 0.4f, y0 + 0.45f);
    glDisable(GL_TEXTURE_2D);
done:
    sgl_text(out, "err", "%s err=0x%x\n", f->name, glGetError());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fb);
    glDeleteTextures(1, &tex);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    GLuint hdr_fb, hdr_dst;
    int i;
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    make_hdr();
    glGenTextures(1, &hdr_dst);
    glBindTexture(GL_TEXTURE_2D, hdr_dst);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, TW, TH, 0, GL_RGBA, GL_FLOAT, NULL);
    glGenFramebuffers(1, &hdr_fb);
    glBindFramebuffer(GL_FRAMEBUFFER, hdr_fb);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, hdr_dst, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    for (i = 0; i < NF; i++)
        run(out, &formats[i], hdr_fb, hdr_dst, i);
    glFinish(); /* the window's pixels reach `buf` at glFinish (OSMesa copies them) */
    sgl_image(out, "window", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "final", "err=0x%x\n", glGetError());
    sgl_close(out);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
