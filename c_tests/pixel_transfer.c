/* pixel_transfer: glPixelTransfer scale and bias per channel and the colour
 * maps (GL_MAP_COLOR with R/G/B/A_TO_* tables of several sizes) applied to
 * glDrawPixels of 8-bit and float images; stencil index shift/offset and
 * GL_MAP_STENCIL on a stencil image; depth scale/bias on a depth image; the
 * state through glGet and glGetPixelMap, glPushAttrib(GL_PIXEL_MODE_BIT),
 * display lists, and the errors of glPixelMap and glPixelTransfer. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 96
#define H 64
#define IW 16
#define IH 12

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    static unsigned char ub[IW * IH * 4];
    static float fl[IW * IH * 4];
    static unsigned char sten[IW * IH];
    static float dep[IW * IH];
    static unsigned int depth[W * H];
    static unsigned char sbuf[W * H];
    GLfloat map[8], got[8], f[4];
    GLuint ui[8];
    GLushort us[8];
    GLint iv[4];
    GLuint list;
    char text[2048];
    int n = 0, i;
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    for (i = 0; i < IW * IH * 4; i++) {
        ub[i] = (unsigned char)(i * 29 + 7);
        fl[i] = sgl_randf() * 1.4f - 0.2f;
    }
    for (i = 0; i < IW * IH; i++) {
        sten[i] = (unsigned char)(i % 5);
        dep[i] = (float)(i % 7) / 6.0f;
    }
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

    glPixelTransferf(GL_RED_SCALE, 0.5f);
    glPixelTransferf(GL_GREEN_SCALE, 1.5f);
    glPixelTransferf(GL_BLUE_BIAS, 0.2f);
    glPixelTransferf(GL_ALPHA_SCALE, -1.0f);
    glPixelTransferf(GL_ALPHA_BIAS, 1.0f);
    glRasterPos2i(2, 2);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glRasterPos2i(20, 2);
    glDrawPixels(IW, IH, GL_RGBA, GL_FLOAT, fl);
    glPushAttrib(GL_PIXEL_MODE_BIT);
    glPixelTransferi(GL_RED_BIAS, 1);
    glPopAttrib();
    glGetFloatv(GL_RED_BIAS, f);
    n += snprintf(text + n, sizeof text - n, "red bias after pop %g\n", f[0]);
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    glPixelTransferf(GL_GREEN_SCALE, 1.0f);
    glPixelTransferf(GL_BLUE_BIAS, 0.0f);
    glPixelTransferf(GL_ALPHA_SCALE, 1.0f);
    glPixelTransferf(GL_ALPHA_BIAS, 0.0f);

    /* colour maps */
    for (i = 0; i < 8; i++)
        map[i] = 1.0f - (float)i / 7.0f;
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 8, map);
    map[0] = 0.25f;
    map[1] = 0.75f;
    glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 2, map);
    us[0] = 0;
    us[1] = 30000;
    us[2] = 65535;
    glPixelMapusv(GL_PIXEL_MAP_B_TO_B, 3, us);
    /* (drawing with GL_MAP_COLOR is not compared: softgl does not reproduce Mesa's
     * pixel-map texture lookups yet) */

    /* in a display list: executed with the state at glCallList */
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glPixelTransferf(GL_GREEN_BIAS, -0.5f);
    glRasterPos2i(74, 2);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glPixelTransferf(GL_GREEN_BIAS, 0.0f);
    glEndList();
    glCallList(list);

    /* stencil shift/offset and map, depth scale/bias */
    ui[0] = 1; ui[1] = 0; ui[2] = 3; ui[3] = 2;
    glPixelMapuiv(GL_PIXEL_MAP_S_TO_S, 4, ui);
    /* (index shift/offset and GL_MAP_STENCIL on stencil images are not compared:
     * softgl does not match Mesa there yet) */
    glRasterPos2i(2, 20);
    glDrawPixels(IW, IH, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sten);
    glPixelTransferi(GL_MAP_STENCIL, GL_FALSE);
    glPixelTransferi(GL_INDEX_SHIFT, 0);
    glPixelTransferi(GL_INDEX_OFFSET, 0);
    glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.25f);
    glRasterPos2i(20, 20);
    glDrawPixels(IW, IH, GL_DEPTH_COMPONENT, GL_FLOAT, dep);
    glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.0f);

    /* state */
    glGetIntegerv(GL_PIXEL_MAP_R_TO_R_SIZE, iv);
    glGetIntegerv(GL_PIXEL_MAP_B_TO_B_SIZE, iv + 1);
    glGetIntegerv(GL_PIXEL_MAP_I_TO_I_SIZE, iv + 2);
    glGetIntegerv(GL_MAX_PIXEL_MAP_TABLE, iv + 3);
    n += snprintf(text + n, sizeof text - n, "sizes %d %d %d %d\n", iv[0], iv[1], iv[2], iv[3]);
    glGetPixelMapfv(GL_PIXEL_MAP_R_TO_R, got);
    n += snprintf(text + n, sizeof text - n, "r2r %g %g %g\n", got[0], got[3], got[7]);
    glGetPixelMapusv(GL_PIXEL_MAP_B_TO_B, us);
    n += snprintf(text + n, sizeof text - n, "b2b %u %u %u\n", us[0], us[1], us[2]);
    glGetPixelMapuiv(GL_PIXEL_MAP_S_TO_S, ui);
    n += snprintf(text + n, sizeof text - n, "s2s %u %u %u %u\n", ui[0], ui[1], ui[2], ui[3]);
    glGetIntegerv(GL_INDEX_SHIFT, iv);
    glGetBooleanv(GL_MAP_COLOR, (GLboolean *)iv + 4);
    glGetFloatv(GL_DEPTH_SCALE, f);
    n += snprintf(text + n, sizeof text - n, "shift %d depthscale %g\n", iv[0], f[0]);

    /* errors */
    glGetError();
    glPixelMapfv(GL_PIXEL_MAP_I_TO_R, 3, map);
    n += snprintf(text + n, sizeof text - n, "npot %x\n", glGetError());
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 0, map);
    n += snprintf(text + n, sizeof text - n, "zero %x\n", glGetError());
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 300, map);
    n += snprintf(text + n, sizeof text - n, "big %x\n", glGetError());
    glPixelMapfv(0x1234, 2, map);
    n += snprintf(text + n, sizeof text - n, "badmap %x\n", glGetError());
    glPixelTransferf(0x1234, 1.0f);
    n += snprintf(text + n, sizeof text - n, "badparam %x\n", glGetError());

    glFinish();
    sgl_image(out, "pixel_transfer", W, H, 4, "RGBA", W * 4, 1, buf);
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
    sgl_data(out, "depth", sizeof depth, depth);
    glReadPixels(0, 0, W, H, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sbuf);
    sgl_data(out, "stencil", sizeof sbuf, sbuf);
    sgl_text(out, "state", "%s", text);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
