/* tex3d: GL_TEXTURE_3D (GL 1.2).  An 8x8x8 RGBA volume with a different
 * pattern per slice: quads through single slices (NEAREST), oblique cuts with
 * r varying (LINEAR, REPEAT and CLAMP_TO_EDGE), GL_CLAMP and MIRRORED_REPEAT
 * on r (the float path), a non-power-of-two 5x3x6 volume with REPEAT, a
 * mipmapped volume (GL_GENERATE_MIPMAP, LINEAR_MIPMAP_LINEAR) on a
 * perspective plane with r from EYE_LINEAR texgen and the texture matrix,
 * glTexSubImage3D with UNPACK_IMAGE_HEIGHT/SKIP_IMAGES, glCopyTexSubImage3D,
 * 3D winning over 2D, proxies, queries and errors. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256

static unsigned char vol[8 * 8 * 8 * 4];

static void quad3(float x0, float y0, float x1, float y1, const float *t0, const float *t1,
                  const float *t2, const float *t3)
{
    glBegin(GL_QUADS);
    glTexCoord3fv(t0);
    glVertex2f(x0, y0);
    glTexCoord3fv(t1);
    glVertex2f(x1, y0);
    glTexCoord3fv(t2);
    glVertex2f(x1, y1);
    glTexCoord3fv(t3);
    glVertex2f(x0, y1);
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    unsigned char npot[5 * 3 * 6 * 4], sub[2 * 4 * 3 * 3 * 4], back[8 * 8 * 8 * 4];
    GLuint tex[4];
    GLint v[8];
    int x, y, z, i;
    unsigned sum = 0;

    for (z = 0; z < 8; z++)
        for (y = 0; y < 8; y++)
            for (x = 0; x < 8; x++) {
                unsigned char *p = vol + 4 * ((z * 8 + y) * 8 + x);
                int on = ((x / 2 + y / 2 + z) & 1);
                p[0] = (unsigned char)(z * 36);
                p[1] = on ? 230 : (unsigned char)(x * 30);
                p[2] = (unsigned char)(255 - y * 32);
                p[3] = (unsigned char)(150 + z * 13);
            }
    for (i = 0; i < 5 * 3 * 6; i++) {
        npot[4 * i] = (unsigned char)(i * 37);
        npot[4 * i + 1] = (unsigned char)(i * 91);
        npot[4 * i + 2] = (unsigned char)(255 - i * 3);
        npot[4 * i + 3] = 255;
    }
    for (i = 0; i < (int)sizeof(sub); i++)
        sub[i] = (unsigned char)(i * 7 + 11);

    glGenTextures(4, tex);
    glBindTexture(GL_TEXTURE_3D, tex[0]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, vol);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

    glEnable(GL_TEXTURE_3D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    sgl_ortho(W, H);
    glClearColor(0.1f, 0.1f, 0.1f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    /* single slices, NEAREST */
    for (z = 0; z < 8; z++) {
        float r = (z + 0.5f) / 8.0f;
        float a[3] = {0, 0, r}, b[3] = {1, 0, r}, c[3] = {1, 1, r}, d[3] = {0, 1, r};
        quad3(2.0f + 31.0f * z, 2.0f, 31.0f + 31.0f * z, 31.0f, a, b, c, d);
    }
    /* oblique cuts, LINEAR, REPEAT then CLAMP_TO_EDGE, then GL_CLAMP / MIRRORED on r */
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    for (i = 0; i < 4; i++) {
        static const GLint wraps[4] = {GL_REPEAT, GL_CLAMP_TO_EDGE, GL_CLAMP, GL_MIRRORED_REPEAT};
        float a[3] = {-0.3f, -0.2f, -0.4f}, b[3] = {1.3f, 0.1f, 0.6f};
        float c[3] = {1.1f, 1.4f, 1.7f}, d[3] = {0.2f, 1.2f, 0.3f};
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, wraps[i]);
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, i == 1 ? GL_CLAMP_TO_EDGE : GL_REPEAT);
        quad3(3.3f + 62.0f * i, 35.1f, 63.7f + 62.0f * i, 95.3f, a, b, c, d);
    }
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_S, GL_REPEAT);

    /* non-power-of-two volume, REPEAT, NEAREST and LINEAR */
    glBindTexture(GL_TEXTURE_3D, tex[1]);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 5, 3, 6, 0, GL_RGBA, GL_UNSIGNED_BYTE, npot);
    for (i = 0; i < 2; i++) {
        float a[3] = {-0.7f, 0.1f, -0.3f}, b[3] = {1.6f, -0.4f, 0.9f};
        float c[3] = {1.2f, 1.9f, 2.2f}, d[3] = {0.1f, 1.1f, 1.1f};
        GLint f = i ? GL_LINEAR : GL_NEAREST;
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, f);
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, f);
        quad3(3.1f + 64.0f * i, 99.2f, 62.9f + 64.0f * i, 127.6f, a, b, c, d);
    }

    /* sub-image with image height / skip images, then copy a framebuffer rectangle */
    glBindTexture(GL_TEXTURE_3D, tex[0]);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 4);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, 1);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    glTexSubImage3D(GL_TEXTURE_3D, 0, 3, 2, 4, 2, 3, 2, GL_RGBA, GL_UNSIGNED_BYTE, sub);
    glPixelStorei(GL_UNPACK_IMAGE_HEIGHT, 0);
    glPixelStorei(GL_UNPACK_SKIP_IMAGES, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 1, 1, 6, 40, 40, 5, 4);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    for (z = 0; z < 8; z++) {
        float r = (z + 0.5f) / 8.0f;
        float a[3] = {0, 0, r}, b[3] = {1, 0, r}, c[3] = {1, 1, r}, d[3] = {0, 1, r};
        quad3(130.0f + 15.0f * (z & 3), 99.0f + 15.0f * (z >> 2), 144.0f + 15.0f * (z & 3),
              113.0f + 15.0f * (z >> 2), a, b, c, d);
    }
    glGetTexImage(GL_TEXTURE_3D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    for (i = 0; i < (int)sizeof(back); i++)
        sum = sum * 31u + back[i];
    sgl_text(out, "getteximage", "%08x", sum);

    /* 3D wins over 2D */
    glBindTexture(GL_TEXTURE_2D, tex[3]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, sub);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    {
        float a[3] = {0, 0, 0.3f}, b[3] = {1, 0, 0.3f}, c[3] = {1, 1, 0.3f}, d[3] = {0, 1, 0.3f};
        quad3(200.0f, 99.0f, 250.0f, 127.0f, a, b, c, d);
    }
    glDisable(GL_TEXTURE_2D);

    /* mipmapped volume on a plane: r from eye-linear texgen, scaled by the texture matrix */
    glBindTexture(GL_TEXTURE_3D, tex[2]);
    glTexParameteri(GL_TEXTURE_3D, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 8, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, vol);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glEnable(GL_DEPTH_TEST);
    glViewport(0, 128, 256, 128);
    {
        static const GLfloat plane_r[4] = {0.0f, 0.13f, 0.05f, 0.2f};
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
        glTexGenfv(GL_R, GL_EYE_PLANE, plane_r);
        glEnable(GL_TEXTURE_GEN_R);
        glMatrixMode(GL_TEXTURE);
        glLoadIdentity();
        glScalef(1.0f, 1.0f, 1.7f);
        glTranslatef(0.0f, 0.0f, 0.11f);
    }
    sgl_ground_view(2.0);
    sgl_ground_plane(3.1f);
    glDisable(GL_TEXTURE_GEN_R);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);

    /* queries */
    glBindTexture(GL_TEXTURE_3D, tex[1]);
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &v[0]);
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_HEIGHT, &v[1]);
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &v[2]);
    glGetIntegerv(GL_TEXTURE_BINDING_3D, &v[3]);
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &v[4]);
    v[5] = glIsEnabled(GL_TEXTURE_3D);
    glGetTexParameteriv(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, &v[6]);
    glBindTexture(GL_TEXTURE_3D, tex[2]);
    glGetTexLevelParameteriv(GL_TEXTURE_3D, 2, GL_TEXTURE_DEPTH, &v[7]);
    sgl_text(out, "queries", "%d %d %d %d %d %d %x %d", v[0], v[1], v[2], v[3] == (GLint)tex[1],
             v[4], v[5], v[6], v[7]);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 64, 32, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_DEPTH, &v[0]);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 4096, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, NULL);
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_3D, 0, GL_TEXTURE_WIDTH, &v[1]);
    sgl_text(out, "proxy", "%d %d err %x", v[0], v[1], glGetError());
    /* errors */
    glTexImage3D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, vol);
    v[0] = glGetError();
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, -1, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, vol);
    v[1] = glGetError();
    glTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 7, 2, 2, 2, GL_RGBA, GL_UNSIGNED_BYTE, vol);
    v[2] = glGetError();
    glTexImage2D(GL_TEXTURE_3D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, vol);
    v[3] = glGetError();
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_LINEAR);
    v[4] = glGetError();
    glCopyTexSubImage3D(GL_TEXTURE_3D, 0, 0, 0, 9, 0, 0, 2, 2);
    v[5] = glGetError();
    sgl_text(out, "errors", "%x %x %x %x %x %x", v[0], v[1], v[2], v[3], v[4], v[5]);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
