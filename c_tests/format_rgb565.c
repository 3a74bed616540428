/* format_rgb565: the format_scene.h scene rendered into an OSMESA_RGB_565 context
 * (2 bytes per pixel, native-endian 16-bit 5-6-5 pixels, red in the high bits). */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"
#include "format_scene.h"

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGB_565, 24, 8, 0, NULL);
    unsigned char *buf;
    GLint v[6];
    SGL_CHECK(ctx != NULL);
    buf = malloc(FW * FH * 2);
    SGL_CHECK(buf != NULL);
    memset(buf, 0xA5, FW * FH * 2);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_SHORT_5_6_5, FW, FH));

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
    sgl_image(out, "color", FW, FH, 2, "RGB565", FW * 2, 1, buf);
    sgl_text(out, "error", "glGetError=0x%04x\n", glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
