/* prims_common.h - boilerplate shared by the line/point/polygon-mode scenes:
 * a 256x256 RGBA context with a pixel-exact ortho projection. */
#ifndef SGL_PRIMS_COMMON_H
#define SGL_PRIMS_COMMON_H
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <math.h>
#include "common.h"

#define PW 256
#define PH 256

static OSMesaContext prims_ctx;
static unsigned char *prims_buf;

/* Create the context and set a window-coordinate ortho projection. */
static inline void prims_begin(void)
{
    prims_ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
    SGL_CHECK(prims_ctx != NULL);
    prims_buf = malloc(PW * PH * 4);
    SGL_CHECK(prims_buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(prims_ctx, prims_buf, GL_UNSIGNED_BYTE, PW, PH));
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, PW, 0.0, PH, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* Finish, write the image and tear down. */
static inline void prims_end(FILE *out, const char *name)
{
    glFinish();
    sgl_image(out, name, PW, PH, 4, "RGBA", PW * 4, 1, prims_buf);
}

static inline void prims_close(FILE *out)
{
    sgl_close(out);
    OSMesaDestroyContext(prims_ctx);
    free(prims_buf);
}

/* A distinct colour per index. */
static inline void prims_color(int i)
{
    glColor3f((float)((i * 53) % 256) / 255.0f, (float)((i * 97 + 80) % 256) / 255.0f,
              (float)((i * 151 + 40) % 256) / 255.0f);
}
#endif
