/*
 * bench.h - the frame loop shared by the softgl benchmark scenes.
 *
 * A scene is an ordinary OSMesa program.  It defines two functions and then
 * includes this header:
 *
 *   static void scene_setup(int w, int h);   once, after OSMesaMakeCurrent
 *   static void scene_frame(int w, int h);   one frame, glClear included
 *
 * and optionally `#define SCENE_EXTRA scene_extra` for a function
 * `static void scene_extra(int w, int h, int frames)` that runs after the
 * timed frames (clear_only uses it to time memset in the same process).
 *
 * Usage: SCENE OUTPUT WIDTH HEIGHT FRAMES
 *
 * The program renders one warm-up frame, then FRAMES timed frames.  Each
 * timed frame is scene_frame() + glFinish(), timed with
 * clock_gettime(CLOCK_MONOTONIC); the time is printed on stdout as
 * "frame_ms <milliseconds>".  FRAMES may be 0: then only the warm-up frame is
 * rendered (the one-frame run used for whole-process time and memory).
 * The final frame is written to OUTPUT as one image block in the c_tests
 * format (see c_tests/README.md):
 *
 *   SGLIMG final <w> <h> 4 RGBA <w*4> up\n  then h*w*4 bytes, then \n
 */
#ifndef SGL_BENCH_H
#define SGL_BENCH_H

#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* Marks the size arguments of a scene function as unused. */
#define BENCH_UNUSED(w, h) ((void)(w), (void)(h))

/* Deterministic pseudo-random numbers in [0, 1) (same LCG as c_tests). */
static unsigned int bench_rand_state = 12345u;
static inline float bench_randf(void)
{
    bench_rand_state = bench_rand_state * 1103515245u + 12345u;
    return (float)((bench_rand_state >> 8) & 0xFFFFFF) / 16777216.0f;
}

static inline double bench_now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static void scene_setup(int w, int h);
static void scene_frame(int w, int h);
#ifdef SCENE_EXTRA
static void SCENE_EXTRA(int w, int h, int frames);
#endif

int main(int argc, char **argv)
{
    OSMesaContext ctx;
    unsigned char *buf;
    int w, h, frames, i;
    FILE *f;

    if (argc < 5) {
        fprintf(stderr, "usage: %s OUTPUT WIDTH HEIGHT FRAMES\n", argv[0]);
        return 2;
    }
    w = atoi(argv[2]);
    h = atoi(argv[3]);
    frames = atoi(argv[4]);
    if (w <= 0 || h <= 0 || frames < 0) {
        fprintf(stderr, "bad size or frame count\n");
        return 2;
    }
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!ctx) {
        fprintf(stderr, "OSMesaCreateContextExt failed\n");
        return 2;
    }
    buf = malloc((size_t)w * (size_t)h * 4);
    if (!buf) {
        fprintf(stderr, "out of memory\n");
        return 2;
    }
    memset(buf, 0, (size_t)w * (size_t)h * 4);
    if (!OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, w, h)) {
        fprintf(stderr, "OSMesaMakeCurrent failed\n");
        return 2;
    }

    scene_setup(w, h);
    /* Warm-up frame: first-use costs (llvmpipe compiles its shaders here). */
    scene_frame(w, h);
    glFinish();
    for (i = 0; i < frames; i++) {
        double t0 = bench_now_ms();
        scene_frame(w, h);
        glFinish();
        printf("frame_ms %.6f\n", bench_now_ms() - t0);
    }
#ifdef SCENE_EXTRA
    SCENE_EXTRA(w, h, frames);
#endif
    fflush(stdout);

    f = fopen(argv[1], "wb");
    if (!f) {
        perror(argv[1]);
        return 2;
    }
    fprintf(f, "SGLIMG final %d %d 4 RGBA %d up\n", w, h, w * 4);
    fwrite(buf, 1, (size_t)w * (size_t)h * 4, f);
    fputc('\n', f);
    if (ferror(f) || fclose(f) != 0) {
        fprintf(stderr, "error writing %s\n", argv[1]);
        return 2;
    }
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}

#endif
