/* frag_discard: fragment shaders with discard, if/else on varying conditions
 * (diverging within 2x2 quads), a loop with a constant trip count, break and
 * continue, and an inlined function, over perspective triangles with the depth
 * test on (a discarded fragment writes no depth: later triangles behind it
 * still draw) and the alpha test on for the last pass, then blending. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "frag_program.h"

static const char *FS_HOLES =
    "void main() {\n"
    "  vec2 p = gl_FragCoord.xy;\n"
    "  if (mod(floor(p.x / 4.0) + floor(p.y / 4.0), 3.0) < 1.0) discard;\n"
    "  if (gl_Color.r > 0.6) discard;\n"
    "  gl_FragColor = gl_Color;\n"
    "}\n";

static const char *FS_LOOP =
    "float shade(float x) { if (x > 0.5) return x * x; return 1.0 - x; }\n"
    "void main() {\n"
    "  vec4 c = gl_Color;\n"
    "  float acc = 0.0;\n"
    "  for (int i = 0; i < 6; i++) {\n"
    "    if (i == 2) continue;\n"
    "    acc += c.r * 0.25;\n"
    "    if (acc > c.g) break;\n"
    "  }\n"
    "  vec3 o;\n"
    "  if (c.b > 0.5) { o = vec3(acc, shade(c.g), 0.2); }\n"
    "  else { o = vec3(shade(c.r), acc * 0.5, 0.9); if (c.a < 0.2) discard; }\n"
    "  gl_FragColor = vec4(o, c.a);\n"
    "}\n";

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    GLuint holes = frag_program(FS_HOLES), loop = frag_program(FS_LOOP);

    glClearColor(0.2f, 0.1f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frag_perspective();
    glEnable(GL_DEPTH_TEST);
    glUseProgram(holes);
    frag_random_tris(10);
    glUseProgram(loop);
    frag_random_tris(10);

    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.4f);
    glUseProgram(holes);
    frag_random_tris(5);
    glDisable(GL_ALPHA_TEST);

    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(loop);
    frag_random_tris(6);

    return frag_end(out, "discard", buf, ctx);
}
