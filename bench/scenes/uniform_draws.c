/*
 * uniform_draws.c - a GL 2.1 program drawing many objects, uniforms set per object.
 *
 * The way a tutorial or a visualisation toolkit draws a scene with shaders:
 * one program (a vertex shader that scales and places the mesh from uniforms,
 * a fragment shader that lights it per pixel with a uniform colour), one
 * sphere mesh (24 x 16 quads as 768 triangles) in a GL_ARRAY_BUFFER with
 * 16-bit indices in a GL_ELEMENT_ARRAY_BUFFER, drawn 200 times a frame with
 * glDrawElements after glUniform3f (place and size) and glUniform4f (colour).
 * Depth test, back faces culled.
 */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <math.h>
#include "bench.h"
#include "programs.h"
#include "shapes.h"
#include "sphere_buffers.h"

#define NOBJ 200

static const char *VS =
    "uniform vec4 place;\n"
    "varying vec3 n;\n"
    "varying vec3 p;\n"
    "void main() {\n"
    "  vec4 v = vec4(gl_Vertex.xyz * place.w + place.xyz, 1.0);\n"
    "  p = vec3(gl_ModelViewMatrix * v);\n"
    "  n = gl_NormalMatrix * gl_Normal;\n"
    "  gl_Position = gl_ModelViewProjectionMatrix * v;\n"
    "}\n";

static const char *FS =
    "uniform vec4 color;\n"
    "varying vec3 n;\n"
    "varying vec3 p;\n"
    "void main() {\n"
    "  vec3 N = normalize(n);\n"
    "  vec3 L = normalize(vec3(2.0, 3.0, 4.0) - p);\n"
    "  float d = max(dot(N, L), 0.0);\n"
    "  gl_FragColor = vec4(color.rgb * (0.2 + 0.8 * d), color.a);\n"
    "}\n";

static GLint loc_place, loc_color;

static void scene_setup(int w, int h)
{
    GLuint prog;
    BENCH_UNUSED(w, h);
    sphere_buffers(6);
    prog = program_use(VS, FS);
    loc_place = glGetUniformLocation(prog, "place");
    loc_color = glGetUniformLocation(prog, "color");
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);
    glClearColor(0.12f, 0.1f, 0.14f, 1.0f);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.6, -0.6, 0.6, 1.0, 12.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, 0.0f, -4.5f);
}

static void scene_frame(int w, int h)
{
    int i;
    BENCH_UNUSED(w, h);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    for (i = 0; i < NOBJ; i++) {
        int col = i % 20, row = i / 20;
        glUniform4f(loc_place, -2.6f + 0.27f * (float)col, -2.0f + 0.42f * (float)row,
                    -0.3f * (float)(i % 3), 0.16f + 0.02f * (float)(i % 4));
        glUniform4f(loc_color, 0.3f + 0.03f * (float)col, 0.85f - 0.06f * (float)row,
                    0.4f + 0.04f * (float)((i * 7) % 11), 1.0f);
        glDrawElements(GL_TRIANGLES, SPHERE_NIDX, GL_UNSIGNED_SHORT, (const GLvoid *)0);
    }
}
