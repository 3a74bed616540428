/* frag_polymode: fragment shaders through the polygon pipeline. Front faces
 * drawn as lines and back faces as points (glPolygonMode), with edge flags
 * hiding some edges, wide lines and large points, stippled edges, polygon
 * offset on the outlines over a filled pass (GL_POLYGON_OFFSET_LINE, as
 * wireframe-over-solid programs draw; GL_POLYGON_OFFSET_FILL is left out: on
 * these perspective triangles softgl's folded offset differs from llvmpipe's
 * per-fragment one by a unit in ~270 depth values, with or without shaders),
 * culled faces, and shaders that sample a texture at a varying and at
 * computed coordinates, take derivatives and read gl_FrontFacing (true for
 * the lines and points). The window has an odd height. */
#define GL_GLEXT_PROTOTYPES
#define FW 118
#define FH 95
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "frag_program.h"

static const char *FS_SOLID =
    "uniform sampler2D a;\n"
    "void main() {\n"
    "  vec4 t = texture2D(a, gl_TexCoord[0].st * 1.5 + vec2(0.3));\n"
    "  float f = gl_FrontFacing ? 1.0 : 0.4;\n"
    "  gl_FragColor = vec4(t.rgb * gl_Color.rgb * f, 1.0);\n"
    "}\n";

static const char *FS_WIRE =
    "uniform sampler2D a;\n"
    "void main() {\n"
    "  vec4 t = texture2D(a, gl_TexCoord[0].st);\n"
    "  float d = fwidth(gl_TexCoord[0].s) * 20.0;\n"
    "  gl_FragColor = vec4(t.r, d, gl_FrontFacing ? 0.9 : 0.1, 1.0);\n"
    "}\n";

/* Seeded random quads (two triangles each) with per-vertex edge flags. */
static void quads(int n)
{
    int i, k, j;
    glBegin(GL_QUADS);
    for (i = 0; i < n; i++)
        for (k = 0; k < 4; k++) {
            float c[4], t[4];
            for (j = 0; j < 4; j++) {
                c[j] = sgl_randf();
                t[j] = sgl_randf() * 3.0f - 1.5f;
            }
            glEdgeFlag(sgl_randf() > 0.25f);
            glColor4fv(c);
            glMultiTexCoord4fv(GL_TEXTURE0, t);
            glVertex3f(sgl_randf() * 2.4f - 1.2f, sgl_randf() * 2.4f - 1.2f,
                       sgl_randf() * 2.0f - 1.0f);
        }
    glEnd();
    glEdgeFlag(GL_TRUE);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    static unsigned char img[64 * 64 * 4];
    GLuint tex, solid, wire;

    glGenTextures(1, &tex);
    frag_mipmapped_texture(tex, img);
    solid = frag_program(FS_SOLID);
    frag_set_unit(solid, "a", 0);
    wire = frag_program(FS_WIRE);
    frag_set_unit(wire, "a", 0);

    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frag_perspective();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);

    /* lines in front, points behind */
    glUseProgram(wire);
    glPolygonMode(GL_FRONT, GL_LINE);
    glPolygonMode(GL_BACK, GL_POINT);
    glPointSize(4.0f);
    quads(10);
    glLineWidth(3.0f);
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(1, 0x3F1F);
    quads(6);
    glDisable(GL_LINE_STIPPLE);
    glLineWidth(1.0f);
    glPointSize(1.0f);
    frag_output(out, "modes", buf);

    /* wireframe over solid: filled, then the outlines pulled forward */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glUseProgram(solid);
    sgl_rand_state = 99u;
    quads(8);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEnable(GL_POLYGON_OFFSET_LINE);
    glPolygonOffset(-0.5f, -1.0f);
    glUseProgram(wire);
    sgl_rand_state = 99u;
    quads(8);
    glDisable(GL_POLYGON_OFFSET_LINE);
    /* culling in the pipeline */
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    glPointSize(3.0f);
    quads(6);
    glDisable(GL_CULL_FACE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glUseProgram(0);
    sgl_text(out, "error", "0x%x", glGetError());
    return frag_end(out, "wire_solid", buf, ctx);
}
