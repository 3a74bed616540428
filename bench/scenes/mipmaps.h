/*
 * mipmaps.h - a full RGBA8 mip chain for the benchmark scenes, made here (no
 * gluBuild2DMipmaps) and uploaded level by level with glTexImage2D.
 *
 * Each level is the 2x2 box filter of the one above, rounded ((sum + 2) / 4).
 * Include after <GL/gl.h>.
 */
#ifndef SGL_BENCH_MIPMAPS_H
#define SGL_BENCH_MIPMAPS_H

/* Uploads the square `size` x `size` RGBA image in `src` as level 0 of the bound
 * GL_TEXTURE_2D and every smaller level down to 1x1; `src` and `tmp` (each
 * size * size * 4 bytes) are overwritten. */
static inline void mip_upload_rgba8(unsigned char *src, unsigned char *tmp, int size)
{
    unsigned char *dst = tmp, *t;
    int x, y, c, lv;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (lv = 0;; lv++) {
        glTexImage2D(GL_TEXTURE_2D, lv, GL_RGBA8, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE, src);
        if (size == 1)
            break;
        size /= 2;
        for (y = 0; y < size; y++)
            for (x = 0; x < size; x++)
                for (c = 0; c < 4; c++) {
                    int s2 = size * 2;
                    int sum = src[((2 * y) * s2 + 2 * x) * 4 + c] +
                              src[((2 * y) * s2 + 2 * x + 1) * 4 + c] +
                              src[((2 * y + 1) * s2 + 2 * x) * 4 + c] +
                              src[((2 * y + 1) * s2 + 2 * x + 1) * 4 + c];
                    dst[(y * size + x) * 4 + c] = (unsigned char)((sum + 2) / 4);
                }
        t = src;
        src = dst;
        dst = t;
    }
}

#endif
