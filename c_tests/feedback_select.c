/* feedback_select: glRenderMode(GL_FEEDBACK) and (GL_SELECT).  Feedback of
 * points, lines, strips, loops, triangles, quads, polygons and rectangles in
 * each feedback type; clipping, culling, polygon modes with edge flags,
 * polygon offset, flat shading, two-sided lighting, texture matrix and texgen
 * (which apply only with a complete texture enabled) in the reported vertices;
 * the line-reset token, which Mesa writes for the first line of an unfilled
 * primitive and keeps pending across draws; glPassThrough (also from a display list); buffer
 * overflow; vertex arrays.  Selection: the name stack, hit records with their
 * depth range (z = 1 included), overflow, and the errors of the name calls.
 * The image drawn afterwards shows that rendering resumes.
 *
 * Not here: glEdgeFlag with unfilled polygons.  Once a program has called
 * glEdgeFlag, Mesa 22.3's feedback path drops every edge and vertex of
 * unfilled polygons (even with all flags GL_TRUE); softgl follows the spec
 * there (tests/feedback.rs checks it against the spec's rule). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"

#define W 64
#define H 48

static char text[65536];
static int n;
static GLfloat fbuf[4096];
static GLuint sbuf[512];

static void say(const char *fmt, double a)
{
    n += snprintf(text + n, sizeof text - n, fmt, a);
}

static void dump_feedback(const char *what, GLint count)
{
    n += snprintf(text + n, sizeof text - n, "%s: %d values err %x\n", what, count, glGetError());
    for (GLint i = 0; i < count && i < 4096; i++)
        n += snprintf(text + n, sizeof text - n, "%.9g%c", fbuf[i], (i % 8 == 7) ? '\n' : ' ');
    n += snprintf(text + n, sizeof text - n, "\n");
}

static void dump_select(const char *what, GLint hits)
{
    GLuint *p = sbuf;
    n += snprintf(text + n, sizeof text - n, "%s: %d hits err %x\n", what, hits, glGetError());
    for (GLint h = 0; h < hits; h++) {
        GLuint names = *p++;
        n += snprintf(text + n, sizeof text - n, "  %u names z %u %u:", names, p[0], p[1]);
        p += 2;
        for (GLuint k = 0; k < names; k++)
            n += snprintf(text + n, sizeof text - n, " %u", *p++);
        n += snprintf(text + n, sizeof text - n, "\n");
    }
}

static void shapes(void)
{
    glBegin(GL_TRIANGLES);
    glColor3f(1.0f, 0.0f, 0.0f);
    glVertex3f(-0.8f, -0.8f, 0.1f);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex3f(0.1f, -0.7f, -0.2f);
    glColor3f(0.0f, 0.0f, 1.0f);
    glVertex3f(-0.3f, 0.4f, 0.3f);
    glEnd();
    glColor4f(0.25f, 0.5f, 0.75f, 0.5f);
    glBegin(GL_LINE_STRIP);
    glVertex2f(-0.9f, 0.9f);
    glVertex2f(0.0f, 0.5f);
    glVertex2f(0.9f, 0.8f);
    glEnd();
    glBegin(GL_POINTS);
    glVertex3f(0.5f, 0.5f, -0.5f);
    glVertex3f(1.5f, 0.5f, 0.0f); /* outside: no point */
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    static unsigned char buf[W * H * 4];
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    GLint v, i;
    GLuint list;
    static const GLfloat verts[] = {-0.5f, -0.5f, 0.5f, -0.5f, 0.5f, 0.5f, -0.5f, 0.5f};
    static const GLubyte idx[] = {0, 1, 2, 2, 3, 0};

    if (!ctx || !OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, W, H))
        return 1;
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);

    /* state before any buffer */
    glGetIntegerv(GL_RENDER_MODE, &v);
    say("render mode %g\n", v);
    glGetIntegerv(GL_MAX_NAME_STACK_DEPTH, &v);
    say("max name stack %g\n", v);
    v = glRenderMode(GL_FEEDBACK);
    say("feedback without buffer %g", v);
    say(" err %g\n", glGetError());
    glRenderMode(GL_RENDER);
    glGetError();

    /* GL_3D_COLOR: the basic shapes */
    glFeedbackBuffer(4096, GL_3D_COLOR, fbuf);
    glGetIntegerv(GL_FEEDBACK_BUFFER_SIZE, &v);
    say("feedback size %g", v);
    glGetIntegerv(GL_FEEDBACK_BUFFER_TYPE, &v);
    say(" type %g\n", v);
    glRenderMode(GL_FEEDBACK);
    glGetIntegerv(GL_RENDER_MODE, &v);
    say("render mode %g\n", v);
    shapes();
    glPassThrough(42.5f);
    dump_feedback("3d color", glRenderMode(GL_RENDER));

    /* 2D, quads, polygon, loop, rect, clipping */
    glFeedbackBuffer(4096, GL_2D, fbuf);
    glRenderMode(GL_FEEDBACK);
    glBegin(GL_QUADS);
    glVertex2f(-0.5f, -0.5f);
    glVertex2f(0.5f, -0.5f);
    glVertex2f(0.5f, 0.5f);
    glVertex2f(-0.5f, 0.5f);
    glEnd();
    glBegin(GL_POLYGON);
    for (i = 0; i < 5; i++)
        glVertex2f(0.3f * (float)i - 0.6f, (i & 1) ? 0.6f : -0.2f * (float)i);
    glEnd();
    glBegin(GL_LINE_LOOP);
    glVertex2f(-0.2f, -0.2f);
    glVertex2f(0.2f, -0.2f);
    glVertex2f(0.0f, 0.3f);
    glEnd();
    glRectf(-0.25f, -0.25f, 0.25f, 0.125f);
    glBegin(GL_TRIANGLES); /* crosses the right and top edges */
    glVertex2f(0.5f, 0.5f);
    glVertex2f(1.7f, 0.6f);
    glVertex2f(0.6f, 1.9f);
    glEnd();
    glBegin(GL_LINES); /* clipped at the left */
    glVertex2f(-1.5f, 0.25f);
    glVertex2f(0.5f, 0.0f);
    glEnd();
    dump_feedback("2d quads polygon loop rect clip", glRenderMode(GL_RENDER));

    /* culling, polygon modes with edge flags, offset, flat shading */
    glFeedbackBuffer(4096, GL_3D_COLOR, fbuf);
    glRenderMode(GL_FEEDBACK);
    glEnable(GL_CULL_FACE);
    glBegin(GL_TRIANGLES);
    glVertex2f(-0.5f, -0.5f); /* clockwise: culled */
    glVertex2f(0.0f, 0.5f);
    glVertex2f(0.5f, -0.5f);
    glVertex2f(-0.5f, -0.5f); /* counter-clockwise: kept */
    glVertex2f(0.5f, -0.5f);
    glVertex2f(0.0f, 0.5f);
    glEnd();
    glDisable(GL_CULL_FACE);
    glPolygonMode(GL_FRONT, GL_LINE);
    glPolygonMode(GL_BACK, GL_POINT);
    glShadeModel(GL_FLAT);
    glEnable(GL_POLYGON_OFFSET_LINE);
    glPolygonOffset(2.0f, 4.0f);
    glBegin(GL_QUADS);
    glColor3f(1.0f, 0.0f, 0.0f);
    glVertex3f(-0.5f, -0.5f, 0.0f);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex3f(0.5f, -0.5f, 0.25f);
    glColor3f(0.0f, 0.0f, 1.0f);
    glVertex3f(0.5f, 0.5f, 0.5f);
    glColor3f(1.0f, 1.0f, 0.0f);
    glVertex3f(-0.5f, 0.5f, 0.0f);
    glEnd();
    glBegin(GL_TRIANGLES); /* back-facing: points */
    glVertex2f(-0.5f, -0.5f);
    glVertex2f(0.0f, 0.5f);
    glVertex2f(0.5f, -0.5f);
    glEnd();
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_POLYGON_OFFSET_LINE);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glBegin(GL_TRIANGLES); /* filled with offset, flat but filled: colours as given */
    glColor3f(1.0f, 0.0f, 0.0f);
    glVertex3f(-0.5f, -0.5f, 0.0f);
    glColor3f(0.0f, 1.0f, 0.0f);
    glVertex3f(0.5f, -0.5f, 0.5f);
    glColor3f(0.0f, 0.0f, 1.0f);
    glVertex3f(0.0f, 0.5f, 0.25f);
    glEnd();
    glDisable(GL_POLYGON_OFFSET_FILL);
    glShadeModel(GL_SMOOTH);
    dump_feedback("cull modes offset flat", glRenderMode(GL_RENDER));

    /* 4D colour texture: perspective, texture matrix, texgen, lighting, arrays */
    glFeedbackBuffer(4096, GL_4D_COLOR_TEXTURE, fbuf);
    glRenderMode(GL_FEEDBACK);
    glMatrixMode(GL_PROJECTION);
    glFrustum(-1.0, 1.0, -0.75, 0.75, 1.0, 10.0);
    glMatrixMode(GL_TEXTURE);
    glTranslatef(0.5f, 0.25f, 0.0f);
    glScalef(2.0f, 1.0f, 1.0f);
    glMatrixMode(GL_MODELVIEW);
    glTranslatef(0.0f, 0.0f, -3.0f);
    glRotatef(30.0f, 1.0f, 0.5f, 0.0f);
    glBegin(GL_TRIANGLES);
    glTexCoord2f(0.0f, 0.0f);
    glVertex3f(-1.0f, -1.0f, 0.0f);
    glTexCoord2f(1.0f, 0.0f);
    glVertex3f(1.0f, -1.0f, 0.0f);
    glTexCoord4f(0.5f, 1.0f, 0.25f, 2.0f);
    glVertex3f(0.0f, 1.0f, 0.5f);
    glEnd();
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glEnable(GL_TEXTURE_GEN_S);
    glBegin(GL_LINES);
    glVertex3f(-0.5f, 0.0f, 0.0f);
    glVertex3f(0.5f, 0.25f, 1.0f);
    glEnd();
    glDisable(GL_TEXTURE_GEN_S);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glNormal3f(0.0f, 0.0f, 1.0f);
    glBegin(GL_TRIANGLES);
    glVertex3f(-1.0f, -1.0f, 0.0f); /* front */
    glVertex3f(1.0f, -1.0f, 0.0f);
    glVertex3f(0.0f, 1.0f, 0.0f);
    glVertex3f(-1.0f, -1.0f, 0.0f); /* back */
    glVertex3f(0.0f, 1.0f, 0.0f);
    glVertex3f(1.0f, -1.0f, 0.0f);
    glEnd();
    glDisable(GL_LIGHTING);
    glVertexPointer(2, GL_FLOAT, 0, verts);
    glEnableClientState(GL_VERTEX_ARRAY);
    glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, idx);
    glDisableClientState(GL_VERTEX_ARRAY);
    {
        /* a complete texture on unit 0: now the texture matrix and texgen apply */
        static const GLubyte texel[4] = {255, 255, 255, 255};
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glEnable(GL_TEXTURE_2D);
        glBegin(GL_TRIANGLES);
        glTexCoord2f(0.0f, 0.0f);
        glVertex3f(-1.0f, -1.0f, 0.0f);
        glTexCoord2f(1.0f, 0.0f);
        glVertex3f(1.0f, -1.0f, 0.0f);
        glTexCoord4f(0.5f, 1.0f, 0.25f, 2.0f);
        glVertex3f(0.0f, 1.0f, 0.5f);
        glEnd();
        glEnable(GL_TEXTURE_GEN_S);
        glBegin(GL_LINES);
        glVertex3f(-0.5f, 0.0f, 0.0f);
        glVertex3f(0.5f, 0.25f, 1.0f);
        glEnd();
        glDisable(GL_TEXTURE_GEN_S);
        glDisable(GL_TEXTURE_2D);
    }
    list = glGenLists(1);
    glNewList(list, GL_COMPILE);
    glPassThrough(7.0f);
    glBegin(GL_POINTS);
    glVertex3f(0.25f, 0.25f, 0.0f);
    glEnd();
    glEndList();
    glCallList(list);
    {
        /* pixel rectangles: a token and the raster position */
        static const GLubyte px[4] = {10, 20, 30, 40};
        static const GLubyte bits[2] = {0xA0, 0x50};
        glColor4f(0.25f, 0.5f, 0.75f, 1.0f);
        glTexCoord2f(0.125f, 0.375f);
        glRasterPos3f(0.1f, 0.2f, 0.3f);
        glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        glBitmap(4, 2, 0.0f, 0.0f, 2.5f, 1.0f, bits);
        glCopyPixels(0, 0, 2, 2, GL_COLOR);
        glRasterPos3f(9.0f, 0.2f, 0.3f); /* invalid: nothing */
        glDrawPixels(1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px);
        glBitmap(4, 2, 0.0f, 0.0f, 2.5f, 1.0f, bits);
    }
    dump_feedback("4d color texture", glRenderMode(GL_RENDER));
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();

    /* overflow: the buffer holds 10 values */
    glFeedbackBuffer(10, GL_3D, fbuf);
    glRenderMode(GL_FEEDBACK);
    shapes();
    v = glRenderMode(GL_RENDER);
    say("overflow returns %g\n", v);
    dump_feedback("overflow contents", 10);
    glFeedbackBuffer(10, GL_3D, fbuf);
    glRenderMode(GL_FEEDBACK);
    glFeedbackBuffer(10, GL_3D, fbuf);
    say("feedback buffer in feedback mode err %g\n", glGetError());
    glRenderMode(GL_RENDER);

    /* selection */
    glSelectBuffer(512, sbuf);
    glGetIntegerv(GL_SELECTION_BUFFER_SIZE, &v);
    say("select size %g\n", v);
    glRenderMode(GL_SELECT);
    glInitNames();
    glLoadName(5);
    say("load name on empty stack err %g\n", glGetError());
    glPopName();
    say("pop empty err %g\n", glGetError());
    glPushName(1);
    shapes();
    glPushName(2);
    glBegin(GL_TRIANGLES); /* off screen: no hit */
    glVertex2f(2.0f, 2.0f);
    glVertex2f(3.0f, 2.0f);
    glVertex2f(2.0f, 3.0f);
    glEnd();
    glLoadName(3);
    glBegin(GL_LINES); /* z from -1 to 1: depths 0 .. 1 */
    glVertex3f(-0.5f, 0.0f, 1.0f);
    glVertex3f(0.5f, 0.0f, -1.0f);
    glEnd();
    glLoadName(4);
    glBegin(GL_POINTS);
    glVertex3f(0.0f, 0.0f, 0.5f);
    glEnd();
    glGetIntegerv(GL_NAME_STACK_DEPTH, &v);
    say("name stack depth %g\n", v);
    glPopName();
    glRectf(-0.5f, -0.5f, 0.5f, 0.5f);
    glLoadName(6);
    glRasterPos3f(0.25f, 0.25f, 0.75f); /* a valid raster position is a hit */
    glLoadName(7);
    glRasterPos3f(2.0f, 0.25f, 0.75f); /* an invalid one is not */
    glLoadName(8);
    glWindowPos3f(3.0f, 4.0f, 0.25f); /* a window position is */
    glLoadName(9);
    glRasterPos3f(0.25f, 0.25f, 0.5f);
    {
        static const GLubyte bits[2] = {0xFF, 0xFF};
        glBitmap(8, 2, 0.0f, 0.0f, 1.0f, 0.0f, bits); /* no hit of its own */
    }
    glInitNames();
    glBegin(GL_POINTS); /* hit with an empty stack */
    glVertex3f(0.0f, 0.0f, -0.5f);
    glEnd();
    for (i = 0; i < 70; i++)
        glPushName((GLuint)i);
    say("push past 64 err %g\n", glGetError());
    glGetIntegerv(GL_NAME_STACK_DEPTH, &v);
    say("name stack depth %g\n", v);
    glInitNames();
    glBegin(GL_POINTS);
    glRenderMode(GL_RENDER);
    glEnd();
    say("render mode in begin err %g\n", glGetError());
    dump_select("select", glRenderMode(GL_RENDER));
    glGetIntegerv(GL_NAME_STACK_DEPTH, &v);
    say("name stack depth after %g\n", v);
    glPushName(9);
    say("push name in render mode err %g\n", glGetError());

    /* selection overflow: 4 slots */
    glSelectBuffer(4, sbuf);
    glRenderMode(GL_SELECT);
    glPushName(11);
    shapes();
    glLoadName(12);
    shapes();
    v = glRenderMode(GL_RENDER);
    say("select overflow returns %g", v);
    n += snprintf(text + n, sizeof text - n, " first %u %u %u %u\n", sbuf[0], sbuf[1], sbuf[2], sbuf[3]);

    /* rendering resumes */
    shapes();
    sgl_text(out, "feedback", "%s", text);
    glFinish();
    sgl_image(out, "after", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    return 0;
}
