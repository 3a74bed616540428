/* frag_smooth: GL_LINE_SMOOTH and GL_POINT_SMOOTH with a fragment shader. llvmpipe's
 * draw module turns the primitives into quads and rewrites the shader to multiply its
 * alpha by the coverage (and, for points, to kill outside the disc). Lines of widths
 * 1 .. 6 and points of sizes 1 .. 14 with blending, a shader that writes alpha above
 * one and one that discards, the alpha test, a vertex shader, stippled smooth lines and
 * unfilled polygons with smooth edges and vertices. Window and framebuffer object. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "vert_program.h"

static const char *FS_COLOR =
    "void main() {\n"
    "  gl_FragColor = vec4(gl_Color.rgb, 0.9);\n"
    "}\n";

static const char *FS_BRIGHT =
    "void main() {\n"
    "  if (fract(gl_FragCoord.x * 0.37) < 0.1) discard;\n"
    "  gl_FragColor = vec4(gl_Color.bgr, 1.6 - gl_Color.r);\n"
    "}\n";

static const char *VS =
    "varying float k;\n"
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  k = gl_Vertex.x * 0.5 + 0.5;\n"
    "  gl_FrontColor = gl_Color;\n"
    "}\n";

static const char *FS_VARYING =
    "varying float k;\n"
    "void main() {\n"
    "  gl_FragColor = vec4(k, gl_Color.g, 1.0 - k, gl_Color.a);\n"
    "}\n";

static float rnd(void)
{
    return sgl_randf() * 2.4f - 1.2f;
}

static void lines_points(void)
{
    int i;
    for (i = 0; i < 6; i++) {
        glLineWidth(1.0f + (float)i);
        glBegin(GL_LINES);
        glColor4f(sgl_randf(), sgl_randf(), sgl_randf(), 1.0f);
        glVertex3f(rnd(), rnd(), rnd() * 0.5f);
        glColor4f(sgl_randf(), sgl_randf(), sgl_randf(), 0.7f);
        glVertex3f(rnd(), rnd(), rnd() * 0.5f);
        glEnd();
    }
    for (i = 0; i < 8; i++) {
        glPointSize(1.0f + 1.8f * (float)i);
        glBegin(GL_POINTS);
        glColor4f(sgl_randf(), sgl_randf(), sgl_randf(), 1.0f);
        glVertex3f(rnd(), rnd(), rnd() * 0.5f);
        glEnd();
    }
}

static void draw_all(const GLuint *progs, int n)
{
    int p;
    (void)n;
    frag_begin_frame(GL_LEQUAL);
    glEnable(GL_LINE_SMOOTH);
    glEnable(GL_POINT_SMOOTH);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (p = 0; p < 3; p++) {
        glUseProgram(progs[p]);
        lines_points();
    }
    /* the alpha test sees the coverage */
    glUseProgram(progs[0]);
    glEnable(GL_ALPHA_TEST);
    glAlphaFunc(GL_GREATER, 0.5f);
    lines_points();
    glDisable(GL_ALPHA_TEST);
    /* stippled smooth lines */
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0x5F3A);
    lines_points();
    glDisable(GL_LINE_STIPPLE);
    /* unfilled polygons: smooth edges, then smooth vertices */
    glUseProgram(progs[2]);
    glLineWidth(2.0f);
    glPointSize(5.0f);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    frag_random_tris(2);
    glPolygonMode(GL_FRONT_AND_BACK, GL_POINT);
    frag_random_tris(2);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_BLEND);
    glDisable(GL_LINE_SMOOTH);
    glDisable(GL_POINT_SMOOTH);
    glUseProgram(0);
}

static void make(GLuint *progs, FILE *out)
{
    progs[0] = frag_program(FS_COLOR);
    progs[1] = frag_program(FS_BRIGHT);
    progs[2] = vert_program(VS, FS_VARYING, NULL);
    (void)out;
}

int main(int argc, char **argv)
{
    return frag_scene_main(argc, argv, 3, make, draw_all);
}
