/* frag_depth_write: fragment shaders that write gl_FragDepth, drawn with the
 * depth test among fixed-function triangles: a depth pushed back by the colour,
 * a sphere impostor (discard outside the disc, depth from the bulge), and a
 * depth that leaves [0, 1] both ways or is NaN. llvmpipe clamps a written
 * depth with min(z, 1) then max(z, 0), so NaN gives 1 (probed). A polygon
 * offset moves the interpolated depth only, not a written one. Drawn into the
 * window (24-bit depth) and into framebuffer objects with DEPTH_COMPONENT16,
 * 32F, 32 and DEPTH24_STENCIL8 (with a stencil pass whose zfail and zpass
 * operations see the written depth); the depth buffers are read back raw. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "frag_program.h"

static const char *FS_PUSH =
    "void main() {\n"
    "  gl_FragColor = gl_Color;\n"
    "  gl_FragDepth = gl_FragCoord.z * 0.5 + 0.45 * gl_Color.r;\n"
    "}\n";

static const char *FS_IMPOSTOR =
    "void main() {\n"
    "  vec2 p = fract(gl_TexCoord[0].xy) * 2.0 - 1.0;\n"
    "  float r2 = dot(p, p);\n"
    "  if (r2 > 1.0) discard;\n"
    "  float h = sqrt(1.0 - r2);\n"
    "  gl_FragColor = vec4(gl_Color.rgb * (0.3 + 0.7 * h), 1.0);\n"
    "  gl_FragDepth = gl_FragCoord.z - 0.2 * h;\n"
    "}\n";

static const char *FS_WILD =
    "void main() {\n"
    "  float t = gl_TexCoord[1].x;\n"
    "  float z = t * 0.6 + 0.5;\n"
    "  if (t > 1.6) z = (t - t) / (t - t);\n"
    "  gl_FragColor = vec4(fract(t), gl_Color.g, 0.5, 1.0);\n"
    "  gl_FragDepth = z;\n"
    "}\n";

static GLuint progs[3];

static void draw(void)
{
    int i;
    frag_begin_frame(GL_LESS);
    for (i = 0; i < 3; i++) {
        glUseProgram(progs[i]);
        frag_random_tris(8);
        glUseProgram(0);
        frag_random_tris(3);
    }
    /* The offset moves the interpolated depth only: a shader that writes its
     * depth from a varying is not moved. (The offset pass draws nothing that
     * reads the interpolated depth: softgl folds llvmpipe's per-fragment
     * offset into the depth plane's origin, which rounds differently.) */
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(4.0f, 64.0f);
    glUseProgram(progs[2]);
    frag_random_tris(5);
    glDisable(GL_POLYGON_OFFSET_FILL);
    glDepthFunc(GL_GREATER);
    glUseProgram(progs[1]);
    frag_random_tris(5);
    glUseProgram(0);
    glDisable(GL_DEPTH_TEST);
}

static float zf[FW * FH];
static GLuint zu[FW * FH];
static unsigned char rb[FW * FH * 4];

static void fbo_pass(FILE *out, GLenum depth_format, GLenum attachment, const char *name)
{
    char label[64];
    GLuint fbo = frag_fbo(depth_format, attachment);
    if (attachment == GL_DEPTH_STENCIL_ATTACHMENT) {
        glClearStencil(0);
        glClear(GL_STENCIL_BUFFER_BIT);
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, 0, 0xff);
        glStencilOp(GL_KEEP, GL_INCR, GL_INVERT);
    }
    draw();
    glDisable(GL_STENCIL_TEST);
    glReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_BYTE, rb);
    sgl_image(out, name, FW, FH, 4, "RGBA", FW * 4, 1, rb);
    glReadPixels(0, 0, FW, FH, GL_DEPTH_COMPONENT, GL_FLOAT, zf);
    snprintf(label, sizeof label, "%s_depth", name);
    sgl_data(out, label, sizeof zf, zf);
    if (attachment == GL_DEPTH_STENCIL_ATTACHMENT) {
        glReadPixels(0, 0, FW, FH, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, zu);
        snprintf(label, sizeof label, "%s_ds", name);
        sgl_data(out, label, sizeof zu, zu);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    progs[0] = frag_program(FS_PUSH);
    progs[1] = frag_program(FS_IMPOSTOR);
    progs[2] = frag_program(FS_WILD);
    draw();
    frag_output(out, "window", buf);
    fbo_pass(out, GL_DEPTH_COMPONENT16, GL_DEPTH_ATTACHMENT, "z16");
    fbo_pass(out, GL_DEPTH_COMPONENT32F, GL_DEPTH_ATTACHMENT, "z32f");
    fbo_pass(out, GL_DEPTH_COMPONENT32, GL_DEPTH_ATTACHMENT, "z32");
    fbo_pass(out, GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL_ATTACHMENT, "z24s8");
    sgl_text(out, "error", "0x%x", glGetError());
    return frag_end(out, "end", buf, ctx);
}
