/* tex_depth_stencil: packed depth-stencil textures (GL_EXT_packed_depth_stencil, GL 3.0).
 * A GL_DEPTH24_STENCIL8 texture uploaded with GL_DEPTH_STENCIL/GL_UNSIGNED_INT_24_8 data
 * (a depth bump with a stencil pattern) is sampled as MuJoCo samples its shadow map:
 * GL_COMPARE_R_TO_TEXTURE, GEQUAL, GL_INTENSITY, NEAREST, CLAMP_TO_EDGE, against r ramps,
 * then with LINEAR and LUMINANCE, and without comparison. A 2048x2048 texture allocated
 * with NULL data gets a glTexSubImage2D patch and a glCopyTexSubImage2D of the depth and
 * stencil buffers (drawn with texgen from the light's view, as tex_depth_shadow does).
 * glGetTexImage of GL_DEPTH_STENCIL and GL_DEPTH_COMPONENT, pixel transfer on upload,
 * level queries and Mesa's errors. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256
#define N 32
#define BIG 2048

static void quad_str(float x0, float y0, float x1, float y1, float r0, float r1)
{
    glBegin(GL_QUADS);
    glTexCoord3f(0.0f, 0.0f, r0);
    glVertex2f(x0, y0);
    glTexCoord3f(1.0f, 0.0f, r1);
    glVertex2f(x1, y0);
    glTexCoord3f(1.0f, 1.0f, r1);
    glVertex2f(x1, y1);
    glTexCoord3f(0.0f, 1.0f, r0);
    glVertex2f(x0, y1);
    glEnd();
}

/* planes facing the light (constant depth in its view, so that the copied depth values
 * do not depend on the rasteriser's interpolation arithmetic) */
static void scene(void)
{
    glColor4f(0.92f, 0.86f, 0.62f, 1.0f);
    glBegin(GL_QUADS);
    glVertex3f(-1.6f, -1.6f, -0.5f);
    glVertex3f(1.6f, -1.6f, -0.5f);
    glVertex3f(1.6f, 1.6f, -0.5f);
    glVertex3f(-1.6f, 1.6f, -0.5f);
    glColor4f(1.0f, 0.52f, 0.42f, 1.0f);
    glVertex3f(-0.7f, -0.4f, 0.3f);
    glVertex3f(0.5f, -0.6f, 0.3f);
    glVertex3f(0.6f, 0.7f, 0.3f);
    glVertex3f(-0.5f, 0.5f, 0.3f);
    glColor4f(0.5f, 0.8f, 1.0f, 1.0f);
    glVertex3f(0.2f, 0.1f, 0.9f);
    glVertex3f(1.1f, 0.1f, 0.9f);
    glVertex3f(1.1f, 1.0f, 0.9f);
    glVertex3f(0.2f, 1.0f, 0.9f);
    glEnd();
}

static void light_view(void)
{
    glOrtho(-2.0, 2.0, -2.0, 2.0, 1.0, 8.0);
    glTranslatef(0.0f, 0.0f, -4.0f);
}

int main(int argc, char **argv)
{
    static const GLfloat sp[4] = {1, 0, 0, 0}, tp[4] = {0, 1, 0, 0};
    static const GLfloat rp[4] = {0, 0, 1, 0}, qp[4] = {0, 0, 0, 1};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    GLuint tex[4], ds[N * N], back[N * N], patch[64 * 64];
    float fback[N * N];
    GLint v[16];
    int i, x, y;

    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    /* a depth bump (values spread over the whole 24 bits) with a stencil pattern */
    for (y = 0; y < N; y++)
        for (x = 0; x < N; x++) {
            float dx = (x - 15.5f) / 16.0f, dy = (y - 13.5f) / 16.0f;
            float d = 0.85f - 0.7f * (1.0f - dx * dx - dy * dy) * (1.0f - dx * dx - dy * dy);
            GLuint z = (GLuint)(d * 16777215.0f) ^ (GLuint)((x * 7 + y * 13) & 15);
            ds[y * N + x] = (z << 8) | (GLuint)((x * 37 + y * 11) & 255);
        }
    glGenTextures(4, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);

    /* 1: MuJoCo's shadow sampling state on an uploaded DEPTH24_STENCIL8 texture */
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, N, N, 0, GL_DEPTH_STENCIL,
                 GL_UNSIGNED_INT_24_8, ds);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
    glClearColor(0.1f, 0.15f, 0.2f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    sgl_ortho(W, H);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor4f(0.9f, 0.8f, 0.55f, 1.0f);
    for (i = 0; i < 4; i++)
        quad_str(2.0f + 40.0f * i, 2.0f, 40.0f + 40.0f * i, 60.0f, 0.1f + 0.2f * i,
                 0.3f + 0.2f * i);
    /* intensity drives alpha: blend it over */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glColor4f(0.3f, 0.9f, 0.6f, 0.8f);
    quad_str(164.0f, 2.0f, 254.0f, 60.0f, 0.0f, 1.0f);
    glDisable(GL_BLEND);
    /* LINEAR, LUMINANCE; then no comparison (the depth itself), minified */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
    glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    quad_str(2.0f, 64.0f, 90.0f, 126.0f, 0.2f, 0.8f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_NONE);
    quad_str(94.0f, 64.0f, 182.0f, 126.0f, 0.0f, 0.0f);
    quad_str(186.0f, 64.0f, 206.0f, 84.0f, 0.0f, 0.0f);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    quad_str(210.0f, 64.0f, 254.0f, 126.0f, 0.0f, 0.0f);
    glDisable(GL_TEXTURE_2D);

    /* 2: a 2048 map allocated empty, then a light pass copied into its corner
     * (depth and stencil), and a patch uploaded beside it */
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0x5a, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glViewport(0, 128, 128, 128);
    glScissor(0, 128, 128, 128);
    glEnable(GL_SCISSOR_TEST);
    glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    light_view();
    /* (no polygon offset: softgl's offset depth is one ulp above llvmpipe's on this
     * plane, which the copy would show) */
    scene();
    glDisable(GL_STENCIL_TEST);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, BIG, BIG, 0, GL_DEPTH_STENCIL,
                 GL_UNSIGNED_INT_24_8, NULL);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 0, 128, 128, 128);
    for (y = 0; y < 64; y++)
        for (x = 0; x < 64; x++)
            patch[y * 64 + x] = ds[(y / 2) * N + x / 2] ^ 0x00abc000u;
    glTexSubImage2D(GL_TEXTURE_2D, 0, 128, 0, 64, 64, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8,
                    patch);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &v[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
    /* camera pass: the map covers [0, 128/2048] of s and t */
    glClear(GL_DEPTH_BUFFER_BIT);
    glViewport(128, 128, 128, 128);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glScalef(128.0f / BIG, 128.0f / BIG, 1.0f);
    glTranslatef(0.5f, 0.5f, 0.5f);
    glScalef(0.5f, 0.5f, 0.5f);
    light_view();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.1f, -4.6f);
    glRotatef(-35.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(25.0f, 0.0f, 1.0f, 0.0f);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_S, GL_OBJECT_PLANE, sp);
    glTexGenfv(GL_T, GL_OBJECT_PLANE, tp);
    glTexGenfv(GL_R, GL_OBJECT_PLANE, rp);
    glTexGenfv(GL_Q, GL_OBJECT_PLANE, qp);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_GEN_R);
    glEnable(GL_TEXTURE_GEN_Q);
    glEnable(GL_TEXTURE_2D);
    /* lit where the fragment's depth is at most the light's */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    scene();
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glDisable(GL_TEXTURE_GEN_R);
    glDisable(GL_TEXTURE_GEN_Q);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);
    /* the patch, GEQUAL */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_GEQUAL);
    sgl_ortho(W, H);
    glColor4f(0.7f, 0.9f, 1.0f, 1.0f);
    glMatrixMode(GL_TEXTURE);
    glTranslatef(128.0f / BIG, 0.0f, 0.0f);
    glScalef(64.0f / BIG, 64.0f / BIG, 1.0f);
    glMatrixMode(GL_MODELVIEW);
    quad_str(2.0f, 130.0f, 124.0f, 252.0f, 0.2f, 0.9f);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glDisable(GL_TEXTURE_2D);
    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);

    /* readback of the copied corner (depth and stencil) and of the patch */
    {
        static GLuint whole[256 * 4];
        GLuint *all = malloc((size_t)BIG * BIG * 4);
        SGL_CHECK(all != NULL);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, all);
        for (y = 0; y < 4; y++)
            memcpy(whole + 256 * y, all + (size_t)BIG * (y * 37), 256 * 4);
        sgl_data(out, "big_rows", sizeof whole, whole);
        free(all);
    }

    /* 3: readback of the uploaded texture */
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, back);
    sgl_data(out, "ds_back", sizeof back, back);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, back);
    sgl_data(out, "uint_back", sizeof back, back);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, fback);
    sgl_data(out, "float_back", sizeof fback, fback);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, back);
    sgl_data(out, "ushort_back", N * N * 2, back);
    /* glTexSubImage2D of DS data, then the readback again */
    glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 5, 4, 2, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, ds);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, back);
    sgl_data(out, "ds_sub_back", sizeof back, back);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &v[1]);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE, &v[2]);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &v[3]);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &v[4]);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_LUMINANCE_SIZE, &v[5]);

    /* unsized GL_DEPTH_STENCIL, with depth scale and index offset on upload */
    glBindTexture(GL_TEXTURE_2D, tex[2]);
    glPixelTransferf(GL_DEPTH_SCALE, 0.5f);
    glPixelTransferi(GL_INDEX_OFFSET, 3);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, N, N, 0, GL_DEPTH_STENCIL,
                 GL_UNSIGNED_INT_24_8, ds);
    glPixelTransferf(GL_DEPTH_SCALE, 1.0f);
    glPixelTransferi(GL_INDEX_OFFSET, 0);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, back);
    sgl_data(out, "transfer_back", sizeof back, back);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &v[6]);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE, &v[7]);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &v[8]);
    /* DS data into DEPTH_COMPONENT16/24: the depth part only */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT16, N, N, 0, GL_DEPTH_STENCIL,
                 GL_UNSIGNED_INT_24_8, ds);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, back);
    sgl_data(out, "z16_back", sizeof back, back);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE, &v[9]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, N, N, 0, GL_DEPTH_STENCIL,
                 GL_UNSIGNED_INT_24_8, ds);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, back);
    sgl_data(out, "z24_back", sizeof back, back);
    /* GL_UNSIGNED_INT depth into 24 bits: Mesa's float path */
    for (i = 0; i < N * N; i++)
        back[i] = ds[i] | 0xff000000u;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, N, N, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT, back);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, back);
    sgl_data(out, "uint_into_z24", sizeof back, back);
    sgl_text(out, "queries", "%d %d %d %x %d %d %d %d %x %d", v[0], v[1], v[2], v[3], v[4],
             v[5], v[6], v[7], v[8], v[9]);

    /* errors */
    glBindTexture(GL_TEXTURE_2D, tex[3]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 2, 2, 0, GL_DEPTH_STENCIL,
                 GL_UNSIGNED_BYTE, ds);
    v[0] = glGetError();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, ds);
    v[1] = glGetError();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, ds);
    v[2] = glGetError();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_INT_24_8, ds);
    v[3] = glGetError();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 2, 2, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT_24_8, ds);
    v[4] = glGetError();
    glTexImage3D(GL_TEXTURE_3D, 0, GL_DEPTH24_STENCIL8, 2, 2, 1, 0, GL_DEPTH_STENCIL,
                 GL_UNSIGNED_INT_24_8, ds);
    v[5] = glGetError();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 2, 2, 0, GL_DEPTH_STENCIL,
                 GL_UNSIGNED_INT_24_8, ds);
    v[6] = glGetError();
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    v[7] = glGetError();
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_BYTE, back);
    v[8] = glGetError();
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_24_8, back);
    v[9] = glGetError();
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, ds);
    v[10] = glGetError();
    glGenerateMipmap(GL_TEXTURE_2D);
    v[11] = glGetError();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                 fback);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, back);
    v[12] = glGetError();
    glTexImage1D(GL_TEXTURE_1D, 0, GL_DEPTH24_STENCIL8, 2, 0, GL_DEPTH_STENCIL,
                 GL_UNSIGNED_INT_24_8, ds);
    v[13] = glGetError();
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_DEPTH24_STENCIL8, 64, 64, 0, GL_DEPTH_STENCIL,
                 GL_UNSIGNED_INT_24_8, NULL);
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_2D, 0, GL_TEXTURE_STENCIL_SIZE, &v[14]);
    v[15] = glGetError();
    sgl_text(out, "errors", "%x %x %x %x %x %x %x %x %x %x %x %x %x %x %d %x", v[0], v[1],
             v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11], v[12], v[13], v[14],
             v[15]);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
