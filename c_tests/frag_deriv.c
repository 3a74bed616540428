/* frag_deriv: derivatives and texture lookups at coordinates the fragment
 * shader computes. dFdx, dFdy and fwidth of varyings, of non-linear functions
 * of them and of gl_FragCoord (their signs show y's direction), after a
 * discard and under a varying branch; texture2D, texture2DProj, textureCube,
 * shadow2D and the 1.30 texture() at computed coordinates (scaled, offset,
 * constant, from sin/cos, normalised), on a trilinear mipmapped texture whose
 * level of detail comes from the 2x2 quad's computed values, mixed with a
 * lookup at a varying in the same shader. Drawn into the window (rows stored
 * top-down) of odd height, so that 2x2 quads straddle GL's row pairs, and into
 * a framebuffer object (rows bottom-up) read back with glReadPixels. */
#define GL_GLEXT_PROTOTYPES
#define FW 130
#define FH 97
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "frag_program.h"

static const char *FS_DERIV =
    "void main() {\n"
    "  vec4 v = gl_TexCoord[0];\n"
    "  float a = dFdx(v.s * v.s);\n"
    "  float b = dFdy(sin(v.t * 9.0));\n"
    "  gl_FragColor = vec4(0.5 + a * 20.0, 0.5 + b * 10.0,\n"
    "                      fwidth(v.s * v.t + v.p) * 30.0, 1.0);\n"
    "}\n";

static const char *FS_COORD =
    "void main() {\n"
    "  vec2 d = vec2(dFdx(gl_FragCoord.x), dFdy(gl_FragCoord.y));\n"
    "  vec2 e = vec2(dFdy(gl_FragCoord.x), dFdx(gl_FragCoord.y));\n"
    "  float z = dFdy(gl_FragCoord.z) * 4000.0;\n"
    "  gl_FragColor = vec4(d * 0.25 + 0.5, e.x + e.y + 0.5 + z, 1.0);\n"
    "}\n";

static const char *FS_DISCARD =
    "void main() {\n"
    "  vec2 p = gl_TexCoord[0].st;\n"
    "  if (gl_Color.g > 0.6) discard;\n"
    "  vec2 w = fwidth(p * p);\n"
    "  if (gl_Color.r > 0.5)\n"
    "    w = vec2(dFdx(p.x * p.y), dFdy(exp2(p.y)));\n"
    "  gl_FragColor = vec4(0.5 + w * 8.0, gl_Color.b, 1.0);\n"
    "}\n";

static const char *FS_TEX =
    "uniform sampler2D a;\n"
    "uniform sampler2D b;\n"
    "void main() {\n"
    "  vec2 st = gl_TexCoord[0].st;\n"
    "  vec4 x = texture2D(a, st * 2.5 + vec2(0.1, -0.3));\n"
    "  vec4 y = texture2D(b, vec2(sin(st.x * 3.0), cos(st.y * 2.0)));\n"
    "  vec4 z = texture2DProj(a, vec3(st * 0.5, gl_TexCoord[1].q + 0.5));\n"
    "  vec4 c = texture2D(a, vec2(0.3, 0.7));\n"
    "  vec4 v = texture2D(b, gl_TexCoord[1].st);\n"
    "  gl_FragColor = x * 0.3 + y * 0.2 + z * 0.2 + c * 0.1 + v * 0.2;\n"
    "}\n";

static const char *FS_TEX2 =
    "uniform samplerCube c;\n"
    "uniform sampler2DShadow d;\n"
    "uniform sampler2D a;\n"
    "void main() {\n"
    "  vec3 n = normalize(gl_TexCoord[0].xyz + vec3(0.1, 0.2, 0.3));\n"
    "  vec4 x = textureCube(c, n);\n"
    "  vec4 s = shadow2D(d, vec3(gl_TexCoord[0].st * 0.5 + 0.5, gl_Color.r));\n"
    "  vec4 col;\n"
    "  if (gl_Color.b > 0.5)\n"
    "    col = texture2D(a, gl_TexCoord[0].ts * 3.0);\n"
    "  else\n"
    "    col = x;\n"
    "  gl_FragColor = vec4(col.rgb * 0.7 + s.rgb * 0.3, 1.0);\n"
    "}\n";

static const char *FS_130 =
    "#version 130\n"
    "uniform sampler2D a;\n"
    "out vec4 o;\n"
    "void main() {\n"
    "  vec2 uv = gl_TexCoord[0].st * gl_TexCoord[0].st * 2.0;\n"
    "  vec2 g = fwidth(uv);\n"
    "  o = texture(a, uv) * 0.8 + vec4(g * 4.0, 0.0, 0.2);\n"
    "}\n";

/* Every program over seeded random triangles, in perspective with the depth
 * test. */
static void draw_all(const GLuint *progs, int n)
{
    frag_each_program(progs, n, 6);
    glUseProgram(0);
    frag_random_tris(3);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    static unsigned char img[64 * 64 * 4], rb[FW * FH * 4];
    GLuint tex[4], progs[6];

    glGenTextures(4, tex);
    glActiveTexture(GL_TEXTURE0);
    frag_mipmapped_texture(tex[0], img);
    glActiveTexture(GL_TEXTURE1);
    frag_pattern_texture(tex[1], img, 16, 1, GL_RGB, GL_NEAREST, GL_LINEAR);
    glActiveTexture(GL_TEXTURE2);
    frag_cube_texture(tex[2], img);
    glActiveTexture(GL_TEXTURE3);
    frag_depth_texture(tex[3]);
    glActiveTexture(GL_TEXTURE0);

    progs[0] = frag_program(FS_DERIV);
    progs[1] = frag_program(FS_COORD);
    progs[2] = frag_program(FS_DISCARD);
    progs[3] = frag_program(FS_TEX);
    frag_set_unit(progs[3], "a", 0);
    frag_set_unit(progs[3], "b", 1);
    progs[4] = frag_program(FS_TEX2);
    frag_set_unit(progs[4], "c", 2);
    frag_set_unit(progs[4], "d", 3);
    frag_set_unit(progs[4], "a", 0);
    progs[5] = frag_program(FS_130);
    frag_set_unit(progs[5], "a", 0);

    frag_window_and_fbo(out, buf, rb, draw_all, progs, 6);
    return frag_end(out, "end", buf, ctx);
}
