/* read_pixels: glReadPixels of an odd-sized region (37 x 23 at 13,7) as
 * GL_RGBA, GL_RGB, GL_BGRA (GL_UNSIGNED_BYTE), GL_RGBA/GL_FLOAT, and
 * GL_DEPTH_COMPONENT as GL_FLOAT and GL_UNSIGNED_INT, with
 * GL_PACK_ALIGNMENT 1 and 4 (and 8 for RGB).  Destination buffers are
 * pre-filled with 0xCD so the padding bytes are compared too. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256
#define RX 13
#define RY 7
#define RW 37
#define RH 23

static void read_block(FILE *out, const char *name, int align, GLenum format, GLenum type,
                       int bytes_per_pixel)
{
    int row = RW * bytes_per_pixel;
    int stride = (row + align - 1) / align * align;
    size_t size = (size_t)stride * RH + 16;
    unsigned char *p = malloc(size);
    SGL_CHECK(p != NULL);
    memset(p, 0xCD, size);
    glPixelStorei(GL_PACK_ALIGNMENT, align);
    glReadPixels(RX, RY, RW, RH, format, type, p);
    sgl_text(out, "info", "%s align=%d error=0x%04x\n", name, align, glGetError());
    sgl_data(out, name, size, p);
    free(p);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf;
    int i;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.25f, 0.5f, 0.75f, 0.6137f);
    glClearDepth(0.7777);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glOrtho(0.0, 64.0, 0.0, 40.0, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);

    /* sloped triangles with varying alpha and depth */
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 5; i++) {
        float x = 1.3f + i * 9.7f;
        glColor4f(1.0f, 0.1f * i, 0.2f, 0.1337f * i);
        glVertex3f(x, 1.1f, -0.93f + 0.1f * i);
        glColor4f(0.1f, 1.0f, 0.3f * i, 1.0f);
        glVertex3f(x + 17.3f, 5.5f + i, 0.77f);
        glColor4f(0.2f, 0.4f, 1.0f, 0.5f);
        glVertex3f(x + 4.4f, 30.1f - i, 0.1f * i);
    }
    glEnd();

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);

    read_block(out, "rgba_ub_a1", 1, GL_RGBA, GL_UNSIGNED_BYTE, 4);
    read_block(out, "rgba_ub_a4", 4, GL_RGBA, GL_UNSIGNED_BYTE, 4);
    read_block(out, "rgb_ub_a1", 1, GL_RGB, GL_UNSIGNED_BYTE, 3);
    read_block(out, "rgb_ub_a4", 4, GL_RGB, GL_UNSIGNED_BYTE, 3);
    read_block(out, "rgb_ub_a8", 8, GL_RGB, GL_UNSIGNED_BYTE, 3);
    read_block(out, "bgra_ub_a1", 1, GL_BGRA, GL_UNSIGNED_BYTE, 4);
    read_block(out, "bgra_ub_a4", 4, GL_BGRA, GL_UNSIGNED_BYTE, 4);
    read_block(out, "rgba_f_a4", 4, GL_RGBA, GL_FLOAT, 16);
    read_block(out, "depth_f_a1", 1, GL_DEPTH_COMPONENT, GL_FLOAT, 4);
    read_block(out, "depth_f_a4", 4, GL_DEPTH_COMPONENT, GL_FLOAT, 4);
    read_block(out, "depth_ui_a1", 1, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, 4);
    read_block(out, "depth_ui_a4", 4, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, 4);

    /* a whole-framebuffer read equals the OSMesa buffer */
    {
        unsigned char *p = malloc(W * H * 4);
        SGL_CHECK(p != NULL);
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glReadPixels(0, 0, W, H, GL_RGBA, GL_UNSIGNED_BYTE, p);
        sgl_image(out, "readback", W, H, 4, "RGBA", W * 4, 1, p);
        sgl_text(out, "same", "readback equals buffer: %d\n", memcmp(p, buf, W * H * 4) == 0);
        free(p);
    }

    sgl_text(out, "error", "glGetError=0x%04x\n", glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
