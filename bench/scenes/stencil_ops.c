/*
 * stencil_ops.c - stencil operations: every op, func and mask, then stencil-tested colour passes.
 *
 * An 8-bit stencil buffer.  Each frame clears stencil to 0x40, then draws 48
 * overlapping smooth-coloured polygons (16-gons about a third of the window
 * across) with colour writes on, each with its own stencil func (all eight),
 * reference, value mask, write mask and sfail/dpfail/dppass ops (KEEP, ZERO,
 * REPLACE, INCR, DECR, INVERT, INCR_WRAP, DECR_WRAP), depth test on; then
 * six full-screen quads each drawn where the stencil value equals, is below,
 * or is above a level (GL_EQUAL, GL_LESS, GL_GREATER with masks), blended.
 */
#define BENCH_STENCIL_BITS 8
#include <GL/gl.h>
#include "bench.h"
#include <math.h>

static void scene_setup(int w, int h)
{
    BENCH_UNUSED(w, h);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glClearStencil(0x40);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE);
}

static void polygon(float cx, float cy, float r, float z, int k)
{
    int i;
    glBegin(GL_POLYGON);
    for (i = 0; i < 16; i++) {
        float a = 6.2831853f * (float)i / 16.0f;
        glColor3f(0.5f + 0.5f * cosf(a + (float)k), 0.5f + 0.5f * sinf(a), 0.3f);
        glVertex3f(cx + r * cosf(a), cy + r * sinf(a), z);
    }
    glEnd();
}

static void scene_frame(int w, int h)
{
    static const GLenum ops[8] = {GL_KEEP, GL_ZERO, GL_REPLACE, GL_INCR,
                                  GL_DECR, GL_INVERT, GL_INCR_WRAP, GL_DECR_WRAP};
    static const GLenum funcs[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                                    GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    static const GLenum tests[3] = {GL_EQUAL, GL_LESS, GL_GREATER};
    int i;
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glEnable(GL_STENCIL_TEST);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    for (i = 0; i < 48; i++) {
        float cx = -0.8f + 1.6f * (float)((i * 7) % 12) / 11.0f;
        float cy = -0.8f + 1.6f * (float)((i * 5) % 8) / 7.0f;
        glStencilFunc(funcs[(i + (i >> 3)) % 8], 0x30 + 3 * i, (i & 1) ? 0xFF : 0x7C);
        glStencilOp(ops[i % 8], ops[(i / 2 + 3) % 8], ops[(i * 3 + 1) % 8]);
        glStencilMask((i & 2) ? 0xFF : 0x3F);
        polygon(cx, cy, 0.35f, 0.5f - (float)(i % 9) * 0.1f, i);
    }
    glStencilMask(0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    for (i = 0; i < 6; i++) {
        glStencilFunc(tests[i % 3], 0x38 + 8 * i, (i & 1) ? 0xF8 : 0xFF);
        glColor4f(i & 1 ? 0.6f : 0.1f, i & 2 ? 0.5f : 0.2f, i & 4 ? 0.9f : 0.3f, 0.35f);
        glRectf(-1.0f, -1.0f, 1.0f, 1.0f);
    }
    glDisable(GL_STENCIL_TEST);
}
