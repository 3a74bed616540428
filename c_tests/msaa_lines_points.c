/* msaa_lines_points: lines and points drawn into a 4x multisample object, resolved.
 * - GL_MULTISAMPLE on: lines of width 1, 1.5, 2, 3.7 and 9.25 at many angles and
 *   sub-pixel offsets (horizontal, vertical, diagonal, sub-pixel short), strips and
 *   loops, smooth and flat colour, line stipple, GL_LINE_SMOOTH on (ignored), a
 *   textured line (texture coordinates along the line), lines whose box starts at a
 *   64-pixel tile boundary.
 * - Points of size 1, 2, 3.3, 10 and 0.4 at sub-pixel positions, GL_POINT_SMOOTH on,
 *   distance attenuation.
 * - Depth-tested lines and points against a sloped triangle (depth per sample),
 *   blending, alpha to coverage, glSampleCoverage.
 * - GL_MULTISAMPLE off on the same object (single-sample rules in every sample), and
 *   polygon modes GL_LINE / GL_POINT.
 * - glBitmap into the object (cached and large bitmaps), and glCopyPixels
 *   from it (GL_INVALID_OPERATION).
 * Each part is resolved with glBlitFramebuffer into a single-sample object and read. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define FW 96
#define FH 80

static unsigned char px[FW * FH * 4];
static GLuint fb[2], rb[3];

static void read_resolved(FILE *out, const char *name)
{
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[0]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fb[1]);
    glBlitFramebuffer(0, 0, FW, FH, 0, 0, FW, FH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb[1]);
    glReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_BYTE, px);
    sgl_image(out, name, FW, FH, 4, "RGBA", FW * 4, 1, px);
    sgl_text(out, name, "err %x", glGetError());
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

/* Lines of `width` from many start points at sub-pixel offsets, in all directions. */
static void star(float cx, float cy, float r, int n, float off)
{
    int i;
    glBegin(GL_LINES);
    for (i = 0; i < n; i++) {
        float t = 6.2831853f * (float)i / (float)n + off;
        glColor4f(1.0f, (float)i / (float)n, 0.2f, 1.0f);
        glVertex2f(cx + 0.37f * (float)(i % 3), cy + 0.29f * (float)(i % 4));
        glColor4f(0.1f, 0.4f, 1.0f - (float)i / (float)n, 1.0f);
        glVertex2f(cx + r * __builtin_cosf(t), cy + r * __builtin_sinf(t));
    }
    glEnd();
}

/* Axis-aligned, diagonal and tiny lines at exact and sub-pixel positions. */
static void straight(float x0, float y0)
{
    static const float offs[] = {0.0f, 0.125f, 0.25f, 0.3f, 0.5f, 0.625f, 0.875f, 0.98f};
    int i;
    glBegin(GL_LINES);
    for (i = 0; i < 8; i++) {
        float o = offs[i];
        glColor3f(1.0f, 1.0f, 1.0f);
        glVertex2f(x0 + o, y0 + 3.0f * (float)i + o);
        glColor3f(0.0f, 1.0f, 0.5f);
        glVertex2f(x0 + 11.0f + o * 0.5f, y0 + 3.0f * (float)i + o);
        glColor3f(1.0f, 0.3f, 0.0f);
        glVertex2f(x0 + 13.0f + 2.0f * (float)i + o, y0 + o);
        glVertex2f(x0 + 13.0f + 2.0f * (float)i + o, y0 + 9.0f + o * 1.5f);
        glColor3f(0.2f, 0.2f, 1.0f);
        glVertex2f(x0 + 30.0f + o, y0 + 3.0f * (float)i + o);
        glVertex2f(x0 + 30.3f + o, y0 + 3.0f * (float)i + o + 0.2f);
        glColor3f(1.0f, 0.0f, 1.0f);
        glVertex2f(x0 + 33.0f + 2.0f * (float)i + o, y0 + o);
        glVertex2f(x0 + 41.0f + 2.0f * (float)i + o, y0 + 8.0f + o);
    }
    glEnd();
}

static void points(float x0, float y0)
{
    static const float sizes[] = {1.0f, 2.0f, 3.3f, 10.0f, 0.4f, 1.5f, 4.0f, 2.7f};
    int i, k;
    for (k = 0; k < 8; k++) {
        glPointSize(sizes[k]);
        glBegin(GL_POINTS);
        for (i = 0; i < 7; i++) {
            float fx = 0.125f * (float)i + 0.01f * (float)k;
            glColor3f((float)i / 7.0f, 1.0f - (float)k / 8.0f, 0.5f);
            glVertex2f(x0 + 12.0f * (float)i + fx, y0 + 9.0f * (float)k + 0.37f * (float)i);
        }
        glEnd();
    }
    glPointSize(1.0f);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(8 * 8 * 4);
    unsigned char texels[8 * 8 * 4];
    static const float widths[] = {1.0f, 1.5f, 2.0f, 3.7f, 9.25f};
    GLuint tex;
    float f[4];
    int i;

    SGL_CHECK(ctx && buf);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, 8, 8));

    glGenFramebuffers(2, fb);
    glGenRenderbuffers(3, rb);
    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_RGBA8, FW, FH);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH24_STENCIL8, FW, FH);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              rb[1]);
    sgl_text(out, "ms", "%x", (unsigned)glCheckFramebufferStatus(GL_FRAMEBUFFER));
    glBindFramebuffer(GL_FRAMEBUFFER, fb[1]);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[2]);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, FW, FH);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[2]);
    sgl_text(out, "ss", "%x", (unsigned)glCheckFramebufferStatus(GL_FRAMEBUFFER));

    glBindFramebuffer(GL_FRAMEBUFFER, fb[0]);
    glViewport(0, 0, FW, FH);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, FW, 0.0, FH, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glClearColor(0.05f, 0.1f, 0.15f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    glShadeModel(GL_SMOOTH);
    glGetFloatv(GL_LINE_WIDTH_RANGE, f);
    glGetFloatv(GL_POINT_SIZE_RANGE, f + 2);
    sgl_text(out, "ranges", "%g %g %g %g", f[0], f[1], f[2], f[3]);

    /* 1. widths */
    for (i = 0; i < 5; i++) {
        char name[32];
        glLineWidth(widths[i]);
        star(30.3f, 40.2f, 27.0f, 36, 0.05f * (float)i);
        star(77.6f, 20.1f, 15.0f, 18, 0.11f);
        snprintf(name, sizeof name, "width_%d", i);
        read_resolved(out, name);
        straight(2.0f + 0.1f * (float)i, 3.0f);
        straight(50.0f, 52.0f);
        snprintf(name, sizeof name, "straight_%d", i);
        read_resolved(out, name);
    }
    glLineWidth(1.0f);

    /* 2. tile boundaries (x = 64 and y = 64) and the frame edges */
    glBegin(GL_LINES);
    for (i = 0; i < 6; i++) {
        float o = 0.2f * (float)i;
        glColor3f(1.0f, 1.0f, 0.0f);
        glVertex2f(63.0f + o, 5.0f + 4.0f * (float)i);
        glVertex2f(75.0f, 5.5f + 4.0f * (float)i);
        glColor3f(0.0f, 1.0f, 1.0f);
        glVertex2f(5.0f + 4.0f * (float)i, 63.1f + o);
        glVertex2f(5.5f + 4.0f * (float)i, 75.0f);
        glColor3f(1.0f, 0.0f, 1.0f);
        glVertex2f(-0.7f + o, 40.0f + 2.0f * (float)i);
        glVertex2f(-0.7f + o + 0.9f, 40.0f + 2.0f * (float)i + 0.1f);
        glVertex2f(30.0f + 2.0f * (float)i, 79.2f + 0.1f * o);
        glVertex2f(40.0f + 2.0f * (float)i, 79.6f + 0.1f * o);
    }
    glEnd();
    read_resolved(out, "tiles");

    /* 3. strips, loops, flat shading, stipple, smooth flag */
    glLineWidth(2.5f);
    glBegin(GL_LINE_STRIP);
    for (i = 0; i < 12; i++) {
        glColor3f((float)(i & 1), (float)((i >> 1) & 1), 0.6f);
        glVertex2f(4.0f + 7.3f * (float)i, 10.0f + 9.7f * (float)(i & 1) + 0.3f * (float)i);
    }
    glEnd();
    glLineWidth(1.0f);
    glShadeModel(GL_FLAT);
    glBegin(GL_LINE_LOOP);
    for (i = 0; i < 9; i++) {
        float t = 6.2831853f * (float)i / 9.0f;
        glColor3f(0.3f + 0.07f * (float)i, 1.0f - 0.1f * (float)i, 0.2f);
        glVertex2f(48.0f + 25.0f * __builtin_cosf(t), 50.0f + 20.0f * __builtin_sinf(t));
    }
    glEnd();
    glShadeModel(GL_SMOOTH);
    read_resolved(out, "strips");

    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x0F3D);
    glLineWidth(1.5f);
    star(48.2f, 40.3f, 35.0f, 24, 0.02f);
    glBegin(GL_LINE_STRIP);
    for (i = 0; i < 10; i++)
        glVertex2f(3.0f + 9.1f * (float)i, 4.0f + 6.3f * (float)(i & 1));
    glEnd();
    glDisable(GL_LINE_STIPPLE);
    read_resolved(out, "stipple");

    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glLineWidth(2.5f);
    star(48.2f, 40.3f, 35.0f, 20, 0.3f);
    glLineWidth(1.0f);
    glDisable(GL_BLEND);
    glDisable(GL_LINE_SMOOTH);
    read_resolved(out, "line_smooth");

    /* 4. textured lines: coordinates along the line */
    for (i = 0; i < 64; i++) {
        texels[i * 4 + 0] = (unsigned char)((i & 1) ? 255 : 20);
        texels[i * 4 + 1] = (unsigned char)(i * 4);
        texels[i * 4 + 2] = (unsigned char)(((i >> 3) & 1) ? 220 : 10);
        texels[i * 4 + 3] = 255;
    }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_2D);
    glLineWidth(3.0f);
    glBegin(GL_LINES);
    for (i = 0; i < 8; i++) {
        glColor3f(1.0f, 1.0f, 1.0f);
        glTexCoord2f(0.0f, 0.1f * (float)i);
        glVertex2f(3.0f + 0.3f * (float)i, 4.0f + 9.0f * (float)i);
        glTexCoord2f(1.0f, 0.9f - 0.1f * (float)i);
        glVertex2f(90.0f - 5.0f * (float)i, 8.0f + 8.5f * (float)i + 0.25f);
    }
    glEnd();
    glPointSize(6.0f);
    glBegin(GL_POINTS);
    for (i = 0; i < 8; i++) {
        glTexCoord2f(0.13f * (float)i, 0.5f);
        glVertex2f(10.3f + 10.0f * (float)i, 75.0f + 0.2f * (float)i);
    }
    glEnd();
    glPointSize(1.0f);
    glLineWidth(1.0f);
    glDisable(GL_TEXTURE_2D);
    read_resolved(out, "textured");

    /* 5. points */
    points(3.0f, 4.0f);
    read_resolved(out, "points");
    glEnable(GL_POINT_SMOOTH);
    points(3.3f, 4.6f);
    glDisable(GL_POINT_SMOOTH);
    read_resolved(out, "point_smooth");
    {
        GLfloat att[3] = {0.0f, 0.3f, 0.02f};
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
        glPointSize(12.0f);
        glBegin(GL_POINTS);
        for (i = 0; i < 12; i++) {
            glColor3f(1.0f, 0.1f * (float)i, 0.3f);
            glVertex3f(5.0f + 7.7f * (float)i, 20.0f + 3.1f * (float)i, -0.08f * (float)i);
        }
        glEnd();
        att[1] = 0.0f;
        att[2] = 0.0f;
        att[0] = 1.0f;
        glPointParameterfv(GL_POINT_DISTANCE_ATTENUATION, att);
        glPointSize(1.0f);
    }
    read_resolved(out, "point_atten");

    /* 6. depth per sample: lines and points through a sloped triangle */
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glBegin(GL_TRIANGLES);
    glColor3f(0.6f, 0.6f, 0.6f);
    glVertex3f(0.0f, 0.0f, -0.9f);
    glVertex3f(96.0f, 0.0f, 0.9f);
    glVertex3f(48.0f, 80.0f, 0.0f);
    glEnd();
    glLineWidth(2.0f);
    glBegin(GL_LINES);
    for (i = 0; i < 10; i++) {
        glColor3f(1.0f, 0.0f, 0.1f * (float)i);
        glVertex3f(2.0f + 0.3f * (float)i, 5.0f + 7.0f * (float)i, 0.5f - 0.1f * (float)i);
        glVertex3f(94.0f, 9.0f + 6.9f * (float)i, -0.5f + 0.05f * (float)i);
    }
    glEnd();
    glPointSize(3.0f);
    glBegin(GL_POINTS);
    for (i = 0; i < 20; i++) {
        glColor3f(0.0f, 1.0f, 0.2f);
        glVertex3f(4.0f + 4.6f * (float)i, 3.3f + 1.7f * (float)i,
                   -0.95f + 0.095f * (float)i);
    }
    glEnd();
    glPointSize(1.0f);
    glLineWidth(1.0f);
    glDisable(GL_DEPTH_TEST);
    read_resolved(out, "depth");

    /* 7. blending, alpha to coverage, sample coverage */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glLineWidth(3.0f);
    glBegin(GL_LINES);
    for (i = 0; i < 12; i++) {
        glColor4f(1.0f, 0.5f, 0.1f * (float)i, 0.5f);
        glVertex2f(3.0f, 3.0f + 6.0f * (float)i);
        glVertex2f(93.0f, 70.0f - 5.5f * (float)i);
    }
    glEnd();
    glDisable(GL_BLEND);
    read_resolved(out, "blend");
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glBegin(GL_LINES);
    for (i = 0; i < 12; i++) {
        glColor4f(1.0f, 1.0f, 0.2f, 0.09f * (float)i);
        glVertex2f(3.0f, 3.0f + 6.0f * (float)i);
        glVertex2f(93.0f, 5.0f + 6.2f * (float)i);
    }
    glEnd();
    glPointSize(5.0f);
    glBegin(GL_POINTS);
    for (i = 0; i < 12; i++) {
        glColor4f(0.2f, 1.0f, 1.0f, 0.09f * (float)i);
        glVertex2f(5.0f + 7.5f * (float)i, 76.0f);
    }
    glEnd();
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glEnable(GL_SAMPLE_COVERAGE);
    glSampleCoverage(0.5f, GL_FALSE);
    glBegin(GL_LINES);
    glColor3f(1.0f, 1.0f, 1.0f);
    glVertex2f(3.0f, 60.5f);
    glVertex2f(90.0f, 66.3f);
    glEnd();
    glSampleCoverage(0.75f, GL_TRUE);
    glBegin(GL_POINTS);
    glVertex2f(40.0f, 40.0f);
    glVertex2f(60.3f, 40.6f);
    glEnd();
    glDisable(GL_SAMPLE_COVERAGE);
    glPointSize(1.0f);
    glLineWidth(1.0f);
    read_resolved(out, "coverage");

    /* 8. GL_MULTISAMPLE off */
    glDisable(GL_MULTISAMPLE);
    glLineWidth(2.0f);
    star(30.3f, 40.2f, 27.0f, 24, 0.07f);
    points(50.0f, 4.0f);
    glLineWidth(1.0f);
    glEnable(GL_MULTISAMPLE);
    read_resolved(out, "ms_off");

    /* 9. polygon modes */
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glLineWidth(1.5f);
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.8f, 0.0f);
    glVertex2f(5.3f, 5.2f);
    glColor3f(0.0f, 0.8f, 1.0f);
    glVertex2f(60.1f, 12.7f);
    glVertex2f(30.6f, 70.9f);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glPointSize(3.0f);
    glBegin(GL_TRIANGLES);
    glVertex2f(65.3f, 5.2f);
    glVertex2f(90.1f, 12.7f);
    glVertex2f(80.6f, 70.9f);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glPointSize(1.0f);
    glLineWidth(1.0f);
    read_resolved(out, "polygon_mode");

    /* 10. glBitmap into the 4x object (every sample), glCopyPixels from it (an error) */
    {
        static const GLubyte glyph[8] = {0x18, 0x3c, 0x66, 0xc3, 0xff, 0xc3, 0xc3, 0x00};
        static GLubyte big[40 * 8];
        for (i = 0; i < 40 * 8; i++)
            big[i] = (GLubyte)(0x5a ^ (i * 37));
        glColor3f(1.0f, 0.8f, 0.2f);
        glRasterPos2f(10.3f, 10.6f);
        for (i = 0; i < 12; i++)
            glBitmap(8, 8, 0.0f, 0.0f, 6.5f, 0.5f, glyph);
        glDisable(GL_MULTISAMPLE);
        glColor3f(0.2f, 1.0f, 0.4f);
        glRasterPos2f(5.0f, 40.0f);
        glBitmap(320, 8, 0.0f, 0.0f, 0.0f, 0.0f, big);
        glEnable(GL_MULTISAMPLE);
        glColor3f(1.0f, 0.2f, 0.2f);
        glRasterPos3f(4.0f, 60.0f, 0.0f);
        for (i = 0; i < 10; i++)
            glBitmap(8, 8, 0.0f, 0.0f, 8.0f, 1.0f, glyph);
        glRasterPos2f(50.0f, 20.0f);
        glCopyPixels(0, 0, 8, 8, GL_COLOR);
        sgl_text(out, "copy_ms", "err %x", glGetError());
    }
    read_resolved(out, "bitmap");

    sgl_text(out, "final", "err %x", glGetError());
    OSMesaDestroyContext(ctx);
    free(buf);
    sgl_close(out);
    return 0;
}
