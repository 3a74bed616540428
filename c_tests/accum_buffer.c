/* accum_buffer: the accumulation buffer (OSMesaCreateContextExt accumBits = 16):
 * motion blur (GL_LOAD, GL_ACCUM, GL_RETURN over several frames), jittered
 * antialiasing (GL_ACCUM 1/n each), GL_MULT and GL_ADD, glClear(GL_ACCUM_BUFFER_BIT)
 * with a negative clear value under a scissor box, GL_RETURN through a colour mask and
 * with values above 1, and the queries and errors (no accumulation buffer:
 * GL_INVALID_OPERATION). */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 80
#define H 64

static void shape(float dx, float dy, float angle)
{
    glPushMatrix();
    glTranslatef(dx, dy, 0.0f);
    glRotatef(angle, 0.0f, 0.0f, 1.0f);
    glBegin(GL_TRIANGLES);
    glColor4f(1.0f, 0.2f, 0.1f, 1.0f);
    glVertex2f(-0.5f, -0.4f);
    glColor4f(0.1f, 0.9f, 0.3f, 0.5f);
    glVertex2f(0.6f, -0.2f);
    glColor4f(0.2f, 0.3f, 1.0f, 0.8f);
    glVertex2f(-0.1f, 0.6f);
    glEnd();
    glPopMatrix();
}

static void frame(float dx, float dy, float angle)
{
    glClearColor(0.05f, 0.1f, 0.2f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    shape(dx, dy, angle);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 16, NULL);
    OSMesaContext none = OSMesaCreateContextExt(OSMESA_RGBA, 16, 0, 0, NULL);
    unsigned char *buf = malloc(W * H * 4), *buf2 = malloc(W * H * 4);
    GLint bits[4];
    GLfloat cv[4];
    int i;
    SGL_CHECK(ctx && none && buf && buf2);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H));
    glGetIntegerv(GL_ACCUM_RED_BITS, &bits[0]);
    glGetIntegerv(GL_ACCUM_GREEN_BITS, &bits[1]);
    glGetIntegerv(GL_ACCUM_BLUE_BITS, &bits[2]);
    glGetIntegerv(GL_ACCUM_ALPHA_BITS, &bits[3]);
    glClearAccum(0.25f, -2.0f, 0.5f, 1.5f);
    glGetFloatv(GL_ACCUM_CLEAR_VALUE, cv);
    sgl_text(out, "state", "bits=%d,%d,%d,%d clear=%g,%g,%g,%g err=0x%x\n", bits[0], bits[1],
             bits[2], bits[3], cv[0], cv[1], cv[2], cv[3], glGetError());

    /* motion blur: 6 frames, the newest weighted most */
    glClearAccum(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_ACCUM_BUFFER_BIT);
    for (i = 0; i < 6; i++) {
        frame(-0.4f + 0.12f * i, 0.05f * i, 7.0f * i);
        if (i == 0)
            glAccum(GL_LOAD, 0.1f);
        else
            glAccum(GL_ACCUM, 0.1f + 0.05f * i);
    }
    glAccum(GL_RETURN, 1.0f);
    glFinish();
    sgl_image(out, "motion_blur", W, H, 4, "RGBA", W * 4, 1, buf);

    /* jittered antialiasing: 8 sub-pixel offsets, 1/8 each */
    glClear(GL_ACCUM_BUFFER_BIT);
    for (i = 0; i < 8; i++) {
        float jx = ((i * 5) % 8 - 3.5f) / 8.0f * 2.0f / W;
        float jy = ((i * 3) % 8 - 3.5f) / 8.0f * 2.0f / H;
        frame(jx, jy, 20.0f);
        glAccum(GL_ACCUM, 0.125f);
    }
    glAccum(GL_RETURN, 1.0f);
    glFinish();
    sgl_image(out, "jitter_aa", W, H, 4, "RGBA", W * 4, 1, buf);

    /* MULT and ADD, then RETURN scaled above 1 through a colour mask */
    frame(0.1f, -0.1f, -15.0f);
    glAccum(GL_LOAD, 0.7f);
    glAccum(GL_MULT, 0.6f);
    glAccum(GL_ADD, 0.13f);
    glAccum(GL_ADD, -0.05f);
    glAccum(GL_MULT, 1.0f);
    glAccum(GL_ADD, 0.0f);
    frame(0.0f, 0.0f, 40.0f);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_TRUE);
    glAccum(GL_RETURN, 1.7f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glFinish();
    sgl_image(out, "mult_add_return", W, H, 4, "RGBA", W * 4, 1, buf);

    /* clearing to a negative value under a scissor box, then accumulating */
    glClearAccum(-0.3f, 0.4f, -1.0f, 0.9f);
    glEnable(GL_SCISSOR_TEST);
    glScissor(10, 8, 50, 40);
    glClear(GL_ACCUM_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    frame(-0.2f, 0.2f, 75.0f);
    glAccum(GL_ACCUM, 0.9f);
    glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
    glClear(GL_COLOR_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    glScissor(4, 4, 70, 50);
    glAccum(GL_RETURN, 1.0f);
    glDisable(GL_SCISSOR_TEST);
    glFinish();
    sgl_image(out, "scissor_negative", W, H, 4, "RGBA", W * 4, 1, buf);

    /* errors */
    glAccum(GL_TEXTURE_2D, 1.0f);
    sgl_text(out, "bad_op", "0x%x\n", glGetError());
    glBegin(GL_POINTS);
    glAccum(GL_LOAD, 1.0f);
    glEnd();
    sgl_text(out, "in_begin", "0x%x\n", glGetError());

    SGL_CHECK(OSMesaMakeCurrent(none, buf2, GL_UNSIGNED_BYTE, W, H));
    glGetIntegerv(GL_ACCUM_RED_BITS, &bits[0]);
    glAccum(GL_LOAD, 1.0f);
    sgl_text(out, "no_accum", "bits=%d err=0x%x\n", bits[0], glGetError());
    glClearAccum(0.5f, 0.5f, 0.5f, 0.5f);
    glClear(GL_ACCUM_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    sgl_text(out, "no_accum_clear", "err=0x%x\n", glGetError());

    sgl_close(out);
    OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
    OSMesaDestroyContext(ctx);
    OSMesaDestroyContext(none);
    free(buf);
    free(buf2);
    return 0;
}
