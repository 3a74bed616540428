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
 * `#define BENCH_BUFFER_TYPE GL_UNSIGNED_SHORT` (or GL_FLOAT) before the
 * include binds an OSMESA_RGBA buffer of that channel type instead of
 * GL_UNSIGNED_BYTE; the output is still 8-bit (u16 -> (v * 255 + 32767) /
 * 65535, float -> clamp to [0, 1], * 255, + 0.5, truncated), the same
 * conversion on both sides.  `#define BENCH_STENCIL_BITS 8` and
 * `#define BENCH_ACCUM_BITS 16` ask the context for a stencil or an
 * accumulation buffer (none by default).
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

#ifndef BENCH_STENCIL_BITS
#define BENCH_STENCIL_BITS 0
#endif
#ifndef BENCH_ACCUM_BITS
#define BENCH_ACCUM_BITS 0
#endif
#ifndef BENCH_BUFFER_TYPE
#define BENCH_BUFFER_TYPE GL_UNSIGNED_BYTE
#endif

/* Bytes per channel of the bound buffer. */
static size_t bench_channel_bytes(void)
{
    switch (BENCH_BUFFER_TYPE) {
    case GL_UNSIGNED_SHORT:
        return 2;
    case GL_FLOAT:
        return 4;
    default:
        return 1;
    }
}

/* Converts the bound buffer (n pixels) to 8-bit RGBA in place. */
static void bench_to_rgba8(unsigned char *buf, size_t n)
{
    size_t i;
    if (BENCH_BUFFER_TYPE == GL_UNSIGNED_SHORT) {
        const unsigned short *s = (const unsigned short *)buf;
        for (i = 0; i < n * 4; i++)
            buf[i] = (unsigned char)(((unsigned)s[i] * 255u + 32767u) / 65535u);
    } else if (BENCH_BUFFER_TYPE == GL_FLOAT) {
        const float *f = (const float *)buf;
        for (i = 0; i < n * 4; i++) {
            float v = f[i];
            v = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
            buf[i] = (unsigned char)(v * 255.0f + 0.5f);
        }
    }
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
    ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, BENCH_STENCIL_BITS, BENCH_ACCUM_BITS, NULL);
    if (!ctx) {
        fprintf(stderr, "OSMesaCreateContextExt failed\n");
        return 2;
    }
    buf = malloc((size_t)w * (size_t)h * 4 * bench_channel_bytes());
    if (!buf) {
        fprintf(stderr, "out of memory\n");
        return 2;
    }
    memset(buf, 0, (size_t)w * (size_t)h * 4 * bench_channel_bytes());
    if (!OSMesaMakeCurrent(ctx, buf, BENCH_BUFFER_TYPE, w, h)) {
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
    bench_to_rgba8(buf, (size_t)w * (size_t)h);
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
