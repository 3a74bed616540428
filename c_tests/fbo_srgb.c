/* fbo_srgb: sRGB colour attachments and GL_FRAMEBUFFER_SRGB (ARB/EXT_framebuffer_sRGB).
 * GL_SRGB8_ALPHA8 renderbuffers and textures as colour attachments, drawn with the
 * enable off (stored as plain bytes) and on (linear -> sRGB encode on write; blending
 * decodes the destination, blends in float and re-encodes): smooth gradients, the over
 * operator, additive and constant-colour blending, full, scissored and colour-masked
 * clears. Then readbacks (glReadPixels never decodes), blits between sRGB and linear
 * attachments with the enable off and on, glCopyTexImage2D from an sRGB attachment, the
 * window (linear: the enable changes nothing), and the queries: attachment colour
 * encoding, GL_FRAMEBUFFER_SRGB_CAPABLE_EXT, the enable itself, glPushAttrib groups,
 * accepted and rejected renderbuffer formats. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 128
#define H 64

static void quad(float x0, float y0, float x1, float y1, const float *c0, const float *c1,
                 const float *c2, const float *c3)
{
    glBegin(GL_QUADS);
    glColor4fv(c0);
    glVertex2f(x0, y0);
    glColor4fv(c1);
    glVertex2f(x1, y0);
    glColor4fv(c2);
    glVertex2f(x1, y1);
    glColor4fv(c3);
    glVertex2f(x0, y1);
    glEnd();
}

/* Gradients and blends over the whole W x H target (viewport set by the caller). */
static void scene(void)
{
    static const float k0[4] = {0, 0, 0, 0}, k1[4] = {1, 1, 1, 1};
    static const float r0[4] = {0, 1, 0.5f, 0.25f}, r1[4] = {1, 0, 0.5f, 1};
    static const float g0[4] = {0.02f, 0.3f, 0.9f, 1}, g1[4] = {0.7f, 0.004f, 0.1f, 0.5f};
    static const float a[4] = {0.9f, 0.3f, 0.1f, 0.6f}, b[4] = {0.2f, 0.8f, 0.7f, 0.3f};
    static const float c[4] = {0.35f, 0.15f, 0.05f, 1}, d[4] = {0.1f, 0.2f, 0.3f, 0.4f};
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    /* a black-to-white ramp (every encoded value of a fine linear ramp) */
    quad(-1, -1, 1, -0.75f, k0, k1, k1, k0);
    /* colour ramps, horizontal and vertical */
    quad(-1, -0.75f, 1, -0.25f, r0, r1, r1, r0);
    quad(-1, -0.25f, 0, 1, g0, g0, g1, g1);
    quad(0, -0.25f, 1, 1, a, b, c, d);
    glEnable(GL_BLEND);
    /* over */
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBegin(GL_TRIANGLES);
    glColor4f(1.0f, 0.2f, 0.1f, 0.4f);
    glVertex2f(-0.9f, -0.9f);
    glColor4f(0.1f, 1.0f, 0.3f, 0.7f);
    glVertex2f(0.95f, -0.5f);
    glColor4f(0.2f, 0.3f, 1.0f, 0.2f);
    glVertex2f(-0.2f, 0.95f);
    glEnd();
    /* additive */
    glBlendFunc(GL_ONE, GL_ONE);
    quad(0.3f, -0.6f, 0.9f, 0.9f, d, c, b, d);
    /* constant colour, separate alpha */
    glBlendColor(0.3f, 0.6f, 0.9f, 0.5f);
    glBlendFuncSeparate(GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA, GL_ONE, GL_ZERO);
    quad(-0.6f, 0.2f, 0.1f, 0.8f, b, a, d, c);
    /* dst colour (multiply) */
    glBlendFunc(GL_DST_COLOR, GL_ZERO);
    quad(-0.95f, 0.5f, -0.3f, 0.95f, a, a, b, b);
    glDisable(GL_BLEND);
}

/* Clears: full, then scissored and colour-masked ones (the quad path in Mesa). */
static void clears(FILE *out, const char *name)
{
    unsigned char px[4];
    glClearColor(0.5f, 0.2f, 0.8f, 0.6f);
    glClear(GL_COLOR_BUFFER_BIT);
    glReadPixels(3, 3, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_text(out, "clear", "%s full %u %u %u %u\n", name, px[0], px[1], px[2], px[3]);
    glEnable(GL_SCISSOR_TEST);
    glScissor(10, 10, 20, 20);
    glClearColor(0.03f, 0.7f, 0.25f, 0.9f);
    glClear(GL_COLOR_BUFFER_BIT);
    glReadPixels(12, 12, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_text(out, "clear", "%s scissor %u %u %u %u\n", name, px[0], px[1], px[2], px[3]);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glClearColor(0.001f, 0.4f, 0.99f, 0.1f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glReadPixels(12, 12, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_text(out, "clear", "%s masked in %u %u %u %u\n", name, px[0], px[1], px[2], px[3]);
    glReadPixels(40, 40, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_text(out, "clear", "%s masked out %u %u %u %u\n", name, px[0], px[1], px[2], px[3]);
}

/* Clears and draws the bound target with the enable `on`, then reads it back. */
static void draw_and_read(FILE *out, const char *name, int on)
{
    static unsigned char img[W * H * 4];
    static float fimg[16 * 4];
    char label[64];
    if (on)
        glEnable(GL_FRAMEBUFFER_SRGB);
    else
        glDisable(GL_FRAMEBUFFER_SRGB);
    glViewport(0, 0, W, H);
    clears(out, name);
    glClearColor(0.5f, 0.2f, 0.8f, 0.6f);
    glClear(GL_COLOR_BUFFER_BIT);
    scene();
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, img);
    snprintf(label, sizeof label, "%s_%s", name, on ? "on" : "off");
    sgl_image(out, label, W, H, 4, "RGBA", W * 4, 1, img);
    glReadPixels(0, 2, 16, 1, GL_RGBA, GL_FLOAT, fimg);
    snprintf(label, sizeof label, "%s_%s_float", name, on ? "on" : "off");
    sgl_data(out, label, sizeof fimg, fimg);
    sgl_text(out, "err", "%s %d err=0x%x\n", name, on, glGetError());
}

static GLint encoding(GLenum target, GLenum attachment)
{
    GLint v = -1;
    glGetFramebufferAttachmentParameteriv(target, attachment,
                                          GL_FRAMEBUFFER_ATTACHMENT_COLOR_ENCODING, &v);
    return v;
}

static void queries(FILE *out, const char *name)
{
    GLint cap = -1;
    GLboolean en = 2;
    glGetIntegerv(GL_FRAMEBUFFER_SRGB_CAPABLE_EXT, &cap);
    glGetBooleanv(GL_FRAMEBUFFER_SRGB, &en);
    sgl_text(out, "query", "%s capable=%d enabled=%d isenabled=%d err=0x%x\n", name, cap, en,
             glIsEnabled(GL_FRAMEBUFFER_SRGB), glGetError());
}

/* A W x H colour renderbuffer or texture FBO of `internal`. */
static GLuint make_fbo(GLenum internal, int texture, GLuint *obj)
{
    GLuint fb;
    glGenFramebuffers(1, &fb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    if (texture) {
        glGenTextures(1, obj);
        glBindTexture(GL_TEXTURE_2D, *obj);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexImage2D(GL_TEXTURE_2D, 0, internal, W, H, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, *obj, 0);
    } else {
        glGenRenderbuffers(1, obj);
        glBindRenderbuffer(GL_RENDERBUFFER, *obj);
        glRenderbufferStorage(GL_RENDERBUFFER, internal, W, H);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, *obj);
    }
    return fb;
}

static void formats(FILE *out)
{
    static const GLenum fmts[8] = {GL_SRGB8_ALPHA8, GL_SRGB8, GL_SRGB, GL_SRGB_ALPHA,
                                   GL_SLUMINANCE8, GL_SLUMINANCE8_ALPHA8, GL_SLUMINANCE,
                                   GL_COMPRESSED_SRGB_ALPHA};
    GLuint fb, rb, tex;
    GLint v[6];
    int i;
    for (i = 0; i < 8; i++) {
        GLenum e0, e1;
        glGenFramebuffers(1, &fb);
        glGenRenderbuffers(1, &rb);
        glBindFramebuffer(GL_FRAMEBUFFER, fb);
        glBindRenderbuffer(GL_RENDERBUFFER, rb);
        glRenderbufferStorage(GL_RENDERBUFFER, fmts[i], 8, 8);
        e0 = glGetError();
        v[0] = v[1] = v[2] = v[3] = v[4] = -1;
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &v[0]);
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_RED_SIZE, &v[1]);
        glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_ALPHA_SIZE, &v[2]);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
        e1 = glGetError();
        sgl_text(out, "rbfmt", "0x%x err=0x%x internal=0x%x r=%d a=%d attach=0x%x "
                 "status=0x%x enc=0x%x err=0x%x\n", fmts[i], e0, v[0], v[1], v[2], e1,
                 glCheckFramebufferStatus(GL_FRAMEBUFFER), encoding(GL_FRAMEBUFFER,
                 GL_COLOR_ATTACHMENT0), glGetError());
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &fb);
        glDeleteRenderbuffers(1, &rb);
    }
    /* multisample sRGB storage */
    glGenFramebuffers(1, &fb);
    glGenRenderbuffers(1, &rb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_SRGB8_ALPHA8, 8, 8);
    v[0] = v[1] = -1;
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_SAMPLES, &v[0]);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &v[1]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    sgl_text(out, "rbms", "samples=%d internal=0x%x status=0x%x enc=0x%x err=0x%x\n", v[0],
             v[1], glCheckFramebufferStatus(GL_FRAMEBUFFER),
             encoding(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0), glGetError());
    queries(out, "ms_fbo");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fb);
    glDeleteRenderbuffers(1, &rb);
    /* sRGB textures as attachments */
    for (i = 0; i < 6; i++) {
        glGenFramebuffers(1, &fb);
        glGenTextures(1, &tex);
        glBindFramebuffer(GL_FRAMEBUFFER, fb);
        glBindTexture(GL_TEXTURE_2D, tex);
        glTexImage2D(GL_TEXTURE_2D, 0, fmts[i], 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
        glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, tex, 0);
        sgl_text(out, "texfmt", "0x%x status=0x%x enc=0x%x err=0x%x\n", fmts[i],
                 glCheckFramebufferStatus(GL_FRAMEBUFFER),
                 encoding(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0), glGetError());
        queries(out, "tex_fbo");
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glDeleteFramebuffers(1, &fb);
        glDeleteTextures(1, &tex);
    }
}

static void enable_state(FILE *out)
{
    GLboolean b[4];
    queries(out, "window");
    sgl_text(out, "enc", "window back=0x%x front=0x%x depth=0x%x err=0x%x\n",
             encoding(GL_FRAMEBUFFER, GL_BACK_LEFT), encoding(GL_FRAMEBUFFER, GL_FRONT_LEFT),
             encoding(GL_FRAMEBUFFER, GL_DEPTH), glGetError());
    glEnable(GL_FRAMEBUFFER_SRGB);
    sgl_text(out, "enable", "err=0x%x on=%d\n", glGetError(), glIsEnabled(GL_FRAMEBUFFER_SRGB));
    glPushAttrib(GL_COLOR_BUFFER_BIT);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glPopAttrib();
    b[0] = glIsEnabled(GL_FRAMEBUFFER_SRGB);
    glPushAttrib(GL_ENABLE_BIT);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glPopAttrib();
    b[1] = glIsEnabled(GL_FRAMEBUFFER_SRGB);
    glPushAttrib(GL_CURRENT_BIT);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glPopAttrib();
    b[2] = glIsEnabled(GL_FRAMEBUFFER_SRGB);
    sgl_text(out, "attrib", "color=%d enable=%d current=%d err=0x%x\n", b[0], b[1], b[2],
             glGetError());
    glEnable(GL_FRAMEBUFFER_SRGB);
    glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glPopClientAttrib();
    sgl_text(out, "attrib", "client=%d err=0x%x\n", glIsEnabled(GL_FRAMEBUFFER_SRGB),
             glGetError());
    glDisable(GL_FRAMEBUFFER_SRGB);
}

/* Blits between an sRGB and an RGBA8 renderbuffer with the enable off and on. */
static void blits(FILE *out, GLuint fsrgb, GLuint flin, GLuint fsrgb2)
{
    static unsigned char img[W * H * 4];
    static const struct {
        const char *name;
        int from_srgb, to, on, scaled;
    } cases[] = {
        {"srgb_to_lin_off", 1, 0, 0, 0}, {"srgb_to_lin_on", 1, 0, 1, 0},
        {"lin_to_srgb_off", 0, 1, 0, 0}, {"lin_to_srgb_on", 0, 1, 1, 0},
        {"srgb_to_srgb_on", 1, 2, 1, 0}, {"srgb_to_lin_on_scaled", 1, 0, 1, 1},
        {"srgb_to_srgb_on_scaled", 1, 2, 1, 1}, {"lin_to_srgb_on_scaled", 0, 1, 1, 1},
    };
    unsigned i;
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        GLuint src = cases[i].from_srgb ? fsrgb : flin;
        GLuint dst = cases[i].to == 0 ? flin : cases[i].to == 1 ? fsrgb : fsrgb2;
        /* restore the sources: the sRGB one drawn with the enable on, the linear off */
        glBindFramebuffer(GL_FRAMEBUFFER, fsrgb);
        draw_and_read(out, "src_srgb", 1);
        glBindFramebuffer(GL_FRAMEBUFFER, flin);
        draw_and_read(out, "src_lin", 0);
        glBindFramebuffer(GL_FRAMEBUFFER, dst);
        glDisable(GL_FRAMEBUFFER_SRGB);
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT);
        if (cases[i].on)
            glEnable(GL_FRAMEBUFFER_SRGB);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, src);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, dst);
        if (cases[i].scaled)
            glBlitFramebuffer(5, 3, 69, 35, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_LINEAR);
        else
            glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glDisable(GL_FRAMEBUFFER_SRGB);
        glBindFramebuffer(GL_FRAMEBUFFER, dst);
        glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, img);
        sgl_image(out, cases[i].name, W, H, 4, "RGBA", W * 4, 1, img);
        sgl_text(out, "err", "%s err=0x%x\n", cases[i].name, glGetError());
    }
}

/* A 4x SRGB8_ALPHA8 renderbuffer drawn with the enable on (per-sample encode and
 * blending), resolved into the sRGB and the RGBA8 renderbuffers with the enable on and
 * off (the resolve decodes, averages and encodes only while the enable is on). */
static void msaa(FILE *out, GLuint fsrgb, GLuint flin)
{
    static unsigned char img[W * H * 4];
    static const struct {
        const char *name;
        int to_srgb, on;
    } cases[] = {{"resolve_srgb_on", 1, 1}, {"resolve_srgb_off", 1, 0},
                 {"resolve_lin_on", 0, 1}, {"resolve_lin_off", 0, 0}};
    GLuint fb, rb;
    unsigned i;
    glGenFramebuffers(1, &fb);
    glGenRenderbuffers(1, &rb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_SRGB8_ALPHA8, W, H);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb);
    glEnable(GL_FRAMEBUFFER_SRGB);
    glViewport(0, 0, W, H);
    glClearColor(0.5f, 0.2f, 0.8f, 0.6f);
    glClear(GL_COLOR_BUFFER_BIT);
    scene();
    for (i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        GLuint dst = cases[i].to_srgb ? fsrgb : flin;
        glDisable(GL_FRAMEBUFFER_SRGB);
        glBindFramebuffer(GL_FRAMEBUFFER, dst);
        glClearColor(0, 0, 0, 0);
        glClear(GL_COLOR_BUFFER_BIT);
        if (cases[i].on)
            glEnable(GL_FRAMEBUFFER_SRGB);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, fb);
        glBlitFramebuffer(0, 0, W, H, 0, 0, W, H, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glDisable(GL_FRAMEBUFFER_SRGB);
        glBindFramebuffer(GL_FRAMEBUFFER, dst);
        glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, img);
        sgl_image(out, cases[i].name, W, H, 4, "RGBA", W * 4, 1, img);
        sgl_text(out, "err", "%s err=0x%x\n", cases[i].name, glGetError());
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fb);
    glDeleteRenderbuffers(1, &rb);
}

/* glCopyTexImage2D from the sRGB attachment into RGBA8 and SRGB8_ALPHA8 textures, with
 * the enable on; the copies read back with glGetTexImage. */
static void copytex(FILE *out, GLuint fsrgb)
{
    static unsigned char img[W * H * 4];
    GLuint tex[2];
    glBindFramebuffer(GL_FRAMEBUFFER, fsrgb);
    draw_and_read(out, "copy_src", 1);
    glGenTextures(2, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 0, 0, W, H, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    sgl_image(out, "copytex_rgba8", W, H, 4, "RGBA", W * 4, 1, img);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, 0, 0, W, H, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    sgl_image(out, "copytex_srgb", W, H, 4, "RGBA", W * 4, 1, img);
    sgl_text(out, "err", "copytex err=0x%x\n", glGetError());
    glDisable(GL_FRAMEBUFFER_SRGB);
    glDeleteTextures(2, tex);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    static unsigned char img[W * H * 4];
    GLuint fsrgb, flin, ftex, fsrgb2, rsrgb, rlin, tsrgb, rsrgb2;
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

    enable_state(out);
    formats(out);

    /* the window: linear, the enable changes nothing */
    draw_and_read(out, "window", 0);
    draw_and_read(out, "window", 1);
    queries(out, "window_on");
    glDisable(GL_FRAMEBUFFER_SRGB);

    fsrgb = make_fbo(GL_SRGB8_ALPHA8, 0, &rsrgb);
    queries(out, "srgb_rb");
    sgl_text(out, "enc", "srgb_rb 0x%x status=0x%x\n", encoding(GL_FRAMEBUFFER,
             GL_COLOR_ATTACHMENT0), glCheckFramebufferStatus(GL_FRAMEBUFFER));
    draw_and_read(out, "srgb_rb", 0);
    draw_and_read(out, "srgb_rb", 1);
    glDisable(GL_FRAMEBUFFER_SRGB);

    flin = make_fbo(GL_RGBA8, 0, &rlin);
    queries(out, "rgba8_rb");
    sgl_text(out, "enc", "rgba8_rb 0x%x\n", encoding(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0));
    draw_and_read(out, "rgba8_rb", 1);
    glDisable(GL_FRAMEBUFFER_SRGB);

    ftex = make_fbo(GL_SRGB8_ALPHA8, 1, &tsrgb);
    queries(out, "srgb_tex");
    draw_and_read(out, "srgb_tex", 1);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glBindTexture(GL_TEXTURE_2D, tsrgb);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    sgl_image(out, "srgb_tex_getteximage", W, H, 4, "RGBA", W * 4, 1, img);

    fsrgb2 = make_fbo(GL_SRGB8_ALPHA8, 0, &rsrgb2);
    blits(out, fsrgb, flin, fsrgb2);
    copytex(out, fsrgb);
    msaa(out, fsrgb, flin);

    /* the window after all that: drawn with the enable on */
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glEnable(GL_FRAMEBUFFER_SRGB);
    glViewport(0, 0, W, H);
    glClearColor(0.5f, 0.2f, 0.8f, 0.6f);
    glClear(GL_COLOR_BUFFER_BIT);
    scene();
    glFinish();
    sgl_image(out, "window_buffer", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "err", "end err=0x%x\n", glGetError());
    glDeleteFramebuffers(1, &ftex);
    OSMesaDestroyContext(ctx);
    free(buf);
    sgl_close(out);
    return 0;
}
