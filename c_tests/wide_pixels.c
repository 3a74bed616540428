/* wide_pixels: the pixel paths of colour buffers wider than 8 bits, compared at full
 * precision (glReadPixels as GL_FLOAT and GL_UNSIGNED_SHORT, glGetTexImage as GL_FLOAT,
 * the raw OSMesa buffer). In OSMesa GL_FLOAT and GL_UNSIGNED_SHORT windows and in
 * GL_RGBA16, GL_RGBA16F and GL_RGBA32F renderbuffers: glClear with a clear colour
 * outside [0, 1] (whole buffer and scissored) and GL_COLOR_CLEAR_VALUE;
 * glBlitFramebuffer between wide buffers and to and from 8-bit ones (unscaled, mirrored,
 * scaled GL_NEAREST), the 4x multisample resolve of RGBA16F/RGBA32F/RGBA16
 * renderbuffers; glCopyTexImage2D/glCopyTexSubImage2D from wide buffers into float
 * textures; glDrawPixels, glCopyPixels and glBitmap into wide buffers; glAccum's LOAD,
 * ACCUM and RETURN on wide windows; GL_RED_BITS and the other sizes of wide buffers
 * (docs/llvmpipe-rules.md §23). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 24
#define H 16

static FILE *out;

/* A smooth quad whose colours reach above 1 and below 0 (float buffers keep them). */
static void smooth(float x0, float y0, float x1, float y1)
{
    glBegin(GL_QUADS);
    glColor4f(0.9f, 0.3f, 0.1f, 0.6f);
    glVertex2f(x0, y0);
    glColor4f(0.2f, 0.8f, 0.7f, 0.3f);
    glVertex2f(x1, y0);
    glColor4f(0.7f, 0.6f, 0.9f, 0.9f);
    glVertex2f(x1, y1);
    glColor4f(0.1f, 0.2f, 0.3f, 0.4f);
    glVertex2f(x0, y1);
    glEnd();
    /* additive: sums above 1 in float buffers */
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glBegin(GL_TRIANGLES);
    glColor4f(0.7f, 0.55f, 0.35f, 0.45f);
    glVertex2f(x0, y0);
    glVertex2f(x1, y0);
    glVertex2f(x0, y1);
    glEnd();
    glDisable(GL_BLEND);
}

static void setup_2d(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* Reads the current read buffer back as GL_FLOAT and GL_UNSIGNED_SHORT. */
static void dump(const char *name, int w, int h)
{
    static float f[64 * 64 * 4];
    static unsigned short s[64 * 64 * 4];
    char label[96];
    memset(f, 0, sizeof f);
    memset(s, 0, sizeof s);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_FLOAT, f);
    snprintf(label, sizeof label, "%s_f", name);
    sgl_data(out, label, (size_t)w * h * 16, f);
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_SHORT, s);
    snprintf(label, sizeof label, "%s_us", name);
    sgl_data(out, label, (size_t)w * h * 8, s);
    sgl_text(out, "err", "%s err=0x%x\n", name, glGetError());
    /* GL_PACK_SWAP_BYTES */
    glPixelStorei(GL_PACK_SWAP_BYTES, 1);
    glReadPixels(1, 1, 5, 3, GL_RGBA, GL_FLOAT, f);
    snprintf(label, sizeof label, "%s_swap_f", name);
    sgl_data(out, label, 5 * 3 * 16, f);
    glReadPixels(1, 1, 5, 3, GL_BGR, GL_UNSIGNED_SHORT, s);
    snprintf(label, sizeof label, "%s_swap_us", name);
    sgl_data(out, label, 5 * 3 * 6, s);
    glPixelStorei(GL_PACK_SWAP_BYTES, 0);
}

static void queries(const char *name)
{
    GLint b[4];
    GLfloat cc[4];
    glGetIntegerv(GL_RED_BITS, &b[0]);
    glGetIntegerv(GL_GREEN_BITS, &b[1]);
    glGetIntegerv(GL_BLUE_BITS, &b[2]);
    glGetIntegerv(GL_ALPHA_BITS, &b[3]);
    glGetFloatv(GL_COLOR_CLEAR_VALUE, cc);
    sgl_text(out, "q", "%s bits=%d,%d,%d,%d clear=%g,%g,%g,%g err=0x%x\n", name, b[0], b[1],
             b[2], b[3], cc[0], cc[1], cc[2], cc[3], glGetError());
}

/* The clears: whole buffer, then scissored, with colours outside [0, 1]. */
static void clears(const char *name, int w, int h)
{
    char label[96];
    glDisable(GL_SCISSOR_TEST);
    glClearColor(1.5f, -0.25f, 0.3f, 2.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    queries(name);
    snprintf(label, sizeof label, "%s_clear", name);
    dump(label, w, h);
    glEnable(GL_SCISSOR_TEST);
    glScissor(3, 2, w / 2, h / 2);
    glClearColor(-0.5f, 0.123456f, 3.25f, 0.7f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    snprintf(label, sizeof label, "%s_clear_scissor", name);
    dump(label, w, h);
}

/* glCopyTexImage2D / glCopyTexSubImage2D of the read buffer into textures of `fmt`. */
static void copy_tex(const char *name, GLenum fmt, int w, int h)
{
    static float f[64 * 64 * 4];
    char label[96];
    GLuint t;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, fmt, 1, 2, 16, 8, 0);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 4, 3, 5, 4, 6, 4);
    memset(f, 0, sizeof f);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_FLOAT, f);
    snprintf(label, sizeof label, "%s_copytex_%x", name, fmt);
    sgl_data(out, label, 16 * 8 * 16, f);
    sgl_text(out, "err", "%s copytex err=0x%x\n", label, glGetError());
    glDeleteTextures(1, &t);
    (void)w;
    (void)h;
}

/* glDrawPixels (GL_FLOAT data beyond [0, 1], GL_UNSIGNED_SHORT data), glCopyPixels (the
 * blit path, and the quad path under blending) and glBitmap. */
static void pixel_rects(const char *name, int w, int h)
{
    static float img[6 * 5 * 4];
    static unsigned short us[5 * 4 * 4];
    static const GLubyte bits[8] = {0xA5, 0x5A, 0xFF, 0x81, 0x3C, 0x66, 0x99, 0xE7};
    char label[96];
    int i;
    for (i = 0; i < 6 * 5 * 4; i++)
        img[i] = -0.3f + 0.0173f * (float)(i * 7 % 97);
    for (i = 0; i < 5 * 4 * 4; i++)
        us[i] = (unsigned short)(i * 3203 + 17);
    glRasterPos2i(-1, -1);
    glBitmap(0, 0, 0, 0, 2, 1, NULL);
    glDrawPixels(6, 5, GL_RGBA, GL_FLOAT, img);
    glRasterPos2f(0.1f, 0.2f);
    glDrawPixels(5, 4, GL_RGBA, GL_UNSIGNED_SHORT, us);
    snprintf(label, sizeof label, "%s_drawpixels", name);
    dump(label, w, h);
    /* the blit path */
    glRasterPos2f(0.5f, -0.9f);
    glCopyPixels(1, 1, 6, 5, GL_COLOR);
    /* the quad path */
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glRasterPos2f(-0.9f, 0.5f);
    glCopyPixels(2, 3, 5, 4, GL_COLOR);
    glDisable(GL_BLEND);
    snprintf(label, sizeof label, "%s_copypixels", name);
    dump(label, w, h);
    glColor4f(0.3141f, 0.2718f, 0.7071f, 0.1234f);
    glRasterPos2f(-0.5f, -0.5f);
    glBitmap(8, 8, 0, 0, 9, 0, bits);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE);
    glBitmap(8, 8, 0, 0, 9, 0, bits);
    glDisable(GL_BLEND);
    glFinish();
    snprintf(label, sizeof label, "%s_bitmap", name);
    dump(label, w, h);
}

/* glAccum LOAD, ACCUM and RETURN (scaled above 1 and masked). */
static void accum(const char *name, int w, int h)
{
    char label[96];
    glClearAccum(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_ACCUM_BUFFER_BIT);
    glAccum(GL_LOAD, 0.5f);
    glAccum(GL_ACCUM, 0.25f);
    glAccum(GL_RETURN, 1.7f);
    snprintf(label, sizeof label, "%s_accum", name);
    dump(label, w, h);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glAccum(GL_RETURN, 0.3f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    snprintf(label, sizeof label, "%s_accum_masked", name);
    dump(label, w, h);
}

static void window(const char *name, GLenum type, int bytes)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 16, NULL);
    void *buf = calloc(W * H * 4, bytes);
    char label[96];
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, type, W, H));
    setup_2d(W, H);
    clears(name, W, H);
    glFinish();
    snprintf(label, sizeof label, "%s_buffer_clear", name);
    sgl_data(out, label, (size_t)W * H * 4 * bytes, buf);
    smooth(-0.9f, -0.8f, 0.7f, 0.9f);
    snprintf(label, sizeof label, "%s_drawn", name);
    dump(label, W, H);
    copy_tex(name, GL_RGBA32F, W, H);
    copy_tex(name, GL_RGBA16F, W, H);
    copy_tex(name, GL_RGB16F, W, H);
    pixel_rects(name, W, H);
    accum(name, W, H);
    glFinish();
    snprintf(label, sizeof label, "%s_buffer_end", name);
    sgl_data(out, label, (size_t)W * H * 4 * bytes, buf);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buf);
}

/* A framebuffer object with one colour renderbuffer of `fmt` (`samples` > 0: multisample). */
static GLuint make_fbo(GLenum fmt, int samples, int w, int h, GLuint *rb)
{
    GLuint fb;
    glGenFramebuffers(1, &fb);
    glGenRenderbuffers(1, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, *rb);
    if (samples)
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, fmt, w, h);
    else
        glRenderbufferStorage(GL_RENDERBUFFER, fmt, w, h);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, *rb);
    return fb;
}

static void free_fbo(GLuint fb, GLuint rb)
{
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fb);
    glDeleteRenderbuffers(1, &rb);
}

static const GLenum fmts[] = {GL_RGBA16, GL_RGBA16F, GL_RGBA32F, GL_RGBA8};
static const char *fnames[] = {"rgba16", "rgba16f", "rgba32f", "rgba8"};

static void objects(void)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    unsigned char *buf = calloc(W * H, 4);
    char label[96];
    int i, j;
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    for (i = 0; i < 3; i++) {
        GLuint rb, fb = make_fbo(fmts[i], 0, W, H, &rb);
        setup_2d(W, H);
        clears(fnames[i], W, H);
        smooth(-0.9f, -0.8f, 0.7f, 0.9f);
        snprintf(label, sizeof label, "%s_drawn", fnames[i]);
        dump(label, W, H);
        copy_tex(fnames[i], GL_RGBA32F, W, H);
        copy_tex(fnames[i], GL_RGBA16F, W, H);
        copy_tex(fnames[i], GL_RGB16F, W, H);
        pixel_rects(fnames[i], W, H);
        /* blits into every format: unscaled, mirrored, scaled nearest */
        for (j = 0; j < 4; j++) {
            GLuint rb2, fb2 = make_fbo(fmts[j], 0, W, H, &rb2);
            glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            glBindFramebuffer(GL_READ_FRAMEBUFFER, fb);
            glBlitFramebuffer(0, 0, 10, 8, 1, 1, 11, 9, GL_COLOR_BUFFER_BIT, GL_NEAREST);
            glBlitFramebuffer(0, 0, 10, 8, 22, 15, 12, 7, GL_COLOR_BUFFER_BIT, GL_NEAREST);
            glBlitFramebuffer(2, 3, 9, 8, 0, 9, 11, 16, GL_COLOR_BUFFER_BIT, GL_NEAREST);
            glBindFramebuffer(GL_READ_FRAMEBUFFER, fb2);
            snprintf(label, sizeof label, "%s_blit_to_%s", fnames[i], fnames[j]);
            dump(label, W, H);
            free_fbo(fb2, rb2);
            glBindFramebuffer(GL_FRAMEBUFFER, fb);
        }
        /* and the other way: from an 8-bit object into this one */
        {
            GLuint rb2, fb2 = make_fbo(GL_RGBA8, 0, W, H, &rb2);
            setup_2d(W, H);
            smooth(-0.9f, -0.8f, 0.7f, 0.9f);
            glBindFramebuffer(GL_READ_FRAMEBUFFER, fb2);
            glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb);
            glBlitFramebuffer(0, 0, 12, 10, 5, 4, 17, 14, GL_COLOR_BUFFER_BIT, GL_NEAREST);
            glBindFramebuffer(GL_READ_FRAMEBUFFER, fb);
            snprintf(label, sizeof label, "%s_blit_from_rgba8", fnames[i]);
            dump(label, W, H);
            free_fbo(fb2, rb2);
        }
        /* into the window */
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fb);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        glFinish();
        snprintf(label, sizeof label, "%s_blit_to_window", fnames[i]);
        sgl_data(out, label, W * H * 4, buf);
        free_fbo(fb, rb);
    }
    /* 4x multisample resolves */
    for (i = 0; i < 3; i++) {
        GLuint rbm, fbm = make_fbo(fmts[i], 4, W, H, &rbm);
        GLuint rb2, fb2;
        setup_2d(W, H);
        glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
        glClear(GL_COLOR_BUFFER_BIT);
        glEnable(GL_MULTISAMPLE);
        glBegin(GL_TRIANGLES);
        glColor4f(1.7f, 0.33f, 0.71f, 0.9f);
        glVertex2f(-0.9f, -0.85f);
        glColor4f(0.13f, 0.97f, 0.4f, 0.2f);
        glVertex2f(0.8f, -0.3f);
        glColor4f(0.45f, 0.25f, 1.0f, 0.6f);
        glVertex2f(-0.2f, 0.9f);
        glEnd();
        for (j = 0; j < 4; j++) {
            if (j != i && j != 3)
                continue;
            fb2 = make_fbo(fmts[j], 0, W, H, &rb2);
            glBindFramebuffer(GL_READ_FRAMEBUFFER, fbm);
            glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
            glBindFramebuffer(GL_READ_FRAMEBUFFER, fb2);
            snprintf(label, sizeof label, "%s_resolve_to_%s", fnames[i], fnames[j]);
            dump(label, W, H);
            free_fbo(fb2, rb2);
            glBindFramebuffer(GL_FRAMEBUFFER, fbm);
        }
        free_fbo(fbm, rbm);
    }
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buf);
}

int main(int argc, char **argv)
{
    out = sgl_open(argc, argv);
    window("win_float", GL_FLOAT, 4);
    window("win_ushort", GL_UNSIGNED_SHORT, 2);
    objects();
    sgl_close(out);
    return 0;
}
