/* copy_tex_1d: glCopyTexImage1D and glCopyTexSubImage1D.  A row of the
 * framebuffer (a smooth-shaded gradient) is copied into 1D textures of
 * several internal formats (RGBA, RGB, LUMINANCE, ALPHA, LUMINANCE_ALPHA), with a
 * border, and partly replaced with glCopyTexSubImage1D; the textures are drawn
 * as bands, read back with glGetTexImage, and the errors checked.  (Copies
 * into formats of fewer than 8 bits are left out, as in tex_sized_formats:
 * llvmpipe's blit rounds some texels differently, not reproduced yet.) */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 128
#define H 128

int main(int argc, char **argv)
{
    static const GLenum formats[5] = {GL_RGBA, GL_RGB, GL_LUMINANCE, GL_ALPHA, GL_LUMINANCE_ALPHA};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    unsigned char back[64 * 4];
    GLuint tex[5];
    GLint v[6];
    int i;

    sgl_ortho(W, H);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_QUADS);
    glColor4f(1.0f, 0.1f, 0.0f, 0.2f);
    glVertex2f(0.0f, 0.0f);
    glColor4f(0.0f, 0.9f, 0.3f, 1.0f);
    glVertex2f(64.0f, 0.0f);
    glColor4f(0.2f, 0.3f, 1.0f, 0.6f);
    glVertex2f(64.0f, 16.0f);
    glColor4f(0.9f, 0.9f, 0.1f, 0.9f);
    glVertex2f(0.0f, 16.0f);
    glEnd();

    glGenTextures(5, tex);
    for (i = 0; i < 5; i++) {
        glBindTexture(GL_TEXTURE_1D, tex[i]);
        if (i == 1)
            glCopyTexImage1D(GL_TEXTURE_1D, 0, formats[i], 3, 5 + i, 34, 1);
        else
            glCopyTexImage1D(GL_TEXTURE_1D, 0, formats[i], 2 + i, 3 + 2 * i, 32, 0);
        glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        if (i == 2 || i == 4)
            glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 4, 40, 10, 9);
    }
    glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    sgl_data(out, "luminance_alpha", 32 * 4, back);
    glBindTexture(GL_TEXTURE_1D, tex[1]);
    glGetTexLevelParameteriv(GL_TEXTURE_1D, 0, GL_TEXTURE_WIDTH, &v[0]);
    glGetTexImage(GL_TEXTURE_1D, 0, GL_RGBA, GL_UNSIGNED_BYTE, back);
    sgl_data(out, "rgb_border", 32 * 4, back);
    sgl_text(out, "width", "%d", v[0]);

    glEnable(GL_TEXTURE_1D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    for (i = 0; i < 5; i++) {
        glBindTexture(GL_TEXTURE_1D, tex[i]);
        glBegin(GL_QUADS);
        glTexCoord1f(-0.1f);
        glVertex2f(0.0f, 20.0f + 20.0f * i);
        glTexCoord1f(1.1f);
        glVertex2f(128.0f, 20.0f + 20.0f * i);
        glTexCoord1f(1.1f);
        glVertex2f(128.0f, 38.0f + 20.0f * i);
        glTexCoord1f(-0.1f);
        glVertex2f(0.0f, 38.0f + 20.0f * i);
        glEnd();
    }
    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);

    /* errors */
    glCopyTexImage1D(GL_TEXTURE_2D, 0, GL_RGBA, 0, 0, 8, 0);
    v[0] = glGetError();
    glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 0, 0, -2, 0);
    v[1] = glGetError();
    glCopyTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 0, 0, 8, 2);
    v[2] = glGetError();
    glCopyTexSubImage1D(GL_TEXTURE_1D, 0, 30, 0, 0, 8);
    v[3] = glGetError();
    glCopyTexImage1D(GL_TEXTURE_1D, 0, 0x1234, 0, 0, 8, 0);
    v[4] = glGetError();
    glCopyTexSubImage1D(GL_TEXTURE_1D, 20, 0, 0, 0, 8);
    v[5] = glGetError();
    sgl_text(out, "errors", "%x %x %x %x %x %x", v[0], v[1], v[2], v[3], v[4], v[5]);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
