/* frag_flat: flat shading with shaders. glShadeModel(GL_FLAT) with a
 * fragment shader reading gl_Color and gl_TexCoord[] (the colour is the
 * provoking vertex's, the texture coordinates still interpolate), and with a
 * program whose vertex shader writes gl_FrontColor and a user varying, on
 * triangles (clipped at the near plane too), quads, lines and points, mixed
 * with smooth and fixed-function draws. Drawn in perspective with the depth
 * test; and a #version 130 program whose vertex shader writes `flat out`
 * values (a colour and a float) beside smooth ones, under both shade models,
 * on triangles clipped at the near plane (the clipper carries the provoking
 * vertex's flat values), quads, lines and points. */
#define GL_GLEXT_PROTOTYPES
#define FW 116
#define FH 97
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "vert_program.h"

static const char *FS_COLOR =
    "void main() {\n"
    "  gl_FragColor = gl_Color * 0.8 + vec4(fract(gl_TexCoord[0].st * 2.0), 0.0, 0.2);\n"
    "}\n";

static const char *VS_FLAT =
    "#version 130\n"
    "out vec2 uv;\n"
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  uv = gl_MultiTexCoord0.st;\n"
    "  gl_FrontColor = gl_Color.bgra;\n"
    "}\n";

static const char *FS_FLAT =
    "#version 130\n"
    "in vec2 uv;\n"
    "void main() {\n"
    "  gl_FragColor = gl_Color * 0.8 + vec4(fract(uv * 3.0), 1.0, 1.0) * 0.2;\n"
    "}\n";

static const char *VS_FLAT_OUT =
    "#version 130\n"
    "flat out vec4 fc;\n"
    "flat out float fk;\n"
    "out vec2 uv;\n"
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  fc = gl_Color;\n"
    "  fk = gl_Vertex.x * 0.5 + 0.5;\n"
    "  uv = gl_MultiTexCoord0.st;\n"
    "  gl_FrontColor = gl_Color.bgra;\n"
    "}\n";

static const char *FS_FLAT_OUT =
    "#version 130\n"
    "flat in vec4 fc;\n"
    "flat in float fk;\n"
    "in vec2 uv;\n"
    "void main() {\n"
    "  gl_FragColor = fc * 0.6 + gl_Color * 0.2 + vec4(fk, fract(uv * 3.0), 1.0) * 0.2;\n"
    "}\n";

/* Lines and points with seeded random colours. */
static void lines_points(void)
{
    int i;
    glLineWidth(2.0f);
    glBegin(GL_LINE_STRIP);
    for (i = 0; i < 8; i++) {
        glColor3f(sgl_randf(), sgl_randf(), sgl_randf());
        glMultiTexCoord2f(GL_TEXTURE0, sgl_randf(), sgl_randf());
        glVertex3f(sgl_randf() * 2.0f - 1.0f, sgl_randf() * 2.0f - 1.0f, 0.0f);
    }
    glEnd();
    glPointSize(4.0f);
    glBegin(GL_POINTS);
    for (i = 0; i < 8; i++) {
        glColor3f(sgl_randf(), sgl_randf(), sgl_randf());
        glVertex3f(sgl_randf() * 2.0f - 1.0f, sgl_randf() * 2.0f - 1.0f, 0.0f);
    }
    glEnd();
    glLineWidth(1.0f);
    glPointSize(1.0f);
}

/* Seeded random quads. */
static void quads(int n)
{
    int i;
    glBegin(GL_QUADS);
    for (i = 0; i < 4 * n; i++) {
        glColor4f(sgl_randf(), sgl_randf(), sgl_randf(), 1.0f);
        glMultiTexCoord2f(GL_TEXTURE0, sgl_randf() * 2.0f, sgl_randf() * 2.0f);
        glVertex3f(sgl_randf() * 2.4f - 1.2f, sgl_randf() * 2.4f - 1.2f,
                   sgl_randf() * 2.0f - 1.0f);
    }
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    GLuint color, flat, flat_out;

    color = frag_program(FS_COLOR);
    flat = vert_program(VS_FLAT, FS_FLAT, NULL);
    flat_out = vert_program(VS_FLAT_OUT, FS_FLAT_OUT, NULL);
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frag_perspective();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);

    glShadeModel(GL_FLAT);
    glUseProgram(color);
    frag_random_tris(8);
    quads(4);
    lines_points();
    frag_output(out, "shade_model", buf);

    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(flat);
    frag_random_tris(8);
    quads(3);
    lines_points();
    glShadeModel(GL_SMOOTH);
    frag_random_tris(6);
    glShadeModel(GL_FLAT);
    glUseProgram(0);
    frag_random_tris(3);
    frag_output(out, "vertex_program", buf);

    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glShadeModel(GL_SMOOTH);
    glUseProgram(flat_out);
    frag_random_tris(8);
    quads(3);
    lines_points();
    glShadeModel(GL_FLAT);
    frag_random_tris(6);
    glUseProgram(0);
    glShadeModel(GL_SMOOTH);
    sgl_text(out, "error", "0x%x", glGetError());
    return frag_end(out, "flat_out", buf, ctx);
}
