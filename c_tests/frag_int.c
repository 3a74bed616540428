/* frag_int: GLSL 1.30 integer arithmetic. Signed and unsigned division
 * (negative operands, and divisors that are zero at run time, where llvmpipe
 * gives 0 for int and all ones for uint), `%` (Mesa's umod for both
 * signednesses), `<<`, `>>` (arithmetic for int, logical for uint, counts
 * masked to 5 bits), `&`, `|`, `^`, `~`, unsigned comparisons across 2^31,
 * constant-folded forms beside run-time ones, and a hash whose uints reach
 * 2^32 - 1 converted to and from float (some halfway between two floats).
 * Each result is reduced to a byte of a colour channel. Drawn
 * into the window. */
#define GL_GLEXT_PROTOTYPES
#define FW 130
#define FH 97
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "frag_program.h"

static const char *FS_DIV =
    "#version 130\n"
    "out vec4 o;\n"
    "uniform int k;\n"
    "void main() {\n"
    "  ivec2 p = ivec2(gl_FragCoord.xy);\n"
    "  int a = p.x * 37 - 2400;\n"
    "  int b = p.y / 9 - 5;\n"
    "  int q = a / b;\n"
    "  int r = a % b;\n"
    "  uint ua = uint(a) * 2654435761u;\n"
    "  uint ub = uint(b + k);\n"
    "  uint uq = ua / ub;\n"
    "  uint ur = ua % (ub + 3u);\n"
    "  o = vec4(float(q & 255), float(r & 255), float(uq & 255u), float(ur & 255u)) / 255.0;\n"
    "}\n";

static const char *FS_BITS =
    "#version 130\n"
    "out vec4 o;\n"
    "uniform int k;\n"
    "void main() {\n"
    "  ivec2 p = ivec2(gl_FragCoord.xy);\n"
    "  int a = (p.x - 64) * 40503;\n"
    "  int s = p.y + k;\n"
    "  int l = a << s;\n"
    "  int r = a >> (s & 7);\n"
    "  uint u = uint(a) >> uint(s);\n"
    "  int m = (a ^ (p.y * 977)) | (~a & 0x3c);\n"
    "  bool c1 = uint(a) > 2147483648u;\n"
    "  bool c2 = uint(p.x) * 33554432u <= uint(p.y) * 16777216u;\n"
    "  int f = (7 / 2) + (-7 / 2) * 3 + (-7 % 3) + (1 << 4) + (-64 >> 3) + 9 / 0 + int(9u % 0u);\n"
    "  o = vec4(float((l >> 3) & 255), float(r & 255) / 2.0 + (c1 ? 127.0 : 0.0),\n"
    "           float(u & 255u), float((m + f) & 255) / 2.0 + (c2 ? 127.0 : 0.0)) / 255.0;\n"
    "}\n";

static const char *FS_HASH =
    "#version 130\n"
    "out vec4 o;\n"
    "void main() {\n"
    "  uint h = uint(gl_FragCoord.x) * 747796405u + uint(gl_FragCoord.y) * 2891336453u;\n"
    "  h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;\n"
    "  uint g = uint(gl_FragCoord.x * 3.0e7 + gl_FragCoord.y);\n"
    "  float t = float(uint(gl_FragCoord.x) * 256u + 2147483777u) - 2147483648.0;\n"
    "  o = vec4(float(h) / 4294967295.0, fract(float(h) * 1.0e-7), float(g & 1023u) / 1023.0,\n"
    "           float(g) / 4.0e9 + t / 40000.0);\n"
    "}\n";

#define NPROG 3

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    GLuint progs[NPROG];

    progs[0] = frag_program(FS_DIV);
    glUniform1i(glGetUniformLocation(progs[0], "k"), 1);
    progs[1] = frag_program(FS_BITS);
    glUniform1i(glGetUniformLocation(progs[1], "k"), 3);
    progs[2] = frag_program(FS_HASH);

    frag_each_program(progs, NPROG, 6);
    frag_output(out, "window", buf);
    glUseProgram(progs[0]);
    glUniform1i(glGetUniformLocation(progs[0], "k"), -2);
    glUseProgram(progs[1]);
    glUniform1i(glGetUniformLocation(progs[1], "k"), 29);
    frag_each_program(progs, NPROG, 6);
    frag_output(out, "uniforms", buf);
    sgl_text(out, "error", "0x%x", glGetError());
    return frag_end(out, "end", buf, ctx);
}
