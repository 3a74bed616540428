/* pixel_transfer_maps: the pixel-transfer paths pixel_transfer.c leaves out.
 * GL_MAP_COLOR with R/G/B/A_TO_* maps of sizes 1..256 when drawing 8-bit and
 * float images with glDrawPixels (with and without scale/bias) and in
 * glCopyPixels; GL_INDEX_SHIFT/OFFSET and GL_MAP_STENCIL on GL_STENCIL_INDEX
 * in glDrawPixels, glReadPixels and glCopyPixels; scale/bias and colour maps
 * applied by glReadPixels (unsigned byte and float); glGetPixelMap{fv,uiv,usv}
 * of all ten maps; and the glPixelMap errors. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 96
#define H 64
#define IW 16
#define IH 12

static char text[16384];
static int n;

static void dump_maps(void)
{
    static const GLenum maps[10] = {
        GL_PIXEL_MAP_I_TO_I, GL_PIXEL_MAP_S_TO_S, GL_PIXEL_MAP_I_TO_R, GL_PIXEL_MAP_I_TO_G,
        GL_PIXEL_MAP_I_TO_B, GL_PIXEL_MAP_I_TO_A, GL_PIXEL_MAP_R_TO_R, GL_PIXEL_MAP_G_TO_G,
        GL_PIXEL_MAP_B_TO_B, GL_PIXEL_MAP_A_TO_A};
    static GLfloat f[256];
    static GLuint ui[256];
    static GLushort us[256];
    int m, i, size;
    for (m = 0; m < 10; m++) {
        glGetIntegerv(GL_PIXEL_MAP_I_TO_I_SIZE + m, &size);
        glGetPixelMapfv(maps[m], f);
        glGetPixelMapuiv(maps[m], ui);
        glGetPixelMapusv(maps[m], us);
        n += snprintf(text + n, sizeof text - n, "map %x size %d:", maps[m], size);
        for (i = 0; i < size && i < 6; i++)
            n += snprintf(text + n, sizeof text - n, " %.9g/%u/%u", f[i], ui[i], us[i]);
        n += snprintf(text + n, sizeof text - n, " err %x\n", glGetError());
    }
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    static unsigned char ub[IW * IH * 4];
    static float fl[IW * IH * 4];
    static unsigned char sten[IW * IH];
    static unsigned char rb[W * H * 4];
    static float rf[24 * 8 * 4];
    static unsigned char sbuf[W * H];
    static GLfloat map[256];
    static GLuint ui[256];
    static GLushort us[256];
    int i;
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    for (i = 0; i < IW * IH * 4; i++) {
        ub[i] = (unsigned char)(i * 37 + 11);
        fl[i] = sgl_randf() * 1.4f - 0.2f;
    }
    for (i = 0; i < IW * IH; i++)
        sten[i] = (unsigned char)(i * 7 + 3);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.1f, 0.2f, 0.3f, 1.0f);
    glClearStencil(0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);

    /* colour maps of several sizes */
    for (i = 0; i < 256; i++)
        map[i] = 1.0f - (float)i / 255.0f;
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 256, map);
    for (i = 0; i < 8; i++)
        map[i] = (float)((i * 5) % 8) / 7.0f;
    glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 8, map);
    us[0] = 0;
    us[1] = 30000;
    us[2] = 65535;
    glPixelMapusv(GL_PIXEL_MAP_B_TO_B, 3, us);
    map[0] = 0.6f;
    glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 1, map);
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    glRasterPos2i(2, 2);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glRasterPos2i(20, 2);
    glDrawPixels(IW, IH, GL_RGBA, GL_FLOAT, fl);
    glRasterPos2i(38, 2);
    glDrawPixels(IW, IH, GL_RGB, GL_UNSIGNED_BYTE, ub);
    /* scale and bias before the maps */
    glPixelTransferf(GL_RED_SCALE, 0.7f);
    glPixelTransferf(GL_GREEN_BIAS, 0.3f);
    glPixelTransferf(GL_BLUE_SCALE, 2.0f);
    glRasterPos2i(56, 2);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    glPixelTransferf(GL_GREEN_BIAS, 0.0f);
    glPixelTransferf(GL_BLUE_SCALE, 1.0f);
    /* a 2-entry map and a copy */
    map[0] = 0.2f;
    map[1] = 0.9f;
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 2, map);
    glRasterPos2i(74, 2);
    glCopyPixels(2, 2, IW, IH, GL_COLOR);
    glPixelTransferi(GL_MAP_COLOR, GL_FALSE);

    /* glReadPixels with scale/bias and maps */
    glPixelTransferf(GL_RED_SCALE, 1.5f);
    glPixelTransferf(GL_ALPHA_BIAS, -0.25f);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, rb);
    sgl_data(out, "read_scaled_ub", sizeof rb, rb);
    glReadPixels(4, 4, 24, 8, GL_RGBA, GL_FLOAT, rf);
    sgl_data(out, "read_scaled_f", sizeof rf, rf);
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, rb);
    sgl_data(out, "read_mapped_ub", sizeof rb, rb);
    glReadPixels(4, 4, 24, 8, GL_RGBA, GL_FLOAT, rf);
    sgl_data(out, "read_mapped_f", sizeof rf, rf);
    glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    glPixelTransferf(GL_ALPHA_BIAS, 0.0f);

    /* stencil: shift/offset, then the S_TO_S map */
    for (i = 0; i < 16; i++)
        ui[i] = (GLuint)((i * 11 + 5) % 256);
    glPixelMapuiv(GL_PIXEL_MAP_S_TO_S, 16, ui);
    glPixelTransferi(GL_INDEX_SHIFT, 1);
    glPixelTransferi(GL_INDEX_OFFSET, 3);
    glRasterPos2i(2, 20);
    glDrawPixels(IW, IH, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sten);
    glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
    glRasterPos2i(20, 20);
    glDrawPixels(IW, IH, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sten);
    glPixelTransferi(GL_INDEX_SHIFT, -2);
    glPixelTransferi(GL_INDEX_OFFSET, -1);
    glRasterPos2i(38, 20);
    glDrawPixels(IW, IH, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sten);
    glRasterPos2i(56, 20);
    glCopyPixels(2, 20, IW, IH, GL_STENCIL);
    glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
    glPixelTransferi(GL_INDEX_SHIFT, 0);
    glPixelTransferi(GL_INDEX_OFFSET, 0);
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sbuf);
    sgl_data(out, "stencil", sizeof sbuf, sbuf);
    glPixelTransferi(GL_INDEX_SHIFT, 2);
    glPixelTransferi(GL_INDEX_OFFSET, 1);
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sbuf);
    sgl_data(out, "stencil_shifted", sizeof sbuf, sbuf);
    glPixelTransferi(GL_MAP_STENCIL, GL_TRUE);
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sbuf);
    sgl_data(out, "stencil_mapped", sizeof sbuf, sbuf);
    glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
    glPixelTransferi(GL_INDEX_SHIFT, 0);
    glPixelTransferi(GL_INDEX_OFFSET, 0);

    /* every map through the three getters, and the errors */
    for (i = 0; i < 4; i++)
        map[i] = 2.5f * (float)i - 1.0f;
    glPixelMapfv(GL_PIXEL_MAP_I_TO_I, 4, map);
    glPixelMapfv(GL_PIXEL_MAP_I_TO_A, 2, map);
    glGetError();
    dump_maps();
    glPixelMapfv(GL_PIXEL_MAP_S_TO_S, 6, map);
    n += snprintf(text + n, sizeof text - n, "s2s npot %x\n", glGetError());
    glPixelMapfv(GL_PIXEL_MAP_I_TO_G, 12, map);
    n += snprintf(text + n, sizeof text - n, "i2g npot %x\n", glGetError());
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 5, map);
    n += snprintf(text + n, sizeof text - n, "r2r npot %x\n", glGetError());
    glPixelMapfv(GL_PIXEL_MAP_I_TO_I, 512, map);
    n += snprintf(text + n, sizeof text - n, "i2i 512 %x\n", glGetError());
    glPixelMapfv(GL_PIXEL_MAP_I_TO_I, -1, map);
    n += snprintf(text + n, sizeof text - n, "i2i -1 %x\n", glGetError());
    glPixelMapuiv(GL_PIXEL_MAP_A_TO_A, 257, ui);
    n += snprintf(text + n, sizeof text - n, "a2a 257 %x\n", glGetError());
    glGetPixelMapfv(GL_PIXEL_MAP_I_TO_I_SIZE, map);
    n += snprintf(text + n, sizeof text - n, "get bad %x\n", glGetError());

    glFinish();
    sgl_image(out, "pixel_transfer_maps", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "state", "%s", text);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
