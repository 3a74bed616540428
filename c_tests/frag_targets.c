/* frag_targets: fragment shaders drawing into every kind of colour target that
 * the packed RGBA8 store does not cover: GL_RGBA16F, GL_RGBA32F and GL_RGBA16
 * renderbuffers, an sRGB renderbuffer with GL_FRAMEBUFFER_SRGB, the window with
 * a logic op, and OSMesa buffers of OSMESA_RGB_565, OSMESA_BGRA and GL_FLOAT.
 * Not OSMESA_RGB: llvmpipe (22.3) writes 3-byte pixels wrongly when a fragment
 * shader draws (softpipe and softgl agree there).
 *
 * Each target gets an opaque pass whose colours leave [0, 1] (negative and
 * above 1: float buffers keep them, unorm ones clamp), a blended pass
 * (SRC_ALPHA, ONE_MINUS_SRC_ALPHA, depth writes off), a pass with a colour
 * mask, and a pass that discards, all in perspective with the depth test.
 * Float and 16-bit buffers are read back raw (GL_FLOAT, GL_UNSIGNED_SHORT).
 * The blue channel is c.b * 2.5 * c.b, not c.b * c.b * 2.5: NIR reassociates
 * the latter to (c.b * 2.5) * c.b (nir_opt_algebraic's constants moved up a
 * multiplication chain), which softgl does not, and a float buffer shows the
 * one-ulp difference. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "frag_program.h"

static const char *FS_WIDE =
    "void main() {\n"
    "  vec4 c = gl_Color;\n"
    "  vec4 t = gl_TexCoord[0];\n"
    "  gl_FragColor = vec4(c.r * 3.0 - 1.0, c.g + t.x * 0.75, c.b * 2.5 * c.b,\n"
    "                      c.a * 1.5 - 0.25);\n"
    "}\n";

static const char *FS_SOFT =
    "void main() {\n"
    "  vec4 t = gl_TexCoord[1];\n"
    "  float s = sin(t.x * 2.0) * 0.5 + 0.5;\n"
    "  gl_FragColor = vec4(s, gl_Color.g * 0.8, fract(t.y), gl_Color.a);\n"
    "}\n";

static const char *FS_CUT =
    "void main() {\n"
    "  if (fract(gl_TexCoord[0].x * 2.0) < 0.4) discard;\n"
    "  gl_FragColor = gl_Color * vec4(1.2, 0.6, 1.8, 1.0) - vec4(0.1);\n"
    "}\n";

static GLuint progs[3];

static void make_programs(void)
{
    progs[0] = frag_program(FS_WIDE);
    progs[1] = frag_program(FS_SOFT);
    progs[2] = frag_program(FS_CUT);
}

/* The four passes, into whatever is bound. */
static void passes(void)
{
    frag_begin_frame(GL_LESS);
    glUseProgram(progs[0]);
    frag_random_tris(10);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glUseProgram(progs[1]);
    frag_random_tris(6);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glUseProgram(progs[0]);
    frag_random_tris(4);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glUseProgram(progs[2]);
    frag_random_tris(5);
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
}

static float rf[FW * FH * 4];
static unsigned short rs[FW * FH * 4];
static unsigned char rb[FW * FH * 4];

/* Draws the passes into a new FBO with colour `format`, reads it back. */
static void fbo_target(FILE *out, GLenum format, const char *name, int srgb)
{
    char label[64];
    GLuint fbo = frag_fbo_of(format, GL_DEPTH_COMPONENT24, GL_DEPTH_ATTACHMENT);
    if (srgb)
        glEnable(GL_FRAMEBUFFER_SRGB);
    passes();
    glDisable(GL_FRAMEBUFFER_SRGB);
    glReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_BYTE, rb);
    sgl_image(out, name, FW, FH, 4, "RGBA", FW * 4, 1, rb);
    if (format == GL_RGBA16) {
        glReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_SHORT, rs);
        snprintf(label, sizeof label, "%s_u16", name);
        sgl_data(out, label, sizeof rs, rs);
    } else if (format != GL_SRGB8_ALPHA8) {
        glReadPixels(0, 0, FW, FH, GL_RGBA, GL_FLOAT, rf);
        snprintf(label, sizeof label, "%s_f32", name);
        sgl_data(out, label, sizeof rf, rf);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
}

/* Draws the passes into an OSMesa buffer of `format` and `type` (its own
 * context and programs), and outputs the buffer's bytes. */
static void osmesa_target(FILE *out, GLenum format, GLenum type, int bpp, const char *name)
{
    OSMesaContext ctx = OSMesaCreateContextExt(format, 24, 0, 0, NULL);
    size_t bytes = (size_t)FW * FH * bpp;
    void *buf = calloc(1, bytes);
    SGL_CHECK(ctx != NULL && buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, type, FW, FH));
    make_programs();
    passes();
    glFinish();
    sgl_data(out, name, bytes, buf);
    sgl_text(out, "error", "0x%x", glGetError());
    OSMesaDestroyContext(ctx);
    free(buf);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    make_programs();

    fbo_target(out, GL_RGBA16F, "rgba16f", 0);
    fbo_target(out, GL_RGBA32F, "rgba32f", 0);
    fbo_target(out, GL_RGBA16, "rgba16", 0);
    fbo_target(out, GL_SRGB8_ALPHA8, "srgb", 1);

    /* the window with a logic op over the passes */
    passes();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glEnable(GL_COLOR_LOGIC_OP);
    glLogicOp(GL_XOR);
    glUseProgram(progs[1]);
    frag_random_tris(6);
    glLogicOp(GL_OR_REVERSE);
    glUseProgram(progs[2]);
    frag_random_tris(6);
    glDisable(GL_COLOR_LOGIC_OP);
    glUseProgram(0);
    frag_output(out, "logic", buf);
    sgl_text(out, "error", "0x%x", glGetError());
    OSMesaDestroyContext(ctx);
    free(buf);

    osmesa_target(out, OSMESA_RGB_565, GL_UNSIGNED_SHORT_5_6_5, 2, "osmesa_rgb565");
    osmesa_target(out, OSMESA_RGBA, GL_FLOAT, 16, "osmesa_float");
    osmesa_target(out, OSMESA_BGRA, GL_UNSIGNED_BYTE, 4, "osmesa_bgra");
    sgl_close(out);
    return 0;
}
