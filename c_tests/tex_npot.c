/* tex_npot: non-power-of-two textures.  A 37x23 RGBA texture drawn with
 * REPEAT and CLAMP_TO_EDGE, NEAREST and LINEAR, over texture coordinates
 * -1.3 .. 2.7 (four cells, magnified and slightly rotated), a 37x23 minified
 * quad, then a mipmapped NPOT texture (37x23 -> 18x11 -> 9x5 -> 4x2 -> 2x1
 * -> 1x1, uploaded by hand) on a perspective ground plane with
 * NEAREST_MIPMAP_NEAREST and LINEAR_MIPMAP_LINEAR. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256
#define TW 37
#define TH 23

static void rotated_quad(float cx, float cy, float r, float s0, float t0, float s1, float t1)
{
    float c = 0.9703f * r, s = 0.2419f * r; /* about 14 degrees */
    glBegin(GL_QUADS);
    glTexCoord2f(s0, t0);
    glVertex2f(cx - c + s, cy - s - c);
    glTexCoord2f(s1, t0);
    glVertex2f(cx + c + s, cy + s - c);
    glTexCoord2f(s1, t1);
    glVertex2f(cx + c - s, cy + s + c);
    glTexCoord2f(s0, t1);
    glVertex2f(cx - c - s, cy - s + c);
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    unsigned char img[TW * TH * 4];
    GLuint tex[2];
    int i, x, y;

    for (y = 0; y < TH; y++)
        for (x = 0; x < TW; x++) {
            unsigned char *p = img + 4 * (y * TW + x);
            int edge = x == 0 || y == 0 || x == TW - 1 || y == TH - 1;
            p[0] = edge ? 255 : (unsigned char)(x * 6 + 20);
            p[1] = edge ? 255 : (unsigned char)(y * 10 + 10);
            p[2] = (unsigned char)(((x / 3 + y / 3) & 1) ? 220 : 40);
            p[3] = 255;
        }
    glGenTextures(2, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, TW, TH, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    sgl_upload_mips(img, TW, TH);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    sgl_ortho(W, H);

    glBindTexture(GL_TEXTURE_2D, tex[0]);
    for (i = 0; i < 4; i++) {
        GLint wrap = (i & 1) ? GL_CLAMP_TO_EDGE : GL_REPEAT;
        GLint filter = (i & 2) ? GL_LINEAR : GL_NEAREST;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
        rotated_quad(32.3f + 64.1f * i, 33.7f, 27.9f, -1.3f, -1.1f, 2.7f, 2.3f);
        /* minified: the whole texture in about 11x7 pixels, repeated 3x */
        sgl_tex_quad(9.3f + 64.1f * i, 70.7f, 42.6f + 64.1f * i, 92.1f, 0.0f, 0.0f, 3.0f, 3.0f);
    }

    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glEnable(GL_DEPTH_TEST);
    for (i = 0; i < 2; i++) {
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                        i ? GL_LINEAR_MIPMAP_LINEAR : GL_NEAREST_MIPMAP_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, i ? GL_LINEAR : GL_NEAREST);
        glViewport(128 * i, 100, 128, 156);
        sgl_ground_view(128.0 / 156.0);
        sgl_ground_plane(2.9f);
    }
    glFinish();
    SGL_CHECK(glGetError() == GL_NO_ERROR);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
