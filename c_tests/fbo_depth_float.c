/* fbo_depth_float: GL_ARB_depth_buffer_float (GL_DEPTH_COMPONENT32F, GL_DEPTH32F_STENCIL8),
 * as MuJoCo uses it.
 * - Renderbuffers of both formats (single and 4x): sizes, attachment component types,
 *   completeness.
 * - Drawing into a DEPTH32F_STENCIL8 object: a perspective scene with far-away,
 *   nearly coplanar planes (where float and 24-bit depth decide differently), stencil,
 *   depth functions, and reversed z (glClipControl GL_ZERO_TO_ONE, GL_GREATER, clear 0)
 *   as MuJoCo draws; full and scissored depth clears; colour and depth read back
 *   (GL_FLOAT, GL_UNSIGNED_INT, GL_UNSIGNED_SHORT), GL_DEPTH_STENCIL with
 *   GL_FLOAT_32_UNSIGNED_INT_24_8_REV and GL_UNSIGNED_INT_24_8, and GL_DEPTH_SCALE.
 * - Depth blits between float objects (unscaled and scaled NEAREST) and a 4x resolve.
 * - Float depth textures: upload from GL_FLOAT (values outside [0, 1] clamped), unsigned
 *   types and packed depth-stencil data; glGetTexImage; a texture as the depth
 *   attachment, then sampled with and without GL_TEXTURE_COMPARE_MODE (the reference is
 *   not clamped for float textures); glCopyTexImage2D from a float depth buffer.
 * - Polygon offset in a float buffer (units scaled by each triangle's largest z
 *   exponent; colour compared, see the offset block).
 * - Errors of the new format/type combinations. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 64
#define H 48
#include "fbo_depth_common.h"

static unsigned char px[W * H * 4];
static PFNGLCLIPCONTROLPROC clip_control;
static int no_fan; /* the fan's near vertex makes huge offset slopes (see the README) */
static float zf[W * H * 2];
static unsigned int zu[W * H * 2];

/* Two far planes meeting at a tiny angle, a near plane crossing them, a fan. */
static void scene(float t)
{
    int i;
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.1, 0.1, -0.075, 0.075, 0.1, 5000.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glBegin(GL_QUADS);
    glColor3f(1.0f, 0.2f, 0.1f);
    glVertex3f(-900.0f, -700.0f, -1500.0f);
    glVertex3f(900.0f, -700.0f, -1500.0f);
    glVertex3f(900.0f, 700.0f, -1500.0f);
    glVertex3f(-900.0f, 700.0f, -1500.0f);
    glColor3f(0.1f, 0.3f, 1.0f);
    glVertex3f(-900.0f, -700.0f, -1500.5f - t);
    glVertex3f(900.0f, -700.0f, -1499.5f + t);
    glVertex3f(900.0f, 700.0f, -1499.7f);
    glVertex3f(-900.0f, 700.0f, -1500.3f);
    glEnd();
    if (no_fan)
        return;
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 12; i++) {
        float a = 0.52f * (float)i;
        glColor3f(0.2f + 0.06f * (float)i, 0.9f, 0.3f);
        glVertex3f(0.0f, 0.0f, -0.5f);
        glColor3f(0.9f, 0.9f, 0.1f * (float)i);
        glVertex3f(40.0f * __builtin_cosf(a), 30.0f * __builtin_sinf(a), -200.0f);
        glVertex3f(40.0f * __builtin_cosf(a + 0.4f), 30.0f * __builtin_sinf(a + 0.4f),
                   -3000.0f);
    }
    glEnd();
}

static void dump(FILE *out, const char *name, int stencil)
{
    char n[64];
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    snprintf(n, sizeof n, "%s_rgba", name);
    sgl_image(out, n, W, H, 4, "RGBA", W * 4, 1, px);
    if (stencil < 0) /* colour only */
        return;
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
    snprintf(n, sizeof n, "%s_zf", name);
    sgl_data(out, n, W * H * 4, zf);
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, zu);
    snprintf(n, sizeof n, "%s_zu", name);
    sgl_data(out, n, W * H * 4, zu);
    if (stencil) {
        memset(zu, 0xab, sizeof zu);
        glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, zu);
        snprintf(n, sizeof n, "%s_dsf", name);
        sgl_data(out, n, W * H * 8, zu);
        glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, zu);
        snprintf(n, sizeof n, "%s_ds24", name);
        sgl_data(out, n, W * H * 4, zu);
    }
    snprintf(n, sizeof n, "%s_err", name);
    errs(out, n);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    GLuint fb[6], col, ds, dz, msc, msds, tex[4];
    GLint v[8];
    int i;
    const GLenum fmts[2] = {GL_DEPTH_COMPONENT32F, GL_DEPTH32F_STENCIL8};

    SGL_CHECK(ctx && OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    SGL_CHECK(strstr((const char *)glGetString(GL_EXTENSIONS), "GL_ARB_depth_buffer_float"));
    glGenFramebuffers(6, fb);
    /* Mesa's libOSMesa does not export glClipControl: fetched as MuJoCo does */
    clip_control = (PFNGLCLIPCONTROLPROC)OSMesaGetProcAddress("glClipControl");
    SGL_CHECK(clip_control != NULL);

    /* renderbuffer queries */
    for (i = 0; i < 2; i++) {
        GLuint rb = rbuf(fmts[i], i * 4);
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_DEPTH_SIZE, &v[0]);
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_STENCIL_SIZE, &v[1]);
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &v[2]);
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &v[3]);
        sgl_text(out, "rb_query", "%x: depth %d stencil %d fmt 0x%x samples %d", fmts[i],
                 v[0], v[1], v[2], v[3]);
        glDeleteRenderbuffers(1, &rb);
    }
    errs(out, "rb_query_err");

    /* a DEPTH32F_STENCIL8 object */
    col = rbuf(GL_RGBA8, 0);
    ds = rbuf(GL_DEPTH32F_STENCIL8, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, col);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, ds);
    sgl_text(out, "status0", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                          GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &v[0]);
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT,
                                          GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &v[1]);
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                          GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &v[2]);
    glGetIntegerv(GL_DEPTH_BITS, &v[3]);
    glGetIntegerv(GL_STENCIL_BITS, &v[4]);
    sgl_text(out, "attach0", "type 0x%x 0x%x size %d bits %d %d", v[0], v[1], v[2], v[3],
             v[4]);
    errs(out, "attach0_err");

    glViewport(0, 0, W, H);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClearDepth(1.0);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOp(GL_KEEP, GL_INCR, GL_INCR);
    scene(0.0f);
    dump(out, "less", 1);

    /* LEQUAL / GREATER over what is there, depth mask off for a part */
    glDepthFunc(GL_LEQUAL);
    scene(0.3f);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
    scene(0.7f);
    glDepthMask(GL_TRUE);
    dump(out, "funcs", 1);

    /* polygon offset: units scaled by each triangle's largest z exponent */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glDepthFunc(GL_LESS);
    scene(0.0f);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glEnable(GL_POLYGON_OFFSET_LINE);
    glPolygonOffset(0.0f, -1.0f);
    glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_TRUE);
    scene(0.0f);
    glPolygonOffset(1.5f, -3.0f);
    glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
    scene(0.05f);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glPolygonOffset(-1.0f, -2.0f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    no_fan = 1;
    scene(0.0f);
    no_fan = 0;
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDisable(GL_POLYGON_OFFSET_LINE);
    /* colour only: softgl adds llvmpipe's per-fragment offset to the z plane's origin
     * instead, which can differ by one ulp in a float buffer (docs/fbo-rules.md §7.4) */
    dump(out, "offset", -1);

    /* reversed z: MuJoCo's GL_ZERO_TO_ONE, GL_GREATER, clear depth 0 */
    clip_control(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glClearDepth(0.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glDepthFunc(GL_GREATER);
    {
        /* a reversed infinite-far projection: z_clip = near, w = -z_eye */
        const float n = 0.1f;
        float m[16] = {1.5f, 0, 0, 0, 0, 2.0f, 0, 0, 0, 0, 0, -1.0f, 0, 0, n, 0};
        int k;
        glMatrixMode(GL_PROJECTION);
        glLoadMatrixf(m);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        for (k = 0; k < 3; k++) {
            float z = -1500.0f - 0.01f * (float)k;
            glBegin(GL_TRIANGLES);
            glColor3f(0.3f * (float)k, 1.0f - 0.3f * (float)k, 0.5f);
            glVertex3f(-900.0f + 50.0f * (float)k, -700.0f, z - 0.2f);
            glVertex3f(900.0f, -650.0f + 20.0f * (float)k, z + 0.2f);
            glVertex3f(0.0f, 800.0f, z);
            glEnd();
        }
        glBegin(GL_TRIANGLES);
        glColor3f(1, 1, 1);
        glVertex3f(-0.05f, -0.05f, -0.2f);
        glVertex3f(0.05f, -0.04f, -0.2f);
        glVertex3f(0.0f, 0.06f, -3000.0f);
        glEnd();
    }
    dump(out, "reversed", 1);
    clip_control(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glDepthFunc(GL_LESS);

    /* clears: full, then scissored, then with GL_DEPTH_SCALE on the read */
    glClearDepth(0.3);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(5, 7, 20, 11);
    glClearDepth(0.123456789);
    glClearStencil(0x5a);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    dump(out, "clears", 1);
    glPixelTransferf(GL_DEPTH_SCALE, 2.0f);
    glPixelTransferf(GL_DEPTH_BIAS, -0.1f);
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
    sgl_data(out, "scaled_zf", W * H * 4, zf);
    glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, zu);
    sgl_data(out, "scaled_dsf", W * H * 8, zu);
    glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.0f);
    glReadPixels(3, 2, 9, 7, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, zu);
    sgl_data(out, "clears_us", 9 * 7 * 2, zu);
    errs(out, "clears_err");

    /* redraw, then blit depth into a DEPTH_COMPONENT32F object (unscaled, scaled) */
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDisable(GL_STENCIL_TEST);
    scene(0.1f);
    dz = rbuf(GL_DEPTH_COMPONENT32F, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                              rbuf(GL_RGBA8, 0));
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, dz);
    sgl_text(out, "status1", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    glClearDepth(0.5);
    glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
    glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[1]);
    dump(out, "blit1", 0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
    glBlitFramebuffer(3, 4, 40, 30, 60, 45, 1, 2, GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[1]);
    dump(out, "blit2", 0);
    /* depth blit float -> 24-bit: the depth formats differ */
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[2]);
    glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                              rbuf(GL_RGBA8, 0));
    glFramebufferRenderbuffer(GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              rbuf(GL_DEPTH24_STENCIL8, 0));
    glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    errs(out, "blit_f_to_24");
    /* float without stencil <- float with stencil: same depth format */
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[1]);
    glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
                      GL_NEAREST);
    errs(out, "blit_ds_to_d");

    /* 4x float depth-stencil, drawn, resolved */
    msc = rbuf(GL_RGBA8, 4);
    msds = rbuf(GL_DEPTH32F_STENCIL8, 4);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[3]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, msc);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              msds);
    sgl_text(out, "status3", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glDepthFunc(GL_LESS);
    scene(0.2f);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[3]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[0]);
    glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_image(out, "msaa_rgba", W, H, 4, "RGBA", W * 4, 1, px);
    errs(out, "msaa_err");

    /* float depth textures: uploads and readback */
    glGenTextures(4, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    for (i = 0; i < 16; i++)
        zf[i] = -0.5f + 0.1234567f * (float)i;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, 4, 4, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                 zf);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, zf + 16);
    sgl_data(out, "tex_f", 16 * 4, zf + 16);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &v[0]);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE, &v[1]);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &v[2]);
    sgl_text(out, "tex_f_q", "%d %d 0x%x", v[0], v[1], v[2]);
    for (i = 0; i < 16; i++)
        zu[i] = 0x10000000u * (unsigned)i + 0x0123457u * (unsigned)i;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, 4, 4, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT, zu);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
    sgl_data(out, "tex_u", 16 * 4, zf);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, zu + 16);
    sgl_data(out, "tex_u_u", 16 * 4, zu + 16);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, 4, 4, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_SHORT, zu);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
    sgl_data(out, "tex_us", 16 * 4, zf);
    errs(out, "tex_err");

    glBindTexture(GL_TEXTURE_2D, tex[1]);
    for (i = 0; i < 16; i++) {
        zf[2 * i] = -0.25f + 0.1f * (float)i;
        zu[2 * i + 1] = 0x1200u + 17u * (unsigned)i;
        memcpy(&zu[2 * i], &zf[2 * i], 4);
    }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH32F_STENCIL8, 4, 4, 0, GL_DEPTH_STENCIL,
                 GL_FLOAT_32_UNSIGNED_INT_24_8_REV, zu);
    memset(zf, 0, 32 * 4);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, zf);
    sgl_data(out, "tex_ds_f", 16 * 8, zf);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, zf);
    sgl_data(out, "tex_ds_24", 16 * 4, zf);
    for (i = 0; i < 16; i++)
        zu[i] = (0x0f0f0fu * (unsigned)i) << 8 | (unsigned)(i * 13);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH32F_STENCIL8, 4, 4, 0, GL_DEPTH_STENCIL,
                 GL_UNSIGNED_INT_24_8, zu);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, zf);
    sgl_data(out, "tex_ds_from24", 16 * 8, zf);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &v[0]);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE, &v[1]);
    sgl_text(out, "tex_ds_q", "%d %d", v[0], v[1]);
    /* a DEPTH24_STENCIL8 texture from float depth-stencil data */
    glBindTexture(GL_TEXTURE_2D, tex[2]);
    for (i = 0; i < 16; i++) {
        float f = 0.0625f * (float)i + 0.01f;
        memcpy(&zu[2 * i], &f, 4);
        zu[2 * i + 1] = (unsigned)i;
    }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 4, 4, 0, GL_DEPTH_STENCIL,
                 GL_FLOAT_32_UNSIGNED_INT_24_8_REV, zu);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, zf);
    sgl_data(out, "tex24_from_f", 16 * 4, zf);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, zf);
    sgl_data(out, "tex24_as_f", 16 * 8, zf);
    errs(out, "tex_ds_err");

    /* a DEPTH_COMPONENT32F texture as the depth attachment */
    glBindTexture(GL_TEXTURE_2D, tex[3]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, W, H, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                 NULL);
    depth_tex_fbo(out, "status4", fb[4], tex[3]);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    scene(0.4f);
    dump(out, "texfbo", 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
    sgl_data(out, "texfbo_get", W * H * 4, zf);

    /* sample it: depth as luminance, then compared (r from 0.9 to 1.1: not clamped) */
    sample_depth_tex(0.9995f, 1.1f, 1.2f, 0);
    glDisable(GL_TEXTURE_2D);
    glFinish();
    sgl_image(out, "sampled", W, H, 4, "RGBA", W * 4, 1, buf);
    errs(out, "sampled_err");

    /* glCopyTexImage2D from the float depth buffer (object 0) into float and 24-bit */
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    copy_depth(out, "copy_f", GL_DEPTH_COMPONENT32F, GL_FLOAT, 16, 12, zf);
    copy_depth(out, "copy_24", GL_DEPTH_COMPONENT24, GL_UNSIGNED_INT, 16, 12, zu);
    errs(out, "copy_err");
    /* from the window's 24-bit depth-stencil buffer into GL_DEPTH32F_STENCIL8 and
     * GL_DEPTH24_STENCIL8 (piglit's copyteximage) */
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    copy_depth(out, "copy_win_f_s8", GL_DEPTH32F_STENCIL8, GL_FLOAT, 16, 12, zf);
    copy_depth(out, "copy_win_24_s8", GL_DEPTH24_STENCIL8, GL_UNSIGNED_INT, 16, 12, zu);
    errs(out, "copy_win_err");
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);

    /* errors */
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, 4, 4, 0, GL_RGBA, GL_FLOAT, zf);
    errs(out, "e_rgba_into_f");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, 4, 4, 0, GL_DEPTH_STENCIL, GL_FLOAT,
                 zf);
    errs(out, "e_ds_float");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32F, 4, 4, 0, GL_DEPTH_COMPONENT,
                 GL_FLOAT_32_UNSIGNED_INT_24_8_REV, zf);
    errs(out, "e_depth_f32_24_8");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 4, 4, 0, GL_RGBA, GL_FLOAT_32_UNSIGNED_INT_24_8_REV,
                 zf);
    errs(out, "e_rgba_f32_24_8");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH32F_STENCIL8, 4, 4, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_BYTE, zf);
    errs(out, "e_ok_ubyte");
    glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
    glReadPixels(0, 0, 2, 2, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, zu);
    errs(out, "e_read_ds_no_stencil");
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    glReadPixels(0, 0, 2, 2, GL_DEPTH_STENCIL, GL_FLOAT, zu);
    errs(out, "e_read_ds_float");
    glReadPixels(0, 0, 2, 2, GL_DEPTH_COMPONENT, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, zu);
    errs(out, "e_read_depth_f32_24_8");
    glReadPixels(0, 0, 2, 2, GL_RGBA, GL_UNSIGNED_INT_24_8, zu);
    errs(out, "e_read_rgba_24_8");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, zu);
    sgl_data(out, "window_ds24", W * H * 4, zu);
    glReadPixels(0, 0, W, H, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, zu);
    sgl_data(out, "window_dsf", W * H * 8, zu);
    errs(out, "window_ds_err");

    OSMesaDestroyContext(ctx);
    free(buf);
    fclose(out);
    return 0;
}
