/* fbo_float_color: renderbuffers of GL_RGBA16, GL_RGBA16F, GL_RGBA32F and GL_RGB16F
 * with a DEPTH24 renderbuffer, drawn into with smooth colours, a lit sheet with the
 * separate specular colour (sums above 1), additive blending (above 1), the SUBTRACT and
 * REVERSE_SUBTRACT equations (below 0 in float buffers) and the over operator; read back
 * as GL_FLOAT, GL_UNSIGNED_SHORT and GL_UNSIGNED_BYTE, with the renderbuffer's sizes.
 * Mesa renders R16G16B16A16_UNORM in 16-bit fixed point and the float formats in f32
 * without clamping (GL_CLAMP_FRAGMENT_COLOR and GL_CLAMP_READ_COLOR are FIXED_ONLY;
 * docs/llvmpipe-rules.md §23). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <math.h>
#include "common.h"

#define W 32
#define H 24
#define FW 57
#define FH 41

static void quad(float x0, float y0, float x1, float y1, const float *c0, const float *c1)
{
    glBegin(GL_QUADS);
    glColor4fv(c0);
    glVertex2f(x0, y0);
    glColor4fv(c1);
    glVertex2f(x1, y0);
    glColor4fv(c0);
    glVertex2f(x1, y1);
    glColor4fv(c1);
    glVertex2f(x0, y1);
    glEnd();
}

static void scene(void)
{
    static const GLfloat pos[4] = {0.3f, 0.5f, 1.0f, 0.0f};
    static const GLfloat diff[4] = {0.9f, 0.8f, 0.7f, 0.9f};
    static const GLfloat spec[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    static const float a[4] = {0.9f, 0.3f, 0.1f, 0.6f}, b[4] = {0.2f, 0.8f, 0.7f, 0.3f};
    static const float c[4] = {0.7f, 0.6f, 0.9f, 0.9f}, d[4] = {0.1f, 0.2f, 0.3f, 0.4f};
    int i, j;
    glViewport(0, 0, FW, FH);
    glClearColor(0.25f, 0.5f, 0.75f, 0.5f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    /* a smooth quad, no blending */
    quad(-0.95f, -0.95f, -0.1f, -0.1f, a, b);
    /* a lit sheet with the separate specular colour: sums above 1 */
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModeli(GL_LIGHT_MODEL_COLOR_CONTROL, GL_SEPARATE_SPECULAR_COLOR);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diff);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 8.0f);
    for (j = 0; j < 4; j++) {
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i <= 6; i++) {
            float u = 0.05f + 0.15f * i, v0 = 0.05f + 0.22f * j, v1 = v0 + 0.22f;
            glNormal3f(0.5f * cosf(6.0f * u), 0.3f * sinf(5.0f * v0), 1.0f);
            glVertex2f(u, v0);
            glNormal3f(0.5f * cosf(6.0f * u), 0.3f * sinf(5.0f * v1), 1.0f);
            glVertex2f(u, v1);
        }
        glEnd();
    }
    glDisable(GL_LIGHTING);
    glEnable(GL_BLEND);
    /* additive: above 1 */
    glBlendFunc(GL_ONE, GL_ONE);
    quad(-0.9f, 0.1f, -0.2f, 0.9f, c, a);
    quad(-0.6f, 0.3f, 0.0f, 0.95f, c, c);
    /* subtract and reverse subtract: below 0 in float buffers */
    glBlendEquation(GL_FUNC_SUBTRACT);
    glBlendFunc(GL_ONE, GL_ONE);
    quad(0.1f, -0.95f, 0.5f, -0.1f, d, b);
    glBlendEquation(GL_FUNC_REVERSE_SUBTRACT);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE);
    quad(0.5f, -0.95f, 0.95f, -0.1f, c, a);
    /* over, across everything */
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glBegin(GL_TRIANGLES);
    glColor4f(1.0f, 0.2f, 0.1f, 0.4f);
    glVertex2f(-0.8f, -0.7f);
    glColor4f(0.1f, 1.0f, 0.3f, 0.7f);
    glVertex2f(0.9f, -0.2f);
    glColor4f(0.2f, 0.3f, 1.0f, 0.2f);
    glVertex2f(-0.1f, 0.9f);
    glEnd();
    /* a constant-colour blend */
    glBlendColor(0.3f, 0.6f, 0.9f, 0.5f);
    glBlendFunc(GL_CONSTANT_COLOR, GL_ONE_MINUS_CONSTANT_ALPHA);
    quad(-0.3f, -0.3f, 0.3f, 0.3f, b, d);
    glDisable(GL_BLEND);
}

static void run(FILE *out, const char *name, GLenum internal)
{
    GLuint fb, rb[2];
    GLint sz[5];
    static float rf[FW * FH * 4];
    static unsigned short rs[FW * FH * 4];
    static unsigned char ru[FW * FH * 4];
    char label[64];
    glGenFramebuffers(1, &fb);
    glGenRenderbuffers(2, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorage(GL_RENDERBUFFER, internal, FW, FH);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_RED_SIZE, &sz[0]);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_GREEN_SIZE, &sz[1]);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_BLUE_SIZE, &sz[2]);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_ALPHA_SIZE, &sz[3]);
    glGetRenderbufferParameteriv(GL_RENDERBUFFER, GL_RENDERBUFFER_INTERNAL_FORMAT, &sz[4]);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, FW, FH);
    glBindFramebuffer(GL_FRAMEBUFFER, fb);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, rb[1]);
    sgl_text(out, "info", "%s sizes=%d,%d,%d,%d internal=0x%x status=0x%x err=0x%x\n", name,
             sz[0], sz[1], sz[2], sz[3], sz[4], glCheckFramebufferStatus(GL_FRAMEBUFFER),
             glGetError());
    scene();
    glReadPixels(0, 0, FW, FH, GL_RGBA, GL_FLOAT, rf);
    snprintf(label, sizeof label, "%s_float", name);
    sgl_data(out, label, sizeof rf, rf);
    glReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_SHORT, rs);
    snprintf(label, sizeof label, "%s_ushort", name);
    sgl_data(out, label, sizeof rs, rs);
    glReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_BYTE, ru);
    snprintf(label, sizeof label, "%s_ubyte", name);
    sgl_data(out, label, sizeof ru, ru);
    sgl_text(out, "err", "%s err=0x%x\n", name, glGetError());
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fb);
    glDeleteRenderbuffers(2, rb);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    run(out, "rgba8", GL_RGBA8);
    run(out, "rgba16", GL_RGBA16);
    run(out, "rgba16f", GL_RGBA16F);
    run(out, "rgba32f", GL_RGBA32F);
    run(out, "rgb16f", GL_RGB16F);
    run(out, "rgb32f", GL_RGB32F);
    sgl_close(out);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
