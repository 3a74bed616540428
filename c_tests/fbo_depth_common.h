/*
 * fbo_depth_common.h - helpers shared by the depth-format framebuffer scenes
 * (fbo_depth32.c, fbo_depth_float.c): renderbuffers, the error line, a depth
 * texture as the depth attachment, that texture sampled into the window, and depth
 * copied into a texture and read back.
 * Include after <GL/gl.h>, <GL/glext.h> (with GL_GLEXT_PROTOTYPES) and
 * "common.h", with W and H defined as the scene's size.
 */
#ifndef SGL_FBO_DEPTH_COMMON_H
#define SGL_FBO_DEPTH_COMMON_H

/* The pending GL error as a text line `name`. */
static void errs(FILE *out, const char *name)
{
    GLenum e = glGetError();
    sgl_text(out, name, "0x%x", e);
}

/* A new W x H renderbuffer of `fmt` with `samples` samples, left bound. */
static GLuint rbuf(GLenum fmt, int samples)
{
    GLuint rb;
    glGenRenderbuffers(1, &rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, fmt, W, H);
    return rb;
}

/* Framebuffer `f` bound with an RGBA8 colour renderbuffer and the bound 2D depth
 * texture `tex` (filtered LINEAR, clamped to its edge) as its depth attachment; its
 * status as the text line `status`. */
static void depth_tex_fbo(FILE *out, const char *status, GLuint f, GLuint tex)
{
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glBindFramebuffer(GL_FRAMEBUFFER, f);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                              rbuf(GL_RGBA8, 0));
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, tex, 0);
    sgl_text(out, status, "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
}

/* glCopyTexImage2D of the w x h pixels at (10, 5) of the read buffer into the bound 2D
 * texture as `ifmt`, read back by glGetTexImage as GL_DEPTH_COMPONENT of `type` (4
 * bytes a value) into `dst` and written as the data line `name`. */
static void copy_depth(FILE *out, const char *name, GLenum ifmt, GLenum type, int w, int h,
                       void *dst)
{
    glCopyTexImage2D(GL_TEXTURE_2D, 0, ifmt, 10, 5, w, h, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, type, dst);
    sgl_data(out, name, (size_t)w * (size_t)h * 4, dst);
}

/* A quad over x0..x1 by 0..y1 with texture coordinates s, t from (0, 0) to (1, t1) and r
 * from r0 on the left to r1 on the right. */
static void quad_r(float x0, float x1, float y1, float t1, float r0, float r1)
{
    glBegin(GL_QUADS);
    glTexCoord3f(0.0f, 0.0f, r0);
    glVertex2f(x0, 0);
    glTexCoord3f(1.0f, 0.0f, r1);
    glVertex2f(x1, 0);
    glTexCoord3f(1.0f, t1, r1);
    glVertex2f(x1, y1);
    glTexCoord3f(0.0f, t1, r0);
    glVertex2f(x0, y1);
    glEnd();
}

/* The bound depth texture drawn into the window (depth test off, W x H ortho):
 * as luminance (REPLACE) on the left half; compared with GL_LEQUAL on the right
 * half, r from r0 on the left to r1 on the right edge; then compared with
 * GL_GREATER at r = rg on the right half's lower left quarter (NEAREST filtered
 * when `nearest`). Compare mode and filters are left as the last quad drew. */
static void sample_depth_tex(float r0, float r1, float rg, int nearest)
{
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glClear(GL_COLOR_BUFFER_BIT);
    quad_r(0, W / 2, H, 1.0f, 0.0f, 0.0f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    quad_r(W / 2, W, H, 1.0f, r0, r1);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GREATER);
    if (nearest) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    quad_r(W / 2, W * 3 / 4, H / 4, 0.5f, rg, rg);
}

#endif
