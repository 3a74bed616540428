/* fbo_share: framebuffer and renderbuffer objects between contexts created with a
 * sharelist (OSMesaCreateContextExt's last argument).  Mesa 22.3 keeps both kinds in
 * the shared state, so a second context sees the first one's renderbuffers and
 * framebuffers (names, glIs*, attachments, contents), while a context outside the
 * group sees neither.  Pixels drawn into a shared renderbuffer by one context are
 * read back through the other, and the first context, still bound to its object,
 * sees what the second drew. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 16
#define H 16

static char log_buf[8192];
static int log_len;

static void note(const char *fmt, int a, int b)
{
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, fmt, a, b);
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, " err=%x\n",
                        glGetError());
}

static void quad(float x0, float y0, float x1, float y1)
{
    glBegin(GL_QUADS);
    glVertex2f(x0, y0);
    glVertex2f(x1, y0);
    glVertex2f(x1, y1);
    glVertex2f(x0, y1);
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext a = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    OSMesaContext b = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, a);
    OSMesaContext c = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *bufa = calloc(W * H, 4), *bufb = calloc(W * H, 4), *bufc = calloc(W * H, 4);
    unsigned char px[W * H * 4];
    GLuint rb[2], fa, fb2, more[2];
    GLint v = -7;

    SGL_CHECK(a && b && c && bufa && bufb && bufc);

    /* context A: a colour renderbuffer and a depth renderbuffer on framebuffer fa */
    SGL_CHECK(OSMesaMakeCurrent(a, bufa, GL_UNSIGNED_BYTE, W, H));
    glGenRenderbuffers(2, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, W, H);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, W, H);
    glGenFramebuffers(1, &fa);
    glBindFramebuffer(GL_FRAMEBUFFER, fa);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
    note("A status %x %d", (int)glCheckFramebufferStatus(GL_FRAMEBUFFER), 0);
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glClearColor(0.2f, 0.3f, 0.4f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glColor3f(1.0f, 0.0f, 0.0f);
    quad(2, 2, 10, 10);
    glFinish();
    note("A names rb %d %d", (int)rb[0], (int)rb[1]);
    note("A name fb %d %d", (int)fa, 0);

    /* context B (shares with A): sees both kinds of objects */
    SGL_CHECK(OSMesaMakeCurrent(b, bufb, GL_UNSIGNED_BYTE, W, H));
    note("B isrb %d %d", glIsRenderbuffer(rb[0]), glIsRenderbuffer(rb[1]));
    note("B isfb %d %d", glIsFramebuffer(fa), glIsFramebuffer(fa + 7));
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &v);
    note("B binding %d %d", v, 0);
    glGenRenderbuffers(2, more);
    note("B new rb names %d %d", (int)more[0], (int)more[1]);
    glGenFramebuffers(1, &fb2);
    note("B new fb name %d %d", (int)fb2, 0);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_WIDTH, &v);
    note("B rb width %d %d", v, 0);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &v);
    note("B rb format %x %d", v, 0);
    /* A's framebuffer, bound in B: its attachments and contents */
    glBindFramebuffer(GL_FRAMEBUFFER, fa);
    note("B bind fa %d %d", 0, 0);
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0,
                                          GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &v);
    note("B fa color %d %d", v, 0);
    note("B fa status %x %d", (int)glCheckFramebufferStatus(GL_FRAMEBUFFER), 0);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    note("B read fa %d %d", 0, 0);
    sgl_data(out, "B_reads_fa", sizeof px, px);
    /* B's own framebuffer on A's renderbuffer: draw into it */
    glBindFramebuffer(GL_FRAMEBUFFER, fb2);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    note("B fb2 status %x %d", (int)glCheckFramebufferStatus(GL_FRAMEBUFFER), 0);
    glViewport(0, 0, W, H);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glColor3f(0.0f, 1.0f, 0.0f);
    quad(6, 6, 14, 14);
    glFinish();
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_data(out, "B_reads_fb2", sizeof px, px);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    note("B window %d %d", bufb[0], bufb[1]);

    /* a context outside the group sees neither */
    SGL_CHECK(OSMesaMakeCurrent(c, bufc, GL_UNSIGNED_BYTE, W, H));
    note("C isrb %d isfb %d", glIsRenderbuffer(rb[0]), glIsFramebuffer(fa));
    glBindFramebuffer(GL_FRAMEBUFFER, fa);
    note("C bind fa (a new name here) %d %d", glIsFramebuffer(fa), 0);
    note("C status %x %d", (int)glCheckFramebufferStatus(GL_FRAMEBUFFER), 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);

    /* back in A, still bound to fa: B's drawing is there, on top of A's */
    SGL_CHECK(OSMesaMakeCurrent(a, bufa, GL_UNSIGNED_BYTE, W, H));
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &v);
    note("A binding %d %d", v, 0);
    note("A isfb fb2 %d isrb more %d", glIsFramebuffer(fb2), glIsRenderbuffer(more[0]));
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_data(out, "A_reads_fa_again", sizeof px, px);
    /* depth from A's draw is still tested: a blue quad behind red, in front elsewhere */
    glColor3f(0.0f, 0.0f, 1.0f);
    glBegin(GL_QUADS);
    glVertex3f(0, 0, 0.5f);
    glVertex3f(W, 0, 0.5f);
    glVertex3f(W, 4, 0.5f);
    glVertex3f(0, 4, 0.5f);
    glEnd();
    glFinish();
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_data(out, "A_draws_again", sizeof px, px);
    /* deleted in A, gone in B */
    glDeleteFramebuffers(1, &fb2);
    glDeleteRenderbuffers(1, &more[1]);
    note("A deleted %d %d", glIsFramebuffer(fb2), glIsRenderbuffer(more[1]));
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    SGL_CHECK(OSMesaMakeCurrent(b, bufb, GL_UNSIGNED_BYTE, W, H));
    note("B sees deleted %d %d", glIsFramebuffer(fb2), glIsRenderbuffer(more[1]));
    note("B still %d %d", glIsFramebuffer(fa), glIsRenderbuffer(rb[0]));

    sgl_text(out, "log", "%s", log_buf);
    sgl_close(out);
    OSMesaDestroyContext(c);
    OSMesaDestroyContext(b);
    OSMesaDestroyContext(a);
    free(bufa);
    free(bufb);
    free(bufc);
    return 0;
}
