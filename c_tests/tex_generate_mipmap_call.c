/* tex_generate_mipmap_call: glGenerateMipmap (exported by Mesa's OSMesa, GL 3.0 /
 * ARB_framebuffer_object) on a 64x48 RGBA texture with a non-trivial pattern, then a
 * minified perspective plane with GL_LINEAR_MIPMAP_LINEAR so every generated level shows.
 * Also checks GL_INVALID_ENUM for a bad target. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <stdlib.h>
#include "common.h"

#define W 256
#define H 256

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf, *img;
    GLuint tex;
    int x, y;
    GLenum e1, e2;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    img = malloc(64 * 48 * 4);
    SGL_CHECK(buf && img);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    for (y = 0; y < 48; y++)
        for (x = 0; x < 64; x++) {
            unsigned char *p = img + 4 * (y * 64 + x);
            int c = ((x / 5) + (y / 3)) & 1;
            p[0] = (unsigned char)(c ? 250 : x * 4);
            p[1] = (unsigned char)(c ? 30 : y * 5);
            p[2] = (unsigned char)((x * y) & 255);
            p[3] = 255;
        }
    glClearColor(0.2f, 0.3f, 0.4f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 64, 48, 0, GL_RGBA, GL_UNSIGNED_BYTE, img);
    glGenerateMipmap(GL_TEXTURE_2D);
    e1 = glGetError();
    glGenerateMipmap(0x1234);
    e2 = glGetError();
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1.0, 1.0, -1.0, 1.0, 1.0, 100.0);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.13f, -1.1f, -2.3f);
    glRotatef(-73.7f, 1.0f, 0.0f, 0.0f);
    glBegin(GL_QUADS);
    glTexCoord2f(0.0f, 0.0f); glVertex3f(-17.0f, -17.0f, 0.0f);
    glTexCoord2f(23.0f, 0.0f); glVertex3f(17.0f, -17.0f, 0.0f);
    glTexCoord2f(23.0f, 23.0f); glVertex3f(17.0f, 17.0f, 0.0f);
    glTexCoord2f(0.0f, 23.0f); glVertex3f(-17.0f, 17.0f, 0.0f);
    glEnd();
    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_text(out, "errors", "generate=0x%x bad_target=0x%x\n", e1, e2);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    free(img);
    return 0;
}
