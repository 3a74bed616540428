/* fbo_lend_depth: a 512x512 depth texture (1 MiB: large enough that softgl lends its
 * texels to the bound object's working copy instead of copying them back after each
 * pass) drawn into while bound, then looked at every other way while still bound.
 * - Three shadow-map passes (bind, clear, draw, unbind, sample with compare onto the
 *   window), as MuJoCo draws its shadows each frame.
 * - glGetTexImage while bound (the drawing must be in it), then more drawing, a
 *   glTexParameteri on the texture while bound, more drawing, read after the unbind.
 * - A feedback draw sampling the texture while it is attached, with colour and depth
 *   writes off (GL leaves what it samples undefined; nothing may change).
 * - glTexSubImage2D into the texture while bound, then a draw depth-tested against it.
 * - A second object sharing the texture, read through GL_READ_FRAMEBUFFER while the
 *   first is bound for drawing.
 * - glTexImage2D of the level while bound (new values), then drawing into it.
 * - The texture deleted while bound (the object loses its depth attachment). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define S 512
#define W 64
#define H 64
#define R 48

static unsigned int z[S * S];
static float zf[S * S];
static unsigned char px[W * H * 4];
static unsigned char big[R * R * 4];
static unsigned int zr[R * R];

static void errs(FILE *out, const char *name)
{
    sgl_text(out, name, "0x%x", glGetError());
}

static void tri(float x, float y, float s, float zn, float r, float g, float b)
{
    glBegin(GL_TRIANGLES);
    glColor3f(r, g, b);
    glVertex3f(x - s, y - s, zn);
    glVertex3f(x + s, y - 0.7f * s, -zn);
    glVertex3f(x + 0.2f * s, y + s, zn * 0.5f);
    glEnd();
}

/* glGetTexImage of the whole map as GL_UNSIGNED_INT */
static void map(FILE *out, const char *name)
{
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, z);
    sgl_data(out, name, sizeof z, z);
    errs(out, name);
}

/* the map compared against a slanted quad's depth on the window */
static void shadow(FILE *out, const char *name)
{
    glViewport(0, 0, W, H);
    glDisable(GL_DEPTH_TEST);
    glClearColor(0.2f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glBegin(GL_QUADS);
    glTexCoord3f(0.0f, 0.0f, 0.2f);
    glVertex2f(-1.0f, -1.0f);
    glTexCoord3f(1.0f, 0.0f, 0.5f);
    glVertex2f(1.0f, -1.0f);
    glTexCoord3f(1.0f, 1.0f, 0.8f);
    glVertex2f(1.0f, 1.0f);
    glTexCoord3f(0.0f, 1.0f, 0.5f);
    glVertex2f(-1.0f, 1.0f);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_image(out, name, W, H, 4, "RGBA", W * 4, 1, px);
    errs(out, name);
}

/* colour and depth of the R x R region at (x, y) of the read framebuffer */
static void region(FILE *out, const char *name, int x, int y, int color)
{
    if (color) {
        glReadPixels(x, y, R, R, GL_RGBA, GL_UNSIGNED_BYTE, big);
        sgl_image(out, name, R, R, 4, "RGBA", R * 4, 1, big);
    }
    glReadPixels(x, y, R, R, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, zr);
    sgl_data(out, name, sizeof zr, zr);
    errs(out, name);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    GLuint tex, a, b, color;
    int i;

    SGL_CHECK(ctx && buf && OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, S, S, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);

    glGenRenderbuffers(1, &color);
    glBindRenderbuffer(GL_RENDERBUFFER, color);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, S, S);
    glGenFramebuffers(1, &a);
    glBindFramebuffer(GL_FRAMEBUFFER, a);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, color);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, tex, 0);
    sgl_text(out, "status", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));

    /* three shadow passes, each cleared, drawn and sampled after the unbind */
    for (i = 0; i < 3; i++) {
        char name[32];
        glBindFramebuffer(GL_FRAMEBUFFER, a);
        glViewport(0, 0, S, S);
        glEnable(GL_DEPTH_TEST);
        glClearDepth(0.6 + 0.1 * i);
        glClearColor(0.0f, 0.1f * i, 0.3f, 1.0f);
        glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
        tri(-0.4f + 0.3f * i, -0.2f, 0.6f, -0.5f + 0.2f * i, 1.0f, 0.5f, 0.0f);
        tri(0.3f, 0.2f - 0.2f * i, 0.5f, 0.4f, 0.0f, 0.8f, 0.4f);
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        sprintf(name, "pass%d", i);
        shadow(out, name);
    }
    map(out, "map_after_passes");

    /* read directly while bound, then drawn around a touch of the texture */
    glBindFramebuffer(GL_FRAMEBUFFER, a);
    glViewport(0, 0, S, S);
    glEnable(GL_DEPTH_TEST);
    tri(0.0f, 0.0f, 0.7f, -0.8f, 0.2f, 0.2f, 1.0f);
    map(out, "map_while_bound");
    tri(-0.5f, 0.5f, 0.3f, -0.9f, 1.0f, 1.0f, 0.0f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
    tri(0.5f, -0.5f, 0.3f, -0.9f, 1.0f, 0.0f, 1.0f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    region(out, "touched", 100, 300, 1);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    map(out, "map_after_touch");

    /* a feedback draw that writes nothing */
    glBindFramebuffer(GL_FRAMEBUFFER, a);
    glViewport(0, 0, S, S);
    glEnable(GL_TEXTURE_2D);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    tri(0.0f, 0.0f, 0.9f, -0.99f, 1.0f, 1.0f, 1.0f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glDisable(GL_TEXTURE_2D);
    errs(out, "feedback_err");
    region(out, "after_feedback", 200, 200, 1);

    /* new depths put into the bound texture, then a draw tested against them */
    for (i = 0; i < R * R; i++)
        zf[i] = 0.05f + 0.0001f * (float)(i % 97);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 230, 240, R, R, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
    errs(out, "subimage_err");
    tri(-0.05f, 0.0f, 0.4f, -0.3f, 0.0f, 1.0f, 1.0f);
    region(out, "subimage", 220, 230, 1);

    /* the same texture read through a second object while the first draws */
    glGenFramebuffers(1, &b);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, b);
    glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, tex, 0);
    glReadBuffer(GL_NONE);
    sgl_text(out, "status_b", "0x%x", glCheckFramebufferStatus(GL_READ_FRAMEBUFFER));
    region(out, "read_b", 120, 140, 0);
    tri(-0.6f, -0.5f, 0.3f, -0.95f, 0.5f, 0.5f, 0.5f);
    region(out, "read_b_after_draw", 40, 40, 0);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, a);
    region(out, "read_a", 40, 40, 1);

    /* the level given new values while bound */
    for (i = 0; i < S * S; i++)
        zf[i] = 0.25f + 0.5f * (float)(i % S) / S;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, S, S, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                 zf);
    sgl_text(out, "status_redefined", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    tri(0.1f, 0.1f, 0.8f, 0.1f, 1.0f, 0.3f, 0.3f);
    region(out, "redefined", 250, 250, 1);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    map(out, "map_redefined");
    shadow(out, "shadow_redefined");

    /* deleted while bound: the object draws on without depth */
    glBindFramebuffer(GL_FRAMEBUFFER, a);
    glDeleteTextures(1, &tex);
    sgl_text(out, "status_deleted", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));
    tri(0.0f, 0.0f, 0.5f, 0.9f, 0.9f, 0.9f, 0.1f);
    glReadPixels(200, 200, R, R, GL_RGBA, GL_UNSIGNED_BYTE, big);
    sgl_image(out, "deleted", R, R, 4, "RGBA", R * 4, 1, big);
    errs(out, "deleted_err");

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &a);
    glDeleteFramebuffers(1, &b);
    glDeleteRenderbuffers(1, &color);
    OSMesaDestroyContext(ctx);
    free(buf);
    sgl_close(out);
    return 0;
}
