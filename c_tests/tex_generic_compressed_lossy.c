/* tex_generic_compressed_lossy: GL_COMPRESSED_RGB, _RGBA, _LUMINANCE and
 * _LUMINANCE_ALPHA 2D textures of smooth, photograph-like content, drawn.
 *
 * Mesa 22.3 llvmpipe stores these four as DXT1, DXT5, LATC1 and LATC2
 * blocks, encoded by its own compressor (the libtxc_dxtn-derived
 * texcompress_s3tc_tmp.h and the RGTC encoder), which is lossy; softgl stores
 * them uncompressed (see tex_generic_compressed and README's known
 * differences), so its pixels are the exact texels and Mesa's carry the
 * compression error.  The harness allows that error (TOLERANCES in
 * tests/osmesa_compare.rs); content that DXT and LATC represent exactly is
 * compared byte for byte in tex_generic_compressed. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 64
#define TS 32

int main(int argc, char **argv)
{
    static const GLenum fmts[4] = {GL_COMPRESSED_RGB, GL_COMPRESSED_RGBA,
                                   GL_COMPRESSED_LUMINANCE,
                                   GL_COMPRESSED_LUMINANCE_ALPHA};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    static unsigned char img[TS * TS * 4];
    GLuint tex[4];
    int k, x, y;

    for (y = 0; y < TS; y++)
        for (x = 0; x < TS; x++) {
            unsigned char *p = img + 4 * (y * TS + x);
            float fx = (float)x / TS, fy = (float)y / TS;
            p[0] = (unsigned char)(127.5f + 120.0f * sinf(6.0f * fx + 1.0f * fy));
            p[1] = (unsigned char)(127.5f + 120.0f * cosf(4.0f * fy - 2.0f * fx));
            p[2] = (unsigned char)(40.0f + 180.0f * fx * fy);
            p[3] = (unsigned char)(255.0f - 200.0f * fx * (1.0f - fy));
        }
    sgl_ortho(W, H);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT);
    glGenTextures(4, tex);
    glEnable(GL_TEXTURE_2D);
    for (k = 0; k < 4; k++) {
        float x0 = 64.0f * k;
        glBindTexture(GL_TEXTURE_2D, tex[k]);
        glTexImage2D(GL_TEXTURE_2D, 0, (GLint)fmts[k], TS, TS, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                     img);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glBegin(GL_QUADS);
        glTexCoord2f(0.0f, 0.0f);
        glVertex2f(x0, 0.0f);
        glTexCoord2f(1.0f, 0.0f);
        glVertex2f(x0 + 64.0f, 0.0f);
        glTexCoord2f(1.0f, 1.0f);
        glVertex2f(x0 + 64.0f, 64.0f);
        glTexCoord2f(0.0f, 1.0f);
        glVertex2f(x0, 64.0f);
        glEnd();
    }
    glFinish();
    sgl_text(out, "error", "%#x", glGetError());
    sgl_image(out, "drawn", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
