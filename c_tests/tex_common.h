/*
 * tex_common.h - helpers shared by the texturing scenes (tex_*.c):
 * context creation, procedural textures, and the perspective ground plane.
 * Include after <GL/gl.h>, <GL/glext.h> (with GL_GLEXT_PROTOTYPES) and
 * "common.h".
 */
#ifndef SGL_TEX_COMMON_H
#define SGL_TEX_COMMON_H

#include <math.h>

/* An RGBA context with 24-bit depth, current on a fresh w x h buffer. */
static inline OSMesaContext sgl_tex_context(int w, int h, unsigned char **buf)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    SGL_CHECK(ctx != NULL);
    *buf = malloc((size_t)w * (size_t)h * 4);
    SGL_CHECK(*buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, *buf, GL_UNSIGNED_BYTE, w, h));
    return ctx;
}

/* An RGBA checkerboard of w x h texels with cells of cw x ch texels;
 * colours a and b (RGBA bytes).  Caller frees. */
static inline unsigned char *sgl_checker(int w, int h, int cw, int ch,
                                         const unsigned char *a,
                                         const unsigned char *b)
{
    unsigned char *p = malloc((size_t)w * (size_t)h * 4);
    int x, y;
    SGL_CHECK(p != NULL);
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++)
            memcpy(p + 4 * (y * w + x), ((x / cw + y / ch) & 1) ? b : a, 4);
    return p;
}

/* Box-filters an RGBA image of w x h into (w/2 or 1) x (h/2 or 1), rounding
 * up, then multiplies RGB by tint/255 (so each level is recognisable). For odd
 * sizes the last row/column is dropped, as a simple user mipmapper would. */
static inline unsigned char *sgl_halve(const unsigned char *src, int w, int h,
                                       const unsigned char *tint)
{
    int nw = w > 1 ? w / 2 : 1, nh = h > 1 ? h / 2 : 1;
    unsigned char *p = malloc((size_t)nw * (size_t)nh * 4);
    int x, y, c;
    SGL_CHECK(p != NULL);
    for (y = 0; y < nh; y++)
        for (x = 0; x < nw; x++)
            for (c = 0; c < 4; c++) {
                int x0 = w > 1 ? 2 * x : 0, x1 = w > 1 ? 2 * x + 1 : 0;
                int y0 = h > 1 ? 2 * y : 0, y1 = h > 1 ? 2 * y + 1 : 0;
                int s = src[4 * (y0 * w + x0) + c] + src[4 * (y0 * w + x1) + c] +
                        src[4 * (y1 * w + x0) + c] + src[4 * (y1 * w + x1) + c];
                int v = (s + 2) / 4;
                if (c < 3 && tint)
                    v = (v * tint[c] + 127) / 255;
                p[4 * (y * nw + x) + c] = (unsigned char)v;
            }
    return p;
}

/* Uploads level 0 (w x h RGBA) and every lower level by hand, box-filtered
 * and tinted, to the bound GL_TEXTURE_2D.  Returns the number of levels. */
static inline int sgl_upload_mips(const unsigned char *level0, int w, int h)
{
    static const unsigned char tints[12][4] = {
        {255, 255, 255, 255}, {255, 200, 200, 255}, {200, 255, 200, 255},
        {200, 200, 255, 255}, {255, 255, 160, 255}, {160, 255, 255, 255},
        {255, 160, 255, 255}, {230, 230, 230, 255}, {255, 120, 120, 255},
        {120, 255, 120, 255}, {120, 120, 255, 255}, {255, 255, 255, 255},
    };
    unsigned char *cur = malloc((size_t)w * (size_t)h * 4);
    int level = 0;
    SGL_CHECK(cur != NULL);
    memcpy(cur, level0, (size_t)w * (size_t)h * 4);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (;;) {
        unsigned char *next;
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, w, h, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, cur);
        if (w == 1 && h == 1)
            break;
        next = sgl_halve(cur, w, h, tints[(level + 1) % 12]);
        free(cur);
        cur = next;
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
        level++;
    }
    free(cur);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    return level + 1;
}

/* Perspective projection and modelview for the ground plane, given the
 * viewport's aspect ratio. */
static inline void sgl_ground_view(double aspect)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.53 * aspect, 0.53 * aspect, -0.53, 0.53, 0.71, 300.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glRotatef(7.3f, 1.0f, 0.0f, 0.0f);
    glRotatef(13.7f, 0.0f, 1.0f, 0.0f);
    glTranslatef(0.37f, -1.13f, 0.0f);
}

/* The classic aliasing demo: a large textured ground quad running to the
 * horizon; texture coordinates repeat every `period` world units. */
static inline void sgl_ground_plane(float period)
{
    static const float xs[2] = {-120.3f, 119.7f};
    static const float zs[2] = {2.1f, -250.9f};
    glBegin(GL_QUADS);
    glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    glTexCoord2f(xs[0] / period, zs[0] / period);
    glVertex3f(xs[0], 0.0f, zs[0]);
    glTexCoord2f(xs[1] / period, zs[0] / period);
    glVertex3f(xs[1], 0.0f, zs[0]);
    glTexCoord2f(xs[1] / period, zs[1] / period);
    glVertex3f(xs[1], 0.0f, zs[1]);
    glTexCoord2f(xs[0] / period, zs[1] / period);
    glVertex3f(xs[0], 0.0f, zs[1]);
    glEnd();
}

/* Orthographic window coordinates for 2D cells. */
static inline void sgl_ortho(int w, int h)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, (double)w, 0.0, (double)h, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* A textured quad from (x0,y0) to (x1,y1) with texcoords (s0,t0)..(s1,t1). */
static inline void sgl_tex_quad(float x0, float y0, float x1, float y1,
                                float s0, float t0, float s1, float t1)
{
    glBegin(GL_QUADS);
    glTexCoord2f(s0, t0);
    glVertex2f(x0, y0);
    glTexCoord2f(s1, t0);
    glVertex2f(x1, y0);
    glTexCoord2f(s1, t1);
    glVertex2f(x1, y1);
    glTexCoord2f(s0, t1);
    glVertex2f(x0, y1);
    glEnd();
}

#endif
