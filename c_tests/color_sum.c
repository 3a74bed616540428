/* color_sum: GL_COLOR_SUM without lighting.  glSecondaryColor3* per vertex
 * is added to the primary colour after texturing (saturating), on untextured
 * and MODULATE-textured triangles; with GL_COLOR_SUM off the secondary
 * colour is ignored; the current secondary colour is queried. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 128
#define H 128

static void tri(float x, float y)
{
    glBegin(GL_TRIANGLES);
    glColor3f(0.5f, 0.1f, 0.2f);
    glSecondaryColor3f(0.6f, 0.0f, 0.1f);
    glTexCoord2f(0.0f, 0.0f);
    glVertex2f(x + 2.5f, y + 3.0f);
    glColor3f(0.1f, 0.4f, 0.3f);
    glSecondaryColor3ub(10, 200, 30);
    glTexCoord2f(1.0f, 0.0f);
    glVertex2f(x + 60.0f, y + 7.5f);
    glColor3f(0.2f, 0.2f, 0.7f);
    glSecondaryColor3d(0.0, 0.3, 0.6);
    glTexCoord2f(0.5f, 1.0f);
    glVertex2f(x + 30.0f, y + 59.0f);
    glEnd();
}

int main(int argc, char **argv)
{
    static const unsigned char a[4] = {250, 240, 40, 255}, b[4] = {30, 90, 170, 255};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    unsigned char *checker = sgl_checker(8, 8, 2, 2, a, b);
    GLuint tex;
    GLfloat f[4];

    sgl_ortho(W, H);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

    tri(0.0f, 0.0f); /* off */
    glEnable(GL_COLOR_SUM);
    tri(64.0f, 0.0f);
    glEnable(GL_TEXTURE_2D);
    tri(0.0f, 64.0f);
    glDisable(GL_COLOR_SUM);
    tri(64.0f, 64.0f);

    glFinish();
    SGL_CHECK(glGetError() == GL_NO_ERROR);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    glGetFloatv(GL_CURRENT_SECONDARY_COLOR, f);
    sgl_text(out, "state", "sec %g %g %g %g sum %d\n", f[0], f[1], f[2], f[3], glIsEnabled(GL_COLOR_SUM));
    sgl_close(out);
    free(checker);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
