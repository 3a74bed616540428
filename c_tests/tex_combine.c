/* tex_combine: GL_COMBINE texture environments.  A 6x5 grid of quads, each
 * with its own COMBINE_RGB / COMBINE_ALPHA function (REPLACE, MODULATE, ADD,
 * ADD_SIGNED, INTERPOLATE, SUBTRACT, DOT3_RGB, DOT3_RGBA), sources (TEXTURE,
 * CONSTANT, PRIMARY_COLOR, PREVIOUS), operands (SRC_COLOR,
 * ONE_MINUS_SRC_COLOR, SRC_ALPHA, ONE_MINUS_SRC_ALPHA) and RGB_SCALE /
 * ALPHA_SCALE 1, 2, 4.  The cells marked "two" run the combiner on unit 1,
 * after unit 0 has modulated the primary colour by a second texture, so
 * PREVIOUS differs from PRIMARY_COLOR there.  Primary colours are smooth
 * with alpha; blending is off and the full RGBA buffer is dumped. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 256
#define H 256

#define TEX GL_TEXTURE
#define CON GL_CONSTANT
#define PRI GL_PRIMARY_COLOR
#define PRE GL_PREVIOUS
#define SC GL_SRC_COLOR
#define OMC GL_ONE_MINUS_SRC_COLOR
#define SA GL_SRC_ALPHA
#define OMA GL_ONE_MINUS_SRC_ALPHA

struct combine {
    GLenum rgb_func, rgb_src[3], rgb_op[3];
    GLenum a_func, a_src[3], a_op[3];
    float rgb_scale, a_scale;
    int two;
};

static const struct combine cells[30] = {
    {GL_REPLACE, {TEX, PRI, CON}, {SC, SC, SA}, GL_REPLACE, {TEX, PRI, CON}, {SA, SA, SA}, 1, 1, 0},
    {GL_REPLACE, {TEX, PRI, CON}, {OMC, SC, SA}, GL_REPLACE, {PRI, TEX, CON}, {OMA, SA, SA}, 1, 1, 0},
    {GL_REPLACE, {TEX, PRI, CON}, {SA, SC, SA}, GL_REPLACE, {CON, TEX, CON}, {SA, SA, SA}, 1, 1, 0},
    {GL_MODULATE, {TEX, PRI, CON}, {SC, SC, SA}, GL_MODULATE, {TEX, PRI, CON}, {SA, SA, SA}, 1, 1, 0},
    {GL_MODULATE, {TEX, CON, CON}, {SC, SC, SA}, GL_MODULATE, {PRI, CON, CON}, {SA, SA, SA}, 2, 2, 0},
    {GL_MODULATE, {TEX, PRI, CON}, {OMC, SA, SA}, GL_MODULATE, {TEX, PRI, CON}, {OMA, SA, SA}, 4, 4, 0},
    {GL_ADD, {TEX, PRI, CON}, {SC, SC, SA}, GL_ADD, {TEX, PRI, CON}, {SA, SA, SA}, 1, 1, 0},
    {GL_ADD, {TEX, CON, CON}, {SC, OMC, SA}, GL_ADD, {TEX, CON, CON}, {OMA, SA, SA}, 2, 1, 0},
    {GL_ADD_SIGNED, {TEX, PRI, CON}, {SC, SC, SA}, GL_ADD_SIGNED, {TEX, PRI, CON}, {SA, SA, SA}, 1, 1, 0},
    {GL_ADD_SIGNED, {TEX, CON, CON}, {SC, SC, SA}, GL_ADD_SIGNED, {TEX, CON, CON}, {SA, OMA, SA}, 2, 4, 0},
    {GL_INTERPOLATE, {TEX, PRI, CON}, {SC, SC, SA}, GL_INTERPOLATE, {TEX, PRI, CON}, {SA, SA, SA}, 1, 1, 0},
    {GL_INTERPOLATE, {CON, PRI, TEX}, {SC, SC, SC}, GL_INTERPOLATE, {CON, PRI, TEX}, {SA, SA, OMA}, 1, 1, 0},
    {GL_SUBTRACT, {TEX, PRI, CON}, {SC, SC, SA}, GL_SUBTRACT, {PRI, TEX, CON}, {SA, SA, SA}, 1, 1, 0},
    {GL_SUBTRACT, {CON, TEX, CON}, {SC, SC, SA}, GL_SUBTRACT, {CON, TEX, CON}, {SA, OMA, SA}, 2, 2, 0},
    {GL_DOT3_RGB, {TEX, PRI, CON}, {SC, SC, SA}, GL_REPLACE, {PRI, TEX, CON}, {SA, SA, SA}, 1, 1, 0},
    {GL_DOT3_RGB, {TEX, CON, CON}, {SC, SC, SA}, GL_MODULATE, {TEX, PRI, CON}, {SA, SA, SA}, 2, 1, 0},
    {GL_DOT3_RGBA, {TEX, PRI, CON}, {SC, SC, SA}, GL_REPLACE, {CON, TEX, CON}, {SA, SA, SA}, 1, 1, 0},
    {GL_DOT3_RGBA, {TEX, CON, CON}, {OMC, SC, SA}, GL_ADD, {TEX, PRI, CON}, {SA, SA, SA}, 4, 2, 0},
    {GL_REPLACE, {PRE, TEX, CON}, {SC, SC, SA}, GL_REPLACE, {PRE, TEX, CON}, {SA, SA, SA}, 1, 1, 1},
    {GL_MODULATE, {PRE, TEX, CON}, {SC, SC, SA}, GL_MODULATE, {PRE, TEX, CON}, {SA, SA, SA}, 1, 1, 1},
    {GL_ADD, {PRE, CON, CON}, {SC, SC, SA}, GL_ADD, {PRE, CON, CON}, {SA, SA, SA}, 2, 1, 1},
    {GL_INTERPOLATE, {PRE, TEX, PRI}, {SC, SC, SA}, GL_INTERPOLATE, {PRE, TEX, PRI}, {SA, SA, OMA}, 1, 1, 1},
    {GL_SUBTRACT, {TEX, PRE, CON}, {SC, SC, SA}, GL_SUBTRACT, {TEX, PRE, CON}, {SA, SA, SA}, 1, 1, 1},
    {GL_DOT3_RGBA, {PRE, TEX, CON}, {SC, SC, SA}, GL_REPLACE, {PRE, TEX, CON}, {SA, SA, SA}, 1, 1, 1},
    {GL_ADD_SIGNED, {PRE, PRI, CON}, {SC, OMC, SA}, GL_ADD_SIGNED, {PRE, PRI, CON}, {SA, OMA, SA}, 4, 1, 1},
    {GL_MODULATE, {PRE, PRI, CON}, {OMA, SA, SA}, GL_MODULATE, {PRE, PRI, CON}, {OMA, SA, SA}, 1, 2, 1},
    {GL_INTERPOLATE, {TEX, PRI, CON}, {OMC, OMC, OMC}, GL_INTERPOLATE, {TEX, PRI, CON}, {OMA, OMA, OMA}, 1, 1, 0},
    {GL_DOT3_RGB, {TEX, PRI, CON}, {SC, SC, SA}, GL_ADD_SIGNED, {TEX, PRI, CON}, {SA, SA, SA}, 4, 2, 0},
    {GL_ADD, {TEX, TEX, CON}, {SC, SA, SA}, GL_SUBTRACT, {TEX, CON, CON}, {SA, SA, SA}, 4, 4, 0},
    {GL_INTERPOLATE, {PRI, CON, TEX}, {SC, SC, SA}, GL_MODULATE, {PRI, CON, CON}, {SA, SA, SA}, 2, 4, 1},
};

static void set_combine(const struct combine *c)
{
    static const GLenum srgb[3] = {GL_SOURCE0_RGB, GL_SOURCE1_RGB, GL_SOURCE2_RGB};
    static const GLenum orgb[3] = {GL_OPERAND0_RGB, GL_OPERAND1_RGB, GL_OPERAND2_RGB};
    static const GLenum sa[3] = {GL_SOURCE0_ALPHA, GL_SOURCE1_ALPHA, GL_SOURCE2_ALPHA};
    static const GLenum oa[3] = {GL_OPERAND0_ALPHA, GL_OPERAND1_ALPHA, GL_OPERAND2_ALPHA};
    int k;
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, (GLint)c->rgb_func);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, (GLint)c->a_func);
    for (k = 0; k < 3; k++) {
        glTexEnvi(GL_TEXTURE_ENV, srgb[k], (GLint)c->rgb_src[k]);
        glTexEnvi(GL_TEXTURE_ENV, orgb[k], (GLint)c->rgb_op[k]);
        glTexEnvi(GL_TEXTURE_ENV, sa[k], (GLint)c->a_src[k]);
        glTexEnvi(GL_TEXTURE_ENV, oa[k], (GLint)c->a_op[k]);
    }
    glTexEnvf(GL_TEXTURE_ENV, GL_RGB_SCALE, c->rgb_scale);
    glTexEnvf(GL_TEXTURE_ENV, GL_ALPHA_SCALE, c->a_scale);
}

int main(int argc, char **argv)
{
    static const GLfloat constant[4] = {0.61f, 0.27f, 0.83f, 0.45f};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    unsigned char a[8 * 8 * 4], b[4 * 4 * 3];
    GLuint tex[2];
    int i, x, y;

    for (y = 0; y < 8; y++)
        for (x = 0; x < 8; x++) {
            unsigned char *p = a + 4 * (y * 8 + x);
            p[0] = (unsigned char)(33 * x + 7);
            p[1] = (unsigned char)(200 - 19 * y + 3 * x);
            p[2] = (unsigned char)(((x * 5 + y * 3) % 8) * 31 + 9);
            p[3] = (unsigned char)(250 - 14 * x - 13 * y);
        }
    for (i = 0; i < 16; i++) {
        b[3 * i] = (unsigned char)(90 + 11 * i);
        b[3 * i + 1] = (unsigned char)(255 - 9 * i);
        b[3 * i + 2] = (unsigned char)((i & 1) ? 240 : 130);
    }
    glGenTextures(2, tex);
    /* unit 1 (and unit 0 in single-unit cells): texture a */
    glBindTexture(GL_TEXTURE_2D, tex[0]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, a);
    glBindTexture(GL_TEXTURE_2D, tex[1]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB, 4, 4, 0, GL_RGB, GL_UNSIGNED_BYTE, b);
    for (i = 0; i < 2; i++) {
        glActiveTexture(GL_TEXTURE0 + i);
        glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, constant);
    }
    sgl_ortho(W, H);
    glClearColor(0.05f, 0.1f, 0.15f, 0.5f);
    glClear(GL_COLOR_BUFFER_BIT);

    for (i = 0; i < 30; i++) {
        const struct combine *c = &cells[i];
        float x0 = 1.3f + 42.5f * (i % 6), y0 = 2.7f + 50.9f * (i / 6);
        float x1 = x0 + 40.1f, y1 = y0 + 47.9f;
        if (c->two) {
            glActiveTexture(GL_TEXTURE0);
            glEnable(GL_TEXTURE_2D);
            glBindTexture(GL_TEXTURE_2D, tex[1]);
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
            glActiveTexture(GL_TEXTURE1);
            glEnable(GL_TEXTURE_2D);
            glBindTexture(GL_TEXTURE_2D, tex[0]);
            set_combine(c);
        } else {
            glActiveTexture(GL_TEXTURE1);
            glDisable(GL_TEXTURE_2D);
            glActiveTexture(GL_TEXTURE0);
            glEnable(GL_TEXTURE_2D);
            glBindTexture(GL_TEXTURE_2D, tex[0]);
            set_combine(c);
        }
        glBegin(GL_QUADS);
        glColor4f(0.91f, 0.23f, 0.37f, 0.87f);
        glMultiTexCoord2f(GL_TEXTURE0, -0.03f, 0.01f);
        glMultiTexCoord2f(GL_TEXTURE1, 0.07f, -0.11f);
        glVertex2f(x0, y0);
        glColor4f(0.17f, 0.79f, 0.53f, 0.11f);
        glMultiTexCoord2f(GL_TEXTURE0, 1.03f, 0.01f);
        glMultiTexCoord2f(GL_TEXTURE1, 0.93f, -0.11f);
        glVertex2f(x1, y0);
        glColor4f(0.61f, 0.97f, 0.03f, 0.63f);
        glMultiTexCoord2f(GL_TEXTURE0, 1.03f, 0.99f);
        glMultiTexCoord2f(GL_TEXTURE1, 0.93f, 1.07f);
        glVertex2f(x1, y1);
        glColor4f(0.07f, 0.31f, 0.89f, 0.41f);
        glMultiTexCoord2f(GL_TEXTURE0, -0.03f, 0.99f);
        glMultiTexCoord2f(GL_TEXTURE1, 0.07f, 1.07f);
        glVertex2f(x0, y1);
        glEnd();
    }
    glFinish();
    SGL_CHECK(glGetError() == GL_NO_ERROR);
    sgl_image(out, "color", W, H, 4, "RGBA", W * 4, 1, buf);
    sgl_close(out);
    OSMesaDestroyContext(ctx);
    free(buf);
    return 0;
}
