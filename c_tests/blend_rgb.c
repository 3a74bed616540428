/* blend_rgb: the blend_scene.h scene rendered into an OSMESA_RGB buffer.
 * The buffer has no alpha, so every destination-alpha factor must read 1.0
 * (DST_ALPHA = 1, ONE_MINUS_DST_ALPHA = 0, SRC_ALPHA_SATURATE = 0).
 *
 * Mesa 22.3's llvmpipe draws wrong pixels into OSMESA_RGB buffers (see
 * format_rgb.c), so when built as the reference (SGL_REFERENCE_OSMESA) the
 * scene renders into an OSMESA_RGBA buffer whose alpha is cleared to 1.0
 * and then write-masked, which is what a correct RGB buffer gives, and
 * packs the result to RGB. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "blend_scene.h"

#ifdef SGL_REFERENCE_OSMESA
#define CTX_FORMAT OSMESA_RGBA
#define CTX_BPP 4
#define EMULATE_RGB 1
#else
#define CTX_FORMAT OSMESA_RGB
#define CTX_BPP 3
#define EMULATE_RGB 0
#endif

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(CTX_FORMAT, 0, 0, 0, NULL);
    unsigned char *buf;
    SGL_CHECK(ctx != NULL);
    buf = malloc(BW * BH * CTX_BPP);
    SGL_CHECK(buf != NULL);
    memset(buf, 0xA5, BW * BH * CTX_BPP);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, BW, BH));

    blend_scene_draw(EMULATE_RGB);
    glFinish();

#ifdef SGL_REFERENCE_OSMESA
    {
        int i;
        for (i = 0; i < BW * BH; i++) {
            buf[3 * i] = buf[4 * i];
            buf[3 * i + 1] = buf[4 * i + 1];
            buf[3 * i + 2] = buf[4 * i + 2];
        }
    }
#endif
    sgl_image(out, "color", BW, BH, 3, "RGB", BW * 3, 1, buf);
    sgl_text(out, "error", "glGetError=0x%04x\n", glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
