/* tex_lod_params: level-of-detail controls on a minified ground plane with a
 * hand-made, per-level tinted mip chain (64x64 .. 1x1).  Twelve settings,
 * four 128x128 viewports per image: GL_TEXTURE_MIN_LOD, GL_TEXTURE_MAX_LOD,
 * both, GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL, GL_TEXTURE_LOD_BIAS as
 * a texture parameter (positive and negative), the GL_TEXTURE_FILTER_CONTROL
 * texture-environment bias, both biases together, and MAX_LEVEL 0, with
 * LINEAR_MIPMAP_LINEAR and some with NEAREST_MIPMAP_NEAREST. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256

struct lod {
    GLint min_filter;
    float min_lod, max_lod, bias, env_bias;
    int base, max_level;
};

static const struct lod cfg[12] = {
    {GL_LINEAR_MIPMAP_LINEAR, -1000.0f, 1000.0f, 0.0f, 0.0f, 0, 1000},
    {GL_LINEAR_MIPMAP_LINEAR, 1.5f, 1000.0f, 0.0f, 0.0f, 0, 1000},
    {GL_LINEAR_MIPMAP_LINEAR, -1000.0f, 2.3f, 0.0f, 0.0f, 0, 1000},
    {GL_LINEAR_MIPMAP_LINEAR, 0.7f, 1.2f, 0.0f, 0.0f, 0, 1000},
    {GL_LINEAR_MIPMAP_LINEAR, -1000.0f, 1000.0f, 0.0f, 0.0f, 1, 1000},
    {GL_LINEAR_MIPMAP_LINEAR, -1000.0f, 1000.0f, 0.0f, 0.0f, 2, 3},
    {GL_LINEAR_MIPMAP_LINEAR, -1000.0f, 1000.0f, 1.7f, 0.0f, 0, 1000},
    {GL_LINEAR_MIPMAP_LINEAR, -1000.0f, 1000.0f, -0.9f, 0.6f, 0, 1000},
    {GL_NEAREST_MIPMAP_NEAREST, -1000.0f, 1000.0f, 0.0f, 1.3f, 0, 1000},
    {GL_NEAREST_MIPMAP_NEAREST, 0.4f, 3.6f, 0.3f, 0.0f, 1, 5},
    {GL_LINEAR_MIPMAP_LINEAR, -1000.0f, 1000.0f, 0.0f, 0.0f, 0, 0},
    {GL_NEAREST_MIPMAP_LINEAR, -2.5f, 1000.0f, -2.1f, 0.37f, 0, 1000},
};

int main(int argc, char **argv)
{
    static const unsigned char black[4] = {0, 0, 0, 255}, white[4] = {255, 255, 255, 255};
    static const char *names[3] = {"lod_clamps", "levels_bias", "more"};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    unsigned char *checker = sgl_checker(64, 64, 4, 4, black, white);
    GLuint tex;
    int i;

    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    sgl_upload_mips(checker, 64, 64);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_DEPTH_TEST);
    glClearColor(0.31f, 0.47f, 0.73f, 1.0f);
    for (i = 0; i < 12; i++) {
        const struct lod *c = &cfg[i];
        if (i % 4 == 0)
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, c->min_filter);
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MIN_LOD, c->min_lod);
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_MAX_LOD, c->max_lod);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, c->base);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, c->max_level);
        glTexParameterf(GL_TEXTURE_2D, GL_TEXTURE_LOD_BIAS, c->bias);
        glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, c->env_bias);
        glViewport(128 * (i % 2), 128 * ((i % 4) / 2), 128, 128);
        sgl_ground_view(1.0);
        sgl_ground_plane(2.3f);
        if (i % 4 == 3) {
            glFinish();
            SGL_CHECK(glGetError() == GL_NO_ERROR);
            sgl_image(out, names[i / 4], W, H, 4, "RGBA", W * 4, 1, buf);
        }
    }
    sgl_close(out);
    free(checker);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
