/*
 * buffer_ushort.c - a 16-bit OSMesa buffer: OSMESA_RGBA with GL_UNSIGNED_SHORT channels.
 *
 * The lit, textured, fogged and blended scene of wide_scene.h drawn into a
 * W*H*8-byte buffer; the output image is the buffer converted to 8 bits
 * ((v * 255 + 32767) / 65535, the same on both sides).
 */
#define BENCH_BUFFER_TYPE GL_UNSIGNED_SHORT
#include "wide_scene.h"
