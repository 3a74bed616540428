/*
 * texgen_common.h - meshes with normals for the texgen and clip-plane scenes.
 * Include after <GL/gl.h> and "common.h".
 */
#ifndef SGL_TEXGEN_COMMON_H
#define SGL_TEXGEN_COMMON_H

#include <math.h>

/* A sphere of radius r as quad strips (slices x stacks), with unit normals. */
static inline void sgl_sphere(float r, int slices, int stacks)
{
    int i, j;
    for (j = 0; j < stacks; j++) {
        float a0 = (float)M_PI * (-0.5f + (float)j / stacks);
        float a1 = (float)M_PI * (-0.5f + (float)(j + 1) / stacks);
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i <= slices; i++) {
            float b = 2.0f * (float)M_PI * (float)i / slices;
            float x0 = cosf(a0) * cosf(b), y0 = sinf(a0), z0 = cosf(a0) * sinf(b);
            float x1 = cosf(a1) * cosf(b), y1 = sinf(a1), z1 = cosf(a1) * sinf(b);
            glNormal3f(x1, y1, z1);
            glVertex3f(r * x1, r * y1, r * z1);
            glNormal3f(x0, y0, z0);
            glVertex3f(r * x0, r * y0, r * z0);
        }
        glEnd();
    }
}

/* A torus (major radius R, minor r) as triangle strips, with unit normals. */
static inline void sgl_torus(float R, float r, int n, int m)
{
    int i, j;
    for (i = 0; i < n; i++) {
        glBegin(GL_TRIANGLE_STRIP);
        for (j = 0; j <= m; j++) {
            int k;
            for (k = 1; k >= 0; k--) {
                float u = 2.0f * (float)M_PI * (float)(i + k) / n;
                float v = 2.0f * (float)M_PI * (float)j / m;
                float nx = cosf(v) * cosf(u), ny = cosf(v) * sinf(u), nz = sinf(v);
                glNormal3f(nx, ny, nz);
                glVertex3f((R + r * cosf(v)) * cosf(u), (R + r * cosf(v)) * sinf(u), r * nz);
            }
        }
        glEnd();
    }
}

/* An RGBA stripe texture, n texels wide and 1 high... as 2D (n x 4) with
 * alternating colours a/b every texel. */
static inline void sgl_stripe_texture(int n, const unsigned char *a, const unsigned char *b)
{
    unsigned char *p = malloc((size_t)n * 4 * 4);
    int x, y;
    SGL_CHECK(p != NULL);
    for (y = 0; y < 4; y++)
        for (x = 0; x < n; x++)
            memcpy(p + 4 * (y * n + x), (x & 1) ? b : a, 4);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, n, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, p);
    free(p);
}

/* A perspective camera looking down -z at the origin from distance d. */
static inline void sgl_persp(int w, int h, float d)
{
    glViewport(0, 0, w, h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5 * w / h, 0.5 * w / h, -0.5, 0.5, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -d);
}

#endif
