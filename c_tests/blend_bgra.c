/* blend_bgra: the blend_scene.h scene (destination-alpha factors over a
 * background with varying alpha) rendered into an OSMESA_BGRA buffer. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "blend_scene.h"

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_BGRA, 0, 0, 0, NULL);
    unsigned char *buf;
    SGL_CHECK(ctx != NULL);
    buf = malloc(BW * BH * 4);
    SGL_CHECK(buf != NULL);
    memset(buf, 0xA5, BW * BH * 4);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, BW, BH));

    blend_scene_draw(0);
    glFinish();

    sgl_image(out, "color", BW, BH, 4, "BGRA", BW * 4, 1, buf);
    sgl_text(out, "error", "glGetError=0x%04x\n", glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
