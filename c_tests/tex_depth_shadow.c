/* tex_depth_shadow: depth textures (GL_ARB_depth_texture, GL_ARB_shadow).
 * Shadow mapping: a box over a ground plane is rendered from the light into the
 * depth buffer, copied with glCopyTexImage2D(GL_DEPTH_COMPONENT), and the scene
 * is drawn from the camera with object-linear texgen and the light's matrices
 * on the texture stack, GL_COMPARE_R_TO_TEXTURE with LEQUAL and LINEAR
 * filtering (compare, then filter).  Then a float-uploaded depth ramp shown
 * with each GL_DEPTH_TEXTURE_MODE (no comparison), all eight compare
 * functions (NEAREST and LINEAR) against an r ramp, DEPTH_COMPONENT16/24/32
 * storage, glGetTexImage of depth, queries and errors. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256
#define SM 64

static void box(float x0, float y0, float z0, float x1, float y1, float z1)
{
    glBegin(GL_QUADS);
    glVertex3f(x0, y1, z0); glVertex3f(x0, y1, z1); glVertex3f(x1, y1, z1); glVertex3f(x1, y1, z0);
    glVertex3f(x0, y0, z1); glVertex3f(x1, y0, z1); glVertex3f(x1, y1, z1); glVertex3f(x0, y1, z1);
    glVertex3f(x0, y0, z0); glVertex3f(x0, y1, z0); glVertex3f(x1, y1, z0); glVertex3f(x1, y0, z0);
    glVertex3f(x0, y0, z0); glVertex3f(x0, y0, z1); glVertex3f(x0, y1, z1); glVertex3f(x0, y1, z0);
    glVertex3f(x1, y0, z0); glVertex3f(x1, y1, z0); glVertex3f(x1, y1, z1); glVertex3f(x1, y0, z1);
    glEnd();
}

/* colours whose 255-multiples are far from .5, so that interpolation ulps do not flip
 * the rounding */
static void scene(void)
{
    glColor4f(0.92f, 0.86f, 0.62f, 1.0f);
    glBegin(GL_QUADS);
    glVertex3f(-1.6f, 0.0f, 1.6f);
    glVertex3f(1.6f, 0.0f, 1.6f);
    glVertex3f(1.6f, 0.0f, -1.6f);
    glVertex3f(-1.6f, 0.0f, -1.6f);
    glEnd();
    glColor4f(0.52f, 0.81f, 1.0f, 1.0f);
    box(-0.45f, 0.5f, -0.35f, 0.35f, 0.9f, 0.4f);
    glColor4f(1.0f, 0.52f, 0.42f, 1.0f);
    glBegin(GL_TRIANGLES);
    glVertex3f(0.6f, 0.2f, 0.9f);
    glVertex3f(1.3f, 0.35f, 0.7f);
    glVertex3f(0.9f, 1.1f, 0.2f);
    glEnd();
}

/* the light's view: orthographic, looking down at an angle */
static void light_view(void)
{
    glOrtho(-2.0, 2.0, -2.0, 2.0, 1.0, 8.0);
    glTranslatef(0.0f, 0.0f, -4.0f);
    glRotatef(55.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(-25.0f, 0.0f, 1.0f, 0.0f);
}

static void quad_str(float x0, float y0, float x1, float y1, float r0, float r1)
{
    glBegin(GL_QUADS);
    glTexCoord3f(0.0f, 0.0f, r0);
    glVertex2f(x0, y0);
    glTexCoord3f(1.0f, 0.0f, r1);
    glVertex2f(x1, y0);
    glTexCoord3f(1.0f, 1.0f, r1);
    glVertex2f(x1, y1);
    glTexCoord3f(0.0f, 1.0f, r0);
    glVertex2f(x0, y1);
    glEnd();
}

int main(int argc, char **argv)
{
    static const GLfloat sp[4] = {1, 0, 0, 0}, tp[4] = {0, 1, 0, 0};
    static const GLfloat rp[4] = {0, 0, 1, 0}, qp[4] = {0, 0, 0, 1};
    static const GLenum funcs[8] = {GL_NEVER, GL_LESS, GL_EQUAL, GL_LEQUAL,
                                    GL_GREATER, GL_NOTEQUAL, GL_GEQUAL, GL_ALWAYS};
    static const GLenum modes[4] = {GL_LUMINANCE, GL_INTENSITY, GL_ALPHA, GL_RED};
    static const GLenum sized[4] = {GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT16,
                                    GL_DEPTH_COMPONENT24, GL_DEPTH_COMPONENT32};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    GLuint tex[3];
    float ramp[16 * 16], fback[16 * 16];
    GLuint uback[SM * SM];
    GLint v[8];
    int i, x, y;

    for (y = 0; y < 16; y++)
        for (x = 0; x < 16; x++)
            ramp[y * 16 + x] = (x + 16 * y) / 255.0f + ((x ^ y) & 1 ? 0.003f : 0.0f);
    glGenTextures(3, tex);

    /* 1: the light pass into the depth buffer, with polygon offset against acne */
    glEnable(GL_DEPTH_TEST);
    glClearColor(0.1f, 0.1f, 0.1f, 0.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glViewport(0, 0, SM, SM);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    light_view();
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 3.0f);
    scene();
    glDisable(GL_POLYGON_OFFSET_FILL);
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glCopyTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 0, 0, SM, SM, 0);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);

    /* 2: the camera pass with the shadow map */
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glViewport(0, 96, 160, 160);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glTranslatef(0.5f, 0.5f, 0.5f);
    glScalef(0.5f, 0.5f, 0.5f);
    light_view();
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.5, 0.5, -0.5, 0.5, 1.0, 20.0);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glTranslatef(0.0f, -0.2f, -4.2f);
    glRotatef(30.0f, 1.0f, 0.0f, 0.0f);
    glRotatef(20.0f, 0.0f, 1.0f, 0.0f);
    glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGeni(GL_R, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGeni(GL_Q, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    glTexGenfv(GL_S, GL_OBJECT_PLANE, sp);
    glTexGenfv(GL_T, GL_OBJECT_PLANE, tp);
    glTexGenfv(GL_R, GL_OBJECT_PLANE, rp);
    glTexGenfv(GL_Q, GL_OBJECT_PLANE, qp);
    glEnable(GL_TEXTURE_GEN_S);
    glEnable(GL_TEXTURE_GEN_T);
    glEnable(GL_TEXTURE_GEN_R);
    glEnable(GL_TEXTURE_GEN_Q);
    glEnable(GL_TEXTURE_2D);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
    scene();
    /* the same with NEAREST and GL_INTENSITY (alpha from the comparison too) */
    glViewport(160, 160, 96, 96);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_INTENSITY);
    scene();
    glDisable(GL_TEXTURE_GEN_S);
    glDisable(GL_TEXTURE_GEN_T);
    glDisable(GL_TEXTURE_GEN_R);
    glDisable(GL_TEXTURE_GEN_Q);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glDisable(GL_DEPTH_TEST);

    /* 3: a float depth ramp shown with each depth texture mode (no comparison) */
    sgl_ortho(W, H);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 16, 16, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                 ramp);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glColor4f(0.8f, 1.0f, 0.6f, 0.7f);
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    for (i = 0; i < 4; i++) {
        glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, modes[i]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, (i & 1) ? GL_NEAREST : GL_LINEAR);
        sgl_tex_quad(2.0f + 40.0f * i, 50.0f, 40.0f + 40.0f * i, 92.0f, -0.1f, -0.1f, 1.1f,
                     1.1f);
    }
    glDisable(GL_BLEND);

    /* 4: every compare function against an r ramp, LINEAR then NEAREST */
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_LUMINANCE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_R_TO_TEXTURE);
    glColor4f(1.0f, 1.0f, 1.0f, 1.0f);
    for (i = 0; i < 16; i++) {
        GLint f = (i & 8) ? GL_NEAREST : GL_LINEAR;
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, funcs[i & 7]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, f);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, f);
        quad_str(2.0f + 31.5f * (i & 7), 2.0f + 24.0f * (i >> 3), 32.0f + 31.5f * (i & 7),
                 24.0f + 24.0f * (i >> 3), -0.1f, 1.2f);
    }
    /* equal: r exactly a stored value (a texel of 16/255) */
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_EQUAL);
    quad_str(164.0f, 50.0f, 180.0f, 92.0f, 16.0f / 255.0f, 16.0f / 255.0f);
    glFinish();
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);

    /* storage precision and readback */
    for (i = 0; i < 4; i++) {
        glBindTexture(GL_TEXTURE_2D, tex[2]);
        glTexImage2D(GL_TEXTURE_2D, 0, sized[i], 16, 16, 0, GL_DEPTH_COMPONENT, GL_FLOAT, ramp);
        glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_DEPTH_SIZE, &v[i]);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_FLOAT, fback);
        sgl_data(out, "float_back", sizeof fback, fback);
        glGetTexImage(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, uback);
        sgl_data(out, "uint_back", 16 * 16 * 4, uback);
    }
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_RED_SIZE, &v[4]);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, &v[5]);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, &v[6]);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, &v[7]);
    sgl_text(out, "queries", "%d %d %d %d %d %x %x %x", v[0], v[1], v[2], v[3], v[4], v[5],
             v[6], v[7]);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, &v[0]);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, &v[1]);
    glGetTexParameteriv(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, &v[2]);
    sgl_text(out, "params", "%x %x %x", v[0], v[1], v[2]);

    /* errors */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, ramp);
    v[0] = glGetError();
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_DEPTH_COMPONENT, GL_FLOAT, ramp);
    v[1] = glGetError();
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_LEQUAL);
    v[2] = glGetError();
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_ZERO);
    v[3] = glGetError();
    glTexParameteri(GL_TEXTURE_2D, GL_DEPTH_TEXTURE_MODE, GL_RGBA);
    v[4] = glGetError();
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, uback);
    v[5] = glGetError();
    glTexImage3D(GL_TEXTURE_3D, 0, GL_DEPTH_COMPONENT, 2, 2, 2, 0, GL_DEPTH_COMPONENT, GL_FLOAT,
                 ramp);
    v[6] = glGetError();
    sgl_text(out, "errors", "%x %x %x %x %x %x %x", v[0], v[1], v[2], v[3], v[4], v[5], v[6]);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
