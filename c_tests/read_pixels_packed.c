/* read_pixels_packed: glReadPixels of a smooth gradient with every GL 1.2 packed type
 * (3_3_2, 2_3_3_REV, 5_6_5, 5_6_5_REV as GL_RGB; 4_4_4_4, 4_4_4_4_REV, 5_5_5_1,
 * 1_5_5_5_REV, 8_8_8_8, 8_8_8_8_REV, 10_10_10_2, 2_10_10_10_REV as GL_RGBA and GL_BGRA),
 * with GL_PACK_ALIGNMENT 1 and 4 (odd width, so rows are padded), GL_PACK_SWAP_BYTES,
 * a pixel-transfer scale/bias (Mesa's float path), and the errors for packed types
 * that do not fit the format.  Buffers are pre-filled with 0xCD so padding is compared. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 64
#define H 48
#define RX 5
#define RY 3
#define RW 37
#define RH 29

static void read_block(FILE *out, const char *name, int align, int swap, GLenum format,
                       GLenum type, int bytes_per_pixel)
{
    int row = RW * bytes_per_pixel;
    int stride = (row + align - 1) / align * align;
    size_t size = (size_t)stride * RH + 16;
    unsigned char *p = malloc(size);
    SGL_CHECK(p != NULL);
    memset(p, 0xCD, size);
    glPixelStorei(GL_PACK_ALIGNMENT, align);
    glPixelStorei(GL_PACK_SWAP_BYTES, swap);
    glReadPixels(RX, RY, RW, RH, format, type, p);
    sgl_text(out, "info", "%s align=%d swap=%d error=0x%04x\n", name, align, swap,
             glGetError());
    sgl_data(out, name, size, p);
    free(p);
}

struct packed {
    const char *name;
    GLenum type;
    int size;
    int fields;
};

static const struct packed types[] = {
    {"332", GL_UNSIGNED_BYTE_3_3_2, 1, 3},
    {"233r", GL_UNSIGNED_BYTE_2_3_3_REV, 1, 3},
    {"565", GL_UNSIGNED_SHORT_5_6_5, 2, 3},
    {"565r", GL_UNSIGNED_SHORT_5_6_5_REV, 2, 3},
    {"4444", GL_UNSIGNED_SHORT_4_4_4_4, 2, 4},
    {"4444r", GL_UNSIGNED_SHORT_4_4_4_4_REV, 2, 4},
    {"5551", GL_UNSIGNED_SHORT_5_5_5_1, 2, 4},
    {"1555r", GL_UNSIGNED_SHORT_1_5_5_5_REV, 2, 4},
    {"8888", GL_UNSIGNED_INT_8_8_8_8, 4, 4},
    {"8888r", GL_UNSIGNED_INT_8_8_8_8_REV, 4, 4},
    {"1010102", GL_UNSIGNED_INT_10_10_10_2, 4, 4},
    {"2101010r", GL_UNSIGNED_INT_2_10_10_10_REV, 4, 4},
};

static void read_all(FILE *out, const char *tag)
{
    char name[64];
    unsigned i;
    int a, s;
    for (i = 0; i < sizeof(types) / sizeof(types[0]); i++) {
        const struct packed *t = &types[i];
        for (a = 1; a <= 4; a += 3) {
            for (s = 0; s <= (t->size > 1); s++) {
                if (t->fields == 3) {
                    snprintf(name, sizeof name, "%s_rgb_%s", tag, t->name);
                    read_block(out, name, a, s, GL_RGB, t->type, t->size);
                } else {
                    snprintf(name, sizeof name, "%s_rgba_%s", tag, t->name);
                    read_block(out, name, a, s, GL_RGBA, t->type, t->size);
                    snprintf(name, sizeof name, "%s_bgra_%s", tag, t->name);
                    read_block(out, name, a, s, GL_BGRA, t->type, t->size);
                }
            }
        }
    }
}

static void error_case(FILE *out, const char *name, int w, GLenum format, GLenum type)
{
    unsigned char p[64];
    memset(p, 0xCD, sizeof p);
    glReadPixels(0, 0, w, 1, format, type, p);
    sgl_text(out, "err", "%s error=0x%04x\n", name, glGetError());
    sgl_data(out, name, sizeof p, p);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    SGL_CHECK(buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));

    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_SMOOTH);
    glBegin(GL_QUADS);
    glColor4f(0.0f, 0.0f, 1.0f, 0.0f);
    glVertex2f(-0.9f, -0.95f);
    glColor4f(1.0f, 0.0f, 0.5f, 0.3f);
    glVertex2f(0.95f, -0.9f);
    glColor4f(1.0f, 1.0f, 0.0f, 1.0f);
    glVertex2f(0.9f, 0.95f);
    glColor4f(0.0f, 1.0f, 0.25f, 0.7f);
    glVertex2f(-0.95f, 0.9f);
    glEnd();
    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);

    read_all(out, "plain");

    /* scale and bias send Mesa down its float path */
    glPixelTransferf(GL_RED_SCALE, 0.8f);
    glPixelTransferf(GL_GREEN_BIAS, 0.1f);
    glPixelTransferf(GL_BLUE_SCALE, 1.3f);
    glPixelTransferf(GL_ALPHA_SCALE, 0.9f);
    read_all(out, "xfer");
    glPixelTransferf(GL_RED_SCALE, 1.0f);
    glPixelTransferf(GL_GREEN_BIAS, 0.0f);
    glPixelTransferf(GL_BLUE_SCALE, 1.0f);
    glPixelTransferf(GL_ALPHA_SCALE, 1.0f);
    glPixelStorei(GL_PACK_SWAP_BYTES, 0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);

    error_case(out, "565_rgba", 4, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5);
    error_case(out, "565r_bgr", 4, GL_BGR, GL_UNSIGNED_SHORT_5_6_5_REV);
    error_case(out, "332_rgba", 4, GL_RGBA, GL_UNSIGNED_BYTE_3_3_2);
    error_case(out, "233r_lum", 4, GL_LUMINANCE, GL_UNSIGNED_BYTE_2_3_3_REV);
    error_case(out, "4444_rgb", 4, GL_RGB, GL_UNSIGNED_SHORT_4_4_4_4);
    error_case(out, "5551_bgr", 4, GL_BGR, GL_UNSIGNED_SHORT_5_5_5_1);
    error_case(out, "1555r_red", 4, GL_RED, GL_UNSIGNED_SHORT_1_5_5_5_REV);
    error_case(out, "8888_la", 4, GL_LUMINANCE_ALPHA, GL_UNSIGNED_INT_8_8_8_8);
    error_case(out, "8888r_alpha", 4, GL_ALPHA, GL_UNSIGNED_INT_8_8_8_8_REV);
    error_case(out, "1010102_rgb", 4, GL_RGB, GL_UNSIGNED_INT_10_10_10_2);
    error_case(out, "2101010r_depth", 4, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT_2_10_10_10_REV);
    error_case(out, "565_stencil", 4, GL_STENCIL_INDEX, GL_UNSIGNED_SHORT_5_6_5);
    error_case(out, "4444r_bad_format", 4, 0x1234, GL_UNSIGNED_SHORT_4_4_4_4_REV);
    error_case(out, "565_rgba_negw", -1, GL_RGBA, GL_UNSIGNED_SHORT_5_6_5);

    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
