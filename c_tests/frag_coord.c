/* frag_coord: fragment shaders (no vertex shader) reading gl_FragCoord: a
 * checkerboard and stripes from its x and y (the window y, bottom row 0, in a
 * buffer stored bottom-up), a colour from its z, and one mixing 1/w (its w)
 * into the colour, over perspective triangles with the depth test on and
 * GL_LEQUAL, then a blended pass with GL_ONE, GL_ONE. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "frag_program.h"

static const char *FS_XY =
    "void main() {\n"
    "  vec2 p = gl_FragCoord.xy;\n"
    "  float check = mod(floor(p.x / 8.0) + floor(p.y / 8.0), 2.0);\n"
    "  float stripe = step(0.5, fract(p.y * 0.0625));\n"
    "  gl_FragColor = vec4(check, stripe, p.x / 128.0, p.y / 128.0);\n"
    "}\n";

static const char *FS_ZW =
    "void main() {\n"
    "  float z = gl_FragCoord.z;\n"
    "  float w = gl_FragCoord.w;\n"
    "  gl_FragColor = vec4(z, fract(z * 16.0), clamp(w, 0.0, 1.0), gl_Color.a);\n"
    "}\n";

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    GLuint xy = frag_program(FS_XY), zw = frag_program(FS_ZW);

    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frag_perspective();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glUseProgram(xy);
    frag_random_tris(10);
    glUseProgram(zw);
    frag_random_tris(10);

    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glUseProgram(xy);
    frag_random_tris(4);

    return frag_end(out, "coord", buf, ctx);
}
