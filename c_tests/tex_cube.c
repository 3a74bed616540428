/* tex_cube: GL_TEXTURE_CUBE_MAP (GL 1.3 / ARB_texture_cube_map).  Six 16x16
 * faces with distinct patterns: a sphere with GL_REFLECTION_MAP texgen
 * (NEAREST and LINEAR), one with GL_NORMAL_MAP, quads whose explicit (s,t,r)
 * sweep across face edges and the major-axis ties, a mipmapped cube map
 * (GL_GENERATE_MIPMAP, LINEAR_MIPMAP_LINEAR) on a sphere seen far away, the
 * texture matrix rotating the lookup, CUBE_MAP winning over 3D and 2D, an
 * incomplete cube map (untextured), glCopyTexSubImage2D into a face, proxies,
 * queries and errors. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256
#define N 16

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

static void quad_str(float x0, float y0, float x1, float y1, const float *a, const float *b,
                     const float *c, const float *d)
{
    glBegin(GL_QUADS);
    glTexCoord3fv(a);
    glVertex2f(x0, y0);
    glTexCoord3fv(b);
    glVertex2f(x1, y0);
    glTexCoord3fv(c);
    glVertex2f(x1, y1);
    glTexCoord3fv(d);
    glVertex2f(x0, y1);
    glEnd();
}

static void upload_faces(GLuint t, int skip_face)
{
    int f;
    glBindTexture(GL_TEXTURE_CUBE_MAP, t);
    for (f = 0; f < 6; f++)
        if (f != skip_face)
            glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGBA, N, N, 0, GL_RGBA,
                         GL_UNSIGNED_BYTE, face[f]);
}

int main(int argc, char **argv)
{
    static const unsigned char base[6][3] = {{230, 40, 40},  {40, 200, 60},  {50, 70, 230},
                                             {230, 220, 40}, {200, 50, 210}, {40, 210, 210}};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    GLuint tex[5];
    GLint v[8];
    int f, x, y, i;
    unsigned char small[4 * 4 * 4];

    for (f = 0; f < 6; f++)
        for (y = 0; y < N; y++)
            for (x = 0; x < N; x++) {
                unsigned char *p = face[f] + 4 * (y * N + x);
                int on = ((x / 4 + y / 4) & 1);
                p[0] = on ? base[f][0] : (unsigned char)(x * 15);
                p[1] = on ? base[f][1] : (unsigned char)(y * 15);
                p[2] = on ? base[f][2] : (unsigned char)(f * 40);
                p[3] = 255;
                if (x == 0 && y == 0)
                    p[0] = p[1] = p[2] = 255; /* marks the (s,t) = (0,0) corner */
            }
    glGenTextures(5, tex);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    upload_faces(tex[0], -1);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);

    glClearColor(0.1f, 0.1f, 0.1f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);

    /* explicit STR: each face's centre, across edges and through ties */
    sgl_ortho(W, H);
    for (f = 0; f < 6; f++) {
        float sgn = (f & 1) ? -1.0f : 1.0f;
        float a[3] = {0, 0, 0}, b[3], c[3], d[3];
        int ax = f / 2, u = (ax + 1) % 3, w = (ax + 2) % 3;
        a[ax] = sgn; a[u] = -1.3f; a[w] = -1.2f;
        memcpy(b, a, sizeof a); b[u] = 1.2f;
        memcpy(c, b, sizeof a); c[w] = 1.4f;
        memcpy(d, a, sizeof a); d[w] = 1.4f;
        quad_str(2.0f + 42.0f * f, 2.0f, 41.0f + 42.0f * f, 41.0f, a, b, c, d);
    }
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_REPEAT); /* ignored */
    for (f = 0; f < 3; f++) {
        float a[3] = {-1.0f, -0.9f, -1.1f}, b[3] = {1.0f, -1.0f, 0.8f};
        float c[3] = {1.1f, 1.0f, 1.0f}, d[3] = {-0.9f, 1.0f, -1.0f};
        a[f] *= 0.5f;
        c[(f + 1) % 3] = 1.0f;
        quad_str(2.0f + 42.0f * f, 44.0f, 41.0f + 42.0f * f, 83.0f, a, b, c, d);
    }

    /* spheres with reflection and normal maps */
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
    glViewport(2, 130, 124, 124);
    sphere(0.0f, 0.0f, -4.0f, 1.6f, 24, 16);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glViewport(130, 130, 124, 124);
    glMatrixMode(GL_TEXTURE);
    glRotatef(35.0f, 0.3f, 1.0f, 0.2f);
    glMatrixMode(GL_MODELVIEW);
    sphere(0.0f, 0.0f, -4.0f, 1.6f, 24, 16);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_NORMAL_MAP);
    glViewport(2, 86, 42, 42);
    glTranslatef(0.0f, 0.0f, -4.0f);
    glRotatef(30.0f, 1.0f, 0.5f, 0.0f);
    sphere(0.0f, 0.0f, 0.0f, 1.6f, 16, 12);
    glLoadIdentity();

    /* mipmapped cube map, far away */
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[1]);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_GENERATE_MIPMAP, GL_TRUE);
    upload_faces(tex[1], -1);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glViewport(46, 86, 42, 42);
    sphere(0.0f, 0.0f, -12.0f, 1.6f, 24, 16);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
    glViewport(90, 86, 42, 42);
    sphere(0.0f, 0.0f, -9.0f, 1.6f, 24, 16);
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glDisable(GL_TEXTURE_GEN_R);
    glDisable(GL_DEPTH_TEST);

    /* cube map over 3D and 2D; with an incomplete cube map the 3D texture is used (Mesa
       takes the first complete enabled target) */
    sgl_ortho(W, H);
    glBindTexture(GL_TEXTURE_3D, tex[3]);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA, 1, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, face[0]);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glEnable(GL_TEXTURE_3D);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[0]);
    {
        float a[3] = {0.2f, 1.0f, -0.5f}, b[3] = {0.5f, 1.0f, -0.5f};
        float c[3] = {0.5f, 1.0f, 0.5f}, d[3] = {-0.5f, 1.0f, 0.5f};
        quad_str(130.0f, 44.0f, 160.0f, 83.0f, a, b, c, d);
        glBindTexture(GL_TEXTURE_CUBE_MAP, tex[2]);
        upload_faces(tex[2], 3);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glColor4f(0.3f, 0.8f, 0.5f, 1.0f);
        quad_str(164.0f, 44.0f, 194.0f, 83.0f, a, b, c, d);
        /* complete it with a copy from the framebuffer, then a sub-image */
        glTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0, GL_RGBA, N, N, 0, GL_RGBA,
                     GL_UNSIGNED_BYTE, face[5]);
        glCopyTexSubImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Y, 0, 2, 3, 140, 60, 8, 9);
        for (i = 0; i < (int)sizeof small; i++)
            small[i] = (unsigned char)(i * 17);
        glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 0, 6, 6, 4, 4, GL_RGBA,
                        GL_UNSIGNED_BYTE, small);
        a[1] = b[1] = c[1] = d[1] = -1.0f;
        quad_str(198.0f, 44.0f, 226.0f, 83.0f, a, b, c, d);
        a[1] = b[1] = c[1] = d[1] = 1.0f;
        quad_str(228.0f, 44.0f, 254.0f, 83.0f, a, b, c, d);
    }
    glDisable(GL_TEXTURE_3D);
    glDisable(GL_TEXTURE_2D);
    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);

    /* queries */
    glGetIntegerv(GL_TEXTURE_BINDING_CUBE_MAP, &v[0]);
    glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &v[1]);
    v[2] = glIsEnabled(GL_TEXTURE_CUBE_MAP);
    glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z, 0, GL_TEXTURE_WIDTH, &v[3]);
    glBindTexture(GL_TEXTURE_CUBE_MAP, tex[1]);
    glGetTexLevelParameteriv(GL_TEXTURE_CUBE_MAP_POSITIVE_Y, 3, GL_TEXTURE_HEIGHT, &v[4]);
    glTexImage2D(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_RGBA, 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 NULL);
    glGetTexLevelParameteriv(GL_PROXY_TEXTURE_CUBE_MAP, 0, GL_TEXTURE_WIDTH, &v[5]);
    sgl_text(out, "queries", "%d %d %d %d %d %d err %x", v[0] == (GLint)tex[2], v[1], v[2],
             v[3], v[4], v[5], glGetError());
    {
        unsigned char back[N * N * 4];
        unsigned sum = 0;
        glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_Z, 1, GL_RGBA, GL_UNSIGNED_BYTE, back);
        for (i = 0; i < (N / 2) * (N / 2) * 4; i++)
            sum = sum * 31u + back[i];
        sgl_text(out, "mip_face", "%08x", sum);
    }
    /* errors */
    glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 8, 4, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, face[0]);
    v[0] = glGetError();
    glTexImage2D(GL_TEXTURE_CUBE_MAP, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, face[0]);
    v[1] = glGetError();
    glTexImage2D(GL_TEXTURE_CUBE_MAP_NEGATIVE_Z + 1, 0, GL_RGBA, 4, 4, 0, GL_RGBA,
                 GL_UNSIGNED_BYTE, face[0]);
    v[2] = glGetError();
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    v[3] = glGetError();
    glTexParameteri(GL_TEXTURE_CUBE_MAP_POSITIVE_X, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    v[4] = glGetError();
    glCopyTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X, 0, GL_RGBA, 0, 0, 8, 6, 0);
    v[5] = glGetError();
    sgl_text(out, "errors", "%x %x %x %x %x %x", v[0], v[1], v[2], v[3], v[4], v[5]);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
