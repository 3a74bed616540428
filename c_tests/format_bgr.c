/* format_bgr: the format_scene.h scene rendered into an OSMESA_BGR context
 * if OSMesaMakeCurrent accepts it (Mesa 22.3 does not)
 * (3 bytes per pixel, byte order BGR in memory). */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"
#include "format_scene.h"

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_BGR, 24, 8, 0, NULL);
    unsigned char *buf;
    GLint v[6];
    GLboolean ok;
    SGL_CHECK(ctx != NULL);
    buf = malloc(FW * FH * 3);
    SGL_CHECK(buf != NULL);
    memset(buf, 0xA5, FW * FH * 3);
    /* Mesa's gallium OSMesa creates the context but refuses to bind a BGR
     * buffer; record the answer, and draw only if it was accepted. */
    ok = OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, FW, FH);
    sgl_text(out, "makecurrent", "OSMesaMakeCurrent(BGR)=%d\n", ok);
    if (!ok) {
        sgl_close(out);
        OSMesaDestroyContext(ctx);
        free(buf);
        return 0;
    }

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
    sgl_image(out, "color", FW, FH, 3, "BGR", FW * 3, 1, buf);
    sgl_text(out, "error", "glGetError=0x%04x\n", glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
