/* tex_filters_ground: the classic aliasing demo.  A black/white checkerboard
 * ground plane runs to the horizon under a perspective projection, drawn
 * once per minification filter (NEAREST, LINEAR and the four MIPMAP
 * filters), one 256x256 image each.  The mip levels are uploaded by hand:
 * box-filtered and tinted per level so the level choice is visible. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256

int main(int argc, char **argv)
{
    static const GLenum mins[6] = {
        GL_NEAREST, GL_LINEAR, GL_NEAREST_MIPMAP_NEAREST,
        GL_LINEAR_MIPMAP_NEAREST, GL_NEAREST_MIPMAP_LINEAR, GL_LINEAR_MIPMAP_LINEAR};
    static const char *names[6] = {"nearest", "linear", "nearest_mipmap_nearest",
                                   "linear_mipmap_nearest", "nearest_mipmap_linear",
                                   "linear_mipmap_linear"};
    static const unsigned char black[4] = {0, 0, 0, 255}, white[4] = {255, 255, 255, 255};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    unsigned char *checker = sgl_checker(64, 64, 8, 8, black, white);
    GLuint tex;
    int i;

    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    sgl_upload_mips(checker, 64, 64);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_TEXTURE_2D);
    glEnable(GL_DEPTH_TEST);
    for (i = 0; i < 6; i++) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, (GLint)mins[i]);
        /* the magnification filter follows the filter of the base level */
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER,
                        (mins[i] == GL_NEAREST || mins[i] == GL_NEAREST_MIPMAP_NEAREST ||
                         mins[i] == GL_NEAREST_MIPMAP_LINEAR)
                            ? GL_NEAREST
                            : GL_LINEAR);
        glClearColor(0.31f, 0.47f, 0.73f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        glViewport(0, 0, W, H);
        sgl_ground_view(1.0);
        sgl_ground_plane(3.7f);
        glFinish();
        SGL_CHECK(glGetError() == GL_NO_ERROR);
        sgl_image(out, names[i], W, H, 4, "RGBA", W * 4, 1, buf);
    }
    sgl_close(out);
    free(checker);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
