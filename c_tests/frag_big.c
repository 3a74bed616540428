/* frag_big: fragment programs over a 512x512 buffer with many large
 * triangles, so that a threaded softgl draws their bands on its pool (each
 * thread compiles its own variants): a shader with uniforms changed between
 * draws, gl_FragCoord stripes, discard and a loop, under the depth test, then
 * blended. The image must not depend on the thread count. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#define FW 512
#define FH 512
#include "frag_program.h"

static const char *FS =
    "uniform vec4 tint;\n"
    "uniform float band;\n"
    "void main() {\n"
    "  vec4 c = gl_Color * tint;\n"
    "  float y = gl_FragCoord.y;\n"
    "  if (fract(y / band) < 0.125) discard;\n"
    "  float acc = 0.0;\n"
    "  for (int i = 0; i < 4; i++) { acc += c[i] * 0.25; }\n"
    "  gl_FragColor = vec4(mix(c.rgb, vec3(acc), step(0.5, fract(gl_FragCoord.x / 32.0))),\n"
    "                      c.a);\n"
    "}\n";

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    GLuint p = frag_program(FS);
    GLint tint, band;
    int i;

    glClearColor(0.3f, 0.3f, 0.3f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frag_perspective();
    glEnable(GL_DEPTH_TEST);
    glUseProgram(p);
    tint = glGetUniformLocation(p, "tint");
    band = glGetUniformLocation(p, "band");
    SGL_CHECK(tint >= 0 && band >= 0);
    for (i = 0; i < 8; i++) {
        glUniform4f(tint, 1.0f - 0.1f * (float)i, 0.4f + 0.07f * (float)i, 0.9f, 0.6f);
        glUniform1f(band, 16.0f + 8.0f * (float)i);
        if (i == 4) {
            glEnable(GL_BLEND);
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        }
        frag_random_tris(200);
    }

    return frag_end(out, "big", buf, ctx);
}
