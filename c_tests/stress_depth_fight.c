/* stress_depth_fight: nearly coplanar planes under glFrustum with near
 * 0.01 and far 1e5 (ratio 1e7), in a 24-bit and a 16-bit depth context
 * (OSMesaCreateContextExt with depth 24 and 16).  Each quadrant holds the
 * planes at another distance (0.7, 23, 900, 3e4): two planes that
 * intersect along a line at a tiny angle (the winner flips along it), and
 * a third plane parallel to the first 0.1% behind it, drawn last.  Colour
 * and depth (glReadPixels GL_DEPTH_COMPONENT GL_UNSIGNED_INT) are dumped
 * for both contexts. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 256
#define H 256

/* a quad at eye depth -d(1 + sx*x' + sy*y'), x', y' in [-1.3, 1.3] frustum units */
static void plane(float d, float sx, float sy, float off, const float *c0,
                  const float *c1)
{
    static const float xs[4] = {-1.3f, 1.3f, 1.3f, -1.3f};
    static const float ys[4] = {-1.3f, -1.3f, 1.3f, 1.3f};
    int i;
    glBegin(GL_QUADS);
    for (i = 0; i < 4; i++) {
        float z = d * (1.0f + off + sx * xs[i] + sy * ys[i]);
        const float *c = (i & 1) ? c1 : c0;
        glColor3fv(c);
        glVertex3f(xs[i] * z, ys[i] * z, -z);
    }
    glEnd();
}

static void scene(FILE *out, int depth_bits, const char *tag)
{
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, depth_bits, 0, 0, NULL);
    unsigned char *buf;
    unsigned int *depth;
    GLint bits = -1;
    char name[64];
    static const float dist[4] = {0.7f, 23.0f, 900.0f, 3e4f};
    static const float red0[3] = {1.0f, 0.1f, 0.1f}, red1[3] = {0.7f, 0.3f, 0.0f};
    static const float grn0[3] = {0.1f, 1.0f, 0.2f}, grn1[3] = {0.0f, 0.6f, 0.5f};
    static const float blu0[3] = {0.2f, 0.2f, 1.0f}, blu1[3] = {0.6f, 0.0f, 0.9f};
    int q;
    SGL_CHECK(ctx != NULL);
    buf = malloc(W * H * 4);
    depth = malloc(W * H * sizeof *depth);
    SGL_CHECK(buf != NULL && depth != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    glGetIntegerv(GL_DEPTH_BITS, &bits);

    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.01, 0.01, -0.01, 0.01, 0.01, 1e5);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    for (q = 0; q < 4; q++) {
        float d = dist[q];
        glViewport((q & 1) * 128, (q >> 1) * 128, 128, 128);
        /* plane A tilts +x, plane B tilts -x: they meet at x' = 0 */
        plane(d, 2e-4f, 3e-5f, 0.0f, red0, red1);
        plane(d, -2e-4f, 1e-5f, 0.0f, grn0, grn1);
        /* a parallel copy of A 0.1% farther, drawn last: must lose */
        glDepthFunc(q == 3 ? GL_LEQUAL : GL_LESS);
        plane(d, 2e-4f, 3e-5f, 1e-3f, blu0, blu1);
        glDepthFunc(GL_LESS);
    }
    glFinish();
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, W, H, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth);
    sgl_text(out, "depth_bits", "%s %d\n", tag, (int)bits);
    snprintf(name, sizeof name, "color_%s", tag);
    sgl_image(out, name, W, H, 4, "RGBA", W * 4, 1, buf);
    snprintf(name, sizeof name, "depth_%s", tag);
    sgl_data(out, name, (size_t)W * H * sizeof *depth, depth);
    OSMesaDestroyContext(ctx);
    free(depth);
    free(buf);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    scene(out, 24, "z24");
    scene(out, 16, "z16");
    sgl_close(out);
    return 0;
}
