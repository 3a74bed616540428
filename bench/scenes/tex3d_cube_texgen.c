/*
 * tex3d_cube_texgen.c - 3D and cube-map textures with reflection-map and normal-map texgen.
 *
 * A full-screen backdrop and 8 tilted slices sample a 32x32x32 RGBA 3D
 * texture (GL_LINEAR, REPEAT in r, MODULATE); 16 lit spheres sample a 64x64
 * RGB cube map with GL_REFLECTION_MAP texgen (left half) or GL_NORMAL_MAP
 * texgen (right half) on S, T and R, GL_LINEAR_MIPMAP_LINEAR built with
 * GL_GENERATE_MIPMAP, perspective and depth test.
 */
#include <GL/gl.h>
#include "bench.h"
#include "shapes.h"

static GLuint tex3d, cube;

static void scene_setup(int w, int h)
{
    static unsigned char vol[32 * 32 * 32 * 4];
    static unsigned char face[64 * 64 * 3];
    int x, y, z, f;
    BENCH_UNUSED(w, h);
    for (z = 0; z < 32; z++)
        for (y = 0; y < 32; y++)
            for (x = 0; x < 32; x++) {
                unsigned char *p = vol + ((z * 32 + y) * 32 + x) * 4;
                p[0] = (unsigned char)(x * 8);
                p[1] = (unsigned char)(((x ^ y ^ z) & 8) ? 220 : 60);
                p[2] = (unsigned char)(z * 8);
                p[3] = (unsigned char)(128 + y * 4);
            }
    glGenTextures(1, &tex3d);
    glBindTexture(GL_TEXTURE_3D, tex3d);
    glTexImage3D(GL_TEXTURE_3D, 0, GL_RGBA8, 32, 32, 32, 0, GL_RGBA, GL_UNSIGNED_BYTE, vol);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_WRAP_R, GL_REPEAT);

    glGenTextures(1, &cube);
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_GENERATE_MIPMAP, GL_TRUE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    for (f = 0; f < 6; f++) {
        for (y = 0; y < 64; y++)
            for (x = 0; x < 64; x++) {
                unsigned char *p = face + (y * 64 + x) * 3;
                int check = ((x >> 3) ^ (y >> 3)) & 1;
                p[0] = (unsigned char)(40 * f + (check ? 60 : 0));
                p[1] = (unsigned char)(255 - 30 * f - y);
                p[2] = (unsigned char)(x * 3 + (check ? 40 : 0));
            }
        glTexImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f, 0, GL_RGB8, 64, 64, 0, GL_RGB,
                     GL_UNSIGNED_BYTE, face);
    }
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_REFLECTION_MAP);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
}

static void scene_frame(int w, int h)
{
    int i;
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    shape_perspective(1.0, 2.0, 30.0);

    /* The 3D-textured backdrop and slices. */
    glDisable(GL_LIGHTING);
    glBindTexture(GL_TEXTURE_3D, tex3d);
    glEnable(GL_TEXTURE_3D);
    glColor3f(1.0f, 1.0f, 1.0f);
    glBegin(GL_QUADS);
    glTexCoord3f(0.0f, 0.0f, 0.3f);
    glVertex3f(-20.0f, -20.0f, -20.0f);
    glTexCoord3f(3.0f, 0.0f, 0.7f);
    glVertex3f(20.0f, -20.0f, -20.0f);
    glTexCoord3f(3.0f, 3.0f, 1.3f);
    glVertex3f(20.0f, 20.0f, -20.0f);
    glTexCoord3f(0.0f, 3.0f, 0.9f);
    glVertex3f(-20.0f, 20.0f, -20.0f);
    for (i = 0; i < 8; i++) {
        float z = -6.0f - 0.8f * (float)i, r = 0.1f * (float)i;
        glTexCoord3f(0.0f, 0.0f, r);
        glVertex3f(-3.0f, -3.0f + 0.2f * (float)i, z - 1.0f);
        glTexCoord3f(1.0f, 0.0f, r + 0.5f);
        glVertex3f(3.0f, -3.0f + 0.2f * (float)i, z);
        glTexCoord3f(1.0f, 1.0f, r + 1.0f);
        glVertex3f(3.0f, 1.0f, z + 1.0f);
        glTexCoord3f(0.0f, 1.0f, r + 0.5f);
        glVertex3f(-3.0f, 1.0f, z);
    }
    glEnd();
    glDisable(GL_TEXTURE_3D);

    /* Cube-mapped spheres. */
    glEnable(GL_LIGHTING);
    glBindTexture(GL_TEXTURE_CUBE_MAP, cube);
    glEnable(GL_TEXTURE_CUBE_MAP);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_GEN_R);
    for (i = 0; i < 16; i++) {
        GLint mode = (i % 4) < 2 ? GL_REFLECTION_MAP : GL_NORMAL_MAP;
        glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, mode);
        glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, mode);
        glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, mode);
        glPushMatrix();
        glTranslatef(-2.4f + 1.6f * (float)(i % 4), -2.4f + 1.6f * (float)(i / 4), -6.0f);
        glRotatef(20.0f * (float)i, 0.3f, 1.0f, 0.2f);
        shape_sphere(0.7f, 24, 16);
        glPopMatrix();
    }
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glDisable(GL_TEXTURE_GEN_R);
    glDisable(GL_TEXTURE_CUBE_MAP);
}
