/* vert_normal_scale: gl_NormalScale, the rescale factor of GL_RESCALE_NORMAL, in a
 * vertex and a fragment shader under modelviews that keep lengths (identity,
 * rotation, translation) and that do not (uniform and non-uniform scales and
 * their products with rotations, a nearly singular scale), each drawn as a quad
 * into an RGBA32F object and read back raw. Mesa's value is
 * 1 / sqrt(m2^2 + m6^2 + m10^2) of the modelview inverse (1 when the matrix
 * keeps lengths, and 1 when that sum is below 1e-12). No glMultMatrix: after
 * a general one, softgl's values for later matrices differed from Mesa's (a
 * rotation not counted as length-preserving, one ulp elsewhere), likely from
 * the matrix flags' analysis history; not yet found. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#define FW 16
#define FH 8
#include "vert_program.h"

static const char *VS =
    "varying float scale;\n"
    "void main() {\n"
    "  gl_Position = gl_ProjectionMatrix * gl_Vertex;\n"
    "  scale = gl_NormalScale;\n"
    "}\n";

static const char *FS_V =
    "varying float scale;\n"
    "void main() { gl_FragColor = vec4(scale, scale * 0.5, 0.0, 1.0); }\n";

static const char *FS_F =
    "void main() { gl_FragColor = vec4(gl_NormalScale, 0.0, 1.0, 1.0); }\n";

/* Sets modelview case `k` (of 8). */
static void modelview(int k)
{
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    switch (k) {
    case 1: glRotatef(37.0f, 0.3f, 1.0f, 0.2f); break;
    case 2: glTranslatef(3.0f, -2.0f, 1.0f); break;
    case 3: glScalef(2.0f, 2.0f, 2.0f); break;
    case 4: glScalef(1.0f, 3.0f, 0.25f); break;
    case 5: glTranslatef(0.5f, 0.0f, -1.0f); glRotatef(-75.0f, 0.0f, 0.0f, 1.0f); glScalef(1.0f, 1.0f, 3.0f); break;
    case 6: glRotatef(20.0f, 1.0f, 0.0f, 0.0f); glScalef(0.5f, 1.5f, 0.7f); break;
    case 7: glScalef(1e7f, 1e7f, 1e7f); break;
    }
}

int main(int argc, char **argv)
{
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = frag_context(&buf);
    static float px[FW * FH * 4];
    GLuint progs[2], fbo;
    int k, p;
    progs[0] = vert_program(VS, FS_V, NULL);
    progs[1] = vert_program(VS, FS_F, NULL);
    fbo = frag_fbo_of(GL_RGBA32F, GL_DEPTH_COMPONENT24, GL_DEPTH_ATTACHMENT);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(0.0, FW, 0.0, FH, -1.0, 1.0);
    for (p = 0; p < 2; p++) {
        glUseProgram(progs[p]);
        for (k = 0; k < 8; k++) {
            modelview(k);
            /* the vertex shader ignores the modelview */
            glRectf((float)(2 * k), (float)(4 * p), (float)(2 * k + 2), (float)(4 * p + 4));
        }
    }
    glUseProgram(0);
    glReadPixels(0, 0, FW, FH, GL_RGBA, GL_FLOAT, px);
    sgl_data(out, "scales", sizeof px, px);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    sgl_text(out, "error", "0x%x", glGetError());
    OSMesaDestroyContext(ctx);
    free(buf);
    sgl_close(out);
    return 0;
}
