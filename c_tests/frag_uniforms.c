/* frag_uniforms: one fragment program drawn many times with its uniforms
 * (a vec4, a float, an int, a bool and a float array) changed between the
 * draws with glUniform*: each draw must use the values current at it. Depth
 * test on, blending on for the second half, colour mask on one draw. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "frag_program.h"

static const char *FS =
    "uniform vec4 tint;\n"
    "uniform float gain;\n"
    "uniform int mode;\n"
    "uniform bool invert;\n"
    "uniform float steps[3];\n"
    "void main() {\n"
    "  vec4 c = gl_Color * tint;\n"
    "  if (mode == 1) c.rgb = c.gbr;\n"
    "  else if (mode == 2) c.rgb = vec3(c.r + steps[0], c.g + steps[1], c.b + steps[2]);\n"
    "  c.rgb = c.rgb * gain;\n"
    "  if (invert) c.rgb = 1.0 - c.rgb;\n"
    "  gl_FragColor = c;\n"
    "}\n";

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    GLuint p = frag_program(FS);
    GLint tint, gain, mode, invert, steps;
    int i;

    glClearColor(0.5f, 0.5f, 0.5f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frag_perspective();
    glEnable(GL_DEPTH_TEST);
    glUseProgram(p);
    tint = glGetUniformLocation(p, "tint");
    gain = glGetUniformLocation(p, "gain");
    mode = glGetUniformLocation(p, "mode");
    invert = glGetUniformLocation(p, "invert");
    steps = glGetUniformLocation(p, "steps");
    SGL_CHECK(tint >= 0 && gain >= 0 && mode >= 0 && invert >= 0 && steps >= 0);
    for (i = 0; i < 16; i++) {
        float st[3] = {0.1f * (float)i - 0.5f, 0.05f * (float)i, -0.03f * (float)i};
        glUniform4f(tint, 0.3f + 0.04f * (float)i, 1.0f - 0.05f * (float)i, 0.7f,
                    0.5f + 0.03f * (float)i);
        glUniform1f(gain, 0.6f + 0.11f * (float)i);
        glUniform1i(mode, i % 3);
        glUniform1i(invert, (i / 3) % 2);
        glUniform1fv(steps, 3, st);
        if (i == 8) {
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        }
        glColorMask(GL_TRUE, i != 11, GL_TRUE, GL_TRUE);
        frag_random_tris(3);
    }
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);

    return frag_end(out, "uniforms", buf, ctx);
}
