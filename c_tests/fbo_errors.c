/* fbo_errors: the completeness rules, the errors of the framebuffer-object calls, and
 * the attachment and renderbuffer queries, as text compared with llvmpipe.  Every
 * call that must fail is followed by a check that nothing it could have changed did:
 * the bindings, the attachment, and the window's pixels (drawn last). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 16
#define H 16

static char log_buf[16384];
static int log_len;

static void note(const char *what)
{
    GLenum e = glGetError();
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, "%s=%x\n", what, e);
}

static void status(const char *what)
{
    GLenum s = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, "%s status=%x err=%x\n",
                        what, s, glGetError());
}

static void geti(const char *what, GLenum pname)
{
    GLint v = -7;
    glGetIntegerv(pname, &v);
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, "%s=%d err=%x\n", what,
                        v, glGetError());
}

static void att(const char *what, GLenum attachment, GLenum pname)
{
    GLint v = -7;
    glGetFramebufferAttachmentParameteriv(GL_FRAMEBUFFER, attachment, pname, &v);
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, "%s=%x err=%x\n", what,
                        v, glGetError());
}

static void rbq(const char *what, GLenum pname)
{
    GLint v = -7;
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, pname, &v);
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, "%s=%x err=%x\n", what,
                        v, glGetError());
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    unsigned char px[4];
    GLuint fb[3], rb[4], tex[3];

    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    glClearColor(0.5f, 0.25f, 0.75f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    /* limits and the window */
    geti("max_renderbuffer_size", GL_MAX_RENDERBUFFER_SIZE);
    geti("max_color_attachments", GL_MAX_COLOR_ATTACHMENTS);
    geti("fb_binding", GL_FRAMEBUFFER_BINDING);
    geti("read_fb_binding", GL_READ_FRAMEBUFFER_BINDING);
    status("window");
    att("window_type", GL_BACK_LEFT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
    att("window_depth_type", GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
    att("window_depth_size", GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE);
    att("window_stencil_size", GL_STENCIL, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE);
    att("window_red_size", GL_BACK_LEFT, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE);

    /* names and bindings */
    glGenFramebuffers(3, fb);
    glGenRenderbuffers(4, rb);
    glGenTextures(3, tex);
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, "is_fb_unbound=%d\n",
                        glIsFramebuffer(fb[0]));
    glBindFramebuffer(GL_FRAMEBUFFER, 1234);
    note("bind_ungenerated");
    geti("fb_binding_after_bad", GL_FRAMEBUFFER_BINDING);
    glBindFramebuffer(0x1234, fb[0]);
    note("bind_bad_target");
    glCheckFramebufferStatus(GL_TEXTURE_2D);
    note("status_bad_target");
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    note("attach_to_window");
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    note("bind");
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, "is_fb_bound=%d\n",
                        glIsFramebuffer(fb[0]));
    status("empty");
    glClear(GL_COLOR_BUFFER_BIT);
    note("clear_incomplete");
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    note("read_incomplete");
    glDrawArrays(GL_TRIANGLES, 0, 3);
    note("draw_incomplete");

    /* renderbuffer storage errors */
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 4, 4);
    note("storage_unbound");
    glBindRenderbuffer(GL_RENDERBUFFER, 999);
    note("bind_rb_ungenerated");
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    note("attach_rb_never_bound");
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, "is_rb=%d\n",
                        glIsRenderbuffer(rb[0]));
    rbq("rb_initial_format", GL_RENDERBUFFER_INTERNAL_FORMAT);
    rbq("rb_initial_width", GL_RENDERBUFFER_WIDTH);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_LUMINANCE8, 4, 4);
    note("storage_bad_format");
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, -1, 4);
    note("storage_negative");
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, 16385, 4);
    note("storage_too_big");
    glRenderbufferStorage(GL_TEXTURE_2D, GL_RGBA8, 4, 4);
    note("storage_bad_target");
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 9, GL_RGBA8, 4, 4);
    note("storage_too_many_samples");
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, -1, GL_RGBA8, 4, 4);
    note("storage_negative_samples");
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    note("attach_rb");
    status("zero_size");
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGB8, 8, 6);
    note("storage");
    status("complete");
    rbq("rb_format", GL_RENDERBUFFER_INTERNAL_FORMAT);
    rbq("rb_width", GL_RENDERBUFFER_WIDTH);
    rbq("rb_height", GL_RENDERBUFFER_HEIGHT);
    rbq("rb_red", GL_RENDERBUFFER_RED_SIZE);
    rbq("rb_alpha", GL_RENDERBUFFER_ALPHA_SIZE);
    rbq("rb_depth", GL_RENDERBUFFER_DEPTH_SIZE);
    rbq("rb_samples", GL_RENDERBUFFER_SAMPLES);
    rbq("rb_bad_pname", GL_TEXTURE_WIDTH);
    geti("alpha_bits_rgb8", GL_ALPHA_BITS);
    geti("red_bits_rgb8", GL_RED_BITS);

    /* attachment errors */
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + 8, GL_RENDERBUFFER, rb[0]);
    note("attach_beyond_max");
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_TEXTURE_2D, GL_RENDERBUFFER, rb[0]);
    note("attach_bad_point");
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, rb[0]);
    note("attach_bad_rb_target");
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, 777, 0);
    note("attach_no_texture");
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_CUBE_MAP_POSITIVE_X,
                           tex[0], 0);
    note("attach_wrong_textarget");
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, tex[0], -1);
    note("attach_negative_level");
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, tex[0], 20);
    note("attach_level_too_big");
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, tex[0], 3);
    note("attach_missing_level");
    status("missing_level");
    att("missing_level_type", GL_COLOR_ATTACHMENT1, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
    att("missing_level_level", GL_COLOR_ATTACHMENT1, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, tex[0], 0);
    status("two_colors_different_sizes");
    att("tex_type", GL_COLOR_ATTACHMENT1, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
    att("tex_name_ok", GL_COLOR_ATTACHMENT1, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME);
    att("tex_face", GL_COLOR_ATTACHMENT1, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_CUBE_MAP_FACE);
    att("rb_type", GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
    att("rb_level", GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL);
    att("none_type", GL_COLOR_ATTACHMENT2, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
    att("none_name", GL_COLOR_ATTACHMENT2, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME);
    att("none_level", GL_COLOR_ATTACHMENT2, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL);
    att("none_red", GL_COLOR_ATTACHMENT2, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE);
    att("bad_point", GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
    att("rb_red", GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE);
    att("rb_component_type", GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE);
    att("rb_encoding", GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING);

    /* wrong kinds of image */
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, 8, 6);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_RENDERBUFFER, rb[1]);
    status("depth_as_color");
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT2, GL_RENDERBUFFER, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[0]);
    status("color_as_depth");
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
    status("with_depth");
    att("depth_size", GL_DEPTH_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE);
    geti("depth_bits", GL_DEPTH_BITS);
    geti("stencil_bits_none", GL_STENCIL_BITS);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[2]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_STENCIL_INDEX8, 8, 6);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[2]);
    status("separate_depth_stencil");
    att("depth_stencil_differ", GL_DEPTH_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[3]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, 8, 6);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, rb[3]);
    status("packed_depth_stencil");
    att("ds_stencil_size", GL_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE);
    att("ds_depth_size", GL_DEPTH_STENCIL_ATTACHMENT, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE);

    /* draw and read buffers */
    glDrawBuffer(GL_BACK);
    note("draw_buffer_back");
    glDrawBuffer(GL_COLOR_ATTACHMENT0 + 8);
    note("draw_buffer_beyond");
    glDrawBuffer(GL_COLOR_ATTACHMENT1);
    note("draw_buffer_1");
    geti("draw_buffer", GL_DRAW_BUFFER);
    glReadBuffer(GL_FRONT);
    note("read_buffer_front");
    glReadBuffer(GL_NONE);
    note("read_buffer_none");
    glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    note("read_none");
    geti("read_buffer", GL_READ_BUFFER);
    glReadBuffer(GL_COLOR_ATTACHMENT0);

    /* blit errors */
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, 0x1, GL_NEAREST);
    note("blit_bad_mask");
    glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, GL_COLOR_BUFFER_BIT, GL_LINEAR_MIPMAP_LINEAR);
    note("blit_bad_filter");
    glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, GL_DEPTH_BUFFER_BIT, GL_LINEAR);
    note("blit_depth_linear");
    glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, GL_STENCIL_BUFFER_BIT, GL_LINEAR);
    note("blit_stencil_linear");
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[1]);
    glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    note("blit_to_incomplete");
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[0]);
    glBlitFramebuffer(0, 0, 4, 4, 0, 0, 4, 4, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    note("blit_ok");
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);

    /* deleting bound objects */
    glDeleteRenderbuffers(1, &rb[0]);
    note("delete_attached_rb");
    att("deleted_rb_type", GL_COLOR_ATTACHMENT0, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
    geti("rb_binding", GL_RENDERBUFFER_BINDING);
    glDeleteTextures(1, &tex[0]);
    att("deleted_tex_type", GL_COLOR_ATTACHMENT1, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
    glDeleteFramebuffers(1, &fb[0]);
    note("delete_bound_fb");
    geti("fb_binding_after_delete", GL_FRAMEBUFFER_BINDING);
    geti("read_binding_after_delete", GL_READ_FRAMEBUFFER_BINDING);
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, "is_fb_deleted=%d\n",
                        glIsFramebuffer(fb[0]));

    /* inside glBegin/glEnd */
    glBegin(GL_POINTS);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
    glEnd();
    note("bind_in_begin");

    glFinish();
    sgl_text(out, "log", "%s", log_buf);
    sgl_image(out, "window", W, H, 4, "RGBA", W * 4, 1, buf);
    OSMesaDestroyContext(ctx);
    free(buf);
    sgl_close(out);
    return 0;
}
