/* osmesa_wide_formats: one lit, blended scene rendered into OSMesa buffers of
 * GL_UNSIGNED_BYTE, GL_UNSIGNED_SHORT and GL_FLOAT (OSMESA_RGBA, OSMESA_BGRA and
 * OSMESA_RGB contexts). Mesa stores 16-bit and float buffers as R16G16B16A16 /
 * R32G32B32A32 (RGB16 / RGB32F) whatever the channel order asked for.
 *
 * The wide buffers are written as 8-bit images (u16 -> round(v / 257), float ->
 * round(clamp(f) * 255)) so that the comparison is in 8-bit steps: the first row
 * of each wide buffer is also written raw so its layout is checked exactly. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <math.h>
#include "common.h"

#define W 96
#define H 80

static int clear_by_quad;

static void scene(void)
{
    static const GLfloat pos[4] = {0.4f, 0.7f, 1.0f, 0.0f};
    static const GLfloat diff[4] = {0.9f, 0.7f, 0.4f, 1.0f};
    static const GLfloat spec[4] = {0.6f, 0.6f, 0.6f, 1.0f};
    int i, j;
    glViewport(0, 0, W, H);
    glClearColor(0.12f, 0.2f, 0.35f, 0.6f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
#ifdef SGL_REFERENCE_OSMESA
    /* Mesa bug: llvmpipe ignores glClear of a colour buffer with 6-byte pixels
     * (OSMESA_RGB + GL_UNSIGNED_SHORT, R16G16B16_UNORM); the buffer stays zero.
     * Paint the clear colour with a quad there so the expected output is right. */
    if (clear_by_quad) {
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glColor4f(0.12f, 0.2f, 0.35f, 0.6f);
        glRectf(-1.0f, -1.0f, 1.0f, 1.0f);
    }
#endif
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.5, 0.5, 1.0, 10.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -3.0f);
    glRotatef(25.0f, 1.0f, 0.3f, 0.0f);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diff);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, spec);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 20.0f);
    /* a lit bumpy sheet */
    for (j = 0; j < 8; j++) {
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i <= 10; i++) {
            int k;
            for (k = 0; k < 2; k++) {
                float u = -1.0f + 0.2f * i, v = -1.0f + 0.25f * (j + k);
                float z = 0.2f * sinf(2.0f * u) * cosf(2.0f * v);
                glNormal3f(-0.4f * cosf(2.0f * u) * cosf(2.0f * v),
                           0.4f * sinf(2.0f * u) * sinf(2.0f * v), 1.0f);
                glVertex3f(u, v, z);
            }
        }
        glEnd();
    }
    glDisable(GL_LIGHTING);
    /* blended, smooth-shaded triangles over it */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_DEPTH_TEST);
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 6; i++) {
        float x = -0.9f + 0.3f * i;
        glColor4f(1.0f, 0.1f * i, 0.2f, 0.35f);
        glVertex3f(x, -0.8f, 0.3f);
        glColor4f(0.1f, 0.9f, 0.15f * i, 0.6f);
        glVertex3f(x + 0.5f, -0.5f, 0.3f);
        glColor4f(0.2f, 0.3f, 1.0f, 0.8f);
        glVertex3f(x + 0.1f, 0.7f, 0.3f);
    }
    glEnd();
    glDisable(GL_BLEND);
}

static unsigned char to8_u16(unsigned short v) { return (unsigned char)((v + 128u) / 257u); }
static unsigned char to8_f(float f)
{
    if (!(f > 0.0f))
        return 0;
    if (f >= 1.0f)
        return 255;
    return (unsigned char)lrintf(f * 255.0f);
}

static void run(FILE *out, const char *name, GLenum format, GLenum type, int channels)
{
    OSMesaContext ctx = OSMesaCreateContextExt(format, 24, 0, 0, NULL);
    int bytes = type == GL_UNSIGNED_BYTE ? 1 : type == GL_UNSIGNED_SHORT ? 2 : 4;
    size_t n = (size_t)W * H * channels;
    unsigned char *buf = malloc(n * bytes), *img = malloc(n);
    GLint bits[4], v;
    size_t k;
    SGL_CHECK(ctx && buf && img);
    memset(buf, 0x5A, n * bytes);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, type, W, H));
    clear_by_quad = channels == 3 && bytes == 2;
    scene();
    glFinish();
    glGetIntegerv(GL_RED_BITS, &bits[0]);
    glGetIntegerv(GL_GREEN_BITS, &bits[1]);
    glGetIntegerv(GL_BLUE_BITS, &bits[2]);
    glGetIntegerv(GL_ALPHA_BITS, &bits[3]);
    OSMesaGetIntegerv(OSMESA_TYPE, &v);
    sgl_text(out, "bits", "%s bits=%d,%d,%d,%d type=0x%x err=0x%x\n", name, bits[0], bits[1],
             bits[2], bits[3], v, glGetError());
    for (k = 0; k < n; k++) {
        if (bytes == 1)
            img[k] = buf[k];
        else if (bytes == 2)
            img[k] = to8_u16(((unsigned short *)buf)[k]);
        else
            img[k] = to8_f(((float *)buf)[k]);
    }
    sgl_image(out, name, W, H, channels,
              channels == 3 ? "RGB" : format == OSMESA_BGRA && bytes == 1 ? "BGRA" : "RGBA",
              W * channels, 1, img);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    free(buf);
    free(img);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    run(out, "rgba_ubyte", OSMESA_RGBA, GL_UNSIGNED_BYTE, 4);
    run(out, "rgba_ushort", OSMESA_RGBA, GL_UNSIGNED_SHORT, 4);
    run(out, "rgba_float", OSMESA_RGBA, GL_FLOAT, 4);
    run(out, "bgra_ushort", OSMESA_BGRA, GL_UNSIGNED_SHORT, 4);
    run(out, "bgra_float", OSMESA_BGRA, GL_FLOAT, 4);
    run(out, "rgb_ushort", OSMESA_RGB, GL_UNSIGNED_SHORT, 3);
    run(out, "rgb_float", OSMESA_RGB, GL_FLOAT, 3);
    sgl_close(out);
    return 0;
}
