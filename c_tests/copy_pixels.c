/* copy_pixels: glCopyPixels of colour, depth and stencil: the blit case
 * (zoom 1, no overlap: ignores the colour mask), overlapping copies (drawn as
 * a textured quad through the fragment operations), zoom (2, 0.5, negative),
 * copies from partly outside the window, pixel-transfer scale/bias, blending,
 * the depth copy with the current colour, the stencil copy through the write
 * mask; an invalid raster position; errors. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 128
#define H 96

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    static unsigned int depth[W * H];
    static unsigned char sten[W * H];
    char errs[256];
    int n = 0;
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    /* a smooth-shaded source with depth and stencil */
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 3, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glBegin(GL_TRIANGLES);
    glColor4f(1, 0, 0, 1);
    glVertex3f(2, 2, -0.8f);
    glColor4f(0, 1, 0, 0.5f);
    glVertex3f(30, 4, 0.3f);
    glColor4f(0, 0, 1, 0.25f);
    glVertex3f(12, 28, 0.9f);
    glEnd();
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_DEPTH_TEST);

    /* blit: no overlap, zoom 1; the colour mask is ignored by Mesa's blit */
    glRasterPos2i(34, 2);
    glCopyPixels(0, 0, 30, 30, GL_COLOR);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    glRasterPos2i(66, 2);
    glCopyPixels(0, 0, 30, 30, GL_COLOR);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    /* overlapping copy */
    glRasterPos2i(40, 10);
    glCopyPixels(34, 2, 30, 30, GL_COLOR);
    /* zooms */
    glPixelZoom(2.0f, 1.5f);
    glRasterPos2i(2, 34);
    glCopyPixels(0, 0, 20, 20, GL_COLOR);
    glPixelZoom(0.5f, 0.5f);
    glRasterPos2i(45, 34);
    glCopyPixels(0, 0, 30, 30, GL_COLOR);
    glPixelZoom(-1.0f, 1.0f);
    glRasterPos2i(95, 34);
    glCopyPixels(0, 0, 30, 30, GL_COLOR);
    glPixelZoom(1.0f, 1.0f);
    /* from partly outside, blending, scale/bias */
    glRasterPos2i(100, 2);
    glCopyPixels(-10, -5, 25, 25, GL_COLOR);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glRasterPos2i(60, 60);
    glCopyPixels(0, 0, 30, 30, GL_COLOR);
    glDisable(GL_BLEND);
    glPixelTransferf(GL_RED_SCALE, 0.5f);
    glPixelTransferf(GL_BLUE_BIAS, 0.25f);
    glRasterPos2i(92, 60);
    glCopyPixels(0, 0, 30, 30, GL_COLOR);
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    glPixelTransferf(GL_BLUE_BIAS, 0.0f);

    /* depth: blit, then overlapping copy with the current colour through the test */
    glRasterPos2i(2, 64);
    glCopyPixels(0, 0, 30, 30, GL_DEPTH);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glColor4f(0.9f, 0.8f, 0.1f, 1.0f);
    glRasterPos2i(10, 70);
    glCopyPixels(2, 64, 20, 20, GL_DEPTH);
    glDepthFunc(GL_LESS);
    glDisable(GL_DEPTH_TEST);
    /* stencil: blit and zoomed copy through the write mask */
    glRasterPos2i(34, 64);
    glCopyPixels(0, 0, 30, 30, GL_STENCIL);
    glStencilMask(0x01);
    glPixelZoom(1.0f, 0.5f);
    glRasterPos2i(34, 40);
    glCopyPixels(0, 0, 30, 30, GL_STENCIL);
    glPixelZoom(1.0f, 1.0f);
    glStencilMask(0xFF);
    /* invalid raster position */
    glRasterPos2i(-3, 10);
    glCopyPixels(0, 0, 30, 30, GL_COLOR);

    glGetError();
    glRasterPos2i(1, 1);
    glCopyPixels(0, 0, -1, 2, GL_COLOR);
    n += snprintf(errs + n, sizeof errs - n, "neg %x\n", glGetError());
    glCopyPixels(0, 0, 2, 2, GL_RGBA);
    n += snprintf(errs + n, sizeof errs - n, "badtype %x\n", glGetError());

    glFinish();
    sgl_image(out, "copy_pixels", W, H, 4, "RGBA", W * 4, 1, buf);
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
    sgl_data(out, "depth", sizeof depth, depth);
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sten);
    sgl_data(out, "stencil", sizeof sten, sten);
    sgl_text(out, "errors", "%s", errs);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
