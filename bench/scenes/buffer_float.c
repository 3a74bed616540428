/*
 * buffer_float.c - a float OSMesa buffer: OSMESA_RGBA with GL_FLOAT channels.
 *
 * The lit, textured, fogged and blended scene of wide_scene.h drawn into a
 * W*H*16-byte buffer; the output image is the buffer clamped to [0, 1] and
 * converted to 8 bits (the same conversion on both sides).
 */
#define BENCH_BUFFER_TYPE GL_FLOAT
#include "wide_scene.h"
