/* frag_stencil: fragment shaders with the stencil test. Shaded triangles write
 * a stencil mask (REPLACE with the depth test), then shaded triangles are
 * drawn where it holds (EQUAL) with INCR/DECR on depth fail and pass; a
 * shader that discards (discarded fragments leave stencil alone); two-sided
 * stencil (glStencilFuncSeparate/glStencilOpSeparate) on triangles of both
 * facings, with a shader that reads gl_FrontFacing and one that does not;
 * stencil without a depth test, a stencil write mask, lines and points; into
 * the window (24-bit depth, 8-bit stencil) and into a framebuffer object with
 * a DEPTH24_STENCIL8 renderbuffer. The colour, depth and stencil buffers are
 * read back. */
#define GL_GLEXT_PROTOTYPES
#define FW 120
#define FH 93
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "frag_program.h"

static const char *FS_PLAIN =
    "void main() {\n"
    "  gl_FragColor = vec4(gl_Color.rgb, 1.0);\n"
    "}\n";

static const char *FS_FACING =
    "void main() {\n"
    "  vec3 c = gl_FrontFacing ? gl_Color.rgb : gl_Color.bgr * 0.5;\n"
    "  gl_FragColor = vec4(c, 1.0);\n"
    "}\n";

static const char *FS_DISCARD =
    "void main() {\n"
    "  if (fract(gl_TexCoord[0].s * 3.0) > 0.6) discard;\n"
    "  gl_FragColor = vec4(gl_TexCoord[0].st * 0.5 + 0.5, gl_Color.b, 1.0);\n"
    "}\n";

/* Every stencil case with the programs. */
static void draw_all(GLuint plain, GLuint facing, GLuint disc)
{
    int i;
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glClearStencil(0x40);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
    frag_perspective();
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_STENCIL_TEST);

    /* a mask: REPLACE where depth passes, INVERT where it fails */
    glUseProgram(plain);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_INVERT, GL_REPLACE);
    frag_random_tris(6);
    /* where the mask holds, with counting on depth fail and pass */
    glUseProgram(facing);
    glStencilFunc(GL_EQUAL, 1, 0x0F);
    glStencilOp(GL_KEEP, GL_DECR_WRAP, GL_INCR);
    frag_random_tris(8);
    /* discarded fragments leave stencil alone */
    glUseProgram(disc);
    glStencilFunc(GL_NOTEQUAL, 3, 0xFF);
    glStencilOp(GL_ZERO, GL_INCR_WRAP, GL_DECR);
    frag_random_tris(8);
    /* two-sided, with and without gl_FrontFacing in the shader */
    glStencilFuncSeparate(GL_FRONT, GL_LEQUAL, 2, 0xFF);
    glStencilFuncSeparate(GL_BACK, GL_GREATER, 0x41, 0x7F);
    glStencilOpSeparate(GL_FRONT, GL_INCR, GL_KEEP, GL_REPLACE);
    glStencilOpSeparate(GL_BACK, GL_DECR, GL_INVERT, GL_INCR_WRAP);
    for (i = 0; i < 2; i++) {
        glUseProgram(i ? plain : facing);
        frag_random_tris(8);
    }
    /* no depth test, a write mask, and lines and points */
    glDisable(GL_DEPTH_TEST);
    glStencilMask(0x3C);
    glStencilFunc(GL_GEQUAL, 0x42, 0xFF);
    glStencilOp(GL_INVERT, GL_KEEP, GL_INCR);
    glUseProgram(facing);
    frag_random_tris(5);
    glLineWidth(3.0f);
    glBegin(GL_LINES);
    for (i = 0; i < 12; i++) {
        glColor3f(sgl_randf(), sgl_randf(), sgl_randf());
        glVertex2f(sgl_randf() * 2.0f - 1.0f, sgl_randf() * 2.0f - 1.0f);
    }
    glEnd();
    glPointSize(5.0f);
    glBegin(GL_POINTS);
    for (i = 0; i < 12; i++)
        glVertex2f(sgl_randf() * 2.0f - 1.0f, sgl_randf() * 2.0f - 1.0f);
    glEnd();
    glStencilMask(0xFF);
    glEnable(GL_DEPTH_TEST);
    /* fixed function with the stencil test after the programs */
    glUseProgram(0);
    glStencilFunc(GL_LESS, 0x40, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    frag_random_tris(4);
    glDisable(GL_STENCIL_TEST);
}

/* The stencil buffer of the bound framebuffer as read back. */
static void stencil_out(FILE *out, const char *name)
{
    static unsigned char st[FW * FH];
    glReadPixels(0, 0, FW, FH, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, st);
    sgl_data(out, name, sizeof st, st);
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, NULL);
    unsigned char *buf = malloc(FW * FH * 4);
    static unsigned char rb[FW * FH * 4];
    GLuint plain, facing, disc;

    SGL_CHECK(ctx != NULL && buf != NULL);
    SGL_CHECK(OSMesaMakeCurrent(ctx, buf, GL_UNSIGNED_BYTE, FW, FH));
    plain = frag_program(FS_PLAIN);
    facing = frag_program(FS_FACING);
    disc = frag_program(FS_DISCARD);

    draw_all(plain, facing, disc);
    frag_output(out, "window", buf);
    stencil_out(out, "window_stencil");

    frag_fbo(GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL_ATTACHMENT);
    draw_all(plain, facing, disc);
    glReadPixels(0, 0, FW, FH, GL_RGBA, GL_UNSIGNED_BYTE, rb);
    sgl_image(out, "fbo", FW, FH, 4, "RGBA", FW * 4, 1, rb);
    stencil_out(out, "fbo_stencil");
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    sgl_text(out, "error", "0x%x", glGetError());
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
