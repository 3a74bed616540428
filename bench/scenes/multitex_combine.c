/*
 * multitex_combine.c - two texture units with GL_COMBINE (INTERPOLATE, DOT3_RGB, RGB_SCALE) and the GL_BLEND environment.
 *
 * Unit 0 holds a 128x128 RGB8 pattern, unit 1 a 64x64 RGBA8 normal-like
 * texture (both GL_LINEAR, REPEAT).  Each frame draws four full-screen
 * layers of 8x8 smooth-coloured quads with different environments, blended
 * over each other: (1) unit 0 COMBINE INTERPOLATE(texture, primary colour,
 * texture alpha), unit 1 COMBINE DOT3_RGB(texture, constant) with RGB_SCALE 2;
 * (2) unit 0 COMBINE MODULATE with RGB_SCALE 4 and ALPHA_SCALE 2, unit 1
 * GL_BLEND with an environment colour; (3) unit 0 COMBINE ADD_SIGNED,
 * unit 1 COMBINE SUBTRACT with ONE_MINUS_SRC_COLOR operands; (4) unit 0
 * GL_BLEND, unit 1 COMBINE INTERPOLATE(previous, texture, primary alpha).
 */
#include <GL/gl.h>
#include "bench.h"

static GLuint tex[2];

static void tex_linear_repeat(void)
{
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
}

static void scene_setup(int w, int h)
{
    static unsigned char a[128 * 128 * 3], b[64 * 64 * 4];
    int x, y;
    BENCH_UNUSED(w, h);
    for (y = 0; y < 128; y++)
        for (x = 0; x < 128; x++) {
            unsigned char *p = a + (y * 128 + x) * 3;
            p[0] = (unsigned char)(x * 2);
            p[1] = (unsigned char)(((x >> 4) ^ (y >> 4)) & 1 ? 200 : 50);
            p[2] = (unsigned char)(y * 2);
        }
    for (y = 0; y < 64; y++)
        for (x = 0; x < 64; x++) {
            unsigned char *p = b + (y * 64 + x) * 4;
            float fx = (float)(x - 32) / 32.0f, fy = (float)(y - 32) / 32.0f;
            p[0] = (unsigned char)(128 + 100 * fx);
            p[1] = (unsigned char)(128 + 100 * fy);
            p[2] = (unsigned char)(200 - 50 * (fx * fx + fy * fy));
            p[3] = (unsigned char)((x * 4) ^ (y * 4));
        }
    glGenTextures(2, tex);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 128, 128, 0, GL_RGB, GL_UNSIGNED_BYTE, a);
    tex_linear_repeat();
    glEnable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, b);
    tex_linear_repeat();
    glEnable(GL_TEXTURE_2D);
    glActiveTexture(GL_TEXTURE0);
    glDisable(GL_DEPTH_TEST);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glClearColor(0.2f, 0.2f, 0.2f, 1.0f);
}

static void combine(GLenum unit, GLint rgb, GLint alpha)
{
    glActiveTexture(unit);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, rgb);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, alpha);
    glTexEnvi(GL_TEXTURE_ENV, GL_RGB_SCALE, 1);
    glTexEnvi(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 1);
}

static void srcs(GLint s0, GLint o0, GLint s1, GLint o1, GLint s2, GLint o2)
{
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE0_RGB, s0);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND0_RGB, o0);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE1_RGB, s1);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND1_RGB, o1);
    glTexEnvi(GL_TEXTURE_ENV, GL_SOURCE2_RGB, s2);
    glTexEnvi(GL_TEXTURE_ENV, GL_OPERAND2_RGB, o2);
}

static void layer(float phase)
{
    int i, j;
    const int n = 8;
    glBegin(GL_QUADS);
    for (j = 0; j < n; j++)
        for (i = 0; i < n; i++) {
            int k;
            for (k = 0; k < 4; k++) {
                int cx = i + (k == 1 || k == 2), cy = j + (k >= 2);
                float x = -1.0f + 2.0f * (float)cx / (float)n;
                float y = -1.0f + 2.0f * (float)cy / (float)n;
                glColor4f(0.5f + 0.5f * x, 0.5f + 0.5f * y, phase, 0.4f + 0.3f * (float)((cx + cy) & 1));
                glMultiTexCoord2f(GL_TEXTURE0, 1.5f * x + phase, 1.5f * y);
                glMultiTexCoord2f(GL_TEXTURE1, 2.0f * y, 2.0f * x + phase);
                glVertex2f(x, y);
            }
        }
    glEnd();
}

static void scene_frame(int w, int h)
{
    static const GLfloat envc[4] = {0.9f, 0.3f, 0.1f, 0.6f};
    static const GLfloat half[4] = {0.5f, 0.6f, 0.9f, 0.5f};
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_BLEND);

    combine(GL_TEXTURE0, GL_INTERPOLATE, GL_MODULATE);
    srcs(GL_TEXTURE, GL_SRC_COLOR, GL_PRIMARY_COLOR, GL_SRC_COLOR, GL_TEXTURE, GL_SRC_ALPHA);
    combine(GL_TEXTURE1, GL_DOT3_RGB, GL_REPLACE);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, half);
    srcs(GL_TEXTURE, GL_SRC_COLOR, GL_CONSTANT, GL_SRC_COLOR, GL_PREVIOUS, GL_SRC_COLOR);
    glTexEnvi(GL_TEXTURE_ENV, GL_RGB_SCALE, 2);
    layer(0.0f);

    glEnable(GL_BLEND);
    combine(GL_TEXTURE0, GL_MODULATE, GL_MODULATE);
    srcs(GL_TEXTURE, GL_SRC_COLOR, GL_PRIMARY_COLOR, GL_SRC_COLOR, GL_CONSTANT, GL_SRC_COLOR);
    glTexEnvi(GL_TEXTURE_ENV, GL_RGB_SCALE, 4);
    glTexEnvi(GL_TEXTURE_ENV, GL_ALPHA_SCALE, 2);
    glActiveTexture(GL_TEXTURE1);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, envc);
    layer(0.25f);

    combine(GL_TEXTURE0, GL_ADD_SIGNED, GL_ADD);
    srcs(GL_TEXTURE, GL_SRC_COLOR, GL_PRIMARY_COLOR, GL_SRC_COLOR, GL_CONSTANT, GL_SRC_COLOR);
    combine(GL_TEXTURE1, GL_SUBTRACT, GL_MODULATE);
    srcs(GL_PREVIOUS, GL_SRC_COLOR, GL_TEXTURE, GL_ONE_MINUS_SRC_COLOR, GL_CONSTANT, GL_SRC_COLOR);
    layer(0.5f);

    glActiveTexture(GL_TEXTURE0);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_BLEND);
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, half);
    combine(GL_TEXTURE1, GL_INTERPOLATE, GL_REPLACE);
    srcs(GL_PREVIOUS, GL_SRC_COLOR, GL_TEXTURE, GL_SRC_COLOR, GL_PRIMARY_COLOR, GL_SRC_ALPHA);
    layer(0.75f);
    glActiveTexture(GL_TEXTURE0);
}
