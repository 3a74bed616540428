/* prim_tex_common.h - textures for the textured line/point/stipple scenes: a
 * mipmapped RGBA checkerboard with a tint per level (so the chosen level shows)
 * and a small luminance ramp for a second unit. */
#ifndef SGL_PRIM_TEX_COMMON_H
#define SGL_PRIM_TEX_COMMON_H
#include "prims_common.h"

/* A 64x64 checkerboard whose levels are tinted differently; LINEAR_MIPMAP_LINEAR. */
static inline GLuint prim_tex_checker(void)
{
    static unsigned char img[64 * 64 * 4];
    static const unsigned char tint[7][3] = {{255, 255, 255}, {255, 80, 80}, {80, 255, 80},
                                             {80, 80, 255}, {255, 255, 60}, {60, 255, 255},
                                             {255, 60, 255}};
    GLuint tex;
    int level, size, x, y;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    for (level = 0, size = 64; size >= 1; level++, size /= 2) {
        for (y = 0; y < size; y++) {
            for (x = 0; x < size; x++) {
                int on = ((x * 8 / size) + (y * 8 / size)) & 1;
                unsigned char *p = img + (y * size + x) * 4;
                p[0] = (unsigned char)(on ? tint[level][0] : tint[level][0] / 4);
                p[1] = (unsigned char)(on ? tint[level][1] : tint[level][1] / 4);
                p[2] = (unsigned char)(on ? tint[level][2] : tint[level][2] / 4);
                p[3] = (unsigned char)(on ? 255 : 100);
            }
        }
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     img);
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    return tex;
}

/* A 16x16 luminance ramp, LINEAR, CLAMP_TO_EDGE-free (REPEAT). */
static inline GLuint prim_tex_ramp(void)
{
    static unsigned char img[16 * 16];
    GLuint tex;
    int x, y;
    for (y = 0; y < 16; y++)
        for (x = 0; x < 16; x++)
            img[y * 16 + x] = (unsigned char)(40 + x * 10 + y * 3);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, 16, 16, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, img);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    return tex;
}
#endif
