/* vert_basic: vertex shaders drawn with glBegin/glEnd in perspective with the
 * depth test on: a #version 110 program (ftransform, gl_NormalMatrix, user
 * varyings and gl_TexCoord read by its fragment shader), a #version 120
 * program with explicit matrices (projection times modelview times vertex)
 * and varyings, a vertex-shader-only program feeding fixed-function
 * fragments (gl_FrontColor, with blending), fixed-function triangles in
 * the same frame, and a generic attribute's current value changed between
 * glBegin/glEnd batches (each batch keeps the value it was given with). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "vert_program.h"

static const char *VS_A =
    "varying vec3 n;\n"
    "varying float k;\n"
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  n = gl_NormalMatrix * gl_Normal;\n"
    "  k = dot(gl_Vertex.xy, vec2(0.7, -0.4)) + 0.5;\n"
    "  gl_FrontColor = gl_Color;\n"
    "  gl_TexCoord[0] = gl_MultiTexCoord0 * 0.25 + 0.5;\n"
    "}\n";

static const char *FS_A =
    "varying vec3 n;\n"
    "varying float k;\n"
    "void main() {\n"
    "  vec3 m = n * 0.25 + 0.5;\n"
    "  gl_FragColor = vec4(m, 1.0) * 0.6 + gl_Color * 0.3\n"
    "      + vec4(fract(k * 3.0), gl_TexCoord[0].xy, 0.0) * 0.1;\n"
    "}\n";

static const char *VS_B =
    "#version 120\n"
    "varying vec4 c;\n"
    "varying vec2 uv;\n"
    "void main() {\n"
    "  vec4 e = gl_ModelViewMatrix * gl_Vertex;\n"
    "  gl_Position = gl_ProjectionMatrix * e;\n"
    "  c = vec4(abs(e.xyz) * 0.4, 1.0) * gl_Color.a;\n"
    "  uv = gl_MultiTexCoord1.xy;\n"
    "  gl_FrontColor = gl_SecondaryColor;\n"
    "}\n";

static const char *FS_B =
    "#version 120\n"
    "varying vec4 c;\n"
    "varying vec2 uv;\n"
    "void main() {\n"
    "  gl_FragColor = vec4(c.rg, fract(uv.x + uv.y), 1.0) + gl_Color * 0.25;\n"
    "}\n";

static const char *VS_C =
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  gl_FrontColor = vec4(gl_Color.bgr, 0.6);\n"
    "}\n";

static const char *VS_D =
    "attribute vec4 tint;\n"
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  gl_FrontColor = tint * gl_Color;\n"
    "}\n";

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    GLuint a = vert_program(VS_A, FS_A, NULL);
    GLuint b = vert_program(VS_B, FS_B, NULL);
    GLuint c = vert_program(VS_C, NULL, NULL);
    static const char *d_attribs[] = {"unused", "tint", NULL};
    GLuint d = vert_program(VS_D, NULL, d_attribs);

    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frag_perspective();
    glRotatef(20.0f, 0.3f, 1.0f, 0.1f);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);

    glUseProgram(a);
    vert_random_tris(12);
    glUseProgram(b);
    vert_random_tris(12);

    /* fixed function in the same frame */
    glUseProgram(0);
    vert_random_tris(6);

    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(c);
    vert_random_tris(8);

    /* GL_TRIANGLES batches merge until a call that is not a vertex attribute:
     * each keeps the tint it was given with. */
    glDisable(GL_BLEND);
    glUseProgram(d);
    glVertexAttrib4f(1, 1.0f, 0.25f, 0.5f, 1.0f);
    vert_random_tris(4);
    glVertexAttrib4f(1, 0.25f, 1.0f, 0.75f, 1.0f);
    vert_random_tris(4);
    glVertexAttrib4f(1, 0.5f, 0.5f, 1.0f, 1.0f);
    vert_random_tris(4);

    return frag_end(out, "basic", buf, ctx);
}
