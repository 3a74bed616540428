/* vert_clip_planes: user clip planes (glClipPlane, GL_CLIP_PLANEi) with a vertex
 * shader. The planes are measured against gl_ClipVertex when the shader writes it (the
 * usual eye-space position, and a clip vertex that is not a linear function of the
 * position), and against gl_Position when it does not (Mesa then still uses the
 * eye-space planes). Triangles, unfilled polygons, lines and points; with fixed-function
 * fragments and with a fragment shader; planes given under a rotated modelview; one,
 * two and three planes. Window and framebuffer object. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "vert_program.h"

static const char *VS_EYE =
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  gl_ClipVertex = gl_ModelViewMatrix * gl_Vertex;\n"
    "  gl_FrontColor = gl_Color;\n"
    "  gl_TexCoord[0] = gl_MultiTexCoord0;\n"
    "}\n";

static const char *VS_BENT =
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  vec4 e = gl_ModelViewMatrix * gl_Vertex;\n"
    "  gl_ClipVertex = e + vec4(0.0, 0.3 * sin(e.x * 4.0), 0.0, 0.0);\n"
    "  gl_FrontColor = vec4(gl_Color.gbr, 1.0);\n"
    "  gl_TexCoord[0] = gl_MultiTexCoord0;\n"
    "}\n";

static const char *VS_NO_CLIP_VERTEX =
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  gl_FrontColor = gl_Color * 0.9;\n"
    "  gl_TexCoord[0] = gl_MultiTexCoord0;\n"
    "}\n";

static const char *FS =
    "void main() {\n"
    "  gl_FragColor = vec4(gl_Color.rg, fract(gl_TexCoord[0].s * 2.0), 1.0);\n"
    "}\n";

static void lines_and_points(void)
{
    int i;
    glBegin(GL_LINES);
    for (i = 0; i < 16; i++) {
        glColor3f(sgl_randf(), sgl_randf(), sgl_randf());
        glVertex3f(sgl_randf() * 2.4f - 1.2f, sgl_randf() * 2.4f - 1.2f,
                   sgl_randf() * 1.6f - 0.8f);
    }
    glEnd();
    glPointSize(3.0f);
    glBegin(GL_POINTS);
    for (i = 0; i < 40; i++) {
        glColor3f(sgl_randf(), sgl_randf(), sgl_randf());
        glVertex3f(sgl_randf() * 2.4f - 1.2f, sgl_randf() * 2.4f - 1.2f,
                   sgl_randf() * 1.6f - 0.8f);
    }
    glEnd();
}

static void draw_all(const GLuint *progs, int n)
{
    static const GLdouble p0[4] = {1.0, 0.2, 0.0, 0.3};
    static const GLdouble p1[4] = {-0.3, 1.0, 0.1, 0.4};
    static const GLdouble p2[4] = {0.0, 0.0, -1.0, -1.9};
    int p;
    frag_begin_frame(GL_LESS);
    /* the planes are given under a rotated modelview (stored in eye space) */
    glPushMatrix();
    glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
    glClipPlane(GL_CLIP_PLANE0, p0);
    glClipPlane(GL_CLIP_PLANE2, p1);
    glPopMatrix();
    glClipPlane(GL_CLIP_PLANE5, p2);
    for (p = 0; p < n; p++) {
        glUseProgram(progs[p]);
        glEnable(GL_CLIP_PLANE0);
        frag_random_tris(3);
        glEnable(GL_CLIP_PLANE2);
        frag_random_tris(3);
        glEnable(GL_CLIP_PLANE5);
        lines_and_points();
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        frag_random_tris(2);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        glDisable(GL_CLIP_PLANE0);
        glDisable(GL_CLIP_PLANE2);
        glDisable(GL_CLIP_PLANE5);
    }
    glUseProgram(0);
}

static void make(GLuint *progs, FILE *out)
{
    progs[0] = vert_program(VS_EYE, NULL, NULL);
    progs[1] = vert_program(VS_BENT, NULL, NULL);
    progs[2] = vert_program(VS_NO_CLIP_VERTEX, NULL, NULL);
    progs[3] = vert_program(VS_EYE, FS, NULL);
    progs[4] = vert_program(VS_NO_CLIP_VERTEX, FS, NULL);
    (void)out;
}

int main(int argc, char **argv)
{
    return frag_scene_main(argc, argv, 5, make, draw_all);
}
