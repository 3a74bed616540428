/* tex_env_modes: each texture environment mode (MODULATE, REPLACE, DECAL,
 * ADD, BLEND with a GL_TEXTURE_ENV_COLOR) on each base internal format
 * (ALPHA, LUMINANCE, LUMINANCE_ALPHA, INTENSITY, RGB, RGBA), drawn as a
 * 6x5 grid of quads with smooth per-vertex colours that include alpha.
 * Blending is off, so the full RGBA result of the texture environment lands
 * in the buffer, which is dumped with its alpha channel.  The textures are
 * uploaded from the same RGBA source (LINEAR filtering, magnified), except
 * LUMINANCE and LUMINANCE_ALPHA, which are uploaded from their own formats.
 * DECAL on ALPHA/LUMINANCE/LUMINANCE_ALPHA/INTENSITY is undefined in GL;
 * Mesa passes the fragment through, so it is drawn too. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256
#define TS 8

int main(int argc, char **argv)
{
    static const GLenum formats[6] = {GL_ALPHA, GL_LUMINANCE, GL_LUMINANCE_ALPHA,
                                      GL_INTENSITY, GL_RGB, GL_RGBA};
    static const GLenum modes[5] = {GL_MODULATE, GL_REPLACE, GL_DECAL, GL_ADD, GL_BLEND};
    static const GLfloat env_color[4] = {0.19f, 0.83f, 0.47f, 0.29f};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    unsigned char rgba[TS * TS * 4], lum[TS * TS], la[TS * TS * 2];
    GLuint tex[6];
    int i, j, x, y;

    for (y = 0; y < TS; y++)
        for (x = 0; x < TS; x++) {
            unsigned char *p = rgba + 4 * (y * TS + x);
            p[0] = (unsigned char)(29 * x + 3 * y + 11);
            p[1] = (unsigned char)(255 - 27 * y - 5 * x);
            p[2] = (unsigned char)(((x ^ y) & 3) * 77 + 13);
            p[3] = (unsigned char)(17 + 16 * x + 15 * y);
            lum[y * TS + x] = p[0];
            la[2 * (y * TS + x)] = p[0];
            la[2 * (y * TS + x) + 1] = p[3];
        }
    glGenTextures(6, tex);
    for (i = 0; i < 6; i++) {
        glBindTexture(GL_TEXTURE_2D, tex[i]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
        if (formats[i] == GL_LUMINANCE) {
            glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE, TS, TS, 0, GL_LUMINANCE,
                         GL_UNSIGNED_BYTE, lum);
        } else if (formats[i] == GL_LUMINANCE_ALPHA) {
            glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_LUMINANCE_ALPHA, TS, TS, 0,
                         GL_LUMINANCE_ALPHA, GL_UNSIGNED_BYTE, la);
        } else {
            glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
            glTexImage2D(GL_TEXTURE_2D, 0, (GLint)formats[i], TS, TS, 0, GL_RGBA,
                         GL_UNSIGNED_BYTE, rgba);
        }
    }
    glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env_color);
    glEnable(GL_TEXTURE_2D);
    sgl_ortho(W, H);
    glShadeModel(GL_SMOOTH);
    glClearColor(0.05f, 0.1f, 0.15f, 0.5f);
    glClear(GL_COLOR_BUFFER_BIT);

    for (j = 0; j < 5; j++) {
        glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, (GLint)modes[j]);
        for (i = 0; i < 6; i++) {
            float x0 = 1.3f + 42.5f * i, y0 = 2.7f + 50.9f * j;
            float x1 = x0 + 40.1f, y1 = y0 + 47.9f;
            glBindTexture(GL_TEXTURE_2D, tex[i]);
            glBegin(GL_QUADS);
            glColor4f(0.91f, 0.23f, 0.37f, 0.87f);
            glTexCoord2f(-0.13f, -0.07f);
            glVertex2f(x0, y0);
            glColor4f(0.17f, 0.79f, 0.53f, 0.11f);
            glTexCoord2f(1.09f, -0.07f);
            glVertex2f(x1, y0);
            glColor4f(0.61f, 0.97f, 0.03f, 0.63f);
            glTexCoord2f(1.09f, 1.21f);
            glVertex2f(x1, y1);
            glColor4f(0.07f, 0.31f, 0.89f, 0.41f);
            glTexCoord2f(-0.13f, 1.21f);
            glVertex2f(x0, y1);
            glEnd();
        }
    }
    glFinish();
    SGL_CHECK(glGetError() == GL_NO_ERROR);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
