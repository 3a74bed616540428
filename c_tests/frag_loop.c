/* frag_loop: loops whose trip count is not a constant, run as loops (not
 * unrolled) under lane masks: a uniform bound changed between draws (0, 5,
 * 13), a data-dependent `while` whose trip count differs within a 2x2 quad, a
 * `for` with `continue` and `break` depending on the fragment, a `do`-`while`,
 * a constant loop nested in a non-constant one, a texture lookup at
 * coordinates the loop moves (implicit LOD from the quad's current values),
 * a `discard` inside a loop and a user function called in the loop. Window
 * and framebuffer object. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "frag_program.h"

static const char *FS_UNIFORM =
    "uniform int n;\n"
    "uniform float step;\n"
    "void main() {\n"
    "  vec3 c = gl_Color.rgb * 0.2;\n"
    "  for (int i = 0; i < n; i++) {\n"
    "    c = fract(c * 1.7 + vec3(step, step * 0.5, float(i) * 0.03));\n"
    "  }\n"
    "  gl_FragColor = vec4(c, 1.0);\n"
    "}\n";

static const char *FS_WHILE =
    "void main() {\n"
    "  float x = abs(gl_TexCoord[0].s) * 6.0 + gl_Color.r;\n"
    "  int k = 0;\n"
    "  while (x > 0.5 && k < 40) {\n"
    "    x = x * 0.71 - 0.05;\n"
    "    k++;\n"
    "  }\n"
    "  gl_FragColor = vec4(x, float(k) / 40.0, gl_Color.b, 1.0);\n"
    "}\n";

static const char *FS_BREAK =
    "void main() {\n"
    "  float acc = 0.0;\n"
    "  int m = int(gl_Color.g * 24.0);\n"
    "  for (int i = 0; i < m; i++) {\n"
    "    if (mod(float(i), 3.0) == 1.0) continue;\n"
    "    acc += gl_Color.r * 0.3 + float(i) * 0.01;\n"
    "    if (acc > 1.5 + gl_TexCoord[0].t) break;\n"
    "  }\n"
    "  gl_FragColor = vec4(fract(acc), acc / 4.0, float(m) / 24.0, 1.0);\n"
    "}\n";

static const char *FS_DO =
    "#version 130\n"
    "float wobble(float v, float k) { return fract(v * k + 0.13); }\n"
    "void main() {\n"
    "  vec2 p = gl_TexCoord[0].st;\n"
    "  int k = 0;\n"
    "  do {\n"
    "    p = vec2(wobble(p.x, 2.3), wobble(p.y + p.x, 1.9));\n"
    "    k++;\n"
    "  } while (p.x < 0.8 && k < int(3.0 + gl_Color.b * 9.0));\n"
    "  float s = 0.0;\n"
    "  for (int j = 0; j < 3; j++) s += p[j % 2] * 0.3;\n"
    "  gl_FragColor = vec4(p, s, 1.0) * gl_Color.a;\n"
    "}\n";

static const char *FS_NESTED =
    "uniform int rows;\n"
    "void main() {\n"
    "  vec4 c = vec4(0.0);\n"
    "  for (int i = 0; i < rows; i++) {\n"
    "    for (int j = 0; j < 3; j++) {\n"
    "      c[j] += gl_Color[j] * float(i + 1) * 0.07;\n"
    "    }\n"
    "    if (c.r > gl_Color.g * 2.0) break;\n"
    "  }\n"
    "  gl_FragColor = vec4(fract(c.rgb), 1.0);\n"
    "}\n";

static const char *FS_TEX =
    "uniform sampler2D tex;\n"
    "uniform int taps;\n"
    "void main() {\n"
    "  vec2 uv = gl_TexCoord[0].st * 0.5;\n"
    "  vec4 sum = vec4(0.0);\n"
    "  for (int i = 0; i < taps; i++) {\n"
    "    sum += texture2D(tex, uv);\n"
    "    uv += vec2(0.07, 0.031) * gl_Color.rg;\n"
    "  }\n"
    "  gl_FragColor = sum / float(taps);\n"
    "}\n";

static const char *FS_DISCARD =
    "void main() {\n"
    "  float h = gl_Color.r;\n"
    "  for (int i = 0; i < int(gl_Color.b * 10.0); i++) {\n"
    "    h = fract(h * 3.1 + 0.2);\n"
    "    if (h < 0.1) discard;\n"
    "  }\n"
    "  gl_FragColor = vec4(h, gl_Color.gb, 1.0);\n"
    "}\n";

static GLuint g_tex;

static void draw_all(const GLuint *progs, int n)
{
    static const int counts[3] = {0, 5, 13};
    int i;
    (void)n;
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frag_perspective();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glUseProgram(progs[0]);
    glUniform1f(glGetUniformLocation(progs[0], "step"), 0.37f);
    for (i = 0; i < 3; i++) {
        glUniform1i(glGetUniformLocation(progs[0], "n"), counts[i]);
        frag_random_tris(2);
    }
    for (i = 1; i < 4; i++) {
        glUseProgram(progs[i]);
        frag_random_tris(3);
    }
    glUseProgram(progs[4]);
    for (i = 0; i < 3; i++) {
        glUniform1i(glGetUniformLocation(progs[4], "rows"), counts[i] + 2);
        frag_random_tris(2);
    }
    glBindTexture(GL_TEXTURE_2D, g_tex);
    glUseProgram(progs[5]);
    frag_set_unit(progs[5], "tex", 0);
    for (i = 1; i < 3; i++) {
        glUniform1i(glGetUniformLocation(progs[5], "taps"), counts[i] - 1);
        frag_random_tris(2);
    }
    glUseProgram(progs[6]);
    frag_random_tris(4);
    glUseProgram(0);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    static unsigned char rb[FW * FH * 4];
    static unsigned char img[64 * 64 * 4];
    GLuint progs[7];

    progs[0] = frag_program(FS_UNIFORM);
    progs[1] = frag_program(FS_WHILE);
    progs[2] = frag_program(FS_BREAK);
    progs[3] = frag_program(FS_DO);
    progs[4] = frag_program(FS_NESTED);
    progs[5] = frag_program(FS_TEX);
    progs[6] = frag_program(FS_DISCARD);
    glGenTextures(1, &g_tex);
    frag_mipmapped_texture(g_tex, img);
    frag_window_and_fbo(out, buf, rb, draw_all, progs, 7);
    return frag_end(out, "end", buf, ctx);
}
