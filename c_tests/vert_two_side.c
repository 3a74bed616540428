/* vert_two_side: GL_VERTEX_PROGRAM_TWO_SIDE. A vertex shader writes front and back
 * colours; back-facing triangles take gl_BackColor (and gl_BackSecondaryColor) when
 * the enable is on and the front ones when it is off. A shader writing only
 * gl_BackColor keeps the front secondary colour on back faces; one writing no back
 * colour is unaffected. With fixed-function fragments (GL_COLOR_SUM on) and with a
 * fragment shader reading gl_Color and gl_SecondaryColor; glFrontFace(GL_CW); unfilled
 * back faces (glPolygonMode) and culling; the enable's queries and
 * glPushAttrib(GL_ENABLE_BIT). Window and framebuffer object. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "vert_program.h"

static const char *VS_BOTH =
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  gl_FrontColor = gl_Color;\n"
    "  gl_FrontSecondaryColor = vec4(0.0, 0.0, 0.3, 1.0);\n"
    "  gl_BackColor = vec4(1.0 - gl_Color.rgb, 1.0);\n"
    "  gl_BackSecondaryColor = vec4(0.25, gl_Color.r * 0.5, 0.0, 1.0);\n"
    "}\n";

static const char *VS_BACK_ONLY =
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  gl_FrontColor = gl_Color * 0.8;\n"
    "  gl_FrontSecondaryColor = vec4(0.2, 0.1, 0.0, 1.0);\n"
    "  gl_BackColor = vec4(gl_Color.gbr, 0.5);\n"
    "}\n";

static const char *VS_FRONT_ONLY =
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  gl_FrontColor = vec4(gl_Color.brg, 1.0);\n"
    "}\n";

static const char *FS =
    "void main() {\n"
    "  gl_FragColor = vec4(gl_Color.rg, gl_SecondaryColor.g + gl_Color.b * 0.5, 1.0);\n"
    "}\n";

static void draw_all(const GLuint *progs, int n)
{
    int p;
    (void)n;
    frag_begin_frame(GL_LESS);
    glEnable(GL_COLOR_SUM);
    for (p = 0; p < 4; p++) {
        glUseProgram(progs[p]);
        glDisable(GL_VERTEX_PROGRAM_TWO_SIDE);
        frag_random_tris(2);
        glEnable(GL_VERTEX_PROGRAM_TWO_SIDE);
        frag_random_tris(3);
    }
    /* clockwise front faces, unfilled back faces, then culled front faces */
    glUseProgram(progs[0]);
    glFrontFace(GL_CW);
    frag_random_tris(2);
    glFrontFace(GL_CCW);
    glPolygonMode(GL_BACK, GL_LINE);
    frag_random_tris(3);
    glPolygonMode(GL_BACK, GL_FILL);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT);
    frag_random_tris(3);
    glDisable(GL_CULL_FACE);
    glDisable(GL_VERTEX_PROGRAM_TWO_SIDE);
    glDisable(GL_COLOR_SUM);
    glUseProgram(0);
}

static void make(GLuint *progs, FILE *out)
{
    GLboolean b[3];
    GLint on = -1;

    progs[0] = vert_program(VS_BOTH, NULL, NULL);
    progs[1] = vert_program(VS_BACK_ONLY, NULL, NULL);
    progs[2] = vert_program(VS_FRONT_ONLY, NULL, NULL);
    progs[3] = vert_program(VS_BOTH, FS, NULL);
    b[0] = glIsEnabled(GL_VERTEX_PROGRAM_TWO_SIDE);
    glPushAttrib(GL_ENABLE_BIT);
    glEnable(GL_VERTEX_PROGRAM_TWO_SIDE);
    b[1] = glIsEnabled(GL_VERTEX_PROGRAM_TWO_SIDE);
    glGetIntegerv(GL_VERTEX_PROGRAM_TWO_SIDE, &on);
    glPopAttrib();
    b[2] = glIsEnabled(GL_VERTEX_PROGRAM_TWO_SIDE);
    sgl_text(out, "enable", "%d %d %d get %d err 0x%x\n", b[0], b[1], b[2], on, glGetError());
    (void)out;
}

int main(int argc, char **argv)
{
    return frag_scene_main(argc, argv, 4, make, draw_all);
}
