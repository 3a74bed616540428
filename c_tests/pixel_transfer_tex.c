/* pixel_transfer_tex: pixel transfer where textures are specified (GL 1.5
 * §3.8.1) and depth is read (§4.3.2): glPixelTransfer scale/bias and the
 * GL_MAP_COLOR tables applied by glTexImage1D/2D/3D, glTexSubImage2D/3D,
 * glCopyTexImage2D, glCopyTexSubImage2D/3D (RGBA, RGB, LUMINANCE, RGB5_A1 and
 * RGBA4 storage; ubyte, float, signed byte, 5_6_5 and BGRA data), depth
 * scale/bias on depth textures (float and ushort data, glCopyTexImage2D from
 * the depth buffer), a glTexImage2D compiled into a display list and run
 * under another transfer state, and glReadPixels of depth in every type with
 * and without depth scale/bias.  Textures are read back with glGetTexImage
 * (with the transfer state reset) and drawn. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 64
#define H 48
#define TW 8
#define TH 8
#define TD 2

static FILE *out;
static unsigned char got[TW * TH * TD * 4];
static unsigned int gotz[TW * TH];

static void reset_transfer(void)
{
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    glPixelTransferf(GL_GREEN_SCALE, 1.0f);
    glPixelTransferf(GL_BLUE_SCALE, 1.0f);
    glPixelTransferf(GL_ALPHA_SCALE, 1.0f);
    glPixelTransferf(GL_RED_BIAS, 0.0f);
    glPixelTransferf(GL_GREEN_BIAS, 0.0f);
    glPixelTransferf(GL_BLUE_BIAS, 0.0f);
    glPixelTransferf(GL_ALPHA_BIAS, 0.0f);
    glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.0f);
    glPixelTransferi(GL_MAP_COLOR, GL_FALSE);
}

static void odd_transfer(void)
{
    glPixelTransferf(GL_RED_SCALE, 0.7f);
    glPixelTransferf(GL_GREEN_SCALE, 1.9f);
    glPixelTransferf(GL_BLUE_SCALE, -0.5f);
    glPixelTransferf(GL_RED_BIAS, 0.1f);
    glPixelTransferf(GL_BLUE_BIAS, 0.8f);
    glPixelTransferf(GL_ALPHA_SCALE, 0.45f);
    glPixelTransferf(GL_ALPHA_BIAS, 0.3f);
}

static void dump_tex(GLenum target, const char *name, int n)
{
    reset_transfer();
    memset(got, 0xcd, sizeof got);
    glGetTexImage(target, 0, GL_RGBA, GL_UNSIGNED_BYTE, got);
    sgl_data(out, name, (size_t)n * 4, got);
}

int main(int argc, char **argv)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    static unsigned char ub[TW * TH * TD * 4];
    static signed char sb[TW * TH * 4];
    static unsigned short us565[TW * TH];
    static unsigned short usz[TW * TH];
    static float fl[TW * TH * TD * 4];
    static float flz[TW * TH];
    static unsigned char zbuf[W * H * 4 * 2];
    GLfloat rmap[4] = {0.9f, 0.1f, 0.6f, 0.25f}, gmap[3] = {0.0f, 1.0f, 0.33f};
    GLfloat bmap[2] = {0.75f, 0.2f}, amap[5] = {1.0f, 0.8f, 0.6f, 0.4f, 0.2f};
    GLuint tex[12], list;
    int i, t = 0;
    static const GLenum types[7] = {GL_UNSIGNED_INT, GL_UNSIGNED_SHORT, GL_UNSIGNED_BYTE,
                                    GL_FLOAT, GL_SHORT, GL_INT, GL_BYTE};
    static const int tsize[7] = {4, 2, 1, 4, 2, 4, 1};
    out = sgl_open(argc, argv);
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    for (i = 0; i < TW * TH * TD * 4; i++) {
        ub[i] = (unsigned char)(i * 37 + 11);
        fl[i] = sgl_randf() * 1.3f - 0.15f;
    }
    for (i = 0; i < TW * TH; i++) {
        sb[i * 4 + 0] = (signed char)(i * 13 - 60);
        sb[i * 4 + 1] = (signed char)(i * 7 - 128);
        sb[i * 4 + 2] = (signed char)(127 - i * 3);
        sb[i * 4 + 3] = (signed char)(i * 5);
        us565[i] = (unsigned short)(i * 1021 + 77);
        usz[i] = (unsigned short)(i * 997 + 3);
        flz[i] = (float)i / (TW * TH - 1) * 1.2f - 0.1f;
    }
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGenTextures(12, tex);

    /* 1: RGBA8 from RGBA ubyte, scale and bias (values out of [0,1] too) */
    odd_transfer();
    glBindTexture(GL_TEXTURE_2D, tex[t++]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, TW, TH, 0, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    dump_tex(GL_TEXTURE_2D, "rgba8_ubyte_scale_bias", TW * TH);

    /* 2: RGB from float data, scale/bias then the colour maps */
    odd_transfer();
    glPixelMapfv(GL_PIXEL_MAP_R_TO_R, 4, rmap);
    glPixelMapfv(GL_PIXEL_MAP_G_TO_G, 3, gmap);
    glPixelMapfv(GL_PIXEL_MAP_B_TO_B, 2, bmap);
    glPixelMapfv(GL_PIXEL_MAP_A_TO_A, 5, amap);
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    glBindTexture(GL_TEXTURE_2D, tex[t++]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, TW, TH, 0, GL_RGBA, GL_FLOAT, fl);
    dump_tex(GL_TEXTURE_2D, "rgb_float_maps", TW * TH);

    /* 3: LUMINANCE from RGB ubyte with a bias; LUMINANCE data into RGBA */
    glPixelTransferf(GL_RED_BIAS, -0.2f);
    glPixelTransferf(GL_GREEN_BIAS, 0.5f);
    glBindTexture(GL_TEXTURE_2D, tex[t++]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, TW, TH, 0, GL_RGB, GL_UNSIGNED_BYTE, ub);
    dump_tex(GL_TEXTURE_2D, "luminance_bias", TW * TH);
    glPixelTransferf(GL_ALPHA_BIAS, -0.3f);
    glPixelTransferf(GL_BLUE_SCALE, 0.6f);
    glBindTexture(GL_TEXTURE_2D, tex[t++]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, TW, TH, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, ub);
    dump_tex(GL_TEXTURE_2D, "rgba_from_luminance", TW * TH);

    /* 4: fewer stored bits; signed, packed and BGRA data */
    odd_transfer();
    glBindTexture(GL_TEXTURE_2D, tex[t++]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB5_A1, TW, TH, 0, GL_RGBA, GL_BYTE, sb);
    dump_tex(GL_TEXTURE_2D, "rgb5a1_byte", TW * TH);
    odd_transfer();
    glBindTexture(GL_TEXTURE_2D, tex[t++]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA4, TW, TH, 0, GL_RGB, GL_UNSIGNED_SHORT_5_6_5,
                 us565);
    dump_tex(GL_TEXTURE_2D, "rgba4_565", TW * TH);
    odd_transfer();
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    glBindTexture(GL_TEXTURE_2D, tex[t++]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, TW, TH, 0, GL_BGRA, GL_UNSIGNED_BYTE, ub);
    /* 5: a sub-image under other maps */
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    glPixelTransferf(GL_RED_BIAS, 0.0f);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 2, 3, 4, 3, GL_RGBA, GL_FLOAT, fl);
    dump_tex(GL_TEXTURE_2D, "bgra_maps_sub", TW * TH);

    /* 6: 1D and 3D images */
    odd_transfer();
    glBindTexture(GL_TEXTURE_1D, tex[t++]);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, TW, 0, GL_RGBA, GL_UNSIGNED_BYTE, ub + 40);
    dump_tex(GL_TEXTURE_1D, "tex1d", TW);
    odd_transfer();
    glBindTexture(GL_TEXTURE_3D, tex[t++]);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, TW, TH, TD, 0, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glPixelTransferf(GL_GREEN_BIAS, -0.4f);
    glTexSubImage3D(GL_TEXTURE_3D, 0, 1, 1, 1, 3, 2, 1, GL_RGBA, GL_FLOAT, fl);
    dump_tex(GL_TEXTURE_3D, "tex3d", TW * TH * TD);

    /* 7: copies from the framebuffer */
    reset_transfer();
    glClearColor(0.2f, 0.4f, 0.6f, 0.8f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glBegin(GL_TRIANGLES);
    glColor4f(1.0f, 0.0f, 0.5f, 1.0f);
    glVertex3f(-1.0f, -1.0f, -0.5f);
    glColor4f(0.0f, 1.0f, 0.25f, 0.5f);
    glVertex3f(1.0f, -1.0f, 0.3f);
    glColor4f(0.3f, 0.2f, 1.0f, 0.0f);
    glVertex3f(-1.0f, 1.0f, 0.9f);
    glEnd();
    glDisable(GL_DEPTH_TEST);
    /* Colour copies are one row high: Mesa 22.3's CPU copy under pixel transfer
     * (st_cb_texture.c fallback_copy_texsubimage, unpack.Invert on an OSMesa
     * framebuffer) stores only the top source row, into the first row, and
     * leaves the other rows of the region unwritten (uninitialised memory). */
    odd_transfer();
    glBindTexture(GL_TEXTURE_2D, tex[t++]);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 3, 2, TW, 1, 0);
    dump_tex(GL_TEXTURE_2D, "copy_tex_image", TW);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, TW, TH, 0, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    odd_transfer();
    glPixelTransferi(GL_MAP_COLOR, GL_TRUE);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 1, 1, 20, 5, 5, 1);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 2, 6, 30, 25, 6, 1);
    dump_tex(GL_TEXTURE_2D, "copy_tex_sub_image", TW * TH);
    odd_transfer();
    glBindTexture(GL_TEXTURE_3D, tex[8]);
    glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 2, 2, 0, 9, 9, 5, 1);
    dump_tex(GL_TEXTURE_3D, "copy_tex_sub_image_3d", TW * TH * TD);

    /* 8: depth textures */
    glPixelTransferf(GL_DEPTH_SCALE, 0.8f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.15f);
    glBindTexture(GL_TEXTURE_2D, tex[t++]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, TW, TH, 0, GL_DEPTH_COMPONENT,
                 GL_FLOAT, flz);
    reset_transfer();
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, gotz);
    sgl_data(out, "depth_float_scale_bias", sizeof gotz, gotz);
    glPixelTransferf(GL_DEPTH_SCALE, 1.5f);
    glPixelTransferf(GL_DEPTH_BIAS, -0.2f);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, TW, TH, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_SHORT, usz);
    reset_transfer();
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, gotz);
    sgl_data(out, "depth_ushort_scale_bias", sizeof gotz, gotz);
    glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.3f);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 10, 4, TW, TH, 0);
    reset_transfer();
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, gotz);
    sgl_data(out, "depth_copy_scale_bias", sizeof gotz, gotz);
    glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
    glPixelTransferf(GL_DEPTH_BIAS, 0.3f);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, 10, 4, TW, TH, 0);
    reset_transfer();
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, gotz);
    sgl_data(out, "depth16_copy_scale_bias", sizeof gotz, gotz);

    /* 9: depth reads in every type, without and with scale/bias */
    for (i = 0; i < 7; i++) {
        char name[64];
        memset(zbuf, 0xab, sizeof zbuf);
        reset_transfer();
        glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, types[i], zbuf);
        snprintf(name, sizeof name, "read_depth_type%d", i);
        sgl_data(out, name, (size_t)W * H * tsize[i], zbuf);
        glPixelTransferf(GL_DEPTH_SCALE, 1.7f);
        glPixelTransferf(GL_DEPTH_BIAS, -0.35f);
        memset(zbuf, 0xab, sizeof zbuf);
        glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, types[i], zbuf);
        snprintf(name, sizeof name, "read_depth_scaled_type%d", i);
        sgl_data(out, name, (size_t)W * H * tsize[i], zbuf);
    }

    /* 10: a display list compiled under one transfer state and run under another */
    reset_transfer();
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, TW, TH, 0, GL_RGBA, GL_UNSIGNED_BYTE, ub);
    glEndList();
    odd_transfer();
    glBindTexture(GL_TEXTURE_2D, tex[t++]);
    glCallList(list);
    dump_tex(GL_TEXTURE_2D, "list_run_with_transfer", TW * TH);

    /* draw a few of the textures */
    reset_transfer();
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    for (i = 0; i < 4; i++) {
        float x0 = -1.0f + 0.5f * (float)i;
        glBindTexture(GL_TEXTURE_2D, tex[i == 3 ? 9 : i]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glBegin(GL_QUADS);
        glTexCoord2f(0, 0);
        glVertex2f(x0, -1.0f);
        glTexCoord2f(1, 0);
        glVertex2f(x0 + 0.5f, -1.0f);
        glTexCoord2f(1, 1);
        glVertex2f(x0 + 0.5f, 1.0f);
        glTexCoord2f(0, 1);
        glVertex2f(x0, 1.0f);
        glEnd();
    }
    glFinish();
    sgl_image(out, "drawn", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "error", "%#x", glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
