/* frag_mrt: several draw buffers (glDrawBuffers, GL 2.0) written through
 * gl_FragData[k] and gl_FragColor: a framebuffer object with three RGBA8
 * colour attachments (renderbuffers and a texture level) and a depth buffer,
 * cleared and drawn with programs that write every element and gl_FragColor
 * (written to every buffer), with discard, blending and a colour mask; then in
 * another order with a GL_NONE in the list, where a program leaves the element
 * of that buffer unwritten (an unwritten element's buffer gets llvmpipe's
 * uninitialised stack, so no scene draws one into a buffer); each attachment read back through glReadBuffer, also
 * while it is bound for drawing. Then glDrawBuffers' errors and the
 * GL_DRAW_BUFFERi queries, for the object and for the window. */
#define GL_GLEXT_PROTOTYPES
#define FW 96
#define FH 80
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "frag_program.h"

static const char *FS_ALL =
    "void main() {\n"
    "  gl_FragData[0] = gl_Color;\n"
    "  gl_FragData[1] = vec4(fract(gl_TexCoord[0].st), 0.25, gl_Color.a);\n"
    "  gl_FragData[2] = gl_Color.bgra * 0.5 + vec4(0.1);\n"
    "}\n";

static const char *FS_SOME =
    "void main() {\n"
    "  gl_FragData[0] = gl_Color.gbra;\n"
    "  gl_FragData[2] = vec4(gl_FragCoord.xy / 128.0, gl_Color.r, 0.6);\n"
    "}\n";

static const char *FS_COLOR =
    "void main() {\n"
    "  if (gl_Color.g > 0.8) discard;\n"
    "  gl_FragColor = vec4(gl_Color.rg * 0.7, fract(gl_TexCoord[0].s), 0.5);\n"
    "}\n";

static char log_buf[4096];
static int log_len;

static void note(const char *what)
{
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, "%s=%x\n", what,
                        glGetError());
}

static void note_buffers(const char *what)
{
    GLint v[9], max = 0;
    int i;
    glGetIntegerv(GL_MAX_DRAW_BUFFERS, &max);
    for (i = 0; i < 8; i++)
        glGetIntegerv(GL_DRAW_BUFFER0 + i, &v[i]);
    glGetIntegerv(GL_DRAW_BUFFER, &v[8]);
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len,
                        "%s max=%d %x %x %x %x %x %x %x %x draw=%x err=%x\n", what, max, v[0],
                        v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], glGetError());
}

static void read_attachment(FILE *out, const char *name, GLenum att, unsigned char *rb)
{
    glReadBuffer(att);
    glReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_BYTE, rb);
    sgl_image(out, name, FW, FH, 4, "RGBA", FW * 4, 1, rb);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    static unsigned char rb[FW * FH * 4];
    static const GLenum all3[3] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1,
                                   GL_COLOR_ATTACHMENT2};
    static const GLenum reordered[3] = {GL_COLOR_ATTACHMENT2, GL_NONE, GL_COLOR_ATTACHMENT0};
    GLuint progs[3], fbo, rbs[3], tex;
    int i;

    progs[0] = frag_program(FS_ALL);
    progs[1] = frag_program(FS_COLOR);
    progs[2] = frag_program(FS_SOME);

    glGenFramebuffers(1, &fbo);
    glGenRenderbuffers(3, rbs);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, FW, FH, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glBindTexture(GL_TEXTURE_2D, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    for (i = 0; i < 2; i++) {
        glBindRenderbuffer(GL_RENDERBUFFER, rbs[i]);
        glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, FW, FH);
    }
    glBindRenderbuffer(GL_RENDERBUFFER, rbs[2]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, FW, FH);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rbs[0]);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, tex, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_RENDERBUFFER, rbs[1]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rbs[2]);
    SGL_CHECK(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
    note_buffers("fbo_initial");

    /* every program into three buffers */
    glDrawBuffers(3, all3);
    note("draw_buffers_3");
    note_buffers("fbo_three");
    frag_each_program(progs, 2, 5);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(progs[0]);
    frag_random_tris(3);
    glDisable(GL_BLEND);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    glUseProgram(progs[1]);
    frag_random_tris(3);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    read_attachment(out, "first_0", GL_COLOR_ATTACHMENT0, rb);
    read_attachment(out, "first_1", GL_COLOR_ATTACHMENT1, rb);
    read_attachment(out, "first_2", GL_COLOR_ATTACHMENT2, rb);

    /* another order, with GL_NONE, after a scissored clear */
    glDrawBuffers(3, reordered);
    note("draw_buffers_reordered");
    note_buffers("fbo_reordered");
    glEnable(GL_SCISSOR_TEST);
    glScissor(10, 8, 50, 40);
    glClearColor(0.9f, 0.5f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glUseProgram(progs[0]);
    frag_random_tris(4);
    glUseProgram(progs[2]);
    frag_random_tris(3);
    read_attachment(out, "second_0", GL_COLOR_ATTACHMENT0, rb);
    read_attachment(out, "second_1", GL_COLOR_ATTACHMENT1, rb);
    read_attachment(out, "second_2", GL_COLOR_ATTACHMENT2, rb);

    /* the texture attachment sampled in the window afterwards */
    glUseProgram(0);
    glDrawBuffer(GL_COLOR_ATTACHMENT0);
    note_buffers("fbo_single");

    /* errors, the object bound; then the window */
    {
        static const GLenum e[9] = {
            GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2,
            GL_COLOR_ATTACHMENT3, GL_COLOR_ATTACHMENT4, GL_COLOR_ATTACHMENT5,
            GL_COLOR_ATTACHMENT6, GL_COLOR_ATTACHMENT7, GL_NONE};
        static const struct {
            const char *name;
            int window, n;
            GLenum b[2];
        } calls[] = {
            {"back", 0, 2, {GL_BACK, GL_COLOR_ATTACHMENT1}},
            {"front_and_back", 0, 2, {GL_COLOR_ATTACHMENT0, GL_FRONT_AND_BACK}},
            {"duplicate", 0, 2, {GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT1}},
            {"attachment8", 0, 2, {GL_COLOR_ATTACHMENT8, GL_NONE}},
            {"front_left_on_fbo", 0, 2, {GL_FRONT_LEFT, GL_NONE}},
            {"bogus", 0, 2, {GL_NONE, GL_TEXTURE_2D}},
            {"none_twice", 0, 2, {GL_NONE, GL_NONE}},
            {"window_front_left", 1, 2, {GL_FRONT_LEFT, GL_NONE}},
            {"window_attachment", 1, 1, {GL_COLOR_ATTACHMENT0, 0}},
            {"window_front_right", 1, 1, {GL_FRONT_RIGHT, 0}},
            {"window_aux0", 1, 1, {GL_AUX0, 0}},
            {"window_back_left", 1, 1, {GL_BACK_LEFT, 0}},
            {"window_front", 1, 1, {GL_FRONT, 0}},
            {"window_duplicate", 1, 2, {GL_FRONT_LEFT, GL_FRONT_LEFT}},
        };
        unsigned k;
        glDrawBuffers(-1, e);
        note("n_negative");
        glDrawBuffers(9, e);
        note("n_nine");
        for (k = 0; k < sizeof calls / sizeof calls[0]; k++) {
            if (calls[k].window && k > 0 && !calls[k - 1].window) {
                note_buffers("fbo_after_errors");
                glDrawBuffers(8, e);
                note("eight");
                note_buffers("fbo_eight");
                glDrawBuffers(0, e);
                note("zero");
                note_buffers("fbo_zero");
                glBindFramebuffer(GL_FRAMEBUFFER, 0);
                note_buffers("window_initial");
            }
            glDrawBuffers(calls[k].n, calls[k].b);
            note(calls[k].name);
            note_buffers(calls[k].name);
        }
        glDrawBuffer(GL_FRONT_LEFT);
        glPushAttrib(GL_COLOR_BUFFER_BIT);
        glDrawBuffers(1, e + 8);
        glPopAttrib();
        note_buffers("window_popped");
    }
    sgl_text(out, "log", "%s", log_buf);

    /* the window: gl_FragData[1..] go nowhere; then the texture drawn into */
    frag_each_program(progs, 3, 4);
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glColor4f(1, 1, 1, 1);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0); glVertex2f(0, -1);
    glTexCoord2f(1, 0); glVertex2f(1, -1);
    glTexCoord2f(1, 1); glVertex2f(1, 0);
    glTexCoord2f(0, 1); glVertex2f(0, 0);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    return frag_end(out, "end", buf, ctx);
}
