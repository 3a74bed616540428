/*
 * tex_truth_plane.h - the ground plane that is judged against an analytic
 * ground truth instead of against OSMesa: c_tests/tex_aniso.c
 * (tests/aniso_truth.rs) and bench/scenes/filter_study.c (the filter study,
 * `bench/filter_study.md`).
 *
 * The texture is a 512x512 black/white checkerboard with 64x64-texel cells
 * (black at texel (0,0)), GL_REPEAT, with its full mip chain box-filtered and
 * uploaded by hand WITHOUT the per-level tints of sgl_upload_mips, so every
 * level is a faithful average of the checkerboard. It is drawn with
 * GL_MODULATE and white vertices on sgl_ground_plane(SGL_TRUTH_PERIOD) seen
 * through sgl_ground_view(aspect) with a full-buffer viewport.
 * bench/runner/ground_truth.rs repeats these constants and the matrices.
 *
 * Include after "common.h" and "tex_common.h".
 */
#ifndef SGL_TEX_TRUTH_PLANE_H
#define SGL_TEX_TRUTH_PLANE_H

#define SGL_TRUTH_TEX 512
#define SGL_TRUTH_CELL 64
#define SGL_TRUTH_PERIOD 3.7f

/* Creates, binds and fills the checkerboard texture with all 10 levels. */
static inline GLuint sgl_truth_texture(void)
{
    static const unsigned char black[4] = {0, 0, 0, 255}, white[4] = {255, 255, 255, 255};
    unsigned char *cur = sgl_checker(SGL_TRUTH_TEX, SGL_TRUTH_TEX, SGL_TRUTH_CELL,
                                     SGL_TRUTH_CELL, black, white);
    int size = SGL_TRUTH_TEX, level = 0;
    GLuint tex;
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (;;) {
        unsigned char *next;
        glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, size, size, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, cur);
        if (size == 1)
            break;
        next = sgl_halve(cur, size, size, NULL);
        free(cur);
        cur = next;
        size /= 2;
        level++;
    }
    free(cur);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    return tex;
}

/* Clears to the sky colour and draws the plane into a w x h viewport. */
static inline void sgl_truth_draw(int w, int h)
{
    glClearColor(0.31f, 0.47f, 0.73f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glViewport(0, 0, w, h);
    sgl_ground_view((double)w / (double)h);
    sgl_ground_plane(SGL_TRUTH_PERIOD);
}

#endif
