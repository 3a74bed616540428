/* fbo_depth_big: a 1024x1024 GL_DEPTH_COMPONENT24 texture (a shadow map's size) as the
 * only attachment of a framebuffer object, drawn into and written back when the object is
 * unbound: large depth images are written back on two threads (context::fbo_image), so
 * every row of both halves is compared here.
 * - Slanted triangles over the whole map (each row's depths differ), glClear'd first.
 * - The texture read back with glGetTexImage as GL_UNSIGNED_INT after the unbind, in
 *   full, and again after a second pass that only touches the top rows.
 * - The map sampled with GL_TEXTURE_COMPARE_MODE onto the window (64x64). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define S 1024
#define W 64
#define H 64

static unsigned int z[S * S];
static unsigned char px[W * H * 4];

static void errs(FILE *out, const char *name)
{
    sgl_text(out, name, "0x%x", glGetError());
}

static void scene(float lift)
{
    glBegin(GL_TRIANGLES);
    glVertex3f(-1.0f, -1.0f, -0.9f + lift);
    glVertex3f(1.0f, -1.0f, 0.2f);
    glVertex3f(-1.0f, 1.0f, 0.8f - lift);
    glVertex3f(1.0f, 1.0f, -0.7f);
    glVertex3f(-1.0f, 1.0f, 0.6f);
    glVertex3f(1.0f, -1.0f, 0.1f + lift);
    /* a narrow sliver across the middle rows, nearer */
    glVertex3f(-1.0f, -0.02f, -0.95f);
    glVertex3f(1.0f, 0.01f, -0.5f);
    glVertex3f(-0.3f, 0.03f, -0.99f);
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    GLuint tex, fbo;

    SGL_CHECK(ctx && buf && OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, S, S, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, tex, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    sgl_text(out, "status", "0x%x", glCheckFramebufferStatus(GL_FRAMEBUFFER));

    /* the first pass over the whole map */
    glViewport(0, 0, S, S);
    glEnable(GL_DEPTH_TEST);
    glClearDepth(0.75);
    glClear(GL_DEPTH_BUFFER_BIT);
    scene(0.0f);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, z);
    sgl_data(out, "map1", sizeof z, z);
    errs(out, "map1_err");

    /* a second pass that only reaches the top rows (the scissor) */
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, S - 40, S, 40);
    glDepthFunc(GL_ALWAYS);
    scene(0.3f);
    glDisable(GL_SCISSOR_TEST);
    glDepthFunc(GL_LESS);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, z);
    sgl_data(out, "map2", sizeof z, z);
    errs(out, "map2_err");

    /* the map compared against a slanted quad's depth on the window */
    glViewport(0, 0, W, H);
    glDisable(GL_DEPTH_TEST);
    glClearColor(0.2f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
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
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_image(out, "shadow", W, H, 4, "RGBA", W * 4, 1, px);
    errs(out, "shadow_err");

    glDeleteFramebuffers(1, &fbo);
    glDeleteTextures(1, &tex);
    OSMesaDestroyContext(ctx);
    free(buf);
    sgl_close(out);
    return 0;
}
