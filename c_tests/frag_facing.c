/* frag_facing: gl_FrontFacing in a fragment shader: seeded random triangles of
 * both windings drawn with culling off under glFrontFace(GL_CCW), then
 * GL_CW, then into a top-down buffer (OSMESA_Y_UP 0, which turns the window's
 * winding over), each coloured by a branch on gl_FrontFacing and by a select
 * (gl_FrontFacing as a float); a fixed-function two-sided lit pass in the same
 * frame for comparison. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "frag_program.h"

static const char *FS_BRANCH =
    "void main() {\n"
    "  if (gl_FrontFacing)\n"
    "    gl_FragColor = gl_Color;\n"
    "  else\n"
    "    gl_FragColor = vec4(1.0) - gl_Color.bgra;\n"
    "}\n";

static const char *FS_SELECT =
    "void main() {\n"
    "  float f = float(gl_FrontFacing);\n"
    "  gl_FragColor = vec4(f, 1.0 - f, gl_Color.b * 0.5 + 0.25 * f, 1.0);\n"
    "}\n";

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    GLuint branch = frag_program(FS_BRANCH), sel = frag_program(FS_SELECT);
    static const GLfloat diffuse[4] = {0.9f, 0.5f, 0.2f, 1.0f};
    static const GLfloat back[4] = {0.2f, 0.4f, 0.9f, 1.0f};

    glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frag_perspective();
    glEnable(GL_DEPTH_TEST);

    glUseProgram(branch);
    frag_random_tris(10);
    glFrontFace(GL_CW);
    glUseProgram(sel);
    frag_random_tris(10);
    glFrontFace(GL_CCW);

    /* fixed function, two-sided lighting */
    glUseProgram(0);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    glMaterialfv(GL_FRONT, GL_DIFFUSE, diffuse);
    glMaterialfv(GL_BACK, GL_DIFFUSE, back);
    frag_random_tris(6);
    glDisable(GL_LIGHTING);
    frag_output(out, "up", buf);

    /* rows stored top-down */
    OSMesaPixelStore(OSMESA_Y_UP, 0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(branch);
    frag_random_tris(10);
    glFrontFace(GL_CW);
    glUseProgram(sel);
    frag_random_tris(10);
    return frag_end(out, "down", buf, ctx);
}
