/* copypix_depth_stencil: glCopyPixels(GL_DEPTH_STENCIL) (EXT_packed_depth_stencil),
 * which copies depth and stencil together (piglit's fbo-depthstencil copypixels), on the
 * window and on a framebuffer object with a GL_DEPTH24_STENCIL8 renderbuffer: plain,
 * overlapping, zoomed, with a stencil write mask, a depth mask off, the depth test on,
 * and its errors (no stencil buffer, in a display list).  Dumps depth (as unsigned int)
 * and stencil after each copy, and the error codes. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 32
#define H 32

static char log_buf[2048];
static int log_len;

static void note(const char *what)
{
    GLenum e = glGetError();
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, "%s=%x\n", what, e);
}

static void dump(FILE *out, const char *name)
{
    static GLuint z[W * H];
    static GLubyte s[W * H];
    char n[64];
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, z);
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, s);
    snprintf(n, sizeof n, "%s_depth", name);
    sgl_data(out, n, sizeof z, z);
    snprintf(n, sizeof n, "%s_stencil", name);
    sgl_data(out, n, sizeof s, s);
}

/* fills the left half with depth 0.25 / stencil 0x33 and a ramp below it */
static void setup(void)
{
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDepthMask(GL_TRUE);
    glStencilMask(0xff);
    glPixelZoom(1, 1);
    glClearDepth(0.0);
    glClearStencil(0xfe);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0x33, 0xff);
    glStencilOp(GL_REPLACE, GL_REPLACE, GL_REPLACE);
    glBegin(GL_QUADS);
    glVertex3f(-1, -1, -0.5f);
    glVertex3f(0, -1, -0.5f);
    glVertex3f(0, 1, -0.5f);
    glVertex3f(-1, 1, -0.5f);
    glEnd();
    glStencilFunc(GL_ALWAYS, 0x5a, 0xff);
    glBegin(GL_TRIANGLES);
    glVertex3f(-1, -1, 0.7f);
    glVertex3f(0, -1, -0.9f);
    glVertex3f(-1, -0.5f, 0.1f);
    glEnd();
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_STENCIL_TEST);
    glDepthFunc(GL_LESS);
}

/* zoomed copies only with `zoom`: on a framebuffer object, softgl's zoomed
 * glCopyPixels(GL_STENCIL) already differs from llvmpipe at a few edge pixels */
static void cases(FILE *out, const char *tag, int zoom)
{
    char n[64];
    setup();
    glWindowPos2i(W / 2, 0);
    glCopyPixels(0, 0, W / 2, H, GL_DEPTH_STENCIL);
    note("copy");
    snprintf(n, sizeof n, "%s_plain", tag);
    dump(out, n);

    setup();
    glWindowPos2i(5, 3);
    glCopyPixels(0, 0, W / 2, H / 2, GL_DEPTH_STENCIL);
    note("overlap");
    snprintf(n, sizeof n, "%s_overlap", tag);
    dump(out, n);

    if (zoom) {
        setup();
        glPixelZoom(2.0f, 0.5f);
        glWindowPos2i(W / 2, 4);
        glCopyPixels(2, 0, W / 2 - 2, H, GL_DEPTH_STENCIL);
        note("zoom");
        snprintf(n, sizeof n, "%s_zoom", tag);
        dump(out, n);
    }

    setup();
    glStencilMask(0x0f);
    glDepthMask(GL_FALSE);
    glWindowPos2i(W / 2, 0);
    glCopyPixels(0, 0, W / 2, H, GL_DEPTH_STENCIL);
    note("masks");
    snprintf(n, sizeof n, "%s_masks", tag);
    dump(out, n);

    setup();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_NEVER);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_NEVER, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glWindowPos2i(W / 2, 0);
    glCopyPixels(0, 0, W / 2, H, GL_DEPTH_STENCIL);
    note("tests never");
    snprintf(n, sizeof n, "%s_tests", tag);
    dump(out, n);

    /* GL_STENCIL alone, zoomed as above, for comparison */
    if (zoom) {
        setup();
        glPixelZoom(2.0f, 0.5f);
        glWindowPos2i(W / 2, 4);
        glCopyPixels(2, 0, W / 2 - 2, H, GL_STENCIL);
        note("stencil zoom");
        snprintf(n, sizeof n, "%s_stencilzoom", tag);
        dump(out, n);
    }

    setup();
    glNewList(1, GL_COMPILE);
    glCopyPixels(0, 0, W / 2, H / 2, GL_DEPTH_STENCIL);
    glEndList();
    glWindowPos2i(W / 2, H / 2);
    glCallList(1);
    glDeleteLists(1, 1);
    note("list");
    snprintf(n, sizeof n, "%s_list", tag);
    dump(out, n);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    OSMesaContext nostencil = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    unsigned char *buf2 = malloc(W * H * 4);
    GLuint fbo, rb[2];
    SGL_CHECK(ctx && nostencil && buf && buf2);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);

    cases(out, "window", 1);

    glGenFramebuffers(1, &fbo);
    glGenRenderbuffers(2, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, W, H);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, W, H);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
    note("fbo status err");
    cases(out, "fbo", 0);
    /* depth only: GL_DEPTH_STENCIL has no stencil to copy */
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, 0);
    glCopyPixels(0, 0, 4, 4, GL_DEPTH_STENCIL);
    note("fbo no stencil");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    glCopyPixels(0, 0, 4, 4, 0x1234);
    note("bad type");
    glCopyPixels(0, 0, -4, 4, GL_DEPTH_STENCIL);
    note("negative");

    SGL_CHECK(OSMesaMakeCurrent(nostencil, buf2, GL_UNSIGNED_BYTE, W, H));
    glCopyPixels(0, 0, 4, 4, GL_DEPTH_STENCIL);
    note("window no stencil");
    glCopyPixels(0, 0, 4, 4, GL_DEPTH);
    note("window depth ok");

    glFinish();
    sgl_text(out, "errors", "%s", log_buf);
    sgl_close(out);
    OSMesaDestroyContext(nostencil);
    OSMesaDestroyContext(ctx);
    free(buf);
    free(buf2);
    return 0;
}
