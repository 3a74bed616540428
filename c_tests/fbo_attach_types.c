/* fbo_attach_types: the component type, sizes and encoding of every depth and
 * stencil attachment (window and objects, renderbuffers and textures, at each
 * attachment point), and glGetTexLevelParameter(GL_TEXTURE_DEPTH_TYPE), as text
 * compared with llvmpipe. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 8
#define H 8

static char log_buf[16384];
static int log_len;

static void att(const char *what, GLenum target, GLenum attachment)
{
    static const GLenum pnames[] = {GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE,
                                    GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE,
                                    GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE,
                                    GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE,
                                    GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING};
    int i;
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, "%s:", what);
    for (i = 0; i < 5; i++) {
        GLint v = -7;
        glGetFramebufferAttachmentParameteriv(target, attachment, pnames[i], &v);
        log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, " %x/%x", v,
                            glGetError());
    }
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, "\n");
}

/* A renderbuffer of `format` at `point` of a fresh framebuffer; the three points
   queried. */
static void rb_case(const char *what, GLenum format, GLenum point)
{
    GLuint fb, rb;
    char name[64];
    glGenFramebuffers(1, &fb);
    glGenRenderbuffers(1, &rb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorage(GL_RENDERBUFFER, format, W, H);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, point, GL_RENDERBUFFER, rb);
    snprintf(name, sizeof name, "%s depth", what);
    att(name, GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT);
    snprintf(name, sizeof name, "%s stencil", what);
    att(name, GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT);
    if (point == GL_DEPTH_STENCIL_ATTACHMENT) {
        snprintf(name, sizeof name, "%s depth_stencil", what);
        att(name, GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fb);
    glDeleteRenderbuffers(1, &rb);
}

static void tex_case(const char *what, GLenum internal, GLenum format, GLenum type,
                     GLenum point)
{
    GLuint fb, tex;
    GLint v = -7, size = -7;
    char name[64];
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, internal, W, H, 0, format, type, NULL);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_TYPE, &v);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &size);
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len,
                        "%s tex depth_type=%x size=%d err=%x\n", what, v, size, glGetError());
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 3, GL_TEXTURE_DEPTH_TYPE, &v);
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len,
                        "%s unspecified level depth_type=%x err=%x\n", what, v, glGetError());
    if (point) {
        glGenFramebuffers(1, &fb);
        glBindFramebuffer(GL_FRAMEBUFFER, fb);
        glFramebufferTexture2D(GL_FRAMEBUFFER, point, GL_TEXTURE_2D, tex, 0);
        snprintf(name, sizeof name, "%s tex depth", what);
        att(name, GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT);
        snprintf(name, sizeof name, "%s tex stencil", what);
        att(name, GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &fb);
    }
    glDeleteTextures(1, &tex);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    OSMesaContext ctx2 = OSMesaCreateContextExt(OSMESA_RGBA, 0, 8, 0, NULL);
    OSMesaContext ctx3 = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    GLint v = -7;

    SGL_CHECK(ctx && ctx2 && ctx3 && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    att("window24_8 depth", GL_FRAMEBUFFER, GL_DEPTH);
    att("window24_8 stencil", GL_FRAMEBUFFER, GL_STENCIL);
    att("window24_8 back", GL_FRAMEBUFFER, GL_BACK_LEFT);

    rb_case("D24S8", GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL_ATTACHMENT);
    rb_case("D32FS8", GL_DEPTH32F_STENCIL8, GL_DEPTH_STENCIL_ATTACHMENT);
    rb_case("D24S8 at stencil", GL_DEPTH24_STENCIL8, GL_STENCIL_ATTACHMENT);
    rb_case("D32FS8 at stencil", GL_DEPTH32F_STENCIL8, GL_STENCIL_ATTACHMENT);
    rb_case("D24S8 at depth", GL_DEPTH24_STENCIL8, GL_DEPTH_ATTACHMENT);
    rb_case("S8", GL_STENCIL_INDEX8, GL_STENCIL_ATTACHMENT);
    rb_case("D16", GL_DEPTH_COMPONENT16, GL_DEPTH_ATTACHMENT);
    rb_case("D24", GL_DEPTH_COMPONENT24, GL_DEPTH_ATTACHMENT);
    rb_case("D32F", GL_DEPTH_COMPONENT32F, GL_DEPTH_ATTACHMENT);

    tex_case("D24S8", GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8,
             GL_DEPTH_STENCIL_ATTACHMENT);
    tex_case("D32FS8", GL_DEPTH32F_STENCIL8, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV,
             GL_DEPTH_STENCIL_ATTACHMENT);
    tex_case("D16", GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT,
             GL_DEPTH_ATTACHMENT);
    tex_case("D24", GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT,
             GL_DEPTH_ATTACHMENT);
    tex_case("D32F", GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, GL_DEPTH_ATTACHMENT);
    tex_case("DEPTH", GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT, GL_FLOAT, 0);
    tex_case("RGBA8", GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 0);
    tex_case("ALPHA", GL_ALPHA, GL_ALPHA, GL_UNSIGNED_BYTE, 0);
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_TYPE, &v);
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len,
                        "proxy depth_type=%x err=%x\n", v, glGetError());

    SGL_CHECK(OSMesaMakeCurrent(ctx2, buf, GL_UNSIGNED_BYTE, W, H));
    att("window0_8 depth", GL_FRAMEBUFFER, GL_DEPTH);
    att("window0_8 stencil", GL_FRAMEBUFFER, GL_STENCIL);
    SGL_CHECK(OSMesaMakeCurrent(ctx3, buf, GL_UNSIGNED_BYTE, W, H));
    att("window16 depth", GL_FRAMEBUFFER, GL_DEPTH);
    att("window16 stencil", GL_FRAMEBUFFER, GL_STENCIL);

    sgl_text(out, "queries", "%s", log_buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx3);
    OSMesaDestroyContext(ctx2);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
