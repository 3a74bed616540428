/* vert_immediate_attrib: generic vertex attributes given between glBegin and glEnd
 * (glVertexAttrib* per vertex, as GL 2.x programs pass tangents and weights in
 * immediate mode) read by a vertex shader. Vertices that set no attribute keep the
 * last value; the value set before glBegin applies to the vertices before the first
 * call inside; two glBegin/glEnd batches of triangles back to back (merged into one
 * draw); points and lines; the normalised and integer forms; attribute 0 as the
 * vertex; the value left current after glEnd read by the next batch; a display
 * list of such a batch; a fragment shader or fixed-function fragments. Window and framebuffer object. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "vert_program.h"

static const char *VS =
    "attribute vec3 tangent;\n"
    "attribute float weight;\n"
    "attribute vec4 extra;\n"
    "varying vec3 t;\n"
    "varying vec4 e;\n"
    "void main() {\n"
    "  gl_Position = gl_ModelViewProjectionMatrix * (gl_Vertex + vec4(0.0, 0.0, weight * 0.3, 0.0));\n"
    "  t = tangent * 0.5 + 0.5;\n"
    "  e = extra;\n"
    "  gl_FrontColor = vec4(fract(tangent * 1.7 + weight), 1.0);\n"
    "  gl_PointSize = 3.0;\n"
    "}\n";

static const char *FS =
    "varying vec3 t;\n"
    "varying vec4 e;\n"
    "void main() {\n"
    "  gl_FragColor = vec4(t.x, mix(t.y, e.x, 0.5), e.y * gl_Color.b, 1.0);\n"
    "}\n";

static void random_attribs(void)
{
    glVertexAttrib3f(1, sgl_randf() * 2.0f - 1.0f, sgl_randf() * 2.0f - 1.0f,
                     sgl_randf() * 2.0f - 1.0f);
    glVertexAttrib1f(2, sgl_randf());
}

static void vertex(void)
{
    glVertex3f(sgl_randf() * 2.4f - 1.2f, sgl_randf() * 2.4f - 1.2f, sgl_randf() * 1.6f - 0.8f);
}

static void draw_all(const GLuint *progs, int n)
{
    int p, i;
    (void)n;
    frag_begin_frame(GL_LESS);
    for (p = 0; p < 2; p++) {
        glUseProgram(progs[p]);
        /* a value set before glBegin, then one per vertex from the third vertex on */
        glVertexAttrib4f(3, 0.9f, 0.2f, 0.0f, 1.0f);
        glVertexAttrib3f(1, 0.4f, -0.6f, 0.2f);
        glVertexAttrib1f(2, 0.25f);
        glBegin(GL_TRIANGLES);
        for (i = 0; i < 12; i++) {
            if (i >= 2)
                random_attribs();
            if (i % 5 == 0)
                glVertexAttrib4Nub(3, (GLubyte)(i * 20), 200, (GLubyte)(255 - i * 9), 255);
            vertex();
        }
        glEnd();
        /* a second batch right after (merged), attributes only on some vertices */
        glBegin(GL_TRIANGLES);
        for (i = 0; i < 9; i++) {
            if (i % 2 == 0)
                random_attribs();
            if (i == 4)
                glVertexAttrib4s(3, 1, 0, 2, 1);
            vertex();
        }
        glEnd();
        /* the last value stays current for a batch that sets none */
        glBegin(GL_TRIANGLE_STRIP);
        for (i = 0; i < 6; i++)
            vertex();
        glEnd();
        /* points and lines */
        glBegin(GL_POINTS);
        for (i = 0; i < 10; i++) {
            random_attribs();
            vertex();
        }
        glEnd();
        glBegin(GL_LINE_STRIP);
        for (i = 0; i < 8; i++) {
            random_attribs();
            glVertexAttrib2f(3, sgl_randf(), sgl_randf());
            vertex();
        }
        glEnd();
        /* a display list of such a batch, compiled, then called */
        if (p == 0) {
            glNewList(1, GL_COMPILE);
            glBegin(GL_TRIANGLES);
            for (i = 0; i < 6; i++) {
                random_attribs();
                vertex();
            }
            glEnd();
            glEndList();
        }
        glCallList(1);
        /* attribute 0 is the vertex */
        glBegin(GL_TRIANGLES);
        for (i = 0; i < 6; i++) {
            random_attribs();
            glVertexAttrib3f(0, sgl_randf() * 2.4f - 1.2f, sgl_randf() * 2.4f - 1.2f, 0.1f);
        }
        glEnd();
    }
    glUseProgram(0);
}

static void make(GLuint *progs, FILE *out)
{
    static const char *attribs[] = {"unused0", "tangent", "weight", "extra", NULL};

    progs[0] = vert_program(VS, FS, attribs);
    progs[1] = vert_program(VS, NULL, attribs);
    glEnable(GL_VERTEX_PROGRAM_POINT_SIZE);
    (void)out;
}

int main(int argc, char **argv)
{
    return frag_scene_main(argc, argv, 2, make, draw_all);
}
