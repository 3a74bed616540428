/* frag_data: fragment shaders that write gl_FragData[0] instead of
 * gl_FragColor (GL 2.0's form for draw buffer 0): written whole, by
 * component, under a varying branch and after a discard, into the window and
 * into a framebuffer object, blended; mixed with gl_FragColor programs. */
#define GL_GLEXT_PROTOTYPES
#define FW 100
#define FH 81
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "frag_program.h"

static const char *FS_WHOLE =
    "void main() {\n"
    "  gl_FragData[0] = gl_Color * vec4(1.0, 0.8, 0.6, 1.0);\n"
    "}\n";

static const char *FS_PARTS =
    "void main() {\n"
    "  gl_FragData[0].rg = fract(gl_TexCoord[0].st * 2.0);\n"
    "  gl_FragData[0].b = gl_Color.b;\n"
    "  gl_FragData[0].a = 0.7;\n"
    "  if (gl_Color.r > 0.5)\n"
    "    gl_FragData[0].r = 1.0 - gl_FragData[0].r;\n"
    "}\n";

static const char *FS_DISCARD =
    "#version 120\n"
    "void main() {\n"
    "  if (gl_Color.g > 0.7) discard;\n"
    "  gl_FragData[0] = vec4(gl_Color.gbr, 0.5);\n"
    "}\n";

static const char *FS_COLOR =
    "void main() {\n"
    "  gl_FragColor = gl_Color.bgra;\n"
    "}\n";

/* Every program over seeded random triangles. */
static void draw_all(const GLuint *progs, int n)
{
    frag_each_program(progs, n, 6);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glUseProgram(progs[1]);
    frag_random_tris(4);
    glDisable(GL_BLEND);
    glUseProgram(0);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    static unsigned char rb[FW * FH * 4];
    GLuint progs[4];

    progs[0] = frag_program(FS_WHOLE);
    progs[1] = frag_program(FS_PARTS);
    progs[2] = frag_program(FS_DISCARD);
    progs[3] = frag_program(FS_COLOR);
    frag_window_and_fbo(out, buf, rb, draw_all, progs, 4);
    return frag_end(out, "end", buf, ctx);
}
