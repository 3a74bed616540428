/*
 * common.h - the tiny output helper shared by the softgl C scenes.
 *
 * A scene writes one output file (argv[1]) made of blocks.  Every block is a
 * one-line ASCII header followed by raw bytes and a '\n':
 *
 *   SGLIMG <name> <width> <height> <bytes_per_pixel> <format> <rowbytes> <up|down>\n
 *          then height*rowbytes raw bytes (the buffer exactly as it is in memory)
 *   SGLDATA <name> <nbytes>\n   then nbytes raw bytes (e.g. glReadPixels of depth)
 *   SGLTEXT <name> <nbytes>\n   then nbytes of text (error codes, glGet values)
 *
 * <format> is the byte order of one pixel (RGBA, BGRA, ARGB, RGB, BGR, ...).
 * "up" means the first row in memory is the bottom row of the image (GL's
 * and OSMesa's default), "down" means it is the top row.
 *
 * The harness (tests/osmesa_compare.rs) compares the whole file byte for byte
 * against the same program built with Mesa's OSMesa.
 */
#ifndef SGL_COMMON_H
#define SGL_COMMON_H

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Abort the scene with a message and exit code 2 when cond is false. */
#define SGL_CHECK(cond)                                                       \
    do {                                                                      \
        if (!(cond)) {                                                        \
            fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, \
                    #cond);                                                   \
            exit(2);                                                          \
        }                                                                     \
    } while (0)

/* Open the output file named on the command line. */
static inline FILE *sgl_open(int argc, char **argv)
{
    FILE *f;
    if (argc < 2) {
        fprintf(stderr, "usage: %s OUTPUT\n", argv[0]);
        exit(2);
    }
    f = fopen(argv[1], "wb");
    if (!f) {
        perror(argv[1]);
        exit(2);
    }
    return f;
}

/* Write an image block: height rows of rowbytes bytes each. */
static inline void sgl_image(FILE *f, const char *name, int width, int height,
                             int bpp, const char *format, int rowbytes,
                             int y_up, const void *data)
{
    fprintf(f, "SGLIMG %s %d %d %d %s %d %s\n", name, width, height, bpp,
            format, rowbytes, y_up ? "up" : "down");
    fwrite(data, 1, (size_t)rowbytes * (size_t)height, f);
    fputc('\n', f);
}

/* Write a raw data block. */
static inline void sgl_data(FILE *f, const char *name, size_t nbytes,
                            const void *data)
{
    fprintf(f, "SGLDATA %s %lu\n", name, (unsigned long)nbytes);
    fwrite(data, 1, nbytes, f);
    fputc('\n', f);
}

/* Write a text block, printf style. */
static inline void sgl_text(FILE *f, const char *name, const char *fmt, ...)
{
    char buf[4096];
    va_list ap;
    int n;
    va_start(ap, fmt);
    n = vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    if (n < 0)
        n = 0;
    if (n >= (int)sizeof buf)
        n = (int)sizeof buf - 1;
    fprintf(f, "SGLTEXT %s %d\n", name, n);
    fwrite(buf, 1, (size_t)n, f);
    fputc('\n', f);
}

/* Run `call` and record in the text block "err" of `f` the error it raised and that one
 * read clears it, labelled `text` (the call as written, `#call` in the scene's own macro,
 * so that its GL names stay unexpanded) padded to `width` columns. */
#define SGL_ERR(f, width, text, call)                                                 \
    do {                                                                              \
        GLenum sgl_e1, sgl_e2;                                                        \
        call;                                                                         \
        sgl_e1 = glGetError();                                                        \
        sgl_e2 = glGetError();                                                        \
        sgl_text(f, "err", "%-*s -> 0x%04x then 0x%04x\n", width, text, sgl_e1, sgl_e2); \
    } while (0)

/* Close the output file; exits non-zero if anything failed to be written. */
static inline void sgl_close(FILE *f)
{
    if (ferror(f) || fclose(f) != 0) {
        fprintf(stderr, "error writing output\n");
        exit(2);
    }
}

/* Deterministic pseudo-random numbers (same sequence on every platform). */
static unsigned int sgl_rand_state = 12345u;
static inline float sgl_randf(void)
{
    sgl_rand_state = sgl_rand_state * 1103515245u + 12345u;
    return (float)((sgl_rand_state >> 8) & 0xFFFFFF) / 16777216.0f;
}

#endif
