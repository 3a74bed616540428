/* frag_loop_return: `return` inside loops whose trip count is not constant
 * (run as loops under lane masks): main returning from a loop with a uniform
 * bound after writing gl_FragColor, a function returning a value from a
 * data-dependent `while` (its lanes return in different iterations of a 2x2
 * quad) with a fallback return after it, a vec3 function returning from a
 * loop nested in another non-constant one, and a void function whose `out`
 * parameter is written before it returns from a loop; the uniform bound
 * changed between draws (0, 5, 13). Window and framebuffer object. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "frag_program.h"

static const char *FS_MAIN =
    "uniform int n;\n"
    "void main() {\n"
    "  vec3 c = gl_Color.rgb * 0.3;\n"
    "  for (int i = 0; i < n; i++) {\n"
    "    c = fract(c * 1.9 + vec3(0.13, 0.07, float(i) * 0.05));\n"
    "    if (c.r > 0.8) {\n"
    "      gl_FragColor = vec4(c.bgr, 1.0);\n"
    "      return;\n"
    "    }\n"
    "  }\n"
    "  gl_FragColor = vec4(c, 0.5);\n"
    "}\n";

static const char *FS_FUNC =
    "float settle(float x) {\n"
    "  int k = 0;\n"
    "  while (k < 40) {\n"
    "    x = x * 0.77 + 0.02;\n"
    "    if (x < 0.4) return x + float(k) * 0.02;\n"
    "    k++;\n"
    "  }\n"
    "  return 0.9;\n"
    "}\n"
    "void main() {\n"
    "  float s = settle(abs(gl_TexCoord[0].s) * 5.0 + gl_Color.g);\n"
    "  float t = settle(gl_Color.r * 3.0);\n"
    "  gl_FragColor = vec4(s, t, gl_Color.b, 1.0);\n"
    "}\n";

static const char *FS_NESTED =
    "uniform int n;\n"
    "vec3 find(vec3 c) {\n"
    "  for (int i = 0; i < n; i++) {\n"
    "    for (int j = 0; j < i + 2; j++) {\n"
    "      c = fract(c + vec3(0.11, 0.23, 0.05) * float(j + 1));\n"
    "      if (c.g > 0.85) return c * 0.5;\n"
    "    }\n"
    "  }\n"
    "  return c;\n"
    "}\n"
    "void main() {\n"
    "  gl_FragColor = vec4(find(gl_Color.rgb), 1.0);\n"
    "}\n";

static const char *FS_OUT =
    "uniform int n;\n"
    "void walk(vec2 p, out vec4 o) {\n"
    "  o = vec4(p, 0.0, 1.0);\n"
    "  for (int i = 0; i < n + 3; i++) {\n"
    "    p = p * 1.3 - vec2(0.1, 0.2);\n"
    "    o.b += 0.07;\n"
    "    if (dot(p, p) > 2.0) return;\n"
    "    o.rg = fract(p);\n"
    "  }\n"
    "}\n"
    "void main() {\n"
    "  vec4 o;\n"
    "  walk(gl_TexCoord[0].st * 2.0 - 1.0 + gl_Color.rg * 0.1, o);\n"
    "  gl_FragColor = o;\n"
    "}\n";

static void draw_all(const GLuint *progs, int n)
{
    static const int counts[3] = {0, 5, 13};
    int i, p;
    (void)n;
    frag_begin_frame(GL_LESS);
    for (p = 0; p < 4; p++) {
        GLint loc;
        glUseProgram(progs[p]);
        loc = glGetUniformLocation(progs[p], "n");
        for (i = 0; i < 3; i++) {
            if (loc >= 0)
                glUniform1i(loc, counts[i]);
            frag_random_tris(2);
        }
    }
    glUseProgram(0);
}

static void make(GLuint *progs, FILE *out)
{
    (void)out;
    progs[0] = frag_program(FS_MAIN);
    progs[1] = frag_program(FS_FUNC);
    progs[2] = frag_program(FS_NESTED);
    progs[3] = frag_program(FS_OUT);
}

int main(int argc, char **argv)
{
    return frag_scene_main(argc, argv, 4, make, draw_all);
}
