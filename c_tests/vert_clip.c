/* vert_clip: triangles crossing the near plane (and the sides of the view)
 * drawn with vertex shaders in perspective: every output is interpolated at
 * the clipped vertices (a user varying and gl_TexCoord read by the fragment
 * shader; gl_FrontColor under fixed-function fragments with flat and smooth
 * shading). */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "vert_program.h"

static const char *VS_A =
    "varying vec4 v;\n"
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  v = vec4(gl_Vertex.xyz * 0.3 + 0.5, 1.0);\n"
    "  gl_TexCoord[1] = gl_Color * 2.0;\n"
    "}\n";

static const char *FS_A =
    "varying vec4 v;\n"
    "void main() {\n"
    "  gl_FragColor = vec4(fract(v.xyz * 2.0), 1.0) * 0.7 + gl_TexCoord[1] * 0.15;\n"
    "}\n";

static const char *VS_B =
    "void main() {\n"
    "  gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex;\n"
    "  gl_FrontColor = gl_Color.gbra;\n"
    "}\n";

static void crossing(int n, float zfar)
{
    int i, k;
    glBegin(GL_TRIANGLES);
    for (i = 0; i < n; i++) {
        for (k = 0; k < 3; k++) {
            glColor4f(sgl_randf(), sgl_randf(), sgl_randf(), 1.0f);
            glVertex3f(sgl_randf() * 4.0f - 2.0f, sgl_randf() * 4.0f - 2.0f,
                       k == 0 ? 2.5f : -sgl_randf() * zfar);
        }
    }
    glEnd();
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    GLuint a = vert_program(VS_A, FS_A, NULL);
    GLuint b = vert_program(VS_B, NULL, NULL);

    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frag_perspective();
    glEnable(GL_DEPTH_TEST);

    glUseProgram(a);
    crossing(6, 6.0f);
    glUseProgram(b);
    crossing(4, 4.0f);
    glShadeModel(GL_FLAT);
    crossing(4, 5.0f);

    return frag_end(out, "clip", buf, ctx);
}
