/* fbo_lend: renderbuffers drawn into while bound, then looked at every other way - the
 * cases softgl's lending of renderbuffer storage to the bound object must keep right.
 * - An RGBA8 + DEPTH24_STENCIL8 object A drawn with depth and stencil, unbound to the
 *   window and bound again (kept working copy), read back (colour, depth, stencil).
 * - A second object B sharing A's colour renderbuffer: read through the read binding while
 *   A is bound for drawing (the drawing must be there), then drawn into itself and A read.
 * - glDrawBuffer(GL_NONE) and back on A, with a draw in between.
 * - A's colour renderbuffer given new storage (another size) while A is bound, then its
 *   depth renderbuffer deleted while bound (detached: A draws without depth).
 * - A 4x object M drawn, A bound, M bound again and drawn over, resolved into A by
 *   glBlitFramebuffer (both bindings set), read; then M deleted while bound.
 * - Two contexts sharing A's renderbuffers through the share list. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "fbo_common.h"

#define W 16
#define H 12
#define FW 21
#define FH 17

static unsigned char px[FW * FH * 4];
static GLuint dz[FW * FH];
static unsigned char st[FW * FH];

static void tri(float x, float y, float s, float z, float r, float g, float b)
{
    glBegin(GL_TRIANGLES);
    glColor3f(r, g, b);
    glVertex3f(x - s, y - s, z);
    glVertex3f(x + s, y - 0.7f * s, -z);
    glVertex3f(x + 0.2f * s, y + s, z * 0.5f);
    glEnd();
}

static void dump(FILE *out, const char *name, int w, int h)
{
    glReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_image(out, name, w, h, 4, "RGBA", w * 4, 1, px);
    sgl_text(out, "err", "%s %x", name, glGetError());
}

static void dump_ds(FILE *out, const char *name, int w, int h)
{
    int i;
    unsigned long sum = 0;
    glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, dz);
    glReadPixels(0, 0, w, h, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, st);
    for (i = 0; i < w * h; i++)
        sum = sum * 31 + (dz[i] >> 8) + st[i] * 7u;
    sgl_text(out, name, "%lu %u %u %u %x", sum, dz[0] >> 8, dz[w * h / 2 + w / 2] >> 8,
             st[w * h / 2 + w / 2], glGetError());
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    OSMesaContext ctx2 = NULL;
    unsigned char *buf = malloc(W * H * 4), *buf2 = malloc(W * H * 4);
    GLuint fb[3], rb[5];

    SGL_CHECK(ctx && buf && buf2);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    glGenFramebuffers(3, fb);
    glGenRenderbuffers(5, rb);
    /* A: colour rb[0] + depth-stencil rb[1] */
    sgl_fbo_rgba8_ds(fb[0], rb[0], rb[1], FW, FH);
    sgl_text(out, "a_status", "%x", (unsigned)glCheckFramebufferStatus(GL_FRAMEBUFFER));

    /* 1. draw with depth and stencil, unbind, rebind, read */
    glViewport(0, 0, FW, FH);
    glClearColor(0.2f, 0.1f, 0.3f, 1.0f);
    glClearDepth(0.75);
    glClearStencil(3);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 9, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    tri(-0.2f, -0.1f, 0.7f, 0.4f, 1.0f, 0.5f, 0.0f);
    tri(0.3f, 0.2f, 0.6f, -0.3f, 0.0f, 0.8f, 0.4f);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    dump(out, "a_rebound", FW, FH);
    dump_ds(out, "a_ds", FW, FH);
    tri(0.0f, 0.0f, 0.3f, -0.9f, 0.9f, 0.9f, 0.1f);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    dump(out, "a_rebound2", FW, FH);

    /* 2. B shares A's colour: read B while A is bound for drawing */
    glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    sgl_text(out, "b_status", "%x", (unsigned)glCheckFramebufferStatus(GL_FRAMEBUFFER));
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[0]);
    glDisable(GL_STENCIL_TEST);
    tri(-0.5f, 0.4f, 0.3f, -0.95f, 0.1f, 0.2f, 1.0f);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[1]);
    dump(out, "b_read_while_a", FW, FH);
    /* then draw into B itself (A's colour) and read A */
    glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
    glDisable(GL_DEPTH_TEST);
    tri(0.5f, -0.5f, 0.35f, 0.0f, 1.0f, 1.0f, 1.0f);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    dump(out, "a_after_b", FW, FH);

    /* 3. glDrawBuffer(GL_NONE) and back */
    glDrawBuffer(GL_NONE);
    glEnable(GL_DEPTH_TEST);
    tri(0.0f, 0.5f, 0.4f, -0.99f, 1.0f, 0.0f, 0.0f);
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
    tri(0.0f, 0.5f, 0.4f, -0.98f, 0.0f, 1.0f, 0.0f);
    dump(out, "a_drawbuffer", FW, FH);
    dump_ds(out, "a_drawbuffer_ds", FW, FH);

    /* 4. new storage for the bound colour renderbuffer, then delete the depth one */
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, FW - 4, FH - 3);
    sgl_text(out, "a_respec", "%x", (unsigned)glCheckFramebufferStatus(GL_FRAMEBUFFER));
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, FW - 4, FH - 3);
    glViewport(0, 0, FW - 4, FH - 3);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    tri(0.1f, 0.0f, 0.8f, 0.2f, 0.6f, 0.3f, 0.9f);
    dump(out, "a_respec_draw", FW - 4, FH - 3);
    glDeleteRenderbuffers(1, &rb[1]);
    glGetIntegerv(GL_DEPTH_BITS, (GLint *)&dz[0]);
    sgl_text(out, "a_deleted_depth", "%x %d %x",
             (unsigned)glCheckFramebufferStatus(GL_FRAMEBUFFER), (int)dz[0], glGetError());
    tri(-0.3f, 0.3f, 0.5f, 0.9f, 0.9f, 0.8f, 0.1f);
    dump(out, "a_no_depth", FW - 4, FH - 3);

    /* 5. a 4x object drawn, left, drawn over, resolved into A */
    glBindFramebuffer(GL_FRAMEBUFFER, fb[2]);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[2]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, FW - 4, FH - 3);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[2]);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[3]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH24_STENCIL8, FW - 4, FH - 3);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              rb[3]);
    sgl_text(out, "m_status", "%x", (unsigned)glCheckFramebufferStatus(GL_FRAMEBUFFER));
    glClearColor(0.0f, 0.3f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    tri(-0.1f, -0.2f, 0.8f, 0.5f, 1.0f, 0.2f, 0.6f);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[2]);
    tri(0.3f, 0.1f, 0.6f, -0.5f, 0.2f, 0.9f, 1.0f);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[2]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[0]);
    glBlitFramebuffer(0, 0, FW - 4, FH - 3, 0, 0, FW - 4, FH - 3, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    sgl_text(out, "m_blit", "%x", glGetError());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
    dump(out, "m_resolved", FW - 4, FH - 3);
    /* the 4x object again, drawn over, resolved a second time */
    glBindFramebuffer(GL_FRAMEBUFFER, fb[2]);
    tri(-0.6f, 0.5f, 0.3f, -0.9f, 0.9f, 0.9f, 0.2f);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[0]);
    glBlitFramebuffer(0, 0, FW - 4, FH - 3, 0, 0, FW - 4, FH - 3, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
    dump(out, "m_resolved2", FW - 4, FH - 3);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[2]);
    glDeleteRenderbuffers(1, &rb[2]);
    sgl_text(out, "m_deleted", "%x %x", (unsigned)glCheckFramebufferStatus(GL_FRAMEBUFFER),
             glGetError());

    /* 6. a second context sharing the objects reads A's colour */
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    tri(0.4f, 0.4f, 0.3f, 0.0f, 0.3f, 0.3f, 0.3f);
    ctx2 = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, ctx);
    SGL_CHECK(ctx2 != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx2, buf2, GL_UNSIGNED_BYTE, W, H));
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    sgl_text(out, "ctx2_status", "%x", (unsigned)glCheckFramebufferStatus(GL_FRAMEBUFFER));
    dump(out, "ctx2_read", FW - 4, FH - 3);
    glViewport(0, 0, FW - 4, FH - 3);
    tri(-0.4f, -0.4f, 0.3f, 0.0f, 0.8f, 0.1f, 0.1f);
    glFinish();
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    dump(out, "ctx1_after", FW - 4, FH - 3);
    OSMesaDestroyContext(ctx2);
    dump(out, "ctx1_after_destroy", FW - 4, FH - 3);

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(3, fb);
    glDeleteRenderbuffers(5, rb);
    sgl_text(out, "end", "%x", glGetError());
    OSMesaDestroyContext(ctx);
    free(buf);
    free(buf2);
    sgl_close(out);
    return 0;
}
