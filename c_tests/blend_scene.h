/*
 * blend_scene.h - the blending scene drawn by blend_bgra and blend_rgb into
 * OSMesa buffers of other pixel formats.  Six bands use different blend
 * functions, four of which read the destination alpha (DST_ALPHA,
 * ONE_MINUS_DST_ALPHA, SRC_ALPHA_SATURATE), over a background whose alpha
 * varies.  In a buffer without alpha (OSMESA_RGB) the destination alpha
 * must read as 1.0.
 */
#ifndef SGL_BLEND_SCENE_H
#define SGL_BLEND_SCENE_H

/* the including scene defines GL_GLEXT_PROTOTYPES before <GL/gl.h> */
#include <GL/gl.h>
#include <GL/glext.h>

#define BW 256
#define BH 256

/* emulate_rgb: draw into an RGBA buffer as if it had no alpha channel
 * (alpha cleared to 1.0 and never written), for the reference of
 * blend_rgb. */
static inline void blend_scene_draw(int emulate_rgb)
{
    int i, band;
    glClearColor(0.29f, 0.37f, 0.43f, emulate_rgb ? 1.0f : 0.37f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (emulate_rgb)
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, 256.0, 0.0, 256.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    /* background: smooth columns, alpha 0 to 1 across each, gaps of clear */
    glBegin(GL_QUADS);
    for (i = 0; i < 5; i++) {
        float x0 = 51.2f * i + 2.3f, x1 = 51.2f * i + 47.9f;
        glColor4f(0.93f - 0.15f * i, 0.21f, 0.07f + 0.2f * i, 0.0f);
        glVertex2f(x0, 0.0f);
        glColor4f(0.13f, 0.71f + 0.05f * i, 0.53f, 1.0f);
        glVertex2f(x1, 0.0f);
        glColor4f(0.61f, 0.97f, 0.19f + 0.1f * i, 0.61f);
        glVertex2f(x1, 256.0f);
        glColor4f(0.37f, 0.05f, 0.83f, 0.13f + 0.17f * i);
        glVertex2f(x0, 256.0f);
    }
    glEnd();

    glEnable(GL_BLEND);
    glBlendColor(0.37f, 0.59f, 0.83f, 0.41f);
    for (band = 0; band < 6; band++) {
        float y = 42.6f * band + 1.3f;
        switch (band) {
        case 0:
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            break;
        case 1:
            glBlendFunc(GL_DST_ALPHA, GL_ONE_MINUS_DST_ALPHA);
            break;
        case 2:
            glBlendFunc(GL_ONE_MINUS_DST_ALPHA, GL_DST_ALPHA);
            break;
        case 3:
            glBlendFunc(GL_SRC_ALPHA_SATURATE, GL_ONE);
            break;
        case 4:
            glBlendFuncSeparate(GL_DST_COLOR, GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ZERO);
            break;
        default:
            glBlendFunc(GL_CONSTANT_COLOR, GL_ONE_MINUS_SRC_COLOR);
            break;
        }
        glBegin(GL_TRIANGLES);
        for (i = 0; i < 7; i++) {
            float x = 37.3f * i - 9.1f;
            glColor4f(0.97f, 0.43f + 0.05f * i, 0.11f, 0.37f);
            glVertex2f(x, y);
            glColor4f(0.17f, 0.91f, 0.63f - 0.06f * i, 0.89f);
            glVertex2f(x + 53.9f, y + 7.7f);
            glColor4f(0.47f, 0.23f, 0.99f, 0.05f + 0.13f * i);
            glVertex2f(x + 21.7f, y + 40.1f);
        }
        glEnd();
    }
    glDisable(GL_BLEND);
    if (emulate_rgb)
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

#endif
