/* draw_pixels: glDrawPixels of every colour format with UNSIGNED_BYTE, FLOAT,
 * UNSIGNED_SHORT and packed types; unpack row length, skips and alignment;
 * glPixelZoom (2, 0.5, fractional 1.5/0.75, negative); a depth image with the
 * depth test and blending; a stencil image used as a stencil mask; texturing
 * (current texture coordinates) and fog on pixel fragments; raster position
 * off-screen (invalid: nothing drawn); errors. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 160
#define H 128
#define IW 13
#define IH 9

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    static unsigned char ub[IW * IH * 4 + 64];
    static float fl[IW * IH * 4];
    static unsigned short us[IW * IH * 4];
    static unsigned short p565[IW * IH], p4444[IW * IH];
    static float depth[IW * IH];
    static unsigned char sten[IW * IH];
    char errs[512];
    int n = 0, i;
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    for (i = 0; i < (int)sizeof ub; i++)
        ub[i] = (unsigned char)(i * 37 + (i >> 3) * 11);
    for (i = 0; i < IW * IH * 4; i++) {
        fl[i] = sgl_randf() * 1.2f - 0.1f;
        us[i] = (unsigned short)(i * 2711u);
    }
    for (i = 0; i < IW * IH; i++) {
        p565[i] = (unsigned short)(i * 1237u);
        p4444[i] = (unsigned short)(i * 4099u);
        depth[i] = (float)((i * 7) % 19) / 18.0f;
        sten[i] = (unsigned char)((i % 3) ? 1 : 0);
    }
    glMatrixMode(GL_PROJECTION);
    glOrtho(0, W, 0, H, -1, 1);
    glMatrixMode(GL_MODELVIEW);
    glClearColor(0.1f, 0.15f, 0.2f, 0.5f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);

    /* row 1: formats, UNSIGNED_BYTE */
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glRasterPos2i(2, 2);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glRasterPos2i(17, 2);
    glDrawPixels(IW, IH, GL_RGB, GL_UNSIGNED_BYTE, ub);
    glRasterPos2i(32, 2);
    glDrawPixels(IW, IH, GL_BGRA, GL_UNSIGNED_BYTE, ub);
    glRasterPos2i(47, 2);
    glDrawPixels(IW, IH, GL_BGR, GL_UNSIGNED_BYTE, ub);
    glRasterPos2i(62, 2);
    glDrawPixels(IW, IH, GL_LUMINANCE, GL_UNSIGNED_BYTE, ub);
    glRasterPos2i(77, 2);
    glDrawPixels(IW, IH, GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, ub);
    glRasterPos2i(92, 2);
    glDrawPixels(IW, IH, GL_ALPHA, GL_UNSIGNED_BYTE, ub);
    glRasterPos2i(107, 2);
    glDrawPixels(IW, IH, GL_RED, GL_UNSIGNED_BYTE, ub);
    glRasterPos2i(122, 2);
    glDrawPixels(IW, IH, GL_GREEN, GL_UNSIGNED_BYTE, ub);
    glRasterPos2i(137, 2);
    glDrawPixels(IW, IH, GL_BLUE, GL_UNSIGNED_BYTE, ub);

    /* row 2: types and unpack state */
    glRasterPos2i(2, 14);
    glDrawPixels(IW, IH, GL_RGBA, GL_FLOAT, fl);
    glRasterPos2i(17, 14);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_SHORT, us);
    glRasterPos2i(32, 14);
    glDrawPixels(IW, IH, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, p565);
    glRasterPos2i(47, 14);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_SHORT_4_4_4_4, p4444);
    glRasterPos2i(62, 14);
    glDrawPixels(IW, IH, GL_BGRA, GL_UNSIGNED_INT_8_8_8_8_REV, ub);
    glRasterPos2i(77, 14);
    glDrawPixels(IW, IH, GL_LUMINANCE, GL_FLOAT, fl);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 15);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 2);
    glRasterPos2i(92, 14);
    glDrawPixels(IW - 4, IH - 3, GL_RGB, GL_UNSIGNED_BYTE, ub);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    /* (Mesa 22.3 draws garbage for swapped bytes combined with a row length and
     * skips, so swapping is shown on its own.) */
    glPixelStorei(GL_UNPACK_SWAP_BYTES, 1);
    glRasterPos2i(107, 14);
    glDrawPixels(IW - 4, IH - 3, GL_LUMINANCE, GL_UNSIGNED_SHORT, us);
    glPixelStorei(GL_UNPACK_SWAP_BYTES, 0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);

    /* row 3: zoom */
    glPixelZoom(2.0f, 2.0f);
    glRasterPos2i(2, 26);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glPixelZoom(1.5f, 0.75f);
    glRasterPos2i(32, 26);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glPixelZoom(0.5f, 0.5f);
    glRasterPos2i(55, 26);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glPixelZoom(-1.0f, 1.0f);
    glRasterPos2i(85, 26);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glPixelZoom(1.0f, -2.0f);
    glRasterPos2i(90, 45);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glPixelZoom(-1.25f, -1.25f);
    glRasterPos2f(125.4f, 45.6f);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glPixelZoom(1.0f, 1.0f);
    /* partly outside the window */
    glRasterPos2i(150, 40);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);

    /* row 4: depth image, then colour through the depth test with blending */
    glEnable(GL_DEPTH_TEST);
    glColor4f(0.9f, 0.3f, 0.1f, 1.0f);
    glRasterPos3f(2, 50, 0.0f);
    glDrawPixels(IW, IH, GL_DEPTH_COMPONENT, GL_FLOAT, depth);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glRasterPos3f(2, 50, 0.1f);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glDisable(GL_BLEND);
    glPixelZoom(2.0f, 1.5f);
    glRasterPos3f(20, 50, 0.5f);
    glDrawPixels(IW, IH, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, us);
    glPixelZoom(1.0f, 1.0f);
    glDisable(GL_DEPTH_TEST);

    /* stencil image as a mask */
    glRasterPos2i(50, 50);
    glDrawPixels(IW, IH, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, sten);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glColor3f(0.2f, 0.9f, 0.4f);
    glRecti(48, 48, 66, 62);
    glDisable(GL_STENCIL_TEST);

    /* texturing at the current texture coordinate, fog */
    {
        static const unsigned char tex[16] = {255, 0, 0, 255, 0, 255, 0, 255,
                                              0, 0, 255, 255, 255, 255, 0, 255};
        static const float fog[4] = {1, 1, 1, 1};
        GLuint t;
        glGenTextures(1, &t);
        glBindTexture(GL_TEXTURE_2D, t);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, tex);
        glEnable(GL_TEXTURE_2D);
        glTexCoord2f(0.75f, 0.25f);
        glRasterPos2i(70, 50);
        glTexCoord2f(0.25f, 0.75f);
        glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);
        glDisable(GL_TEXTURE_2D);
        glEnable(GL_FOG);
        glFogi(GL_FOG_MODE, GL_LINEAR);
        glFogf(GL_FOG_START, -1.0f);
        glFogf(GL_FOG_END, 1.0f);
        glFogfv(GL_FOG_COLOR, fog);
        glRasterPos2i(85, 50);
        glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);
        glDisable(GL_FOG);
    }

    /* invalid raster position: nothing */
    glRasterPos2i(-5, 50);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    /* scissor and colour mask */
    glEnable(GL_SCISSOR_TEST);
    glScissor(104, 52, 8, 5);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    glRasterPos2i(100, 50);
    glDrawPixels(IW, IH, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_SCISSOR_TEST);

    /* errors */
    glGetError();
    glRasterPos2i(1, 1);
    glDrawPixels(-1, 2, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    n += snprintf(errs + n, sizeof errs - n, "neg %x\n", glGetError());
    glDrawPixels(2, 2, GL_RGBA, 0x1234, ub);
    n += snprintf(errs + n, sizeof errs - n, "badtype %x\n", glGetError());
    glDrawPixels(2, 2, 0x1234, GL_UNSIGNED_BYTE, ub);
    n += snprintf(errs + n, sizeof errs - n, "badformat %x\n", glGetError());
    glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5, ub);
    n += snprintf(errs + n, sizeof errs - n, "mismatch %x\n", glGetError());
    glDrawPixels(2, 2, GL_RGB, GL_BITMAP, ub);
    n += snprintf(errs + n, sizeof errs - n, "bitmaptype %x\n", glGetError());
    glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    n += snprintf(errs + n, sizeof errs - n, "null %x\n", glGetError());
    glDrawPixels(0, 0, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    n += snprintf(errs + n, sizeof errs - n, "zero %x\n", glGetError());
    glBegin(GL_POINTS);
    glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glEnd();
    n += snprintf(errs + n, sizeof errs - n, "inbegin %x\n", glGetError());

    /* A packed (or depth-stencil) type with a format it does not fit: Mesa checks
     * the type first, so even a format GL 1.5 does not know (GL_RG, 0x1234) gives
     * GL_INVALID_OPERATION, and GL_DEPTH_STENCIL with a plain type
     * GL_INVALID_ENUM (piglit's draw-pixels). Fitting pairs are skipped. */
    {
        static const GLenum fmts[] = {GL_RED, 0x8227 /* GL_RG */, GL_RGB, GL_BGR,
                                      GL_RGBA, GL_BGRA, GL_LUMINANCE,
                                      GL_LUMINANCE_ALPHA, GL_ALPHA,
                                      GL_DEPTH_COMPONENT, GL_STENCIL_INDEX,
                                      GL_COLOR_INDEX, GL_DEPTH_STENCIL, 0x1234};
        static const GLenum types[] = {
            GL_UNSIGNED_BYTE_3_3_2, GL_UNSIGNED_SHORT_5_6_5_REV,
            GL_UNSIGNED_SHORT_4_4_4_4, GL_UNSIGNED_SHORT_1_5_5_5_REV,
            GL_UNSIGNED_INT_8_8_8_8_REV, GL_UNSIGNED_INT_10_10_10_2,
            GL_UNSIGNED_INT_24_8, GL_FLOAT_32_UNSIGNED_INT_24_8_REV,
            GL_UNSIGNED_BYTE, GL_BITMAP};
        char perrs[2048];
        int pn = 0;
        for (unsigned t = 0; t < sizeof types / sizeof types[0]; t++) {
            pn += snprintf(perrs + pn, sizeof perrs - pn, "type %04x:", types[t]);
            for (unsigned f = 0; f < sizeof fmts / sizeof fmts[0]; f++) {
                GLenum fm = fmts[f], ty = types[t];
                int three = ty == GL_UNSIGNED_BYTE_3_3_2 || ty == GL_UNSIGNED_SHORT_5_6_5_REV;
                int ds = ty == GL_UNSIGNED_INT_24_8 || ty == GL_FLOAT_32_UNSIGNED_INT_24_8_REV;
                int plain = ty == GL_UNSIGNED_BYTE || ty == GL_BITMAP;
                if ((three && fm == GL_RGB) || (ds && fm == GL_DEPTH_STENCIL) ||
                    (!three && !ds && !plain && (fm == GL_RGBA || fm == GL_BGRA)) ||
                    /* (GL_RG with a plain type is ARB_texture_rg, which Mesa has) */
                    (ty == GL_UNSIGNED_BYTE && fm != GL_DEPTH_STENCIL && fm != 0x1234) ||
                    (ty == GL_BITMAP && (fm == GL_COLOR_INDEX || fm == GL_STENCIL_INDEX)))
                    continue;
                glDrawPixels(2, 2, fm, ty, ub);
                pn += snprintf(perrs + pn, sizeof perrs - pn, " %x", glGetError());
            }
            pn += snprintf(perrs + pn, sizeof perrs - pn, "\n");
        }
        sgl_text(out, "packed_errors", "%s", perrs);
    }

    glFinish();
    sgl_image(out, "draw_pixels", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "errors", "%s", errs);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
