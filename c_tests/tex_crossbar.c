/* tex_crossbar: ARB_texture_env_crossbar, a combiner source naming another
 * unit (GL_TEXTUREn).  Three units with three different textures and
 * texture coordinates; each cell enables a subset of the units and gives
 * them COMBINE environments whose sources read other units' texels: a later
 * unit, an earlier one, a unit that is disabled (Mesa's generated shader
 * reads zero there), a unit past a disabled one (the enabled units are not
 * consecutive), a unit whose texture is incomplete (not enabled for
 * texturing, so zero too), and alpha sources.  Blending is off and the full
 * RGBA buffer is dumped. */
#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include "common.h"
#include "tex_common.h"

#define W 192
#define H 128

#define T0 GL_TEXTURE0
#define T1 GL_TEXTURE1
#define T2 GL_TEXTURE2
#define TEX GL_TEXTURE
#define PRI GL_PRIMARY_COLOR
#define PRE GL_PREVIOUS
#define CON GL_CONSTANT
#define SC GL_SRC_COLOR
#define OMC GL_ONE_MINUS_SRC_COLOR
#define SA GL_SRC_ALPHA

/* One unit's environment: enabled (0 off, 1 on, 2 on with an incomplete
 * texture), combine function and sources/operands for RGB and alpha. */
struct unit_env {
    int on;
    GLenum rgb_func, rgb_src[3], rgb_op[3];
    GLenum a_func, a_src[3], a_op[3];
};

struct cell {
    struct unit_env u[3];
};

#define OFF {0, GL_MODULATE, {TEX, PRE, CON}, {SC, SC, SA}, GL_MODULATE, {TEX, PRE, CON}, {SA, SA, SA}}
#define MOD {1, GL_MODULATE, {TEX, PRE, CON}, {SC, SC, SA}, GL_MODULATE, {TEX, PRE, CON}, {SA, SA, SA}}

static const struct cell cells[12] = {
    /* unit 0 reads unit 1 (a later unit); unit 1 modulates */
    {{{1, GL_REPLACE, {T1, PRI, CON}, {SC, SC, SA}, GL_REPLACE, {TEX, PRI, CON}, {SA, SA, SA}}, MOD, OFF}},
    /* unit 1 interpolates unit 0 and itself by unit 0's alpha */
    {{MOD, {1, GL_INTERPOLATE, {T0, T1, T0}, {SC, SC, SA}, GL_MODULATE, {T0, PRE, CON}, {SA, SA, SA}}, OFF}},
    /* unit 1 reads unit 2, which is disabled: zero */
    {{MOD, {1, GL_ADD, {T2, PRE, CON}, {SC, SC, SA}, GL_ADD, {T2, PRE, CON}, {SA, SA, SA}}, OFF}},
    /* unit 0 off; unit 1 reads unit 0: zero */
    {{OFF, {1, GL_ADD, {T0, TEX, CON}, {OMC, SC, SA}, GL_REPLACE, {T0, PRI, CON}, {SA, SA, SA}}, OFF}},
    /* units 0 and 2 on, 1 off; unit 0 reads unit 2, unit 2 reads unit 0 */
    {{{1, GL_MODULATE, {T2, PRI, CON}, {SC, SC, SA}, GL_REPLACE, {T2, PRI, CON}, {SA, SA, SA}}, OFF,
      {1, GL_SUBTRACT, {T0, PRE, CON}, {SC, SC, SA}, GL_MODULATE, {T0, TEX, CON}, {SA, SA, SA}}}},
    /* unit 2 reads unit 1, which has an incomplete texture: zero */
    {{MOD, {2, GL_MODULATE, {TEX, PRE, CON}, {SC, SC, SA}, GL_MODULATE, {TEX, PRE, CON}, {SA, SA, SA}},
      {1, GL_ADD, {T1, PRE, CON}, {SC, SC, SA}, GL_ADD, {T1, TEX, CON}, {SA, SA, SA}}}},
    /* all three; unit 2 dot3 of unit 0 and unit 1 */
    {{MOD, MOD, {1, GL_DOT3_RGB, {T0, T1, CON}, {SC, SC, SA}, GL_REPLACE, {T1, PRI, CON}, {SA, SA, SA}}}},
    /* alpha-only crossbar: unit 0 alpha from unit 2's alpha, inverted */
    {{{1, GL_MODULATE, {TEX, PRI, CON}, {SC, SC, SA}, GL_REPLACE, {T2, PRI, CON}, {GL_ONE_MINUS_SRC_ALPHA, SA, SA}},
      OFF, MOD}},
    /* a unit naming itself by number is its own texture */
    {{{1, GL_MODULATE, {T0, PRI, CON}, {SC, SC, SA}, GL_MODULATE, {T0, PRI, CON}, {SA, SA, SA}}, OFF, OFF}},
    /* unit 1 interpolates unit 2 and primary by unit 0's colour */
    {{MOD, {1, GL_INTERPOLATE, {T2, PRI, T0}, {SC, SC, SC}, GL_ADD_SIGNED, {T2, T0, CON}, {SA, SA, SA}}, MOD}},
    /* unit 0 reads units 1 and 2 (both later), ADD_SIGNED */
    {{{1, GL_ADD_SIGNED, {T1, T2, CON}, {SC, OMC, SA}, GL_ADD_SIGNED, {T1, T2, CON}, {SA, SA, SA}}, MOD, MOD}},
    /* only unit 2 on; it reads units 0 and 1, both disabled */
    {{OFF, OFF, {1, GL_ADD, {T0, T1, CON}, {SC, SC, SA}, GL_ADD, {T0, TEX, CON}, {SA, SA, SA}}}},
};

static void set_unit(int unit, const struct unit_env *e, const GLuint *tex)
{
    static const GLenum srgb[3] = {GL_SOURCE0_RGB, GL_SOURCE1_RGB, GL_SOURCE2_RGB};
    static const GLenum orgb[3] = {GL_OPERAND0_RGB, GL_OPERAND1_RGB, GL_OPERAND2_RGB};
    static const GLenum sa[3] = {GL_SOURCE0_ALPHA, GL_SOURCE1_ALPHA, GL_SOURCE2_ALPHA};
    static const GLenum oa[3] = {GL_OPERAND0_ALPHA, GL_OPERAND1_ALPHA, GL_OPERAND2_ALPHA};
    int k;
    glActiveTexture(GL_TEXTURE0 + unit);
    if (!e->on) {
        glDisable(GL_TEXTURE_2D);
        return;
    }
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, e->on == 2 ? tex[3] : tex[unit]);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_COMBINE);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_RGB, (GLint)e->rgb_func);
    glTexEnvi(GL_TEXTURE_ENV, GL_COMBINE_ALPHA, (GLint)e->a_func);
    for (k = 0; k < 3; k++) {
        glTexEnvi(GL_TEXTURE_ENV, srgb[k], (GLint)e->rgb_src[k]);
        glTexEnvi(GL_TEXTURE_ENV, orgb[k], (GLint)e->rgb_op[k]);
        glTexEnvi(GL_TEXTURE_ENV, sa[k], (GLint)e->a_src[k]);
        glTexEnvi(GL_TEXTURE_ENV, oa[k], (GLint)e->a_op[k]);
    }
}

static void vertex(float x, float y, float s, float t, const float *c)
{
    glColor4fv(c);
    glMultiTexCoord2f(GL_TEXTURE0, s, t);
    glMultiTexCoord2f(GL_TEXTURE1, 1.1f - t, s * 0.9f + 0.05f);
    glMultiTexCoord2f(GL_TEXTURE2, s * 1.7f - 0.2f, t * 1.3f);
    glVertex2f(x, y);
}

int main(int argc, char **argv)
{
    static const GLfloat constant[4] = {0.61f, 0.27f, 0.83f, 0.45f};
    static const float col[4][4] = {{0.91f, 0.23f, 0.37f, 0.87f},
                                    {0.17f, 0.79f, 0.53f, 0.11f},
                                    {0.61f, 0.97f, 0.03f, 0.63f},
                                    {0.07f, 0.31f, 0.89f, 0.41f}};
    FILE *out = sgl_open(argc, argv);
    unsigned char *buf;
    OSMesaContext ctx = sgl_tex_context(W, H, &buf);
    unsigned char img[3][8 * 8 * 4];
    GLuint tex[4];
    int i, x, y, u;

    for (u = 0; u < 3; u++)
        for (y = 0; y < 8; y++)
            for (x = 0; x < 8; x++) {
                unsigned char *p = img[u] + 4 * (y * 8 + x);
                p[0] = (unsigned char)((33 * x + 7 + 70 * u) & 255);
                p[1] = (unsigned char)(200 - 19 * y + 3 * x + 11 * u);
                p[2] = (unsigned char)(((x * 5 + y * 3 + u) % 8) * 31 + 9);
                p[3] = (unsigned char)(250 - 14 * x - 13 * y + 5 * u);
            }
    glGenTextures(4, tex);
    for (u = 0; u < 3; u++) {
        glBindTexture(GL_TEXTURE_2D, tex[u]);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, u == 1 ? GL_NEAREST : GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, u == 1 ? GL_NEAREST : GL_LINEAR);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img[u]);
    }
    /* incomplete: a mipmap minification filter and only level 0 */
    glBindTexture(GL_TEXTURE_2D, tex[3]);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 8, 8, 0, GL_RGBA, GL_UNSIGNED_BYTE, img[1]);
    for (u = 0; u < 3; u++) {
        glActiveTexture(GL_TEXTURE0 + u);
        glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, constant);
    }
    sgl_ortho(W, H);
    glClearColor(0.05f, 0.1f, 0.15f, 0.5f);
    glClear(GL_COLOR_BUFFER_BIT);

    for (i = 0; i < 12; i++) {
        float x0 = 1.3f + 47.5f * (i % 4), y0 = 2.7f + 41.9f * (i / 4);
        float x1 = x0 + 44.1f, y1 = y0 + 39.3f;
        for (u = 0; u < 3; u++)
            set_unit(u, &cells[i].u[u], tex);
        glBegin(GL_QUADS);
        vertex(x0, y0, -0.03f, 0.01f, col[0]);
        vertex(x1, y0, 1.03f, 0.01f, col[1]);
        vertex(x1, y1, 1.03f, 0.99f, col[2]);
        vertex(x0, y1, -0.03f, 0.99f, col[3]);
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
