/* tex_matrix: the texture matrix.  Eight animation frames of a texture
 * matrix (rotation about the texture centre, non-uniform scale and a
 * translation that grow per frame) drawn into separate cells; then
 * projective texture coordinates: a quad with glTexCoord4f where q differs
 * per vertex, a quad whose texture matrix is a perspective projection
 * (glFrustum in GL_TEXTURE mode, as for projected textures), and q < 0 at
 * one vertex of a triangle. */
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
    static const unsigned char a[4] = {250, 240, 40, 255}, b[4] = {30, 90, 170, 255};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    unsigned char *checker = sgl_checker(16, 16, 4, 4, a, b);
    GLuint tex;
    int f;

    checker[0] = 255, checker[1] = 0, checker[2] = 0; /* mark texel (0,0) */
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 16, 16, 0, GL_RGBA, GL_UNSIGNED_BYTE, checker);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    sgl_ortho(W, H);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glColor3f(1.0f, 1.0f, 1.0f);

    for (f = 0; f < 8; f++) {
        float x0 = 2.7f + 63.5f * (f % 4), y0 = 129.3f + 63.5f * (f / 4);
        glMatrixMode(GL_TEXTURE);
        glLoadIdentity();
        glTranslatef(0.5f + 0.13f * f, 0.5f - 0.07f * f, 0.0f);
        glRotatef(11.3f * f, 0.0f, 0.0f, 1.0f);
        glScalef(1.0f + 0.21f * f, 1.0f + 0.09f * f, 1.0f);
        glTranslatef(-0.5f, -0.5f, 0.0f);
        glMatrixMode(GL_MODELVIEW);
        sgl_tex_quad(x0, y0, x0 + 59.9f, y0 + 60.3f, 0.0f, 0.0f, 1.0f, 1.0f);
    }

    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    /* per-vertex q: (s*q, t*q, 0, q) */
    glBegin(GL_QUADS);
    glTexCoord4f(0.0f, 0.0f, 0.0f, 1.0f);
    glVertex2f(3.3f, 3.7f);
    glTexCoord4f(2.0f * 2.7f, 0.0f, 0.0f, 2.7f);
    glVertex2f(121.1f, 9.3f);
    glTexCoord4f(2.0f * 0.4f, 2.0f * 0.4f, 0.0f, 0.4f);
    glVertex2f(115.9f, 120.3f);
    glTexCoord4f(0.0f, 2.0f * 1.3f, 0.0f, 1.3f);
    glVertex2f(7.5f, 117.1f);
    glEnd();

    /* projected texture: texture matrix = bias * frustum * view */
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTranslatef(0.5f, 0.5f, 0.0f);
    glScalef(0.5f, 0.5f, 1.0f);
    glFrustum(-0.3, 0.3, -0.3, 0.3, 1.0, 10.0);
    glRotatef(27.0f, 1.0f, 0.3f, 0.0f);
    glTranslatef(-0.2f, 0.1f, -2.3f);
    glMatrixMode(GL_MODELVIEW);
    glBegin(GL_QUADS);
    glTexCoord3f(-1.0f, -1.0f, 0.0f);
    glVertex2f(131.1f, 3.9f);
    glTexCoord3f(1.0f, -1.0f, 0.3f);
    glVertex2f(251.7f, 5.3f);
    glTexCoord3f(1.0f, 1.0f, -0.4f);
    glVertex2f(249.3f, 58.9f);
    glTexCoord3f(-1.0f, 1.0f, 0.0f);
    glVertex2f(133.9f, 60.1f);
    glEnd();
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);

    /* q of mixed sign across a triangle */
    glBegin(GL_TRIANGLES);
    glTexCoord4f(0.1f, 0.2f, 0.0f, 1.0f);
    glVertex2f(131.7f, 65.3f);
    glTexCoord4f(0.9f, 0.1f, 0.0f, 0.7f);
    glVertex2f(250.3f, 70.9f);
    glTexCoord4f(-0.5f, 0.8f, 0.0f, -0.3f);
    glVertex2f(190.1f, 124.7f);
    glEnd();

    glFinish();
    SGL_CHECK(glGetError() == GL_NO_ERROR);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    free(checker);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
