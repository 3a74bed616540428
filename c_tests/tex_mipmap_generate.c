/* tex_mipmap_generate: GL_GENERATE_MIPMAP (SGIS, core in GL 1.4) against
 * levels uploaded by hand.  The same 64x64 level 0 (a fine pattern of lines
 * and dots) is given to two textures: one generates its mipmaps, the other
 * gets box-filtered, tinted levels from the program.  Both are drawn side by
 * side on a perspective ground plane (LINEAR_MIPMAP_LINEAR) and as a row of
 * ever smaller quads (NEAREST_MIPMAP_NEAREST), so the lower levels show.
 * A glTexSubImage2D into level 0 regenerates the chain, and a 45x27 NPOT
 * texture generates its chain too.  The generated levels are read back with
 * glGetTexImage.  (glGenerateMipmap is GL 3.0; Mesa's libOSMesa exports it,
 * but it is not part of GL 1.5, so it is not used.) */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256

static void pattern(unsigned char *p, int w, int h)
{
    int x, y;
    for (y = 0; y < h; y++)
        for (x = 0; x < w; x++) {
            unsigned char *q = p + 4 * (y * w + x);
            int line = (x % 5 == 0) || (y % 7 == 3);
            int dot = ((x * 3 + y * 5) % 11) == 0;
            q[0] = line ? 250 : (unsigned char)(40 + 3 * x);
            q[1] = dot ? 255 : (unsigned char)(30 + 2 * y);
            q[2] = line ? 20 : (unsigned char)(200 - x - y);
            q[3] = (unsigned char)(255 - ((x + y) & 15) * 4);
        }
}

static void row_of_quads(float x, float y)
{
    float size = 32.0f;
    int i;
    for (i = 0; i < 7; i++) {
        sgl_tex_quad(x, y, x + size, y + size, 0.0f, 0.0f, 1.0f, 1.0f);
        x += size + 1.0f;
        size *= 0.5f;
    }
}

static void dump_levels(FILE *out, const char *prefix, int w, int h)
{
    static unsigned char rb[64 * 64 * 4];
    char name[64];
    int level = 0;
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    for (;;) {
        glGetTexImage(GL_TEXTURE_2D, level, GL_RGBA, GL_UNSIGNED_BYTE, rb);
        snprintf(name, sizeof name, "%s_level%d", prefix, level);
        sgl_data(out, name, (size_t)(w * h * 4), rb);
        if (w == 1 && h == 1)
            break;
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
        level++;
    }
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    static unsigned char img[64 * 64 * 4], npot[45 * 27 * 4], patch[9 * 5 * 4];
    GLuint tex[3];
    GLint gm;
    int i;

    pattern(img, 64, 64);
    pattern(npot, 45, 27);
    for (i = 0; i < 9 * 5 * 4; i++)
        patch[i] = (unsigned char)(i % 4 == 1 ? 255 : 0);
    glGenTextures(3, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, &gm);
    SGL_CHECK(gm == GL_TRUE);
    glHint(GL_GENERATE_MIPMAP_HINT, GL_NICEST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    dump_levels(out, "generated", 64, 64);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    sgl_upload_mips(img, 64, 64);
    glBindTexture(GL_TEXTURE_2D, tex[2]);
    glTexParameteri(GL_TEXTURE_2D, GL_GENERATE_MIPMAP, GL_TRUE);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 45, 27, 0, GL_RGBA, GL_UNSIGNED_BYTE, npot);
    dump_levels(out, "npot", 45, 27);

    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glClearColor(0.2f, 0.3f, 0.4f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    for (i = 0; i < 2; i++) {
        glBindTexture(GL_TEXTURE_2D, tex[i]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glViewport(128 * i, 128, 128, 128);
        sgl_ground_view(1.0);
        sgl_ground_plane(4.3f);
    }
    glDisable(GL_DEPTH_TEST);
    sgl_ortho(W, H);
    for (i = 0; i < 3; i++) {
        glBindTexture(GL_TEXTURE_2D, tex[i]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        row_of_quads(1.3f + 128.0f * (i & 1), 1.7f + 64.0f * (i >> 1));
    }
    /* a sub-image update regenerates the chain of the generated texture */
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 13, 21, 9, 5, GL_RGBA, GL_UNSIGNED_BYTE, patch);
    row_of_quads(129.3f, 65.7f);
    dump_levels(out, "regenerated", 64, 64);

    glFinish();
    SGL_CHECK(glGetError() == GL_NO_ERROR);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
