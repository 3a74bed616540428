/* immediate_hierarchy: immediate mode with a matrix hierarchy (a small
 * solar system and a robot arm): glPushMatrix/glPopMatrix, glTranslatef/d,
 * glRotatef/d, glScalef/d, glMultMatrixf, glLoadMatrixd, glFrustum
 * perspective and the depth test. */
#include <GL/gl.h>
#include <GL/osmesa.h>
#include <math.h>
#include "common.h"

#define W 256
#define H 256

/* a unit cube, each face with its own corner colours */
static void cube(float shade)
{
    static const GLfloat p[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const int f[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
    int i, k;
    glBegin(GL_QUADS);
    for (i = 0; i < 6; i++)
        for (k = 0; k < 4; k++) {
            const GLfloat *v = p[f[i][k]];
            glColor3f(shade * (0.5f + 0.5f * v[0]), shade * (0.5f + 0.5f * v[1]),
                      0.3f + 0.1f * i);
            glVertex3fv(v);
        }
    glEnd();
}

/* a triangulated "sphere" (octahedron subdivided once) */
static void ball(float r, float g, float b)
{
    static const GLfloat o[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                    {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    static const int t[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    int i, k;
    glBegin(GL_TRIANGLES);
    for (i = 0; i < 8; i++) {
        const GLfloat *a = o[t[i][0]], *bb = o[t[i][1]], *c = o[t[i][2]];
        GLfloat m[3][3];
        const GLfloat *tri[4][3];
        for (k = 0; k < 3; k++) {
            m[0][k] = a[k] + bb[k];
            m[1][k] = bb[k] + c[k];
            m[2][k] = c[k] + a[k];
        }
        for (k = 0; k < 3; k++) {
            float l = sqrtf(m[k][0] * m[k][0] + m[k][1] * m[k][1] + m[k][2] * m[k][2]);
            m[k][0] /= l;
            m[k][1] /= l;
            m[k][2] /= l;
        }
        tri[0][0] = a; tri[0][1] = m[0]; tri[0][2] = m[2];
        tri[1][0] = m[0]; tri[1][1] = bb; tri[1][2] = m[1];
        tri[2][0] = m[2]; tri[2][1] = m[1]; tri[2][2] = c;
        tri[3][0] = m[0]; tri[3][1] = m[1]; tri[3][2] = m[2];
        for (k = 0; k < 4; k++) {
            int v;
            for (v = 0; v < 3; v++) {
                const GLfloat *p = tri[k][v];
                glColor3f(r * (0.6f + 0.4f * p[0]), g * (0.6f + 0.4f * p[1]),
                          b * (0.6f + 0.4f * p[2]));
                glVertex3fv(p);
            }
        }
    }
    glEnd();
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

    glClearColor(0.02f, 0.03f, 0.08f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.613, 0.587, -0.55, 0.6137, 1.337, 40.0);
    glMatrixMode(GL_MODELVIEW);
    {
        /* camera given as a raw matrix */
        static const GLdouble cam[16] = {1, 0, 0, 0, 0, 0.96126, -0.27564, 0,
                                         0, 0.27564, 0.96126, 0, -0.37, 0.61, -12.3, 1};
        glLoadMatrixd(cam);
    }

    /* solar system */
    glPushMatrix();
    glTranslatef(-1.3f, 0.4f, 0.0f);
    glRotatef(23.7f, 0.0f, 1.0f, 0.0f);
    ball(1.0f, 0.85f, 0.2f); /* sun */
    for (i = 0; i < 4; i++) {
        glPushMatrix();
        glRotated(47.3 + 71.9 * i, 0.0, 1.0, 0.0);
        glTranslated(1.7 + 0.9 * i, 0.0, 0.0);
        glRotatef(13.3f * i, 0.3f, 0.2f, 1.0f);
        glScalef(0.31f + 0.07f * i, 0.31f + 0.07f * i, 0.31f + 0.07f * i);
        ball(0.3f + 0.2f * i, 0.9f - 0.2f * i, 0.5f + 0.1f * i);
        if (i >= 1) { /* a moon */
            glPushMatrix();
            glRotatef(-31.0f * i, 0.0f, 1.0f, 0.0f);
            glTranslatef(1.9f, 0.3f, 0.0f);
            glScaled(0.4, 0.4, 0.4);
            ball(0.8f, 0.8f, 0.8f);
            glPopMatrix();
        }
        glPopMatrix();
    }
    glPopMatrix();

    /* robot arm */
    glPushMatrix();
    glTranslatef(2.9f, -1.9f, 1.3f);
    glRotatef(-20.0f, 0.0f, 1.0f, 0.0f);
    glPushMatrix();
    glScalef(1.2f, 0.2f, 1.2f);
    cube(0.6f); /* base */
    glPopMatrix();
    glRotatef(75.5f, 0.0f, 0.0f, 1.0f);
    glTranslatef(1.0f, 0.0f, 0.0f);
    glPushMatrix();
    glScalef(1.0f, 0.25f, 0.3f);
    cube(1.0f); /* upper arm */
    glPopMatrix();
    glTranslatef(1.0f, 0.0f, 0.0f);
    glRotatef(-110.3f, 0.0f, 0.0f, 1.0f);
    glTranslatef(0.8f, 0.0f, 0.0f);
    {
        /* shear the forearm with a custom matrix */
        static const GLfloat shear[16] = {0.8f, 0.0f, 0.0f, 0.0f, 0.137f, 0.2f, 0.0f, 0.0f,
                                          0.0f, 0.0f, 0.25f, 0.0f, 0.0f, 0.0f, 0.0f, 1.0f};
        glPushMatrix();
        glMultMatrixf(shear);
        cube(0.8f);
        glPopMatrix();
    }
    glTranslatef(0.9f, 0.0f, 0.0f);
    glScalef(0.3f, 0.3f, 0.3f);
    ball(1.0f, 0.3f, 0.3f); /* hand */
    glPopMatrix();

    /* a ground grid of quads */
    glBegin(GL_QUADS);
    for (i = 0; i < 64; i++) {
        float x = -6.0f + (i % 8) * 1.5f, z = -8.0f + (i / 8) * 1.5f;
        float c = ((i + i / 8) & 1) ? 0.35f : 0.15f;
        glColor3f(c, c + 0.1f, c);
        glVertex3f(x, -2.3f, z);
        glVertex3f(x, -2.3f, z + 1.5f);
        glVertex3f(x + 1.5f, -2.3f, z + 1.5f);
        glVertex3f(x + 1.5f, -2.3f, z);
    }
    glEnd();

    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
