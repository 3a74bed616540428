/*
 * shapes.h - tessellated shapes shared by the feature-group benchmark scenes.
 *
 * Immediate-mode spheres, tori, wavy sheets and boxes with normals and
 * texture coordinates, as ordinary GL 1.x programs draw them.  Include after
 * <GL/gl.h> and <math.h>.
 */
#ifndef SGL_BENCH_SHAPES_H
#define SGL_BENCH_SHAPES_H

#include <math.h>

#define SHAPES_PI 3.14159265358979f

/* A symmetric perspective projection (glFrustum with +-half at `n`) and an identity
 * modelview, the modelview matrix left current. */
static inline void shape_perspective(double half, double n, double f)
{
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-half, half, -half, half, n, f);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
}

/* A sphere of radius r at the origin: `slices` x `stacks` quads as strips. */
static inline void shape_sphere(float r, int slices, int stacks)
{
    int i, j;
    for (j = 0; j < stacks; j++) {
        float a0 = SHAPES_PI * ((float)j / (float)stacks - 0.5f);
        float a1 = SHAPES_PI * ((float)(j + 1) / (float)stacks - 0.5f);
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i <= slices; i++) {
            float b = 2.0f * SHAPES_PI * (float)i / (float)slices;
            float x0 = cosf(a0) * cosf(b), y0 = sinf(a0), z0 = cosf(a0) * sinf(b);
            float x1 = cosf(a1) * cosf(b), y1 = sinf(a1), z1 = cosf(a1) * sinf(b);
            glTexCoord2f((float)i / (float)slices, (float)(j + 1) / (float)stacks);
            glNormal3f(x1, y1, z1);
            glVertex3f(r * x1, r * y1, r * z1);
            glTexCoord2f((float)i / (float)slices, (float)j / (float)stacks);
            glNormal3f(x0, y0, z0);
            glVertex3f(r * x0, r * y0, r * z0);
        }
        glEnd();
    }
}

/* A torus around the z axis: ring radius R, tube radius r. */
static inline void shape_torus(float R, float r, int rings, int sides)
{
    int i, j;
    for (i = 0; i < rings; i++) {
        glBegin(GL_QUAD_STRIP);
        for (j = 0; j <= sides; j++) {
            int k;
            for (k = 1; k >= 0; k--) {
                float u = 2.0f * SHAPES_PI * (float)(i + k) / (float)rings;
                float v = 2.0f * SHAPES_PI * (float)j / (float)sides;
                float nx = cosf(u) * cosf(v), ny = sinf(u) * cosf(v), nz = sinf(v);
                glTexCoord2f(4.0f * (float)(i + k) / (float)rings, (float)j / (float)sides);
                glNormal3f(nx, ny, nz);
                glVertex3f((R + r * cosf(v)) * cosf(u), (R + r * cosf(v)) * sinf(u), r * nz);
            }
        }
        glEnd();
    }
}

/* A wavy sheet over [-1, 1]^2 in z = 0 with n x n quads and smooth normals. */
static inline void shape_sheet(int n, float amp, float freq)
{
    int i, j;
    for (j = 0; j < n; j++) {
        glBegin(GL_TRIANGLE_STRIP);
        for (i = 0; i <= n; i++) {
            int k;
            for (k = 1; k >= 0; k--) {
                float x = -1.0f + 2.0f * (float)i / (float)n;
                float y = -1.0f + 2.0f * (float)(j + k) / (float)n;
                float z = amp * sinf(freq * x) * cosf(freq * y);
                float dx = amp * freq * cosf(freq * x) * cosf(freq * y);
                float dy = -amp * freq * sinf(freq * x) * sinf(freq * y);
                float l = sqrtf(dx * dx + dy * dy + 1.0f);
                glTexCoord2f(0.5f * x + 0.5f, 0.5f * y + 0.5f);
                glNormal3f(-dx / l, -dy / l, 1.0f / l);
                glVertex3f(x, y, z);
            }
        }
        glEnd();
    }
}

/* An axis-aligned unit cube centred at the origin, with normals and texcoords. */
static inline void shape_cube(void)
{
    static const float n[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                  {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    int f;
    glBegin(GL_QUADS);
    for (f = 0; f < 6; f++) {
        /* two axes spanning the face */
        float u[3], v[3];
        int c;
        if (n[f][0] != 0) {
            u[0] = 0; u[1] = 1; u[2] = 0;
        } else if (n[f][1] != 0) {
            u[0] = 0; u[1] = 0; u[2] = 1;
        } else {
            u[0] = 1; u[1] = 0; u[2] = 0;
        }
        v[0] = n[f][1] * u[2] - n[f][2] * u[1];
        v[1] = n[f][2] * u[0] - n[f][0] * u[2];
        v[2] = n[f][0] * u[1] - n[f][1] * u[0];
        glNormal3fv(n[f]);
        for (c = 0; c < 4; c++) {
            float su = (c == 1 || c == 2) ? 0.5f : -0.5f;
            float sv = (c >= 2) ? 0.5f : -0.5f;
            glTexCoord2f(su + 0.5f, sv + 0.5f);
            glVertex3f(0.5f * n[f][0] + su * u[0] + sv * v[0],
                       0.5f * n[f][1] + su * u[1] + sv * v[1],
                       0.5f * n[f][2] + su * u[2] + sv * v[2]);
        }
    }
    glEnd();
}

/* A unit sphere as arrays for glDrawElements: `slices` x `stacks` quads as two
 * triangles each (`slices * stacks * 6` indices into `(slices + 1) * (stacks + 1)`
 * vertices). Each vertex is `stride` floats: the position, the normal (the same), and
 * with a stride of 8 the texture coordinates (s twice around, t from pole to pole). */
static inline void shape_sphere_arrays(float *verts, int stride, unsigned short *idx,
                                       int slices, int stacks)
{
    int i, j, k = 0;
    for (j = 0; j <= stacks; j++)
        for (i = 0; i <= slices; i++) {
            float th = SHAPES_PI * (float)j / (float)stacks;
            float ph = 2.0f * SHAPES_PI * (float)i / (float)slices;
            float *v = verts + (j * (slices + 1) + i) * stride;
            v[0] = v[3] = sinf(th) * cosf(ph);
            v[1] = v[4] = sinf(th) * sinf(ph);
            v[2] = v[5] = cosf(th);
            if (stride >= 8) {
                v[6] = 2.0f * (float)i / (float)slices;
                v[7] = (float)j / (float)stacks;
            }
        }
    for (j = 0; j < stacks; j++)
        for (i = 0; i < slices; i++) {
            unsigned short a = (unsigned short)(j * (slices + 1) + i);
            unsigned short b = (unsigned short)(a + slices + 1);
            idx[k++] = a;
            idx[k++] = b;
            idx[k++] = (unsigned short)(a + 1);
            idx[k++] = (unsigned short)(a + 1);
            idx[k++] = b;
            idx[k++] = (unsigned short)(b + 1);
        }
}

#endif
