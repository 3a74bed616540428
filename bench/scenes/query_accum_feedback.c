/*
 * query_accum_feedback.c - occlusion queries, the accumulation buffer and feedback mode.
 *
 * A 16-bit accumulation buffer.  Each frame: (1) 4 jittered renders of 30
 * lit spheres behind a wall of quads, each sphere inside a
 * GL_SAMPLES_PASSED occlusion query (results read with glGetQueryObjectuiv),
 * combined with glAccum(GL_LOAD / GL_ACCUM, 0.25) and GL_RETURN; (2) the
 * even-numbered spheres whose query counted over 200 samples are drawn in
 * glRenderMode(GL_FEEDBACK) (GL_3D_COLOR, 128k floats), and the feedback
 * polygons are drawn back as line loops over the image.
 */
#define BENCH_ACCUM_BITS 16
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include "bench.h"
#include "shapes.h"

#define NSPH 30
#define FB_SIZE 131072

static GLuint queries[NSPH];
static GLfloat fb[FB_SIZE];

static void scene_setup(int w, int h)
{
    static const GLfloat pos[4] = {0.3f, 0.6f, 1.0f, 0.0f};
    BENCH_UNUSED(w, h);
    glGenQueries(NSPH, queries);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    glLightfv(GL_LIGHT0, GL_POSITION, pos);
    glEnable(GL_COLOR_MATERIAL);
    glEnable(GL_NORMALIZE);
    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClearAccum(0.0f, 0.0f, 0.0f, 0.0f);
    glFeedbackBuffer(FB_SIZE, GL_3D_COLOR, fb);
}

static void projection(float jx, float jy, int w, int h)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glTranslatef(2.0f * jx / (float)w, 2.0f * jy / (float)h, 0.0f);
    glFrustum(-1.0, 1.0, -1.0, 1.0, 2.0, 40.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

static void sphere_at(int i)
{
    glPushMatrix();
    glTranslatef(-4.0f + 1.6f * (float)(i % 6), -3.2f + 1.6f * (float)(i / 6),
                 -9.0f - 0.4f * (float)(i % 4));
    glColor3f(0.4f + 0.02f * (float)i, 0.7f - 0.02f * (float)i, 0.5f);
    shape_sphere(0.75f, 16, 10);
    glPopMatrix();
}

static void scene_frame(int w, int h)
{
    static const float jit[4][2] = {{0.25f, 0.25f}, {-0.25f, 0.25f}, {0.25f, -0.25f},
                                    {-0.25f, -0.25f}};
    GLuint visible[NSPH];
    GLint n, p;
    int i, j;
    for (j = 0; j < 4; j++) {
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        projection(jit[j][0], jit[j][1], w, h);
        /* the occluding wall: horizontal slats */
        glDisable(GL_LIGHTING);
        glBegin(GL_QUADS);
        for (i = 0; i < 8; i++) {
            float y = -4.0f + (float)i;
            glColor3f(0.5f, 0.35f + 0.03f * (float)i, 0.2f);
            glVertex3f(-6.0f, y, -7.0f);
            glVertex3f(6.0f, y, -7.0f);
            glVertex3f(6.0f, y + 0.55f, -7.0f);
            glVertex3f(-6.0f, y + 0.55f, -7.0f);
        }
        glEnd();
        glEnable(GL_LIGHTING);
        for (i = 0; i < NSPH; i++) {
            glBeginQuery(GL_SAMPLES_PASSED, queries[i]);
            sphere_at(i);
            glEndQuery(GL_SAMPLES_PASSED);
        }
        glAccum(j == 0 ? GL_LOAD : GL_ACCUM, 0.25f);
    }
    glAccum(GL_RETURN, 1.0f);
    for (i = 0; i < NSPH; i++)
        glGetQueryObjectuiv(queries[i], GL_QUERY_RESULT, &visible[i]);

    /* Feedback of the visible spheres, drawn back as outlines. */
    projection(0.0f, 0.0f, w, h);
    glRenderMode(GL_FEEDBACK);
    for (i = 0; i < NSPH; i++)
        if (visible[i] > 200u && i % 2 == 0)
            sphere_at(i);
    n = glRenderMode(GL_RENDER);
    glDisable(GL_LIGHTING);
    glDisable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, (double)w, 0.0, (double)h, -1.0, 1.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    for (p = 0; p < n;) {
        GLint token = (GLint)fb[p++];
        if (token == GL_POLYGON_TOKEN) {
            GLint k, count = (GLint)fb[p++];
            glBegin(GL_LINE_LOOP);
            for (k = 0; k < count; k++, p += 7) {
                glColor3f(fb[p + 3], 1.0f - fb[p + 4], fb[p + 5]);
                glVertex2f(fb[p], fb[p + 1]);
            }
            glEnd();
        } else {
            break;
        }
    }
    glEnable(GL_DEPTH_TEST);
}
