/*
 * fbo_common.h - the framebuffer object the FBO scenes (fbo_render.c, fbo_lend.c)
 * start from. Include after <GL/gl.h>, <GL/glext.h> (with GL_GLEXT_PROTOTYPES)
 * and "common.h".
 */
#ifndef SGL_FBO_COMMON_H
#define SGL_FBO_COMMON_H

/* Framebuffer object `f` bound, with renderbuffer `color` given RGBA8 storage as its
 * colour attachment 0 and renderbuffer `ds` DEPTH24_STENCIL8 storage as its depth and
 * stencil attachment, both w x h; `ds` is left bound as the renderbuffer. */
static void sgl_fbo_rgba8_ds(GLuint f, GLuint color, GLuint ds, int w, int h)
{
    glBindFramebuffer(GL_FRAMEBUFFER, f);
    glBindRenderbuffer(GL_RENDERBUFFER, color);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    glBindRenderbuffer(GL_RENDERBUFFER, ds);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, ds);
}

#endif
