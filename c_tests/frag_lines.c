/* frag_lines: fragment shaders on lines and points. GL_LINES, GL_LINE_STRIP
 * and GL_LINE_LOOP of widths 1, 2.5 and 4 (x- and y-major, stippled), and
 * GL_POINTS of sizes 1, 3, 6 and 9, drawn in perspective with the depth test,
 * through shaders that read gl_Color, gl_TexCoord[], gl_FragCoord and
 * gl_FrontFacing (true for lines and points), sample a mipmapped texture at a
 * varying and at computed coordinates, take derivatives (a line's planes vary
 * along its major axis only), discard, and through a program with a vertex
 * shader; mixed with fixed-function lines and points. The window has an odd
 * height, so that 2x2 quads straddle GL's row pairs. */
#define GL_GLEXT_PROTOTYPES
#define FW 122
#define FH 91
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "vert_program.h"

static const char *FS_COLOR =
    "void main() {\n"
    "  float f = gl_FrontFacing ? 1.0 : 0.0;\n"
    "  gl_FragColor = vec4(gl_Color.rg, fract(gl_FragCoord.x / 16.0), f * 0.5 + 0.25);\n"
    "}\n";

static const char *FS_TEX =
    "uniform sampler2D a;\n"
    "void main() {\n"
    "  vec4 x = texture2D(a, gl_TexCoord[0].st);\n"
    "  vec4 y = texture2D(a, gl_TexCoord[0].ts * 3.0 + vec2(0.2));\n"
    "  gl_FragColor = x * 0.6 + y * 0.4 * gl_Color;\n"
    "}\n";

static const char *FS_DERIV =
    "void main() {\n"
    "  vec2 p = gl_TexCoord[0].st;\n"
    "  if (gl_Color.b > 0.8) discard;\n"
    "  vec2 d = vec2(dFdx(p.x * p.y), dFdy(p.y * p.y));\n"
    "  gl_FragColor = vec4(0.5 + d * 30.0, fwidth(p.x) * 40.0, 1.0);\n"
    "}\n";

static const char *VS_WAVE =
    "varying vec2 uv;\n"
    "void main() {\n"
    "  gl_Position = ftransform();\n"
    "  uv = gl_MultiTexCoord0.st * 2.0;\n"
    "  gl_FrontColor = vec4(gl_Color.bgr, 1.0);\n"
    "}\n";

static const char *FS_WAVE =
    "varying vec2 uv;\n"
    "void main() {\n"
    "  gl_FragColor = gl_Color * (0.5 + 0.5 * sin(uv.x * 5.0 + uv.y * 3.0));\n"
    "}\n";

/* Seeded random lines of `mode` (count vertices) in [-1.2,1.2]^2 x [-1,1]. */
static void random_lines(GLenum mode, int count)
{
    int k, j;
    glBegin(mode);
    for (k = 0; k < count; k++) {
        float c[4], t[4];
        for (j = 0; j < 4; j++) {
            c[j] = sgl_randf();
            t[j] = sgl_randf() * 4.0f - 2.0f;
        }
        glColor4fv(c);
        glMultiTexCoord4fv(GL_TEXTURE0, t);
        glVertex3f(sgl_randf() * 2.4f - 1.2f, sgl_randf() * 2.4f - 1.2f,
                   sgl_randf() * 2.0f - 1.0f);
    }
    glEnd();
}

/* Every kind of line and point, at several widths and sizes. */
static void draw_prims(void)
{
    static const float widths[3] = {1.0f, 2.5f, 4.0f};
    static const float sizes[4] = {1.0f, 3.0f, 6.0f, 9.0f};
    int i;
    for (i = 0; i < 3; i++) {
        glLineWidth(widths[i]);
        random_lines(GL_LINES, 8);
        random_lines(GL_LINE_STRIP, 5);
        random_lines(GL_LINE_LOOP, 4);
    }
    glEnable(GL_LINE_STIPPLE);
    glLineStipple(2, 0xF0C3);
    glLineWidth(2.0f);
    random_lines(GL_LINE_STRIP, 6);
    glDisable(GL_LINE_STIPPLE);
    glLineWidth(1.0f);
    for (i = 0; i < 4; i++) {
        glPointSize(sizes[i]);
        random_lines(GL_POINTS, 12);
    }
    glPointSize(1.0f);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    static unsigned char img[64 * 64 * 4];
    GLuint tex, color, texp, deriv, wave;

    glGenTextures(1, &tex);
    frag_mipmapped_texture(tex, img);

    color = frag_program(FS_COLOR);
    texp = frag_program(FS_TEX);
    frag_set_unit(texp, "a", 0);
    deriv = frag_program(FS_DERIV);
    wave = vert_program(VS_WAVE, FS_WAVE, NULL);

    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    frag_perspective();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);

    glUseProgram(color);
    draw_prims();
    glUseProgram(texp);
    draw_prims();
    frag_output(out, "color_tex", buf);

    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glUseProgram(deriv);
    draw_prims();
    glUseProgram(wave);
    draw_prims();
    /* fixed function between them, textured and not */
    glUseProgram(0);
    draw_prims();
    glEnable(GL_TEXTURE_2D);
    draw_prims();
    glDisable(GL_TEXTURE_2D);
    glUseProgram(texp);
    draw_prims();
    sgl_text(out, "error", "0x%x", glGetError());
    return frag_end(out, "deriv_wave", buf, ctx);
}
