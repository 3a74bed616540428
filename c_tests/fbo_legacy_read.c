/* fbo_legacy_read: glReadPixels from framebuffer objects whose colour image is a
 * luminance, intensity, luminance-alpha or alpha texture or renderbuffer (renderable
 * in the compatibility profile).  Mesa rebases luminance and intensity images to
 * (L, 0, 0, 1) and luminance-alpha ones to (L, 0, 0, A) before converting to the
 * requested format (piglit's getteximage-luminance), so GL_RGBA, GL_RGB, GL_LUMINANCE,
 * GL_LUMINANCE_ALPHA, GL_ALPHA and a packed type are read here, from an uploaded image
 * and after drawing a coloured quad into it, as unsigned bytes and floats. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 8
#define H 8
#define S 4

static void read_all(FILE *out, const char *tag)
{
    static const struct {
        GLenum format;
        const char *name;
        int comps;
    } fmts[] = {{GL_RGBA, "rgba", 4},          {GL_RGB, "rgb", 3},
                {GL_LUMINANCE, "l", 1},        {GL_LUMINANCE_ALPHA, "la", 2},
                {GL_ALPHA, "a", 1},            {GL_RED, "r", 1},
                {GL_GREEN, "g", 1}};
    char name[96];
    for (unsigned i = 0; i < sizeof fmts / sizeof fmts[0]; i++) {
        unsigned char ub[S * S * 4];
        float fl[S * S * 4];
        memset(ub, 0xcd, sizeof ub);
        memset(fl, 0xcd, sizeof fl);
        glReadPixels(0, 0, S, S, fmts[i].format, GL_UNSIGNED_BYTE, ub);
        snprintf(name, sizeof name, "%s_%s_ubyte_err%x", tag, fmts[i].name, glGetError());
        sgl_data(out, name, (size_t)(S * S * fmts[i].comps), ub);
        glReadPixels(0, 0, S, S, fmts[i].format, GL_FLOAT, fl);
        snprintf(name, sizeof name, "%s_%s_float_err%x", tag, fmts[i].name, glGetError());
        sgl_data(out, name, sizeof(float) * (size_t)(S * S * fmts[i].comps), fl);
    }
    {
        unsigned short p[S * S];
        memset(p, 0xcd, sizeof p);
        glReadPixels(0, 0, S, S, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, p);
        snprintf(name, sizeof name, "%s_rgba4444_err%x", tag, glGetError());
        sgl_data(out, name, sizeof p, p);
    }
    {
        /* with a scale and bias: the rebase comes first */
        unsigned char ub[S * S * 4];
        glPixelTransferf(GL_GREEN_BIAS, 0.25f);
        glPixelTransferf(GL_RED_SCALE, 0.5f);
        glReadPixels(0, 0, S, S, GL_RGBA, GL_UNSIGNED_BYTE, ub);
        snprintf(name, sizeof name, "%s_rgba_transfer_err%x", tag, glGetError());
        sgl_data(out, name, sizeof ub, ub);
        glPixelTransferf(GL_GREEN_BIAS, 0.0f);
        glPixelTransferf(GL_RED_SCALE, 1.0f);
    }
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    static const GLenum internals[] = {GL_LUMINANCE8, GL_INTENSITY8, GL_LUMINANCE8_ALPHA8,
                                       GL_ALPHA8, GL_LUMINANCE, GL_RGB8};
    static const char *names[] = {"l8", "i8", "la8", "a8", "l", "rgb8"};
    unsigned char img[S * S * 4];
    GLuint fbo, tex, rb;
    char tag[64];
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    for (int i = 0; i < S * S * 4; i++)
        img[i] = (unsigned char)(i * 29 + 7);

    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    for (unsigned k = 0; k < sizeof internals / sizeof internals[0]; k++) {
        /* a texture image, uploaded as RGBA */
        glGenTextures(1, &tex);
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)internals[k], S, S, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     img);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
        snprintf(tag, sizeof tag, "tex_%s_status%x", names[k],
                 glCheckFramebufferStatus(GL_FRAMEBUFFER));
        read_all(out, tag);

        /* drawn into: a quad of a colour with distinct channels */
        glViewport(0, 0, S, S);
        glColor4f(0.2f, 0.6f, 0.8f, 0.4f);
        glBegin(GL_QUADS);
        glVertex2f(-1, -1);
        glVertex2f(0.5f, -1);
        glVertex2f(0.5f, 0.5f);
        glVertex2f(-1, 0.5f);
        glEnd();
        snprintf(tag, sizeof tag, "tex_%s_drawn", names[k]);
        read_all(out, tag);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, 0, 0);
        glDeleteTextures(1, &tex);

        /* a renderbuffer of the same format, cleared and drawn into */
        glGenRenderbuffers(1, &rb);
        glBindRenderbuffer(GL_RENDERBUFFER, rb);
        glRenderbufferStorage(GL_RENDERBUFFER, internals[k], S, S);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
        glClearColor(0.7f, 0.1f, 0.3f, 0.9f);
        glClear(GL_COLOR_BUFFER_BIT);
        glColor4f(0.9f, 0.5f, 0.1f, 0.3f);
        glBegin(GL_TRIANGLES);
        glVertex2f(-1, -1);
        glVertex2f(1, -1);
        glVertex2f(-1, 1);
        glEnd();
        snprintf(tag, sizeof tag, "rb_%s_status%x", names[k],
                 glCheckFramebufferStatus(GL_FRAMEBUFFER));
        read_all(out, tag);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, 0);
        glDeleteRenderbuffers(1, &rb);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);

    glFinish();
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
