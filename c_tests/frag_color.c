/* frag_color: a fragment shader (no vertex shader) computing its colour from
 * gl_Color and gl_TexCoord[0..1] with arithmetic and the built-in families
 * that lower bit-exactly (fract/floor/mod/abs, min/max/clamp/mix/step/
 * smoothstep, sin/cos, exp2/log2, pow), drawn in perspective (w varies, so
 * the varyings are perspective-correct) with the depth test on: an opaque
 * pass, then a blended pass (SRC_ALPHA, ONE_MINUS_SRC_ALPHA, depth writes
 * off), then fixed-function triangles over them in the same frame. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "frag_program.h"

static const char *FS_A =
    "void main() {\n"
    "  vec4 c = gl_Color;\n"
    "  float t = c.r * 6.0 + 0.25;\n"
    "  gl_FragColor = vec4(fract(t), clamp(c.g * 1.7 - 0.2, 0.0, 1.0),\n"
    "                      mix(c.b, 1.0 - c.r, smoothstep(0.2, 0.8, c.g)),\n"
    "                      step(0.3, c.a) * 0.5 + 0.25);\n"
    "}\n";

static const char *FS_B =
    "void main() {\n"
    "  vec4 t = gl_TexCoord[0];\n"
    "  vec4 u = gl_TexCoord[1];\n"
    "  float s = sin(t.x * 3.0) * 0.5 + 0.5;\n"
    "  float k = cos(u.y * 2.0 + 1.0);\n"
    "  float e = exp2(t.y) * 0.125;\n"
    "  float l = log2(abs(u.x) + 1.0);\n"
    "  float p = pow(abs(t.z) + 0.01, 1.5);\n"
    "  gl_FragColor = vec4(max(s, e), abs(k) * gl_Color.g, min(l, 1.0) + floor(p),\n"
    "                      mod(gl_Color.a * 3.0, 1.0));\n"
    "}\n";

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    GLuint a = frag_program(FS_A), b = frag_program(FS_B);

    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frag_perspective();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);

    glUseProgram(a);
    frag_random_tris(12);
    glUseProgram(b);
    frag_random_tris(12);

    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glUseProgram(a);
    frag_random_tris(8);
    glUseProgram(b);
    frag_random_tris(8);

    /* fixed function in the same frame */
    glUseProgram(0);
    glDepthMask(GL_TRUE);
    frag_random_tris(6);

    return frag_end(out, "color", buf, ctx);
}
