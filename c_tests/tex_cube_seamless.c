/* tex_cube_seamless: GL_ARB_seamless_cube_map (GL_TEXTURE_CUBE_MAP_SEAMLESS).
 * An 8x8 cube map whose faces have distinct colours and a per-texel ramp,
 * magnified on quads with explicit (s,t,r) around each of the eight cube
 * corners and across each face's edges, with seamless filtering off and on;
 * NEAREST magnification with LINEAR minification; a mipmapped cube map at a
 * fixed LOD between two levels (MIN_LOD = MAX_LOD); spheres with reflection-map
 * texgen, seamless off and on; then the enable's queries, its (absent) attribute
 * group, and the extension string. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <string.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256
#define N 8
#define P 32 /* panel size */

static unsigned char face[6][N * N * 4];

static void sphere(float cx, float cy, float cz, float rad, int slices, int stacks)
{
    int i, j;
    for (j = 0; j < stacks; j++) {
        float a0 = 3.14159265f * (float)j / stacks - 1.5707963f;
        float a1 = 3.14159265f * (float)(j + 1) / stacks - 1.5707963f;
        glBegin(GL_QUAD_STRIP);
        for (i = 0; i <= slices; i++) {
            float b = 6.2831853f * (float)i / slices;
            float x0 = cosf(a0) * cosf(b), y0 = sinf(a0), z0 = cosf(a0) * sinf(b);
            float x1 = cosf(a1) * cosf(b), y1 = sinf(a1), z1 = cosf(a1) * sinf(b);
            glNormal3f(x1, y1, z1);
            glVertex3f(cx + rad * x1, cy + rad * y1, cz + rad * z1);
            glNormal3f(x0, y0, z0);
            glVertex3f(cx + rad * x0, cy + rad * y0, cz + rad * z0);
        }
        glEnd();
    }
}

/* A panel at (x, y) whose corners look along c ± e1 ± e2. */
static void panel(float x, float y, const float *c, const float *e1, const float *e2)
{
    static const float sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1};
    int k, i;
    glBegin(GL_QUADS);
    for (k = 0; k < 4; k++) {
        float d[3];
        for (i = 0; i < 3; i++)
            d[i] = c[i] + sx[k] * e1[i] + sy[k] * e2[i];
        glTexCoord3fv(d);
        glVertex2f(x + (sx[k] > 0 ? P - 1 : 1), y + (sy[k] > 0 ? P - 1 : 1));
    }
    glEnd();
}

/* The eight cube corners in a row at y. */
static void corners(float y, float ext)
{
    int k;
    for (k = 0; k < 8; k++) {
        float c[3] = {(k & 1) ? 1.0f : -1.0f, (k & 2) ? 1.0f : -1.0f, (k & 4) ? 1.0f : -1.0f};
        float e1[3] = {ext, -0.3f * ext, 0.2f * ext}, e2[3] = {0.1f * ext, ext, -0.4f * ext};
        panel(P * k, y, c, e1, e2);
    }
}

/* Each face's centre-to-edge sweeps: six panels at y, crossing the x+ and y+ edges
   of face f (and the corner between them). */
static void edges(float y, float reach)
{
    int f;
    for (f = 0; f < 6; f++) {
        float sgn = (f & 1) ? -1.0f : 1.0f;
        int ax = f / 2, u = (ax + 1) % 3, w = (ax + 2) % 3;
        float c[3] = {0, 0, 0}, e1[3] = {0, 0, 0}, e2[3] = {0, 0, 0};
        c[ax] = sgn;
        c[u] = reach;
        c[w] = 0.6f * reach;
        e1[u] = 0.45f;
        e1[w] = 0.05f;
        e2[w] = 0.5f;
        panel(P * f, y, c, e1, e2);
    }
}

static void upload(GLuint t, int levels)
{
    int f, l, size, x, y;
    glBindTexture(GL_TEXTURE_CUBE_MAP, t);
    for (f = 0; f < 6; f++)
        for (l = 0, size = N; l < levels; l++, size /= 2) {
            unsigned char img[N * N * 4];
            for (y = 0; y < size; y++)
                for (x = 0; x < size; x++) {
                    const unsigned char *s = face[f] + 4 * ((y << l) * N + (x << l));
                    unsigned char *d = img + 4 * (y * size + x);
                    d[0] = s[0];
                    d[1] = (unsigned char)(s[1] ^ (l * 60));
                    d[2] = s[2];
                    d[3] = s[3];
                }
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, l, GL_RGBA, size, size, 0, GL_RGBA,
                         GL_UNSIGNED_BYTE, img);
        }
}

int main(int argc, char **argv)
{
    static const unsigned char base[6][3] = {{230, 40, 40},  {40, 200, 60},  {50, 70, 230},
                                             {230, 220, 40}, {200, 50, 210}, {40, 210, 210}};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    GLuint tex[2];
    GLint v[12];
    GLboolean bv = 9;
    int f, x, y;

    for (f = 0; f < 6; f++)
        for (y = 0; y < N; y++)
            for (x = 0; x < N; x++) {
                unsigned char *p = face[f] + 4 * (y * N + x);
                p[0] = (unsigned char)(base[f][0] - 9 * x);
                p[1] = (unsigned char)(base[f][1] + 3 * y - 2 * x);
                p[2] = (unsigned char)(base[f][2] ^ (7 * y + x));
                p[3] = 255;
            }
    glGenTextures(2, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    upload(tex[0], 1);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_REPEAT); /* ignored */
    upload(tex[1], 4);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameterf(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_LOD, 1.375f);
    glTexParameterf(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LOD, 1.375f);

    v[0] = glIsEnabled(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glClearColor(0.1f, 0.1f, 0.1f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    sgl_ortho(W, H);

    /* rows of panels: corners off / on, edges on, mipmapped edges and corners on */
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[0]);
    corners(0.0f, 0.22f);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    corners(P, 0.22f);
    edges(2 * P, 0.85f);
    /* NEAREST magnification (LINEAR minification): no seamless taps */
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    {
        float c[3] = {1.0f, 0.9f, 0.9f}, e1[3] = {0, 0.2f, 0}, e2[3] = {0, 0, 0.2f};
        panel(6 * P, 2 * P, c, e1, e2);
        /* minified: LINEAR across the edges */
        e1[1] = 3.0f;
        e2[2] = 2.5f;
        panel(7 * P, 2 * P, c, e1, e2);
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[1]);
    edges(3 * P, 0.9f);
    {
        float c[3] = {-1.0f, 1.0f, 1.0f}, e1[3] = {0.3f, 0, 0.1f}, e2[3] = {0, 0.3f, 0};
        panel(6 * P, 3 * P, c, e1, e2);
        c[0] = 1.0f;
        c[1] = -1.0f;
        panel(7 * P, 3 * P, c, e1, e2);
    }

    /* reflection-mapped spheres, seamless off and on */
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[0]);
    glEnable(GL_DEPTH_TEST);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.6, 0.6, 1.0, 30.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_GEN_R);
    glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glViewport(2, 130, 124, 124);
    sphere(0.0f, 0.0f, -4.0f, 1.6f, 24, 16);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glViewport(130, 130, 124, 124);
    sphere(0.0f, 0.0f, -4.0f, 1.6f, 24, 16);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glDisable(GL_TEXTURE_GEN_R);
    glDisable(GL_DEPTH_TEST);
    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);

    /* queries: the enable, glGet, and push/pop (Mesa keeps it out of every group) */
    v[1] = glIsEnabled(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glGetBooleanv(GL_TEXTURE_CUBE_MAP_SEAMLESS, &bv);
    glGetIntegerv(GL_TEXTURE_CUBE_MAP_SEAMLESS, &v[2]);
    glPushAttrib(GL_ALL_ATTRIB_BITS);
    glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glPopAttrib();
    v[3] = glIsEnabled(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glPushAttrib(GL_ENABLE_BIT);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glPopAttrib();
    v[4] = glIsEnabled(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    v[5] = glGetError();
    /* in a display list */
    glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glNewList(1, GL_COMPILE);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glEndList();
    v[6] = glIsEnabled(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glCallList(1);
    v[7] = glIsEnabled(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    /* between glBegin and glEnd */
    glBegin(GL_POINTS);
    glDisable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    glEnd();
    v[8] = glGetError();
    v[9] = glIsEnabled(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    v[10] = strstr((const char *)glGetString(GL_EXTENSIONS), "GL_ARB_seamless_cube_map ") != NULL;
    v[11] = glGetError();
    sgl_text(out, "queries", "%d %d %d %d %d %d err %x list %d %d begin %x %d ext %d err %x",
             v[0], v[1], bv, v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11]);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
