/* tex_aniso: GL_EXT_texture_filter_anisotropic on the perspective
 * checkerboard ground plane (tex_truth_plane.h: untinted hand-made mip chain,
 * GL_LINEAR_MIPMAP_LINEAR), with GL_TEXTURE_MAX_ANISOTROPY_EXT 1, 2, 4, 8 and
 * 16, one 256x256 image each, plus the implementation's maximum.
 *
 * softgl's anisotropic filter deliberately differs from llvmpipe's EWA
 * (src/texture/sample.rs), so tests/osmesa_compare.rs only checks that the
 * scene runs and has the same blocks; tests/aniso_truth.rs judges both
 * renderers against the analytic ground truth. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"
#include "tex_truth_plane.h"

#define W 256
#define H 256

int main(int argc, char **argv)
{
    static const float levels[5] = {1.0f, 2.0f, 4.0f, 8.0f, 16.0f};
    static const char *names[5] = {"aniso1", "aniso2", "aniso4", "aniso8", "aniso16"};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    GLfloat max_aniso = 0.0f;
    GLuint tex;
    int i;

    glGetFloatv(GL_MAX_TEXTURE_MAX_ANISOTROPY_EXT, &max_aniso);
    sgl_text(out, "max_anisotropy", "%g\n", (double)max_aniso);
    tex = sgl_truth_texture();
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_DEPTH_TEST);
    for (i = 0; i < 5; i++) {
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_ANISOTROPY_EXT, levels[i]);
        sgl_truth_draw(W, H);
        glFinish();
        SGL_CHECK(glGetError() == GL_NO_ERROR);
        sgl_image(out, names[i], W, H, 4, "RGBA", W * 4, 1, buf);
    }
    sgl_close(out);
    glDeleteTextures(1, &tex);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
