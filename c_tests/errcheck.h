/* errcheck.h - what the error-code scenes share (errors, generic_attrib_errors,
 * shader_objects, shader_uniforms): the output file, the E() wrapper that prints
 * a call with the two glGetError values after it, a name-order comparison for
 * sorting lines (of active shader variables, whose order GL leaves to the
 * implementation) and the common end of a scene. Include after the GL and
 * OSMesa headers. SGL_E_WIDTH is the column the call's text is padded to. */
#ifndef SGL_ERRCHECK_H
#define SGL_ERRCHECK_H

#include "common.h"

#ifndef SGL_E_WIDTH
#define SGL_E_WIDTH 70
#endif

static FILE *out;

/* run a call and record the error it raised (and that one read clears it) */
#define E(call) SGL_ERR(out, SGL_E_WIDTH, #call, call)

/* strcmp for qsort over rows of char. */
static inline int by_name(const void *a, const void *b)
{
    return strcmp((const char *)a, (const char *)b);
}

/* glFinish, the final error, then close the output and free the context. */
static inline int sgl_end_scene(OSMesaContext ctx, void *buf)
{
    glFinish();
    sgl_text(out, "final", "err 0x%04x\n", glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}

#endif
