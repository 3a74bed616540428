/* vert_builtin_matrices: every built-in matrix uniform, with its inverse and
 * transposes, in a vertex and in a fragment shader. The modelview (a rotation,
 * a translation and a non-uniform scale), the projection (glFrustum) and the
 * texture matrices of units 0 and 1 are set; a grid of cells is drawn, cell
 * (m, col), 4 pixels wide, showing column col of matrix m as colour (0.25 * value + 0.5): the
 * top half computed by a vertex shader (flat shading, gl_FrontColor), the
 * bottom half by fragment shaders (two: a fragment shader has room for 512
 * uniform components), each picking the matrix and column by
 * uniforms. Mesa's values come from _mesa_fetch_state: inverses from
 * _math_matrix_analyse, the normal matrix from the modelview inverse. The
 * normal matrix's columns are its products with unit vectors; the vertex
 * shader shows column 0 only: Mesa 22.3's vertex shader multiplies by a
 * gl_NormalMatrix whose columns 1 and 2 are wrong (column 1's length is 1.85
 * where the inverse transpose of this modelview, R S^-1, has 1/0.8), its
 * fragment shader by the right one, as softgl does in both. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#define FW 304
#define FH 32
#include "vert_program.h"

#define NM 19

/* column c as the normal matrix's factor */
#define UNIT "vec3(float(c == 0), float(c == 1), float(c == 2))"

/* the matrices, each as one expression of the column index c: in two halves,
 * as a fragment shader has room for 512 uniform components and the four
 * gl_TextureMatrix arrays are 128 each */
#define PICK_A(M, N)                                                               \
    "  if (m == 0) v = " M "(gl_ModelViewMatrix[c]);\n"                           \
    "  else if (m == 1) v = " M "(gl_ProjectionMatrix[c]);\n"                     \
    "  else if (m == 2) v = " M "(gl_ModelViewProjectionMatrix[c]);\n"            \
    "  else if (m == 3) v = " M "(gl_TextureMatrix[1][c]);\n"                     \
    "  else if (m == 4) v = " M "(vec4(gl_NormalMatrix * " N ", 1.0));\n"          \
    "  else if (m == 5) v = " M "(gl_ModelViewMatrixTranspose[c]);\n"             \
    "  else if (m == 6) v = " M "(gl_ProjectionMatrixTranspose[c]);\n"            \
    "  else if (m == 7) v = " M "(gl_ModelViewProjectionMatrixTranspose[c]);\n"   \
    "  else if (m == 8) v = " M "(gl_TextureMatrixTranspose[0][c]);\n"            \
    "  else v = " M "(gl_ModelViewMatrixInverse[c]);\n"

#define PICK_B(M)                                                                 \
    "  if (m == 10) v = " M "(gl_ProjectionMatrixInverse[c]);\n"                  \
    "  else if (m == 11) v = " M "(gl_ModelViewProjectionMatrixInverse[c]);\n"    \
    "  else if (m == 12) v = " M "(gl_TextureMatrixInverse[1][c]);\n"             \
    "  else if (m == 13) v = " M "(gl_ModelViewMatrixInverseTranspose[c]);\n"     \
    "  else if (m == 14) v = " M "(gl_ProjectionMatrixInverseTranspose[c]);\n"    \
    "  else if (m == 15) v = " M "(gl_ModelViewProjectionMatrixInverseTranspose[c]);\n" \
    "  else if (m == 16) v = " M "(gl_TextureMatrixInverseTranspose[0][c]);\n"    \
    "  else if (m == 17) v = " M "(gl_TextureMatrixInverse[0][c]);\n"             \
    "  else v = " M "(gl_TextureMatrix[0][c]);\n"

static const char *VS = "uniform int m;\n"
                        "uniform int c;\n"
                        "vec4 enc(vec4 x) { return x * 0.25 + 0.5; }\n"
                        "void main() {\n"
                        "  vec4 v;\n"
                        "  if (m < 10) {\n" PICK_A("enc", "vec3(1.0, 0.0, 0.0)") "  } else {\n" PICK_B("enc") "  }\n"
                        "  gl_FrontColor = v;\n"
                        "  gl_Position = vec4(gl_Vertex.xy, 0.0, 1.0);\n"
                        "}\n";

static const char *FS_A = "uniform int m;\n"
                          "uniform int c;\n"
                          "vec4 enc(vec4 x) { return x * 0.25 + 0.5; }\n"
                          "void main() {\n"
                          "  vec4 v;\n" PICK_A("enc", UNIT) "  gl_FragColor = v;\n"
                          "}\n";

static const char *FS_B = "uniform int m;\n"
                          "uniform int c;\n"
                          "vec4 enc(vec4 x) { return x * 0.25 + 0.5; }\n"
                          "void main() {\n"
                          "  vec4 v;\n" PICK_B("enc") "  gl_FragColor = v;\n"
                          "}\n";

static const char *PASS_VS = "void main() { gl_Position = vec4(gl_Vertex.xy, 0.0, 1.0); }\n";

/* the cells between y0 and y1, matrices 0..9 with program a, the rest with b */
static void cells(GLuint a, GLuint b, float y0, float y1)
{
    int m, c;
    for (m = 0; m < NM; m++)
        for (c = 0; c < 4; c++) {
            GLuint p = m < 10 ? a : b;
            glUseProgram(p);
            float x0 = -1.0f + 2.0f * (float)(m * 4 + c) / (NM * 4);
            float x1 = -1.0f + 2.0f * (float)(m * 4 + c + 1) / (NM * 4);
            glUniform1i(glGetUniformLocation(p, "m"), m);
            glUniform1i(glGetUniformLocation(p, "c"), c);
            glRectf(x0, y0, x1, y1);
        }
    glUseProgram(0);
}

int main(int argc, char **argv)
{
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    FILE *out = sgl_open(argc, argv);
    GLuint vs = vert_program(VS, NULL, NULL);
    GLuint fs_a = vert_program(PASS_VS, FS_A, NULL);
    GLuint fs_b = vert_program(PASS_VS, FS_B, NULL);

    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.6, 0.8, -0.5, 0.7, 1.5, 9.0);
    glMatrixMode(GL_TEXTURE);
    glActiveTexture(GL_TEXTURE0);
    glScalef(1.5f, 0.5f, 1.0f);
    glActiveTexture(GL_TEXTURE1);
    glTranslatef(0.3f, -0.2f, 0.1f);
    glRotatef(30.0f, 0.0f, 0.0f, 1.0f);
    glActiveTexture(GL_TEXTURE0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.2f, -0.3f, -3.0f);
    glRotatef(35.0f, 0.3f, 1.0f, 0.2f);
    glScalef(1.25f, 0.8f, 1.5f);

    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glShadeModel(GL_FLAT);
    cells(vs, vs, 0.05f, 1.0f);
    cells(fs_a, fs_b, -1.0f, -0.05f);
    sgl_text(out, "err", "0x%04x\n", glGetError());
    return frag_end(out, "image", buf, ctx);
}
