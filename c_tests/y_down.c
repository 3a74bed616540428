/* y_down: OSMesaPixelStore(OSMESA_Y_UP, 0) (first row in memory is the top
 * row) together with OSMESA_ROW_LENGTH larger than the width, on an odd
 * sized (203 x 117, row length 211) buffer.  The padding pixels of each row
 * are pre-filled and must stay untouched.  A second frame then switches back
 * to Y_UP=1 with a row length of 0 (= width) in a new, tight buffer of the
 * same size. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 203
#define H 117
#define RL 211

static void draw(float shift)
{
    glClearColor(0.0f, 0.2f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, W, 0.0, H, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(shift, 0.0f, 0.0f);
    glBegin(GL_TRIANGLES);
    /* a triangle pointing up, only in the bottom half */
    glColor3f(1.0f, 0.0f, 0.0f);
    glVertex2f(10.3f, 3.7f);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex2f(99.9f, 5.1f);
    glColor3f(0.0f, 0.0f, 1.0f);
    glVertex2f(40.4f, 55.5f);
    /* a triangle touching the top-right corner */
    glColor3f(1.0f, 1.0f, 0.0f);
    glVertex2f(120.5f, 60.6f);
    glColor3f(0.0f, 1.0f, 1.0f);
    glVertex2f(203.0f, 80.2f);
    glColor3f(1.0f, 0.0f, 1.0f);
    glVertex2f(203.0f, 117.0f);
    glEnd();
    glBegin(GL_QUADS); /* top-left marker */
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex2f(0.0f, 100.0f);
    glVertex2f(17.0f, 100.0f);
    glVertex2f(17.0f, 117.0f);
    glVertex2f(0.0f, 117.0f);
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContext(OSMESA_RGBA, NULL);
    unsigned char *buf, *buf2;
    GLint rl, yup, w, h;
    SGL_CHECK(ctx != NULL);
    buf = malloc(RL * H * 4);
    buf2 = malloc(W * H * 4);
    SGL_CHECK(buf != NULL && buf2 != NULL);
    memset(buf, 0x3c, RL * H * 4);
    memset(buf2, 0x3c, W * H * 4);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    OSMesaPixelStore(OSMESA_Y_UP, 0);
    OSMesaPixelStore(OSMESA_ROW_LENGTH, RL);
    OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &rl);
    OSMesaGetIntegerv(OSMESA_Y_UP, &yup);
    sgl_text(out, "pixelstore", "row_length=%d y_up=%d\n", rl, yup);

    draw(0.0f);
    glFinish();
    sgl_image(out, "ydown_rowlength", W, H, 4, "RGBA", RL * 4, 0, buf);

    /* second frame: bottom-up, tight rows, into a second buffer */
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf2, GL_UNSIGNED_BYTE, W, H));
    OSMesaPixelStore(OSMESA_Y_UP, 1);
    OSMesaPixelStore(OSMESA_ROW_LENGTH, 0);
    OSMesaGetIntegerv(OSMESA_ROW_LENGTH, &rl);
    OSMesaGetIntegerv(OSMESA_Y_UP, &yup);
    OSMesaGetIntegerv(OSMESA_WIDTH, &w);
    OSMesaGetIntegerv(OSMESA_HEIGHT, &h);
    sgl_text(out, "pixelstore2", "row_length=%d y_up=%d width=%d height=%d\n", rl, yup, w, h);
    draw(3.5f);
    glFinish();
    sgl_image(out, "yup_tight", W, H, 4, "RGBA", W * 4, 1, buf2);
    /* the first buffer was not touched by the second frame */
    sgl_image(out, "first_again", W, H, 4, "RGBA", RL * 4, 0, buf);

    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    free(buf2);
    return 0;
}
