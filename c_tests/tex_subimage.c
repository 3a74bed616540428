/* tex_subimage: partial texture updates.  A 64x64 checker texture gets
 * glTexSubImage2D patches (odd offsets and sizes, one with unpack alignment
 * 1 and GL_RGB data, one into mip level 1) and is drawn; then the scene
 * renders into the framebuffer and copies from it: glCopyTexImage2D of an
 * odd-positioned 32x16 region into a new texture, glCopyTexSubImage2D of a
 * 13x11 region into the middle of the first texture, each drawn again.
 * The copied textures are also read back with glGetTexImage. */
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
    static const unsigned char c0[4] = {40, 60, 200, 255}, c1[4] = {230, 220, 90, 255};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    unsigned char *checker = sgl_checker(64, 64, 8, 8, c0, c1);
    unsigned char patch[21 * 9 * 4], rgb[7 * 5 * 3], lvl1[5 * 3 * 4];
    unsigned char readback[64 * 64 * 4];
    GLuint tex[2];
    int i;

    for (i = 0; i < 21 * 9; i++) {
        patch[4 * i] = (unsigned char)(i * 7);
        patch[4 * i + 1] = (unsigned char)(255 - i);
        patch[4 * i + 2] = (unsigned char)(i * 13);
        patch[4 * i + 3] = 255;
    }
    for (i = 0; i < 7 * 5 * 3; i++)
        rgb[i] = (unsigned char)(i * 37 + 11);
    for (i = 0; i < 5 * 3 * 4; i++)
        lvl1[i] = (unsigned char)((i % 4 == 3) ? 255 : 250 - i * 4);

    glGenTextures(2, tex);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    sgl_upload_mips(checker, 64, 64);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 3, 5, 21, 9, GL_RGBA, GL_UNSIGNED_BYTE, patch);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 50, 41, 7, 5, GL_RGB, GL_UNSIGNED_BYTE, rgb);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTexSubImage2D(GL_TEXTURE_2D, 1, 9, 17, 5, 3, GL_RGBA, GL_UNSIGNED_BYTE, lvl1);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

    sgl_ortho(W, H);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    /* level 0 magnified (bottom left), level 1 at 1:1 (bottom right, 32x32) */
    sgl_tex_quad(3.0f, 3.0f, 131.0f, 131.0f, 0.0f, 0.0f, 1.0f, 1.0f);
    sgl_tex_quad(150.0f, 40.0f, 182.0f, 72.0f, 0.0f, 0.0f, 1.0f, 1.0f);

    /* untextured drawing to copy from */
    glDisable(GL_TEXTURE_2D);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.2f, 0.3f);
    glVertex2f(141.3f, 141.7f);
    glColor3f(0.2f, 1.0f, 0.4f);
    glVertex2f(251.9f, 150.1f);
    glColor3f(0.3f, 0.4f, 1.0f);
    glVertex2f(190.5f, 201.3f);
    glEnd();
    glFinish();

    /* glCopyTexImage2D into a new texture; glCopyTexSubImage2D into tex 0 */
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 171, 147, 32, 16, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, readback);
    sgl_data(out, "copyteximage", 32 * 16 * 4, readback);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glCopyTexSubImage2D(GL_TEXTURE_2D, 0, 27, 29, 185, 163, 13, 11);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, readback);
    sgl_data(out, "copytexsubimage", 64 * 64 * 4, readback);
    /* replace mip level 1 of tex 0 by a 32x32 copy */
    glCopyTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 200, 160, 32, 32, 0);

    glEnable(GL_TEXTURE_2D);
    glColor3f(1.0f, 1.0f, 1.0f);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    sgl_tex_quad(3.0f, 140.0f, 131.0f, 204.0f, 0.0f, 0.0f, 1.0f, 1.0f);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    sgl_tex_quad(3.0f, 207.0f, 67.0f, 255.0f, 0.0f, 0.0f, 1.0f, 0.75f);
    sgl_tex_quad(190.0f, 3.0f, 222.0f, 19.0f, 0.0f, 0.0f, 1.0f, 0.5f); /* level 1 */
    glFinish();
    SGL_CHECK(glGetError() == GL_NO_ERROR);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    free(checker);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
