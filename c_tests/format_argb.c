/* format_argb: the format_scene.h scene rendered into an OSMESA_ARGB context
 * (4 bytes per pixel, byte order ARGB in memory). */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"
#include "format_scene.h"

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_ARGB, 24, 8, 0, NULL);
    unsigned char *buf;
    GLint v[6];
    SGL_CHECK(ctx != NULL);
    buf = malloc(FW * FH * 4);
    SGL_CHECK(buf != NULL);
    memset(buf, 0xA5, FW * FH * 4);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, FW, FH));

    format_scene_draw();
    glFinish();

    OSMesaGetIntegerv(OSMESA_WIDTH, &v[0]);
    OSMesaGetIntegerv(OSMESA_HEIGHT, &v[1]);
    OSMesaGetIntegerv(OSMESA_FORMAT, &v[2]);
    OSMesaGetIntegerv(OSMESA_TYPE, &v[3]);
    OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &v[4]);
    OSMesaGetIntegerv(OSMESA_Y_UP, &v[5]);
    sgl_text(out, "osmesa", "width=%d height=%d format=0x%x type=0x%x row_length=%d y_up=%d\n",
             v[0], v[1], v[2], v[3], v[4], v[5]);
    sgl_image(out, "color", FW, FH, 4, "ARGB", FW * 4, 1, buf);
    sgl_text(out, "error", "glGetError=0x%04x\n", glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
