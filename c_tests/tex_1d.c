/* tex_1d: one-dimensional textures (glTexImage1D).  A 16-texel colour ramp
 * with alpha on triangles and a fan: NEAREST and LINEAR, REPEAT and
 * CLAMP_TO_EDGE with s outside [0,1]; a texture coordinate that varies
 * along a diagonal; a GL_LUMINANCE 1D ramp of odd width 13 with
 * UNPACK_ALIGNMENT 1 modulating smooth colour; and a mipmapped 1D texture
 * (levels uploaded by hand) minified on a perspective plane.  GL_TEXTURE_2D
 * is enabled together with GL_TEXTURE_1D in one draw (2D wins). */
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
    static const unsigned char white2x2[16] = {255, 0, 255, 255, 0, 255, 255, 255,
                                               255, 255, 0, 255, 0, 0, 0, 255};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    unsigned char ramp[16 * 4], lum[13], mip[64 * 4];
    GLuint tex[4];
    int i, w, level;

    for (i = 0; i < 16; i++) {
        ramp[4 * i] = (unsigned char)(i * 17);
        ramp[4 * i + 1] = (unsigned char)(255 - i * 13);
        ramp[4 * i + 2] = (unsigned char)((i & 1) ? 230 : 30);
        ramp[4 * i + 3] = (unsigned char)(128 + i * 8);
    }
    for (i = 0; i < 13; i++)
        lum[i] = (unsigned char)(20 + i * 19);
    glGenTextures(4, tex);
    glBindTexture(GL_TEXTURE_1D, tex[0]);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_RGBA, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, ramp);
    glBindTexture(GL_TEXTURE_1D, tex[1]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage1D(GL_TEXTURE_1D, 0, GL_LUMINANCE, 13, 0, GL_LUMINANCE, GL_UNSIGNED_BYTE, lum);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindTexture(GL_TEXTURE_1D, tex[2]);
    for (w = 64, level = 0; w >= 1; w /= 2, level++) {
        for (i = 0; i < w; i++) {
            int on = ((i * 8) / w + level) & 1;
            mip[4 * i] = on ? 240 : (unsigned char)(20 + level * 30);
            mip[4 * i + 1] = on ? (unsigned char)(240 - level * 30) : 20;
            mip[4 * i + 2] = (unsigned char)(level * 36);
            mip[4 * i + 3] = 255;
        }
        glTexImage1D(GL_TEXTURE_1D, level, GL_RGBA, w, 0, GL_RGBA, GL_UNSIGNED_BYTE, mip);
    }
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glBindTexture(GL_TEXTURE_2D, tex[3]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, white2x2);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);

    glEnable(GL_TEXTURE_1D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    sgl_ortho(W, H);
    glClearColor(0.1f, 0.1f, 0.1f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    glBindTexture(GL_TEXTURE_1D, tex[0]);
    for (i = 0; i < 4; i++) {
        GLint filter = (i & 1) ? GL_LINEAR : GL_NEAREST;
        GLint wrap = (i & 2) ? GL_CLAMP_TO_EDGE : GL_REPEAT;
        float y0 = 3.3f + 31.1f * i;
        glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, filter);
        glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, filter);
        glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, wrap);
        glBegin(GL_TRIANGLES);
        glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
        glTexCoord1f(-0.37f);
        glVertex2f(2.1f, y0);
        glTexCoord1f(1.61f);
        glVertex2f(125.7f, y0 + 3.1f);
        glTexCoord1f(0.5f);
        glVertex2f(61.9f, y0 + 28.3f);
        glEnd();
    }
    /* a fan whose s runs round the centre */
    glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glBegin(GL_TRIANGLE_FAN);
    glColor4f(0.9f, 0.8f, 1.0f, 1.0f);
    glTexCoord1f(0.5f);
    glVertex2f(190.5f, 64.5f);
    for (i = 0; i <= 12; i++) {
        float ang = (float)i * 0.5235988f;
        glTexCoord1f((float)i / 12.0f * 3.0f);
        glVertex2f(190.5f + 57.3f * cosf(ang), 64.5f + 57.3f * sinf(ang));
    }
    glEnd();

    /* luminance ramp modulating smooth colours */
    glBindTexture(GL_TEXTURE_1D, tex[1]);
    glBegin(GL_QUADS);
    glColor4f(1.0f, 0.2f, 0.2f, 0.5f);
    glTexCoord1f(0.0f);
    glVertex2f(3.7f, 131.3f);
    glColor4f(0.2f, 1.0f, 0.2f, 1.0f);
    glTexCoord1f(1.0f);
    glVertex2f(125.3f, 131.3f);
    glColor4f(0.2f, 0.2f, 1.0f, 0.75f);
    glTexCoord1f(0.0f);
    glVertex2f(125.3f, 160.1f);
    glColor4f(1.0f, 1.0f, 0.2f, 0.25f);
    glTexCoord1f(1.0f);
    glVertex2f(3.7f, 160.1f);
    glEnd();

    /* 1D and 2D both enabled: the 2D texture is used */
    glEnable(GL_TEXTURE_2D);
    glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    sgl_tex_quad(3.7f, 165.3f, 60.1f, 190.9f, 0.0f, 0.0f, 1.0f, 1.0f);
    glDisable(GL_TEXTURE_2D);

    /* mipmapped 1D texture on a plane to the horizon */
    glBindTexture(GL_TEXTURE_1D, tex[2]);
    glEnable(GL_DEPTH_TEST);
    glViewport(128, 128, 128, 128);
    sgl_ground_view(1.0);
    sgl_ground_plane(5.1f);
    glFinish();
    SGL_CHECK(glGetError() == GL_NO_ERROR);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
