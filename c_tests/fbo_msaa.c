/* fbo_msaa: 4x multisample framebuffer objects, as MuJoCo uses them.
 * - Limits and queries: GL_MAX_SAMPLES, the sample count a request of 0..5 gives
 *   (GL_RENDERBUFFER_SAMPLES), GL_SAMPLE_BUFFERS / GL_SAMPLES with a 4x object bound
 *   and with the window, GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE for mixed counts.
 * - A 4x RGBA8 + DEPTH24_STENCIL8 object: smooth-shaded triangles whose edges sit at
 *   many sub-pixel offsets, intersecting triangles (depth per sample), a textured
 *   triangle, blending, stencil, alpha to coverage, glSampleCoverage, and a part drawn
 *   with GL_MULTISAMPLE off; resolved with glBlitFramebuffer into a single-sample
 *   object (also offset and mirrored) and read back.
 * - Errors: glReadPixels and glCopyTexImage2D from a multisample read buffer, a scaled
 *   resolve, a blit into a multisample object (allowed: every sample gets the value).
 * - glDrawPixels into the 4x object. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 32
#define H 24
#define FW 67
#define FH 53

static unsigned char px[FW * FH * 4];

static void read_resolved(FILE *out, GLuint ms, GLuint ss, const char *name)
{
    glBindFramebuffer(GL_READ_FRAMEBUFFER, ms);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, ss);
    glBlitFramebuffer(0, 0, FW, FH, 0, 0, FW, FH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, ss);
    glReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_image(out, name, FW, FH, 4, "RGBA", FW * 4, 1, px);
    glBindFramebuffer(GL_FRAMEBUFFER, ms);
}

/* A fan of thin triangles around (cx, cy) whose edges cross pixels at many offsets. */
static void fan(float cx, float cy, float r, int n, float a)
{
    int i;
    glBegin(GL_TRIANGLES);
    for (i = 0; i < n; i += 2) {
        float t0 = 6.2831853f * (float)i / (float)n, t1 = 6.2831853f * (float)(i + 1) / (float)n;
        glColor4f(1.0f, 0.2f + 0.6f * (float)i / (float)n, 0.1f, a);
        glVertex2f(cx + 0.013f, cy - 0.007f);
        glColor4f(0.1f, 0.9f, (float)i / (float)n, a);
        glVertex2f(cx + r * __builtin_cosf(t0), cy + r * __builtin_sinf(t0));
        glColor4f(0.2f, 0.3f, 1.0f, a);
        glVertex2f(cx + r * __builtin_cosf(t1), cy + r * __builtin_sinf(t1));
    }
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    GLuint fb[4], rb[6], tex;
    GLint v[8];
    unsigned char texels[8 * 8 * 4];
    int i, k;

    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    /* 1. limits */
    glGetIntegerv(GL_MAX_SAMPLES, &v[0]);
    glGetIntegerv(GL_SAMPLE_BUFFERS, &v[1]);
    glGetIntegerv(GL_SAMPLES, &v[2]);
    sgl_text(out, "limits", "%d %d %d %x", v[0], v[1], v[2], glGetError());

    glGenFramebuffers(4, fb);
    glGenRenderbuffers(6, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[5]);
    for (i = 0; i <= 5; i++) {
        GLint s = -1;
        GLenum e;
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, i, GL_RGBA8, 4, 4);
        e = glGetError();
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &s);
        sgl_text(out, "request", "%d -> %x %d", i, e, s);
    }

    /* 2. the 4x object */
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, FW, FH);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH24_STENCIL8, FW, FH);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              rb[1]);
    v[0] = (GLint)glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glGetIntegerv(GL_SAMPLE_BUFFERS, &v[1]);
    glGetIntegerv(GL_SAMPLES, &v[2]);
    glGetIntegerv(GL_MAX_SAMPLES, &v[3]);
    glGetIntegerv(GL_DEPTH_BITS, &v[4]);
    glGetIntegerv(GL_STENCIL_BITS, &v[5]);
    sgl_text(out, "ms_state", "%x %d %d %d %d %d %x", v[0], v[1], v[2], v[3], v[4], v[5],
             glGetError());

    /* the single-sample resolve target */
    glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[2]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, FW, FH);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[2]);
    v[0] = (GLint)glCheckFramebufferStatus(GL_FRAMEBUFFER);
    glGetIntegerv(GL_SAMPLE_BUFFERS, &v[1]);
    glGetIntegerv(GL_SAMPLES, &v[2]);
    sgl_text(out, "ss_state", "%x %d %d", v[0], v[1], v[2]);

    /* mixed sample counts */
    glBindFramebuffer(GL_FRAMEBUFFER, fb[2]);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[3]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, FW, FH);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              rb[3]);
    sgl_text(out, "mixed", "%x", (unsigned)glCheckFramebufferStatus(GL_FRAMEBUFFER));

    /* 3. drawing */
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    glViewport(0, 0, FW, FH);
    glClearColor(0.1f, 0.15f, 0.2f, 1.0f);
    glClearDepth(1.0);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glShadeModel(GL_SMOOTH);
    fan(-0.45f, 0.4f, 0.5f, 22, 1.0f);
    /* random small triangles */
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 60; i++) {
        float x = sgl_randf() * 1.8f - 0.9f, y = sgl_randf() * 1.8f - 0.9f;
        for (k = 0; k < 3; k++) {
            glColor3f(sgl_randf(), sgl_randf(), sgl_randf());
            glVertex2f(x + sgl_randf() * 0.25f - 0.12f, y + sgl_randf() * 0.25f - 0.12f);
        }
    }
    glEnd();
    read_resolved(out, fb[0], fb[1], "smooth");

    /* intersecting triangles: depth per sample */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.0f, 0.0f);
    glVertex3f(-0.9f, -0.8f, -0.9f);
    glVertex3f(0.9f, -0.7f, 0.9f);
    glVertex3f(0.0f, 0.9f, 0.0f);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex3f(-0.9f, 0.7f, 0.8f);
    glVertex3f(0.85f, 0.8f, -0.8f);
    glVertex3f(0.1f, -0.9f, 0.05f);
    glColor3f(0.0f, 0.3f, 1.0f);
    glVertex3f(-0.95f, 0.05f, 0.3f);
    glVertex3f(0.95f, -0.03f, -0.2f);
    glVertex3f(0.93f, 0.11f, 0.1f);
    glEnd();
    /* a quad whose depth varies along x against a constant-depth quad */
    glBegin(GL_QUADS);
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex3f(-0.9f, -0.95f, -1.0f);
    glVertex3f(0.9f, -0.95f, 1.0f);
    glVertex3f(0.9f, -0.6f, 1.0f);
    glVertex3f(-0.9f, -0.6f, -1.0f);
    glColor3f(0.5f, 0.0f, 0.5f);
    glVertex3f(-0.9f, -0.95f, 0.013f);
    glVertex3f(0.9f, -0.95f, 0.013f);
    glVertex3f(0.9f, -0.6f, 0.013f);
    glVertex3f(-0.9f, -0.6f, 0.013f);
    glEnd();
    read_resolved(out, fb[0], fb[1], "depth");

    /* textured and blended */
    for (i = 0; i < 64; i++) {
        texels[i * 4 + 0] = (unsigned char)((i & 1) ? 255 : 30);
        texels[i * 4 + 1] = (unsigned char)(i * 4);
        texels[i * 4 + 2] = (unsigned char)(((i >> 3) & 1) ? 200 : 10);
        texels[i * 4 + 3] = (unsigned char)(128 + i);
    }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 1.0f, 1.0f);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(-0.8f, -0.85f, 0.5f);
    glColor3f(1.0f, 0.5f, 1.0f);
    glTexCoord2f(1.0f, 0.0f);
    glVertex3f(0.83f, -0.4f, -0.5f);
    glColor3f(0.5f, 1.0f, 0.7f);
    glTexCoord2f(0.3f, 1.0f);
    glVertex3f(-0.2f, 0.87f, 0.0f);
    glEnd();
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBegin(GL_TRIANGLES);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(0.1f, 0.1f, -0.95f);
    glTexCoord2f(1.0f, 0.2f);
    glVertex3f(0.93f, 0.3f, -0.95f);
    glTexCoord2f(0.5f, 1.0f);
    glVertex3f(0.4f, 0.91f, -0.95f);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_DEPTH_TEST);
    fan(0.4f, -0.3f, 0.45f, 18, 0.6f);
    glDisable(GL_BLEND);
    read_resolved(out, fb[0], fb[1], "textured");

    /* stencil: a fan writes 1, then a quad is drawn where stencil == 1 */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    fan(0.0f, 0.0f, 0.8f, 14, 1.0f);
    fan(0.1f, 0.05f, 0.5f, 10, 1.0f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilFunc(GL_EQUAL, 1, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glBegin(GL_QUADS);
    glColor3f(1.0f, 0.9f, 0.2f);
    glVertex2f(-1.0f, -1.0f);
    glColor3f(0.2f, 0.9f, 1.0f);
    glVertex2f(1.0f, -1.0f);
    glVertex2f(1.0f, 1.0f);
    glColor3f(1.0f, 0.1f, 0.6f);
    glVertex2f(-1.0f, 1.0f);
    glEnd();
    glStencilFunc(GL_EQUAL, 2, 0xff);
    glBegin(GL_QUADS);
    glColor3f(0.0f, 0.0f, 0.0f);
    glVertex2f(-1.0f, -1.0f);
    glVertex2f(1.0f, -1.0f);
    glVertex2f(1.0f, 1.0f);
    glVertex2f(-1.0f, 1.0f);
    glEnd();
    glDisable(GL_STENCIL_TEST);
    read_resolved(out, fb[0], fb[1], "stencil");

    /* alpha to coverage (alpha ramps across a quad) and sample coverage */
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glBegin(GL_QUADS);
    glColor4f(1.0f, 1.0f, 1.0f, 0.0f);
    glVertex2f(-1.0f, 0.5f);
    glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    glVertex2f(1.0f, 0.5f);
    glVertex2f(1.0f, 1.0f);
    glColor4f(1.0f, 1.0f, 1.0f, 0.0f);
    glVertex2f(-1.0f, 1.0f);
    glEnd();
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glEnable(GL_SAMPLE_COVERAGE);
    for (i = 0; i < 10; i++) {
        float x0 = -1.0f + 0.2f * (float)i;
        glSampleCoverage((float)(i % 5) * 0.25f + 0.125f * (float)(i / 5), (GLboolean)(i >= 5));
        glBegin(GL_QUADS);
        glColor3f(0.9f, 0.5f, 0.1f + 0.08f * (float)i);
        glVertex2f(x0, -0.2f);
        glVertex2f(x0 + 0.2f, -0.2f);
        glVertex2f(x0 + 0.2f, 0.4f);
        glVertex2f(x0, 0.4f);
        glEnd();
    }
    glSampleCoverage(1.0f, GL_FALSE);
    glDisable(GL_SAMPLE_COVERAGE);
    /* GL_MULTISAMPLE off: centre coverage, every sample written */
    glDisable(GL_MULTISAMPLE);
    fan(0.0f, -0.65f, 0.3f, 12, 1.0f);
    glEnable(GL_MULTISAMPLE);
    fan(0.55f, -0.65f, 0.3f, 12, 1.0f);
    read_resolved(out, fb[0], fb[1], "coverage");

    /* 4. resolves offset and mirrored */
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[1]);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
    glBlitFramebuffer(0, 0, 30, 20, 5, 7, 35, 27, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBlitFramebuffer(0, 20, 30, 40, 60, 20, 30, 40, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    sgl_text(out, "resolve_err", "%x", glGetError());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[1]);
    glReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_image(out, "offset", FW, FH, 4, "RGBA", FW * 4, 1, px);

    /* 5. errors */
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
    glReadPixels(0, 0, 4, 4, GL_RGBA, GL_UNSIGNED_BYTE, px);
    v[0] = (GLint)glGetError();
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 4, 4, 0);
    v[1] = (GLint)glGetError();
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[1]);
    glBlitFramebuffer(0, 0, 30, 20, 0, 0, 60, 40, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    v[2] = (GLint)glGetError();
    glBlitFramebuffer(0, 0, 30, 20, 0, 0, 60, 40, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    v[3] = (GLint)glGetError();
    glBlitFramebuffer(0, 0, FW, FH, 0, 0, FW, FH, GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    v[4] = (GLint)glGetError();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[1]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[0]);
    glBlitFramebuffer(0, 0, FW, FH, 0, 0, FW, FH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    v[5] = (GLint)glGetError();
    sgl_text(out, "errors", "%x %x %x %x %x %x", v[0], v[1], v[2], v[3], v[4], v[5]);
    read_resolved(out, fb[0], fb[1], "after_upload");

    /* glDrawPixels into the 4x object: every sample of the covered pixels */
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    glClear(GL_COLOR_BUFFER_BIT);
    glRasterPos2f(-0.5f, -0.4f);
    glDrawPixels(8, 8, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    read_resolved(out, fb[0], fb[1], "draw_pixels");

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glGetIntegerv(GL_SAMPLE_BUFFERS, &v[1]);
    glGetIntegerv(GL_SAMPLES, &v[2]);
    sgl_text(out, "window", "%d %d %x", v[1], v[2], glGetError());
    glFinish();
    sgl_image(out, "window_img", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
