/* tex_wrap_modes: every combination of the five wrap modes on s and t
 * (REPEAT, CLAMP, CLAMP_TO_EDGE, CLAMP_TO_BORDER, MIRRORED_REPEAT), as a 5x5
 * grid of quads (s mode by column, t mode by row), with NEAREST and LINEAR
 * filtering, and with texture coordinates just outside [0,1]
 * (-1.7 .. 2.3) and far outside (-7.3 .. 9.1).  The texture is 8x4 RGBA
 * with distinct colours and a border colour is set, so GL_CLAMP's linear
 * border blend and CLAMP_TO_BORDER show. */
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
    static const GLenum modes[5] = {GL_REPEAT, GL_CLAMP, GL_CLAMP_TO_EDGE,
                                    GL_CLAMP_TO_BORDER, GL_MIRRORED_REPEAT};
    static const GLfloat border[4] = {0.93f, 0.41f, 0.07f, 0.61f};
    static const float ranges[2][4] = {
        {-1.7f, -1.3f, 2.3f, 2.1f},  /* s0, t0, s1, t1 */
        {-7.3f, -6.1f, 9.1f, 8.7f},
    };
    static const char *names[2][2] = {{"near_nearest", "near_linear"},
                                      {"far_nearest", "far_linear"}};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    unsigned char texels[4 * 8 * 4];
    GLuint tex;
    int r, f, i, j, x, y;

    for (y = 0; y < 4; y++)
        for (x = 0; x < 8; x++) {
            unsigned char *p = texels + 4 * (y * 8 + x);
            p[0] = (unsigned char)(31 * x + 17);
            p[1] = (unsigned char)(71 * y + 23);
            p[2] = (unsigned char)(((x + y) & 1) ? 229 : 37);
            p[3] = (unsigned char)(255 - 13 * (x + 8 * y));
        }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, border);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glEnable(GL_TEXTURE_2D);
    sgl_ortho(W, H);

    for (r = 0; r < 2; r++)
        for (f = 0; f < 2; f++) {
            GLint filter = f ? GL_LINEAR : GL_NEAREST;
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
            glClearColor(0.2f, 0.2f, 0.2f, 0.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            for (j = 0; j < 5; j++)
                for (i = 0; i < 5; i++) {
                    float x0 = 1.3f + 51.0f * i, y0 = 1.7f + 51.0f * j;
                    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, (GLint)modes[i]);
                    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, (GLint)modes[j]);
                    sgl_tex_quad(x0, y0, x0 + 48.9f, y0 + 48.3f, ranges[r][0],
                                 ranges[r][1], ranges[r][2], ranges[r][3]);
                }
            glFinish();
            SGL_CHECK(glGetError() == GL_NO_ERROR);
            sgl_image(out, names[r][f], W, H, 4, "RGBA", W * 4, 1, buf);
        }
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
