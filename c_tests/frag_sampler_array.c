/* frag_sampler_array: arrays of samplers indexed by constants (GLSL 1.10/1.20):
 * a uniform sampler2D t[3] whose elements name units 0, 1 and 2 (set by
 * glUniform1iv on the whole array and by glUniform1i on one element's
 * location), sampled at varyings and at computed coordinates, a samplerCube
 * array beside it, the units changed between draws, an element naming a unit
 * with no complete texture (0,0,0,1), and glGetUniformiv of the elements;
 * drawn in perspective with the depth test. Then GL 2.0's validation: samplers
 * of different types on one unit make glBegin and glDrawArrays
 * GL_INVALID_OPERATION (nothing drawn) and glValidateProgram fail, an unused
 * element below the last one indexed (c[0]) counts, the array ends there (t[2]
 * has no location in a program reading only t[0]), and a shadow sampler shares
 * a 2D unit. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "vert_program.h"

static const char *FS =
    "uniform sampler2D t[3];\n"
    "uniform samplerCube c[2];\n"
    "void main() {\n"
    "  vec4 a = texture2D(t[0], gl_TexCoord[0].st);\n"
    "  vec4 b = texture2D(t[1], gl_TexCoord[1].st);\n"
    "  vec4 d = texture2D(t[2], gl_TexCoord[0].st * 1.5 + vec2(0.1, 0.2));\n"
    "  vec4 e = textureCube(c[1], gl_TexCoord[0].xyz - vec3(0.5));\n"
    "  gl_FragColor = a * 0.4 + b * 0.3 + d * 0.2 + e * 0.1;\n"
    "}\n";

/* Reads the first element of t, a shadow sampler and c[1]. */
static const char *FS_FIRST =
    "uniform sampler2D t[3];\n"
    "uniform samplerCube c[2];\n"
    "uniform sampler2DShadow d;\n"
    "void main() {\n"
    "  vec4 a = texture2D(t[0], gl_TexCoord[0].st);\n"
    "  vec4 e = textureCube(c[1], gl_TexCoord[0].xyz - vec3(0.5));\n"
    "  gl_FragColor = a * 0.5 + e * 0.25 + shadow2D(d, gl_TexCoord[0].stp) * 0.25;\n"
    "}\n";

static const GLfloat tri[6] = {-0.9f, -0.9f, 0.9f, -0.8f, 0.0f, 0.9f};

/* glValidateProgram's status and the error after it. */
static void validate(FILE *out, GLuint p, const char *label)
{
    GLint st = -7;
    glValidateProgram(p);
    glGetProgramiv(p, GL_VALIDATE_STATUS, &st);
    sgl_text(out, "validate", "%s: %d err 0x%04x\n", label, st, glGetError());
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    static unsigned char img[64 * 64 * 4];
    static const GLint units[3] = {0, 1, 2};
    GLuint tex[4], p, q;
    GLint got[3] = {-7, -7, -7};

    glGenTextures(4, tex);
    glActiveTexture(GL_TEXTURE0);
    frag_mipmapped_texture(tex[0], img);
    glActiveTexture(GL_TEXTURE1);
    frag_pattern_texture(tex[1], img, 16, 1, GL_RGB, GL_NEAREST, GL_LINEAR);
    glActiveTexture(GL_TEXTURE2);
    frag_pattern_texture(tex[2], img, 32, 2, GL_RGBA, GL_LINEAR, GL_LINEAR);
    glActiveTexture(GL_TEXTURE3);
    frag_cube_texture(tex[3], img);
    glActiveTexture(GL_TEXTURE0);

    p = frag_program(FS);
    glUseProgram(p);
    glUniform1iv(glGetUniformLocation(p, "t"), 3, units);
    glUniform1i(glGetUniformLocation(p, "c[0]"), 4);
    glUniform1i(glGetUniformLocation(p, "c[1]"), 3);
    glGetUniformiv(p, glGetUniformLocation(p, "t[1]"), &got[1]);
    glGetUniformiv(p, glGetUniformLocation(p, "t[2]"), &got[2]);
    sgl_text(out, "units", "t[1] %d t[2] %d err 0x%04x\n", got[1], got[2], glGetError());

    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frag_perspective();
    glEnable(GL_DEPTH_TEST);
    frag_random_tris(12);
    /* elements swapped, one naming unit 5 (no texture) */
    glUniform1i(glGetUniformLocation(p, "t[0]"), 1);
    glUniform1i(glGetUniformLocation(p, "t[1]"), 0);
    glUniform1i(glGetUniformLocation(p, "t[2]"), 5);
    frag_random_tris(12);
    sgl_text(out, "err", "draws 0x%04x\n", glGetError());

    /* c[0] (unused, below c[1]) on unit 1, a 2D sampler's */
    glUniform1i(glGetUniformLocation(p, "c[0]"), 1);
    validate(out, p, "c[0] on a 2D unit");
    frag_random_tris(4);
    sgl_text(out, "err", "glBegin 0x%04x\n", glGetError());
    glEnableClientState(GL_VERTEX_ARRAY);
    glVertexPointer(2, GL_FLOAT, 0, tri);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    sgl_text(out, "err", "glDrawArrays 0x%04x\n", glGetError());
    glDisableClientState(GL_VERTEX_ARRAY);
    glUniform1i(glGetUniformLocation(p, "c[0]"), 4);
    validate(out, p, "restored");

    q = frag_program(FS_FIRST);
    glUseProgram(q);
    glUniform1i(glGetUniformLocation(q, "t[0]"), 0);
    glUniform1i(glGetUniformLocation(q, "d"), 0);
    glUniform1i(glGetUniformLocation(q, "c[1]"), 3);
    glUniform1i(glGetUniformLocation(q, "c[0]"), 4);
    glGetError();
    validate(out, q, "shadow on the 2D unit");
    glUniform1i(glGetUniformLocation(q, "t[2]"), 3);
    sgl_text(out, "err", "t[2] location %d err 0x%04x\n", glGetUniformLocation(q, "t[2]"),
             glGetError());
    validate(out, q, "t[2] past the last index");
    glUniform1i(glGetUniformLocation(q, "d"), 3);
    validate(out, q, "shadow on the cube unit");
    frag_random_tris(2);
    sgl_text(out, "err", "glBegin 0x%04x\n", glGetError());
    glUniform1i(glGetUniformLocation(q, "d"), 0);
    frag_random_tris(6);
    glUseProgram(0);
    sgl_text(out, "err", "0x%04x\n", glGetError());
    return frag_end(out, "image", buf, ctx);
}
