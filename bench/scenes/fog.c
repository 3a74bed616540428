/*
 * fog.c - fog: LINEAR, EXP and EXP2, fragment depth and fog coordinates, over a textured terrain.
 *
 * A 96x96 height-field terrain in perspective (smooth colours, MODULATE with
 * a 64x64 RGB texture, depth test) drawn four times per frame, each in a
 * quarter of the window (scissored viewport): GL_LINEAR fog (start 2,
 * end 30), GL_EXP (density 0.08), GL_EXP2 (density 0.06), and GL_LINEAR with
 * GL_FOG_COORD_SRC = GL_FOG_COORD from per-vertex glFogCoordf, each with a
 * GL_FOG_HINT of NICEST or FASTEST in turn.
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include "bench.h"
#include <math.h>

#define N 96

static float height(int i, int j)
{
    float x = (float)i / (float)N, y = (float)j / (float)N;
    return 0.8f * sinf(9.0f * x) * cosf(7.0f * y) + 0.4f * sinf(23.0f * x * y);
}

static void scene_setup(int w, int h)
{
    static unsigned char t[64 * 64 * 3];
    static const GLfloat fogc[4] = {0.7f, 0.75f, 0.8f, 1.0f};
    GLuint tex;
    int i;
    BENCH_UNUSED(w, h);
    for (i = 0; i < 64 * 64; i++) {
        int x = i % 64, y = i / 64;
        t[i * 3 + 0] = (unsigned char)(120 + ((x * y) & 63));
        t[i * 3 + 1] = (unsigned char)(((x >> 3) ^ (y >> 3)) & 1 ? 200 : 140);
        t[i * 3 + 2] = (unsigned char)(80 + y);
    }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, 64, 64, 0, GL_RGB, GL_UNSIGNED_BYTE, t);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glFogfv(GL_FOG_COLOR, fogc);
    glFogf(GL_FOG_START, 2.0f);
    glFogf(GL_FOG_END, 30.0f);
    glEnable(GL_FOG);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_SCISSOR_TEST);
    glClearColor(0.7f, 0.75f, 0.8f, 1.0f);
}

static void terrain(void)
{
    int i, j;
    for (j = 0; j < N; j++) {
        glBegin(GL_TRIANGLE_STRIP);
        for (i = 0; i <= N; i++) {
            int k;
            for (k = 1; k >= 0; k--) {
                float z = height(i, j + k);
                glColor3f(0.5f + 0.3f * z, 0.6f, 0.4f - 0.2f * z);
                glFogCoordf(0.3f * (float)(j + k) + 4.0f * z);
                glTexCoord2f(0.1f * (float)i, 0.1f * (float)(j + k));
                glVertex3f(-12.0f + 24.0f * (float)i / (float)N, z,
                           -40.0f + 38.0f * (float)(j + k) / (float)N);
            }
        }
        glEnd();
    }
}

static void scene_frame(int w, int h)
{
    static const GLint modes[4] = {GL_LINEAR, GL_EXP, GL_EXP2, GL_LINEAR};
    static const GLfloat dens[4] = {0.0f, 0.08f, 0.06f, 0.0f};
    int q;
    glScissor(0, 0, w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (q = 0; q < 4; q++) {
        int x = (q & 1) * (w / 2), y = (q >> 1) * (h / 2);
        glViewport(x, y, w / 2, h / 2);
        glScissor(x, y, w / 2, h / 2);
        glMatrixMode(GL_PROJECTION);
        glLoadIdentity();
        glFrustum(-0.6, 0.6, -0.4, 0.6, 1.0, 60.0);
        glMatrixMode(GL_MODELVIEW);
        glLoadIdentity();
        glTranslatef(0.0f, -2.0f, 0.0f);
        glRotatef(8.0f, 1.0f, 0.0f, 0.0f);
        glFogi(GL_FOG_MODE, modes[q]);
        glFogf(GL_FOG_DENSITY, dens[q]);
        glFogi(GL_FOG_COORD_SRC, q == 3 ? GL_FOG_COORD : GL_FRAGMENT_DEPTH);
        glHint(GL_FOG_HINT, (q & 1) ? GL_FASTEST : GL_NICEST);
        terrain();
    }
}
