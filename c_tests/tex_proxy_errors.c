/* tex_proxy_errors: which glTexImage1D/2D/3D errors a proxy target raises and which it
 * answers silently (piglit's proxy-texture).  A bad level, border or negative size is
 * GL_INVALID_VALUE for a proxy too and leaves the proxy's state alone; only an image too
 * large for the level empties the proxy without an error.  Also the order of the
 * checks (level, border and size before format and type), on proxy and real targets.
 * Prints each call's error and the proxy's width, height and internal format after it. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 8
#define H 8

static char log_buf[8192];
static int log_len;

static void state(const char *what, GLenum proxy)
{
    GLenum e = glGetError();
    GLint w = -7, h = -7, f = -7;
    glGetTexLevelParameteriv(proxy, 0, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(proxy, 0, GL_TEXTURE_HEIGHT, &h);
    glGetTexLevelParameteriv(proxy, 0, GL_TEXTURE_INTERNAL_FORMAT, &f);
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len,
                        "%-28s err=%x proxy w=%d h=%d fmt=%x (err %x)\n", what, e, w, h, f,
                        glGetError());
}

static void note(const char *what)
{
    GLenum e = glGetError();
    log_len += snprintf(log_buf + log_len, sizeof log_buf - (size_t)log_len, "%-28s err=%x\n",
                        what, e);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(W * H * 4);
    static unsigned char px[64 * 64 * 4];
    GLint max2d = 0, max3d = 0;
    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max2d);
    glGetIntegerv(GL_MAX_3D_TEXTURE_SIZE, &max3d);

    /* 2D proxy */
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_FLOAT, NULL);
    state("2d valid", GL_PROXY_TEXTURE_2D);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 5555, GL_RGBA, 8, 8, 0, GL_RGBA, GL_FLOAT, NULL);
    state("2d level 5555", GL_PROXY_TEXTURE_2D);
    glTexImage2D(GL_PROXY_TEXTURE_2D, -1, GL_RGBA, 8, 8, 0, GL_RGBA, GL_FLOAT, NULL);
    state("2d level -1", GL_PROXY_TEXTURE_2D);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, -8, 8, 0, GL_RGBA, GL_FLOAT, NULL);
    state("2d width -8", GL_PROXY_TEXTURE_2D);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 8, -1, 0, GL_RGBA, GL_FLOAT, NULL);
    state("2d height -1", GL_PROXY_TEXTURE_2D);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 8, 8, 2, GL_RGBA, GL_FLOAT, NULL);
    state("2d border 2", GL_PROXY_TEXTURE_2D);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 8, 8, -1, GL_RGBA, GL_FLOAT, NULL);
    state("2d border -1", GL_PROXY_TEXTURE_2D);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_DEPTH_COMPONENT,
                 GL_UNSIGNED_INT_8_8_8_8, NULL);
    state("2d depth 8888", GL_PROXY_TEXTURE_2D);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, 0x1234, NULL);
    state("2d bad type", GL_PROXY_TEXTURE_2D);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, 0x1234, 8, 8, 0, GL_RGBA, GL_FLOAT, NULL);
    state("2d bad internal", GL_PROXY_TEXTURE_2D);
    /* the order: level and size errors before format errors */
    glTexImage2D(GL_PROXY_TEXTURE_2D, 99, GL_RGBA, 8, 8, 0, 0x1234, GL_FLOAT, NULL);
    state("2d level 99 + bad format", GL_PROXY_TEXTURE_2D);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, 0x1234, -2, 8, 0, GL_RGBA, GL_FLOAT, NULL);
    state("2d width -2 + bad internal", GL_PROXY_TEXTURE_2D);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 8, 8, 3, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4,
                 NULL);
    state("2d border 3 + 4444 rgb", GL_PROXY_TEXTURE_2D);
    /* too large: silently empty */
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, max2d * 2, max2d * 2, 0, GL_RGBA, GL_FLOAT,
                 NULL);
    state("2d too large", GL_PROXY_TEXTURE_2D);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_FLOAT, NULL);
    state("2d valid again", GL_PROXY_TEXTURE_2D);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 1, 1, 1, GL_RGBA, GL_FLOAT, NULL);
    state("2d 1x1 border 1", GL_PROXY_TEXTURE_2D);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_FLOAT, NULL);
    glTexImage2D(GL_PROXY_TEXTURE_2D, 3, GL_RGBA, max2d, 4, 0, GL_RGBA, GL_FLOAT, NULL);
    state("2d level 3 too wide", GL_PROXY_TEXTURE_2D);

    /* 1D and cube proxies */
    glTexImage1D(GL_PROXY_TEXTURE_1D, 0, GL_RGBA, 8, 0, GL_RGBA, GL_FLOAT, NULL);
    state("1d valid", GL_PROXY_TEXTURE_1D);
    glTexImage1D(GL_PROXY_TEXTURE_1D, 0, GL_RGBA, -8, 0, GL_RGBA, GL_FLOAT, NULL);
    state("1d width -8", GL_PROXY_TEXTURE_1D);
    glTexImage1D(GL_PROXY_TEXTURE_1D, 0, GL_RGBA, 8, 5, GL_RGBA, GL_FLOAT, NULL);
    state("1d border 5", GL_PROXY_TEXTURE_1D);
    glTexImage1D(GL_PROXY_TEXTURE_1D, 77, GL_RGBA, 8, 0, GL_RGBA, GL_FLOAT, NULL);
    state("1d level 77", GL_PROXY_TEXTURE_1D);
    glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_FLOAT, NULL);
    state("cube valid", GL_PROXY_TEXTURE_CUBE_MAP);
    glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 8, -8, 0, GL_RGBA, GL_FLOAT, NULL);
    state("cube height -8", GL_PROXY_TEXTURE_CUBE_MAP);
    glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 8, 4, 0, GL_RGBA, GL_FLOAT, NULL);
    state("cube 8x4", GL_PROXY_TEXTURE_CUBE_MAP);

    /* 3D proxy */
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 8, 8, 8, 0, GL_RGBA, GL_FLOAT, NULL);
    state("3d valid", GL_PROXY_TEXTURE_3D);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 5555, GL_RGBA, 8, 8, 8, 0, GL_RGBA, GL_FLOAT, NULL);
    state("3d level 5555", GL_PROXY_TEXTURE_3D);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 8, 8, -8, 0, GL_RGBA, GL_FLOAT, NULL);
    state("3d depth -8", GL_PROXY_TEXTURE_3D);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 8, 8, 8, 2, GL_RGBA, GL_FLOAT, NULL);
    state("3d border 2", GL_PROXY_TEXTURE_3D);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 14, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_FLOAT, NULL);
    state("3d level 14", GL_PROXY_TEXTURE_3D);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, max3d * 2, 8, 8, 0, GL_RGBA, GL_FLOAT, NULL);
    state("3d too large", GL_PROXY_TEXTURE_3D);
    glTexImage3D(GL_PROXY_TEXTURE_3D, 0, GL_RGBA, 8, 8, -1, 0, 0x1234, GL_FLOAT, NULL);
    state("3d depth -1 + bad format", GL_PROXY_TEXTURE_3D);

    /* real targets: the same order */
    glTexImage2D(GL_TEXTURE_2D, 99, GL_RGBA, 8, 8, 0, 0x1234, GL_FLOAT, px);
    note("real 2d level 99 + bad fmt");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, -1, 8, 0, GL_RGBA, 0x1234, px);
    note("real 2d width -1 + bad type");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 4, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4, px);
    note("real 2d border 4 + mismatch");
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, max2d * 2, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, px);
    note("real 2d too wide");
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 8, 2, 0x1234, GL_FLOAT, px);
    note("real 1d border 2 + bad fmt");
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 8, 8, 8, 7, GL_DEPTH_COMPONENT, GL_FLOAT, px);
    note("real 3d border 7 + depth");
    glTexImage3D(GL_TEXTURE_3D, 20, GL_RGBA, 8, 8, 8, 0, GL_RGBA, 0x1234, px);
    note("real 3d level 20 + bad type");

    glFinish();
    sgl_data(out, "proxy", (size_t)log_len, log_buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
