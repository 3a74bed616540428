/*
 * shader_lit_tex.c - a GL 2.1 program: per-pixel Blinn-Phong lighting and a texture.
 *
 * A vertex shader passes the eye-space position and normal as varyings and
 * the texture coordinates through gl_TexCoord[0]; a fragment shader normalises
 * them, lights with one point light (diffuse, specular with pow, ambient) and
 * modulates a mipmapped 128x128 RGBA8 texture sampled with texture2D
 * (LINEAR_MIPMAP_LINEAR, REPEAT).  Each frame draws a 40x40 wavy sheet
 * filling the view behind 9 tori, about 12,000 vertices, with depth test.
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include "bench.h"
#include "shapes.h"
#include "mipmaps.h"
#include "programs.h"

#define TS 128

static const char *VS =
    "varying vec3 n;\n"
    "varying vec3 p;\n"
    "void main() {\n"
    "  p = vec3(gl_ModelViewMatrix * gl_Vertex);\n"
    "  n = gl_NormalMatrix * gl_Normal;\n"
    "  gl_TexCoord[0] = gl_MultiTexCoord0;\n"
    "  gl_Position = ftransform();\n"
    "}\n";

static const char *FS =
    "uniform sampler2D tex;\n"
    "uniform vec3 light;\n"
    "varying vec3 n;\n"
    "varying vec3 p;\n"
    "void main() {\n"
    "  vec3 N = normalize(n);\n"
    "  vec3 L = normalize(light - p);\n"
    "  vec3 H = normalize(L + normalize(-p));\n"
    "  float d = max(dot(N, L), 0.0);\n"
    "  float s = pow(max(dot(N, H), 0.0), 32.0);\n"
    "  vec4 t = texture2D(tex, gl_TexCoord[0].st);\n"
    "  gl_FragColor = vec4(t.rgb * (0.15 + 0.85 * d) + vec3(0.6 * s), 1.0);\n"
    "}\n";

static void scene_setup(int w, int h)
{
    static unsigned char level[2][TS * TS * 4];
    unsigned char *src = level[0], *dst = level[1];
    GLuint prog, tex;
    int x, y;
    BENCH_UNUSED(w, h);
    for (y = 0; y < TS; y++)
        for (x = 0; x < TS; x++) {
            unsigned char *px = &src[(y * TS + x) * 4];
            int check = ((x >> 3) ^ (y >> 3)) & 1;
            px[0] = (unsigned char)(check ? 220 : 70 + x);
            px[1] = (unsigned char)(check ? 200 : 60 + y);
            px[2] = (unsigned char)(check ? 150 : 90);
            px[3] = 255;
        }
    glGenTextures(1, &tex);
    glBindTexture(GL_TEXTURE_2D, tex);
    mip_upload_rgba8(src, dst, TS);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    prog = program_use(VS, FS);
    glUniform1i(glGetUniformLocation(prog, "tex"), 0);
    glUniform3f(glGetUniformLocation(prog, "light"), 1.5f, 2.0f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    shape_perspective(0.08, 0.1, 50.0);
    glClearColor(0.1f, 0.1f, 0.15f, 1.0f);
}

static void scene_frame(int w, int h)
{
    int i;
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -4.0f);
    glPushMatrix();
    glTranslatef(0.0f, 0.0f, -1.5f);
    glScalef(3.5f, 3.5f, 1.0f);
    shape_sheet(40, 0.08f, 3.0f);
    glPopMatrix();
    for (i = 0; i < 9; i++) {
        glPushMatrix();
        glTranslatef(-1.2f + 1.2f * (float)(i % 3), -1.2f + 1.2f * (float)(i / 3), 0.0f);
        glRotatef(25.0f * (float)i, 1.0f, 0.4f, 0.2f);
        shape_torus(0.4f, 0.15f, 24, 16);
        glPopMatrix();
    }
}
