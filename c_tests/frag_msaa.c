/* frag_msaa: fragment shaders drawing into 4x multisample framebuffer objects:
 * the shader runs once per pixel at its centre, coverage, stencil and depth
 * are per sample (the depth at each sample point, or the shader's
 * gl_FragDepth for all of them), and each covered sample that passes is
 * written. Programs: colour arithmetic with gl_FragCoord, discard, texture
 * lookups with derivatives, and a written depth; then blending, the stencil
 * test, alpha to coverage, glSampleCoverage, lines and points, and an RGBA16F
 * multisample object. Each object is resolved with glBlitFramebuffer (colour,
 * and depth from the 8-bit one) into a single-sample object and read back. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#define FW 97
#define FH 81
#include "frag_program.h"

static const char *FS_COORD =
    "void main() {\n"
    "  vec2 p = gl_FragCoord.xy * vec2(0.11, 0.07);\n"
    "  gl_FragColor = vec4(fract(p.x), gl_Color.g, fract(p.y + gl_Color.b),\n"
    "                      gl_Color.a);\n"
    "}\n";

static const char *FS_CUT =
    "void main() {\n"
    "  if (fract(gl_TexCoord[0].x * 1.5) < 0.3) discard;\n"
    "  gl_FragColor = gl_Color.bgra;\n"
    "}\n";

static const char *FS_TEX =
    "uniform sampler2D tex;\n"
    "void main() {\n"
    "  vec2 uv = gl_TexCoord[0].xy * 0.7 + vec2(0.1 * sin(gl_TexCoord[1].x));\n"
    "  vec4 t = texture2D(tex, uv);\n"
    "  gl_FragColor = vec4(t.rgb * gl_Color.rgb + vec3(abs(dFdx(uv.x)) * 8.0),\n"
    "                      t.a);\n"
    "}\n";

static const char *FS_DEPTH =
    "void main() {\n"
    "  gl_FragColor = vec4(gl_Color.r, 0.3, 1.0 - gl_Color.r, gl_Color.a);\n"
    "  gl_FragDepth = gl_FragCoord.z * 0.6 + 0.3 * gl_Color.g;\n"
    "}\n";

static GLuint progs[4], tex;
static unsigned char img[64 * 64 * 4];
static unsigned char rb8[FW * FH * 4];
static float rbf[FW * FH * 4];
static GLuint zu[FW * FH];

/* A new 4x object with colour `format` and DEPTH24_STENCIL8. */
static GLuint ms_fbo(GLenum format)
{
    GLuint fbo, rb[2];
    glGenFramebuffers(1, &fbo);
    glGenRenderbuffers(2, rb);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[0]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, format, FW, FH);
    glBindRenderbuffer(GL_RENDERBUFFER, rb[1]);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, 4, GL_DEPTH24_STENCIL8, FW, FH);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, rb[0]);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                              rb[1]);
    SGL_CHECK(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);
    return fbo;
}

static void draw(void)
{
    int i;
    frag_begin_frame(GL_LESS);
    glClearStencil(0);
    glClear(GL_STENCIL_BUFFER_BIT);
    for (i = 0; i < 4; i++) {
        glUseProgram(progs[i]);
        frag_random_tris(6);
    }
    /* fixed function in the same frame */
    glUseProgram(0);
    frag_random_tris(3);
    /* blending */
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glUseProgram(progs[0]);
    frag_random_tris(4);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    /* stencil: count the covered samples, then draw where two or more passed */
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOp(GL_KEEP, GL_INCR, GL_INCR);
    glUseProgram(progs[1]);
    frag_random_tris(4);
    glStencilFunc(GL_LEQUAL, 2, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glDepthFunc(GL_ALWAYS);
    glUseProgram(progs[3]);
    frag_random_tris(3);
    glDisable(GL_STENCIL_TEST);
    glDepthFunc(GL_LESS);
    /* alpha to coverage and sample coverage */
    glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glUseProgram(progs[2]);
    frag_random_tris(3);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    glEnable(GL_SAMPLE_COVERAGE);
    glSampleCoverage(0.5f, GL_FALSE);
    glUseProgram(progs[0]);
    frag_random_tris(3);
    glSampleCoverage(0.25f, GL_TRUE);
    glUseProgram(progs[3]);
    frag_random_tris(3);
    glDisable(GL_SAMPLE_COVERAGE);
    /* lines and points */
    glUseProgram(progs[0]);
    glLineWidth(2.0f);
    glBegin(GL_LINES);
    for (i = 0; i < 8; i++) {
        glColor4f(0.1f * i, 0.8f, 0.3f, 1.0f);
        glVertex3f(-1.0f + 0.2f * i, -0.9f, 0.2f);
        glVertex3f(-0.6f + 0.17f * i, 0.9f, -0.3f);
    }
    glEnd();
    glPointSize(3.0f);
    glBegin(GL_POINTS);
    for (i = 0; i < 12; i++) {
        glColor4f(0.9f, 0.05f * i, 0.5f, 1.0f);
        glVertex3f(-0.9f + 0.15f * i, 0.5f - 0.07f * i, 0.1f);
    }
    glEnd();
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
}

/* Draws into a 4x object of `format`, resolves it into a single-sample one
 * and reads back the colour (and for RGBA8 the depth and stencil). */
static void pass(FILE *out, GLenum format, const char *name)
{
    char label[64];
    GLuint ms = ms_fbo(format);
    GLuint ss = frag_fbo_of(format, GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL_ATTACHMENT);
    glBindFramebuffer(GL_FRAMEBUFFER, ms);
    draw();
    glBindFramebuffer(GL_READ_FRAMEBUFFER, ms);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, ss);
    glBlitFramebuffer(0, 0, FW, FH, 0, 0, FW, FH, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    if (format == GL_RGBA8)
        glBlitFramebuffer(0, 0, FW, FH, 0, 0, FW, FH,
                          GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, ss);
    glReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_BYTE, rb8);
    sgl_image(out, name, FW, FH, 4, "RGBA", FW * 4, 1, rb8);
    if (format == GL_RGBA8) {
        glReadPixels(0, 0, FW, FH, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, zu);
        snprintf(label, sizeof label, "%s_ds", name);
        sgl_data(out, label, sizeof zu, zu);
    } else {
        glReadPixels(0, 0, FW, FH, GL_RGBA, GL_FLOAT, rbf);
        snprintf(label, sizeof label, "%s_f32", name);
        sgl_data(out, label, sizeof rbf, rbf);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    sgl_text(out, "error", "0x%x", glGetError());
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    progs[0] = frag_program(FS_COORD);
    progs[1] = frag_program(FS_CUT);
    progs[2] = frag_program(FS_TEX);
    progs[3] = frag_program(FS_DEPTH);
    glGenTextures(1, &tex);
    frag_mipmapped_texture(tex, img);
    frag_set_unit(progs[2], "tex", 0);
    pass(out, GL_RGBA8, "rgba8");
    pass(out, GL_RGBA16F, "rgba16f");
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
