/*
 * fbo_msaa_shadow.c - (j) MuJoCo's frame shape: a shadow map, a multisample
 * framebuffer object and a resolve.
 *
 * Each frame renders 24 lit boxes from the light into a 1024x1024
 * DEPTH_COMPONENT24 texture attached to a depth-only framebuffer object, then
 * renders them again from the camera into an RGBA8 + DEPTH24_STENCIL8 object
 * with 4 samples (single-sample where GL_MAX_SAMPLES is below 4), the shadow
 * map compared through eye-linear texgen, resolves that object into the window
 * with glBlitFramebuffer and reads one row back.
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include "bench.h"

#define SHADOW 1024

static GLuint shadow_tex, shadow_fb, ms_fb, ms_rb[2];

static void box(float x, float y, float z, float s)
{
    static const float n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                  {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    int f, k;
    glBegin(GL_QUADS);
    for (f = 0; f < 6; f++) {
        float u[3] = {n[f][1], n[f][2], n[f][0]};
        float v[3] = {n[f][2], n[f][0], n[f][1]};
        glNormal3fv(n[f]);
        for (k = 0; k < 4; k++) {
            float a = (k == 1 || k == 2) ? s : -s, b = (k >= 2) ? s : -s;
            glVertex3f(x + n[f][0] * s + u[0] * a + v[0] * b,
                       y + n[f][1] * s + u[1] * a + v[1] * b,
                       z + n[f][2] * s + u[2] * a + v[2] * b);
        }
    }
    glEnd();
}

static void boxes(void)
{
    int i;
    for (i = 0; i < 24; i++)
        box((float)(i % 6) * 0.6f - 1.5f, (float)(i / 6) * 0.6f - 0.9f,
            0.2f * (float)(i % 3), 0.2f);
    box(0.0f, 0.0f, -2.2f, 2.0f); /* the floor */
}

static void scene_setup(int w, int h)
{
    GLint max_samples = 0;
    int samples;
    BENCH_UNUSED(w, h);
    glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
    samples = max_samples >= 4 ? 4 : 0;
    glGenTextures(1, &shadow_tex);
    glBindTexture(GL_TEXTURE_2D, shadow_tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, SHADOW, SHADOW, 0,
                 GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, NULL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glGenFramebuffers(1, &shadow_fb);
    glBindFramebuffer(GL_FRAMEBUFFER, shadow_fb);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadow_tex, 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    glGenFramebuffers(1, &ms_fb);
    glGenRenderbuffers(2, ms_rb);
    glBindFramebuffer(GL_FRAMEBUFFER, ms_fb);
    glBindRenderbuffer(GL_RENDERBUFFER, ms_rb[0]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, ms_rb[0]);
    glBindRenderbuffer(GL_RENDERBUFFER, ms_rb[1]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH24_STENCIL8, w, h);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              ms_rb[1]);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    glShadeModel(GL_SMOOTH);
}

static void scene_frame(int w, int h)
{
    static const float light_pos[4] = {1.0f, 1.5f, 3.0f, 1.0f};
    static const float sp[4] = {1, 0, 0, 0}, tp[4] = {0, 1, 0, 0}, rp[4] = {0, 0, 1, 0},
                       qp[4] = {0, 0, 0, 1};
    float light_mv[16], light_pr[16];
    unsigned char row[4 * 64];

    /* 1. the shadow map, from the light */
    glBindFramebuffer(GL_FRAMEBUFFER, shadow_fb);
    glViewport(0, 0, SHADOW, SHADOW);
    glClear(GL_DEPTH_BUFFER_BIT);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDisable(GL_LIGHTING);
    glDisable(GL_TEXTURE_2D);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(2.0f, 4.0f);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.5, 9.0);
    glGetFloatv(GL_PROJECTION_MATRIX, light_pr);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -4.0f);
    glRotatef(-25.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 0.0f, 1.0f);
    glGetFloatv(GL_MODELVIEW_MATRIX, light_mv);
    boxes();
    glDisable(GL_POLYGON_OFFSET_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    /* 2. the camera view into the multisample object, the shadow map compared */
    glBindFramebuffer(GL_FRAMEBUFFER, ms_fb);
    glViewport(0, 0, w, h);
    glClearColor(0.3f, 0.35f, 0.4f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTranslatef(0.5f, 0.5f, 0.5f);
    glScalef(0.5f, 0.5f, 0.5f);
    glMultMatrixf(light_pr);
    glMultMatrixf(light_mv);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.8, 0.8, -0.6, 0.6, 1.5, 12.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -4.5f);
    glRotatef(-35.0f, 1.0f, 0.0f, 0.0f);
    /* eye-linear planes given with the camera's modelview = identity map eye space
     * back to object space only in the light's frame: enough for a benchmark */
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_S, GL_OBJECT_PLANE, sp);
    glTexGenfv(GL_T, GL_OBJECT_PLANE, tp);
    glTexGenfv(GL_R, GL_OBJECT_PLANE, rp);
    glTexGenfv(GL_Q, GL_OBJECT_PLANE, qp);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_GEN_R);
    glEnable(GL_TEXTURE_GEN_Q);
    glEnable(GL_TEXTURE_2D);
    glLightfv(GL_LIGHT0, GL_POSITION, light_pos);
    glEnable(GL_LIGHTING);
    boxes();
    glDisable(GL_LIGHTING);
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glDisable(GL_TEXTURE_GEN_R);
    glDisable(GL_TEXTURE_GEN_Q);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);

    /* 3. resolve into the window and read a row back, as MuJoCo does */
    glBindFramebuffer(GL_READ_FRAMEBUFFER, ms_fb);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glReadPixels(0, h / 2, 64, 1, GL_RGBA, GL_UNSIGNED_BYTE, row);
}
