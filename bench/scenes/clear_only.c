/*
 * clear_only.c - (i) glClear of colour and depth, and memset for scale.
 *
 * Each frame is glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT) with a
 * clear colour that changes every frame (so no implementation can skip a
 * redundant clear), then glFinish.  After the timed frames, the same number
 * of memset calls over w*h*8 bytes (4 bytes of RGBA and 4 of depth per
 * pixel, the size of the colour buffer plus a 32-bit depth buffer) are timed
 * in the same process and printed as "memset_ms <milliseconds>": the runner
 * reports glClear / memset.
 */
#include <GL/gl.h>
#define SCENE_EXTRA scene_extra
#include "bench.h"

static int frame_no;

static void scene_setup(int w, int h)
{
    BENCH_UNUSED(w, h);
    glEnable(GL_DEPTH_TEST);
    glClearDepth(1.0);
}

static void scene_frame(int w, int h)
{
    float s = (float)(frame_no++ % 16) / 15.0f;
    BENCH_UNUSED(w, h);
    glClearColor(0.25f + 0.5f * s, 0.5f, 0.75f - 0.5f * s, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

static void scene_extra(int w, int h, int frames)
{
    size_t n = (size_t)w * (size_t)h * 8;
    unsigned char *mem = malloc(n);
    volatile unsigned char sink = 0;
    int i;
    if (!mem) {
        fprintf(stderr, "out of memory\n");
        exit(2);
    }
    memset(mem, 1, n); /* warm-up: fault the pages in */
    for (i = 0; i < frames; i++) {
        double t0 = bench_now_ms();
        memset(mem, (i & 0x7f) + 1, n);
        /* Read a byte so the compiler keeps the memset. */
        sink = mem[(size_t)i * 4099 % n];
        printf("memset_ms %.6f\n", bench_now_ms() - t0);
    }
    (void)sink;
    free(mem);
}
