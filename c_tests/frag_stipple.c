/* frag_stipple: GL_POLYGON_STIPPLE with a fragment shader (llvmpipe's pstipple stage
 * kills the fragments under zero bits, anchored at GL window (0, 0)). Shaders that
 * read gl_Color and gl_FragCoord, take derivatives and sample a texture at computed
 * coordinates (whole 2x2 quads, some of whose pixels the stipple kills), discard
 * fragments, and read gl_FrontFacing; with a vertex shader; with the depth test and
 * polygon offset; two patterns. Window and framebuffer object. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "vert_program.h"

static const char *FS_COLOR =
    "void main() {\n"
    "  gl_FragColor = vec4(gl_Color.rgb, 1.0) * (0.5 + 0.5 * fract(gl_FragCoord.x / 7.0));\n"
    "}\n";

static const char *FS_DERIV =
    "uniform sampler2D tex;\n"
    "void main() {\n"
    "  vec2 uv = gl_TexCoord[0].st * 0.7 + vec2(0.1, 0.2);\n"
    "  vec4 t = texture2D(tex, uv * 1.3);\n"
    "  float w = fwidth(gl_TexCoord[0].s) * 20.0;\n"
    "  if (t.r < 0.1) discard;\n"
    "  gl_FragColor = vec4(t.rg, w, 1.0);\n"
    "}\n";

static const char *FS_FACING =
    "void main() {\n"
    "  gl_FragColor = gl_FrontFacing ? gl_Color : vec4(1.0, 1.0, 0.0, 1.0) - gl_Color;\n"
    "}\n";

static const char *VS =
    "varying vec3 n;\n"
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  n = normalize(gl_Color.rgb - 0.5);\n"
    "  gl_FrontColor = gl_Color;\n"
    "}\n";

static const char *FS_VARYING =
    "varying vec3 n;\n"
    "void main() {\n"
    "  gl_FragColor = vec4(n * 0.5 + 0.5, 1.0);\n"
    "}\n";

static GLuint g_tex;

static void patterns(GLubyte *a, GLubyte *b)
{
    int i;
    for (i = 0; i < 128; i++) {
        a[i] = (GLubyte)(((i / 4) & 1) ? 0xAA : 0x55);
        b[i] = (GLubyte)((i * 37 + 11) & 0xff);
    }
}

static void draw_all(const GLuint *progs, int n)
{
    static GLubyte pa[128], pb[128];
    int p;
    (void)n;
    patterns(pa, pb);
    frag_begin_frame(GL_LESS);
    glEnable(GL_POLYGON_STIPPLE);
    glBindTexture(GL_TEXTURE_2D, g_tex);
    for (p = 0; p < 4; p++) {
        glUseProgram(progs[p]);
        if (p == 1)
            frag_set_unit(progs[1], "tex", 0);
        glPolygonStipple(p & 1 ? pb : pa);
        frag_random_tris(3);
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(1.0f, 2.0f);
        frag_random_tris(2);
        glDisable(GL_POLYGON_OFFSET_FILL);
    }
    glDisable(GL_POLYGON_STIPPLE);
    glUseProgram(progs[0]);
    frag_random_tris(1);
    glUseProgram(0);
}

static void make(GLuint *progs, FILE *out)
{
    static unsigned char img[64 * 64 * 4];

    progs[0] = frag_program(FS_COLOR);
    progs[1] = frag_program(FS_DERIV);
    progs[2] = frag_program(FS_FACING);
    progs[3] = vert_program(VS, FS_VARYING, NULL);
    glGenTextures(1, &g_tex);
    frag_mipmapped_texture(g_tex, img);
    (void)out;
}

int main(int argc, char **argv)
{
    return frag_scene_main(argc, argv, 4, make, draw_all);
}
