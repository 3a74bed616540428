/* LOD bias: texture-parameter bias vs texenv (FILTER_CONTROL) bias vs both,
 * LINEAR_MIPMAP_LINEAR on a minified ground plane, one 64x64 viewport each. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "../common.h"
#include "../tex_common.h"
int main(int argc, char **argv)
{
    static const float b[8][2] = {{-0.3f, 0}, {0, -0.3f}, {-0.9f, 0.6f}, {0.6f, -0.9f},
                                  {0.3f, 0}, {0, 0.3f}, {0.9f, -0.6f}, {-0.6f, 0.9f}};
    static const unsigned char k[4] = {0, 0, 0, 255}, w[4] = {255, 255, 255, 255};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(256, 128, &buf);
    (void)ctx;
    unsigned char *c = sgl_checker(64, 64, 4, 4, k, w);
    GLuint t; int i;
    glGenTextures(1, &t); glBindTexture(GL_TEXTURE_2D, t);
    sgl_upload_mips(c, 64, 64);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glClear(GL_COLOR_BUFFER_BIT);
    for (i = 0; i < 8; i++) {
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, b[i][0]);
        glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, b[i][1]);
        glViewport(64 * (i % 4), 64 * (i / 4), 64, 64);
        sgl_ground_view(1.0);
        sgl_ground_plane(2.3f);
    }
    glFinish();
    sgl_image(out, "color", 256, 128, 4, "RGBA", 1024, 1, buf);
    sgl_close(out);
    return 0;
}
