/* fbo_depth32: GL_DEPTH_COMPONENT32 (llvmpipe's Z32_UNORM) as a renderbuffer and as a
 * depth texture attached to a framebuffer object.
 * - Renderbuffer queries (single and 4x), completeness, GL_DEPTH_BITS, attachment sizes.
 * - Full and scissored clears with depths that need rounding, read back as
 *   GL_UNSIGNED_INT, GL_FLOAT and GL_UNSIGNED_SHORT.
 * - Every depth function over overlapping slanted triangles, nearly coplanar planes
 *   (depths differing in the low bits), z exactly 0 and 1, glDepthRange.
 * - Polygon offset (factor and units; units are 2/(2^32 - 1) each, visible only near 0;
 *   colour compared, see the offset block).
 * - A DEPTH_COMPONENT32 texture as the depth attachment, read back and sampled (plain
 *   and with GL_TEXTURE_COMPARE_MODE).
 * - Depth blits D32 -> D32 (unscaled, scaled, flipped) and the errors against
 *   D24 / D32F / D16; glCopyTexImage2D from a D32 buffer into 32/24/16-bit textures.
 * - 4x D32: colour resolved after a depth-tested scene.
 * - OSMesaCreateContextExt with 32 depth bits. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 64
#define H 48
#include "fbo_depth_common.h"

static unsigned char px[W * H * 4];
static float zf[W * H];
static unsigned int zu[W * H];
static unsigned short zs[W * H];

static void ortho(void)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* A triangle with window depths z0, z1, z2 (glOrtho: z_win = (1 - z_obj) / 2 with the
 * default range, so z_obj = 1 - 2 z_win). */
static void tri(float x0, float y0, float z0, float x1, float y1, float z1, float x2,
                float y2, float z2)
{
    glVertex3f(x0, y0, 1.0f - 2.0f * z0);
    glVertex3f(x1, y1, 1.0f - 2.0f * z1);
    glVertex3f(x2, y2, 1.0f - 2.0f * z2);
}

/* Overlapping slanted triangles, nearly coplanar planes, planes at exactly 0 and 1. */
static void scene(float t)
{
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.2f, 0.1f);
    tri(0, 0, 0.1f, W, 4, 0.9f, 10, H, 0.45f + t);
    glColor3f(0.1f, 0.3f, 1.0f);
    tri(W, H, 0.05f, 2, 6, 0.95f - t, W - 3, 1, 0.5f);
    /* two planes differing in the last bits of z */
    glColor3f(0.2f, 0.9f, 0.2f);
    tri(5, 20, 0.3f, 60, 22, 0.30000001f, 30, 44, 0.3000001f);
    glColor3f(0.9f, 0.9f, 0.2f);
    tri(6, 19, 0.30000003f, 59, 24, 0.30000003f, 28, 45, 0.3000001f);
    /* near 0, where z keeps many more bits than 32-bit unorm's spacing */
    glColor3f(0.5f, 0.1f, 0.7f);
    tri(40, 2, 1e-6f, 62, 10, 3e-6f, 50, 30, 2e-6f);
    glColor3f(0.1f, 0.7f, 0.7f);
    tri(38, 4, 2.5e-6f, 63, 12, 1.5e-6f, 45, 28, 2e-6f);
    glEnd();
    /* z exactly 0 and exactly 1 (NDC -1 and 1) */
    glBegin(GL_QUADS);
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex3f(2, 30, 1.0f);
    glVertex3f(12, 30, 1.0f);
    glVertex3f(12, 40, 1.0f);
    glVertex3f(2, 40, 1.0f);
    glColor3f(0.0f, 0.0f, 0.0f);
    glVertex3f(14, 30, -1.0f);
    glVertex3f(24, 30, -1.0f);
    glVertex3f(24, 40, -1.0f);
    glVertex3f(14, 40, -1.0f);
    glEnd();
}

static void dump(FILE *out, const char *name, int depth)
{
    char n[64];
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    snprintf(n, sizeof n, "%s_rgba", name);
    sgl_image(out, n, W, H, 4, "RGBA", W * 4, 1, px);
    if (depth) {
        glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, zu);
        snprintf(n, sizeof n, "%s_zu", name);
        sgl_data(out, n, sizeof zu, zu);
        glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
        snprintf(n, sizeof n, "%s_zf", name);
        sgl_data(out, n, sizeof zf, zf);
    }
    snprintf(n, sizeof n, "%s_err", name);
    errs(out, n);
}

static GLuint fbo(GLenum depth_fmt, int samples)
{
    GLuint f;
    glGenFramebuffers(1, &f);
    glBindFramebuffer(GL_FRAMEBUFFER, f);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                              rbuf(GL_RGBA8, samples));
    if (depth_fmt)
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                  rbuf(depth_fmt, samples));
    return f;
}

static void clears(FILE *out, const char *name, int scissored)
{
    static const double ds[] = {0.0,         1.0,          0.5,        1.0 / 3.0,
                                0.123456789, 0.7777777777, 1e-10,      0.9999999999,
                                2.5e-10,     0.99999999,   0.30000001, 1.0 - 1.0 / 4294967295.0};
    char n[64];
    int i;
    for (i = 0; i < (int)(sizeof ds / sizeof ds[0]); i++) {
        glClearDepth(scissored ? 0.25 : 0.75);
        glClear(GL_DEPTH_BUFFER_BIT);
        if (scissored) {
            glEnable(GL_SCISSOR_TEST);
            glScissor(2, 3, 5, 4);
        }
        glClearDepth(ds[i]);
        glClear(GL_DEPTH_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        glReadPixels(0, 0, 8, 8, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, zu);
        glReadPixels(0, 0, 8, 8, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
        glReadPixels(0, 0, 8, 8, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, zs);
        snprintf(n, sizeof n, "%s%d", name, i);
        sgl_text(out, n, "u %08x %08x f %.9g %.9g s %04x %04x", zu[0], zu[3 * 8 + 3],
                 (double)zf[0], (double)zf[3 * 8 + 3], zs[0], zs[3 * 8 + 3]);
        snprintf(n, sizeof n, "%s%d_zu", name, i);
        sgl_data(out, n, 64 * 4, zu);
    }
    errs(out, name);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL), ctx32;
    unsigned char *buf = malloc(W * H * 4);
    GLuint fa, fb2, fms, f24, f32f, f16, tex[4];
    GLint v[8];
    int i;
    static const GLenum funcs[8] = {GL_NEVER,   GL_LESS,     GL_EQUAL,  GL_LEQUAL,
                                    GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};

    SGL_CHECK(ctx && OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    /* renderbuffer queries */
    for (i = 0; i < 2; i++) {
        GLuint rb = rbuf(GL_DEPTH_COMPONENT32, i * 4);
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_DEPTH_SIZE, &v[0]);
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_STENCIL_SIZE, &v[1]);
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &v[2]);
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &v[3]);
        sgl_text(out, "rb_query", "depth %d stencil %d fmt 0x%x samples %d", v[0], v[1], v[2],
                 v[3]);
        glDeleteRenderbuffers(1, &rb);
    }
    errs(out, "rb_query_err");

    /* a colour + DEPTH_COMPONENT32 object */
    fa = fbo(GL_DEPTH_COMPONENT32, 0);
    sgl_text(out, "status_a", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                          GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE, &v[0]);
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT,
                                          GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE, &v[1]);
    glGetIntegerv(GL_DEPTH_BITS, &v[2]);
    glGetIntegerv(GL_STENCIL_BITS, &v[3]);
    sgl_text(out, "attach_a", "type 0x%x size %d bits %d %d", v[0], v[1], v[2], v[3]);
    errs(out, "attach_a_err");

    glViewport(0, 0, W, H);
    clears(out, "clear", 0);
    clears(out, "sclear", 1);

    /* every depth function over the scene drawn at LESS */
    ortho();
    glEnable(GL_DEPTH_TEST);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    for (i = 0; i < 8; i++) {
        char n[32];
        glClearDepth(i == 3 ? 1.0 : 0.5);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glDepthFunc(GL_LESS);
        scene(0.0f);
        glDepthFunc(funcs[i]);
        scene(0.001f);
        glBegin(GL_TRIANGLES);
        glColor3f(0.6f, 0.6f, 0.0f);
        tri(0, H, 0.5f, W, H, 0.2f, 30, 0, 0.8f);
        glEnd();
        snprintf(n, sizeof n, "func%d", i);
        dump(out, n, 1);
    }

    /* depth range, reversed range */
    glDepthFunc(GL_LESS);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDepthRange(0.2, 0.7);
    scene(0.0f);
    dump(out, "range", 1);
    glClearDepth(0.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glDepthFunc(GL_GEQUAL);
    glDepthRange(1.0, 0.0);
    scene(0.0f);
    dump(out, "reversed", 1);
    glDepthRange(0.0, 1.0);
    glDepthFunc(GL_LESS);

    /* polygon offset: factor, units (units matter only near z = 0) */
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    scene(0.0f);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(0.0f, -3.0f);
    glColorMask(GL_TRUE, GL_FALSE, GL_FALSE, GL_TRUE);
    scene(0.0f);
    glPolygonOffset(0.0f, 1000.0f);
    glColorMask(GL_FALSE, GL_TRUE, GL_FALSE, GL_TRUE);
    scene(0.0f);
    glPolygonOffset(-1.5f, -7.0f);
    glColorMask(GL_FALSE, GL_FALSE, GL_TRUE, GL_TRUE);
    scene(0.0f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_POLYGON_OFFSET_FILL);
    /* colour only: llvmpipe adds the offset to each fragment's interpolated z, softgl to
     * the z plane's origin, which a 32-bit buffer shows as one ulp of z in some pixels
     * (docs/fbo-rules.md 7.4) */
    dump(out, "offset", 0);

    /* a DEPTH_COMPONENT32 texture as the depth attachment */
    glGenTextures(4, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT32, W, H, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT, NULL);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &v[0]);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &v[1]);
    sgl_text(out, "tex_q", "%d 0x%x", v[0], v[1]);
    glGenFramebuffers(1, &fb2);
    depth_tex_fbo(out, "status_tex", fb2, tex[0]);
    glGetIntegerv(GL_DEPTH_BITS, &v[0]);
    sgl_text(out, "tex_bits", "%d", v[0]);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    scene(0.0f);
    dump(out, "texfbo", 1);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, zu);
    sgl_data(out, "texfbo_get_u", sizeof zu, zu);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
    sgl_data(out, "texfbo_get_f", sizeof zf, zf);

    /* sample it into the window: as luminance, then compared (MuJoCo's shadows) */
    sample_depth_tex(0.0f, 1.0f, 0.30000002f, 1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    glDisable(GL_TEXTURE_2D);
    glFinish();
    sgl_image(out, "sampled", W, H, 4, "RGBA", W * 4, 1, buf);
    errs(out, "sampled_err");

    /* depth blits D32 -> D32 (unscaled; scaled and flipped) */
    glEnable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, fa);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    scene(0.0f);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb2);
    glClearDepth(0.5);
    glClear(GL_DEPTH_BUFFER_BIT);
    glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb2);
    dump(out, "blit1", 1);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fa);
    glBlitFramebuffer(3, 4, 40, 30, 60, 45, 1, 2, GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb2);
    dump(out, "blit2", 1);
    /* D32 against D24, D32F, D16 either way */
    f24 = fbo(GL_DEPTH_COMPONENT24, 0);
    f32f = fbo(GL_DEPTH_COMPONENT32F, 0);
    f16 = fbo(GL_DEPTH_COMPONENT16, 0);
    {
        const GLuint others[3] = {f24, f32f, f16};
        for (i = 0; i < 3; i++) {
            char n[32];
            glBindFramebuffer(GL_READ_FRAMEBUFFER, fa);
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, others[i]);
            glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
            snprintf(n, sizeof n, "blit_to_%d", i);
            errs(out, n);
            glBindFramebuffer(GL_READ_FRAMEBUFFER, others[i]);
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fa);
            glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
            snprintf(n, sizeof n, "blit_from_%d", i);
            errs(out, n);
        }
    }

    /* glCopyTexImage2D from the D32 buffer into 32-, 24- and 16-bit textures */
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fa);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    copy_depth(out, "copy_32", GL_DEPTH_COMPONENT32, GL_UNSIGNED_INT, 40, 30, zu);
    copy_depth(out, "copy_24", GL_DEPTH_COMPONENT24, GL_UNSIGNED_INT, 40, 30, zu);
    copy_depth(out, "copy_16", GL_DEPTH_COMPONENT16, GL_UNSIGNED_INT, 40, 30, zu);
    errs(out, "copy_err");
    /* and from the window's 24-bit buffer into a 32-bit texture */
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glClearDepth(0.3);
    glClear(GL_DEPTH_BUFFER_BIT);
    scene(0.0f);
    copy_depth(out, "copy_win_32", GL_DEPTH_COMPONENT32, GL_UNSIGNED_INT, 40, 30, zu);
    errs(out, "copy_win_err");

    /* 4x D32: depth-tested scene, colour resolved */
    fms = fbo(GL_DEPTH_COMPONENT32, 4);
    sgl_text(out, "status_ms", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    scene(0.0f);
    glDepthFunc(GL_GREATER);
    glBegin(GL_TRIANGLES);
    glColor3f(0.6f, 0.6f, 0.0f);
    tri(0, H, 0.5f, W, H, 0.2f, 30, 0, 0.8f);
    glEnd();
    glDepthFunc(GL_LESS);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fms);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fa);
    glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, fa);
    dump(out, "msaa", 0);

    /* a 32-bit window depth request */
    ctx32 = OSMesaCreateContextExt(OSMESA_RGBA, 32, 0, 0, NULL);
    SGL_CHECK(ctx32 && OSMesaMakeCurrent(ctx32, buf, GL_UNSIGNED_BYTE, W, H));
    glGetIntegerv(GL_DEPTH_BITS, &v[0]);
    sgl_text(out, "ctx32_bits", "%d", v[0]);
    glClearDepth(1.0 / 3.0);
    glClear(GL_DEPTH_BUFFER_BIT);
    glReadPixels(0, 0, 1, 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, zu);
    sgl_text(out, "ctx32_clear", "%08x", zu[0]);
    OSMesaDestroyContext(ctx32);

    OSMesaDestroyContext(ctx);
    free(buf);
    sgl_close(out);
    return 0;
}
