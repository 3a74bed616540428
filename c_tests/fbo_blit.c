/* fbo_blit: glBlitFramebuffer between framebuffer objects and the window.
 * A 37x29 source object holds a smooth gradient with a checker pattern; blits copy it
 * unscaled, scaled up and down by odd ratios with GL_NEAREST and GL_LINEAR, mirrored in
 * x, in y and both, with the source partly outside the read buffer, through the
 * scissor, from the window into an object and from an object into the window; depth and
 * stencil are blitted between two depth-stencil objects.  Destination rectangles stay
 * inside the draw buffer (llvmpipe clips a quad that leaves it geometrically, which
 * softgl does not follow yet).  Every destination is read back and compared. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 100
#define H 90
#define SW 37
#define SH 29
#define DW 96
#define DH 80

static void fill_source(void)
{
    int i, j;
    glViewport(0, 0, SW, SH);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, SW, 0.0, SH, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClearDepth(0.25);
    glClearStencil(7);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glBegin(GL_QUADS);
    glColor4f(1.0f, 0.0f, 0.2f, 1.0f);
    glVertex2f(0, 0);
    glColor4f(0.0f, 1.0f, 0.4f, 0.5f);
    glVertex2f(SW, 0);
    glColor4f(0.1f, 0.2f, 1.0f, 0.2f);
    glVertex2f(SW, SH);
    glColor4f(0.9f, 0.9f, 0.0f, 0.8f);
    glVertex2f(0, SH);
    glEnd();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOp(GL_INCR, GL_INCR, GL_INCR);
    glBegin(GL_QUADS);
    for (j = 0; j < SH; j += 4)
        for (i = (j / 4) % 2 * 3; i < SW; i += 6) {
            glColor3f((float)i / SW, 1.0f - (float)j / SH, 0.5f);
            glVertex3f(i, j, (float)i / SW - 0.5f);
            glVertex3f(i + 3, j, (float)i / SW - 0.5f);
            glVertex3f(i + 3, j + 2, (float)j / SH - 0.5f);
            glVertex3f(i, j + 2, (float)j / SH - 0.5f);
        }
    glEnd();
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
}

static void read_dst(FILE *out, const char *name)
{
    static unsigned char px[DW * DH * 4];
    glReadPixels(0, 0, DW, DH, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_image(out, name, DW, DH, 4, "RGBA", DW * 4, 1, px);
}

int main(int argc, char **argv)
{
    static const int cases[][9] = {
        /* src x0 y0 x1 y1, dst x0 y0 x1 y1, linear */
        {0, 0, SW, SH, 3, 4, 3 + SW, 4 + SH, 0},
        {0, 0, SW, SH, 0, 0, 74, 58, 0},
        {0, 0, SW, SH, 0, 0, 74, 58, 1},
        {2, 3, 35, 27, 5, 1, 94, 79, 0},
        {2, 3, 35, 27, 5, 1, 94, 79, 1},
        {0, 0, SW, SH, 10, 10, 31, 25, 0},
        {0, 0, SW, SH, 10, 10, 31, 25, 1},
        {0, 0, SW, SH, 90, 2, 7, 70, 0},
        {0, 0, SW, SH, 4, 77, 88, 6, 1},
        {SW, SH, 0, 0, 1, 1, 56, 44, 0},
        {-10, -6, 30, 40, 2, 2, 62, 71, 0},
        {20, 10, 60, 50, 2, 2, 62, 71, 1},
        {0, 0, 24, 24, 0, 0, 36, 36, 0},
        {0, 0, 24, 24, 0, 0, 36, 36, 1},
        {5, 5, 29, 29, 40, 40, 56, 56, 0},
        {3, 3, 9, 9, 0, 0, 95, 79, 1},
    };
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    GLuint fb[3], rb[4];
    unsigned char st[DW * DH];
    GLuint dz[DW * DH];
    char name[32];
    unsigned k;

    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    glGenFramebuffers(3, fb);
    glGenRenderbuffers(4, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, SW, SH);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, SW, SH);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
    fill_source();
    glBindRenderbuffer(GL_RENDERBUFFER, rb[2]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, DW, DH);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[3]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, DW, DH);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[2]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[3]);
    SGL_CHECK(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);

    /* object to object, each case into a cleared destination */
    for (k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        const int *c = cases[k];
        glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
        glDisable(GL_SCISSOR_TEST);
        glClearColor(0.2f, 0.2f, 0.2f, 0.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        if (k == 4 || k == 8) {
            glEnable(GL_SCISSOR_TEST);
            glScissor(11, 7, 50, 41);
        }
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
        glBlitFramebuffer(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], GL_COLOR_BUFFER_BIT,
                          c[8] ? GL_LINEAR : GL_NEAREST);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[1]);
        snprintf(name, sizeof name, "case%u", k);
        read_dst(out, name);
        sgl_text(out, "err", "%x", glGetError());
    }
    glDisable(GL_SCISSOR_TEST);

    /* depth and stencil, scaled and mirrored */
    glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
    glClearDepth(1.0);
    glClearStencil(0);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
    glBlitFramebuffer(0, 0, SW, SH, 90, 3, 4, 70, GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT,
                      GL_NEAREST);
    sgl_text(out, "ds_err", "%x", glGetError());
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[1]);
    glReadPixels(0, 0, DW, DH, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, dz);
    sgl_data(out, "depth", sizeof dz, dz);
    glReadPixels(0, 0, DW, DH, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, st);
    sgl_data(out, "stencil", sizeof st, st);

    /* within one object (apart: overlapping is undefined), then object to window and
     * window to object */
    glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
    glBlitFramebuffer(0, 0, 40, 30, 45, 35, 85, 75, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBlitFramebuffer(0, 0, 40, 30, 50, 0, 90, 30, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT,
                      GL_NEAREST);
    read_dst(out, "within");
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glClearColor(0.0f, 0.0f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
    glBlitFramebuffer(0, 0, SW, SH, 3, 2, 80, 61, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBlitFramebuffer(SW, 0, 0, SH, 50, 60, 99, 89, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[1]);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glBlitFramebuffer(0, 0, W, H, 0, DH, DW, 0, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBlitFramebuffer(10, 10, 40, 30, 60, 50, 95, 79, GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[1]);
    read_dst(out, "from_window");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glFinish();
    sgl_image(out, "window", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "error", "%x", glGetError());
    OSMesaDestroyContext(ctx);
    free(buf);
    sgl_close(out);
    return 0;
}
