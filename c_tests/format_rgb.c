/* format_rgb: the format_scene.h scene rendered into an OSMESA_RGB context
 * (3 bytes per pixel, byte order RGB in memory).
 *
 * Mesa 22.3's llvmpipe draws wrong pixels into OSMESA_RGB buffers (a
 * smooth quad over a clear comes out striped, with bytes shifted between
 * neighbouring pixels, even with LP_NUM_THREADS=1; with more threads the
 * result also changes from run to run).  The clear alone is correct.  So
 * when built as the reference (the harness defines SGL_REFERENCE_OSMESA
 * for the Mesa build) the scene renders into an OSMESA_RGBA buffer and
 * packs it to RGB, which is what a correct RGB context must produce: the
 * RGB channels do not depend on the buffer format. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"
#include "format_scene.h"

#ifdef SGL_REFERENCE_OSMESA
#define CTX_FORMAT OSMESA_RGBA
#define CTX_BPP 4
#else
#define CTX_FORMAT OSMESA_RGB
#define CTX_BPP 3
#endif

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(CTX_FORMAT, 24, 8, 0, NULL);
    unsigned char *buf;
    GLint v[6];
    SGL_CHECK(ctx != NULL);
    buf = malloc(FW * FH * CTX_BPP);
    SGL_CHECK(buf != NULL);
    memset(buf, 0xA5, FW * FH * CTX_BPP);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, FW, FH));

    format_scene_draw();
    glFinish();

    OSMesaGetIntegerv(OSMESA_WIDTH, &v[0]);
    OSMesaGetIntegerv(OSMESA_HEIGHT, &v[1]);
    OSMesaGetIntegerv(OSMESA_FORMAT, &v[2]);
    OSMesaGetIntegerv(OSMESA_TYPE, &v[3]);
    OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &v[4]);
    OSMesaGetIntegerv(OSMESA_Y_UP, &v[5]);
#ifdef SGL_REFERENCE_OSMESA
    {
        /* pack RGBA to RGB in place; report what an RGB context reports */
        int i;
        for (i = 0; i < FW * FH; i++) {
            buf[3 * i] = buf[4 * i];
            buf[3 * i + 1] = buf[4 * i + 1];
            buf[3 * i + 2] = buf[4 * i + 2];
        }
        v[2] = OSMESA_RGB;
    }
#endif
    sgl_text(out, "osmesa", "width=%d height=%d format=0x%x type=0x%x row_length=%d y_up=%d\n",
             v[0], v[1], v[2], v[3], v[4], v[5]);
    sgl_image(out, "color", FW, FH, 3, "RGB", FW * 3, 1, buf);
    sgl_text(out, "error", "glGetError=0x%04x\n", glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
